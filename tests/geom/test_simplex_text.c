/* A simplex as text and the wording of one that cannot be built (simplex_text.c). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>
#include "simplex.h"

static void test_init_text(void **state) {
    (void)state;
    char msg[160];
    double flat[] = {0, 0, 1, 0, 2, 0}, same[] = {0, 0, 0, 0};
    double block[64];   /* more than pc_simplex_size(2, 2) */
    pc_simplex *s = (pc_simplex *)block;
    int st = pc_simplex_init(s, 2, 2, flat);
    assert_int_equal(st, PC_ECOLLINEAR);
    pc_simplex_init_text(st, 2, 2, flat, msg, sizeof msg);
    assert_string_equal(msg, "the 3 points are collinear: a flat (degenerate) triangle");
    st = pc_simplex_init(s, 2, 1, same);
    pc_simplex_init_text(st, 2, 1, same, msg, sizeof msg);
    assert_string_equal(msg, "argument #2 coincides with argument #1 (the initial point): a degenerate simplex");
    pc_simplex_init_text(PC_EDIM, 2, 3, NULL, msg, sizeof msg);
    assert_string_equal(msg, "4 points in 2-D are always dependent: a simplex has at most dimension + 1 = 3 vertices");
}

static void test_text(void **state) {
    (void)state;
    double v[] = {0, 0, 1, 0, 0, 1.5};
    double block[64];   /* more than pc_simplex_size(2, 2) */
    pc_simplex *s = (pc_simplex *)block;
    assert_int_equal(pc_simplex_init(s, 2, 2, v), PC_OK);
    char buf[64], small[10];
    assert_int_equal(pc_simplex_text(s, buf, sizeof buf), strlen("simplex(P(0, 0), P(1, 0), P(0, 1.5))"));
    assert_string_equal(buf, "simplex(P(0, 0), P(1, 0), P(0, 1.5))");
    assert_int_equal(pc_simplex_text(s, small, sizeof small), strlen(buf));   /* truncated, the length needed */
    assert_string_equal(small, "simplex(P");
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_init_text), cmocka_unit_test(test_text)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
