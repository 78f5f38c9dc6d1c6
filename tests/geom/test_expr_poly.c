/* An equation in powers of its parameter (expr.h: pc_expr_power_basis): the Bezier form
 * expanded, the book's (4.10) and (4.16) interpolation weights, Fig. 2.17's printed conic
 * (its two denominators a factor 5 apart kept of degree 2), a rational Bezier arc's weight
 * channel, scalars, negative powers, and the refusals. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "expr.h"

#define NEAR(a, b) assert_true(fabs((a) - (double)(b)) <= 1e-12 * (1 + fabs((double)(b))))

static pc_expr_pool *P;
static int st, T, K0;

static int K(double c) { int e = pc_expr_const(P, c, &st); assert_true(e >= 0); return e; }
static int PT(double x, double y) { double h[3] = {x, y, 1}; int e = pc_expr_vconst(P, 2, h, &st); assert_true(e >= 0); return e; }
static int add(int a, int b) { int e = pc_expr_add(P, a, b, &st); assert_true(e >= 0); return e; }
static int sub(int a, int b) { int e = pc_expr_sub(P, a, b, &st); assert_true(e >= 0); return e; }
static int mul(int a, int b) { int e = pc_expr_mul(P, a, b, &st); assert_true(e >= 0); return e; }
static int dv(int a, int b) { int e = pc_expr_div(P, a, b, &st); assert_true(e >= 0); return e; }
static int pw(int a, double k) { int e = pc_expr_pow(P, a, K(k), &st); assert_true(e >= 0); return e; }
static int bar(int t) { int e = pc_expr_bar(P, t, &st); assert_true(e >= 0); return e; }

static int setup(void **s) {
    (void)s;
    P = pc_expr_pool_new();
    T = pc_expr_param(P, "t", &st);
    K0 = pc_expr_param_index(P, T);
    return P && T >= 0 ? 0 : -1;
}
static int teardown(void **s) { (void)s; pc_expr_pool_free(P); return 0; }

/* A t̄² + 2B t t̄ + C t² with A(0,0), B(1,2), C(4,0): x = 2t² + 2t, y = -4t² + 4t, weight 1 */
static void test_bezier(void **s) {
    (void)s;
    int tb = bar(T);
    int M = add(add(mul(PT(0, 0), pw(tb, 2)), mul(mul(PT(1, 2), K(2)), mul(T, tb))), mul(PT(4, 0), pw(T, 2)));
    double c[65 * 3];
    int deg;
    assert_int_equal(pc_expr_power_basis(P, M, K0, 64, c, &deg), PC_OK);
    assert_int_equal(deg, 2);
    const double want[9] = {0, 0, 1, 2, 4, 0, 2, -4, 0};
    for (int i = 0; i < 9; i++) NEAR(c[i], want[i]);
}

/* (4.10) t̄(1 - 2t) = 2t² - 3t + 1 and (4.16)'s first weight t̄³ - 2.5t̄²t + t̄t²
 * = -4.5t³ + 9t² - 5.5t + 1 (the Lagrange cubic on 0, 1/3, 2/3, 1) */
static void test_interp_weights(void **s) {
    (void)s;
    int tb = bar(T);
    double c[65 * 2];
    int deg;
    int w410 = mul(tb, sub(K(1), mul(K(2), T)));
    assert_int_equal(pc_expr_power_basis(P, w410, K0, 64, c, &deg), PC_OK);
    assert_int_equal(deg, 2);
    NEAR(c[0], 1); NEAR(c[2], -3); NEAR(c[4], 2);
    NEAR(c[1], 1); NEAR(c[3], 0); NEAR(c[5], 0);   /* a scalar: its denominator 1 */
    int w416 = add(sub(pw(tb, 3), mul(K(2.5), mul(pw(tb, 2), T))), mul(tb, pw(T, 2)));
    assert_int_equal(pc_expr_power_basis(P, w416, K0, 64, c, &deg), PC_OK);
    assert_int_equal(deg, 3);
    NEAR(c[0], 1); NEAR(c[2], -5.5); NEAR(c[4], 9); NEAR(c[6], -4.5);
}

/* Fig. 2.17 as printed: x = 4t(9t + 0,8)/(70t² - 75t + 44,2), y = -8t(t - 1)/(14t² - 15t + 8,84):
 * one denominator of degree 2 (the second is the first over 5), so x = channel 0 / channel 2
 * with 36t² + 3.2t over 70t² - 75t + 44.2 up to one common factor */
static void test_fig217(void **s) {
    (void)s;
    int x = dv(mul(mul(K(4), T), add(mul(K(9), T), K(0.8))), add(sub(mul(K(70), pw(T, 2)), mul(K(75), T)), K(44.2)));
    int y = dv(mul(mul(K(-8), T), sub(T, K(1))), add(sub(mul(K(14), pw(T, 2)), mul(K(15), T)), K(8.84)));
    int co[2] = {x, y};
    int M = pc_expr_pack(P, 2, co, 1, &st);
    assert_true(M >= 0);
    double c[65 * 3];
    int deg;
    assert_int_equal(pc_expr_power_basis(P, M, K0, 64, c, &deg), PC_OK);
    assert_int_equal(deg, 2);
    double f = c[2 * 3 + 2] / 70;   /* the common factor */
    const double want[9] = {0, 0, 44.2, 3.2, 40, -75, 36, -40, 70};
    for (int i = 0; i < 9; i++) assert_true(fabs(c[i] - f * want[i]) <= 1e-9 * fabs(f) * 75);
}

/* a rational arc: (A w0 t̄² + 2B w1 t t̄ + C w2 t²)/(w0 t̄² + 2 w1 t t̄ + w2 t²); its weight channel
 * is the denominator (the division cancels in the coordinates); and a negative power */
static void test_rational(void **s) {
    (void)s;
    int tb = bar(T);
    int den = add(add(pw(tb, 2), mul(K(2 * 0.5), mul(T, tb))), pw(T, 2));
    int num = add(add(mul(PT(0, 0), pw(tb, 2)), mul(PT(1, 1), mul(K(2 * 0.5), mul(T, tb)))), mul(PT(2, 0), pw(T, 2)));
    int M = dv(num, den);
    double c[65 * 3];
    int deg;
    assert_int_equal(pc_expr_power_basis(P, M, K0, 64, c, &deg), PC_OK);
    assert_int_equal(deg, 2);
    /* weight t̄² + t t̄ + t² = t² - t + 1, x numerator t t̄ + 2t² = t² + t, y t t̄ = t - t², all
     * over one factor f (the denominator dropped) */
    double f = c[2];
    NEAR(c[3 + 2] / f, -1); NEAR(c[6 + 2] / f, 1);
    NEAR(c[0] / f, 0); NEAR(c[3] / f, 1); NEAR(c[6] / f, 1);
    NEAR(c[1] / f, 0); NEAR(c[4] / f, 1); NEAR(c[7] / f, -1);
    int r = pw(add(T, K(2)), -2);   /* 1/(t + 2)² = 1/(t² + 4t + 4) */
    assert_int_equal(pc_expr_power_basis(P, r, K0, 64, c, &deg), PC_OK);
    assert_int_equal(deg, 2);
    NEAR(c[0] / c[1], 0.25); NEAR(c[2], 0); NEAR(c[4], 0);
    NEAR(c[3] / c[1], 1); NEAR(c[5] / c[1], 0.25);
}

static void test_refusals(void **s) {
    (void)s;
    double c[65 * 3];
    int deg;
    int sn = pc_expr_fn(P, PC_EX_SIN, T, &st);
    assert_int_equal(pc_expr_power_basis(P, sn, K0, 64, c, &deg), PC_EDOMAIN);
    assert_int_equal(pc_expr_power_basis(P, pw(T, 0.5), K0, 64, c, &deg), PC_EDOMAIN);
    assert_int_equal(pc_expr_power_basis(P, pw(T, 9), K0, 8, c, &deg), PC_EDOMAIN);   /* above maxdeg */
    int S = pc_expr_param(P, "s", &st);
    assert_int_equal(pc_expr_power_basis(P, mul(T, S), K0, 64, c, &deg), PC_EDIM);
    assert_int_equal(pc_expr_power_basis(P, T, 5, 64, c, &deg), PC_EDIM);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_bezier, setup, teardown),
        cmocka_unit_test_setup_teardown(test_interp_weights, setup, teardown),
        cmocka_unit_test_setup_teardown(test_fig217, setup, teardown),
        cmocka_unit_test_setup_teardown(test_rational, setup, teardown),
        cmocka_unit_test_setup_teardown(test_refusals, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
