/* QBasic's screen beyond SCREEN 12 (qbscreen.h): the modes' facts and palettes, text in
 * character cells with the 8x8/8x14/8x16 fonts, scrolling, GET/PUT with every action, DRAW's
 * macro language, PCOPY between pages; exact pixels throughout. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"
#include "font.h"
#include "qbscreen.h"

static int px(const pc_canvas *c, int x, int y) { return c->pixels[(size_t)y * c->width + x]; }

/* How many pixels of the rectangle have colour col. */
static int count(const pc_canvas *c, int x0, int y0, int x1, int y1, int col) {
    int n = 0;
    for (int y = y0; y <= y1; y++)
        for (int x = x0; x <= x1; x++) n += px(c, x, y) == col;
    return n;
}

static void test_modes(void **state) {
    (void)state;
    pc_mode_info m;
    /* size, colours, pages, text cells as QBasic 1.1's help lists them */
    assert_int_equal(pc_mode_info_of(13, &m), PC_OK);
    assert_int_equal(m.width, 320);
    assert_int_equal(m.height, 200);
    assert_int_equal(m.ncolors, 256);
    assert_int_equal(m.cell_h, 8);
    assert_int_equal(m.cols, 40);
    /* 4/3 * 200/320: SCREEN 13's circles are flattened to look round on a 4:3 monitor */
    assert_true(fabs(m.aspect - 5.0 / 6.0) < 1e-12);
    assert_int_equal(pc_mode_info_of(9, &m), PC_OK);
    assert_int_equal(m.height, 350);
    assert_int_equal(m.cell_h, 14);
    assert_int_equal(m.pages, 2);
    assert_true(fabs(m.aspect - 4.0 / 3.0 * 350 / 640) < 1e-12);
    assert_int_equal(pc_mode_info_of(12, &m), PC_OK);
    assert_true(fabs(m.aspect - 1.0) < 1e-12);   /* 640x480: square pixels */
    assert_int_equal(m.rows, 30);
    assert_int_equal(pc_mode_info_of(7, &m), PC_OK);
    assert_int_equal(m.pages, 8);
    assert_int_equal(pc_mode_info_of(2, &m), PC_OK);
    assert_int_equal(m.ncolors, 2);
    /* SCREEN 8: EGA's 640x200 in 16 colours, 80x25 text in 8x8 cells, 4 pages in 64K each */
    assert_int_equal(pc_mode_info_of(8, &m), PC_OK);
    assert_int_equal(m.width, 640);
    assert_int_equal(m.height, 200);
    assert_int_equal(m.ncolors, 16);
    assert_int_equal(m.pages, 4);
    assert_int_equal(m.cols, 80);
    assert_int_equal(m.rows, 25);
    assert_int_equal(m.cell_h, 8);
    assert_true(fabs(m.aspect - 4.0 / 3.0 * 200 / 640) < 1e-12);   /* tall pixels: 0.4167 */
    assert_int_equal(pc_mode_info_of(10, &m), PC_EARG);
    assert_int_equal(pc_mode_info_of(0, &m), PC_EARG);

    pc_canvas *c = pc_canvas_new_mode(1);
    assert_non_null(c);
    assert_int_equal(c->width, 320);
    assert_int_equal(c->ncolors, 4);
    pc_rgb rgb;
    assert_int_equal(pc_canvas_rgb(c, 1, &rgb), PC_OK);   /* light cyan: DAC 21, 63, 63 */
    assert_int_equal(rgb.r, 0x55);
    assert_int_equal(rgb.g, 0xff);
    assert_int_equal(rgb.b, 0xff);
    assert_int_equal(c->fg, 3);                            /* the default ink: white */
    assert_int_equal(pc_canvas_set_mode(c, 9), PC_OK);
    assert_int_equal(c->height, 350);
    assert_int_equal(c->ncolors, 16);
    assert_int_equal(pc_canvas_set_mode(c, 4), PC_EARG);
    assert_non_null(strstr(pc_canvas_error(c), "mode 4"));
    assert_null(pc_canvas_new_mode(3));
    /* a canvas knows its mode by its size and colours: 9 is 640x350x16 with 14-pixel cells */
    assert_int_equal(pc_mode_of_canvas(c, &m), 9);
    assert_int_equal(m.cell_h, 14);
    assert_int_equal(pc_cell_height(c), 14);
    assert_int_equal(pc_canvas_set_mode(c, 13), PC_OK);
    assert_int_equal(pc_mode_of_canvas(c, &m), 13);
    assert_true(fabs(m.aspect - 4.0 / 3.0 * 200 / 320) < 1e-15);
    assert_int_equal(pc_cell_height(c), 8);
    assert_int_equal(pc_canvas_reset(c, 320, 200, 16), PC_OK);   /* SCREEN 7's size */
    assert_int_equal(pc_mode_of_canvas(c, &m), 7);
    assert_int_equal(pc_canvas_reset(c, 300, 200, 16), PC_OK);   /* no mode's size */
    assert_int_equal(pc_mode_of_canvas(c, &m), 0);
    assert_int_equal(pc_cell_height(c), 16);
    pc_canvas_free(c);
}

/* The glyph rows of 'A' in a font, compared with the screen cell at (x0, y0). */
static void assert_cell_is(const pc_canvas *c, int x0, int y0, const pc_font *f, uint32_t cp,
                           int fg, int bg) {
    const uint8_t *rows = f->bits + (size_t)pc_font_glyph_in(f, cp) * f->h;
    for (int r = 0; r < f->h; r++)
        for (int b = 0; b < 8; b++)
            assert_int_equal(px(c, x0 + b, y0 + r), (rows[r] & (0x80 >> b)) ? fg : bg);
}

static void test_text_cells(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new_mode(13);
    const pc_font *f8 = pc_font_of_height(8);
    assert_non_null(f8);
    assert_int_equal(f8->h, 8);
    assert_null(pc_font_of_height(12));
    /* LOCATE 1, 1: PRINT "A" puts the glyph's pixels in the top-left cell */
    assert_int_equal(pc_text_cells(c, 1, 1, "A", 1, 8, 14, 0), PC_OK);
    assert_cell_is(c, 0, 0, f8, 'A', 14, 0);
    assert_true(count(c, 0, 0, 7, 7, 14) > 10);   /* 'A' has ink */
    /* the background is opaque: a cell over a drawn box shows bg around the glyph */
    assert_int_equal(pc_box(c, 0, 8, 50, 30, 4, 1), PC_OK);
    assert_int_equal(pc_text_cells(c, 3, 2, "Hi", 2, 8, 15, 1), PC_OK);
    assert_cell_is(c, 8, 16, f8, 'H', 15, 1);
    assert_cell_is(c, 16, 16, f8, 'i', 15, 1);
    assert_int_equal(px(c, 24, 16), 4);   /* the box beyond the two cells is untouched */
    /* code page 437: byte 219 is the full block */
    assert_int_equal(pc_text_cells(c, 5, 1, "\xdb", 1, 8, 2, 0), PC_OK);
    assert_int_equal(pc_cp437[219], 0x2588);
    /* the control bytes PRINT shows are their pictures (CHR$(1) a face, 3 a heart, 127 a house);
     * those it acts on (7 the bell, 13 the carriage return) stay controls */
    assert_int_equal(pc_cp437[1], 0x263a);
    assert_int_equal(pc_cp437[3], 0x2665);
    assert_int_equal(pc_cp437[27], 0x2190);
    assert_int_equal(pc_cp437[127], 0x2302);
    assert_int_equal(pc_cp437[7], 7);
    assert_int_equal(pc_cp437[13], 13);
    assert_int_not_equal(pc_font_glyph_in(pc_font_of_height(8), pc_cp437[3]),
                         pc_font_of_height(8)->replacement);
    assert_int_equal(count(c, 0, 32, 7, 39, 2), 64);
    /* VIEW does not clip text */
    assert_int_equal(pc_view(c, 100, 100, 200, 150, -1, -1, 0), PC_OK);
    assert_int_equal(pc_text_cells(c, 1, 40, "Z", 1, 8, 9, 0), PC_OK);
    assert_cell_is(c, 312, 0, f8, 'Z', 9, 0);
    /* the SVG's text op carries the cell height */
    const pc_op *op = &c->ops[c->nops - 1];
    assert_int_equal(op->kind, PC_OP_TEXT);
    assert_true(op->ry == 8);
    assert_true(op->x1 == 312 && op->y1 == 0);
    /* the 8x16 cells of SCREEN 12 and the 8x14 of SCREEN 9 */
    assert_int_equal(pc_canvas_set_mode(c, 12), PC_OK);
    assert_int_equal(pc_text_cells(c, 2, 3, "g", 1, 16, 15, 0), PC_OK);
    assert_cell_is(c, 16, 16, pc_font_of_height(16), 'g', 15, 0);
    assert_int_equal(pc_canvas_set_mode(c, 9), PC_OK);
    assert_int_equal(pc_text_cells(c, 25, 80, "Q", 1, 14, 12, 0), PC_OK);
    assert_cell_is(c, 632, 336, pc_font_of_height(14), 'Q', 12, 0);
    /* errors */
    assert_int_equal(pc_text_cells(c, 1, 1, "x", 1, 10, 1, 0), PC_EARG);
    assert_int_equal(pc_text_cells(c, 1, 1, "x", 1, 14, 16, 0), PC_EARG);
    assert_int_equal(pc_text_cells(c, 0, 1, "x", 1, 14, 1, 0), PC_EARG);
    pc_canvas_free(c);
}

static void test_scroll(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new_mode(13);
    assert_int_equal(pc_text_cells(c, 2, 1, "A", 1, 8, 14, 0), PC_OK);
    assert_int_equal(pc_text_cells(c, 25, 1, "B", 1, 8, 13, 0), PC_OK);
    assert_int_equal(pc_text_scroll(c, 1, 25, 8, 0), PC_OK);
    const pc_font *f8 = pc_font_of_height(8);
    assert_cell_is(c, 0, 0, f8, 'A', 14, 0);        /* row 2 is now row 1 */
    assert_cell_is(c, 0, 23 * 8, f8, 'B', 13, 0);   /* row 25 is now 24 */
    assert_int_equal(count(c, 0, 192, 319, 199, 0), 320 * 8);   /* the last row is empty */
    /* the SVG sees the moved pixels: the last ops are FILLs */
    assert_int_equal(c->ops[c->nops - 1].kind, PC_OP_FILL);
    pc_canvas_free(c);
}

static void test_get_put(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new_mode(12);
    assert_int_equal(pc_box(c, 10, 10, 13, 12, 5, 1), PC_OK);   /* 4x3 of colour 5 */
    assert_int_equal(pc_pset(c, 11, 11, 9), PC_OK);
    pc_block *b = NULL;
    assert_int_equal(pc_get_block(c, 13, 12, 10, 10, &b), PC_OK);   /* corners in any order */
    assert_int_equal(b->w, 4);
    assert_int_equal(b->h, 3);
    assert_int_equal(b->px[0], 5);
    assert_int_equal(b->px[1 * 4 + 1], 9);
    /* QBasic's array size: 4 + 4 planes * 1 byte * 3 rows in the 16-colour modes */
    assert_int_equal(pc_block_bytes(c, 4, 3), 16);
    assert_int_equal(pc_block_bytes(c, 9, 3), 4 + 2 * 4 * 3);

    /* PSET copies; the cursor stays */
    double lx = c->last_x, ly = c->last_y;
    assert_int_equal(pc_put_block(c, 100, 50, b, PC_PUT_PSET), PC_OK);
    assert_int_equal(px(c, 100, 50), 5);
    assert_int_equal(px(c, 101, 51), 9);
    assert_int_equal(px(c, 104, 50), 0);
    assert_true(c->last_x == lx && c->last_y == ly);
    /* XOR twice restores the screen, over a background that is not black */
    assert_int_equal(pc_box(c, 200, 200, 220, 220, 3, 1), PC_OK);
    assert_int_equal(pc_put_block(c, 202, 202, b, PC_PUT_XOR), PC_OK);
    assert_int_equal(px(c, 202, 202), 5 ^ 3);
    assert_int_equal(px(c, 203, 203), 9 ^ 3);
    assert_int_equal(pc_put_block(c, 202, 202, b, PC_PUT_XOR), PC_OK);
    assert_int_equal(count(c, 200, 200, 220, 220, 3), 21 * 21);
    /* PRESET: the complement within the 4 colour bits; AND, OR */
    assert_int_equal(pc_put_block(c, 300, 300, b, PC_PUT_PRESET), PC_OK);
    assert_int_equal(px(c, 300, 300), 15 - 5);
    assert_int_equal(px(c, 301, 301), 15 - 9);
    assert_int_equal(pc_box(c, 400, 400, 410, 410, 6, 1), PC_OK);
    assert_int_equal(pc_put_block(c, 400, 400, b, PC_PUT_AND), PC_OK);
    assert_int_equal(px(c, 400, 400), 5 & 6);
    assert_int_equal(pc_put_block(c, 405, 405, b, PC_PUT_OR), PC_OK);
    assert_int_equal(px(c, 406, 406), 9 | 6);
    /* a block that does not fit, a corner outside: QBasic's Illegal function call */
    assert_int_equal(pc_put_block(c, 638, 10, b, PC_PUT_PSET), PC_EARG);
    assert_non_null(strstr(pc_canvas_error(c), "does not fit"));
    pc_block *b2 = NULL;
    assert_int_equal(pc_get_block(c, 0, 0, 640, 10, &b2), PC_EARG);
    assert_null(b2);
    assert_int_equal(pc_put_block(c, 0, 0, b, 7), PC_EARG);
    /* world coordinates: WINDOW applies */
    assert_int_equal(pc_window(c, 0, 0, 64, 48, 1), PC_OK);
    assert_int_equal(pc_put_block(c, 1, 1, b, PC_PUT_PSET), PC_OK);
    assert_int_equal(px(c, 10, 10), 5);
    pc_block_free(b);
    pc_canvas_free(c);
}

static void test_draw(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new_mode(12);
    pc_draw_state st;
    pc_draw_state_reset(&st);
    /* BM moves without drawing; a square of side 10 in colour 4 */
    assert_int_equal(pc_draw_macro(c, &st, "BM100,100 C4 R10 D10 L10 U10"), PC_OK);
    assert_int_equal(count(c, 100, 100, 110, 100, 4), 11);
    assert_int_equal(count(c, 110, 100, 110, 110, 4), 11);
    assert_int_equal(count(c, 100, 110, 110, 110, 4), 11);
    assert_int_equal(px(c, 99, 100), 0);
    assert_int_equal(px(c, 105, 105), 0);
    assert_true(c->last_x == 100 && c->last_y == 100);   /* the cursor is back at the start */
    /* diagonals: E goes up-right, F down-right; the colour stays from the last DRAW */
    assert_int_equal(pc_draw_macro(c, &st, "bm200,200 e5 f5"), PC_OK);
    assert_int_equal(px(c, 203, 197), 4);
    assert_int_equal(px(c, 205, 195), 4);
    assert_int_equal(px(c, 210, 200), 4);
    /* N returns, S scales (S8: 2 pixels a unit), TA turns counter-clockwise */
    assert_int_equal(pc_draw_macro(c, &st, "BM300,300 C2 NU5 S8 R5"), PC_OK);
    assert_int_equal(px(c, 300, 295), 2);
    assert_int_equal(px(c, 310, 300), 2);
    assert_int_equal(px(c, 311, 300), 0);
    assert_int_equal(pc_draw_macro(c, &st, "S4 BM400,300 TA90 C3 U10 TA0"), PC_OK);
    assert_int_equal(px(c, 390, 300), 3);   /* up turned by 90 degrees: left */
    assert_int_equal(px(c, 400, 290), 0);
    assert_int_equal(pc_draw_macro(c, &st, "BM50,400 A1 C6 R10 A0"), PC_OK);
    assert_int_equal(px(c, 50, 390), 6);    /* right turned a quarter: up */
    /* relative M and the cursor; P paints */
    assert_int_equal(pc_draw_macro(c, &st, "BM500,100 C15 M+20,+0 M+0,20 M-20,+0 M+0,-20 BM+5,+5 P1,15"), PC_OK);
    assert_int_equal(px(c, 510, 110), 1);
    assert_int_equal(px(c, 520, 110), 15);
    assert_int_equal(px(c, 530, 110), 0);
    /* errors name the command */
    assert_int_equal(pc_draw_macro(c, &st, "R5 Q3"), PC_EARG);
    assert_non_null(strstr(pc_canvas_error(c), "unknown command 'Q' at character 4"));
    assert_int_equal(pc_draw_macro(c, &st, "C"), PC_EARG);
    assert_int_equal(pc_draw_macro(c, &st, "C16"), PC_EARG);
    assert_int_equal(pc_draw_macro(c, &st, "M10"), PC_EARG);
    assert_int_equal(pc_draw_macro(c, &st, "S0"), PC_EARG);
    assert_int_equal(pc_draw_macro(c, &st, "TA400"), PC_EARG);
    assert_int_equal(pc_draw_macro(c, &st, "R5 B"), PC_EARG);
    pc_canvas_free(c);
}

/* DRAW turns on the monitor: in SCREEN 2 (pixels 2.4 times as high as wide) a quarter turn
 * keeps a figure's size, so "A1 R24" goes up 24 * 0.4167 = 10 pixels and "A1 U10" left 24. */
static void test_draw_aspect(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new_mode(2);
    pc_draw_state st;
    pc_draw_state_reset(&st);
    pc_mode_info m;
    pc_mode_info_of(2, &m);
    st.aspect = m.aspect;
    assert_int_equal(pc_draw_macro(c, &st, "BM100,100 C1 A1 R24 A0"), PC_OK);
    assert_int_equal(count(c, 100, 90, 100, 100, 1), 11);   /* up 10 pixels */
    assert_int_equal(px(c, 100, 89), 0);
    assert_int_equal(pc_draw_macro(c, &st, "BM300,100 A1 U10 A0"), PC_OK);
    assert_int_equal(count(c, 276, 100, 300, 100, 1), 25);  /* left 24 pixels */
    assert_int_equal(px(c, 275, 100), 0);
    /* not turned: no correction; a half turn neither */
    assert_int_equal(pc_draw_macro(c, &st, "BM400,150 R10 BM400,150 A2 U10 A0"), PC_OK);
    assert_int_equal(count(c, 400, 150, 410, 150, 1), 11);
    assert_int_equal(count(c, 400, 150, 400, 160, 1), 11);
    pc_canvas_free(c);
}

/* PAINT with a tile: the pattern of the mode's tile string, aligned to the screen. */
static void test_paint_tile(void **state) {
    (void)state;
    /* SCREEN 12: a row is 4 bytes, bit planes blue, green, red, intensity: CHR$(&HF0) in the
     * red plane and CHR$(&H0F) in the blue one is 4 red (4) then 4 blue (1) pixels */
    pc_canvas *c = pc_canvas_new_mode(12);
    pc_tile t;
    const unsigned char rows12[] = {0x0F, 0x00, 0xF0, 0x00, 0xFF, 0xFF, 0xFF, 0xFF};
    assert_int_equal(pc_tile_from_bytes(c, rows12, sizeof rows12, &t), PC_OK);
    assert_int_equal(t.w, 8);
    assert_int_equal(t.h, 2);
    assert_int_equal(t.attr[0], 4);
    assert_int_equal(t.attr[4], 1);
    assert_int_equal(t.attr[8], 15);
    assert_int_equal(pc_box(c, 16, 16, 47, 31, 14, 0), PC_OK);      /* a yellow frame */
    assert_int_equal(pc_paint_tile(c, 30, 20, &t, 14), PC_OK);
    assert_int_equal(px(c, 17, 18), 4);      /* x 17: 17 mod 8 = 1 (red), y 18: an even row */
    assert_int_equal(px(c, 19, 18), 4);
    assert_int_equal(px(c, 20, 18), 1);      /* 20 mod 8 = 4: blue */
    assert_int_equal(px(c, 23, 18), 1);
    assert_int_equal(px(c, 24, 18), 4);      /* the next repeat */
    assert_int_equal(px(c, 17, 17), 15);     /* odd rows: white */
    assert_int_equal(px(c, 19, 19), 15);
    assert_int_equal(px(c, 16, 20), 14);     /* the frame stays */
    assert_int_equal(px(c, 50, 20), 0);      /* outside: untouched */
    assert_int_equal(count(c, 17, 17, 46, 30, 0), 0);
    /* SCREEN 1: a byte is 4 pixels of 2 bits: &H1B is 0, 1, 2, 3 */
    pc_canvas *c1 = pc_canvas_new_mode(1);
    const unsigned char row1[] = {0x1B};
    assert_int_equal(pc_tile_from_bytes(c1, row1, 1, &t), PC_OK);
    assert_int_equal(t.w, 4);
    assert_int_equal(t.h, 1);
    assert_int_equal(pc_paint_tile(c1, 10, 10, &t, -1), PC_OK);   /* the whole screen */
    assert_int_equal(px(c1, 0, 0), 0);
    assert_int_equal(px(c1, 1, 7), 1);
    assert_int_equal(px(c1, 6, 100), 2);
    assert_int_equal(px(c1, 319, 199), 3);
    /* SCREEN 2: a byte is 8 pixels: &HAA is on, off, on, ... */
    pc_canvas *c2 = pc_canvas_new_mode(2);
    const unsigned char row2[] = {0xAA, 0x55};
    assert_int_equal(pc_tile_from_bytes(c2, row2, 2, &t), PC_OK);
    assert_int_equal(pc_paint_tile(c2, 5, 5, &t, -1), PC_OK);
    assert_int_equal(px(c2, 0, 0), 1);
    assert_int_equal(px(c2, 1, 0), 0);
    assert_int_equal(px(c2, 0, 1), 0);
    assert_int_equal(px(c2, 1, 1), 1);
    /* the same from the bytes in one call: the tile read, then painted; an empty one refused */
    assert_int_equal(pc_cls(c2), PC_OK);
    assert_int_equal(pc_paint_tile_bytes(c2, 5, 5, row2, 2, -1), PC_OK);
    assert_int_equal(px(c2, 2, 0), 1);
    assert_int_equal(px(c2, 3, 0), 0);
    assert_int_equal(px(c2, 3, 1), 1);
    assert_int_equal(pc_paint_tile_bytes(c2, 5, 5, row2, 0, -1), PC_EARG);
    /* SCREEN 13: a byte a pixel, 8 a row */
    pc_canvas *c13 = pc_canvas_new_mode(13);
    const unsigned char row13[] = {40, 41, 42, 43, 44, 45, 46, 47};
    assert_int_equal(pc_tile_from_bytes(c13, row13, 8, &t), PC_OK);
    assert_int_equal(pc_paint_tile(c13, 0, 0, &t, -1), PC_OK);
    assert_int_equal(px(c13, 11, 3), 43);
    /* errors: an empty or long tile, colours of another mode */
    unsigned char many[65] = {0};
    assert_int_equal(pc_tile_from_bytes(c, many, 0, &t), PC_EARG);
    assert_int_equal(pc_tile_from_bytes(c, many, 65, &t), PC_EARG);
    assert_non_null(strstr(pc_canvas_error(c), "1..64 bytes"));
    assert_int_equal(pc_tile_from_bytes(c13, row13, 8, &t), PC_OK);
    t.attr[0] = 300;
    assert_int_equal(pc_paint_tile(c13, 0, 0, &t, -1), PC_EARG);
    pc_canvas_free(c);
    pc_canvas_free(c1);
    pc_canvas_free(c2);
    pc_canvas_free(c13);
}

static void test_pcopy(void **state) {
    (void)state;
    pc_canvas *a = pc_canvas_new_mode(7), *b = pc_canvas_new_mode(7);
    assert_int_equal(pc_line(a, 0, 0, 50, 50, 12), PC_OK);
    assert_int_equal(pc_text_cells(a, 3, 3, "ok", 2, 8, 14, 0), PC_OK);
    assert_int_equal(pc_pset(b, 5, 100, 3), PC_OK);
    assert_int_equal(pc_canvas_copy_picture(b, a), PC_OK);
    assert_memory_equal(a->pixels, b->pixels, 320 * 200 * sizeof *a->pixels);
    assert_int_equal(b->nops, a->nops);
    assert_int_equal(px(b, 5, 100), 0);
    assert_int_equal(b->ntext, a->ntext);
    /* drawing on the copy leaves the original alone */
    assert_int_equal(pc_pset(b, 1, 199, 9), PC_OK);
    assert_int_equal(px(a, 1, 199), 0);
    pc_canvas *d = pc_canvas_new_mode(13);
    assert_int_equal(pc_canvas_copy_picture(d, a), PC_EARG);
    pc_canvas_free(a);
    pc_canvas_free(b);
    pc_canvas_free(d);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_modes),   cmocka_unit_test(test_text_cells),
        cmocka_unit_test(test_scroll),  cmocka_unit_test(test_get_put),
        cmocka_unit_test(test_draw),    cmocka_unit_test(test_pcopy),
        cmocka_unit_test(test_draw_aspect), cmocka_unit_test(test_paint_tile),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
