/* Options of chapters 4-5 (issue 23): the interpolation contour arc of §4.9 at given node
 * parameters (pc_interp_arc_u) and the MSE divisor (pc_approx_rescale) with the Runge example of
 * §5.1 (digest konopatsky_ch3_5.md §3.2: SSE/(m+1) = 2.83922e-5, SSE/m = 2.8676e-5). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "konop_interp.h"
#include "approx.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_arc_params(void **state) {
    (void)state;
    const double pts[8] = {0, 0, 1, 2, 3, 2.5, 4, 0}, c2[2] = {0.3, 1}, cn[2] = {3.8, 1};
    const double u[4] = {0, 0.2, 0.7, 1.5};
    int st;
    pc_curve *c = pc_interp_arc_u(2, 4, pts, u, c2, cn, &st);
    assert_non_null(c);
    NEAR(c->t0, 0, 0);
    NEAR(c->t1, 1.5, 0);
    for (int j = 0; j < 4; j++) {
        double x[2];
        assert_int_equal(pc_curve_eval(c, u[j], x), PC_OK);
        NEAR(x[0], pts[2 * j], 1e-12);
        NEAR(x[1], pts[2 * j + 1], 1e-12);
    }
    /* the tangent handles are the second and the second-last control points */
    NEAR(c->cp[3], 0.3, 0); NEAR(c->cp[4], 1, 0);
    pc_curve_release(c);
    /* NULL params is the uniform arc of pc_interp_arc */
    pc_curve *a = pc_interp_arc_u(2, 4, pts, NULL, c2, cn, &st), *b = pc_interp_arc(2, 4, pts, c2, cn, &st);
    for (int i = 0; i < a->ncp * 3; i++) NEAR(a->cp[i], b->cp[i], 0);
    pc_curve_release(a);
    pc_curve_release(b);
    const double bad[4] = {0, 0.5, 0.4, 1};
    assert_null(pc_interp_arc_u(2, 4, pts, bad, c2, cn, &st));
    assert_int_equal(st, PC_EDOMAIN);
}

static double runge(double x, void *ud) {
    (void)ud;
    return 1 / (1 + 25 * x * x);
}

static void test_divisor(void **state) {
    (void)state;
    const double x[6] = {-1, -0.233198, -0.06054, 0.06054, 0.233198, 1};
    double mse, r;
    assert_int_equal(pc_approx_mse(runge, NULL, 6, x, 100, &mse), PC_OK);
    NEAR(mse, 2.83922e-5, 1e-10);
    assert_int_equal(pc_approx_rescale(mse, 100, PC_MSE_DIV_M, &r), PC_OK);
    NEAR(r, 2.8676e-5, 1e-9);
    NEAR(r, mse * 101 / 100, 1e-18);
    assert_int_equal(pc_approx_rescale(mse, 100, PC_MSE_DIV_MMINUS1, &r), PC_OK);
    NEAR(r, mse * 101 / 99, 1e-18);
    assert_int_equal(pc_approx_rescale(mse, 100, PC_MSE_DIV_M1, &r), PC_OK);
    NEAR(r, mse, 0);
    assert_int_equal(pc_approx_rescale(mse, 1, PC_MSE_DIV_MMINUS1, &r), PC_EDOMAIN);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_arc_params), cmocka_unit_test(test_divisor),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
