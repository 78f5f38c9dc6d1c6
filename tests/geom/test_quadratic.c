/* Conics that know what they are (quadratic.h): arcs of rational quadratic Bezier curves with
 * any weights, five-point conics and coefficients, checked against the elements worked out by
 * hand for the engineering-discriminant arcs of Konopatsky's (2.97) on A(0,0), B(4,0), C(2,3)
 * (digest konopatsky_ch1_2.md §5.6 and §6: weights (k, 1 - k, k) on A, C, B), the 90-degree
 * circle of §5.8 and the textbook's ellipse x^2/9 + y^2/4 = 1. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "quadratic.h"
#include "status.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

/* homogeneous control points of the arc P0, P1, P2 with weights w */
static void rquad(const double p[6], const double w[3], double h[9]) {
    for (int i = 0; i < 3; i++) {
        h[3 * i] = w[i] * p[2 * i];
        h[3 * i + 1] = w[i] * p[2 * i + 1];
        h[3 * i + 2] = w[i];
    }
}

static const double ACB[6] = {0, 0, 2, 3, 4, 0};   /* A, C, B of §5.6's test vectors */

static void ed_info(double k, double scale, pc_conic_info *o) {
    double w[3] = {k * scale, (1 - k) * scale, k * scale}, h[9];
    rquad(ACB, w, h);
    assert_int_equal(pc_conic_info_rquad(h, o), PC_OK);
}

static void test_ed_ellipse(void **state) {
    (void)state;
    /* k = 0.7: by symmetry the centre is on x = 2; through A, K(2, 0.9) and tangent to CA at A
     * gives y0 = -0.675, the vertical semi-axis 0.9 - y0 = 1.575 and the horizontal one
     * 1.575/sqrt(0.50625) */
    pc_conic_info o;
    ed_info(0.7, 1, &o);
    assert_int_equal(o.kind, PC_CK_ELLIPSE);
    assert_false(o.circle);
    assert_true(o.disc < 0);
    NEAR(o.center[0], 2, 1e-12);
    NEAR(o.center[1], -0.675, 1e-12);
    double a = 1.575 / sqrt(0.50625), b = 1.575, c = sqrt(a * a - b * b);
    NEAR(o.semi[0], a, 1e-12);
    NEAR(o.semi[1], b, 1e-12);
    NEAR(fabs(o.axis[0][0]), 1, 1e-12);      /* the major axis is horizontal */
    NEAR(o.focus[0][1], -0.675, 1e-12);
    NEAR(fabs(o.focus[0][0] - 2), c, 1e-12);
    NEAR(o.focus[0][0] + o.focus[1][0], 4, 1e-12);
    NEAR(o.ecc, c / a, 1e-12);
    NEAR(o.param, b * b / a, 1e-12);
    NEAR(o.k_ed, 0.7, 1e-15);
    NEAR(o.mu, (0.3 / 0.7) * (0.3 / 0.7), 1e-15);
    assert_int_equal(o.nasym, 0);
    /* the equation holds on the arc (the old classifier missed it by 0.211) */
    for (int i = 0; i <= 8; i++) {
        double u = i / 8.0, s = 1 - u, W = 0.7 * s * s + 0.6 * u * s + 0.7 * u * u;
        double x = (0.6 * u * s * 2 + 0.7 * u * u * 4) / W, y = 0.6 * u * s * 3 / W;
        NEAR(pc_conic_eq(o.coef, x, y), 0, 1e-13);
    }
    NEAR(pc_conic_eq(o.coef, 0.727273, 0.613636), 0, 1e-6);   /* §5.6: u = 0.25 */
}

static void test_ed_parabola_hyperbola(void **state) {
    (void)state;
    pc_conic_info o;
    /* k = 0.5: y = 1.5 - (x - 2)^2 3/8, i.e. (x - 2)^2 = -(8/3)(y - 1.5): vertex K(2, 1.5),
     * focal length 2/3 downwards, semi-latus rectum 4/3 */
    ed_info(0.5, 1, &o);
    assert_int_equal(o.kind, PC_CK_PARABOLA);
    NEAR(o.vertex[0], 2, 1e-12);
    NEAR(o.vertex[1], 1.5, 1e-12);
    NEAR(o.axis[0][0], 0, 1e-12);
    NEAR(o.axis[0][1], -1, 1e-12);
    NEAR(o.focus[0][0], 2, 1e-12);
    NEAR(o.focus[0][1], 1.5 - 2.0 / 3, 1e-12);
    NEAR(o.param, 4.0 / 3, 1e-12);
    NEAR(o.ecc, 1, 0);
    assert_int_equal(o.nfoci, 1);
    assert_false(o.central);
    /* k = 0.3: the same conditions give the centre (2, 3.675) above C, the transverse axis
     * vertical with a = 1.575, b = 1.575/sqrt(2.75625) */
    ed_info(0.3, 1, &o);
    assert_int_equal(o.kind, PC_CK_HYPERBOLA);
    assert_true(o.disc > 0);
    NEAR(o.center[0], 2, 1e-12);
    NEAR(o.center[1], 3.675, 1e-12);
    double a = 1.575, b = 1.575 / sqrt(2.75625);
    NEAR(o.semi[0], a, 1e-12);
    NEAR(o.semi[1], b, 1e-12);
    NEAR(fabs(o.axis[0][1]), 1, 1e-12);
    NEAR(o.ecc, hypot(a, b) / a, 1e-12);
    assert_int_equal(o.nasym, 2);
    NEAR(fabs(o.asym[0][1] / o.asym[0][0]), a / b, 1e-12);   /* slopes +- a/b */
    NEAR(o.asym[0][1] / o.asym[0][0], -o.asym[1][1] / o.asym[1][0], 1e-12);
    NEAR(o.k_ed, 0.3, 1e-15);
}

static void test_weight_invariance(void **state) {
    (void)state;
    /* every weight scaled by 2, by -3, by 1e-4: the same conic, the same k */
    const double ks[3] = {0.3, 0.5, 0.7}, sc[3] = {2, -3, 1e-4};
    for (int i = 0; i < 3; i++) {
        pc_conic_info o, s;
        ed_info(ks[i], 1, &o);
        for (int j = 0; j < 3; j++) {
            ed_info(ks[i], sc[j], &s);
            assert_int_equal(s.kind, o.kind);
            NEAR(s.k_ed, ks[i], 1e-12);
            for (int m = 0; m < 6; m++) NEAR(fabs(s.coef[m]), fabs(o.coef[m]), 1e-12);
            NEAR(s.center[1], o.center[1], 1e-9);
        }
    }
    /* the quarter circle with every weight doubled: a circle centred at the origin */
    const double q[6] = {1, 0, 1, 1, 0, 1};
    const double w[3] = {2, 2 * sqrt(0.5), 2};
    double h[9];
    rquad(q, w, h);
    pc_conic_info o;
    assert_int_equal(pc_conic_info_rquad(h, &o), PC_OK);
    assert_int_equal(o.kind, PC_CK_ELLIPSE);
    assert_true(o.circle);
    NEAR(o.center[0], 0, 1e-12);
    NEAR(o.center[1], 0, 1e-12);
    NEAR(o.semi[0], 1, 1e-12);
    NEAR(o.semi[1], 1, 1e-12);
    NEAR(o.ecc, 0, 1e-12);
    NEAR(o.focus[0][0], 0, 1e-12);
}

static void test_signs_and_infinity(void **state) {
    (void)state;
    pc_conic_info o, n;
    /* a negative middle weight is the complementary arc of the same conic: same coefficients,
     * w -> -w, k = 1/(1 + w) outside [0, 1] */
    double w[3] = {1, 0.5, 1}, h[9];
    rquad(ACB, w, h);
    assert_int_equal(pc_conic_info_rquad(h, &o), PC_OK);
    w[1] = -0.5;
    rquad(ACB, w, h);
    assert_int_equal(pc_conic_info_rquad(h, &n), PC_OK);
    assert_int_equal(n.kind, PC_CK_ELLIPSE);
    for (int m = 0; m < 6; m++) NEAR(fabs(n.coef[m]), fabs(o.coef[m]), 1e-12);
    NEAR(n.w, -0.5, 1e-15);
    NEAR(n.k_ed, 2, 1e-15);
    /* end weights of opposite signs: mu < 0, a hyperbola through infinity inside the arc */
    const double w2[3] = {1, 0.5, -1};
    rquad(ACB, w2, h);
    assert_int_equal(pc_conic_info_rquad(h, &o), PC_OK);
    assert_int_equal(o.kind, PC_CK_HYPERBOLA);
    assert_true(o.mu < 0);
    assert_true(isnan(o.k_ed));
    assert_true(o.disc > 0);
    /* both ends at infinity: s^2 (1, 0, 0) + 2 s t (0, 0, w1) + t^2 (0, 1, 0) has
     * x y = 1/(4 w1^2), so w1 = 1/2 is the hyperbola x y = 1 with its vertex (1, 1) */
    const double hi[9] = {1, 0, 0, 0, 0, 0.5, 0, 1, 0};
    assert_int_equal(pc_conic_info_rquad(hi, &o), PC_OK);
    assert_int_equal(o.kind, PC_CK_HYPERBOLA);
    NEAR(o.center[0], 0, 1e-12);
    NEAR(o.center[1], 0, 1e-12);
    NEAR(o.coef[1], o.coef[1] > 0 ? 1 : -1, 1e-12);
    NEAR(o.coef[5], -o.coef[1], 1e-12);
    NEAR(o.semi[0], sqrt(2), 1e-12);
    /* the middle control point at infinity (parallel end tangents): the semi-ellipse
     * (x - 1)^2 + 4 y^2 = 1 from (0, 0) over (0, 1) at infinity to (2, 0), by the discriminant */
    const double semi[9] = {0, 0, 1, 0, 0.5, 0, 2, 0, 1};
    assert_int_equal(pc_conic_info_rquad(semi, &o), PC_OK);
    assert_int_equal(o.kind, PC_CK_ELLIPSE);
    NEAR(o.semi[0], 1, 1e-12);
    NEAR(o.semi[1], 0.5, 1e-12);
    NEAR(o.center[0], 1, 1e-12);
    assert_true(isnan(o.mu));
    /* a straight segment: w1 = 0, or collinear points */
    const double w3[3] = {1, 0, 1};
    rquad(ACB, w3, h);
    assert_int_equal(pc_conic_info_rquad(h, &o), PC_ECOLLINEAR);
    const double line[6] = {0, 0, 1, 1, 2, 2}, w4[3] = {1, 1, 1};
    rquad(line, w4, h);
    assert_int_equal(pc_conic_info_rquad(h, &o), PC_ECOLLINEAR);
    h[4] = NAN;
    assert_int_equal(pc_conic_info_rquad(h, &o), PC_ENONFINITE);
}

static void test_five_points(void **state) {
    (void)state;
    /* x^2/9 + y^2/4 = 1 rotated by 30 degrees and moved to (1, 2) */
    double pts[10], th = M_PI / 6;
    for (int i = 0; i < 5; i++) {
        double t = 0.4 + 1.1 * i, x = 3 * cos(t), y = 2 * sin(t);
        pts[2 * i] = 1 + x * cos(th) - y * sin(th);
        pts[2 * i + 1] = 2 + x * sin(th) + y * cos(th);
    }
    double q[6];
    assert_int_equal(pc_conic_coef_five(pts, q), PC_OK);
    pc_conic_info o;
    assert_int_equal(pc_conic_info_coef(q, &o), PC_OK);
    assert_int_equal(o.kind, PC_CK_ELLIPSE);
    NEAR(o.center[0], 1, 1e-12);
    NEAR(o.center[1], 2, 1e-12);
    NEAR(o.semi[0], 3, 1e-12);
    NEAR(o.semi[1], 2, 1e-12);
    NEAR(fabs(o.axis[0][0]), cos(th), 1e-12);
    NEAR(o.ecc, sqrt(5) / 3, 1e-12);
    NEAR(o.param, 4.0 / 3, 1e-12);
    assert_true(isnan(o.k_ed));
    /* |MF1| + |MF2| = 2a at another point of the ellipse */
    double x = 1 + 3 * cos(2.0) * cos(th) - 2 * sin(2.0) * sin(th);
    double y = 2 + 3 * cos(2.0) * sin(th) + 2 * sin(2.0) * cos(th);
    NEAR(hypot(x - o.focus[0][0], y - o.focus[0][1]) + hypot(x - o.focus[1][0], y - o.focus[1][1]),
         6, 1e-12);
    /* four collinear points fix no conic */
    const double bad[10] = {0, 0, 1, 1, 2, 2, 3, 3, 0, 5};
    assert_int_equal(pc_conic_coef_five(bad, q), PC_ECOLLINEAR);
    /* a line pair and an empty conic are degenerate */
    const double pair[6] = {1, 0, -1, 0, 0, 0}, none[6] = {1, 0, 1, 0, 0, 1};
    assert_int_equal(pc_conic_info_coef(pair, &o), PC_EDOMAIN);
    assert_int_equal(pc_conic_info_coef(none, &o), PC_EDOMAIN);
    const double lin[6] = {0, 0, 0, 1, 1, 0};
    assert_int_equal(pc_conic_info_coef(lin, &o), PC_EDOMAIN);
}

static void test_curve_conic(void **state) {
    (void)state;
    int st;
    /* the k = 0.7 arc as a curve; then a curve that is a conic but not stored as one (a cubic
     * Bezier that is the degree-raised parabola of k = 0.5); then a cubic that is none */
    double w[3] = {0.7, 0.3, 0.7}, h[9];
    rquad(ACB, w, h);
    pc_curve *c = pc_curve_bezier(2, 3, h, &st);
    pc_conic_info o;
    assert_int_equal(pc_curve_conic(c, &o), PC_OK);
    NEAR(o.center[1], -0.675, 1e-12);
    NEAR(o.k_ed, 0.7, 1e-15);
    pc_curve_release(c);
    const double raised[12] = {0, 0, 1, 4.0 / 3, 2, 1, 8.0 / 3, 2, 1, 4, 0, 1};
    c = pc_curve_bezier(2, 4, raised, &st);
    assert_int_equal(pc_curve_conic(c, &o), PC_OK);
    assert_int_equal(o.kind, PC_CK_PARABOLA);
    NEAR(o.vertex[1], 1.5, 1e-9);
    NEAR(o.focus[0][1], 1.5 - 2.0 / 3, 1e-9);
    pc_curve_release(c);
    const double cubic[12] = {0, 0, 1, 1, 3, 1, 2, -3, 1, 4, 0, 1};
    c = pc_curve_bezier(2, 4, cubic, &st);
    assert_int_equal(pc_curve_conic(c, &o), PC_ENOTCOLLINEAR);
    pc_curve_release(c);
    const double h3[12] = {0, 0, 0, 1, 1, 1, 1, 2, 0, 1, 1, 1};
    c = pc_curve_bezier(3, 3, h3, &st);
    assert_int_equal(pc_curve_conic(c, &o), PC_EDIM);
    pc_curve_release(c);
}

static void test_conditions(void **state) {
    (void)state;
    /* Korotky's C-1 hyperbola (digest korotky_curves_surfaces.md B.3): U = (0, 0), V = (2, 0),
     * tangents (1, sqrt 3) and (-1, sqrt 3), T = (1, 1.5): centre (1, 1.774519), semi-axes
     * 0.274519 (transverse, along y) and 0.156586 */
    double rows[30], q[6];
    const double r3 = sqrt(3);
    pc_conic_row_point(0, 0, rows);
    pc_conic_row_tangent(0, 0, 1, r3, rows + 6);
    pc_conic_row_point(2, 0, rows + 12);
    pc_conic_row_tangent(2, 0, -1, r3, rows + 18);
    pc_conic_row_point(1, 1.5, rows + 24);
    assert_int_equal(pc_conic_coef_conditions(rows, q), PC_OK);
    pc_conic_info o;
    assert_int_equal(pc_conic_info_coef(q, &o), PC_OK);
    assert_int_equal(o.kind, PC_CK_HYPERBOLA);
    NEAR(o.center[0], 1, 1e-12);
    NEAR(o.center[1], 1.774519, 1e-6);
    NEAR(o.semi[0], 0.274519, 1e-6);
    NEAR(o.semi[1], 0.156586, 1e-6);
    NEAR(fabs(o.axis[0][1]), 1, 1e-12);
    /* the same conic as the rational arc with w = 3 + 2 sqrt 3 on U, W = (1, sqrt 3), V */
    double w = 3 + 2 * r3, h[9] = {0, 0, 1, w, w * r3, w, 2, 0, 1}, qa[6];
    assert_int_equal(pc_conic_coef_rquad(h, qa), PC_OK);
    for (int i = 0; i < 6; i++) NEAR(qa[i], q[i], 1e-12);
    /* slopes: the tangent directions given, back */
    double sl;
    assert_int_equal(pc_conic_slope(q, 0, 0, &sl), PC_OK);
    NEAR(sl, r3, 1e-9);
    assert_int_equal(pc_conic_slope(q, 2, 0, &sl), PC_OK);
    NEAR(sl, -r3, 1e-9);
    /* the unit circle: slope -x/y, vertical at (1, 0) */
    const double circ[6] = {1, 0, 1, 0, 0, -1};
    assert_int_equal(pc_conic_slope(circ, 0.6, 0.8, &sl), PC_OK);
    NEAR(sl, -0.75, 1e-15);
    assert_int_equal(pc_conic_slope(circ, 1, 0, &sl), PC_EPOLE);
    const double pair[6] = {1, 0, -1, 0, 0, 0};
    assert_int_equal(pc_conic_slope(pair, 0, 0, &sl), PC_EZERO);
    /* dependent conditions: the same point twice */
    pc_conic_row_point(0, 0, rows + 24);
    memcpy(rows + 24, rows, sizeof(double) * 6);
    assert_int_equal(pc_conic_coef_conditions(rows, q), PC_ECOLLINEAR);
}

/* the kinds' names, in the order of pc_ckind */
static void test_kind_names(void **state) {
    (void)state;
    assert_string_equal(pc_ckind_names[PC_CK_ELLIPSE], "ellipse");
    assert_string_equal(pc_ckind_names[PC_CK_PARABOLA], "parabola");
    assert_string_equal(pc_ckind_names[PC_CK_HYPERBOLA], "hyperbola");
    assert_null(pc_ckind_names[3]);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ed_ellipse),   cmocka_unit_test(test_ed_parabola_hyperbola),
        cmocka_unit_test(test_weight_invariance), cmocka_unit_test(test_signs_and_infinity),
        cmocka_unit_test(test_five_points),  cmocka_unit_test(test_curve_conic),
        cmocka_unit_test(test_conditions),   cmocka_unit_test(test_kind_names),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
