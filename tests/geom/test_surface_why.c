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

/* s(u, v) at a point at infinity and s:normal where it has none: a row for the call with the
 * parameters' values; a point that evaluates leaves the table empty */
static void test_eval_normal_checked(void **state) {
    (void)state;
    double cp[12] = {0, 0, 1, 1, 0, 0, 0, 1, 1, 1, 1, 1};   /* P(0, 0), V(1, 0); P(0, 1), P(1, 1) */
    double line[12] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0}, out[3], n[3];
    int st;
    pc_why_call w;
    pc_surface *s = pc_surface_bezier(2, 1, 1, cp, &st);
    pc_surface *flat = pc_surface_bilinear(3, line, line + 3, line + 6, line + 9, &st);   /* on the x axis */
    assert_non_null(s);
    assert_non_null(flat);
    assert_int_equal(pc_surface_eval_checked("s", s, 0, 1, out, &w), PC_IMPROPER);
    assert_string_equal(w.row[0].op, "s");
    assert_int_equal(w.row[0].arg, 0);
    assert_string_equal(w.row[0].text, "the point at (0, 1) is at infinity");
    assert_null(w.row[1].op);
    assert_int_equal(pc_surface_eval_checked("s", s, 0.5, 0, out, &w), PC_OK);
    assert_null(w.row[0].op);
    assert_int_equal(pc_surface_normal_checked("s:normal", s, 0.5, 0, n, &w), PC_EDIM);
    assert_string_equal(w.row[0].text, "a normal needs a 3-D surface, this one is 2-D");
    assert_int_equal(pc_surface_normal_checked("s:normal", flat, 0.25, 0.5, n, &w), PC_EZERO);
    assert_string_equal(w.row[0].op, "s:normal");
    assert_string_equal(w.row[0].text, "the surface is singular at (0.25, 0.5): its partial derivatives are parallel");
    pc_surface_release(s);
    pc_surface_release(flat);
}

/* s:partials at a point at infinity: the same row as s(u, v); elsewhere the point and the
 * partial derivatives, the table empty */
static void test_partials_checked(void **state) {
    (void)state;
    double cp[12] = {0, 0, 1, 1, 0, 0, 0, 1, 1, 1, 1, 1}, out[6], p[6];   /* as above */
    int st;
    pc_why_call w;
    pc_surface *s = pc_surface_bezier(2, 1, 1, cp, &st);
    assert_non_null(s);
    assert_int_equal(pc_surface_partials_checked("s:partials", s, 0, 1, out, &w), PC_IMPROPER);
    assert_string_equal(w.row[0].op, "s:partials");
    assert_string_equal(w.row[0].text, "the point at (0, 1) is at infinity");
    assert_null(w.row[1].op);
    assert_int_equal(pc_surface_partials_checked("s:partials", s, 0.5, 0, out, &w), PC_OK);
    assert_null(w.row[0].op);
    assert_int_equal(pc_surface_partials(s, 0.5, 0, p), PC_OK);   /* the plain call's values */
    assert_memory_equal(out, p, sizeof p);
    pc_surface_release(s);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_revolution_axis),
        cmocka_unit_test(test_coons_corners),
        cmocka_unit_test(test_shade_rows),
        cmocka_unit_test(test_eval_normal_checked),
        cmocka_unit_test(test_partials_checked),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
