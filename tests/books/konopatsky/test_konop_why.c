/* The explanations of the statuses of Konopatsky's constructions (konop_why.h): one row per
 * operation and status (a second would never be found), each with a text, and the argument
 * numbers those of the declarations. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>
#include <math.h>
#include "konop_why.h"

static void test_rows(void **state) {
    (void)state;
    int n = 0;
    for (const pc_why *w = pc_konop_why; w->op; w++, n++) {
        assert_non_null(w->text);
        assert_true(strlen(w->text) > 5);
        assert_true(w->status != PC_OK);
        assert_true(w->arg >= -7 && w->arg <= 7);
        assert_ptr_equal(pc_why_find(pc_konop_why, w->op, w->status), w);   /* the first: unique */
    }
    assert_true(n > 40);
}

static void test_lookups(void **state) {
    (void)state;
    const pc_why *w = pc_why_find(pc_konop_why, "conic.ed_k", PC_ENOTCOLLINEAR);
    assert_non_null(w);
    assert_int_equal(w->arg, 4);                      /* K */
    w = pc_why_find(pc_konop_why, "conic.ceva_scheme", PC_EPOLE);
    assert_int_equal(w->arg, -5);                     /* shows t */
    assert_non_null(strstr(w->text, "%s"));
    assert_null(pc_why_find(pc_konop_why, "conic.ed_k", PC_EDOMAIN));
    assert_null(pc_why_find(pc_konop_why, "conic.nothing", PC_EDOMAIN));
    /* causes the core tells apart by PC_EDOMAIN, PC_EDOMAIN2, PC_EDOMAIN3 */
    assert_int_equal(pc_why_find(pc_konop_why, "oneratio.double_contact", PC_EDOMAIN)->arg, 4);     /* kp = 0 */
    assert_int_equal(pc_why_find(pc_konop_why, "oneratio.double_contact", PC_EDOMAIN2)->arg, 5);    /* kq = 0 */
    w = pc_why_find(pc_konop_why, "oneratio.double_contact", PC_EDOMAIN3);
    assert_non_null(strstr(w->text, "different from kp"));
    assert_int_equal(pc_why_find(pc_konop_why, "conic.cones", PC_EDOMAIN3)->arg, 7);                /* n */
    assert_string_equal(pc_why_find(pc_konop_why, "conic.sinusoid", PC_EDOMAIN2)->key, "range");
    w = pc_why_find(pc_konop_why, "conic.focal_point", PC_EDOMAIN2);
    assert_non_null(strstr(w->text, "the major one"));
}

/* plane.conic_slope on the unit circle: -x/y, a vertical tangent, a point off it, the centre */
static void test_conic_slope(void **state) {
    (void)state;
    const double circle[6] = {1, 0, 1, 0, 0, -1}, X[2] = {0.6, 0.8}, E[2] = {1, 0}, F[2] = {2, 0}, O[2] = {0, 0};
    const double pair[6] = {1, 0, -1, 0, 0, 0};   /* x^2 - y^2 = 0: the origin is singular */
    double m;
    pc_why_call w;
    assert_int_equal(pc_conic_slope_checked(circle, X, &m, &w), PC_OK);
    assert_true(fabs(m + 0.75) < 1e-15);
    assert_int_equal(pc_conic_slope_checked(circle, E, &m, &w), PC_OK);
    assert_true(isinf(m) && m > 0);
    assert_int_equal(pc_conic_slope_checked(circle, F, &m, &w), PC_EDOMAIN);
    assert_string_equal(w.row[0].text, "the point X is not on the curve (the equation gives 3 there)");
    assert_int_equal(pc_conic_slope_checked(circle, O, &m, &w), PC_EDOMAIN);
    assert_int_equal(pc_conic_slope_checked(pair, O, &m, &w), PC_EZERO);
    assert_non_null(strstr(w.row[0].text, "singular point"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rows),
        cmocka_unit_test(test_lookups),
        cmocka_unit_test(test_conic_slope),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
