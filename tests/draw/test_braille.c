/* The braille preview of the canvas: fitting to a terminal, exact cells of small drawings,
 * the colour of a cell, and the text with and without colour escapes. */
#define _GNU_SOURCE   /* open_memstream */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "braille.h"
#include "canvas.h"

static pc_canvas *small(int w, int h) {
    pc_canvas *c = pc_canvas_new(w, h, 16);
    assert_non_null(c);
    return c;
}

static void test_bits_follow_unicode_dot_numbers(void **state) {
    (void)state;
    /* dots 1 2 3 7 down the left column, 4 5 6 8 down the right (U+2801 is dot 1, ...) */
    assert_int_equal(pc_braille_bit(0, 0), 0x01);
    assert_int_equal(pc_braille_bit(0, 1), 0x02);
    assert_int_equal(pc_braille_bit(0, 2), 0x04);
    assert_int_equal(pc_braille_bit(1, 0), 0x08);
    assert_int_equal(pc_braille_bit(1, 1), 0x10);
    assert_int_equal(pc_braille_bit(1, 2), 0x20);
    assert_int_equal(pc_braille_bit(0, 3), 0x40);
    assert_int_equal(pc_braille_bit(1, 3), 0x80);
}

static void test_fit(void **state) {
    (void)state;
    int cols, rows;
    /* SCREEN 12 in 80x24 cells: 160x96 dots available; 480/96 = 5 pixels per dot wins */
    assert_true(pc_braille_fit(640, 480, 80, 24, &cols, &rows) == 5.0);
    assert_int_equal(cols, 64);
    assert_int_equal(rows, 24);
    /* 40 columns and plenty of rows: the width decides, 8 pixels per dot */
    assert_true(pc_braille_fit(640, 480, 40, 100, &cols, &rows) == 8.0);
    assert_int_equal(cols, 40);
    assert_int_equal(rows, 15);
    /* a small canvas is shown pixel for pixel, never enlarged */
    assert_true(pc_braille_fit(7, 5, 80, 24, &cols, &rows) == 1.0);
    assert_int_equal(cols, 4);
    assert_int_equal(rows, 2);
    /* a fractional scale keeps the aspect and stays inside the limits */
    double s = pc_braille_fit(640, 480, 50, 50, &cols, &rows);
    assert_true(s == 6.4);
    assert_int_equal(cols, 50);
    assert_int_equal(rows, 19);   /* 480 / 6.4 = 75 dots = 18.75 cells */
}

static void test_exact_cells_pixel_for_pixel(void **state) {
    (void)state;
    pc_canvas *c = small(4, 8);        /* 2 x 2 cells at scale 1 */
    pc_pset(c, 0, 0, 14);              /* cell (0,0), dot 1 */
    pc_pset(c, 1, 3, 14);              /* cell (0,0), dot 8 */
    pc_pset(c, 3, 4, 2);               /* cell (1,1), dot 4 */
    pc_line(c, 0, 7, 3, 7, 4);         /* the bottom row of dots of both lower cells */
    pc_braille_cell cells[4];
    pc_braille_render(c, 0, 1.0, 2, 2, cells);
    assert_int_equal(cells[0].bits, 0x81);
    assert_int_equal(cells[0].color, 14);
    assert_int_equal(cells[1].bits, 0x00);
    assert_int_equal(cells[1].color, -1);
    assert_int_equal(cells[2].bits, 0xc0);
    assert_int_equal(cells[2].color, 4);
    assert_int_equal(cells[3].bits, 0xc8);
    assert_int_equal(cells[3].color, 4);   /* two red pixels against one green */
    pc_canvas_free(c);
}

static void test_circle_cells_match_pixels(void **state) {
    (void)state;
    pc_canvas *c = small(16, 16);
    pc_circle(c, 8, 8, 6, 15, NAN, NAN, NAN);
    pc_braille_cell cells[8 * 4];
    pc_braille_render(c, 0, 1.0, 8, 4, cells);
    int set = 0;
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            const pc_braille_cell *cell = &cells[(y / 4) * 8 + x / 2];
            int dot = (cell->bits & pc_braille_bit(x % 2, y % 4)) != 0;
            int ink = c->pixels[y * 16 + x] != 0;
            if (dot != ink) fail_msg("pixel (%d, %d): dot %d, ink %d", x, y, dot, ink);
            set += dot;
        }
    assert_true(set > 30);
    /* the centre of the circle is empty, the top of the circle (8, 2) is set */
    assert_int_equal(cells[2 * 8 + 4].bits & pc_braille_bit(0, 0), 0);
    assert_true(cells[0 * 8 + 4].bits & pc_braille_bit(0, 2));
    pc_canvas_free(c);
}

static void test_reduction_keeps_thin_lines_and_majority_colour(void **state) {
    (void)state;
    pc_canvas *c = small(8, 16);       /* scale 2: 2 x 2 cells, each dot a 2x2 block */
    pc_pset(c, 5, 9, 12);              /* dot (2, 4): cell (1, 1), dot 1 */
    /* cell (0, 0): three pixels of colour 2 in one block, one of colour 4 in another */
    pc_pset(c, 0, 0, 2); pc_pset(c, 1, 0, 2); pc_pset(c, 0, 1, 2);
    pc_pset(c, 3, 7, 4);               /* dot (1, 3): dot 8 */
    /* cell (1, 0): one pixel each of 9 and 3: the tie goes to the lower attribute */
    pc_pset(c, 4, 0, 9); pc_pset(c, 7, 7, 3);
    pc_braille_cell cells[4];
    pc_braille_render(c, 0, 2.0, 2, 2, cells);
    assert_int_equal(cells[0].bits, 0x81);
    assert_int_equal(cells[0].color, 2);
    assert_int_equal(cells[1].bits, 0x81);
    assert_int_equal(cells[1].color, 3);
    assert_int_equal(cells[2].bits, 0);
    assert_int_equal(cells[3].bits, 0x01);
    assert_int_equal(cells[3].color, 12);
    /* a one-pixel line across a 640x480 screen survives a reduction to 5 pixels per dot */
    pc_canvas *big = pc_canvas_new_mode(12);
    pc_line(big, 0, 333, 639, 333, 15);
    int cols, rows;
    double s = pc_braille_fit(640, 480, 80, 24, &cols, &rows);
    pc_braille_cell *bc = calloc((size_t)cols * rows, sizeof *bc);
    pc_braille_render(big, 0, s, cols, rows, bc);
    /* y 333 is dot row 66 (333 / 5 = 66.6): cell row 16, dot row 2 */
    for (int col = 0; col < cols; col++) {
        assert_int_equal(bc[16 * cols + col].bits, pc_braille_bit(0, 2) | pc_braille_bit(1, 2));
        assert_int_equal(bc[15 * cols + col].bits, 0);
    }
    free(bc);
    pc_canvas_free(big);
    pc_canvas_free(c);
}

static void test_background_attribute(void **state) {
    (void)state;
    pc_canvas *c = small(2, 4);
    pc_color(c, 15, 1);
    pc_cls(c);                          /* everything is now attribute 1: the background */
    pc_pset(c, 1, 1, 15);
    pc_braille_cell cell;
    pc_braille_render(c, 1, 1.0, 1, 1, &cell);
    assert_int_equal(cell.bits, 0x10);
    assert_int_equal(cell.color, 15);
    pc_braille_render(c, 0, 1.0, 1, 1, &cell);   /* with 0 as paper, all of it is ink */
    assert_int_equal(cell.bits, 0xff);
    assert_int_equal(cell.color, 1);
    pc_canvas_free(c);
}

/* Print to a string. */
static char *print(const pc_braille_cell *cells, int cols, int rows, const pc_rgb *pal,
                   pc_term_colors mode, int frame) {
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    assert_int_equal(pc_braille_print(f, cells, cols, rows, pal, mode, frame), 0);
    fclose(f);
    return buf;
}

static void test_text(void **state) {
    (void)state;
    pc_rgb pal[256];
    pc_palette_default(pal, 16);
    pc_braille_cell cells[3] = {{0x01, 4}, {0, -1}, {0xff, 15}};
    char *s = print(cells, 3, 1, pal, PC_TERM_MONO, 0);
    assert_string_equal(s, "\u2801 \u28ff\n");
    free(s);
    s = print(cells, 3, 1, pal, PC_TERM_MONO, 1);
    assert_string_equal(s, "\u250c\u2500\u2500\u2500\u2510\n"
                           "\u2502\u2801 \u28ff\u2502\n"
                           "\u2514\u2500\u2500\u2500\u2518\n");
    free(s);
    /* red ink (VGA 4 = #aa0000) is ANSI red; white ink is the terminal's own foreground */
    s = print(cells, 3, 1, pal, PC_TERM_16, 0);
    assert_string_equal(s, "\x1b[31m\u2801 \x1b[39m\u28ff\n");
    free(s);
    s = print(cells, 3, 1, pal, PC_TERM_RGB, 0);
    assert_string_equal(s, "\x1b[38;2;170;0;0m\u2801 \x1b[39m\u28ff\n");
    free(s);
    cells[2].color = 14;
    s = print(cells, 3, 1, pal, PC_TERM_256, 0);
    /* #aa0000 -> cube (3, 0, 0) = 124; #ffff55 -> cube (5, 5, 1) = 227 */
    assert_string_equal(s, "\x1b[38;5;124m\u2801 \x1b[38;5;227m\u28ff\x1b[39m\n");
    free(s);
    char sgr[24];
    assert_string_equal(pc_term_color((pc_rgb){0x55, 0x55, 0x55}, PC_TERM_256, sgr), "38;5;240");
    assert_string_equal(pc_term_color((pc_rgb){0xff, 0xff, 0x55}, PC_TERM_16, sgr), "93");
    assert_string_equal(pc_term_color((pc_rgb){0, 0, 0xaa}, PC_TERM_16, sgr), "34");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bits_follow_unicode_dot_numbers),
        cmocka_unit_test(test_fit),
        cmocka_unit_test(test_exact_cells_pixel_for_pixel),
        cmocka_unit_test(test_circle_cells_match_pixels),
        cmocka_unit_test(test_reduction_keeps_thin_lines_and_majority_colour),
        cmocka_unit_test(test_background_attribute),
        cmocka_unit_test(test_text),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
