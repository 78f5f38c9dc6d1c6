/* Running equations with the reasons worded (expr_run.c, pc_expr_curve_at in expr_curve.c):
 * the value of 1/(t - s) at t = s is no number and the message lists the values; samples of
 * sqrt(t - 1/2) fail at the first sample left of 1/2; a curve applies to a scalar equation only
 * when it is a single-piece Bezier. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "expr.h"

static void test_value_at(void **state) {
    (void)state;
    pc_expr_pool *P = pc_expr_pool_new();
    int st, t = pc_expr_param(P, "t", &st), s = pc_expr_param(P, "s", &st), in[2] = {t, s};
    int e = pc_expr_div(P, pc_expr_const(P, 1, &st), pc_expr_sub(P, t, s, &st), &st);
    pc_expr_prog *p = pc_expr_compile(P, e, 2, in, &st);
    assert_non_null(p);
    double h[2], x[2] = {3, 1};
    char why[256] = "";
    assert_int_equal(pc_expr_value_at(P, p, 2, in, x, h, why, sizeof why), PC_OK);
    assert_true(fabs(h[0] - 0.5) < 1e-15);
    x[0] = 1;
    assert_int_equal(pc_expr_value_at(P, p, 2, in, x, h, why, sizeof why), PC_ENONFINITE);
    assert_string_equal(why, "the value at t = 1, s = 1 is not finite (NaN or infinite: outside the domain of a "
                             "function, or a division by zero)");
    pc_expr_prog_free(p);
    pc_expr_pool_free(P);
}

static void test_sample_at(void **state) {
    (void)state;
    pc_expr_pool *P = pc_expr_pool_new();
    int st, t = pc_expr_param(P, "t", &st);
    int e = pc_expr_fn(P, PC_EX_SQRT, pc_expr_sub(P, t, pc_expr_const(P, 0.5, &st), &st), &st);
    pc_expr_prog *p = pc_expr_compile(P, e, 1, &t, &st);
    double out[5];
    char why[128] = "";
    assert_int_equal(pc_expr_sample_at(P, p, t, 0.5, 1, 5, out, why, sizeof why), PC_OK);
    assert_true(fabs(out[4] - sqrt(0.5)) < 1e-15);
    assert_int_equal(pc_expr_sample_at(P, p, t, 1, 0, 5, out, why, sizeof why), PC_ENONFINITE);
    assert_string_equal(why, "the value at t = 0.25 is not finite");   /* 1, 0.75, 0.5, then 0.25 */
    assert_string_equal(pc_expr_why(PC_ENOMEM), "out of memory (too many equation nodes)");
    assert_string_equal(pc_expr_why(PC_EDIM), pc_strerror(PC_EDIM));
    pc_expr_prog_free(p);
    pc_expr_pool_free(P);
}

static void test_curve_at(void **state) {
    (void)state;
    pc_expr_pool *P = pc_expr_pool_new();
    double cp[9] = {0, 0, 1, 1, 2, 1, 2, 0, 1}, h0[3] = {1, 2, 1};
    int st, t = pc_expr_param(P, "t", &st);
    pc_curve *c = pc_curve_bezier(2, 3, cp, &st);
    char why[256] = "";
    int e = pc_expr_curve_at(P, c, t, why, sizeof why);
    assert_true(e >= 0);
    assert_int_equal(pc_expr_dim(P, e), 2);
    pc_expr_prog *p = pc_expr_compile(P, e, 1, &t, &st);
    double x = 0.5, h[3];
    assert_int_equal(pc_expr_eval(p, 1, &x, 0, h, NULL), PC_OK);
    assert_true(fabs(h[0] - 1) < 1e-15 && fabs(h[1] - 1) < 1e-15 && fabs(h[2] - 1) < 1e-15);   /* (0,0), (1,2), (2,0) */
    pc_expr_prog_free(p);
    assert_int_equal(pc_expr_curve_at(P, c, pc_expr_vconst(P, 2, h0, &st), why, sizeof why), -1);
    assert_string_equal(why, "the parameter must be a number or a scalar equation, got a 2-D point equation");
    pc_curve *two = pc_curve_bezier_pieces(2, 1, 2, cp, NULL, &st);
    assert_int_equal(pc_expr_curve_at(P, two, t, why, sizeof why), -1);
    assert_non_null(strstr(why, "this one has several pieces"));
    pc_curve_release(two);
    pc_curve_release(c);
    pc_expr_pool_free(P);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_value_at),
        cmocka_unit_test(test_sample_at),
        cmocka_unit_test(test_curve_at),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
