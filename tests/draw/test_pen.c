/* Exact-pixel tests of paths, the pen (widths and dashes) and QBasic's LINE style. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"

static pc_canvas *small(int w, int h) {
    pc_canvas *c = pc_canvas_new(w, h, 16);
    assert_non_null(c);
    return c;
}

static int at(const pc_canvas *c, int x, int y) { return c->pixels[y * c->width + x]; }

static int count(const pc_canvas *c, int color) {
    int n = 0;
    for (int i = 0; i < c->width * c->height; i++) n += c->pixels[i] == color;
    return n;
}

static void assert_same_pixels(const pc_canvas *a, const pc_canvas *b) {
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++)
            if (at(a, x, y) != at(b, x, y))
                fail_msg("pixel (%d, %d): %d against %d", x, y, at(a, x, y), at(b, x, y));
}

/* Row y from x0 to x1 against a string of '#' (colour) and '.' (background). */
static void assert_row(const pc_canvas *c, int y, int x0, const char *want, int color) {
    for (int i = 0; want[i]; i++) {
        int got = at(c, x0 + i, y);
        if ((want[i] == '#') != (got == color))
            fail_msg("pixel (%d, %d) is %d: want %s", x0 + i, y, got, want[i] == '#' ? "ink" : "none");
    }
}

static void assert_column(const pc_canvas *c, int x, int y0, const char *want, int color) {
    for (int i = 0; want[i]; i++) {
        int got = at(c, x, y0 + i);
        if ((want[i] == '#') != (got == color))
            fail_msg("pixel (%d, %d) is %d: want %s", x, y0 + i, got, want[i] == '#' ? "ink" : "none");
    }
}

/* ---- paths -------------------------------------------------------------------------------- */

static void test_polyline_is_its_lines(void **state) {
    (void)state;
    const double xy[] = {3.2, 4.7, 40.5, 9.1, 22.4, 37.6, 61, 44, 60.5, 2.5};
    pc_canvas *a = small(64, 48), *b = small(64, 48);
    assert_int_equal(pc_path(a, 5, xy, NULL, 0, 0, 9), PC_OK);
    for (int i = 0; i < 4; i++) pc_line(b, xy[2 * i], xy[2 * i + 1], xy[2 * i + 2], xy[2 * i + 3], 9);
    assert_same_pixels(a, b);
    assert_true(count(a, 9) > 100);
    /* the graphics cursor is at the last point */
    assert_true(a->last_x == 60.5 && a->last_y == 2.5);
    /* closed: one more line back to the start */
    pc_canvas *d = small(64, 48);
    assert_int_equal(pc_path(d, 5, xy, NULL, 0, 1, 9), PC_OK);
    pc_line(b, 60.5, 2.5, 3.2, 4.7, 9);
    assert_same_pixels(d, b);
    /* through WINDOW, like every statement */
    pc_canvas *e = small(64, 48), *f = small(64, 48);
    pc_window(e, 0, 0, 10, 10, 0);
    pc_window(f, 0, 0, 10, 10, 0);
    const double w[] = {1, 1, 9, 2, 5, 8};
    assert_int_equal(pc_path(e, 3, w, NULL, 0, 0, 4), PC_OK);
    pc_line(f, 1, 1, 9, 2, 4);
    pc_line(f, 9, 2, 5, 8, 4);
    assert_same_pixels(e, f);
    pc_canvas_free(a); pc_canvas_free(b); pc_canvas_free(d); pc_canvas_free(e); pc_canvas_free(f);
}

static void test_cubic_lies_on_its_curve(void **state) {
    (void)state;
    pc_canvas *c = small(80, 60);
    const double xy[] = {5, 50, 15, 2, 60, 2, 74, 50};
    const uint8_t verbs[] = {PC_PATH_MOVE, PC_PATH_CUBIC};
    assert_int_equal(pc_path(c, 4, xy, verbs, 2, 0, 14), PC_OK);
    /* the exact curve, densely */
    enum { N = 20000 };
    static double cx[N + 1], cy[N + 1];
    for (int i = 0; i <= N; i++) {
        double t = (double)i / N, u = 1 - t;
        cx[i] = u * u * u * 5 + 3 * u * u * t * 15 + 3 * u * t * t * 60 + t * t * t * 74;
        cy[i] = u * u * u * 50 + 3 * u * u * t * 2 + 3 * u * t * t * 2 + t * t * t * 50;
    }
    int ink = 0;
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++) {
            if (at(c, x, y) != 14) continue;
            ink++;
            double best = 1e9;
            for (int i = 0; i <= N; i++) best = fmin(best, hypot(cx[i] - x, cy[i] - y));
            if (best > 1.0) fail_msg("pixel (%d, %d) is %.3f px off the curve", x, y, best);
        }
    /* and the curve is covered: every point of it has ink within a pixel */
    for (int i = 0; i <= N; i += 50) {
        int near = 0;
        for (int dy = -1; dy <= 1 && !near; dy++)
            for (int dx = -1; dx <= 1 && !near; dx++) {
                int x = (int)lrint(cx[i]) + dx, y = (int)lrint(cy[i]) + dy;
                near = at(c, x, y) == 14;
            }
        if (!near) fail_msg("no ink near the curve at t = %g", (double)i / N);
    }
    assert_true(ink > 90);
    assert_int_equal(at(c, 5, 50), 14);
    assert_int_equal(at(c, 74, 50), 14);
    pc_canvas_free(c);
}

static void test_move_breaks_the_path(void **state) {
    (void)state;
    pc_canvas *c = small(64, 20);
    const double xy[] = {5, 10, 20, 10, 40, 10, 55, 10, 50, 15};
    const uint8_t verbs[] = {PC_PATH_MOVE, PC_PATH_LINE, PC_PATH_MOVE, PC_PATH_LINE, PC_PATH_MOVE};
    assert_int_equal(pc_path(c, 5, xy, verbs, 5, 0, 2), PC_OK);
    assert_row(c, 10, 4, ".################...................################.", 2);
    /* a subpath of a single point draws nothing */
    assert_int_equal(count(c, 2), 32);
    pc_canvas_free(c);
}

static void test_path_errors(void **state) {
    (void)state;
    pc_canvas *c = small(64, 20);
    const double xy[] = {1, 1, 2, 2, 3, 3, 4, 4};
    const uint8_t bad_first[] = {PC_PATH_LINE, PC_PATH_LINE};
    assert_int_equal(pc_path(c, 2, xy, bad_first, 2, 0, 1), PC_EARG);
    assert_string_equal(c->error, "path: the first verb must be a move");
    const uint8_t cubic[] = {PC_PATH_MOVE, PC_PATH_CUBIC};
    assert_int_equal(pc_path(c, 3, xy, cubic, 2, 0, 1), PC_EARG);
    assert_string_equal(c->error, "path: 3 points are too few for the verbs");
    assert_int_equal(pc_path(c, 4, xy, cubic + 1, 1, 0, 1), PC_EARG);
    const uint8_t moves[] = {PC_PATH_MOVE, PC_PATH_LINE};
    assert_int_equal(pc_path(c, 4, xy, moves, 2, 0, 1), PC_EARG);
    assert_string_equal(c->error, "path: the verbs take 2 points, 4 were given");
    assert_int_equal(pc_path(c, 0, xy, NULL, 0, 0, 1), PC_EARG);
    const double nan_xy[] = {1, 1, NAN, 2};
    assert_int_equal(pc_path(c, 2, nan_xy, NULL, 0, 0, 1), PC_EARG);
    const double far[] = {-1e20, -1e20, 1e20, 1e20};
    assert_int_equal(pc_path(c, 2, far, NULL, 0, 0, 1), PC_EARG);
    /* nothing was drawn or recorded by the refused paths */
    assert_int_equal(count(c, 1), 0);
    assert_int_equal(c->nops, 0);
    assert_int_equal(c->npts, 0);
    pc_canvas_free(c);
}

/* ---- dashes and widths -------------------------------------------------------------------- */

static void test_dashed_line(void **state) {
    (void)state;
    pc_canvas *c = small(40, 10);
    const double dash[] = {4, 2};
    assert_int_equal(pc_pen(c, 1, dash, 2), PC_OK);
    pc_line(c, 10, 2, 30, 2, 7);
    assert_row(c, 2, 9, ".####..####..####..###.", 7);
    /* drawn the other way, the dashes are measured from its own start */
    pc_line(c, 30, 5, 10, 5, 7);
    assert_row(c, 5, 9, ".###..####..####..####.", 7);
    /* the op remembers the pen; the same pen is one entry of the table */
    assert_int_not_equal(c->ops[0].pen, 0);
    assert_int_equal(c->ops[0].pen, c->ops[1].pen);
    pc_pen_reset(c);
    pc_line(c, 10, 8, 30, 8, 7);
    assert_row(c, 8, 9, ".#####################.", 7);
    assert_int_equal(c->ops[2].pen, 0);
    pc_canvas_free(c);
}

static void test_dash_phase_runs_across_vertices(void **state) {
    (void)state;
    pc_canvas *c = small(30, 30);
    const double dash[] = {3, 3};
    pc_pen(c, 1, dash, 2);
    const double xy[] = {10, 5, 15, 5, 15, 20};
    pc_path(c, 3, xy, NULL, 0, 0, 3);
    /* distance 0..5 along the row, then 5..20 down the column */
    assert_row(c, 5, 9, ".###...", 3);
    assert_column(c, 15, 5, ".###...###...###.", 3);
    /* the next op starts its own pattern */
    const double xy2[] = {20, 10, 28, 10};
    pc_path(c, 2, xy2, NULL, 0, 0, 3);
    assert_row(c, 10, 20, "###...##", 3);
    pc_canvas_free(c);
}

static void test_wide_lines(void **state) {
    (void)state;
    pc_canvas *c = small(32, 20);
    assert_int_equal(pc_pen(c, 3, NULL, 0), PC_OK);
    pc_line(c, 10, 10, 20, 10, 5);
    /* a 3x3 disc at every pixel: rows 9..11, one pixel past each end (round caps) */
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++) {
            int want = y >= 9 && y <= 11 && x >= 9 && x <= 21;
            if ((at(c, x, y) == 5) != want) fail_msg("width 3: pixel (%d, %d)", x, y);
        }
    /* width 2 is 2 pixels thick: the disc's centre is the pixel's lower-right corner */
    pc_cls(c);
    pc_pen(c, 2, NULL, 0);
    pc_line(c, 10, 5, 20, 5, 5);
    assert_int_equal(count(c, 5), 2 * 12);
    assert_row(c, 5, 9, ".############.", 5);
    assert_row(c, 6, 9, ".############.", 5);
    assert_row(c, 4, 9, "..............", 5);
    /* a wide dashed line: discs only at the pixels in a dash */
    pc_cls(c);
    const double dash[] = {2, 4};
    pc_pen(c, 3, dash, 2);
    pc_line(c, 4, 10, 16, 10, 5);
    assert_row(c, 10, 2, ".####..####..###.", 5);   /* on at 4, 5; 10, 11; 16 */
    /* SCREEN restores the default pen */
    pc_canvas_reset(c, 32, 20, 16);
    assert_int_equal(c->pen, 0);
    assert_int_equal(c->npens, 1);
    pc_canvas_free(c);
}

static void test_pen_errors(void **state) {
    (void)state;
    pc_canvas *c = small(8, 8);
    const double d[] = {1, 2, 3, 0};
    assert_int_equal(pc_pen(c, 0.5, NULL, 0), PC_EARG);
    assert_string_equal(c->error, "pen: width must be 1..256 pixels, got 0.5");
    assert_int_equal(pc_pen(c, 300, NULL, 0), PC_EARG);
    assert_int_equal(pc_pen(c, 1, d, 3), PC_EARG);
    assert_string_equal(c->error, "pen: a dash pattern has an even number of lengths, at most 16, got 3");
    assert_int_equal(pc_pen(c, 1, d, 18), PC_EARG);
    assert_int_equal(pc_pen(c, 1, d, 4), PC_EARG);
    assert_string_equal(c->error, "pen: dash length 4 must be a positive number of pixels, got 0");
    assert_int_equal(c->pen, 0);   /* a refused pen leaves the pen as it was */
    pc_canvas_free(c);
}

static void test_boxes_and_circles_with_a_pen(void **state) {
    (void)state;
    pc_canvas *c = small(64, 64), *plain = small(64, 64);
    pc_pen(c, 3, NULL, 0);
    pc_box(c, 10, 10, 20, 16, 2, 0);
    /* the outline grown by one pixel each way; the inside stays empty */
    for (int y = 0; y < 30; y++)
        for (int x = 0; x < 30; x++) {
            int outer = x >= 9 && x <= 21 && y >= 9 && y <= 17;
            int inner = x >= 12 && x <= 18 && y >= 12 && y <= 14;
            if ((at(c, x, y) == 2) != (outer && !inner)) fail_msg("wide box: pixel (%d, %d)", x, y);
        }
    /* a filled box is not stroked */
    pc_box(c, 40, 2, 44, 4, 3, 1);
    assert_int_equal(count(c, 3), 15);
    /* a wide circle covers the plain one's pixels and lies within a disc of them */
    pc_circle(c, 32, 44, 10, 4, NAN, NAN, NAN);
    pc_circle(plain, 32, 44, 10, 4, NAN, NAN, NAN);
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            if (at(plain, x, y) == 4) assert_int_equal(at(c, x, y), 4);
            if (at(c, x, y) == 4) {
                double r = hypot(x - 32, y - 44);
                if (r < 8 || r > 12) fail_msg("wide circle: pixel (%d, %d) at %g", x, y, r);
            }
        }
    /* dashed: measured from angle 0 counter-clockwise, arc length r * angle */
    pc_canvas *d = small(64, 64);
    const double dash[] = {5, 5};
    pc_pen(d, 1, dash, 2);
    pc_circle(d, 32, 32, 10, 6, NAN, NAN, NAN);
    assert_int_equal(at(d, 42, 32), 6);   /* angle 0: distance 0, on */
    assert_int_equal(at(d, 32, 22), 0);   /* pi/2: 15.7, off */
    assert_int_equal(at(d, 22, 32), 6);   /* pi: 31.4, on */
    assert_int_equal(at(d, 32, 42), 0);   /* 3pi/2: 47.1, off */
    int dashed = count(d, 6), all = count(plain, 4);
    assert_true(dashed > all / 2 - 8 && dashed < all / 2 + 8);
    pc_canvas_free(c); pc_canvas_free(plain); pc_canvas_free(d);
}

/* ---- QBasic's LINE style ------------------------------------------------------------------ */

static void test_qbasic_line_style(void **state) {
    (void)state;
    pc_canvas *c = small(40, 40);
    /* &HAAAA: every other pixel, from the first */
    assert_int_equal(pc_line_styled(c, 5, 0, 5, 15, 9, 0, 0xAAAA), PC_OK);
    assert_column(c, 5, 0, "#.#.#.#.#.#.#.#.", 9);
    /* &HFF00: eight on, eight off from the first pixel, the pattern repeating */
    pc_line_styled(c, 3, 0, 3, 39, 9, 0, 0xFF00);
    assert_column(c, 3, 0, "########........########........########", 9);
    /* walked from the upper end: drawn upwards it gives the same pixels */
    pc_line_styled(c, 7, 39, 7, 0, 9, 0, 0xFF00);
    assert_column(c, 7, 0, "########........########........########", 9);
    /* a level line starts at its second point, as GW-BASIC draws it */
    pc_line_styled(c, 10, 20, 39, 20, 9, 0, 0xFF00);
    assert_row(c, 20, 10, "......########........########", 9);
    /* each LINE restarts the pattern */
    pc_line_styled(c, 10, 30, 13, 30, 9, 0, 0xAAAA);
    pc_line_styled(c, 14, 30, 17, 30, 9, 0, 0xAAAA);
    assert_row(c, 30, 10, ".#.#.#.#", 9);
    /* a diagonal: one bit per step along the major axis */
    pc_cls(c);
    pc_line_styled(c, 0, 0, 7, 3, 9, 0, 0xAAAA);
    assert_int_equal(count(c, 9), 4);
    assert_int_equal(at(c, 0, 0), 9);
    assert_int_equal(at(c, 2, 1), 9);
    pc_canvas_free(c);
}

static void test_qbasic_box_style(void **state) {
    (void)state;
    pc_canvas *c = small(20, 20), *b = small(20, 20);
    /* &HFFFF is the plain box */
    pc_line_styled(c, 2, 2, 9, 6, 5, 1, 0xFFFF);
    pc_box(b, 2, 2, 9, 6, 5, 0);
    assert_same_pixels(c, b);
    /* &H8000: bit 15 only, every 16th pixel of the run bottom, top, right, left: the
     * bottom side starts at the second corner (bit 0), the right side's top is bit 16 */
    pc_cls(c);
    pc_line_styled(c, 2, 2, 9, 6, 5, 1, 0x8000);
    assert_int_equal(count(c, 5), 2);
    assert_int_equal(at(c, 9, 6), 5);
    assert_int_equal(at(c, 9, 2), 5);
    /* the op records the style, not the pen */
    assert_int_equal(c->pens[c->ops[c->nops - 1].pen].style, 0x18000u);
    pc_canvas_free(c);
    pc_canvas_free(b);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_polyline_is_its_lines),
        cmocka_unit_test(test_cubic_lies_on_its_curve),
        cmocka_unit_test(test_move_breaks_the_path),
        cmocka_unit_test(test_path_errors),
        cmocka_unit_test(test_dashed_line),
        cmocka_unit_test(test_dash_phase_runs_across_vertices),
        cmocka_unit_test(test_wide_lines),
        cmocka_unit_test(test_pen_errors),
        cmocka_unit_test(test_boxes_and_circles_with_a_pen),
        cmocka_unit_test(test_qbasic_line_style),
        cmocka_unit_test(test_qbasic_box_style),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
