/* The tables of status explanations (why.h): a row is found by operation and status only. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>
#include "why.h"

static const pc_why table[] = {
    {"f", PC_EDOMAIN, 2, NULL, "must be positive"},
    {"f", PC_ECOLLINEAR, 0, NULL, "the points are collinear"},
    {"g", PC_EDOMAIN, 0, "range", "must be increasing"},
    {0}};

static void test_find(void **state) {
    (void)state;
    const pc_why *w = pc_why_find(table, "f", PC_EDOMAIN);
    assert_non_null(w);
    assert_int_equal(w->arg, 2);
    assert_string_equal(w->text, "must be positive");
    w = pc_why_find(table, "g", PC_EDOMAIN);
    assert_non_null(w);
    assert_string_equal(w->key, "range");
    assert_int_equal(w->arg, 0);
    assert_int_equal(pc_why_find(table, "f", PC_ECOLLINEAR) - table, 1);
}

static void test_not_found(void **state) {
    (void)state;
    assert_null(pc_why_find(table, "g", PC_ECOLLINEAR));   /* the status of another op */
    assert_null(pc_why_find(table, "h", PC_EDOMAIN));
    assert_null(pc_why_find(table, "f", PC_OK));
    assert_null(pc_why_find(NULL, "f", PC_EDOMAIN));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_find),
        cmocka_unit_test(test_not_found),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
