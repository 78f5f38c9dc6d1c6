/* A point equation's coordinates as the book prints them (konop_expanded.h): the line
 * A (1 - t) + B t of A = (1, 0), B = (3, 2) is x = 2t + 1, y = 2t; a scalar t^2 - 1 has no
 * "x = "; sin(t) is not rational, t s has two parameters. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>
#include "konop_expanded.h"

static void test_expanded(void **state) {
    (void)state;
    pc_expr_pool *p = pc_expr_pool_new();
    int st, t = pc_expr_param(p, "t", &st), s = pc_expr_param(p, "s", &st);
    double a[3] = {1, 0, 1}, b[3] = {3, 2, 1};
    int A = pc_expr_vconst(p, 2, a, &st), B = pc_expr_vconst(p, 2, b, &st);
    int line = pc_expr_lerp(p, A, B, t, &st);
    char texts[2 * 64], why[256];
    assert_int_equal(pc_k_expanded(p, line, texts, 64, why, sizeof why), 2);
    assert_string_equal(texts, "x = 2t + 1");
    assert_string_equal(texts + 64, "y = 2t");
    int sq = pc_expr_sub(p, pc_expr_mul(p, t, t, &st), pc_expr_const(p, 1, &st), &st);
    assert_int_equal(pc_k_expanded(p, sq, texts, 64, why, sizeof why), 1);
    assert_string_equal(texts, "t^2 - 1");
    assert_int_equal(pc_k_expanded(p, pc_expr_fn(p, PC_EX_SIN, t, &st), texts, 64, why, sizeof why), -1);
    assert_non_null(strstr(why, "only an equation rational in its parameter expands in its powers"));
    assert_int_equal(pc_k_expanded(p, pc_expr_mul(p, t, s, &st), texts, 64, why, sizeof why), -1);
    assert_string_equal(why, "the equation has the parameters t and s: fix all but one with M:with{...} first");
    assert_int_equal(pc_k_expanded(p, A, texts, 64, why, sizeof why), -1);
    assert_string_equal(why, "the equation has no parameter: it is a constant");
    pc_expr_pool_free(p);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_expanded)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
