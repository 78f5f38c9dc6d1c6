/* The parts of Korotky's constructions the bindings use (korotky_parts.h): the spline of a
 * list of points, the ridge shell of fixed guides, the line pair of a degenerate section and
 * the meaning of the failure statuses. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "korotky_parts.h"
#include "conic_surface.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_poly_spline_points(void **state) {
    (void)state;
    /* y = x^2 sampled at 0, 1, 2 with clamped slopes 0 and 4: the spline is the parabola */
    const double p[6] = {0, 0, 1, 1, 2, 4};
    double coef[8], xy[2];
    int bad = -1, st;
    pc_curve *c = pc_poly_spline_points(3, p, PC_END_CLAMPED, 0, 4, coef, &bad, &st);
    assert_non_null(c);
    assert_int_equal(st, PC_OK);
    NEAR(coef[0], 0, 1e-14); NEAR(coef[1], 0, 1e-14); NEAR(coef[2], 1, 1e-14); NEAR(coef[3], 0, 1e-14);
    assert_int_equal(pc_curve_eval(c, 1.5, xy), PC_OK);
    NEAR(xy[0], 1.5, 1e-14); NEAR(xy[1], 2.25, 1e-14);
    pc_curve_release(c);
    const double back[6] = {0, 0, 1, 1, 1, 4};   /* x does not increase at the third point */
    assert_null(pc_poly_spline_points(3, back, PC_END_NATURAL, 0, 0, coef, &bad, &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_int_equal(bad, 2);
}

/* korotky.poly_spline, korotky.ferguson_lambda and korotky.elastic with their conditions
 * explained: the clamped ends' slopes, the count of the ratios lambda, a failure at a knot */
static void test_checked(void **state) {
    (void)state;
    const double p[6] = {0, 0, 1, 1, 2, 4}, back[6] = {0, 0, 1, 1, 1, 4}, tA[2] = {1, 0}, tE[2] = {1, 4};
    const double lam[2] = {1, 1};
    double coef[8], E;
    int st;
    pc_why_call w;
    assert_null(pc_poly_spline_checked(3, p, PC_END_CLAMPED, 0, 0, 0, coef, &st, &w));
    assert_string_equal(w.row[0].text, "clamped ends need the end slopes s0 and s1 (numbers)");
    assert_null(w.row[0].key);
    pc_curve *c = pc_poly_spline_checked(3, p, PC_END_CLAMPED, 1, 0, 4, coef, &st, &w);
    assert_non_null(c);
    assert_null(w.row[0].op);
    NEAR(coef[2], 1, 1e-14);
    pc_curve_release(c);
    assert_null(pc_poly_spline_checked(3, back, PC_END_NATURAL, 0, 0, 0, coef, &st, &w));
    assert_int_equal(w.row[0].arg, 1);
    assert_string_equal(w.row[0].text, "[3] must lie right of the point before (x must increase)");
    assert_null(pc_ferguson_lambda_checked(3, p, tA, tE, 1, 1, -1, NULL, &st, &w));
    assert_string_equal(w.row[0].key, "lambda");
    assert_string_equal(w.row[0].text, "must be a list of 1 numbers, got nil");
    assert_null(pc_ferguson_lambda_checked(3, p, tA, tE, 1, 1, 2, lam, &st, &w));
    assert_string_equal(w.row[0].text, "must hold 1 numbers, got 2");
    c = pc_ferguson_lambda_checked(3, p, tA, tE, 1, 1, 1, lam, &st, &w);
    assert_non_null(c);
    assert_null(w.row[0].op);
    pc_curve_release(c);
    c = pc_ferguson_lambda_checked(2, p, tA, tE, 1, 1, 2, lam, &st, &w);   /* two points: lambda unused */
    assert_non_null(c);
    pc_curve_release(c);
    const double T[6] = {1, 0, 1, 1, 1, 0}, mags[4] = {1, 1, 1, 1}, Z[6] = {1, 0, 0, 0, 1, 0};
    assert_null(pc_ferguson_checked(3, p, T, 2, mags, &st, &w));
    assert_int_equal(w.row[0].arg, 3);
    assert_string_equal(w.row[0].text, "must hold 4 numbers, got 2");
    c = pc_ferguson_checked(3, p, T, 4, mags, &st, &w);
    assert_non_null(c);
    assert_null(w.row[0].op);
    pc_curve_release(c);
    assert_null(pc_ferguson_checked(3, p, Z, 4, mags, &st, &w));   /* a zero tangent */
    assert_non_null(strstr(w.row[0].text, "argument #2 (tangents) ("));
    assert_int_equal(w.row[0].arg, 0);
    c = pc_elastic_checked(3, p, 0, NULL, 0, &E, &st, &w);
    assert_non_null(c);
    assert_null(w.row[0].op);
    pc_curve_release(c);
    assert_null(pc_elastic_checked(3, p, 0, NULL, 1, &E, &st, &w));   /* shorter than the polyline */
    assert_int_equal(st, PC_EDOMAIN);
    assert_non_null(strstr(w.row[0].text, "is not longer than the polyline"));
}

static pc_curve *segment(double x0, double y0, double z0, double x1, double y1, double z1) {
    double cp[8] = {x0, y0, z0, 1, x1, y1, z1, 1};
    int st;
    return pc_curve_bezier(3, 2, cp, &st);
}

static void test_ridge_shell_of(void **state) {
    (void)state;
    /* the quarter ellipse from U = (x, -2, 0) to R = (x, 0, 1.5), then the straight segment
     * down to V = (x, 2, 0), as test_korotky_shells.c, with P, H, Q fixed directions */
    const double c = sqrt(.5);
    pc_pencil_point g[8] = {{segment(0, -2, 0, 4, -2, 0), {0}}, {segment(0, 0, 1.5, 4, 0, 1.5), {0}},
                            {segment(0, 2, 0, 4, 2, 0), {0}},
                            {segment(0, -2 * c, 1.5 * c, 4, -2 * c, 1.5 * c), {0}},
                            {segment(0, 1, .75, 4, 1, .75), {0}}, {NULL, {0, 0, 1, 0}}, {NULL, {0, 1, 0, 0}},
                            {NULL, {0, 0, 1, 0}}};
    int st;
    pc_surface *s = pc_surface_ridge_shell_of(g, NULL, &st);
    assert_non_null(s);
    for (int j = 0; j <= 8; j++) {
        double S[3];
        assert_int_equal(pc_surface_eval(s, .5, j / 8.0, S), PC_OK);
        NEAR(S[0], 2, 1e-12);
        NEAR(S[1] * S[1] / 4 + S[2] * S[2] / 2.25, 1, 1e-12);
    }
    pc_surface_release(s);
    pc_why_call w;   /* korotky.ridge_shell's, its failure explained */
    s = pc_sweep_checked(1, g, &st, &w);
    assert_non_null(s);
    assert_null(w.row[0].op);
    pc_surface_release(s);
    pc_curve_release(g[3].c);
    g[3].c = segment(0, 5, 5, 4, 5, 5);   /* T1 off the profile's tangent lines */
    assert_null(pc_sweep_checked(1, g, &st, &w));
    assert_string_equal(w.row[0].op, "korotky.ridge_shell");
    assert_non_null(strstr(w.row[0].text, "no conic arc of the profile at u = 0 ("));
    for (int i = 0; i < 5; i++) pc_curve_release(g[i].c);
}

static void test_line_pair(void **state) {
    (void)state;
    /* U = (0, 0), its midpoint with W, W = (1, 1) twice, then towards V = (2, 0); weights 2 */
    const double pair[15] = {0, 0, 2, 1, 1, 2, 2, 2, 2, 3, 1, 2, 4, 0, 2};
    double w[2];
    assert_int_equal(pc_conic_line_pair(pair, w), 1);
    NEAR(w[0], 1, 0); NEAR(w[1], 1, 0);
    const double bent[15] = {0, 0, 1, 1, 0, 1, 1, 1, 1, 1.5, .5, 1, 2, 0, 1};
    assert_int_equal(pc_conic_line_pair(bent, w), 0);
}

static void test_why(void **state) {
    (void)state;
    assert_string_equal(pc_ferguson_why(PC_ENOCONVERGE), "Newton's method does not converge");
    assert_string_equal(pc_ferguson_why(PC_ECOINCIDENT), "the point repeats the one before");
    assert_string_equal(pc_ferguson_why(PC_EDIM), pc_strerror(PC_EDIM));
    assert_string_equal(pc_conic_arc_why(PC_ECOINCIDENT), "U and V coincide");
    assert_string_equal(pc_conic_arc_why(PC_ESKEW), "the tangents must lie in the plane of U, V and T");
    assert_string_equal(pc_conic_arc_why(PC_EDIM), "the points must be 2-D or more");
    assert_string_equal(pc_conic_revolve_why(PC_ECOLLINEAR), "the ridge point lies on the axis AB");
    assert_string_equal(pc_conic_revolve_why(PC_EZERO), "a tangent plane's normal is the zero vector");
    assert_non_null(strstr(pc_meet_planes4_why(PC_ESAME_LINE, 0), "more than one common point"));
    assert_non_null(strstr(pc_meet_planes4_why(PC_ESAME_LINE, 1), "a plane of one pencil"));
    assert_non_null(strstr(pc_meet_planes4_why(PC_ESKEW, 1), "span only a line"));
    assert_string_equal(pc_meet_planes4_why(PC_ENONFINITE, 0), pc_strerror(PC_ENONFINITE));
    assert_string_equal(pc_poly_spline_ends[PC_END_NATURAL], "natural");
    assert_string_equal(pc_poly_spline_ends[PC_END_CLAMPED], "clamped");
    assert_null(pc_poly_spline_ends[2]);
    assert_string_equal(pc_ferguson_roots[1], "max");   /* root_max */
    assert_null(pc_ferguson_roots[2]);
}

/* the conic of an arc of korotky.conic_arc: (x - 1)^2 + 4 y^2 = 1 (test_korotky_shells.lua's
 * ellipse); with T = W the line pair U W V, its lines meeting at W */
static void test_conic_info_arc(void **state) {
    (void)state;
    const double U[2] = {0, 0}, tU[2] = {0, 1}, V[2] = {2, 0}, tV[2] = {0, 1}, T[2] = {1, .5};
    double w, W[2];
    int st;
    pc_curve *c = pc_conic_arc(2, U, tU, V, tV, T, &w, &st);
    assert_non_null(c);
    pc_conic_info o;
    assert_int_equal(pc_conic_info_arc(c, &o, W), PC_OK);
    assert_true(pc_conic_arc_shaped(c));
    assert_int_equal(o.kind, PC_CK_ELLIPSE);
    NEAR(o.center[0], 1, 1e-12); NEAR(o.center[1], 0, 1e-12);
    NEAR(o.semi[0], 1, 1e-12); NEAR(o.semi[1], .5, 1e-12);
    pc_curve_release(c);
    const double sU[2] = {1, 1}, sV[2] = {1, -1}, Wp[2] = {1, 1};
    c = pc_conic_arc(2, U, sU, V, sV, Wp, &w, &st);
    assert_non_null(c);
    assert_int_equal(pc_conic_info_arc(c, &o, W), PC_ESAME_LINE);
    assert_true(pc_conic_arc_shaped(c));   /* two quadratic pieces, 5 control points */
    NEAR(W[0], 1, 1e-12); NEAR(W[1], 1, 1e-12);
    pc_why_call why;   /* korotky.conic_elements words it with W as Lua shows numbers */
    assert_int_equal(pc_conic_elements_checked(c, NULL, &o, &why), PC_ESAME_LINE);
    assert_non_null(strstr(why.row[0].text, "its lines meet at W = P(1.0, 1.0)"));
    assert_null(why.row[1].op);
    pc_curve_release(c);
    const double zero[6] = {0, 0, 0, 1, 2, 3}, bad[6] = {1, 0, NAN, 0, 0, -1};
    const double circle[6] = {1, 0, 1, 0, 0, -1.5};
    assert_int_equal(pc_conic_elements_checked(NULL, zero, &o, &why), PC_EDOMAIN);
    assert_string_equal(why.row[0].text, "a degenerate conic (a line pair, or no real points)");
    assert_int_equal(pc_conic_elements_checked(NULL, bad, &o, &why), PC_ENONFINITE);
    assert_int_equal(why.row[0].arg, 1);
    assert_int_equal(pc_conic_elements_checked(NULL, circle, &o, &why), PC_OK);
    assert_true(o.circle);
    assert_null(why.row[0].op);
    const double cub[12] = {0, 0, 1, 1, 2, 1, 2, 1, 1, 3, 0, 1};   /* a cubic: no conic arc */
    c = pc_curve_bezier(2, 4, cub, &st);
    assert_non_null(c);
    assert_int_equal(pc_conic_info_arc(c, &o, W), PC_EDIM);
    assert_false(pc_conic_arc_shaped(c));
    assert_int_equal(pc_why_find(pc_korotky_why, "korotky.conic_elements", PC_EDIM)->arg, 1);
    pc_curve_release(c);
    assert_non_null(strstr(pc_why_find(pc_korotky_why, "korotky.dome_tri", PC_ECOLLINEAR)->text, "flat"));
}

/* system (22) with the end tangents as directions scaled to the moduli: two points are one
 * Hermite segment with the end derivatives w_A t_A / |t_A| and w_E t_E / |t_E| */
static void test_ferguson_lambda_curve(void **state) {
    (void)state;
    const double p[4] = {0, 0, 1, 0}, tA[2] = {2, 0}, tE[2] = {0, 3};
    int bad = -1, st;
    pc_curve *c = pc_ferguson_lambda_curve(2, p, tA, tE, 1, 2, NULL, &bad, &st);
    assert_non_null(c);
    double d[4];
    assert_int_equal(pc_curve_derivs(c, c->t0, 1, d), PC_OK);
    NEAR(d[0], 0, 1e-15); NEAR(d[1], 0, 1e-15); NEAR(d[2], 1, 1e-14); NEAR(d[3], 0, 1e-14);
    assert_int_equal(pc_curve_derivs(c, c->t1, 1, d), PC_OK);
    NEAR(d[0], 1, 1e-15); NEAR(d[1], 0, 1e-15); NEAR(d[2], 0, 1e-14); NEAR(d[3], 2, 1e-14);
    pc_curve_release(c);
    const double zero[2] = {0, 0}, q[6] = {0, 0, 1, 1, 2, 0}, lam[1] = {-1};
    assert_null(pc_ferguson_lambda_curve(2, p, zero, tE, 1, 1, NULL, &bad, &st));
    assert_int_equal(st, PC_EZERO);
    assert_null(pc_ferguson_lambda_curve(3, q, tA, tE, 1, 1, lam, &bad, &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_int_equal(bad, 1);
}

/* the elastic reference's failures and the graphical slope's conditions, with their values */
static void test_explained(void **state) {
    (void)state;
    pc_why_call w;
    assert_int_equal(pc_elastic_explain(PC_EDOMAIN, 3, 0, 1.5, &w), PC_EDOMAIN);
    assert_string_equal(w.row[0].text, "length 1.5 is not longer than the polyline through the points");
    pc_elastic_explain(PC_EDIM, 2, 1, 3, &w);
    assert_non_null(strstr(w.row[0].text, "a length needs a free node"));
    pc_elastic_explain(PC_EDIM, 9, 4, 0, &w);
    assert_string_equal(w.row[0].text, "9 points with 4 pieces per span are too many unknowns; use fewer pieces");
    pc_elastic_explain(PC_ENOMEM, 9, 4, 0, &w);
    assert_null(pc_why_find(w.row, "korotky.elastic", PC_ENOMEM));
    /* y = x^2 sampled: the slope 2x at x = 1.5 from the parabola through the window */
    const double xy[10] = {0, 0, 1, 1, 2, 4, 3, 9, 4, 16};
    double m;
    assert_int_equal(pc_graphical_slope_checked(5, xy, 1.5, 5, &m, &w), PC_OK);
    NEAR(m, 3, 1e-12);
    assert_int_equal(pc_graphical_slope_checked(5, xy, 1.5, 7, &m, &w), PC_EDIM);
    assert_int_equal(w.row[0].arg, 3);
    assert_string_equal(w.row[0].text, "must be an integer 3 to 5, got 7");
    assert_int_equal(pc_graphical_slope_checked(5, xy, 9, 5, &m, &w), PC_EDOMAIN);
    assert_int_equal(w.row[0].arg, 2);
    assert_string_equal(w.row[0].text, "must lie within the samples [0, 4], got 9");
    const double back[6] = {0, 0, 2, 1, 1, 2};
    assert_int_equal(pc_graphical_slope_checked(3, back, 1, 3, &m, &w), PC_EDOMAIN);
    assert_int_equal(w.row[0].arg, 1);
    assert_non_null(strstr(w.row[0].text, "[3] must lie right of the sample before"));
}

/* the splines' failures at a knot, as each construction words them */
static void test_ferguson_explain(void **state) {
    (void)state;
    pc_why_call w;
    assert_int_equal(pc_ferguson_explain("korotky.poly_spline", PC_EDOMAIN, 2, &w), PC_EDOMAIN);
    assert_int_equal(w.row[0].arg, 1);
    assert_string_equal(w.row[0].text, "[3] must lie right of the point before (x must increase)");
    pc_ferguson_explain("korotky.ferguson_lambda", PC_EZERO, -1, &w);
    assert_int_equal(w.row[0].arg, 0);
    assert_string_equal(w.row[0].text, "the end tangents must not be zero vectors");
    pc_ferguson_explain("korotky.ferguson_lambda", PC_EDOMAIN, 1, &w);
    assert_string_equal(w.row[0].key, "lambda");
    assert_string_equal(w.row[0].text, "[1] (at knot #2) must be positive");
    pc_ferguson_explain("korotky.ferguson_tangents", PC_EDOMAIN, 3, &w);
    assert_string_equal(w.row[0].op, "korotky.ferguson_tangents");
    assert_string_equal(w.row[0].text, "no positive derivative moduli at knot #4");
    pc_ferguson_explain("korotky.ferguson_substitution", PC_ENOCONVERGE, 0, &w);
    assert_string_equal(w.row[0].text, "Newton's method does not converge at knot #1");
    assert_int_equal(pc_ferguson_explain("korotky.ferguson_tangents", PC_ESINGULAR, -1, &w), PC_ESINGULAR);
    assert_null(pc_why_find(w.row, "korotky.ferguson_tangents", PC_ESINGULAR));
}

/* the deviation of two curves: two parallel segments 1 apart; mixed dimensions explained */
static void test_hausdorff_checked(void **state) {
    (void)state;
    const double a[6] = {0, 0, 1, 4, 0, 1}, b[6] = {0, 1, 1, 4, 1, 1}, c[8] = {0, 0, 0, 1, 4, 0, 0, 1};
    int st;
    pc_curve *A = pc_curve_bezier(2, 2, a, &st), *B = pc_curve_bezier(2, 2, b, &st), *C = pc_curve_bezier(3, 2, c, &st);
    double d = 0;
    pc_why_call w;
    assert_int_equal(pc_curve_hausdorff_checked(A, B, 16, &d, &w), PC_OK);
    NEAR(d, 1, 1e-9);
    assert_int_equal(pc_curve_hausdorff_checked(A, C, 16, &d, &w), PC_EDIM);
    assert_string_equal(w.row[0].op, "korotky.deviation");
    assert_string_equal(w.row[0].text,
                        "argument #2 (reference) is 3-D, but argument #1 (model) is 2-D (mixed dimensions)");
    pc_curve_release(A);
    pc_curve_release(B);
    pc_curve_release(C);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_poly_spline_points), cmocka_unit_test(test_ridge_shell_of),
        cmocka_unit_test(test_line_pair), cmocka_unit_test(test_why),
        cmocka_unit_test(test_conic_info_arc), cmocka_unit_test(test_ferguson_lambda_curve),
        cmocka_unit_test(test_explained), cmocka_unit_test(test_ferguson_explain),
        cmocka_unit_test(test_hausdorff_checked), cmocka_unit_test(test_checked),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
