/* The ratio of parallel vectors (point.h pc_vec_ratio): (T - A)/(T_C - A) of Konopatsky's
 * (2.62) (digest konopatsky_ch1_2.md §5.3), any dimension, and the refusals. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "point.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_ratio(void **state) {
    (void)state;
    /* T on AT_C at t: T - A = t (T_C - A) */
    const double A[3] = {1, 2, -1}, TC[3] = {4, -2, 3};
    double T[3], u[3], v[3], r, ang;
    for (int i = 0; i < 3; i++) {
        T[i] = A[i] + 0.35 * (TC[i] - A[i]);
        u[i] = T[i] - A[i];
        v[i] = TC[i] - A[i];
    }
    assert_int_equal(pc_vec_ratio(3, u, v, &r, &ang), PC_OK);
    NEAR(r, 0.35, 1e-15);
    for (int i = 0; i < 3; i++) u[i] = -2.5 * v[i];
    assert_int_equal(pc_vec_ratio(3, u, v, &r, &ang), PC_OK);
    NEAR(r, -2.5, 1e-15);
    const double z[3] = {0, 0, 0};
    assert_int_equal(pc_vec_ratio(3, z, v, &r, &ang), PC_OK);
    NEAR(r, 0, 0);
    assert_int_equal(pc_vec_ratio(3, v, z, &r, &ang), PC_EZERO);
    const double a[2] = {1, 0}, b[2] = {1, 1}, c[2] = {1, 1e-6};
    assert_int_equal(pc_vec_ratio(2, a, b, &r, &ang), PC_ENOTCOLLINEAR);
    NEAR(ang, M_PI / 4, 1e-15);
    assert_int_equal(pc_vec_ratio(2, c, a, &r, &ang), PC_ENOTCOLLINEAR);
    NEAR(ang, 1e-6, 1e-12);
    const double d[2] = {1, 1e-12};
    assert_int_equal(pc_vec_ratio(2, d, a, &r, &ang), PC_OK);      /* within 1e-9 */
    NEAR(r, 1, 0);
    const double nan2[2] = {NAN, 0};
    assert_int_equal(pc_vec_ratio(2, nan2, a, &r, &ang), PC_ENONFINITE);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_ratio)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
