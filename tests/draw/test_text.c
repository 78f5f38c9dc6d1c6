/* Text in the built-in VGA font: the glyphs, their pixels at each scale, the nine anchors,
 * UTF-8 and the replacement glyph. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"
#include "font.h"

static int at(const pc_canvas *c, int x, int y) { return c->pixels[y * c->width + x]; }

/* The IBM VGA 8x16 'A', row by row. */
static const uint8_t vga_A[16] = {0x00, 0x00, 0x10, 0x38, 0x6c, 0xc6, 0xc6, 0xfe,
                                  0xc6, 0xc6, 0xc6, 0xc6, 0x00, 0x00, 0x00, 0x00};

static void test_font_has_vga_glyphs(void **state) {
    (void)state;
    assert_int_equal(pc_font_nglyphs, 512 + 22 + 96);   /* Uni2-VGA16, the BIOS's pictures, 128..223 */
    assert_memory_equal(pc_font_bits[pc_font_glyph('A')], vga_A, 16);
    /* Latin, Greek and Cyrillic are in the font; a character it lacks gets the replacement */
    int repl = pc_font_replacement;
    assert_int_equal(pc_font_glyph(0xfffd), repl);
    assert_int_not_equal(pc_font_glyph(0x00e9), repl);   /* e acute */
    assert_int_not_equal(pc_font_glyph(0x03b1), repl);   /* alpha */
    assert_int_not_equal(pc_font_glyph(0x0416), repl);   /* Zhe */
    assert_int_equal(pc_font_glyph(0x4e2d), repl);       /* a CJK ideograph */
    assert_int_equal(pc_font_glyph(0x1f600), repl);      /* beyond the BMP */
    /* capitals stand on the baseline: their last row of ink is the one above it */
    assert_int_not_equal(pc_font_bits[pc_font_glyph('H')][PC_FONT_BASELINE - 1], 0);
    assert_int_equal(pc_font_bits[pc_font_glyph('H')][PC_FONT_BASELINE], 0);
}

/* The cell at (x0, y0) holds glyph g at scale s, in colour col, nothing else inside it. */
static void assert_glyph_at(const pc_canvas *c, int x0, int y0, int g, int s, int col) {
    for (int y = 0; y < 16 * s; y++)
        for (int x = 0; x < 8 * s; x++) {
            int ink = (pc_font_bits[g][y / s] >> (7 - x / s)) & 1;
            int got = at(c, x0 + x, y0 + y);
            if (got != (ink ? col : 0))
                fail_msg("glyph %d at scale %d: pixel (%d, %d) is %d", g, s, x, y, got);
        }
}

/* Code page 437's box drawings and blocks in each cell size, from the VGA BIOS (CMakeLists.txt):
 * the double lines are double (two full rows for CHR$(205), two columns for CHR$(186)), the
 * lower of them on the row of the single CHR$(196), so that the pieces join; the half blocks
 * CHR$(220), CHR$(223), CHR$(221), CHR$(222) are halves, not the replacement.  And the BIOS's
 * 8x8 and 8x14 letters, not the console font's: IBM's 8x8 'A' is 30 78 CC CC FC CC CC 00. */
static const uint8_t *rows_of(const pc_font *f, uint32_t cp) {
    return f->bits + (size_t)pc_font_glyph_in(f, cp) * (size_t)f->h;
}

static void test_font_box_drawings(void **state) {
    (void)state;
    const int heights[3] = {8, 14, 16};
    for (int k = 0; k < 3; k++) {
        const pc_font *f = pc_font_of_height(heights[k]);
        assert_non_null(f);
        int full = 0, empty = 0, dbl = 0, single = 0;
        const uint8_t *h2 = rows_of(f, pc_cp437[205]), *h1 = rows_of(f, pc_cp437[196]);
        const uint8_t *v2 = rows_of(f, pc_cp437[186]), *v1 = rows_of(f, pc_cp437[179]);
        for (int r = 0; r < f->h; r++) {
            full += h2[r] == 0xff;
            empty += h2[r] == 0;
            single += h1[r] == 0xff;
            dbl += __builtin_popcount(v2[r]) == 4 && v2[r] != v1[r];
        }
        assert_int_equal(full, 2);
        assert_int_equal(empty, f->h - 2);
        assert_int_equal(single, 1);
        int lower_line = 0, single_row = 0;
        for (int r = 0; r < f->h; r++) {
            if (h2[r] == 0xff) lower_line = r;
            if (h1[r] == 0xff) single_row = r;
        }
        assert_int_equal(lower_line, single_row);
        assert_int_equal(dbl, f->h);   /* two 2-pixel columns on every row */
        const uint8_t *lower = rows_of(f, pc_cp437[220]), *upper = rows_of(f, pc_cp437[223]);
        const uint8_t *left = rows_of(f, pc_cp437[221]), *right = rows_of(f, pc_cp437[222]);
        assert_int_not_equal(pc_font_glyph_in(f, pc_cp437[220]), f->replacement);
        assert_int_equal(lower[0], 0);
        assert_int_equal(lower[f->h - 1], 0xff);
        assert_int_equal(upper[0], 0xff);
        assert_int_equal(upper[f->h - 1], 0);
        for (int r = 0; r < f->h; r++) {
            assert_int_equal(left[r], 0xf0);
            assert_int_equal(right[r], 0x0f);
            assert_false(lower[r] && upper[r]);   /* the halves do not overlap */
        }
    }
    static const uint8_t ibm_a8[8] = {0x30, 0x78, 0xcc, 0xcc, 0xfc, 0xcc, 0xcc, 0x00};
    static const uint8_t ibm_a14[14] = {0x00, 0x00, 0x10, 0x38, 0x6c, 0xc6, 0xc6,
                                        0xfe, 0xc6, 0xc6, 0xc6, 0x00, 0x00, 0x00};
    assert_memory_equal(rows_of(pc_font_of_height(8), 'A'), ibm_a8, 8);
    assert_memory_equal(rows_of(pc_font_of_height(14), 'A'), ibm_a14, 14);
}

static void test_text_pixels(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(64, 48, 16);
    /* SE with no gap puts the cell's top-left pixel on the point */
    assert_int_equal(pc_text(c, 3, 4, "A", PC_ANCHOR_SE, 0, 1, 14), PC_OK);
    assert_glyph_at(c, 3, 4, pc_font_glyph('A'), 1, 14);
    assert_int_equal(pc_text(c, 20, 10, "A", PC_ANCHOR_SE, 0, 2, 12), PC_OK);
    assert_glyph_at(c, 20, 10, pc_font_glyph('A'), 2, 12);
    /* the op records the cell box and the string */
    const pc_op *op = &c->ops[1];
    assert_int_equal(op->kind, PC_OP_TEXT);
    assert_true(op->x1 == 20 && op->y1 == 10 && op->rx == 2);
    assert_memory_equal(c->text + op->first, "A", 1);
    pc_canvas_free(c);
}

static void test_text_is_transparent_and_utf8(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(64, 20, 16);
    pc_pset(c, 0, 0, 5);   /* the 'A' has no ink in its cell's top-left pixel */
    pc_text(c, 0, 0, "A\xce\xb1\xe4\xb8\xad", PC_ANCHOR_SE, 0, 1, 15);   /* A, alpha, CJK */
    assert_int_equal(at(c, 0, 0), 5);
    pc_pset(c, 0, 0, 0);
    assert_glyph_at(c, 8, 0, pc_font_glyph(0x03b1), 1, 15);
    assert_glyph_at(c, 16, 0, pc_font_replacement, 1, 15);
    const char *bad[] = {"\xff", "ab\xc3", "\xc0\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80"};
    for (int i = 0; i < 5; i++) {
        assert_int_equal(pc_text(c, 0, 0, bad[i], PC_ANCHOR_SE, 0, 1, 15), PC_EARG);
        assert_non_null(strstr(c->error, "invalid UTF-8"));
    }
    assert_string_equal((pc_text(c, 0, 0, "ab\xc3", PC_ANCHOR_SE, 0, 1, 15), c->error),
                        "text: invalid UTF-8 at byte 3");
    assert_int_equal(pc_text(c, 0, 0, "x", PC_ANCHOR_SE, 0, 9, 15), PC_EARG);
    assert_string_equal(c->error, "text: scale must be an integer 1..8, got 9");
    assert_int_equal(pc_text(c, 0, 0, "x", PC_ANCHOR_AUTO + 1, 0, 1, 15), PC_EARG);
    assert_int_equal(pc_text(c, 0, 0, "x", PC_ANCHOR_SE, 0, 1, 16), PC_EARG);
    int w, h;
    assert_int_equal(pc_text_size("A\xce\xb1z", 3, &w, &h), PC_OK);
    assert_int_equal(w, 3 * 8 * 3);
    assert_int_equal(h, 48);
    assert_int_equal(pc_text_size("\xff", 1, &w, &h), PC_EARG);
    assert_int_equal(pc_text_size("a", 0, &w, &h), PC_EARG);
    pc_canvas_free(c);
}

/* The bounding box of the ink of colour col. */
typedef struct { int x0, y0, x1, y1; } box;

static box ink_box(const pc_canvas *c, int col) {
    box b = {c->width, c->height, -1, -1};
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++)
            if (at(c, x, y) == col) {
                if (x < b.x0) b.x0 = x;
                if (x > b.x1) b.x1 = x;
                if (y < b.y0) b.y0 = y;
                if (y > b.y1) b.y1 = y;
            }
    return b;
}

static void test_anchors(void **state) {
    (void)state;
    const int X = 60, Y = 40, g = 3;
    for (int a = PC_ANCHOR_C; a <= PC_ANCHOR_NW; a++) {
        pc_canvas *c = pc_canvas_new(120, 80, 16);
        assert_int_equal(pc_text(c, X, Y, "HH", a, g, 1, 15), PC_OK);
        box b = ink_box(c, 15);
        /* the cell box the op records, and the ink inside it */
        long left = lrint(c->ops[0].x1), top = lrint(c->ops[0].y1);
        assert_true(b.x0 >= left && b.x1 < left + 16 && b.y0 >= top && b.y1 < top + 16);
        int east = a == PC_ANCHOR_NE || a == PC_ANCHOR_E || a == PC_ANCHOR_SE;
        int west = a == PC_ANCHOR_NW || a == PC_ANCHOR_W || a == PC_ANCHOR_SW;
        int north = a == PC_ANCHOR_NW || a == PC_ANCHOR_N || a == PC_ANCHOR_NE;
        int south = a == PC_ANCHOR_SW || a == PC_ANCHOR_S || a == PC_ANCHOR_SE;
        if (east) { assert_true(b.x0 >= X + g); assert_int_equal(left, X + g); }
        else if (west) { assert_true(b.x1 <= X - g); assert_int_equal(left + 15, X - g); }
        else { assert_true(b.x0 < X && b.x1 > X); assert_int_equal(left, X - 8); }
        if (north) { assert_true(b.y1 <= Y - g); assert_int_equal(top + 15, Y - g); }
        else if (south) { assert_true(b.y0 >= Y + g); assert_int_equal(top, Y + g); }
        else { assert_true(b.y0 < Y && b.y1 > Y); assert_int_equal(top, Y - 8); }
        pc_canvas_free(c);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_font_has_vga_glyphs),
        cmocka_unit_test(test_font_box_drawings),
        cmocka_unit_test(test_text_pixels),
        cmocka_unit_test(test_text_is_transparent_and_utf8),
        cmocka_unit_test(test_anchors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
