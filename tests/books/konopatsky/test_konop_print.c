/* The book's printed coordinates (konop_print.h): Fig. 2.17's x(t), y(t) of the digest
 * (konopatsky_ch1_2.md §5.5) from the power-basis coefficients, a polynomial, a 3-D curve and
 * the failures. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>
#include "konop_print.h"
#include "curve.h"
#include "status.h"

/* x = 4t(9t + 0,8)/(70t^2 - 75t + 44,2) and y = -8t(t - 1)/(14t^2 - 15t + 8,84), the book's
 * scale: the same curve as (36t^2 + 3.2t, (-40t^2 + 40t), 70t^2 - 75t + 44.2) homogeneous;
 * the monic denominator is t^2 - 1.07143t + 0.631429 */
static void test_fig217(void **state) {
    (void)state;
    const double coef[3 * 3] = {0, 0, 44.2, 3.2, 40, -75, 36, -40, 70};
    char buf[160];
    assert_int_equal(pc_k_coordinate_text(coef, 2, 2, 0, "t", buf, sizeof buf), PC_OK);
    assert_string_equal(buf, "x = (0.514286t^2 + 0.0457143t)/(t^2 - 1.07143t + 0.631429)");
    assert_int_equal(pc_k_coordinate_text(coef, 2, 2, 1, "t", buf, sizeof buf), PC_OK);
    assert_string_equal(buf, "y = (-0.571429t^2 + 0.571429t)/(t^2 - 1.07143t + 0.631429)");
}

/* a polynomial (constant weight 2: the coordinates are halved), unit coefficients and a zero
 * coordinate; z and the fourth axis name */
static void test_polynomial(void **state) {
    (void)state;
    const double coef[4 * 5] = {2, 0, 0, 0, 2,  -4, 2, 0, 0, 0,  0, 0, 0, 0, 0,  6, 0, 0, 1, 0};
    char buf[80];
    assert_int_equal(pc_k_coordinate_text(coef, 4, 3, 0, "u", buf, sizeof buf), PC_OK);
    assert_string_equal(buf, "x = 3u^3 - 2u + 1");
    assert_int_equal(pc_k_coordinate_text(coef, 4, 3, 1, "u", buf, sizeof buf), PC_OK);
    assert_string_equal(buf, "y = u");
    assert_int_equal(pc_k_coordinate_text(coef, 4, 3, 2, "u", buf, sizeof buf), PC_OK);
    assert_string_equal(buf, "z = 0");
    assert_int_equal(pc_k_coordinate_text(coef, 4, 3, 3, "u", buf, sizeof buf), PC_OK);
    assert_string_equal(buf, "x4 = 0.5u^3");
}

static void test_failures(void **state) {
    (void)state;
    const double zero[2 * 3] = {1, 2, 0, 3, 4, 0};
    char buf[8];
    assert_int_equal(pc_k_coordinate_text(zero, 2, 1, 0, "t", buf, sizeof buf), PC_EDOMAIN);
    assert_int_equal(pc_k_coordinate_text(zero, 2, 1, 2, "t", buf, sizeof buf), PC_EDIM);
    const double line[2 * 2] = {1, 1, 2, 0};
    assert_int_equal(pc_k_coordinate_text(line, 1, 1, 0, "t", buf, 5), PC_ENOMEM);
}

/* a curve's own coordinates: the parabola B(t) on (0, 0), (1, 2), (2, 0): x = 2t, y = -4t^2 + 4t */
static void test_curve_text(void **state) {
    (void)state;
    const double cp[9] = {0, 0, 1, 1, 2, 1, 2, 0, 1};
    int st;
    pc_curve *c = pc_curve_bezier(2, 3, cp, &st);
    char buf[80];
    assert_int_equal(pc_k_curve_text(c, 0, "t", buf, sizeof buf), PC_OK);
    assert_string_equal(buf, "x = 2t");
    assert_int_equal(pc_k_curve_text(c, 1, "s", buf, sizeof buf), PC_OK);
    assert_string_equal(buf, "y = -4s^2 + 4s");
    pc_curve_release(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fig217),
        cmocka_unit_test(test_polynomial),
        cmocka_unit_test(test_failures),
        cmocka_unit_test(test_curve_text),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
