/* The surface statuses explained (surface_why.c): each row answers the status its call
 * really returns, and concerns the argument or key the binding names. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>
#include "surface.h"

static const pc_why *row(const char *op, int st) {
    const pc_why *w = pc_why_find(pc_surface_why, op, st);
    assert_non_null(w);
    return w;
}

/* a zero axis: PC_EZERO from the constructor, explained at argument #3 (d) */
static void test_revolution_axis(void **state) {
    (void)state;
    double cp[8] = {1, 0, 0, 1, 2, 0, 1, 1}, a[3] = {0, 0, 0}, d[3] = {0, 0, 0};
    int st;
    pc_curve *prof = pc_curve_bezier(3, 2, cp, &st);
    assert_non_null(prof);
    assert_null(pc_surface_revolution(prof, a, d, 0, 1, &st));
    assert_int_equal(st, PC_EZERO);
    const pc_why *w = row("surface.revolution", st);
    assert_int_equal(w->arg, 3);
    assert_string_equal(w->text, "must be a nonzero vector (the axis)");
    pc_curve_release(prof);
}

/* four sides that do not meet: PC_EDOMAIN, the corners' condition */
static void test_coons_corners(void **state) {
    (void)state;
    double a[6] = {0, 0, 1, 1, 0, 1}, b[6] = {0, 5, 1, 1, 5, 1};
    int st;
    pc_curve *c0 = pc_curve_bezier(2, 2, a, &st), *c1 = pc_curve_bezier(2, 2, b, &st);
    assert_null(pc_surface_coons(c0, c1, c0, c1, &st));
    assert_int_equal(st, PC_EDOMAIN);
    const pc_why *w = row("surface.coons", st);
    assert_int_equal(w->arg, 0);
    assert_null(w->key);
    assert_non_null(strstr(w->text, "do not meet at the corners"));
    pc_curve_release(c0);
    pc_curve_release(c1);
}

/* s:shade's zero light concerns the key light; its singular projection none */
static void test_shade_rows(void **state) {
    (void)state;
    assert_string_equal(row("s:shade", PC_EZERO)->key, "light");
    assert_int_equal(row("s:shade", PC_ESINGULAR)->arg, 0);
    assert_non_null(strstr(row("s:shade", PC_ESINGULAR)->text, "flattens space onto a line"));
    assert_null(pc_why_find(pc_surface_why, "s:shade", PC_EDIM));   /* the binding words it */
    assert_null(pc_why_find(pc_surface_why, "surface.coons", PC_EZERO));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_revolution_axis),
        cmocka_unit_test(test_coons_corners),
        cmocka_unit_test(test_shade_rows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
