/* The textbook's API gaps of issue 24: the G1 joint of Bezier curves (Buimov §4.3, digest buimov_textbook.md: P_n = Q_0 and
 * n (P_n - P_(n-1)) = g m (Q_1 - Q_0)) the spline with the user's segment lengths, the sphere frame at a general centre. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "buimov.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_g1(void **state) {
    (void)state;
    const double p[8] = {0, 0, 1, 2, 3, 3, 4, 2};   /* a cubic ending at (4, 2) along (1, -1) */
    double q0[2], q1[2];
    assert_int_equal(pc_bezier_g1_next(2, 3, p, 2, 1.5, q0, q1), PC_OK);
    NEAR(q0[0], 4, 0); NEAR(q0[1], 2, 0);
    NEAR(q1[0], 4 + 3 * 1.0 / (1.5 * 2), 1e-15); NEAR(q1[1], 2 - 3 * 1.0 / (1.5 * 2), 1e-15);
    double q[6] = {q0[0], q0[1], q1[0], q1[1], 7, 0}, g;
    int kind;
    assert_int_equal(pc_bezier_joint(2, 3, p, 2, q, &kind, &g), PC_OK);
    assert_int_equal(kind, 2);
    NEAR(g, 1.5, 1e-12);
    /* the derivatives at the joint: P'(1) = g Q'(0) */
    assert_int_equal(pc_bezier_g1_next(2, 3, p, 2, 1, q0, q1), PC_OK);
    q[2] = q1[0], q[3] = q1[1];
    pc_bezier_joint(2, 3, p, 2, q, &kind, &g);
    assert_int_equal(kind, 3);                      /* g = 1: C1 */
    q[2] = 5, q[3] = 2;                             /* a corner */
    pc_bezier_joint(2, 3, p, 2, q, &kind, &g);
    assert_int_equal(kind, 1);
    q[0] = 4.1;                                     /* apart */
    pc_bezier_joint(2, 3, p, 2, q, &kind, &g);
    assert_int_equal(kind, 0);
    q[0] = 4, q[2] = 3, q[3] = 3;                   /* collinear but turning back: not G1 */
    pc_bezier_joint(2, 3, p, 2, q, &kind, &g);
    assert_int_equal(kind, 1);
    assert_int_equal(pc_bezier_g1_next(2, 3, p, 2, 0, q0, q1), PC_EDOMAIN);
}

/* buimov.spline with the user's segment lengths (issue 24): the nodes at the accumulated
 * lengths, C2 at the joints, and the book's uniform lengths give the uniform spline */
static void test_spline_lengths(void **state) {
    (void)state;
    const double p[8] = {0, 0, 1, 2, 3, 3, 4, 0}, tl[3] = {1, 2.5, 0.5}, d0[2] = {1, 1}, d1[2] = {1, -1};
    int st;
    pc_curve *c = pc_curve_book_spline_tl(2, 4, p, tl, PC_BOOK_CLAMPED, d0, d1, NULL, &st);
    assert_non_null(c);
    const double u[4] = {0, 1, 3.5, 4};
    for (int j = 0; j < 4; j++) {
        double x[2];
        pc_curve_eval(c, u[j], x);
        NEAR(x[0], p[2 * j], 1e-12);
        NEAR(x[1], p[2 * j + 1], 1e-12);
    }
    double l[6], r[6];
    for (int j = 1; j <= 2; j++) {
        pc_curve_derivs_n(c, u[j], 2, -1, l);
        pc_curve_derivs_n(c, u[j], 2, 1, r);
        for (int k = 2; k < 6; k++) NEAR(l[k], r[k], 1e-9);     /* C2 at the joints */
    }
    pc_curve_derivs(c, 0, 1, l);
    NEAR(l[2], 1, 1e-12); NEAR(l[3], 1, 1e-12);              /* the clamped tangent */
    pc_curve_release(c);
    const double ones[3] = {1, 1, 1};
    pc_curve *a = pc_curve_book_spline_tl(2, 4, p, ones, PC_BOOK_NATURAL, NULL, NULL, NULL, &st);
    pc_curve *b = pc_curve_book_spline(2, 4, p, 0, PC_BOOK_NATURAL, NULL, NULL, NULL, &st);
    double x[2], y[2];
    pc_curve_eval(a, 1.7, x);
    pc_curve_eval(b, 1.7, y);
    NEAR(x[0], y[0], 1e-15); NEAR(x[1], y[1], 1e-15);
    pc_curve_release(a);
    pc_curve_release(b);
    const double bad[3] = {1, 0, 1};
    assert_null(pc_curve_book_spline_tl(2, 4, p, bad, PC_BOOK_NATURAL, NULL, NULL, NULL, &st));
    assert_int_equal(st, PC_EDOMAIN);
}

/* the sphere frame at a general centre against the surface's partials and differences */
static void test_sphere_at(void **state) {
    (void)state;
    const double c[3] = {1, -2, 0.5};
    double f[15];
    assert_int_equal(pc_sphere_frame_at(c, 2.5, 0.4, 1.1, f), PC_OK);
    double u[15];
    pc_sphere_frame(0.4, 1.1, u);
    for (int j = 0; j < 3; j++) {
        NEAR(f[j], c[j] + 2.5 * u[j], 1e-15);
        NEAR(f[9 + j], 2.5 * u[9 + j], 1e-15);          /* the twist */
    }
    /* the twist is d/dph of S_th: differences of the frame */
    double a[15], b[15], h = 1e-6;
    pc_sphere_frame_at(c, 2.5, 0.4, 1.1 - h, a);
    pc_sphere_frame_at(c, 2.5, 0.4, 1.1 + h, b);
    for (int j = 0; j < 3; j++) NEAR(f[9 + j], (b[3 + j] - a[3 + j]) / (2 * h), 1e-8);
    /* N = S_th x S_ph */
    NEAR(f[12], f[4] * f[8] - f[5] * f[7], 1e-12);
    NEAR(f[13], f[5] * f[6] - f[3] * f[8], 1e-12);
    NEAR(f[14], f[3] * f[7] - f[4] * f[6], 1e-12);
    assert_int_equal(pc_sphere_frame_at(c, 0, 0.4, 1.1, f), PC_EDOMAIN);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_g1), cmocka_unit_test(test_spline_lengths),
                                       cmocka_unit_test(test_sphere_at)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
