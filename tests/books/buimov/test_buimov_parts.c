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

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_bezier_points), cmocka_unit_test(test_joint_name)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
