/* Curves of one ratio, Konopatsky's chapter 3 (oneratio.h): the test vectors of the digest
 * konopatsky_ch3_5.md §1 and §6 with A(0,0,0), B(4,0,0), C(1,3,0), D(4,3,2), t = 0.3; the
 * schemes against the closed forms; end tangents, end curvature, the printed closed forms of
 * Fig. 3.6. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "oneratio.h"
#include "conic.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static const double A[3] = {0, 0, 0}, B[3] = {4, 0, 0}, C[3] = {1, 3, 0}, D[3] = {4, 3, 2};

static void near3(pc_curve *c, double t, double x, double y, double z, double tol) {
    double m[3];
    assert_int_equal(pc_curve_eval(c, t, m), PC_OK);
    NEAR(m[0], x, tol);
    NEAR(m[1], y, tol);
    NEAR(m[2], z, tol);
}

/* d^order M/dt^order at t into out (3) */
static void deriv(pc_curve *c, double t, int order, double *out) {
    double d[9];
    assert_int_equal(pc_curve_derivs(c, t, order, d), PC_OK);
    for (int k = 0; k < 3; k++) out[k] = d[3 * order + k];
}

/* |u x v| / (|u||v|): zero for parallel vectors */
static double sin_between(const double *u, const double *v) {
    double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
    return sqrt(x * x + y * y + z * z) / (sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) *
                                          sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
}

static void test_simplex_tetra(void **state) {
    (void)state;
    int st;
    pc_curve *c = pc_oneratio_simplex(3, A, B, C, &st);
    near3(c, 0.3, 1.41, 0.63, 0, 1e-12);
    for (double t = 0; t <= 1; t += 0.1) {     /* the scheme N = A t' + C t, M = N t' + B t */
        double m[3], N[3];
        for (int k = 0; k < 3; k++) N[k] = A[k] * (1 - t) + C[k] * t;
        pc_curve_eval(c, t, m);
        for (int k = 0; k < 3; k++) NEAR(m[k], N[k] * (1 - t) + B[k] * t, 1e-12);
    }
    double d[3], bc[3] = {B[0] - C[0], B[1] - C[1], 0}, ac[3] = {C[0] - A[0], C[1] - A[1], 0};
    deriv(c, 1, 1, d);                          /* BC tangent at B: M'(1) = B - C */
    for (int k = 0; k < 3; k++) NEAR(d[k], bc[k], 1e-12);
    deriv(c, 0, 1, d);                          /* AC not tangent at A */
    assert_true(sin_between(d, ac) > 0.1);
    NEAR(d[0], B[0] + C[0] - 2 * A[0], 1e-12);
    pc_curve_release(c);

    c = pc_oneratio_tetra(3, A, B, C, D, &st);
    near3(c, 0.3, 1.41, 1.26, 0.42, 1e-12);
    near3(c, 0.5, 9.0 / 4, 6.0 / 4, 2.0 / 4, 1e-12);   /* the centroid */
    pc_curve_release(c);
}

static void test_smooth(void **state) {
    (void)state;
    int st;
    static const double tv[5][2] = {{0.78, 1.26}, {0.6683544304, 1.594936709},
                                    {0.6279310345, 1.716206897}, {0.6117362956, 1.764791113},
                                    {0.604988026, 1.785035922}};
    for (int n = 1; n <= 6; n++) {
        pc_curve *c = pc_oneratio_smooth(3, A, B, C, n, &st);
        assert_non_null(c);
        if (n <= 5) near3(c, 0.3, tv[n - 1][0], tv[n - 1][1], 0, 1e-9);
        /* the general law with D_n = sum t'^k t^(n-k) */
        double t = 0.37, tb = 1 - t, Dn = 0, m[3];
        for (int k = 0; k <= n; k++) Dn += pow(tb, k) * pow(t, n - k);
        pc_curve_eval(c, t, m);
        for (int k = 0; k < 3; k++)
            NEAR(m[k], (A[k] - C[k]) * pow(tb, n + 1) / Dn + (B[k] - C[k]) * pow(t, n + 1) / Dn + C[k], 1e-12);
        /* curvature at the ends: zero for n >= 2 ("points of straightening") */
        double k0, k1;
        assert_int_equal(pc_curve_curvature(c, 0, &k0), PC_OK);
        assert_int_equal(pc_curve_curvature(c, 1, &k1), PC_OK);
        if (n >= 2) {
            NEAR(k0, 0, 1e-9);
            NEAR(k1, 0, 1e-9);
        } else {
            assert_true(fabs(k0) > 0.01);
        }
        pc_curve_release(c);
    }
    /* M_2's scheme (Fig. 3.9): P2 = (A t'^2 + C t)/(1 - t't), Q1 = (B t^2 + C t')/(1 - t't), M on P2Q1 */
    pc_curve *c = pc_oneratio_smooth(3, A, B, C, 2, &st);
    double t = 0.4, tb = 0.6, d = 1 - tb * t, m[3];
    pc_curve_eval(c, t, m);
    for (int k = 0; k < 3; k++) {
        double p2 = (A[k] * tb * tb + C[k] * t) / d, q1 = (B[k] * t * t + C[k] * tb) / d;
        NEAR(m[k], p2 + t * (q1 - p2), 1e-12);
    }
    pc_curve_release(c);
    assert_null(pc_oneratio_smooth(3, A, B, C, 0, &st));
    assert_int_equal(st, PC_EDOMAIN);
}

static void test_desargues(void **state) {
    (void)state;
    int st;
    pc_curve *c = pc_oneratio_desargues(3, A, B, C, D, &st);
    near3(c, 0.3, 0.874137931, 0.9, 0.09310344828, 1e-9);
    near3(c, 0.5, 9.0 / 4, 6.0 / 4, 2.0 / 4, 1e-12);
    double d[3];
    deriv(c, 0, 1, d);
    for (int k = 0; k < 3; k++) NEAR(d[k], C[k] - A[k], 1e-12);
    deriv(c, 1, 1, d);
    for (int k = 0; k < 3; k++) NEAR(d[k], D[k] - B[k], 1e-12);
    deriv(c, 0, 2, d);
    for (int k = 0; k < 3; k++) NEAR(d[k], 2 * (B[k] - A[k]), 1e-12);
    deriv(c, 1, 2, d);
    for (int k = 0; k < 3; k++) NEAR(d[k], 2 * (C[k] - D[k]), 1e-12);
    /* the scheme: M = S t(2t - 1)/(2t^2 - 2t + 1) + N t'/(2t^2 - 2t + 1) */
    double t = 0.3, tb = 0.7, den = 2 * t * t - 2 * t + 1, m[3];
    pc_curve_eval(c, t, m);
    for (int k = 0; k < 3; k++) {
        double S = (C[k] * tb * tb - D[k] * t * t) / (1 - 2 * t);
        double N = A[k] * tb * tb + 2 * C[k] * tb * t + B[k] * t * t;
        NEAR(m[k], S * t * (2 * t - 1) / den + N * tb / den, 1e-12);
    }
    pc_curve_release(c);
}

static double f_sq(void *ud, double v) { (void)ud; return v * v; }
static double f_sqrt(void *ud, double v) { (void)ud; return sqrt(v); }

/* (3.4): the cubic Bezier A, C1, C2, B of the de Casteljau scheme */
static void test_bezier3(void **state) {
    (void)state;
    int st;
    pc_curve *c = pc_oneratio_bezier3(3, A, C, D, B, &st);
    assert_non_null(c);
    near3(c, 0, 0, 0, 0, 1e-14);
    near3(c, 1, 4, 0, 0, 1e-14);
    near3(c, 0.5, (A[0] + 3 * C[0] + 3 * D[0] + B[0]) / 8, (3 * C[1] + 3 * D[1]) / 8, 3 * D[2] / 8, 1e-14);
    pc_curve_release(c);
    assert_null(pc_oneratio_bezier3(0, A, C, D, B, &st));
    assert_int_equal(st, PC_EDIM);
}

/* a constant blend f = 1/4: M = P 3/4 + Q/4 of the arcs (2.97) kp, kq */
static void test_double_contact_const(void **state) {
    (void)state;
    int st;
    double a2[2] = {0, 0}, b2[2] = {10, 0}, c2[2] = {4, 6};
    pc_curve *c = pc_oneratio_double_contact_const(2, a2, b2, c2, 0.3, 0.7, 0.25, &st);
    pc_curve *p = pc_conic_ed(2, a2, b2, c2, 0.3, &st), *q = pc_conic_ed(2, a2, b2, c2, 0.7, &st);
    for (double v = 0.1; v < 1; v += 0.2) {
        double m[2], mp[2], mq[2];
        assert_int_equal(pc_curve_eval(c, v, m), PC_OK);
        pc_curve_eval(p, v, mp);
        pc_curve_eval(q, v, mq);
        for (int k = 0; k < 2; k++) NEAR(m[k], 0.75 * mp[k] + 0.25 * mq[k], 1e-12);
    }
    pc_curve_release(c);
    pc_curve_release(p);
    pc_curve_release(q);
    assert_null(pc_oneratio_double_contact_const(2, a2, b2, c2, 0.4, 0.4, 0.5, &st));
    assert_int_equal(st, PC_EDOMAIN3);
}

static void test_double_contact(void **state) {
    (void)state;
    int st;
    double a2[2] = {0, 0}, b2[2] = {10, 0}, c2[2] = {4, 6};
    pc_curve *c = pc_oneratio_double_contact(2, a2, b2, c2, 0.3, 0.7, f_sq, NULL, NULL, &st);
    for (double v = 0.1; v < 1; v += 0.2) {
        /* the printed closed form of Fig. 3.6a */
        double den = (0.8 * v * v - 0.8 * v - 0.3) * (0.8 * v * v - 0.8 * v + 0.7);
        double fa = (0.8 * pow(v, 6) - 2.4 * pow(v, 5) + 2.16 * pow(v, 4) - 0.08 * pow(v, 3)
                     - 0.93 * v * v + 0.66 * v - 0.21) / den;
        double fb = (0.8 * pow(v, 6) - 0.8 * pow(v, 5) - 0.24 * pow(v, 4) + 0.24 * pow(v, 3)
                     - 0.21 * v * v) / den;
        double m[2];
        pc_curve_eval(c, v, m);
        for (int k = 0; k < 2; k++)
            NEAR(m[k], (a2[k] - c2[k]) * fa + (b2[k] - c2[k]) * fb + c2[k], 1e-10);
    }
    /* end tangents along CA and CB (the core differences a FUNC curve) */
    double d[4];
    assert_int_equal(pc_curve_derivs(c, 0, 1, d), PC_OK);
    NEAR(d[2] * (c2[1] - a2[1]) - d[3] * (c2[0] - a2[0]), 0, 1e-5 * hypot(d[2], d[3]) * 8);
    assert_int_equal(pc_curve_derivs(c, 1, 1, d), PC_OK);
    NEAR(d[2] * (c2[1] - b2[1]) - d[3] * (c2[0] - b2[0]), 0, 1e-5 * hypot(d[2], d[3]) * 8);
    pc_curve_release(c);
    c = pc_oneratio_double_contact(2, a2, b2, c2, 0.3, 0.7, f_sqrt, NULL, NULL, &st);
    for (double v = 0.1; v < 1; v += 0.2) {      /* Fig. 3.6b */
        double s = sqrt(v), d1 = 0.8 * v * v - 0.8 * v - 0.3, d2 = 0.8 * v * v - 0.8 * v + 0.7;
        double fa = (-1 + s) * (0.3 * v * v - 0.6 * v + 0.3) / d1 + (0.7 * v * v - 1.4 * v + 0.7) * s / d2;
        double fb = 0.3 * (-1 + s) * v * v / d1 + 0.7 * pow(v, 2.5) / d2;
        double m[2];
        pc_curve_eval(c, v, m);
        for (int k = 0; k < 2; k++)
            NEAR(m[k], (a2[k] - c2[k]) * fa + (b2[k] - c2[k]) * fb + c2[k], 1e-10);
    }
    pc_curve_release(c);
    /* a negative k: the pole of P is a point at infinity of M */
    c = pc_oneratio_double_contact(2, a2, b2, c2, -0.5, 0.5, NULL, NULL, NULL, &st);
    double h[3], u = 0.5 * (1 - 1 / sqrt(2));
    pc_curve_eval_h(c, u, 0, h);
    NEAR(h[2], 0, 1e-14);
    pc_curve_release(c);
    assert_null(pc_oneratio_double_contact(2, a2, b2, c2, 0.4, 0.4, NULL, NULL, NULL, &st));
    assert_int_equal(st, PC_EDOMAIN3);   /* kp = kq: M is the conic P = Q */
    assert_null(pc_oneratio_double_contact(2, a2, b2, c2, 0, 0.4, NULL, NULL, NULL, &st));
    assert_int_equal(st, PC_EDOMAIN);    /* kp = 0 */
    assert_null(pc_oneratio_double_contact(2, a2, b2, c2, 0.4, 0, NULL, NULL, NULL, &st));
    assert_int_equal(st, PC_EDOMAIN2);   /* kq = 0 */
}

static void test_closed(void **state) {
    (void)state;
    int st;
    pc_curve *c1 = pc_oneratio_closed(3, A, B, C, 0.8, 0.5, 1, &st);
    pc_curve *c2 = pc_oneratio_closed(3, A, B, C, 0.8, 0.5, 2, &st);
    near3(c1, 0.3, 2.344218978, 0.6998978102, 0, 1e-9);
    near3(c2, 0.3, 2.365218978, 0.7628978102, 0, 1e-9);
    near3(c1, 0, 4, 0, 0, 1e-12);
    near3(c1, 1, 4, 0, 0, 1e-12);
    near3(c2, 0, 4, 0, 0, 1e-12);
    near3(c2, 1, 4, 0, 0, 1e-12);
    /* scheme 1's start tangent 2(1 - kP)/kP (C - B) + (A - B) (ours, digest §1.5) */
    double d[9], want[3];
    assert_int_equal(pc_curve_derivs(c1, 0, 1, d), PC_OK);
    for (int k = 0; k < 3; k++) want[k] = 2 * 0.2 / 0.8 * (C[k] - B[k]) + (A[k] - B[k]);
    for (int k = 0; k < 3; k++) NEAR(d[3 + k], want[k], 1e-5);
    pc_curve_release(c1);
    pc_curve_release(c2);
    assert_null(pc_oneratio_closed(3, A, B, C, 0.8, 0.5, 3, &st));
    assert_int_equal(st, PC_EARG);
    assert_null(pc_oneratio_closed(3, A, B, C, 0, 0.5, 1, &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_null(pc_oneratio_closed(3, A, B, C, 0.8, 0, 2, &st));
    assert_int_equal(st, PC_EDOMAIN2);
}

/* homogeneous row h (dim 3 + weight) to a point */
static void hnorm(const double *h, double *x) {
    for (int k = 0; k < 3; k++) x[k] = h[k] / h[3];
}

/* |(q - p) x (r - p)|: zero when p, q, r are collinear */
static double collinear3(const double *p, const double *q, const double *r) {
    double u[3], v[3];
    for (int k = 0; k < 3; k++) u[k] = q[k] - p[k], v[k] = r[k] - p[k];
    double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
    return sqrt(x * x + y * y + z * z);
}

static void test_schemes(void **state) {
    (void)state;
    /* Fig. 3.1: N on AC, M on NB with one ratio; M is the curve (3.1) */
    double n[3], m[3], want[3];
    int st;
    assert_int_equal(pc_oneratio_simplex_scheme(3, A, B, C, 0.3, n, m), PC_OK);
    NEAR(n[0], 0.3, 1e-15), NEAR(n[1], 0.9, 1e-15);
    NEAR(m[0], 1.41, 1e-12), NEAR(m[1], 0.63, 1e-12);    /* digest §1.1 TV */
    pc_curve *c = pc_oneratio_simplex(3, A, B, C, &st);
    pc_curve_eval(c, 0.3, want);
    for (int k = 0; k < 3; k++) NEAR(m[k], want[k], 1e-12);
    pc_curve_release(c);

    /* Fig. 3.4: the levels of (3.4) at t = 0.4; the last is the Bezier point */
    const double pts[12] = {0, 0, 0, 2, 5, 0, 8, 5, 0, 10, 0, 0}, t = 0.4;
    double lv[18];
    assert_int_equal(pc_decasteljau_levels(3, 4, pts, t, lv), PC_OK);
    NEAR(lv[0], 0.8, 1e-15), NEAR(lv[1], 2, 1e-15);          /* P1 = (C1 - A)t + A */
    NEAR(lv[6], 8.8, 1e-14), NEAR(lv[7], 3, 1e-14);          /* P3 = (B - C2)t + C2 */
    double printed_p3[3];                                      /* the print: (C2 - B)t + C2 */
    for (int k = 0; k < 3; k++) printed_p3[k] = (pts[6 + k] - pts[9 + k]) * t + pts[6 + k];
    assert_true(collinear3(pts + 6, pts + 9, lv + 6) < 1e-12);
    assert_true(printed_p3[0] < pts[6]);                       /* beyond C2, away from B */
    double tb = 1 - t, bern[3];
    for (int k = 0; k < 3; k++)
        bern[k] = pts[k] * tb * tb * tb + 3 * pts[3 + k] * tb * tb * t + 3 * pts[6 + k] * tb * t * t +
                  pts[9 + k] * t * t * t;                      /* (3.4), corrected powers */
    for (int k = 0; k < 3; k++) NEAR(lv[15 + k], bern[k], 1e-12);
    for (int k = 0; k < 3; k++) NEAR(lv[9 + k], lv[k] + t * (lv[3 + k] - lv[k]), 1e-14);  /* Q1 */
    assert_int_equal(pc_decasteljau_levels(3, 1, pts, t, lv), PC_EDOMAIN);
    assert_int_equal(pc_decasteljau_levels(3, 4, pts, NAN, lv), PC_ENONFINITE);

    /* Fig. 3.12: T, S, R, N, J, Q, M of the Desargues arc at t = 0.3 */
    double h[28], pq[2], T[3], S[3], R[3], N[3], J[3], Q[3], M[3], Pp[3], K[3];
    assert_int_equal(pc_desargues_scheme(3, A, B, C, D, 0.3, h, pq), PC_OK);
    hnorm(h, T), hnorm(h + 4, S), hnorm(h + 8, R), hnorm(h + 12, N), hnorm(h + 16, J);
    hnorm(h + 20, Q), hnorm(h + 24, M);
    NEAR(M[0], 0.874137931, 1e-9), NEAR(M[1], 0.9, 1e-12), NEAR(M[2], 0.09310344828, 1e-10);
    for (int k = 0; k < 3; k++) {
        Pp[k] = (C[k] - A[k]) * 0.3 + A[k];                    /* AP/AC = t */
        K[k] = (D[k] - B[k]) * 0.3 + B[k];                     /* BK/BD = t */
    }
    assert_true(collinear3(A, B, T) < 1e-12);                 /* T on AB and on PQ */
    assert_true(collinear3(Pp, Q, T) < 1e-12);
    assert_true(collinear3(C, D, S) < 1e-12);                 /* S on CD and on QK */
    assert_true(collinear3(Q, K, S) < 1e-12);
    assert_true(collinear3(S, N, M) < 1e-12);                 /* M = SN x TJ */
    assert_true(collinear3(T, J, M) < 1e-12);
    for (int k = 0; k < 3; k++) {
        NEAR(R[k], T[k] + 0.3 * (S[k] - T[k]), 1e-12);         /* TR/TS = t */
        NEAR(J[k], (S[k] - T[k]) * pq[0] + (N[k] - T[k]) * pq[1] + T[k], 1e-12);
    }
    NEAR(pq[0], -0.4, 1e-15), NEAR(pq[1], 0.7 / 0.3, 1e-15);
    assert_int_equal(pc_desargues_scheme(3, A, B, C, D, 0.5, h, NULL), PC_OK);
    NEAR(h[3], 0, 1e-15), NEAR(h[7], 0, 1e-15), NEAR(h[11], 0, 1e-15);   /* T, S, R at infinity */
    hnorm(h + 24, M);                                          /* M(1/2): the centroid */
    for (int k = 0; k < 3; k++) NEAR(M[k], (A[k] + B[k] + C[k] + D[k]) / 4, 1e-15);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_simplex_tetra), cmocka_unit_test(test_smooth),
        cmocka_unit_test(test_desargues),     cmocka_unit_test(test_double_contact),
        cmocka_unit_test(test_bezier3),      cmocka_unit_test(test_double_contact_const),
        cmocka_unit_test(test_closed),       cmocka_unit_test(test_schemes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
