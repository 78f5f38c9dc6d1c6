/* The textbook's conics at the book's parameter (issue 24): pc_curve_ellipse and
 * pc_curve_hyperbola give c + (A cos th, B sin th) and (A ch t, B sh t) at every th, t — not
 * only at the breakpoints of their rational quadratic pieces — with the exact derivatives, on
 * the circles of plane.circle3 / plane.arc3 too (digest buimov_textbook.md §3.3-§3.5). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "plane_curves.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_ellipse_param(void **state) {
    (void)state;
    int s;
    const double c[2] = {1, 2};
    pc_curve *e = pc_curve_ellipse(c, 3, 2, 0, 2 * M_PI, &s);
    assert_non_null(e);
    double x[6];
    /* the value: th = 1 is (2.620907, 3.682942), not (2.593554, 3.694512) */
    assert_int_equal(pc_curve_eval(e, 1.0, x), PC_OK);
    NEAR(x[0], 2.620907, 5e-7);
    NEAR(x[1], 3.682942, 5e-7);
    for (int i = 0; i <= 64; i++) {
        double th = 2 * M_PI * i / 64 + 0.013;
        assert_int_equal(pc_curve_derivs(e, th, 2, x), PC_OK);
        NEAR(x[0], 1 + 3 * cos(th), 1e-13);
        NEAR(x[1], 2 + 2 * sin(th), 1e-13);
        NEAR(x[2], -3 * sin(th), 1e-12);
        NEAR(x[3], 2 * cos(th), 1e-12);
        NEAR(x[4], -3 * cos(th), 1e-11);
        NEAR(x[5], -2 * sin(th), 1e-11);
    }
    /* the tangent at th = pi/3 is the book's */
    assert_int_equal(pc_curve_derivs(e, M_PI / 3, 1, x), PC_OK);
    NEAR(x[3] / x[2], -(2 * cos(M_PI / 3)) / (3 * sin(M_PI / 3)), 1e-12);
    assert_true(e->closed);
    pc_curve_release(e);
}

static void test_hyperbola_param(void **state) {
    (void)state;
    int s;
    pc_curve *h = pc_curve_hyperbola(2, 1.5, -1.3, 1.3, &s);
    assert_non_null(h);
    double x[6];
    assert_int_equal(pc_curve_eval(h, 0.7, x), PC_OK);
    NEAR(x[0], 2.510338, 5e-7);             /* not (2.513667, 1.142002) */
    NEAR(x[1], 1.137876, 5e-7);
    for (int i = 0; i <= 40; i++) {
        double t = -1.3 + 2.6 * i / 40;
        assert_int_equal(pc_curve_derivs(h, t, 2, x), PC_OK);
        NEAR(x[0], 2 * cosh(t), 1e-13);
        NEAR(x[1], 1.5 * sinh(t), 1e-13);
        NEAR(x[2], 2 * sinh(t), 1e-12);
        NEAR(x[3], 1.5 * cosh(t), 1e-12);
        NEAR(x[4], 2 * cosh(t), 1e-11);
        NEAR(x[5], 1.5 * sinh(t), 1e-11);
    }
    pc_curve_release(h);
}

static void test_circle_arcs(void **state) {
    (void)state;
    /* the circle through (1, 1), (2, 2), (3, 2): centre (2.5, 0.5), r^2 = 2.5; its arc runs
     * over the true angles at the centre */
    const double a[2] = {1, 1}, b[2] = {2, 2}, d[2] = {3, 2};
    int s;
    pc_curve *arc = pc_curve_arc3(a, b, d, &s);
    assert_non_null(arc);
    double x[2], r = sqrt(2.5);
    for (int i = 0; i <= 20; i++) {
        double th = arc->t0 + (arc->t1 - arc->t0) * i / 20;
        assert_int_equal(pc_curve_eval(arc, th, x), PC_OK);
        NEAR(x[0], 2.5 + r * cos(th), 1e-12);
        NEAR(x[1], 0.5 + r * sin(th), 1e-12);
    }
    pc_curve_release(arc);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ellipse_param), cmocka_unit_test(test_hyperbola_param),
        cmocka_unit_test(test_circle_arcs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
