/* The checked operations of point equations (expr_apply.c): lerp(A, B, t) of two points is the
 * book's (B - A) t + A and evaluates to it, meet gives K, lambda, mu, and each wrong operand
 * gets its message with the operand's place ("@k") for the caller's description. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>
#include "expr.h"

static pc_expr_pool *P;
static int st, t;
static char why[512];

static int setup(void **state) {
    (void)state;
    P = pc_expr_pool_new();
    t = pc_expr_param(P, "t", &st);
    return P && t >= 0 ? 0 : -1;
}
static int teardown(void **state) { (void)state; pc_expr_pool_free(P); return 0; }

static int val(double x, double y, double w) { double h[3] = {x, y, w}; return pc_expr_vconst(P, 2, h, &st); }

/* the value of a one-parameter equation e at t = x (dim 2) */
static void at(int e, double x, double *h) {
    int in[1] = {0};
    pc_expr_prog *p = pc_expr_compile(P, e, 1, in, &st);
    assert_non_null(p);
    assert_int_equal(pc_expr_eval(p, 1, &x, 0, h, NULL), PC_OK);
    pc_expr_prog_free(p);
}

static void test_lerp_and_pack(void **state) {
    (void)state;
    int ids[3] = {val(1, 2, 1), val(5, 10, 1), t}, r[3];
    assert_int_equal(pc_expr_apply(P, PC_EQV_LERP, 3, ids, NULL, r, why, sizeof why), 1);
    double h[3];
    at(r[0], 0.25, h);
    assert_float_equal(h[0], 2, 1e-12);   /* (B - A) t + A at t = 1/4 */
    assert_float_equal(h[1], 4, 1e-12);
    assert_float_equal(h[2], 1, 1e-12);
    int xy[2] = {t, pc_expr_const(P, 3, &st)};
    assert_int_equal(pc_expr_apply(P, PC_EQV_V, 2, xy, NULL, r, why, sizeof why), 1);
    at(r[0], 0.5, h);
    assert_float_equal(h[0], 0.5, 1e-12);
    assert_float_equal(h[1], 3, 1e-12);
    assert_float_equal(h[2], 0, 1e-12);
}

static void test_meet(void **state) {
    (void)state;
    /* the line through (0, 0) and (2, 2t) meets x = 1 at (1, t) with lambda 1/2 */
    int a2[2] = {pc_expr_const(P, 2, &st), pc_expr_mul(P, pc_expr_const(P, 2, &st), t, &st)}, r[3];
    int pa2[1];
    assert_int_equal(pc_expr_apply(P, PC_EQV_P, 2, a2, NULL, pa2, why, sizeof why), 1);
    int ids[4] = {val(0, 0, 1), pa2[0], val(1, -5, 1), val(1, 5, 1)};
    assert_int_equal(pc_expr_apply(P, PC_EQV_MEET, 4, ids, NULL, r, why, sizeof why), 3);
    double h[3];
    at(r[0], 0.75, h);
    assert_float_equal(h[0] / h[2], 1, 1e-12);
    assert_float_equal(h[1] / h[2], 0.75, 1e-12);
    at(r[1], 0.75, h);
    assert_float_equal(h[0], 0.5, 1e-12);
}

static void test_messages(void **state) {
    (void)state;
    int r[3], pt = val(1, 2, 1), vec = val(1, 0, 0);
    int bad[2] = {pt, -1};
    assert_int_equal(pc_expr_apply(P, PC_EQV_ADD, 2, bad, NULL, r, why, sizeof why), -1);
    assert_string_equal(why, "cannot add @1 and @2: equations combine with numbers, points, vectors and equations");
    int pp[2] = {pt, pt};
    assert_int_equal(pc_expr_apply(P, PC_EQV_MUL, 2, pp, NULL, r, why, sizeof why), -1);
    assert_string_equal(why, "cannot multiply @1 by @2: use dot(u, v) or cross(u, v) for products of vectors");
    int lt[3] = {pt, pt, pt};
    assert_int_equal(pc_expr_apply(P, PC_EQV_LERP, 3, lt, NULL, r, why, sizeof why), -1);
    assert_string_equal(why, "argument #3 (t) must be a number or a scalar equation, got @3");
    int dv[2] = {vec, pt};
    assert_int_equal(pc_expr_apply(P, PC_EQV_DOT, 2, dv, NULL, r, why, sizeof why), -1);
    assert_string_equal(why, "argument #2 (v) must be a vector (weight 0), got @2 whose weight is not 0; a difference "
                             "of points is a vector, e.g. B - A");
    int zero[1] = {val(0, 0, 0)};
    assert_int_equal(pc_expr_apply(P, PC_EQV_UNIT, 1, zero, NULL, r, why, sizeof why), -1);
    assert_string_equal(why, "the zero vector has no direction");
    pc_expr_how how = {.fn = PC_EX_LOG};
    int minus[1] = {pc_expr_const(P, -1, &st)};
    assert_int_equal(pc_expr_apply(P, PC_EQV_MATH, 1, minus, &how, r, why, sizeof why), -1);
    assert_string_equal(why, "argument #1 (x) is outside the function's domain");
    int ts[2] = {t, pt};
    assert_int_equal(pc_expr_apply(P, PC_EQV_POW, 2, ts, NULL, r, why, sizeof why), -1);
    assert_string_equal(why, "cannot raise @1 to @2: powers are of numbers and scalar equations");
}

/* A curve's program: A + (B - A) t is a point throughout; B - A a vector; 2 A t has weight 2t */
static void test_compile_point(void **state) {
    (void)state;
    int r[1], ids[3] = {val(1, 2, 1), val(5, 10, 1), t};
    assert_int_equal(pc_expr_apply(P, PC_EQV_LERP, 3, ids, NULL, r, why, sizeof why), 1);
    double lo = 0, hi = 1;
    pc_expr_prog *p = pc_expr_compile_point(P, r[0], 1, &lo, &hi, why, sizeof why);
    assert_non_null(p);
    assert_int_equal(pc_expr_prog_dim(p), 2);
    pc_expr_prog_free(p);
    assert_null(pc_expr_compile_point(P, r[0], 2, &lo, &hi, why, sizeof why));
    assert_string_equal(why, "argument #1 (equation) depends on t, but a surface has 2 parameters: fix the others "
                             "with M:with{name = value}");
    assert_null(pc_expr_compile_point(P, val(1, 2, 1), 1, &lo, &hi, why, sizeof why));
    assert_string_equal(why, "argument #1 (equation) has no parameter (it is the constant @1)");
    assert_null(pc_expr_compile_point(P, t, 1, &lo, &hi, why, sizeof why));
    assert_string_equal(why, "argument #1 (equation) must be a point equation, got a scalar equation");
    int twice = pc_expr_mul(P, pc_expr_mul(P, val(1, 2, 1), t, &st), pc_expr_const(P, 2, &st), &st);
    assert_null(pc_expr_compile_point(P, twice, 1, &lo, &hi, why, sizeof why));
    assert_non_null(strstr(why, "argument #1 (equation) has weight "));
    assert_non_null(strstr(why, "so it is neither a point (weight 1) nor a vector (weight 0)"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lerp_and_pack),
        cmocka_unit_test(test_meet),
        cmocka_unit_test(test_messages),
        cmocka_unit_test(test_compile_point),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
