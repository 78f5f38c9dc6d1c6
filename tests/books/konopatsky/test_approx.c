/* The optimiser and the approximation curves of Konopatsky's chapter 5 (optimize.h): Nelder-Mead
 * on Rosenbrock's function; the book's MSE at the book's nodes; the optimal-node search reaching
 * the book's Runge nodes and MSE and every other row at or below the book's value; the
 * Chebyshev comparison (digest konopatsky_ch3_5.md §3 and §6). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "approx.h"
#include "status.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static double rosenbrock(void *ud, const double *x) {
    (void)ud;
    return 100 * (x[1] - x[0] * x[0]) * (x[1] - x[0] * x[0]) + (1 - x[0]) * (1 - x[0]);
}

static void test_rosenbrock(void **state) {
    (void)state;
    double x[2] = {-1.2, 1}, fx;
    int it;
    assert_int_equal(pc_nelder_mead(2, rosenbrock, NULL, x, 0.5, 1e-15, 1e-9, 10000, &fx, &it), PC_OK);
    NEAR(x[0], 1, 1e-6);
    NEAR(x[1], 1, 1e-6);
    assert_true(fx < 1e-12);
    /* deterministic: the same run gives the same iterations and point */
    double y[2] = {-1.2, 1}, fy;
    int it2;
    pc_nelder_mead(2, rosenbrock, NULL, y, 0.5, 1e-15, 1e-9, 10000, &fy, &it2);
    assert_int_equal(it, it2);
    assert_true(x[0] == y[0] && x[1] == y[1]);
    /* the iteration limit */
    double z[2] = {-1.2, 1}, fz;
    assert_int_equal(pc_nelder_mead(2, rosenbrock, NULL, z, 0.5, 1e-15, 1e-9, 10, &fz, NULL), PC_ENOCONVERGE);
    assert_true(fz < rosenbrock(NULL, (double[]){-1.2, 1}));
}

static double runge(double x, void *ud) { (void)ud; return 1 / (1 + 25 * x * x); }
static double ellipse(double x, void *ud) { (void)ud; return sqrt(fmax(9 - 9 * x * x / 16, 0)); }
static double sines(double x, void *ud) { (void)ud; return sin(x) + sin(10 * x); }

static double pole(double x, void *ud) {
    (void)ud;
    return 1 / x;
}

/* §5.1 the curve through (x_j, f(x_j)) at uniform t */
static void test_curve(void **state) {
    (void)state;
    const double x[3] = {-1, 0.25, 1};
    int st, bad = -1;
    pc_curve *c = pc_approx_curve(runge, NULL, 3, x, &bad, &st);
    assert_non_null(c);
    double m[2];
    assert_int_equal(pc_curve_eval(c, 0.5, m), PC_OK);    /* the middle node at t = 1/2 */
    NEAR(m[0], 0.25, 1e-15);
    NEAR(m[1], runge(0.25, NULL), 1e-15);
    assert_int_equal(pc_curve_eval(c, 1, m), PC_OK);
    NEAR(m[1], 1.0 / 26, 1e-15);
    pc_curve_release(c);
    const double y[3] = {-1, 0, 1};
    assert_null(pc_approx_curve(pole, NULL, 3, y, &bad, &st));
    assert_int_equal(st, PC_ENONFINITE);
    assert_int_equal(bad, 1);
    assert_null(pc_approx_curve(runge, NULL, 1, y, &bad, &st));
    assert_int_equal(st, PC_EDOMAIN);
}

/* the book's nodes give the book's MSE (with SSE/(m + 1)) */
static void test_mse(void **state) {
    (void)state;
    double x6[6] = {-1, -0.233198, -0.06054, 0.06054, 0.233198, 1}, mse;
    assert_int_equal(pc_approx_mse(runge, NULL, 6, x6, 100, &mse), PC_OK);
    NEAR(mse, 2.839222e-5, 2e-10);
    double xe[4] = {-4, -1.877016, 1.877016, 4};
    pc_approx_mse(ellipse, NULL, 4, xe, 10, &mse);
    NEAR(mse, 1.457706e-4, 1e-9);
    double xs[6] = {-0.5, -0.265069, -0.084952, 0.084952, 0.265069, 0.5};
    pc_approx_mse(sines, NULL, 6, xs, 100, &mse);
    NEAR(mse, 2.47155e-6, 1e-10);
    double x10[10] = {-1, -0.52455, -0.3, -0.128125, -0.030585, 0.030585, 0.128125, 0.3, 0.52455, 1};
    pc_approx_mse(sines, NULL, 10, x10, 50, &mse);
    NEAR(mse, 4.6214e-4, 1e-8);
}

/* Runge, 6 nodes, m = 100: the book's nodes +-0.233198, +-0.06054 and 2.83922e-5 */
static void test_runge_search(void **state) {
    (void)state;
    double x[6], mse;
    int evals;
    assert_int_equal(pc_approx_optimal_nodes(runge, NULL, -1, 1, 6, 100, x, &mse, &evals), PC_OK);
    NEAR(mse, 2.83922e-5, 2.83922e-5 * 1e-6);
    assert_true(mse <= 2.8393e-5);
    NEAR(x[0], -1, 0);
    NEAR(x[1], -0.233198, 2e-6);
    NEAR(x[2], -0.06054, 2e-6);
    NEAR(x[3], 0.06054, 2e-6);
    NEAR(x[4], 0.233198, 2e-6);
    NEAR(x[5], 1, 0);
}

/* Table 5.1 and the other examples: at or below the book's printed values */
static void test_table(void **state) {
    (void)state;
    /* book: the printed value; hu: half a unit of its last printed digit */
    struct { pc_scalar_fn f; double a, b; int N, m; double book, hu; } rows[] = {
        {runge, -1, 1, 5, 10, 0.000963, 0.5e-6},
        {runge, -1, 1, 7, 100, 5.14e-7, 0.005e-7},
        {runge, -1, 1, 8, 100, 1.01e-8, 0.005e-8},
        {runge, -1, 1, 9, 100, 8.15e-10, 0.005e-10},
        {runge, -1, 1, 10, 100, 2.67e-8, 0.005e-8},
        {runge, -1, 1, 11, 100, 4e-9, 0.5e-9},
        {runge, -2.5, 2.5, 6, 100, 0.0005587, 0.00000005},
        {runge, -2.5, 2.5, 7, 100, 0.00001936, 0.000000005},
        {ellipse, -4, 4, 4, 10, 0.00014577, 0.000000005},
        {sines, -0.5, 0.5, 6, 100, 2.47e-6, 0.005e-6},
        {sines, -1, 1, 10, 50, 0.000462, 0.0000005},
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        double x[16], mse;
        assert_int_equal(pc_approx_optimal_nodes(rows[i].f, NULL, rows[i].a, rows[i].b, rows[i].N,
                                                 rows[i].m, x, &mse, NULL), PC_OK);
        /* at or below the book's value within its rounding */
        assert_true(mse <= rows[i].book + rows[i].hu);
        for (int j = 1; j < rows[i].N; j++) assert_true(x[j] > x[j - 1]);
    }
}

static void test_chebyshev(void **state) {
    (void)state;
    double x[23], mse;
    assert_int_equal(pc_chebyshev_nodes(23, -1, 1, x), PC_OK);
    assert_true(x[0] < x[22]);
    NEAR(x[22], cos(M_PI / 46), 1e-15);
    assert_int_equal(pc_lagrange_mse_x(runge, NULL, 23, x, -1, 1, 101, &mse), PC_OK);
    NEAR(mse, 2.53e-5, 0.01e-5);          /* book 0.0000253 */
    assert_int_equal(pc_chebyshev_nodes(2, 1, 1, x), PC_EDOMAIN);   /* an empty interval */
    pc_chebyshev_nodes(6, -1, 1, x);
    pc_lagrange_mse_x(runge, NULL, 6, x, -1, 1, 101, &mse);
    NEAR(mse, 0.0314, 0.0001);            /* the number the book leaves blank */
    double u[6] = {-1, -0.6, -0.2, 0.2, 0.6, 1};
    pc_lagrange_mse_x(runge, NULL, 6, u, -1, 1, 101, &mse);
    NEAR(mse, 0.0211, 0.0001);
    assert_int_equal(pc_approx_optimal_nodes(runge, NULL, 1, -1, 6, 100, x, &mse, NULL), PC_EDOMAIN);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rosenbrock),   cmocka_unit_test(test_mse),
        cmocka_unit_test(test_runge_search), cmocka_unit_test(test_table),
        cmocka_unit_test(test_chebyshev),    cmocka_unit_test(test_curve),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
