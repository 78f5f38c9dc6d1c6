/* Flattening with a clip box (issue 26): a curve reaching 1e15 far off the picture costs what
 * its visible part costs, and inside the box the polyline is the one without a box, vertex for
 * vertex; the vertex cap is PC_ENOMEM with the polyline at PC_POLYLINE_MAX. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "curve.h"

static const double box[4] = {-640, -640, 1280, 1120};   /* 640x480 and a margin of 640 */

static int inside(const double *xy) {
    return xy[0] >= box[0] && xy[0] <= box[2] && xy[1] >= box[1] && xy[1] <= box[3];
}

/* the probe's case: bezier{P(0,0), P(1e15,1e14), P(0,1e15)}: without a box the arc at 0.25 px
 * would need more vertices than the cap (842 MB before the cap); with one, a few */
static void test_far_bezier(void **state) {
    (void)state;
    double cp[9] = {0, 0, 1, 1e15, 1e14, 1, 0, 1e15, 1};
    int st;
    pc_curve *c = pc_curve_bezier(2, 3, cp, &st);
    assert_non_null(c);
    pc_polyline full = {0}, clipped = {.clip = box};
    assert_int_equal(pc_curve_flatten_map(c, 0, 1, NULL, 0.25, &full), PC_ENOMEM);
    assert_int_equal(full.n, PC_POLYLINE_MAX);
    assert_int_equal(pc_curve_flatten_map(c, 0, 1, NULL, 0.25, &clipped), PC_OK);
    assert_true(clipped.n < 200);
    /* it starts and ends where the curve does */
    assert_true(clipped.xy[0] == 0 && clipped.xy[1] == 0);
    assert_true(clipped.xy[2 * clipped.n - 2] == 0 && clipped.xy[2 * clipped.n - 1] == 1e15);
    pc_polyline_free(&full);
    pc_polyline_free(&clipped);
    pc_curve_release(c);
}

/* a smaller one, flattened whole and clipped: every segment drawn near the picture is a
 * segment of the whole polyline */
static void test_clipped_segments(void **state) {
    (void)state;
    double cp[9] = {0, 0, 1, 1e7, 1e6, 1, 0, 1e7, 1};
    int st;
    pc_curve *c = pc_curve_bezier(2, 3, cp, &st);
    assert_non_null(c);
    pc_polyline full = {0}, clipped = {.clip = box};
    assert_int_equal(pc_curve_flatten_map(c, 0, 1, NULL, 0.25, &full), PC_OK);
    assert_int_equal(pc_curve_flatten_map(c, 0, 1, NULL, 0.25, &clipped), PC_OK);
    assert_true(clipped.n * 20 < full.n);
    size_t seen = 0;
    for (size_t k = 1; k < clipped.n; k++) {
        if (clipped.move[k] || !(inside(clipped.xy + 2 * k) || inside(clipped.xy + 2 * k - 2))) continue;
        int found = 0;
        for (size_t j = 1; j < full.n && !found; j++)
            found = full.xy[2 * j] == clipped.xy[2 * k] && full.xy[2 * j + 1] == clipped.xy[2 * k + 1] &&
                    full.xy[2 * j - 2] == clipped.xy[2 * k - 2] && full.xy[2 * j - 1] == clipped.xy[2 * k - 1];
        assert_true(found);
        seen++;
    }
    assert_true(seen >= 1);
    pc_polyline_free(&full);
    pc_polyline_free(&clipped);
    pc_curve_release(c);
}

static void test_inside_unchanged(void **state) {
    (void)state;
    double cp[12] = {10, 10, 1, 600, 20, 1, 20, 460, 1, 630, 470, 1};
    int st;
    pc_curve *c = pc_curve_bezier(2, 4, cp, &st);
    assert_non_null(c);
    pc_polyline a = {0}, b = {.clip = box};
    assert_int_equal(pc_curve_flatten_map(c, 0, 1, NULL, 0.1, &a), PC_OK);
    assert_int_equal(pc_curve_flatten_map(c, 0, 1, NULL, 0.1, &b), PC_OK);
    assert_int_equal(a.n, b.n);
    for (size_t k = 0; k < a.n; k++) {
        assert_true(a.xy[2 * k] == b.xy[2 * k] && a.xy[2 * k + 1] == b.xy[2 * k + 1]);
        assert_int_equal(a.move[k], b.move[k]);
    }
    pc_polyline_free(&a);
    pc_polyline_free(&b);
    pc_curve_release(c);
}

static void test_vertex_cap(void **state) {
    (void)state;
    pc_polyline pl = {0};
    int st = PC_OK;
    for (size_t k = 0; k <= PC_POLYLINE_MAX && st == PC_OK; k++)
        st = pc_polyline_push(&pl, (double)k, 0, k == 0);
    assert_int_equal(st, PC_ENOMEM);
    assert_int_equal(pl.n, PC_POLYLINE_MAX);
    pc_polyline_free(&pl);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_far_bezier),
        cmocka_unit_test(test_clipped_segments),
        cmocka_unit_test(test_inside_unchanged),
        cmocka_unit_test(test_vertex_cap),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
