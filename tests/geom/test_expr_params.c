/* The parameters of a point equation (expr_params.c): the list in order, a name looked up,
 * the lists of names and values the messages show (and their truncation), and the weight
 * class of the book's equations: a quadratic Bezier (1.5) is a point, a difference a vector,
 * a sum of two points a weighted value. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>
#include "expr.h"

static pc_expr_pool *P;
static int st, t, s, u;

static int setup(void **state) {
    (void)state;
    P = pc_expr_pool_new();
    t = pc_expr_param(P, "t", &st);
    s = pc_expr_param(P, "s", &st);
    u = pc_expr_param(P, "u", &st);
    return P && t >= 0 && s >= 0 && u >= 0 ? 0 : -1;
}
static int teardown(void **state) { (void)state; pc_expr_pool_free(P); return 0; }

static int pt(double x, double y) { double h[3] = {x, y, 1}; return pc_expr_vconst(P, 2, h, &st); }

static void test_list_and_find(void **state) {
    (void)state;
    int e = pc_expr_add(P, pc_expr_mul(P, u, t, &st), s, &st), in[PC_EXPR_MAXPARAM];
    assert_int_equal(pc_expr_param_list(P, e, in), 3);
    assert_int_equal(in[0], 0);   /* t, s, u: in the order they were made */
    assert_int_equal(in[1], 1);
    assert_int_equal(in[2], 2);
    assert_int_equal(pc_expr_param_list(P, pc_expr_mul(P, u, u, &st), in), 1);
    assert_int_equal(in[0], 2);
    assert_int_equal(pc_expr_param_list(P, pt(1, 2), in), 0);
    assert_int_equal(pc_expr_find_param(P, "s"), 1);
    assert_int_equal(pc_expr_find_param(P, "v"), -1);
    assert_int_equal(pc_expr_find_param(P, NULL), -1);
}

static void test_names_and_values(void **state) {
    (void)state;
    int in[3] = {0, 1, 2};
    char buf[64];
    assert_int_equal(pc_expr_param_names(P, 3, in, buf, sizeof buf), 10);
    assert_string_equal(buf, "t, s and u");
    pc_expr_param_names(P, 2, in, buf, sizeof buf);
    assert_string_equal(buf, "t and s");
    pc_expr_param_names(P, 1, in + 2, buf, sizeof buf);
    assert_string_equal(buf, "u");
    double x[3] = {0.5, -0.0, 1e20};
    assert_int_equal(pc_expr_param_values(P, 3, in, x, buf, sizeof buf), 25);
    assert_string_equal(buf, "t = 0.5, s = 0, u = 1e+20");
    char small[8];                     /* truncated, 0-terminated, the full length returned */
    assert_int_equal(pc_expr_param_names(P, 3, in, small, sizeof small), 10);
    assert_string_equal(small, "t, s an");
}

static void test_weight_class(void **state) {
    (void)state;
    /* A bar(t)^2 + 2 B t bar(t) + C t^2: the coefficients sum to 1 for every t (a point) */
    int bt = pc_expr_bar(P, t, &st), two = pc_expr_const(P, 2, &st);
    int a = pc_expr_mul(P, pt(0, 0), pc_expr_mul(P, bt, bt, &st), &st);
    int b = pc_expr_mul(P, pc_expr_mul(P, two, pt(1, 2), &st), pc_expr_mul(P, t, bt, &st), &st);
    int c = pc_expr_mul(P, pt(2, 0), pc_expr_mul(P, t, t, &st), &st);
    int bez = pc_expr_add(P, pc_expr_add(P, a, b, &st), c, &st);
    assert_true(bez >= 0);
    assert_int_equal(pc_expr_weight_class(P, bez), PC_KIND_POINT);
    assert_int_equal(pc_expr_weight_class(P, pc_expr_sub(P, bez, pt(1, 1), &st)), PC_KIND_VECTOR);
    assert_int_equal(pc_expr_weight_class(P, pc_expr_add(P, bez, pt(1, 1), &st)), PC_KIND_WEIGHTED);
    assert_int_equal(pc_expr_weight_class(P, pc_expr_mul(P, pt(1, 1), t, &st)), PC_KIND_WEIGHTED);
    assert_int_equal(pc_expr_weight_class(P, t), -1);   /* a scalar has no weight */
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_list_and_find, setup, teardown),
        cmocka_unit_test_setup_teardown(test_names_and_values, setup, teardown),
        cmocka_unit_test_setup_teardown(test_weight_class, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
