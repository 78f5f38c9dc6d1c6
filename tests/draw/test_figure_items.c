/* Figure items (figure_items.c): a caption and device-unit text keep their pixels whatever the
 * window, axes{} without options span the window, a graph breaks where f has no value (a lone
 * point draws nothing), and the labels come back as a writer places them. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"
#include "axes.h"
#include "furniture.h"
#include "layout.h"
#include "print.h"

static int px(const pc_canvas *c, int x, int y) { return c->pixels[(size_t)y * c->width + x]; }

static int ink(const pc_canvas *c, int x0, int y0, int x1, int y1, int col) {
    int n = 0;
    for (int y = y0; y <= y1; y++)
        for (int x = x0; x <= x1; x++) n += px(c, x, y) == col;
    return n;
}

static void test_caption_and_device_text(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_window(c, -1, -1, 1, 1, 0), PC_OK);
    assert_int_equal(pc_view(c, 100, 100, 200, 200, -1, -1, 1), PC_OK);
    assert_int_equal(pc_caption(c, "AB", 0, 14), PC_OK);
    assert_true(c->ops[c->nops - 1].flags & PC_TEXT_DEVICE);
    assert_int_equal(c->view.x0, 100);   /* the view is back */
    /* two 8x16 cells centred on x = 320, 3 px above the bottom row */
    assert_true(ink(c, 312, 460, 327, 476, 14) > 10);
    assert_int_equal(ink(c, 0, 0, 639, 459, 14), 0);
    assert_int_equal(pc_caption(c, "T", 1, 13), PC_OK);
    assert_true(ink(c, 316, 3, 323, 19, 13) > 4);
    assert_int_equal(pc_view_reset(c), PC_OK);
    assert_int_equal(pc_text_device(c, 40, 50, "X", 1, 12), PC_OK);
    assert_true(c->ops[c->nops - 1].flags & PC_TEXT_DEVICE);
    assert_true(ink(c, 40, 50, 47, 65, 12) > 4);
    assert_int_equal(ink(c, 0, 0, 39, 479, 12) + ink(c, 48, 0, 639, 479, 12), 0);
    pc_canvas_free(c);
}

static void test_axes_default(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_window(c, 3, 4, -1, -2, 0), PC_OK);
    pc_axes_spec s;
    pc_axes_default(c, &s);
    assert_true(fabs(s.x0 + 1) < 1e-9 && fabs(s.x1 - 3) < 1e-9);
    assert_true(fabs(s.y0 + 2) < 1e-9 && fabs(s.y1 - 4) < 1e-9);
    assert_int_equal(s.ticks, 5);
    assert_int_equal(s.labels, 1);
    assert_int_equal(s.arrows, 1);
    assert_int_equal(s.grid, 0);
    assert_int_equal(s.grid_color, -1);
    pc_canvas_free(c);
}

/* y = 100 left of x = 50, 200 right of x = 60, nothing between; calls counted */
static int step(void *ctx, double x, double *y, int *have) {
    ++*(int *)ctx;
    *have = x < 50 || x > 60;
    *y = x < 50 ? 100 : 200;
    return PC_OK;
}

static int lone(void *ctx, double x, double *y, int *have) {
    (void)ctx;
    *y = 10;
    *have = fabs(x - 50) < 1e-9;
    return PC_OK;
}

static int failing(void *ctx, double x, double *y, int *have) {
    (void)ctx, (void)y, (void)have;
    return x > 30 ? PC_EARG : PC_OK;
}

static void test_graph(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    int calls = 0;
    assert_int_equal(pc_graph(c, 0, 100, 10, step, &calls, 9), PC_OK);
    assert_int_equal(calls, 11);
    assert_int_equal(px(c, 20, 100), 9);
    assert_int_equal(px(c, 80, 200), 9);
    assert_int_equal(ink(c, 51, 0, 69, 479, 9), 0);   /* broken over the gap */
    size_t ops = c->nops;
    assert_int_equal(pc_graph(c, 0, 100, 10, lone, NULL, 9), PC_OK);
    assert_int_equal(c->nops, ops);   /* one point alone: nothing */
    assert_int_equal(pc_graph(c, 0, 100, 10, failing, NULL, 9), PC_EARG);
    assert_int_equal(c->nops, ops);
    pc_canvas_free(c);
}

static void test_placed_labels(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_text(c, 100, 200, "AB", PC_ANCHOR_NE, 3, 1, 15), PC_OK);
    assert_int_equal(pc_text(c, 300, 300, "C", PC_ANCHOR_AUTO, 3, 1, 15), PC_OK);
    size_t n;
    pc_placed *p = pc_placed_labels(c, &n);
    assert_non_null(p);
    assert_int_equal(n, 2);
    assert_string_equal(p[0].text, "AB");
    assert_int_equal(p[0].len, 2);
    assert_string_equal(p[0].side, "ne");
    assert_int_equal(p[0].autoplaced, 0);
    assert_true(fabs(p[0].box.x1 - p[0].box.x0 - 16) < 1e-9);
    assert_true(fabs(p[0].box.y1 - p[0].box.y0 - 16) < 1e-9);
    assert_true(p[0].box.x0 > 100 && p[0].box.y1 < 200);   /* north-east of the point */
    assert_string_equal(p[1].text, "C");
    assert_int_equal(p[1].autoplaced, 1);
    assert_true(fabs(p[1].box.x1 - p[1].box.x0 - 8) < 1e-9);
    free(p);
    pc_canvas_free(c);
}

/* path{}: a head at the end only, a filled square with and without its outline */
static void test_path_stmt(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    double xy[4] = {100, 100, 200, 100};
    assert_int_equal(pc_path_stmt(c, 2, xy, NULL, 0, 14, PC_ARROW_END, 0, -1, PC_FILL_EVENODD), PC_OK);
    assert_int_equal(px(c, 150, 100), 14);
    assert_true(ink(c, 190, 97, 199, 103, 14) > 12);   /* the head's triangle at B */
    assert_int_equal(ink(c, 100, 96, 110, 99, 14) + ink(c, 100, 101, 110, 104, 14), 0);   /* none at A */
    double sq[8] = {300, 300, 340, 300, 340, 340, 300, 340};
    assert_int_equal(pc_path_stmt(c, 4, sq, NULL, 0, -1, 0, 1, 9, PC_FILL_EVENODD), PC_OK);
    assert_int_equal(px(c, 320, 320), 9);
    assert_int_equal(px(c, 300, 320), 9);   /* no outline: the fill's own edge pixel */
    double sq2[8] = {400, 300, 440, 300, 440, 340, 400, 340};
    assert_int_equal(pc_path_stmt(c, 4, sq2, NULL, 0, 12, 0, 1, 9, PC_FILL_EVENODD), PC_OK);
    assert_int_equal(px(c, 420, 320), 9);
    assert_int_equal(px(c, 400, 320), 12);   /* the outline on top */
    assert_int_equal(px(c, 420, 340), 12);
    pc_canvas_free(c);
}

/* fit{}: each framing refuses the other's option; around sets the window round the points */
static void test_fit_options(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    double xy[4] = {0, 0, 4, 3};
    pc_fit_opts o = {.has_margin = 1, .margin = 5, .around = 1, .n = 2, .xy = xy};
    assert_int_equal(pc_fit_options(c, &o), PC_EARG);
    assert_string_equal(c->error, "margin frames what is drawn (in pixels); with around give pad (world units)");
    o = (pc_fit_opts){.has_pad = 1, .pad = 1};
    assert_int_equal(pc_fit_options(c, &o), PC_EARG);
    assert_string_equal(c->error, "pad is the room round the points of around: give around too (or margin)");
    o = (pc_fit_opts){.has_band = 1, .band = 20};
    assert_int_equal(pc_fit_options(c, &o), PC_EARG);
    assert_string_equal(c->error, "band is the caption's room under the points of around: give around too");
    o = (pc_fit_opts){.around = 1, .n = 2, .xy = xy, .aspect = PC_FIT_FILL};
    assert_int_equal(pc_fit_options(c, &o), PC_OK);
    double sx, sy;
    pc_world_to_screen(c, 4, 3, &sx, &sy);   /* the box itself fills the view, y up */
    assert_true(fabs(sx - 639) < 1e-6 && fabs(sy) < 1e-6);
    pc_world_to_screen(c, 0, 0, &sx, &sy);
    assert_true(fabs(sx) < 1e-6 && fabs(sy - 479) < 1e-6);
    pc_canvas_free(c);
}

/* pen{}: pixels or lengths, never mixed */
static void test_pen_options(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    double px_dash[2] = {4, 2}, pt_dash[2] = {8.5, 4.25};
    pc_pen_opts o = {.has_width = 1, .width = 3, .has_dash = 1, .ndash = 2, .dash = px_dash};
    assert_int_equal(pc_pen_options(c, &o), PC_OK);
    assert_true(fabs(c->pens[c->pen].width - 3) < 1e-9);
    o = (pc_pen_opts){.has_width = 1, .width = 2, .has_dash = 1, .dash_len = 1, .ndash = 2, .dash = pt_dash};
    assert_int_equal(pc_pen_options(c, &o), PC_EARG);
    assert_string_equal(c->error, "option 'width' must be a length with its unit, as the dash is, got 2");
    o = (pc_pen_opts){.has_width = 1, .width_len = 1, .width = 1.42, .has_dash = 1, .ndash = 0};
    assert_int_equal(pc_pen_options(c, &o), PC_EARG);
    assert_string_equal(c->error, "option 'dash' must hold lengths with their units, as the width is");
    pc_canvas_free(c);
}

/* axes{}: the window's ranges unless given, checked; the ticks counted */
static void test_axes_options(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_window(c, -5, -5, 5, 5, 0), PC_OK);
    const double x[2] = {0, 4}, bad[2] = {2, 1}, origin[2] = {1, 1};
    pc_axes_opts o = {.x = x, .origin = origin, .ticks = 4, .labels = 0, .arrows = 0, .grid_color = -1};
    int n = 0;
    assert_int_equal(pc_axes_options(c, &o, 15, &n), PC_OK);
    assert_int_equal(n, 5 + 5);   /* 0..4 by 1 on x; -4..4 by 2 on y, the window's range */
    o.y = bad;
    assert_int_equal(pc_axes_options(c, &o, 15, &n), PC_EARG);
    assert_string_equal(c->error, "option 'y' must be {lo, hi} with lo < hi");
    o = (pc_axes_opts){.x = bad};
    assert_int_equal(pc_axes_options(c, &o, 15, &n), PC_EARG);
    assert_string_equal(c->error, "option 'x' must be {lo, hi} with lo < hi");
    pc_canvas_free(c);
}

/* figure{}: the options given over the canvas's figure, framed; a width alone clears the height */
static void test_figure_options(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_figure_opts o = {.has_width = 1, .has_height = 1, .width = 300, .height = 200, .has_dpi = 1, .dpi = 150,
                        .font = "sans", .has_size = 1, .size = 9};
    assert_int_equal(pc_figure_options(c, &o), PC_OK);
    assert_true(c->figure.on && c->figure.frame);
    assert_true(c->figure.width == 300 && c->figure.height == 200 && c->figure.dpi == 150 && c->figure.size == 9);
    assert_string_equal(c->figure.font, "sans");
    o = (pc_figure_opts){.has_width = 1, .width = 400};
    assert_int_equal(pc_figure_options(c, &o), PC_OK);
    assert_true(c->figure.width == 400 && c->figure.height == 0 && c->figure.dpi == 150);
    assert_string_equal(c->figure.font, "sans");
    char long_font[80];
    memset(long_font, 'a', sizeof long_font - 1);
    long_font[sizeof long_font - 1] = 0;
    o = (pc_figure_opts){.font = long_font};
    assert_int_equal(pc_figure_options(c, &o), PC_EARG);
    assert_string_equal(c->error, "option 'font' is too long");
    o = (pc_figure_opts){.has_dpi = 1, .dpi = 5};
    assert_int_equal(pc_figure_options(c, &o), PC_EARG);
    assert_string_equal(c->error, "figure: dpi must be 10..2400, got 5");
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_caption_and_device_text), cmocka_unit_test(test_axes_default),
        cmocka_unit_test(test_graph), cmocka_unit_test(test_placed_labels), cmocka_unit_test(test_path_stmt),
        cmocka_unit_test(test_fit_options), cmocka_unit_test(test_pen_options),
        cmocka_unit_test(test_axes_options), cmocka_unit_test(test_figure_options)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
