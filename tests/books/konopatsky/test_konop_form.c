/* The forms of the spec tables (konop_form.h): each check of an option with the row that
 * explains it, the values shown, and the curves the forms make (the ellipse of centre C(0, 0)
 * with semi-axes CA = 4, CB = 2 of §2.1.1). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "konop_form.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static const double C[2] = {0, 0}, A[2] = {4, 0}, B[2] = {0, 2}, K[2] = {-4, 0};

static void assert_row(const pc_why_call *w, int st, const char *key, const char *text) {
    assert_string_equal(w->row[0].op, "conic.ellipse");
    assert_int_equal(w->row[0].status, st);
    assert_string_equal(w->row[0].key, key);
    assert_string_equal(w->row[0].text, text);
    assert_null(w->row[1].op);
}

static void test_checks(void **state) {
    (void)state;
    int st;
    pc_why_call w;
    double lambda = 1.5, none = NAN, delta = 4, quadrant = 1;
    assert_null(pc_konop_form("conic.ellipse", PC_KF_DIAMETER, 2, NULL, A, B, NULL, &lambda, 1, NAN, NAN, &st, &w));
    assert_row(&w, PC_EARG, "K", "must be a point, got nil");
    assert_null(pc_konop_form("conic.ellipse", PC_KF_DIAMETER, 2, NULL, A, B, K, &lambda, 1, NAN, NAN, &st, &w));
    assert_row(&w, PC_EDOMAIN, "lambda", "must be a number in (0, 1), got 1.5");
    assert_null(pc_konop_form("conic.ellipse", PC_KF_DIAMETER, 2, NULL, A, B, K, &none, 1, NAN, NAN, &st, &w));
    assert_row(&w, PC_EDOMAIN, "lambda", "must be a number in (0, 1), got nil");
    assert_null(pc_konop_form("conic.ellipse", PC_KF_CONJUGATE, 2, NULL, A, B, NULL, &quadrant, 1, NAN, NAN, &st,
                              &w));
    assert_row(&w, PC_EARG, "C", "must be a point, got nil");
    assert_null(pc_konop_form("conic.ellipse", PC_KC_CIRCLE_ANGLE, 2, C, A, B, NULL, &delta, 1, NAN, NAN, &st, &w));
    assert_row(&w, PC_EDOMAIN, "delta", "must be an angle in (0, pi), got 4");
    /* (2.15): rho runs over [b, a] = [2, 4] */
    assert_null(pc_konop_form("conic.ellipse", PC_KC_ELLIPSE_RADIUS, 2, C, A, B, NULL, &quadrant, 1, 1, 3, &st, &w));
    assert_int_equal(st, PC_EDOMAIN3);
    assert_row(&w, PC_EDOMAIN3, "range", "must lie within the form's real range [2, 4]");
    /* other statuses: the row of pc_konop_why */
    assert_null(pc_konop_form("conic.ellipse", PC_KC_ELLIPSE_ANGLE, 2, C, A, B, NULL, &quadrant, 1, 2, 1, &st, &w));
    assert_int_equal(st, PC_EDOMAIN2);
    assert_row(&w, PC_EDOMAIN2, "range", "must be two finite numbers t0 < t1");
}

static void test_made(void **state) {
    (void)state;
    int st;
    pc_why_call w;
    double lambda = 0.5, quadrant = 1, p[2];
    pc_curve *c = pc_konop_form("conic.ellipse", PC_KC_ELLIPSE_ANGLE, 2, C, A, B, NULL, &quadrant, 1, NAN, NAN, &st,
                                &w);
    assert_non_null(c);
    assert_null(w.row[0].op);                           /* made: the empty table */
    assert_int_equal(pc_curve_eval(c, M_PI / 2, p), PC_OK);
    NEAR(p[0], 0, 1e-12);
    NEAR(p[1], 2, 1e-12);                               /* (2.11) phi = pi/2 at B */
    pc_curve_release(c);
    c = pc_konop_form("conic.ellipse", PC_KF_DIAMETER, 2, NULL, A, B, K, &lambda, 1, NAN, NAN, &st, &w);
    assert_non_null(c);
    assert_int_equal(pc_curve_eval(c, 0.5, p), PC_OK);   /* B at t = lambda */
    NEAR(p[0], 0, 1e-12);
    NEAR(p[1], 2, 1e-12);
    pc_curve_release(c);
    c = pc_konop_form("conic.circle", PC_KF_CIRCLE_ARC, 2, (double[]){2, 2}, (double[]){0, 2}, (double[]){2, 0}, NULL,
                      NULL, 0, NAN, NAN, &st, &w);
    assert_non_null(c);                                 /* a quarter of the circle of radius 2 about 0 */
    assert_int_equal(pc_curve_eval(c, 0.5 * (c->t0 + c->t1), p), PC_OK);
    NEAR(hypot(p[0], p[1]), 2, 1e-12);
    pc_curve_release(c);
}

/* the first form of each spec table, its 'by' choices the forms from it */
static void test_base(void **state) {
    (void)state;
    assert_int_equal(pc_konop_form_base("conic.hyperbola"), PC_KC_HYPERBOLA_ANGLE);
    assert_int_equal(pc_konop_form_base("conic.reparam") + 1, PC_KC_PARABOLA_SIGMA);
    assert_int_equal(pc_konop_form_base("conic.cycloid"), PC_KC_CYCLOID);
    assert_int_equal(pc_konop_form_base("conic.sinusoid"), PC_KC_SINUSOID);
    assert_int_equal(pc_konop_form_base("conic.ed"), -1);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_checks), cmocka_unit_test(test_made),
                                       cmocka_unit_test(test_base)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
