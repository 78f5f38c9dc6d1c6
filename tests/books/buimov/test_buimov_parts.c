/* The control points of a polynomial Bezier curve as §4.3 takes them, and the names of the
 * kinds of joint (buimov_parts.h). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "buimov_parts.h"
#include "buimov.h"

static void test_bezier_points(void **state) {
    (void)state;
    const double cp[9] = {0, 0, 1, 1, 2, 1, 3, 0, 1};
    double p[6];
    int st;
    pc_curve *c = pc_curve_bezier(2, 3, cp, &st);
    assert_non_null(c);
    assert_int_equal(pc_bezier_points(c, p), 2);
    assert_true(p[0] == 0 && p[1] == 0 && p[2] == 1 && p[3] == 2 && p[4] == 3 && p[5] == 0);
    pc_curve_release(c);
    const double rational[9] = {0, 0, 1, 2, 4, 2, 3, 0, 1};   /* the middle weight 2 */
    c = pc_curve_bezier(2, 3, rational, &st);
    assert_int_equal(pc_bezier_points(c, p), -1);
    pc_curve_release(c);
}

static void test_joint_name(void **state) {
    (void)state;
    /* P = (0,0) (1,0) (2,0), Q = (2,0) (3,0) (4,0): a C1 joint, g = 1 */
    const double p[6] = {0, 0, 1, 0, 2, 0}, q[6] = {2, 0, 3, 0, 4, 0};
    int kind;
    double g;
    assert_int_equal(pc_bezier_joint(2, 2, p, 2, q, &kind, &g), PC_OK);
    assert_string_equal(pc_bezier_joint_name(kind), "C1");
    assert_true(fabs(g - 1) < 1e-12);
    assert_string_equal(pc_bezier_joint_name(0), "none");
    assert_string_equal(pc_bezier_joint_name(2), "G1");
}

/* the G1 joint of curves: polynomial Bezier curves of one dimension, else the condition explained */
static void test_joint_of(void **state) {
    (void)state;
    const double pc[9] = {0, 0, 1, 1, 0, 1, 2, 0, 1}, qc[9] = {2, 0, 1, 3, 0, 1, 4, 0, 1};
    const double rc[9] = {0, 0, 1, 2, 0, 2, 2, 0, 1}, sc[8] = {2, 0, 0, 1, 3, 0, 0, 1};
    int st, kind;
    pc_curve *P = pc_curve_bezier(2, 3, pc, &st), *Q = pc_curve_bezier(2, 3, qc, &st);
    pc_curve *R = pc_curve_bezier(2, 3, rc, &st), *S = pc_curve_bezier(3, 2, sc, &st);
    double g, q0[2], q1[2];
    pc_why_call w;
    /* Q0 = P2, 2 (P2 - P1) = g m (Q1 - Q0) with g = 1, m = 2: Q1 = P2 + (P2 - P1) */
    assert_int_equal(pc_bezier_g1_next_of(P, 2, 1, q0, q1, &w), PC_OK);
    assert_true(q0[0] == 2 && q0[1] == 0 && q1[0] == 3 && q1[1] == 0);
    assert_null(pc_why_find(w.row, "buimov.g1_next", PC_OK));
    assert_int_equal(pc_bezier_g1_next_of(R, 2, 1, q0, q1, &w), PC_EARG);
    assert_int_equal(w.row[0].arg, 1);
    assert_string_equal(w.row[0].text, "must be a polynomial Bezier curve (bezier{P0, ..., Pn}), not a rational or "
                                       "piecewise one");
    assert_int_equal(pc_bezier_joint_of(P, Q, &kind, &g, &w), PC_OK);
    assert_string_equal(pc_bezier_joint_name(kind), "C1");
    assert_true(fabs(g - 1) < 1e-12);
    assert_int_equal(pc_bezier_joint_of(P, R, &kind, &g, &w), PC_EARG);
    assert_int_equal(w.row[0].arg, 2);
    assert_int_equal(pc_bezier_joint_of(P, S, &kind, &g, &w), PC_EDIM);
    assert_string_equal(w.row[0].op, "buimov.joint");
    assert_string_equal(w.row[0].text, "argument #2 (Q) is 3-D, but argument #1 (P) is 2-D (mixed dimensions)");
    pc_curve_release(P);
    pc_curve_release(Q);
    pc_curve_release(R);
    pc_curve_release(S);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_bezier_points), cmocka_unit_test(test_joint_name),
                                       cmocka_unit_test(test_joint_of)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
