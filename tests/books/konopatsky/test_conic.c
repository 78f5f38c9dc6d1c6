/* Konopatsky's conics, chapter 2 (conic.h, konop_curves.h): the test vectors of the digest
 * konopatsky_ch1_2.md §5 (those of konopatsky_ch1_2_verify.py), the corrected formulas against
 * the constructions they come from, and the identities (on the conic, through the points,
 * tangents). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "conic.h"
#include "konop_curves.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void at(pc_curve *c, double t, double *out) {
    assert_int_equal(pc_curve_eval(c, t, out), PC_OK);
}

static void near_pt(pc_curve *c, double t, double x, double y, double tol) {
    double m[3];
    at(c, t, m);
    NEAR(m[0], x, tol);
    NEAR(m[1], y, tol);
}


/* the conic x^2 a + xy b + y^2 c + x d + y e + 1 = 0 through five points (Gauss-Jordan), in
 * coordinates shifted so that no test conic passes through the origin */
#define SX 0.1234
#define SY 0.5678
static void conic_fit(double pts[][2], double *co) {
    double a[5][6];
    for (int i = 0; i < 5; i++) {
        double x = pts[i][0] + SX, y = pts[i][1] + SY, r[6] = {x * x, x * y, y * y, x, y, -1};
        for (int k = 0; k < 6; k++) a[i][k] = r[k];
    }
    for (int p = 0; p < 5; p++) {
        int piv = p;
        for (int i = p + 1; i < 5; i++) if (fabs(a[i][p]) > fabs(a[piv][p])) piv = i;
        for (int k = 0; k < 6; k++) { double tmp = a[p][k]; a[p][k] = a[piv][k]; a[piv][k] = tmp; }
        for (int i = 0; i < 5; i++) {
            if (i == p) continue;
            double f = a[i][p] / a[p][p];
            for (int k = p; k < 6; k++) a[i][k] -= f * a[p][k];
        }
    }
    for (int i = 0; i < 5; i++) co[i] = a[i][5] / a[i][i];
    co[5] = 1;
}

static double conic_val(const double *co, const double *p) {
    double x = p[0] + SX, y = p[1] + SY;
    return co[0] * x * x + co[1] * x * y + co[2] * y * y + co[3] * x + co[4] * y + co[5];
}

/* ---- 2.1.6 the engineering discriminant ---- */
static void test_ed(void **state) {
    (void)state;
    double A[2] = {0, 0}, B[2] = {4, 0}, C[2] = {2, 3};
    int st;
    static const double tv[3][3][2] = {
        {{1.333333, 1.75}, {2, 2.1}, {2.666667, 1.75}},               /* k = 0.3 */
        {{1, 1.125}, {2, 1.5}, {3, 1.125}},                           /* k = 0.5 */
        {{0.727273, 0.613636}, {2, 0.9}, {3.272727, 0.613636}}};      /* k = 0.7 */
    double ks[3] = {0.3, 0.5, 0.7};
    for (int i = 0; i < 3; i++) {
        pc_curve *c = pc_conic_ed(2, A, B, C, ks[i], &st);
        assert_non_null(c);
        for (int j = 0; j < 3; j++) near_pt(c, 0.25 * (j + 1), tv[i][j][0], tv[i][j][1], 1e-6);
        near_pt(c, 0, 0, 0, 1e-15);
        near_pt(c, 1, 4, 0, 1e-15);
        /* the construction AQ x BP (§5.6) at u = 0.4 */
        double u = 0.4, K[3], T[3], P[3], Q[3], M[3], m[2];
        for (int k = 0; k < 2; k++) {
            K[k] = (0.5 * (A[k] + B[k]) - C[k]) * ks[i] + C[k];
            T[k] = (B[k] - A[k]) * u + A[k];
        }
        assert_int_equal(pc_meet(2, A, K, C, T, P, NULL, NULL, NULL), PC_OK);
        assert_int_equal(pc_meet(2, B, K, C, T, Q, NULL, NULL, NULL), PC_OK);
        assert_int_equal(pc_meet(2, A, Q, B, P, M, NULL, NULL, NULL), PC_OK);
        at(c, u, m);
        NEAR(m[0], M[0], 1e-12);
        NEAR(m[1], M[1], 1e-12);
        double k;   /* k back from the shoulder point K */
        assert_int_equal(pc_conic_ed_k(2, A, B, C, K, &k), PC_OK);
        NEAR(k, ks[i], 1e-14);
        /* tangents CA at A and CB at B: M'(0) = 2(1 - k)/k (C - A) */
        double d[4];
        assert_int_equal(pc_curve_derivs(c, 0, 1, d), PC_OK);
        NEAR(d[2], 2 * (1 - ks[i]) / ks[i] * (C[0] - A[0]), 1e-9);
        NEAR(d[3], 2 * (1 - ks[i]) / ks[i] * (C[1] - A[1]), 1e-9);
        pc_curve_release(c);
    }
    double off[2] = {3, 1}, k;
    assert_int_equal(pc_conic_ed_k(2, A, B, C, off, &k), PC_ENOTCOLLINEAR);
    assert_null(pc_conic_ed(2, A, B, C, 0, &st));
    assert_int_equal(st, PC_EDOMAIN);
    /* k < 0: poles u = (1 +- 1/sqrt(1 - 2k))/2 inside [0, 1]: a point at infinity there */
    pc_curve *h = pc_conic_ed(2, A, B, C, -0.5, &st);
    double hx[3], u = 0.5 * (1 - 1 / sqrt(2));
    assert_int_equal(pc_curve_eval_h(h, u, 0, hx), PC_OK);
    NEAR(hx[2], 0, 1e-14);
    pc_curve_release(h);
}

/* (2.107): the 90 degree arc of the unit circle, k = 2 - sqrt 2 */
static void test_ed_circle(void **state) {
    (void)state;
    double A[2] = {1, 0}, B[2] = {0, 1}, C[2] = {1, 1}, k;
    assert_int_equal(pc_conic_ed_circle_k(2, A, B, C, &k), PC_OK);
    NEAR(k, 2 - sqrt(2), 1e-14);
    NEAR(k, 0.585786438, 1e-9);
    int st;
    pc_curve *c = pc_conic_ed(2, A, B, C, k, &st);
    near_pt(c, 0.25, 0.929788, 0.368095, 1e-6);
    near_pt(c, 0.5, 0.707107, 0.707107, 1e-6);
    near_pt(c, 0.8, 0.293812, 0.955863, 1e-6);
    for (double u = 0; u <= 1; u += 0.05) {
        double m[2];
        at(c, u, m);
        NEAR(hypot(m[0], m[1]), 1, 1e-12);
    }
    pc_curve_release(c);
    c = pc_conic_circle_arc(2, A, B, C, &st);       /* the same arc in one call */
    near_pt(c, 0.5, 0.707107, 0.707107, 1e-6);
    pc_curve_release(c);
    double C2[2] = {2, 1};
    assert_int_equal(pc_conic_ed_circle_k(2, A, B, C2, &k), PC_EDOMAIN);
    assert_null(pc_conic_circle_arc(2, A, B, C2, &st));
    assert_int_equal(st, PC_EDOMAIN);
}

/* §4.1: the arc through A, K, B; u = 0.3 -> (18/19, 30/19) */
static void test_ed3(void **state) {
    (void)state;
    double A[3] = {0, 0, 0}, K[3] = {2, 2, 0}, B[3] = {4, 0, 0}, m[3];
    int st;
    pc_curve *c = pc_conic_ed3(3, A, K, B, 0.7, &st);
    at(c, 0.3, m);
    NEAR(m[0], 18.0 / 19, 1e-12);
    NEAR(m[1], 30.0 / 19, 1e-12);
    NEAR(m[2], 0, 1e-15);
    at(c, 0.5, m);
    NEAR(m[0], 2, 1e-12);
    NEAR(m[1], 2, 1e-12);
    pc_curve_release(c);
    assert_null(pc_conic_ed3(3, A, K, B, 1, &st));
}

/* 2.1.7 Ceva: the test vectors, (2.105), k from a fifth point, the median relation */
static void test_ceva(void **state) {
    (void)state;
    double A1[2] = {0, 0}, A2[2] = {4, 0}, A3[2] = {2, 3};
    int st;
    pc_curve *c = pc_conic_ceva(2, A1, A2, A3, 0.25, &st);
    near_pt(c, 0.25, 3.428571, 0.734694, 1e-6);
    near_pt(c, 0.5, 2.666667, 1.333333, 1e-6);
    near_pt(c, 2.0 / 3, 2, 1.5, 1e-12);
    near_pt(c, 0.75, 1.6, 1.44, 1e-12);
    near_pt(c, 0.3, 3.294118, 0.871972, 1e-6);      /* (2.105) */
    pc_curve_release(c);
    c = pc_conic_ceva(2, A1, A2, A3, 1, &st);
    near_pt(c, 0.25, 3.230769, 0.692308, 1e-6);
    near_pt(c, 0.5, 2, 1, 1e-12);
    near_pt(c, 2.0 / 3, 1.142857, 0.857143, 1e-6);
    near_pt(c, 0.75, 0.769231, 0.692308, 1e-6);
    near_pt(c, 0.3, 3.012658, 0.797468, 1e-6);
    /* (2.100) recovers k from a point of the arc */
    double K[2], k;
    at(c, 0.37, K);
    assert_int_equal(pc_conic_ceva_k(2, A1, A2, A3, K, &k), PC_OK);
    NEAR(k, 1, 1e-12);
    /* the same conic as the ED arc with k_ED = 2 sqrt k/(1 + 2 sqrt k) (ours, digest §5.7) */
    pc_curve *e = pc_conic_ed(2, A1, A2, A3, 2.0 / 3, &st);
    double m1[2], m2[2];
    at(c, 0.5, m1);       /* t = 1/(1 + sqrt k) */
    at(e, 0.5, m2);
    NEAR(m1[0], m2[0], 1e-12);
    NEAR(m1[1], m2[1], 1e-12);
    pc_curve_release(e);
    pc_curve_release(c);
}

/* 2.1.3 parabolas */
static void test_parabolas(void **state) {
    (void)state;
    double A1[2] = {0, 0}, A2[2] = {4, 0}, A3[2] = {2, 4};
    int st;
    pc_curve *c = pc_conic_parabola(2, A1, A3, A2, &st);
    near_pt(c, 0.25, 1, 1.5, 1e-14);
    near_pt(c, 0.5, 2, 2, 1e-14);
    pc_curve_release(c);
    double A[2] = {0, 0}, B[2] = {4, 0}, C[2] = {1, 3};
    c = pc_conic_parabola3(2, A, C, B, 0.25, &st);
    near_pt(c, 0.25, 1, 3, 1e-12);
    near_pt(c, 0.5, 2, 4, 1e-12);
    near_pt(c, 0.75, 3, 3, 1e-12);
    pc_curve_release(c);
    c = pc_conic_parabola3(2, A, C, B, 0.5, &st);
    near_pt(c, 0.25, 0.25, 2.25, 1e-12);
    near_pt(c, 0.5, 1, 3, 1e-12);
    near_pt(c, 0.75, 2.25, 2.25, 1e-12);
    pc_curve_release(c);
    assert_null(pc_conic_parabola3(2, A, C, B, 1, &st));
    assert_int_equal(st, PC_EDOMAIN);
}

static double on_ellipse(const double *m, double a, double b) {
    return m[0] * m[0] / (a * a) + m[1] * m[1] / (b * b) - 1;
}

/* 2.1.1 the ellipse, set E: C(0,0) A(4,0) B(0,2) */
static void test_ellipse(void **state) {
    (void)state;
    double C[2] = {0, 0}, A[2] = {4, 0}, B[2] = {0, 2}, m[2];
    int st;
    pc_curve *c = pc_kcurve(PC_KC_ELLIPSE_ANGLE, 2, C, A, B, NULL, 0, NAN, NAN, &st);
    assert_non_null(c);
    near_pt(c, 0, 4, 0, 1e-14);
    near_pt(c, M_PI / 6, 2.618615, 1.511858, 1e-6);
    near_pt(c, M_PI / 4, 1.788854, 1.788854, 1e-6);
    near_pt(c, M_PI / 2, 0, 2, 1e-14);
    near_pt(c, 2.0, -0.892253, 1.949608, 1e-6);
    for (double ph = 0.1; ph < 6.2; ph += 0.3) {      /* (2.11): the true polar angle */
        at(c, ph, m);
        NEAR(on_ellipse(m, 4, 2), 0, 1e-12);
        NEAR(remainder(atan2(m[1], m[0]) - ph, 2 * M_PI), 0, 1e-12);
    }
    assert_true(c->closed);
    pc_curve_release(c);

    c = pc_kcurve(PC_KC_ELLIPSE_RADIUS, 2, C, A, B, NULL, 0, NAN, NAN, &st);
    near_pt(c, 2.5, 1.732051, 1.802776, 1e-6);
    near_pt(c, 3, 2.581989, 1.527525, 1e-6);
    near_pt(c, 3.5, 3.316625, 1.118034, 1e-6);
    at(c, 3, m);
    NEAR(hypot(m[0], m[1]), 3, 1e-12);
    assert_true(c->t0 == 2 && c->t1 == 4);
    pc_curve_release(c);

    c = pc_kcurve(PC_KC_ELLIPSE_FOCAL, 2, C, A, B, NULL, 0, NAN, NAN, &st);
    near_pt(c, M_PI / 3, -2.582248, 1.527416, 1e-6);
    near_pt(c, M_PI / 2, -3.464102, 1, 1e-6);
    near_pt(c, M_PI, -4, 0, 1e-12);
    near_pt(c, 4, -3.881479, -0.483249, 1e-6);
    at(c, M_PI / 3, m);   /* |F2 M| = p/(1 - e cos phi) */
    NEAR(hypot(m[0] + sqrt(12), m[1]), 1.763708, 1e-6);
    pc_curve_release(c);

    c = pc_kcurve(PC_KC_ELLIPSE_COMPRESSION, 2, C, A, B, NULL, 0, NAN, NAN, &st);
    near_pt(c, M_PI / 3, 2, 1.732051, 1e-6);
    pc_curve_release(c);
    c = pc_kcurve(PC_KC_ELLIPSE_ALGEBRAIC, 2, C, A, B, NULL, 0, NAN, NAN, &st);
    near_pt(c, 0.5, 3.464102, 1, 1e-6);
    pc_curve_release(c);

    c = pc_conic_conjugate(2, C, A, B, &st);           /* (2.32) */
    near_pt(c, 0.25, 3.529412, 0.941176, 1e-6);
    near_pt(c, 0.5, 2.4, 1.6, 1e-12);
    at(c, 0.7, m);
    NEAR(on_ellipse(m, 4, 2), 0, 1e-12);
    pc_curve_release(c);

    double K[2] = {-4, 0}, B2[2] = {2, sqrt(3)};
    c = pc_conic_conjugate2(2, K, A, B, 0.5, &st);
    near_pt(c, 0.25, -3.2, 1.2, 1e-12);
    near_pt(c, 0.5, 0, 2, 1e-12);
    near_pt(c, 0.75, 3.2, 1.2, 1e-12);
    pc_curve_release(c);
    c = pc_conic_conjugate2(2, K, A, B2, 0.75, &st);
    near_pt(c, 0.25, -3.714286, 0.742307, 1e-6);
    near_pt(c, 0.5, -2, 1.732051, 1e-6);
    near_pt(c, 0.9, 3.714286, 0.742307, 1e-6);
    pc_curve_release(c);

    /* a = b: the radial form is 0/0 */
    double B4[2] = {0, 4};
    assert_null(pc_kcurve(PC_KC_ELLIPSE_RADIUS, 2, C, A, B4, NULL, 0, NAN, NAN, &st));
    assert_int_equal(st, PC_EDOMAIN);
    double Af[2] = {0, 3};
    assert_null(pc_kcurve(PC_KC_ELLIPSE_ANGLE, 2, C, Af, B, NULL, 0, NAN, NAN, &st));
    assert_int_equal(st, PC_ECOLLINEAR);
}

/* the tilted ellipse, A(0,0) B(4,3) C(5,-1), m = 2, n = 1 */
static void test_tilted(void **state) {
    (void)state;
    double A[2] = {0, 0}, B[2] = {4, 3}, C[2] = {5, -1}, P[2], Q[2];
    static const double tv[3][6] = {
        {6.6, 0.2, 5.6, -1.8, 6.252198, -1.178885},
        {5.282843, 0.979899, 5.989949, -1.141421, 6.011929, -0.241053},
        {3.8, 0.6, 5.8, -0.4, 5.178885, 0.252198}};
    for (int i = 0; i < 3; i++) {
        double th = i * M_PI / 4, m[2];
        assert_int_equal(pc_ellipse_tilted_axes(2, A, B, C, th, 2, 1, P, Q), PC_OK);
        NEAR(P[0], tv[i][0], 1e-6);
        NEAR(P[1], tv[i][1], 1e-6);
        NEAR(Q[0], tv[i][2], 1e-6);
        NEAR(Q[1], tv[i][3], 1e-6);
        NEAR(hypot(P[0] - C[0], P[1] - C[1]), 2, 1e-12);
        NEAR((P[0] - C[0]) * (Q[0] - C[0]) + (P[1] - C[1]) * (Q[1] - C[1]), 0, 1e-12);
        int st;
        pc_curve *c = pc_kcurve(PC_KC_ELLIPSE_ANGLE, 2, C, P, Q, NULL, 0, NAN, NAN, &st);
        at(c, M_PI / 4, m);
        NEAR(m[0], tv[i][4], 1e-6);
        NEAR(m[1], tv[i][5], 1e-6);
        pc_curve_release(c);
        /* the angle between CP and AB is theta */
        double cp = (P[0] - C[0]) * 4 + (P[1] - C[1]) * 3;
        NEAR(acos(fmin(1, fabs(cp) / (2 * 5))), th < M_PI / 2 + 1e-9 ? th : M_PI - th, 1e-7);
    }
}

/* the same construction's K = CP x AB and the rotated A (Fig. 2.5): theta = pi/4 puts K on AB
 * beyond B at (5.76, 4.32), pi/2 at (2.72, 2.04) inside; theta = 0 makes CP parallel to AB (K a
 * direction); |C Arot| = b = |CA| and Q = (Arot - C) n/b + C */
static void test_tilted_scheme(void **state) {
    (void)state;
    double A[2] = {0, 0}, B[2] = {4, 3}, C[2] = {5, -1}, K[3], Ar[2], tau, P[2], Q[2];
    static const double tv[2][3] = {{M_PI / 4, 5.76, 4.32}, {M_PI / 2, 2.72, 2.04}};
    for (int i = 0; i < 2; i++) {
        assert_int_equal(pc_ellipse_tilted_scheme(2, A, B, C, tv[i][0], K, Ar, &tau), PC_OK);
        NEAR(K[2], 1, 0);
        NEAR(K[0], tv[i][1], 1e-12);
        NEAR(K[1], tv[i][2], 1e-12);
        NEAR(hypot(Ar[0] - C[0], Ar[1] - C[1]), sqrt(26), 1e-12);
        assert_int_equal(pc_ellipse_tilted_axes(2, A, B, C, tv[i][0], 2, 1, P, Q), PC_OK);
        NEAR((Ar[0] - C[0]) / sqrt(26) + C[0], Q[0], 1e-12);   /* n = 1 */
        NEAR((Ar[1] - C[1]) / sqrt(26) + C[1], Q[1], 1e-12);
        /* K, P, C collinear */
        NEAR((K[0] - C[0]) * (P[1] - C[1]) - (K[1] - C[1]) * (P[0] - C[0]), 0, 1e-12);
        NEAR(tau, M_PI - (atan2(3, 4) + atan2(1, 5)) - tv[i][0], 1e-12);   /* alpha = angle BAC */
    }
    double o[2 + 2 + 3 + 2 + 1], m[2];
    int st;
    pc_curve *e = pc_ellipse_tilted(2, A, B, C, M_PI / 4, 2, 1, o, &st);   /* all in one: P, Q, K, Arot, tau */
    NEAR(o[0], 5.282843, 1e-6);
    NEAR(o[3], -1.141421, 1e-6);
    NEAR(o[4], 5.76, 1e-12);
    NEAR(o[9], M_PI - (atan2(3, 4) + atan2(1, 5)) - M_PI / 4, 1e-12);
    at(e, M_PI / 4, m);
    NEAR(m[0], 6.011929, 1e-6);
    pc_curve_release(e);
    assert_null(pc_ellipse_tilted(2, A, B, C, M_PI / 4, 0, 1, o, &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_int_equal(pc_ellipse_tilted_scheme(2, A, B, C, 0, K, Ar, &tau), PC_OK);
    NEAR(K[2], 0, 0);
    NEAR(K[0], 0.8, 1e-12);
    NEAR(K[1], 0.6, 1e-12);
    double Af[2] = {3, 2.25};   /* on AB: no triangle */
    assert_int_equal(pc_ellipse_tilted_scheme(2, A, B, Af, 1, K, Ar, &tau), PC_ECOLLINEAR);
}

static double on_hyperbola(const double *m) {
    return m[0] * m[0] / 9 - m[1] * m[1] / 4 - 1;
}

/* 2.1.2 the hyperbola, set H: C(0,0) A(3,0) B(0,2) */
static void test_hyperbola(void **state) {
    (void)state;
    double C[2] = {0, 0}, A[2] = {3, 0}, B[2] = {0, 2}, m[2], h[3];
    int st;
    double br2 = 2;
    pc_curve *c = pc_kcurve(PC_KC_HYPERBOLA_ANGLE, 2, C, A, B, NULL, 0, NAN, NAN, &st);
    NEAR(c->t1, 0.588003, 1e-6);       /* arcsin(b/c) */
    near_pt(c, 0.3, 3.386643, 1.047612, 1e-6);
    near_pt(c, 0.5, 5.234274, 2.859497, 1e-6);
    assert_int_equal(pc_curve_eval_h(c, c->t1, 0, h), PC_OK);   /* the asymptote */
    NEAR(h[2], 0, 1e-7);
    NEAR(h[1] / h[0], 2.0 / 3, 1e-6);
    pc_curve_release(c);
    c = pc_kcurve(PC_KC_HYPERBOLA_ANGLE, 2, C, A, B, &br2, 1, NAN, NAN, &st);
    near_pt(c, M_PI + 0.3, -3.386643, -1.047612, 1e-6);
    pc_curve_release(c);

    c = pc_kcurve(PC_KC_HYPERBOLA_RADIUS, 2, C, A, B, NULL, 0, 3, 8, &st);
    near_pt(c, 4, 3.721042, 1.467599, 1e-6);
    near_pt(c, 6, 5.262348, 2.882307, 1e-6);
    pc_curve_release(c);
    assert_null(pc_kcurve(PC_KC_HYPERBOLA_RADIUS, 2, C, A, B, NULL, 0, 2, 8, &st));
    assert_int_equal(st, PC_EDOMAIN3);   /* rho = 2 < a = 3: no real point */
    assert_null(pc_kcurve(PC_KC_HYPERBOLA_RADIUS, 2, C, A, B, NULL, 0, 8, 3, &st));
    assert_int_equal(st, PC_EDOMAIN2);   /* an empty range */

    /* (2.56): the branch through A by default; the book's printed range is the other one */
    c = pc_kcurve(PC_KC_HYPERBOLA_FOCAL, 2, C, A, B, NULL, 0, NAN, NAN, &st);
    near_pt(c, M_PI / 2, 3.605551, 1.333333, 1e-6);
    near_pt(c, 2, 3.235679, 0.808186, 1e-6);
    near_pt(c, M_PI, 3, 0, 1e-12);
    near_pt(c, 5, 4.179406, -1.939923, 1e-6);
    for (double ph = 1; ph < 5.2; ph += 0.4) {
        at(c, ph, m);
        NEAR(on_hyperbola(m), 0, 1e-11);
        assert_true(m[0] > 0);
    }
    pc_curve_release(c);
    c = pc_kcurve(PC_KC_HYPERBOLA_FOCAL, 2, C, A, B, &br2, 1, NAN, NAN, &st);
    near_pt(c, 0, -3, 0, 1e-12);
    near_pt(c, 0.3, -4.991118, -2.659262, 1e-6);
    pc_curve_release(c);
}

/* 2.1.8 circles with Fig. 2.25's A(0,0) B(0.5,1) C(1,0) */
static void test_circles(void **state) {
    (void)state;
    double A[2] = {0, 0}, B[2] = {0.5, 1}, C[2] = {1, 0}, m[2];
    int st;
    double dl = M_PI / 3;
    pc_curve *c = pc_kcurve(PC_KC_CIRCLE_ANGLE, 2, C, A, B, &dl, 1, NAN, NAN, &st);
    static const double tv[7][2] = {{0, 0}, {0, 0.577350}, {0.5, 0.866025}, {1, 0.577350},
                                    {1, 0}, {0.5, -0.288675}, {0, 0}};
    for (int i = 0; i < 7; i++) {
        near_pt(c, i * M_PI / 6, tv[i][0], tv[i][1], 1e-6);
        at(c, i * M_PI / 6 + 0.1, m);
        NEAR(hypot(m[0] - 0.5, m[1] - 0.5 / sqrt(3)), 1 / sqrt(3), 1e-12);
    }
    pc_curve_release(c);
    /* (2.116): delta = beta gives the circumcircle; phi = gamma at B, pi - beta at C */
    double beta = 0.927295218001612, gamma = 1.10714871779409;
    c = pc_kcurve(PC_KC_CIRCLE_ANGLE, 2, C, A, B, &beta, 1, NAN, NAN, &st);
    near_pt(c, gamma, 0.5, 1, 1e-12);
    near_pt(c, M_PI - beta, 1, 0, 1e-12);
    pc_curve_release(c);
    double R = 0.5;
    c = pc_kcurve(PC_KC_CIRCLE_RADIUS, 2, C, A, B, &R, 1, NAN, NAN, &st);
    near_pt(c, 0, 0.5, 0, 1e-12);
    near_pt(c, gamma / 2, 0.574675, 0.262866, 1e-6);
    near_pt(c, gamma, 0.776393, 0.447214, 1e-6);
    near_pt(c, M_PI, 1.5, 0, 1e-12);
    pc_curve_release(c);
    dl = M_PI;
    assert_null(pc_kcurve(PC_KC_CIRCLE_ANGLE, 2, C, A, B, &dl, 1, NAN, NAN, &st));
    assert_int_equal(st, PC_EDOMAIN);
}

/* 2.1.4 the conic through five points, corrected */
static void test_five_points(void **state) {
    (void)state;
    double A[2] = {1, 0}, B[2] = {0, 1}, C[2] = {0, 0}, D[2] = {0.3, 0.8}, E[2] = {0.7, 0.6};
    double u[5];
    int st;
    pc_curve *c = pc_conic_five_points(2, A, B, C, D, E, 0, 2.6, 0, u, &st);
    assert_non_null(c);
    NEAR(u[0], 1, 0);
    NEAR(u[1], 1.75, 1e-12);
    NEAR(u[2], 0, 0);
    NEAR(u[3], 1.9, 1e-12);
    NEAR(u[4], 2.557692308, 1e-9);
    double u0, u1, far[5] = {1, -0.5, 0, 1e7, NAN};
    pc_conic_five_points_span(u, &u0, &u1);   /* the default range: C (u = 0) to E */
    NEAR(u0, 0, 0);
    NEAR(u1, 2.557692308, 1e-9);
    pc_conic_five_points_span(far, &u0, &u1);  /* no range end at infinity (|u| >= 1e6) */
    NEAR(u0, -0.5, 0);
    NEAR(u1, 1, 0);
    pc_curve *dflt = pc_conic_five_points(2, A, B, C, D, E, NAN, NAN, 0, NULL, &st);   /* the span */
    assert_true(dflt->t0 == 0 && fabs(dflt->t1 - 2.557692308) < 1e-9);
    pc_curve_release(dflt);
    dflt = pc_conic_five_points(2, A, B, C, D, E, NAN, 2, 0, NULL, &st);
    assert_true(dflt->t0 == 0 && dflt->t1 == 2);
    pc_curve_release(dflt);
    near_pt(c, 0.25, 0.3, 0.066667, 1e-6);
    near_pt(c, 0.5, 0.531496, 0.094488, 1e-6);
    near_pt(c, 0.75, 0.743119, 0.082569, 1e-6);
    near_pt(c, 1.25, 1.569767, -0.348837, 1e-6);
    near_pt(c, 1.5, -8.1, 7.2, 1e-9);
    const double *pts[5] = {A, B, C, D, E};
    for (int i = 0; i < 5; i++) near_pt(c, u[i], pts[i][0], pts[i][1], 1e-12);
    /* the scheme S = BE x AD, U, V = SU x CB, M = UE x VD at u = 0.6 */
    double S[3], U[2] = {0.6, 0}, V[3], M[3], m[2];
    assert_int_equal(pc_meet(2, B, E, A, D, S, NULL, NULL, NULL), PC_OK);
    NEAR(S[0], 0.25, 1e-12);
    NEAR(S[1], 0.857143, 1e-6);
    assert_int_equal(pc_meet(2, S, U, C, B, V, NULL, NULL, NULL), PC_OK);
    assert_int_equal(pc_meet(2, U, E, V, D, M, NULL, NULL, NULL), PC_OK);
    at(c, 0.6, m);
    NEAR(m[0], M[0], 1e-12);
    NEAR(m[1], M[1], 1e-12);
    /* a hyperbola: the curve passes through infinity between u = 1.25 and 1.5 */
    double h0[3], h1[3];
    pc_curve_eval_h(c, 1.25, 0, h0);
    pc_curve_eval_h(c, 1.5, 0, h1);
    assert_true(h0[2] * h1[2] < 0);
    pc_curve_release(c);
    /* the whole conic closes */
    c = pc_conic_five_points(2, A, B, C, D, E, 0, 2.6, 1, NULL, &st);
    near_pt(c, 5.2, 0, 0, 1e-12);
    double five[5][2] = {{1, 0}, {0, 1}, {0, 0}, {0.3, 0.8}, {0.7, 0.6}}, co[6], mid[2];
    conic_fit(five, co);
    for (double s = 2.7; s < 5.2; s += 0.3) {    /* the complementary arc is on the conic */
        at(c, s, mid);
        NEAR(conic_val(co, mid) / (1 + mid[0] * mid[0] + mid[1] * mid[1]), 0, 1e-9);
    }
    pc_curve_release(c);
    assert_null(pc_conic_five_points(2, A, B, C, D, E, 1, 0.5, 0, NULL, &st));
    assert_int_equal(st, PC_EDOMAIN2);   /* u1 < u0 */
    double F[2] = {0.5, 0.5};    /* on AB: A, B, F collinear */
    assert_null(pc_conic_five_points(2, A, B, C, D, F, 0, 1, 0, NULL, &st));
    assert_int_equal(st, PC_EDOMAIN);
}

/* 2.1.5 the second parametrisation: Fig. 2.17's printed equations */
static void test_five_points2(void **state) {
    (void)state;
    double A[2] = {0, 0}, B[2] = {1, 0}, C[2] = {0.5, 1};
    int st;
    pc_curve *c = pc_conic_five_points2(2, C, A, B, 0.7, 0.7, 0.8, 0.8, &st);
    for (double t = 0.1; t < 0.95; t += 0.2) {
        double xb = 4 * t * (9 * t + 0.8) / (70 * t * t - 75 * t + 44.2);
        double yb = -8 * t * (t - 1) / (14 * t * t - 15 * t + 8.84);
        near_pt(c, t, xb, yb, 1e-12);
    }
    near_pt(c, 0.25, 0.102263, 0.251467, 1e-6);
    near_pt(c, 0.5, 0.438017, 0.413223, 1e-6);
    near_pt(c, 0.75, 0.828911, 0.274474, 1e-6);
    pc_curve_release(c);
    /* p1 != p2: the corrected (2.93) against the construction (Pascal hexagon A A1 A2 M A3 B) */
    double A1[2] = {1, 0}, B1[2] = {0, 1}, C1[2] = {0, 0};
    double p1 = 0.3, p2 = 0.6, q2 = 0.7, q3 = 0.4;
    c = pc_conic_five_points2(2, C1, A1, B1, p1, p2, q2, q3, &st);
    double X1[2] = {p1, 0}, X3[2] = {0, q3}, X2[2] = {p1 * (1 - p2) * q2, p2 * q2 * q3};
    double ts[3] = {0.2, 0.45, 0.8};
    for (int i = 0; i < 3; i++) {
        double t = ts[i], P[2] = {1 - t, 0}, Q[3], R[3], M[3], m[2];
        assert_int_equal(pc_meet(2, X1, X2, B1, C1, Q, NULL, NULL, NULL), PC_OK);
        assert_int_equal(pc_meet(2, P, Q, A1, B1, R, NULL, NULL, NULL), PC_OK);
        assert_int_equal(pc_meet(2, R, X2, P, X3, M, NULL, NULL, NULL), PC_OK);
        at(c, t, m);
        NEAR(m[0], M[0], 1e-12);
        NEAR(m[1], M[1], 1e-12);
    }
    pc_curve_release(c);
    /* both tangents (p1 = q3 = 1): the simplified form of (2.96) */
    p2 = 0.4, q2 = 0.6;
    c = pc_conic_five_points2(2, C1, A1, B1, 1, p2, q2, 1, &st);
    for (double t = 0.3; t < 0.8; t += 0.4) {
        double qb = 1 - q2, Dl = qb * qb * (1 - t) + p2 * (1 - p2) * q2 * q2 * t * t;
        near_pt(c, t, qb * qb * (1 - t) * (1 - t) / Dl, p2 * (1 - p2) * q2 * q2 * t * t / Dl, 1e-12);
    }
    pc_curve_release(c);
    assert_null(pc_conic_five_points2(2, C1, A1, B1, 1.5, p2, q2, 1, &st));
    assert_int_equal(st, PC_EDOMAIN);    /* p1 outside (0, 1] */
    assert_null(pc_conic_five_points2(2, C1, A1, B1, 1, p2, 1, 1, &st));
    assert_int_equal(st, PC_EDOMAIN2);   /* q2 = 1: A2 on the side */
}

/* 2.2 (b), 2.3, 2.4 */
static void test_triples_redundant_reparam(void **state) {
    (void)state;
    double A1[2] = {3.0, 0.2}, A5[2] = {0.5, 2.7}, A2[2] = {1.2, 0.9}, A4[2] = {0.2, 1.3},
           A3[2] = {2.0, 1.8};
    int st;
    pc_curve *c = pc_triples_conic(2, A1, A2, A3, A4, A5, 0, 1, &st);
    assert_non_null(c);
    near_pt(c, 0, A1[0], A1[1], 1e-12);
    /* a conic through A1, A3, A4: six points of the locus and A3, A4 satisfy one conic */
    double pts[8][2];
    for (int i = 0; i < 6; i++) at(c, (i + 1) / 8.0 + 0.013, pts[i]);
    pts[6][0] = A3[0], pts[6][1] = A3[1], pts[7][0] = A4[0], pts[7][1] = A4[1];
    double co[6];
    conic_fit(pts, co);
    for (int i = 5; i < 8; i++) {
        NEAR(conic_val(co, pts[i]), 0, 1e-9);
    }
    assert_true(fabs(conic_val(co, A2)) > 1e-3);
    assert_true(fabs(conic_val(co, A5)) > 1e-3);
    pc_curve_release(c);
    assert_null(pc_triples_conic(2, A1, A2, A3, A4, A5, 1, 1, &st));
    assert_int_equal(st, PC_EDOMAIN2);   /* an empty range */

    /* (2.120) and (2.121) = the ED arc k = 2/3 */
    double C[2] = {0, 0}, A[2] = {1, 0}, B[2] = {0, 1}, K[2];
    assert_int_equal(pc_redundant_point(2, C, A, B, 0.25, 0.25, K), PC_OK);
    NEAR(K[0], 0.692308, 1e-6);
    NEAR(K[1], 0.076923, 1e-6);
    assert_int_equal(pc_redundant_point(2, C, A, B, 0.5, 0.5, K), PC_OK);
    NEAR(K[0], 1.0 / 3, 1e-15);
    assert_int_equal(pc_redundant_point(2, C, A, B, 0, 1, K), PC_EPOLE);

    /* §2.4, C(0,0) A(4,0) B(1,3) */
    double A4b[2] = {4, 0}, B4b[2] = {1, 3}, g = atan2(3, 1);
    c = pc_kcurve(PC_KC_PARABOLA_ANGLE, 2, C, A4b, B4b, NULL, 0, NAN, NAN, &st);
    near_pt(c, g / 4, 1.561061, 0.503946, 1e-6);
    near_pt(c, g / 2, 1.166280, 0.840607, 1e-6);
    near_pt(c, g, 1, 3, 1e-12);
    at(c, 0.4, K);
    NEAR(atan2(K[1], K[0]), 0.4, 1e-12);
    pc_curve_release(c);
    double one = 1, two = 2, fa = sqrt(10), fb = 4, smin = fa * fb / (fa + fb);
    c = pc_kcurve(PC_KC_PARABOLA_SIGMA, 2, C, A4b, B4b, &one, 1, NAN, NAN, &st);
    near_pt(c, 2.883037, 2.825181, 0.080271, 1e-6);
    near_pt(c, smin, 1.091656, 0.935705, 1e-6);
    near_pt(c, fb, 4, 0, 1e-12);
    pc_curve_release(c);
    c = pc_kcurve(PC_KC_PARABOLA_SIGMA, 2, C, A4b, B4b, &two, 1, NAN, NAN, &st);
    near_pt(c, 2.464176, 0.824980, 2.274263, 1e-6);
    near_pt(c, fa, 1, 3, 1e-12);
    pc_curve_release(c);
}

/* 2.5, 2.8, 2.6, 2.7 */
static void test_sinusoid_cycloid_cones_contour(void **state) {
    (void)state;
    double C[2] = {0, 0}, A[2] = {1, 0}, B[2] = {0, 1};
    int st;
    double k1[2] = {1, 6}, k2[3] = {2, 6, 24};
    pc_curve *m = pc_kcurve(PC_KC_SINUSOID, 2, C, A, B, k1, 2, NAN, NAN, &st);
    pc_curve *n = pc_kcurve(PC_KC_SINUSOID, 2, C, A, B, k2, 3, NAN, NAN, &st);
    near_pt(m, 0, 1.166667, 0, 1e-6);
    near_pt(n, 0, 1.215278, 0, 1e-6);
    near_pt(m, M_PI / 12, 0.979250, 0.262389, 1e-6);
    near_pt(n, M_PI / 12, 1.020052, 0.273322, 1e-6);
    near_pt(m, M_PI / 6, 0.721688, 0.416667, 1e-6);
    near_pt(n, M_PI / 6, 0.751758, 0.434028, 1e-6);
    near_pt(m, M_PI / 2, 0, 0.833333, 1e-6);
    near_pt(n, M_PI / 2, 0, 0.868056, 1e-6);
    pc_curve_release(m);
    pc_curve_release(n);

    double Cc[2] = {0, 0}, Ac[2] = {0, 2}, Bc[2] = {M_PI, 0}, zero = 0, one = 1;
    pc_curve *cv = pc_kcurve(PC_KC_CYCLOID, 2, Cc, Ac, Bc, &zero, 1, 0, 2 * M_PI, &st);
    pc_curve *cc = pc_kcurve(PC_KC_CYCLOID, 2, Cc, Ac, Bc, &one, 1, 0, 2 * M_PI, &st);
    near_pt(cv, M_PI / 2, 2.570796, 1, 1e-6);
    near_pt(cc, M_PI / 2, 0.570796, 1, 1e-6);
    near_pt(cv, M_PI, 0, 2, 1e-12);
    near_pt(cc, M_PI, 0, 2, 1e-12);
    near_pt(cv, 2 * M_PI, -M_PI, 0, 1e-12);
    near_pt(cc, 2 * M_PI, -M_PI, 0, 1e-12);
    pc_curve_release(cv);
    pc_curve_release(cc);

    /* §2.6 in the Cartesian simplex A = E1, B = E2, C = E3, D = O */
    double E1[3] = {1, 0, 0}, E2[3] = {0, 1, 0}, E3[3] = {0, 0, 1}, O[3] = {0, 0, 0}, M[3];
    pc_curve *q = pc_cubic_cones(3, E1, E2, E3, O, 0.3, 0.8, 2, &st);
    assert_non_null(q);
    at(q, 0.25, M);
    NEAR(M[0], 0.005718, 1e-6); NEAR(M[1], 0.000635, 1e-6); NEAR(M[2], 0.008895, 1e-6);
    at(q, 0.5, M);
    NEAR(M[0], 0.005590, 1e-6); NEAR(M[1], 0.005590, 1e-6); NEAR(M[2], 0.026087, 1e-6);
    at(q, 0.75, M);
    NEAR(M[0], 0.005096, 1e-6); NEAR(M[1], 0.045866, 1e-6); NEAR(M[2], 0.071348, 1e-6);
    at(q, 1, M);
    NEAR(M[1], 1, 1e-9);
    pc_curve_release(q);
    q = pc_cubic_cones(3, E1, E2, E3, O, 0.8, 0.3, 0.5, &st);
    at(q, 0.25, M);
    NEAR(M[0], 0.441248, 1e-6); NEAR(M[1], 0.049028, 1e-6); NEAR(M[2], 0.073541, 1e-6);
    at(q, 0.5, M);
    NEAR(M[0], 0.286654, 1e-6); NEAR(M[1], 0.286654, 1e-6); NEAR(M[2], 0.143327, 1e-6);
    at(q, 0.75, M);
    NEAR(M[0], 0.080074, 1e-6); NEAR(M[1], 0.720662, 1e-6); NEAR(M[2], 0.120110, 1e-6);
    pc_curve_release(q);
    assert_null(pc_cubic_cones(2, A, B, C, O, 0.3, 0.8, 2, &st));
    assert_int_equal(st, PC_EDIM);
    assert_null(pc_cubic_cones(3, E1, E2, E3, O, 1, 0.8, 2, &st));
    assert_int_equal(st, PC_EDOMAIN);    /* fP outside (0, 1) */
    assert_null(pc_cubic_cones(3, E1, E2, E3, O, 0.3, 0, 2, &st));
    assert_int_equal(st, PC_EDOMAIN2);   /* fQ outside (0, 1) */
    assert_null(pc_cubic_cones(3, E1, E2, E3, O, 0.3, 0.8, 1, &st));
    assert_int_equal(st, PC_EDOMAIN3);   /* n = 1: N = D */
}

static double uv_t_t2(void *ud, int which, double t) {
    (void)ud;
    switch (which) {
    case 0: return t;
    case 1: return t * t;
    case 2: return 1;
    default: return 2 * t;
    }
}

static void test_contour_arc(void **state) {
    (void)state;
    double A1[2] = {0, 0}, A2[2] = {4, 0}, A3[2] = {2, 4};
    int st;
    pc_curve *c = pc_contour_arc(2, A1, A2, A3, uv_t_t2, 1, NULL, NULL, &st);
    near_pt(c, 0.25, 0.732143, 1.392857, 1e-6);
    near_pt(c, 0.5, 1.5, 2.333333, 1e-6);
    near_pt(c, 0.75, 2.475, 2.25, 1e-9);
    near_pt(c, 0, 0, 0, 0);
    near_pt(c, 1, 4, 0, 0);
    pc_curve_release(c);
    /* without derivatives: central differences give the same points */
    c = pc_contour_arc(2, A1, A2, A3, uv_t_t2, 0, NULL, NULL, &st);
    near_pt(c, 0.25, 0.732143, 1.392857, 1e-6);
    pc_curve_release(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ed),            cmocka_unit_test(test_ed_circle),
        cmocka_unit_test(test_ed3),           cmocka_unit_test(test_ceva),
        cmocka_unit_test(test_parabolas),     cmocka_unit_test(test_ellipse),
        cmocka_unit_test(test_tilted),        cmocka_unit_test(test_tilted_scheme),        cmocka_unit_test(test_hyperbola),
        cmocka_unit_test(test_circles),       cmocka_unit_test(test_five_points),
        cmocka_unit_test(test_five_points2),  cmocka_unit_test(test_triples_redundant_reparam),
        cmocka_unit_test(test_sinusoid_cycloid_cones_contour),
        cmocka_unit_test(test_contour_arc),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
