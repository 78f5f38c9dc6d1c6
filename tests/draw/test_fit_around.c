/* Framing given points before drawing (layout.h: pc_fit_around): the window round their box
 * plus pad, equal units at the view's aspect (one world unit the same number of pixels on
 * both axes), centred; or the box itself plus pad; errors named. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"
#include "layout.h"

/* pixels per world unit on each axis of the current window */
static void units(const pc_canvas *c, double *ux, double *uy) {
    *ux = (c->view.x1 - c->view.x0) / (c->wx2 - c->wx1);
    *uy = (c->view.y1 - c->view.y0) / (c->wy2 - c->wy1);
}

static void test_equal_units(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    /* the triangle (0,0), (4,0), (2,3): its height 3 decides (4 * 479/639 < 3), pad 0.5 */
    const double tri[] = {0, 0, 4, 0, 2, 3};
    assert_int_equal(pc_fit_around(c, 3, tri, 0.5, PC_FIT_EQUAL), PC_OK);
    assert_true(c->has_window && !c->window_screen);
    assert_true(fabs(c->wy1 - -0.5) < 1e-12 && fabs(c->wy2 - 3.5) < 1e-12);
    assert_true(fabs(c->wx1 - (2 - 2.0 * 639 / 479)) < 1e-12 && fabs(c->wx2 - (2 + 2.0 * 639 / 479)) < 1e-12);
    double ux, uy, sx, sy;
    units(c, &ux, &uy);
    assert_true(fabs(ux - uy) < 1e-9 * ux);
    pc_world_to_screen(c, 2, 1.5, &sx, &sy);   /* the box's centre at the view's */
    assert_true(fabs(sx - 319.5) < 1e-9 && fabs(sy - 239.5) < 1e-9);
    pc_world_to_screen(c, 2, 3, &sx, &sy);     /* the apex pad * 479/4 = 59.875 px below the top */
    assert_true(fabs(sy - 479.0 / 8) < 1e-9);
    /* a wide box: its width decides, the pad on each side in x too */
    const double wide[] = {0, 0, 10, 1};
    assert_int_equal(pc_fit_around(c, 2, wide, 1, PC_FIT_EQUAL), PC_OK);
    units(c, &ux, &uy);
    assert_true(fabs(ux - uy) < 1e-9 * ux);
    assert_true(fabs(c->wx1 - (0 - 639.0 / 479)) < 1e-12 && fabs(c->wx2 - (10 + 639.0 / 479)) < 1e-12);
    pc_canvas_free(c);
}

static void test_view_aspect_and_fill(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_view(c, 100, 100, 399, 199, -1, -1, 1), PC_OK);   /* a 299:99 span */
    const double sq[] = {-1, -1, 1, 1};
    assert_int_equal(pc_fit_around(c, 2, sq, 0, PC_FIT_EQUAL), PC_OK);
    double ux, uy;
    units(c, &ux, &uy);
    assert_true(fabs(ux - uy) < 1e-9 * ux);
    assert_true(fabs(c->wy1 - -1) < 1e-12 && fabs(c->wy2 - 1) < 1e-12);
    /* fill: the box plus pad on each axis, whatever the aspect */
    assert_int_equal(pc_fit_around(c, 2, sq, 0.25, PC_FIT_FILL), PC_OK);
    assert_true(c->wx1 == -1.25 && c->wx2 == 1.25 && c->wy1 == -1.25 && c->wy2 == 1.25);
    pc_canvas_free(c);
}

static void test_drawn_stays(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_line(c, 10, 20, 30, 40, 15);
    size_t nops = c->nops;
    pc_op before = c->ops[0];
    const double p[] = {0, 0, 1, 1};
    assert_int_equal(pc_fit_around(c, 2, p, 0.1, PC_FIT_EQUAL), PC_OK);
    assert_int_equal(c->nops, nops);
    assert_true(c->ops[0].x1 == before.x1 && c->ops[0].y2 == before.y2);
    pc_canvas_free(c);
}

static void test_errors(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    const double one[] = {2, 3}, bad[] = {0, 0, NAN, 1}, two[] = {0, 0, 1, 1};
    assert_int_equal(pc_fit_around(c, 0, one, 1, PC_FIT_EQUAL), PC_EARG);
    assert_non_null(strstr(c->error, "at least one point"));
    assert_int_equal(pc_fit_around(c, 2, bad, 1, PC_FIT_EQUAL), PC_EARG);
    assert_non_null(strstr(c->error, "point 2 is not finite"));
    assert_int_equal(pc_fit_around(c, 2, two, -1, PC_FIT_EQUAL), PC_EARG);
    assert_non_null(strstr(c->error, "pad"));
    assert_int_equal(pc_fit_around(c, 1, one, 0, PC_FIT_EQUAL), PC_EARG);
    assert_non_null(strstr(c->error, "one point and pad is 0"));
    assert_int_equal(pc_fit_around(c, 1, one, 0, PC_FIT_FILL), PC_EARG);
    assert_false(c->has_window);   /* nothing changed on an error */
    /* one point with a pad: a window of 2 pad high round it */
    assert_int_equal(pc_fit_around(c, 1, one, 1, PC_FIT_EQUAL), PC_OK);
    assert_true(c->wy1 == 2 && c->wy2 == 4);
    pc_canvas_free(c);
}

/* band: 39 pixels kept free at the bottom; the points framed in the 440 px above, same units */
static void test_caption_band(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    const double tri[] = {0, 0, 4, 0, 2, 3};   /* height 3 + 2 pad decides: 4 * 440/639 < 3 */
    assert_int_equal(pc_fit_around_band(c, 3, tri, 0.5, 39, PC_FIT_EQUAL), PC_OK);
    double ux, uy, sx, sy;
    units(c, &ux, &uy);
    assert_true(fabs(ux - 110) < 1e-9 && fabs(uy - 110) < 1e-9);   /* 440 px over 4 units */
    assert_true(fabs(c->wy2 - 3.5) < 1e-12 && fabs(c->wy1 - (-0.5 - 39.0 / 110)) < 1e-12);
    pc_world_to_screen(c, 2, 1.5, &sx, &sy);    /* the box's centre: the middle of the 440 px */
    assert_true(fabs(sx - 319.5) < 1e-9 && fabs(sy - 220) < 1e-9);
    pc_world_to_screen(c, 2, -0.5, &sx, &sy);   /* the pad's lower edge: the band's top */
    assert_true(fabs(sy - 440) < 1e-9);
    /* fill: the box plus pad over the 440 px, the band below at the same y units */
    const double sq[] = {0, 0, 2, 2};
    assert_int_equal(pc_fit_around_band(c, 2, sq, 0, 39, PC_FIT_FILL), PC_OK);
    pc_world_to_screen(c, 0, 0, &sx, &sy);
    assert_true(fabs(sx - 0) < 1e-9 && fabs(sy - 440) < 1e-9);
    /* band 0 is pc_fit_around's frame exactly */
    assert_int_equal(pc_fit_around_band(c, 3, tri, 0.5, 0, PC_FIT_EQUAL), PC_OK);
    assert_true(fabs(c->wy1 - -0.5) < 1e-12 && fabs(c->wy2 - 3.5) < 1e-12);
    assert_int_equal(pc_fit_around_band(c, 3, tri, 0.5, -1, PC_FIT_EQUAL), PC_EARG);
    assert_int_equal(pc_fit_around_band(c, 3, tri, 0.5, 479, PC_FIT_EQUAL), PC_EARG);
    assert_non_null(strstr(c->error, "band must be a number of pixels >= 0 and below the view's 479, got 479"));
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_equal_units),
        cmocka_unit_test(test_view_aspect_and_fill),
        cmocka_unit_test(test_drawn_stays),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_caption_band),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
