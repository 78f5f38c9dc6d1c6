/* The G1 joint of Bezier curves (Buimov §4.3, digest buimov_textbook.md: P_n = Q_0 and
 * n (P_n - P_(n-1)) = g m (Q_1 - Q_0)) */
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

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_g1)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
