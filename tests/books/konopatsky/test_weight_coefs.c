/* The interpolation weights as polynomials (konop_interp.h pc_lagrange_weight_coefs): the
 * output of the Maple program of §4.8 for n = 5 (digest konopatsky_ch3_5.md §2.4, "Equivalent
 * output"), and agreement with the numeric weights at other nodes. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "konop_interp.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_maple_n5(void **state) {
    (void)state;
    double c[36];
    assert_int_equal(pc_lagrange_weight_coefs(6, NULL, c), PC_OK);
    /* rows M1..M6 from u^0 up */
    const double want[6][6] = {
        {1, -137.0 / 12, 375.0 / 8, -2125.0 / 24, 625.0 / 8, -625.0 / 24},
        {0, 25, -1925.0 / 12, 8875.0 / 24, -4375.0 / 12, 3125.0 / 24},
        {0, -25, 2675.0 / 12, -7375.0 / 12, 8125.0 / 12, -3125.0 / 12},
        {0, 50.0 / 3, -325.0 / 2, 6125.0 / 12, -625, 3125.0 / 12},
        {0, -25.0 / 4, 1525.0 / 24, -5125.0 / 24, 6875.0 / 24, -3125.0 / 24},
        {0, 1, -125.0 / 12, 875.0 / 24, -625.0 / 12, 625.0 / 24}};
    for (int j = 0; j < 6; j++)
        for (int i = 0; i < 6; i++) NEAR(c[6 * j + i], want[j][i], 1e-10);
}

static void test_against_weights(void **state) {
    (void)state;
    const double u[4] = {0, 0.2, 0.7, 1};
    double c[16], w[4];
    assert_int_equal(pc_lagrange_weight_coefs(4, u, c), PC_OK);
    for (double t = -0.5; t <= 1.5; t += 0.25) {
        pc_lagrange_weights(4, u, t, w);
        double sum = 0;
        for (int j = 0; j < 4; j++) {
            double v = c[4 * j] + t * (c[4 * j + 1] + t * (c[4 * j + 2] + t * c[4 * j + 3]));
            NEAR(v, w[j], 1e-12);
            sum += v;
        }
        NEAR(sum, 1, 1e-12);
    }
    const double bad[3] = {0, 0.5, 0.5};
    assert_int_equal(pc_lagrange_weight_coefs(3, bad, c), PC_ECOINCIDENT);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_maple_n5), cmocka_unit_test(test_against_weights),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
