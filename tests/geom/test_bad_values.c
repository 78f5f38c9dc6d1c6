/* Issue 15, item 7: values the core used to turn silently into wrong results.  lerp of two
 * points at a huge t rounded the weight to 0 (a vector); divide at a huge lambda overflowed
 * to an infinite point; the sine smoothstep at a huge t was cos(inf) = NaN. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include "point.h"
#include "smooth.h"

static void test_lerp_keeps_equal_weights(void **state) {
    (void)state;
    const double a[3] = {0, 0, 1}, b[3] = {1, 0, 1};
    double out[3];
    pc_lerp(2, a, b, 1e16, out);
    assert_true(out[2] == 1);                 /* a point, not a vector */
    assert_true(out[0] == 1e16 && out[1] == 0);
    pc_lerp(2, a, b, 0.25, out);              /* (B - A) t + A */
    assert_true(out[0] == 0.25 && out[2] == 1);
    const double u[3] = {1, 0, 0}, v[3] = {0, 1, 0};
    pc_lerp(2, u, v, 1e16, out);
    assert_true(out[2] == 0);                 /* two vectors: a vector */
    const double w[3] = {2, 2, 2};            /* weights 1 and 2: t̄ + 2t */
    pc_lerp(2, a, w, 0.5, out);
    assert_true(out[2] == 1.5);
    /* the status: an overflow or a t that is not finite is PC_ENONFINITE */
    assert_int_equal(pc_lerp(2, a, b, 0.25, out), PC_OK);
    const double big[3] = {1e308, 0, 1}, far[3] = {-1e308, 0, 1};
    assert_int_equal(pc_lerp(2, big, far, 3, out), PC_ENONFINITE);
    assert_int_equal(pc_lerp(2, a, b, INFINITY, out), PC_ENONFINITE);
    assert_int_equal(pc_lerp(2, a, b, NAN, out), PC_ENONFINITE);
    const double x[2] = {2, 1}, y[2] = {4, 1};            /* two numbers: 2 t̄ + 4 t */
    assert_int_equal(pc_lerp(1, x, y, 0.75, out), PC_OK);
    assert_true(out[0] == 3.5 && out[1] == 1);
}

static void test_divide_huge_lambda(void **state) {
    (void)state;
    const double x[3] = {1, 0, 1}, y[3] = {2, 0, 1};
    double z[3];
    assert_int_equal(pc_divide(2, x, y, 1e308, z), PC_OK);
    assert_true(z[0] == 2 && z[1] == 0 && z[2] == 1);      /* Y itself, finite */
    assert_int_equal(pc_divide(2, x, y, -1e308, z), PC_OK);
    assert_true(z[0] == 2 && z[2] == 1);
    assert_int_equal(pc_divide(2, x, y, 3, z), PC_OK);     /* (X + 3Y)/4 = 7/4 */
    assert_true(fabs(z[0] / z[2] - 1.75) < 1e-15);
    assert_int_equal(pc_divide(2, x, y, 0.5, z), PC_OK);   /* (X + Y/2)/(3/2) = 4/3 */
    assert_true(fabs(z[0] / z[2] - 4.0 / 3) < 1e-15);
    assert_int_equal(pc_divide(2, x, y, -1, z), PC_IMPROPER);
    assert_true(z[2] == 0);
    const double far1[3] = {-1e308, 0, 1}, far2[3] = {1e308, 0, 1};
    assert_int_equal(pc_divide(2, far1, far2, -0.5, z), PC_ENONFINITE);
}

static void test_sine_any_t(void **state) {
    (void)state;
    assert_true(pc_smooth_sine(1e308) == 0);                 /* an even integer */
    assert_true(pc_smooth_sine(-1e308) == 0);
    assert_true(fabs(pc_smooth_sine(3.5) - 0.5) < 1e-15);    /* period 2 */
    assert_true(fabs(pc_smooth_sine(1) - 1) < 1e-15);
    assert_true(pc_smooth_sine(0) == 0);
    assert_true(fabs(pc_smooth_sine(0.5) - 0.5) < 1e-15);
    for (double t = 1e3; t < 1e300; t *= 7.3) assert_true(isfinite(pc_smooth_sine(t)));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lerp_keeps_equal_weights),
        cmocka_unit_test(test_divide_huge_lambda),
        cmocka_unit_test(test_sine_any_t),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
