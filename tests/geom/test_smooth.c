/* Smoothsteps and half-splines: the numbers of examples 3-8, 10, 20-22 of
 * stepanov_examples.md and the defining identities g(0) = 0, g(1) = 1, g'(0) = g'(1) = 0. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "smooth.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

/* central difference */
static double dsine(double t) { return (pc_smooth_sine(t + 1e-6) - pc_smooth_sine(t - 1e-6)) / 2e-6; }
static double dcubic(double t) {
    return (pc_smooth_cubic(t + 1e-6) - pc_smooth_cubic(t - 1e-6)) / 2e-6;
}

static void test_sine_cubic(void **state) {
    (void)state;
    NEAR(pc_smooth_sine(0), 0, 1e-15);
    NEAR(pc_smooth_sine(1), 1, 1e-15);
    NEAR(pc_smooth_sine(0.5), 0.5, 1e-15);
    NEAR(pc_smooth_sine(0.25), (1 - cos(M_PI / 4)) / 2, 1e-15);
    NEAR(dsine(0), 0, 1e-6);
    NEAR(dsine(1), 0, 1e-6);
    /* example 3: y = a + (1 + sin u)(b - a)/2, u = -pi/2 + pi t, is a + g(t)(b - a) */
    for (double t = 0; t <= 1; t += 0.125)
        NEAR(pc_smooth_sine(t), (1 + sin(-M_PI / 2 + M_PI * t)) / 2, 1e-14);
    NEAR(pc_smooth_cubic(0), 0, 0);
    NEAR(pc_smooth_cubic(1), 1, 0);
    NEAR(pc_smooth_cubic(0.5), 0.5, 0);
    NEAR(dcubic(0), 0, 1e-6);
    NEAR(dcubic(1), 0, 1e-6);
    /* example 5 extrapolates: g(-1) = 5, g(3) = -27 */
    NEAR(pc_smooth_cubic(-1), 5, 0);
    NEAR(pc_smooth_cubic(3), -27, 0);
    NEAR(pc_smooth_cubic(0.3), -2 * 0.027 + 3 * 0.09, 1e-15);
}

static void test_power(void **state) {
    (void)state;
    /* example 7: n = 2, 4, 6, 8 all pass through the centre (1/2, 1/2) */
    for (int n = 2; n <= 8; n += 2) {
        NEAR(pc_smooth_power(n, 0), 0, 0);
        NEAR(pc_smooth_power(n, 1), 1, 0);
        NEAR(pc_smooth_power(n, 0.5), 0.5, 1e-15);
        NEAR(pc_smooth_power(n, 0.25), pow(2, n - 1) * pow(0.25, n), 1e-15);
        /* point symmetry about (1/2, 1/2) */
        NEAR(pc_smooth_power(n, 0.2) + pc_smooth_power(n, 0.8), 1, 1e-15);
    }
    NEAR(pc_smooth_power(2, 0.25), 0.125, 1e-15);
    NEAR(pc_smooth_power(2, 0.75), 0.875, 1e-15);
    /* example 14's degree 5: k(.1) = 16 * 1e-5 */
    NEAR(pc_smooth_power(5, 0.1), 16e-5, 1e-18);
    /* the power half-spline is the asymmetric one with (n, n, 1/2) */
    pc_hspline h;
    assert_int_equal(pc_hspline_init(&h, 6, 6, 0.5), PC_OK);
    for (double t = -0.5; t <= 1.5; t += 0.0625) NEAR(pc_hspline_eval(&h, t), pc_smooth_power(6, t), 1e-12);
}

static void check_hspline(double n, double m, double t0, double c1, double c2) {
    pc_hspline h;
    assert_int_equal(pc_hspline_init(&h, n, m, t0), PC_OK);
    NEAR(h.c1, c1, 1e-9 * fabs(c1));
    NEAR(h.c2, c2, 1e-9 * fabs(c2));
    NEAR(pc_hspline_eval(&h, 0), 0, 1e-15);
    NEAR(pc_hspline_eval(&h, 1), 1, 1e-15);
    NEAR(pc_hspline_deriv(&h, 0), 0, 1e-15);
    NEAR(pc_hspline_deriv(&h, 1), 0, 1e-15);
    /* value and slope continuous at t0; the junction ordinate is v(t0) */
    double v = pc_hspline_locus(n, m, t0);
    NEAR(h.c1 * pow(t0, n), v, 1e-12);
    NEAR(pc_hspline_eval(&h, t0), v, 1e-12);
    NEAR(pc_hspline_eval(&h, t0 - 1e-9), v, 1e-6);
    NEAR(pc_hspline_deriv(&h, t0 - 1e-12), pc_hspline_deriv(&h, t0), 1e-6 * pc_hspline_deriv(&h, t0));
    /* increasing on [0, 1] */
    double prev = -1;
    for (int i = 0; i <= 1000; i++) {
        double g = pc_hspline_eval(&h, i / 1000.0);
        assert_true(g >= prev);
        prev = g;
    }
}

static void test_hspline(void **state) {
    (void)state;
    /* example 8: n = 8, m = 2, t0 = .1 .. .9 (c1, c2 from the closed forms) */
    check_hspline(8, 2, 0.1, 2702702.7027027, 1.2012012012012012);
    check_hspline(8, 2, 0.3, 1474.9915187987674, 1.8433179723502306);
    check_hspline(8, 2, 0.5, 51.2, 3.2);
    check_hspline(8, 2, 0.7, 6.39087199422112, 7.017543859649121);
    check_hspline(8, 2, 0.9, 1.6082704471443767, 30.769230769230763);
    /* example 9's horns, example 10's nodes */
    check_hspline(3, 5, 1.0 / 3, 12.272727272727273, 4.142045454545453);
    check_hspline(2, 7, 0.3, 20.0 / 3, 4.857062715608052);
    check_hspline(4, 5, 0.5, 8.88888888888889, 14.222222222222221);
    check_hspline(6, 3, 0.7, 4.576847558938355, 17.09401709401709);
    check_hspline(2, 2, 0.5, 2, 2);
    /* the locus v(t0) = m t0 / (n - n t0 + m t0): ends, and example 8's value at .5 */
    NEAR(pc_hspline_locus(8, 2, 0), 0, 0);
    NEAR(pc_hspline_locus(8, 2, 1), 1, 0);
    NEAR(pc_hspline_locus(8, 2, 0.5), 0.2, 1e-15);
    NEAR(pc_hspline_locus(3, 3, 0.4), 0.4, 1e-15);   /* n = m: the diagonal */
    /* domain */
    pc_hspline h = {0};
    assert_int_equal(pc_hspline_init(&h, 2, 2, 0), PC_EDOMAIN);
    assert_int_equal(pc_hspline_init(&h, 2, 2, 1), PC_EDOMAIN);
    assert_int_equal(pc_hspline_init(&h, 0, 2, 0.5), PC_EDOMAIN);
    assert_int_equal(pc_hspline_init(&h, 2, -1, 0.5), PC_EDOMAIN);
    assert_int_equal(pc_hspline_init(&h, NAN, 2, 0.5), PC_ENONFINITE);
    assert_true(h.c1 == 0);   /* untouched */
    /* degrees in the hundreds: t0^(n-1) underflows, c1 would be inf */
    assert_int_equal(pc_hspline_init(&h, 800, 2, 0.1), PC_EDOMAIN);
    char msg[200];
    assert_true(pc_hspline_init_text(800, 2, 0.1, msg, sizeof msg) > 0);
    assert_string_equal(msg, "the degrees n = 800, m = 2 are too large for t0 = 0.1: the coefficients c1, c2 overflow a double");
}

/* Outside [0, 1] the pieces extrapolate (example 5 shows the cubic doing so); with a
 * fractional degree t^n (t < 0) or (1 - t)^m (t > 1) is not real, and the check says so
 * instead of letting eval return NaN. */
static void test_domain(void **state) {
    (void)state;
    pc_hspline h;
    assert_int_equal(pc_hspline_init(&h, 2.5, 2, 0.5), PC_OK);
    assert_int_equal(pc_hspline_check(&h, -0.1), PC_EDOMAIN);
    assert_true(isnan(pc_hspline_eval(&h, -0.1)));   /* what the check guards against */
    assert_int_equal(pc_hspline_check(&h, 0), PC_OK);
    assert_int_equal(pc_hspline_check(&h, 1.5), PC_OK);   /* m = 2 is whole */
    NEAR(pc_hspline_eval(&h, 1.5), 1 - h.c2 * 0.25, 1e-15);
    assert_int_equal(pc_hspline_init(&h, 2, 3.5, 0.5), PC_OK);
    assert_int_equal(pc_hspline_check(&h, -2), PC_OK);
    NEAR(pc_hspline_eval(&h, -2), h.c1 * 4, 1e-15);
    assert_int_equal(pc_hspline_check(&h, 1 + 1e-12), PC_EDOMAIN);
    char msg[200] = "untouched";
    assert_int_equal(pc_hspline_check_text(&h, 1, msg, sizeof msg), 0);
    assert_string_equal(msg, "untouched");
    assert_true(pc_hspline_check_text(&h, 1.5, msg, sizeof msg) > 0);
    assert_string_equal(msg, "must be at most 1 (the degree m = 3.5 is fractional, so the formula does not extrapolate past 1)");
    assert_int_equal(pc_hspline_init(&h, 2.5, 2, 0.5), PC_OK);
    assert_true(pc_hspline_check_text(&h, -0.25, msg, sizeof msg) > 0);
    assert_string_equal(msg, "must be at least 0 (the degree n = 2.5 is fractional, so the formula does not extrapolate past 0)");
    assert_int_equal(pc_hspline_init(&h, 2, 3.5, 0.5), PC_OK);
    pc_gfun g = {.kind = PC_G_HALF, .h = h};
    assert_int_equal(pc_gfun_check(&g, 2), PC_EDOMAIN);
    g.kind = PC_G_CUBIC;
    assert_int_equal(pc_gfun_check(&g, 2), PC_OK);
    /* degrees so large that t0^(n-1) underflows: c1 would be inf and c2 NaN */
    pc_hspline big = {0};
    assert_int_equal(pc_hspline_init(&big, 2000, 2, 0.5), PC_EDOMAIN);
    assert_int_equal(pc_hspline_init(&big, 2, 2000, 0.5), PC_EDOMAIN);
    assert_true(big.c1 == 0);   /* untouched */
    assert_int_equal(pc_hspline_init(&big, 500, 2, 0.5), PC_OK);   /* large but finite */
    assert_true(isfinite(big.c1) && isfinite(big.c2));
    NEAR(pc_hspline_eval(&big, 0.5), pc_hspline_locus(500, 2, 0.5), 1e-12);
}

static void test_clamp(void **state) {
    (void)state;
    NEAR(pc_smooth_clamp(-3), 0, 0);
    NEAR(pc_smooth_clamp(0), 0, 0);
    NEAR(pc_smooth_clamp(0.25), 0.125, 1e-15);
    NEAR(pc_smooth_clamp(0.5), 0.5, 0);
    NEAR(pc_smooth_clamp(0.75), 0.875, 1e-15);
    NEAR(pc_smooth_clamp(1), 1, 0);
    NEAR(pc_smooth_clamp(7), 1, 0);
    /* the listings' strict chain: the same values away from 0, 1/2, 1 ... */
    for (double t = -1.03; t < 2; t += 0.07)
        NEAR(pc_smooth_clamp_qb(t, 42), pc_smooth_clamp(t), 1e-15);
    /* ... and the previous value exactly there (example 20's stray first dot: u = 0 gives
     * t = .5 with s still 0) */
    NEAR(pc_smooth_clamp_qb(0.5, 0), 0, 0);
    NEAR(pc_smooth_clamp_qb(0, 0.3), 0.3, 0);
    NEAR(pc_smooth_clamp_qb(1, 0.3), 0.3, 0);
    NEAR(pc_smooth_clamp_qb(NAN, 0.7), 0.7, 0);
}

static void test_gfun(void **state) {
    (void)state;
    pc_gfun g = {.kind = PC_G_CUBIC};
    NEAR(pc_gfun_eval(&g, 3), -27, 0);
    g.kind = PC_G_SINE;
    NEAR(pc_gfun_eval(&g, 0.5), 0.5, 1e-15);
    g.kind = PC_G_LINEAR;
    NEAR(pc_gfun_eval(&g, 0.3), 0.3, 0);
    g.kind = PC_G_HALF;
    assert_int_equal(pc_hspline_init(&g.h, 8, 2, 0.5), PC_OK);
    NEAR(pc_gfun_eval(&g, 0.5), 0.2, 1e-15);
    assert_string_equal(pc_strerror(PC_ENOBRACKET), "no sign change: the interval brackets no root");
}

/* the fields of the half-spline (2, 3, 0.4): c1 = m/((n - n t0 + m t0) t0^(n-1)) = 3/(2.4 * 0.4) */
static void test_fields(void **state) {
    (void)state;
    pc_hspline h;
    double x = 0;
    assert_int_equal(pc_hspline_init(&h, 2, 3, 0.4), PC_OK);
    assert_int_equal(pc_hspline_field(&h, "c1", &x), 1);
    assert_float_equal(x, 3 / (2.4 * 0.4), 1e-12);
    assert_int_equal(pc_hspline_field(&h, "t0", &x), 1);
    assert_float_equal(x, 0.4, 0);
    assert_int_equal(pc_hspline_field(&h, "v", &x), 1);
    assert_float_equal(x, pc_hspline_locus(2, 3, 0.4), 1e-12);
    assert_int_equal(pc_hspline_field(&h, "deriv", &x), 0);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sine_cubic), cmocka_unit_test(test_power),
        cmocka_unit_test(test_hspline),    cmocka_unit_test(test_domain),
        cmocka_unit_test(test_clamp),
        cmocka_unit_test(test_gfun),
        cmocka_unit_test(test_fields),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
