/* The explanations of the curve type's failures (curve_why.h): the methods' rows, and the
 * B-spline's degree and knot conditions with the numbers that break them. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "curve_why.h"

static void test_method_rows(void **state) {
    (void)state;
    const pc_why *w = pc_why_find(pc_curve_why, "c:normal", PC_ECOLLINEAR);
    assert_non_null(w);
    assert_int_equal(w->arg, -2);
    assert_string_equal(w->text, "the curve is straight at t = %s (no principal normal)");
    w = pc_why_find(pc_curve_why, "c:tangent", PC_EZERO);
    assert_string_equal(w->text, "the derivative is zero at t = %s (a cusp or a stop)");
    w = pc_why_find(pc_curve_why, "c:length", PC_IMPROPER);
    assert_int_equal(w->arg, 0);
    assert_string_equal(w->text, "the curve passes through infinity: its length is infinite");
    assert_null(pc_why_find(pc_curve_why, "c:deriv", PC_EZERO));   /* the core's own message stands */
}

static void test_degree(void **state) {
    (void)state;
    char why[160];
    assert_int_equal(pc_bspline_degree_why(4, 3, 0, why, sizeof why), PC_OK);
    assert_int_equal(pc_bspline_degree_why(4, 4, 1, why, sizeof why), PC_OK);
    assert_int_equal(pc_bspline_degree_why(4, 4, 0, why, sizeof why), PC_EDOMAIN);
    assert_string_equal(why, "must be an integer from 1 to 3 (fewer than the 4 points), got 4");
    assert_int_equal(pc_bspline_degree_why(4, 0, 1, why, sizeof why), PC_EDOMAIN);
    assert_string_equal(why, "must be an integer from 1 to 4 (the number of points), got 0");
    assert_int_equal(pc_bspline_degree_why(100, 70, 0, why, sizeof why), PC_EDOMAIN);
    assert_string_equal(why, "must be an integer from 1 to 64 (fewer than the 100 points), got 70");
}

static void test_knots(void **state) {
    (void)state;
    char why[160];
    const double good[] = {0, 0, 0, 1, 2, 2, 2}, back[] = {0, 0, 1, 0, 2, 2, 2}, flat[] = {0, 0, 0, 0, 0, 0, 1};
    assert_int_equal(pc_knots_why(4, 2, 7, good, why, sizeof why), PC_OK);
    assert_int_equal(pc_knots_why(4, 2, 6, good, why, sizeof why), PC_EDOMAIN);
    assert_string_equal(why, "must hold points + degree + 1 = 7 knots, got 6");
    assert_int_equal(pc_knots_why(4, 2, 7, back, why, sizeof why), PC_EDOMAIN);
    assert_string_equal(why, "must be non-decreasing, but knot [4] = 0 is less than knot [3] = 1");
    assert_int_equal(pc_knots_why(4, 2, 7, flat, why, sizeof why), PC_EDOMAIN);
    assert_string_equal(why, "leaves no domain: knot [3] = 0 (the start) must be less than knot [5] = 0 (the end)");
}

static void test_params(void **state) {
    (void)state;
    char why[160];
    const double up[] = {0, 1, 2}, back[] = {0, 2, 1};
    assert_int_equal(pc_params_why(3, 3, up, 0, why, sizeof why), PC_OK);
    assert_int_equal(pc_params_why(3, 2, up, 0, why, sizeof why), PC_EDOMAIN);
    assert_string_equal(why, "must hold 3 numbers (one per point), got 2");
    assert_int_equal(pc_params_why(3, 3, back, 0, why, sizeof why), PC_EDOMAIN);
    assert_string_equal(why, "must increase, but [3] = 1 follows [2] = 2");
    assert_int_equal(pc_params_why(3, 3, back, 1, why, sizeof why), PC_OK);   /* any order */
}

/* piece and coordinate numbers, a parameter inside the domain, a part of it */
static void test_ranges(void **state) {
    (void)state;
    char why[200];
    double cp[] = {0, 0, 1, 4, 0, 1};
    int st;
    pc_curve *c = pc_curve_bezier(2, 2, cp, &st);
    assert_int_equal(pc_number_why("piece", 3, 3, why, sizeof why), PC_OK);
    assert_int_equal(pc_number_why("piece", 4, 3, why, sizeof why), PC_EDOMAIN);
    assert_string_equal(why, "must be a piece number 1..3, got 4");
    assert_int_equal(pc_number_why("coordinate", 0, 2, why, sizeof why), PC_EDOMAIN);
    assert_string_equal(why, "must be a coordinate number 1..2, got 0");
    assert_int_equal(pc_curve_inside_why(c, 0.5, why, sizeof why), PC_OK);
    assert_int_equal(pc_curve_inside_why(c, 1, why, sizeof why), PC_EDOMAIN);
    assert_string_equal(why, "must be inside the domain (0, 1), got 1");
    assert_int_equal(pc_curve_part_why(c, 0, 1, why, sizeof why), PC_OK);
    assert_int_equal(pc_curve_part_why(c, 0.5, 0.25, why, sizeof why), PC_EDOMAIN);
    assert_string_equal(why, "need t0 <= a < b <= t1 in the domain [0, 1], got a = 0.5, b = 0.25");
    assert_int_equal(pc_curve_part_why(c, -1, 0.5, why, sizeof why), PC_EDOMAIN);
    pc_curve_release(c);
}

/* c:monomial's conditions: a function curve, a piece out of range; a piece in range gives its rows */
static int line_x(void *ud, double t, int order, double *out) {
    (void)ud, (void)order;
    out[0] = t, out[1] = 1;
    return PC_OK;
}

static void test_monomial_checked(void **state) {
    (void)state;
    double cp[] = {0, 0, 1, 4, 0, 1, 8, 2, 1}, rows[3 * 3];
    int st, deg, rational;
    pc_why_call w;
    pc_curve *c = pc_curve_bezier(2, 3, cp, &st), *f = pc_curve_func(1, 0, 1, 0, line_x, NULL, NULL, &st);
    assert_non_null(f);
    assert_int_equal(pc_curve_monomial_checked("c:monomial", c, 2, rows, &deg, &rational, &w), PC_EDOMAIN);
    assert_string_equal(w.row[0].op, "c:monomial");
    assert_int_equal(w.row[0].arg, 1);
    assert_string_equal(w.row[0].text, "must be from 1 to 1 (the curve's pieces), got 2");
    assert_int_equal(pc_curve_monomial_checked("c:monomial", f, 1, rows, &deg, &rational, &w), PC_EDOMAIN);
    assert_int_equal(w.row[0].arg, 0);
    assert_string_equal(w.row[0].text,
                        "a function curve has no power-basis coefficients (only Bezier and B-spline curves)");
    assert_int_equal(pc_curve_monomial_checked("c:monomial", c, 1, rows, &deg, &rational, &w), PC_OK);
    assert_null(w.row[0].op);
    assert_int_equal(deg, 2);
    assert_int_equal(rational, 0);
    double want[6] = {0, 8, 0, 0, 0, 2};   /* x = 2 (1 - t) t 4 + t^2 8 = 8t, y = 2t^2 */
    for (int i = 0; i < 6; i++) assert_true(fabs(rows[i] - want[i]) < 1e-12);
    pc_curve_release(c);
    pc_curve_release(f);
}

/* c:deriv's conditions: a function curve's order beyond 2, a rational curve at infinity (the
 * table's row), a derivative that exists */
static void test_derivs_checked(void **state) {
    (void)state;
    double cp[] = {0, 0, 1, 0, 1, -1, 1, 0, 1}, out[4 * 2];   /* weight (1 - 2t)^2: 0 at t = 1/2 */
    int st;
    pc_why_call w;
    pc_curve *c = pc_curve_bezier(2, 3, cp, &st);
    pc_curve *f = pc_curve_func(1, 0, 1, 0, line_x, NULL, NULL, &st);
    assert_int_equal(pc_curve_derivs_checked("c:deriv", f, 0.5, 3, 0, out, &w), PC_EDOMAIN);
    assert_int_equal(w.row[0].arg, 0);
    assert_string_equal(w.row[0].text, "a function curve gives derivatives up to order 2, not 3");
    assert_int_equal(pc_curve_derivs_checked("c:deriv", c, 0.5, 1, 0, out, &w), PC_IMPROPER);
    assert_string_equal(w.row[0].op, "c:deriv");
    assert_int_equal(w.row[0].arg, -2);
    assert_string_equal(w.row[0].text, "the curve is at infinity at t = %s");
    assert_int_equal(pc_curve_derivs_checked("c:deriv", c, 0, 1, 0, out, &w), PC_OK);
    assert_null(w.row[0].op);
    assert_true(fabs(out[0]) + fabs(out[1]) < 1e-12);   /* the point at t = 0: P0 */
    pc_curve_release(c);
    pc_curve_release(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_method_rows),
        cmocka_unit_test(test_degree),
        cmocka_unit_test(test_knots),
        cmocka_unit_test(test_params),
        cmocka_unit_test(test_ranges),
        cmocka_unit_test(test_monomial_checked),
        cmocka_unit_test(test_derivs_checked),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
