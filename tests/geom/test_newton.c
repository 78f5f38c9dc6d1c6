/* Newton's method for small systems and the BFGS minimiser (numeric.h), used by Korotky's
 * Ferguson splines (system (23)) and the elastic reference curve. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "numeric.h"
#include "optimize.h"
#include "status.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

/* x^2 + y^2 = 4, x y = 1: the root near (1.9, 0.5) is ((sqrt 6 + sqrt 2)/2, (sqrt 6 - sqrt 2)/2) */
static int circle_hyperbola(void *ud, const double *x, double *f) {
    (void)ud;
    f[0] = x[0] * x[0] + x[1] * x[1] - 4;
    f[1] = x[0] * x[1] - 1;
    return PC_OK;
}

static void test_newton_root(void **state) {
    (void)state;
    double x[2] = {1.9, 0.5};
    int it = 0, worst = 7;
    assert_int_equal(pc_newton(2, circle_hyperbola, NULL, x, 1e-14, 50, &it, &worst), PC_OK);
    NEAR(x[0], (sqrt(6) + sqrt(2)) / 2, 1e-12);
    NEAR(x[1], (sqrt(6) - sqrt(2)) / 2, 1e-12);
    assert_true(it >= 2 && it <= 10);   /* quadratic convergence from a close start */
    assert_int_equal(worst, -1);
    /* a far start still reaches a root, by step halving */
    double y[2] = {10, -3};
    assert_int_equal(pc_newton(2, circle_hyperbola, NULL, y, 1e-14, 100, NULL, NULL), PC_OK);
    double f[2];
    circle_hyperbola(NULL, y, f);
    NEAR(f[0], 0, 1e-10);
    NEAR(f[1], 0, 1e-10);
}

/* no real root: x^2 + 1 = 0 (one unknown) and y - 2 = 0 */
static int no_root(void *ud, const double *x, double *f) {
    (void)ud;
    f[0] = x[1] - 2;
    f[1] = x[0] * x[0] + 1;
    return PC_OK;
}

/* singular: the second unknown does not occur */
static int missing_unknown(void *ud, const double *x, double *f) {
    (void)ud;
    f[0] = x[0] - 1;
    f[1] = 2 * x[0] - 2;
    return PC_OK;
}

static int nan_at_x(void *ud, const double *x, double *f) {
    (void)ud;
    f[0] = x[0] - 1;
    f[1] = x[1] > 3 ? NAN : x[1] - 5;
    return PC_OK;
}

static void test_newton_failures(void **state) {
    (void)state;
    double x[2] = {0.5, 0};
    int worst = -1;
    assert_int_equal(pc_newton(2, no_root, NULL, x, 1e-12, 40, NULL, &worst), PC_ENOCONVERGE);
    assert_int_equal(worst, 1);      /* the equation that cannot be met */
    double y[2] = {3, 3};
    assert_int_equal(pc_newton(2, missing_unknown, NULL, y, 1e-12, 40, NULL, &worst), PC_ESINGULAR);
    assert_int_equal(worst, 1);      /* the unknown without a pivot */
    double z[2] = {0, 4};
    assert_int_equal(pc_newton(2, nan_at_x, NULL, z, 1e-12, 40, NULL, &worst), PC_ENONFINITE);
    assert_int_equal(worst, 1);
    double q[2] = {NAN, 0};
    assert_int_equal(pc_newton(2, circle_hyperbola, NULL, q, 1e-12, 40, NULL, &worst), PC_ENONFINITE);
    assert_int_equal(worst, 0);
    assert_int_equal(pc_newton(0, circle_hyperbola, NULL, q, 1e-12, 40, NULL, NULL), PC_EDIM);
    assert_int_equal(pc_newton(PC_NEWTON_MAXN + 1, circle_hyperbola, NULL, q, 1e-12, 40, NULL, NULL), PC_EDIM);
}

/* Rosenbrock's valley: minimum 0 at (1, 1) */
static double rosen(void *ud, const double *x) {
    (void)ud;
    return 100 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]) + (1 - x[0]) * (1 - x[0]);
}

/* a quadratic bowl centred at (1, -2, 3) with its Hessian diag(2, 20, 200) */
static double bowl(void *ud, const double *x) {
    (void)ud;
    return (x[0] - 1) * (x[0] - 1) + 10 * (x[1] + 2) * (x[1] + 2) + 100 * (x[2] - 3) * (x[2] - 3);
}

static double nan_start(void *ud, const double *x) {
    (void)ud;
    return x[0] > 0 ? NAN : x[0] * x[0];
}

static void test_minimize(void **state) {
    (void)state;
    double x[2] = {-1.2, 1}, fx;
    int it;
    assert_int_equal(pc_minimize(2, rosen, NULL, x, 1e-8, 0, 1000, &fx, &it), PC_OK);
    NEAR(x[0], 1, 1e-5);
    NEAR(x[1], 1, 1e-5);
    assert_true(fx < 1e-10);
    double y[3] = {0, 0, 0};
    assert_int_equal(pc_minimize(3, bowl, NULL, y, 1e-9, 0, 200, &fx, &it), PC_OK);
    NEAR(y[0], 1, 1e-7);
    NEAR(y[1], -2, 1e-7);
    NEAR(y[2], 3, 1e-7);
    double r[2] = {-1.2, 1};
    assert_int_equal(pc_minimize(2, rosen, NULL, r, 1e-12, 0, 3, NULL, NULL), PC_ENOCONVERGE);
    double z[1] = {1};
    assert_int_equal(pc_minimize(1, nan_start, NULL, z, 1e-9, 0, 10, NULL, NULL), PC_ENONFINITE);
    assert_int_equal(pc_minimize(0, bowl, NULL, y, 1e-9, 0, 10, NULL, NULL), PC_EDIM);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_newton_root),
        cmocka_unit_test(test_newton_failures),
        cmocka_unit_test(test_minimize),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
