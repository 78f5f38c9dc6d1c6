/* The slope of an implicit conic at a point on it (quadratic_on.h): the circle x^2 + y^2 = 25. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "quadratic.h"
#include "quadratic_on.h"

static const double CIRCLE[6] = {1, 0, 1, 0, 0, -25};

static void test_on(void **state) {
    (void)state;
    double s, v;
    assert_int_equal(pc_conic_slope_on(CIRCLE, 3, 4, &s, &v), PC_OK);
    assert_true(fabs(s - (-0.75)) < 1e-15);             /* -x/y */
    assert_true(v == 0);
    assert_int_equal(pc_conic_slope_on(CIRCLE, 5, 0, &s, &v), PC_EPOLE);   /* vertical */
}

static void test_off(void **state) {
    (void)state;
    double s = 7, v;
    assert_int_equal(pc_conic_slope_on(CIRCLE, 3, 4.1, &s, &v), PC_EDOMAIN);
    assert_true(fabs(v - (9 + 4.1 * 4.1 - 25)) < 1e-12);
    assert_true(s == 7);                                   /* untouched */
    assert_int_equal(pc_conic_slope_on(CIRCLE, NAN, 4, &s, &v), PC_EDOMAIN);
    /* the line pair x^2 - y^2 = 0 at its double point: singular */
    const double pair[6] = {1, 0, -1, 0, 0, 0};
    assert_int_equal(pc_conic_slope_on(pair, 0, 0, &s, &v), PC_EZERO);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_on),
        cmocka_unit_test(test_off),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
