/* A why-table made for one call (why_call.h): its one row found as any table's, its text
 * formatted with the values, and an empty table for PC_OK or no operation. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include "why_call.h"

static void one_row(void **state) {
    (void)state;
    pc_why_call w;
    assert_int_equal(pc_why_call_set(&w, "buimov.spline", PC_EDOMAIN, 0, "lengths", "must hold %d lengths, got %d", 3, 2),
                     PC_EDOMAIN);
    const pc_why *r = pc_why_find(w.row, "buimov.spline", PC_EDOMAIN);
    assert_ptr_equal(r, &w.row[0]);
    assert_string_equal(r->text, "must hold 3 lengths, got 2");
    assert_string_equal(r->key, "lengths");
    assert_int_equal(r->arg, 0);
    assert_null(pc_why_find(w.row, "buimov.spline", PC_EDIM));
    assert_null(pc_why_find(w.row, "plane.points", PC_EDOMAIN));
    pc_why_call_set(&w, "korotky.elastic", PC_EDIM, 3, NULL, "must be an integer 3 to %d, got %d", 5, 9);
    assert_int_equal(pc_why_find(w.row, "korotky.elastic", PC_EDIM)->arg, 3);
}

static void empty_tables(void **state) {
    (void)state;
    pc_why_call w;
    assert_int_equal(pc_why_call_set(&w, "buimov.spline", PC_OK, 0, NULL, ""), PC_OK);
    assert_null(pc_why_find(w.row, "buimov.spline", PC_OK));
    assert_int_equal(pc_why_call_set(&w, NULL, PC_ESINGULAR, 0, NULL, ""), PC_ESINGULAR);
    assert_null(pc_why_find(w.row, "buimov.spline", PC_ESINGULAR));
}

/* a fixed table's row as the one row of a call's table */
static void row_of_table(void **state) {
    (void)state;
    static const pc_why table[] = {{"korotky.dome_tri", PC_EDOMAIN, 4, NULL, "must stand above, got %s"},
                                   {"korotky.dome_tri", PC_ECOLLINEAR, 0, NULL, "flat"}, {NULL, 0, 0, NULL, NULL}};
    pc_why_call w;
    assert_int_equal(pc_why_call_row(&w, table, "korotky.dome_tri", PC_EDOMAIN), PC_EDOMAIN);
    assert_string_equal(w.row[0].text, "must stand above, got %s");
    assert_int_equal(w.row[0].arg, 4);
    assert_null(w.row[1].op);
    assert_int_equal(pc_why_call_row(&w, table, "korotky.dome_tri", PC_EDIM), PC_EDIM);
    assert_null(w.row[0].op);
    assert_int_equal(pc_why_call_row(&w, table, "korotky.dome_tri", PC_OK), PC_OK);
    assert_null(w.row[0].op);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(one_row), cmocka_unit_test(empty_tables),
                                       cmocka_unit_test(row_of_table)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
