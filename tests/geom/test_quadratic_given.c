/* The conic of given points and tangents (quadratic_given.h): the elements, and a status of
 * its own for each way the conditions fail to fix one conic. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "quadratic_given.h"
#include "status.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_five(void **state) {
    (void)state;
    /* five points of the ellipse x^2/9 + y^2/4 = 1 */
    double pts[10];
    for (int i = 0; i < 5; i++) pts[2 * i] = 3 * cos(0.3 + 1.2 * i), pts[2 * i + 1] = 2 * sin(0.3 + 1.2 * i);
    pc_conic_info o;
    assert_int_equal(pc_conic_info_five(pts, &o), PC_OK);
    assert_int_equal(o.kind, PC_CK_ELLIPSE);
    NEAR(o.semi[0], 3, 1e-12);
    NEAR(o.semi[1], 2, 1e-12);
    NEAR(o.center[0], 0, 1e-12);
    const double bad[10] = {0, 0, 1, 1, 2, 2, 3, 3, 0, 5};   /* four collinear */
    assert_int_equal(pc_conic_info_five(bad, &o), PC_ECOINCIDENT);
}

static void test_given(void **state) {
    (void)state;
    /* Korotky's C-1 hyperbola: U = (0, 0), V = (2, 0) with tangents (1, sqrt 3), (-1, sqrt 3),
     * and T = (1, 1.5): centre (1, 1.774519), semi-axes 0.274519 and 0.156586 */
    const double r3 = sqrt(3), pts[6] = {0, 0, 2, 0, 1, 1.5}, tg[8] = {0, 0, 1, r3, 2, 0, -1, r3};
    pc_conic_info o;
    assert_int_equal(pc_conic_info_given(3, pts, 2, tg, &o), PC_OK);
    assert_int_equal(o.kind, PC_CK_HYPERBOLA);
    NEAR(o.center[0], 1, 1e-12);
    NEAR(o.center[1], 1.774519, 1e-6);
    NEAR(o.semi[0], 0.274519, 1e-6);
    NEAR(o.semi[1], 0.156586, 1e-6);
    assert_int_equal(pc_conic_info_given(2, pts, 2, tg, &o), PC_EDIM);          /* four conditions */
    const double twice[6] = {0, 0, 2, 0, 0, 0};                                   /* U given twice */
    assert_int_equal(pc_conic_info_given(3, twice, 2, tg, &o), PC_ESINGULAR);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_five),
        cmocka_unit_test(test_given),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
