/* The conics of chapter 2 know what they are: pc_curve_conic (geom/quadratic.h) on the arcs of
 * conic.h, with the cases of issue 23 — the engineering discriminant (2.97) on A(0,0), B(4,0),
 * C(2,3) (digest konopatsky_ch1_2.md §5.6: k = 0.5 parabola, below hyperbola, above ellipse),
 * Ceva's (2.104) (k = 1/4 parabola, §5.7, and its conversion k = (k_ED/(2(1 - k_ED)))^2), the
 * 90-degree circle of (2.107) (§5.8) and the conic through five points of §2.1.4. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "conic.h"
#include "quadratic.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static const double A[2] = {0, 0}, B[2] = {4, 0}, C[2] = {2, 3};

static void info(pc_curve *c, pc_conic_info *o) {
    assert_non_null(c);
    assert_int_equal(pc_curve_conic(c, o), PC_OK);
    for (int i = 0; i <= 10; i++) {     /* the equation holds along the arc */
        double p[2];
        if (pc_curve_eval(c, c->t0 + (c->t1 - c->t0) * i / 10, p) == PC_OK)
            NEAR(pc_conic_eq(o->coef, p[0], p[1]), 0, 1e-12);
    }
    pc_curve_release(c);
}

static void test_ed_kinds(void **state) {
    (void)state;
    int st;
    pc_conic_info o;
    info(pc_conic_ed(2, A, B, C, 0.3, &st), &o);
    assert_int_equal(o.kind, PC_CK_HYPERBOLA);      /* the old classifier said ellipse */
    NEAR(o.k_ed, 0.3, 1e-15);
    info(pc_conic_ed(2, A, B, C, 0.5, &st), &o);
    assert_int_equal(o.kind, PC_CK_PARABOLA);       /* the old classifier said ellipse */
    NEAR(o.vertex[0], 2, 1e-12);
    NEAR(o.vertex[1], 1.5, 1e-12);                  /* K = M(1/2) on the median */
    info(pc_conic_ed(2, A, B, C, 0.7, &st), &o);
    assert_int_equal(o.kind, PC_CK_ELLIPSE);
    NEAR(o.center[0], 2, 1e-12);
    NEAR(o.center[1], -0.675, 1e-12);               /* not (2, -0.2967) */
    NEAR(o.k_ed, 0.7, 1e-15);
    NEAR(o.k_ceva, pow(0.7 / (2 * 0.3), 2), 1e-12); /* §5.7's relation to §2.1.6 */
    /* k > 1 and k < 0 (ch. 3): the curve leaves the triangle, the conic stays typed */
    info(pc_conic_ed(2, A, B, C, 1.4, &st), &o);
    assert_int_equal(o.kind, PC_CK_ELLIPSE);
    NEAR(o.k_ed, 1.4, 1e-12);
    info(pc_conic_ed(2, A, B, C, -0.4, &st), &o);
    assert_int_equal(o.kind, PC_CK_HYPERBOLA);
    NEAR(o.k_ed, -0.4, 1e-12);
}

static void test_ceva_kinds(void **state) {
    (void)state;
    int st;
    pc_conic_info o;
    info(pc_conic_ceva(2, A, B, C, 0.09, &st), &o);
    assert_int_equal(o.kind, PC_CK_HYPERBOLA);      /* k < 1/4; the old classifier: ellipse */
    NEAR(o.k_ceva, 0.09, 1e-12);
    NEAR(o.k_ed, 2 * 0.3 / (1 + 2 * 0.3), 1e-12);  /* k_ED = 2 sqrt k/(1 + 2 sqrt k) */
    info(pc_conic_ceva(2, A, B, C, 0.25, &st), &o);
    assert_int_equal(o.kind, PC_CK_PARABOLA);
    NEAR(o.k_ed, 0.5, 1e-12);
    info(pc_conic_ceva(2, A, B, C, 1, &st), &o);
    assert_int_equal(o.kind, PC_CK_ELLIPSE);
    /* §5.7 TV: t = 0.5 -> (2, 1) lies on it, and the ellipse is symmetric about x = 2 */
    NEAR(pc_conic_eq(o.coef, 2, 1), 0, 1e-12);
    NEAR(o.center[0], 2, 1e-12);
}

static void test_circle(void **state) {
    (void)state;
    /* the 90-degree arc A(1,0), B(0,1), C(1,1), k = 2 - sqrt 2: the unit circle (the old
     * classifier put its centre at (0.396, 0.396)) */
    const double a[2] = {1, 0}, b[2] = {0, 1}, c[2] = {1, 1};
    double k;
    int st;
    assert_int_equal(pc_conic_ed_circle_k(2, a, b, c, &k), PC_OK);
    NEAR(k, 2 - sqrt(2), 1e-12);
    pc_conic_info o;
    info(pc_conic_ed(2, a, b, c, k, &st), &o);
    assert_int_equal(o.kind, PC_CK_ELLIPSE);
    assert_true(o.circle);
    NEAR(o.center[0], 0, 1e-12);
    NEAR(o.center[1], 0, 1e-12);
    NEAR(o.semi[0], 1, 1e-12);
    NEAR(o.semi[1], 1, 1e-12);
    NEAR(o.ecc, 0, 1e-12);
}

static void test_five_points(void **state) {
    (void)state;
    /* §2.1.4's five points: the arc, the whole conic and the five points give one conic, a
     * hyperbola (the arc passes through infinity between u = 1.25 and 1.5) */
    const double a[2] = {1, 0}, b[2] = {0, 1}, c[2] = {0, 0}, d[2] = {0.3, 0.8}, e[2] = {0.7, 0.6};
    const double pts[10] = {1, 0, 0, 1, 0, 0, 0.3, 0.8, 0.7, 0.6};
    int st;
    pc_conic_info arc, whole, five;
    info(pc_conic_five_points(2, a, b, c, d, e, 0, 2.6, 0, NULL, &st), &arc);
    info(pc_conic_five_points(2, a, b, c, d, e, 0, 2.6, 1, NULL, &st), &whole);
    double q[6];
    assert_int_equal(pc_conic_coef_five(pts, q), PC_OK);
    assert_int_equal(pc_conic_info_coef(q, &five), PC_OK);
    assert_int_equal(arc.kind, PC_CK_HYPERBOLA);
    assert_int_equal(whole.kind, PC_CK_HYPERBOLA);
    assert_int_equal(five.kind, PC_CK_HYPERBOLA);
    for (int i = 0; i < 6; i++) {
        NEAR(arc.coef[i], five.coef[i], 1e-12);
        NEAR(whole.coef[i], five.coef[i], 1e-12);
    }
    NEAR(arc.center[0], five.center[0], 1e-10);
    NEAR(arc.center[1], five.center[1], 1e-10);
    for (int i = 0; i < 5; i++) NEAR(pc_conic_eq(five.coef, pts[2 * i], pts[2 * i + 1]), 0, 1e-13);
    /* every focal property: | |MF1| - |MF2| | = 2a at the five points */
    for (int i = 0; i < 5; i++) {
        double x = pts[2 * i], y = pts[2 * i + 1];
        double d1 = hypot(x - five.focus[0][0], y - five.focus[0][1]);
        double d2 = hypot(x - five.focus[1][0], y - five.focus[1][1]);
        NEAR(fabs(d1 - d2), 2 * five.semi[0], 1e-10);
    }
}

static void test_ceva_ed(void **state) {
    (void)state;
    double k;
    assert_int_equal(pc_ceva_to_ed(0.25, &k), PC_OK);
    NEAR(k, 0.5, 1e-15);
    assert_int_equal(pc_ed_to_ceva(0.5, &k), PC_OK);
    NEAR(k, 0.25, 1e-15);
    assert_int_equal(pc_ceva_to_ed(0.09, &k), PC_OK);
    NEAR(k, 0.6 / 1.6, 1e-15);
    double back;
    pc_ed_to_ceva(k, &back);
    NEAR(back, 0.09, 1e-15);
    /* the same arc: Ceva's (2.104) with k and the ED (2.97) with k_ED share the point on the
     * median at t = 2/3 (A1(0,0), A2(4,0), A3(2,3): Ceva k = 1/4 gives (2, 1.5) = K of k_ED 1/2) */
    const double a1[2] = {0, 0}, a2[2] = {4, 0}, a3[2] = {2, 3};
    int st;
    pc_curve *c = pc_conic_ceva(2, a1, a2, a3, 0.25, &st), *e = pc_conic_ed(2, a2, a1, a3, 0.5, &st);
    double x[2], y[2];
    pc_curve_eval(c, 2.0 / 3, x);
    pc_curve_eval(e, 0.5, y);
    NEAR(x[0], y[0], 1e-12); NEAR(x[1], y[1], 1e-12);
    pc_curve_release(c);
    pc_curve_release(e);
    assert_int_equal(pc_ceva_to_ed(-1, &k), PC_EDOMAIN);
    assert_int_equal(pc_ed_to_ceva(1, &k), PC_EDOMAIN);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ed_kinds), cmocka_unit_test(test_ceva_kinds),
        cmocka_unit_test(test_circle), cmocka_unit_test(test_five_points),
        cmocka_unit_test(test_ceva_ed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
