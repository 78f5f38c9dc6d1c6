/* The scheme points of §2.1.4 and §2.1.6 (konop_schemes.h) against the digest's vectors
 * (konopatsky_ch1_2.md §5.4: S = (0.25, 0.857143), M(0.25) = (0.3, 0.066667), ...; §5.6: the
 * (2.97) arcs and the closed forms of P and N). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "konop_schemes.h"
#include "conic.h"
#include "oneratio.h"
#include "point.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void pt(const double *h, double x, double y, double tol) {
    NEAR(h[2], 1, 0);
    NEAR(h[0], x, tol);
    NEAR(h[1], y, tol);
}

static void test_ed_scheme(void **state) {
    (void)state;
    const double A[2] = {0, 0}, B[2] = {4, 0}, C[2] = {2, 3};
    double o[PC_ED_NPTS * 3];
    const double ks[3] = {0.3, 0.5, 0.7};
    const double tv[3][3][2] = {{{1.333333, 1.75}, {2, 2.1}, {2.666667, 1.75}},
                                {{1, 1.125}, {2, 1.5}, {3, 1.125}},
                                {{0.727273, 0.613636}, {2, 0.9}, {3.272727, 0.613636}}};
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            double u = 0.25 * (j + 1), k = ks[i];
            int st = pc_conic_ed_scheme(2, A, B, C, k, u, o);
            assert_int_equal(st, PC_OK);
            pt(o + 3 * PC_ED_M, tv[i][j][0], tv[i][j][1], 1e-6);       /* §5.6 TV */
            pt(o + 3 * PC_ED_T1, 2, 0, 0);
            pt(o + 3 * PC_ED_K, 2, 3 * (1 - k), 1e-15);
            pt(o + 3 * PC_ED_T, 4 * u, 0, 1e-15);
            /* P = A u'k/(2uk' + k) + B uk/(2uk' + k) + C 2uk'/(2uk' + k) */
            double den = 2 * u * (1 - k) + k;
            pt(o + 3 * PC_ED_P, (4 * u * k + 2 * 2 * u * (1 - k)) / den, 3 * 2 * u * (1 - k) / den, 1e-12);
            if (j != 1) {   /* N = A u'/(1 - 2u) - B u/(1 - 2u) */
                pt(o + 3 * PC_ED_N, -4 * u / (1 - 2 * u), 0, 1e-12);
            } else {
                NEAR(o[3 * PC_ED_N + 2], 0, 0);                    /* at infinity */
            }
        }
    }
    assert_int_equal(pc_conic_ed_scheme(2, A, B, C, 0, 0.3, o), PC_EDOMAIN);
    const double D[2] = {8, 0};
    assert_int_equal(pc_conic_ed_scheme(2, A, B, D, 0.5, 0.3, o), PC_ECOLLINEAR);
}

static void test_five_scheme(void **state) {
    (void)state;
    const double A[2] = {1, 0}, B[2] = {0, 1}, C[2] = {0, 0}, D[2] = {0.3, 0.8}, E[2] = {0.7, 0.6};
    double o[PC_P5_NPTS * 3];
    assert_int_equal(pc_conic_five_scheme(2, A, B, C, D, E, 0.25, o), PC_OK);
    pt(o + 3 * PC_P5_S, 0.25, 0.857143, 1e-6);
    pt(o + 3 * PC_P5_U, 0.25, 0, 1e-15);
    pt(o + 3 * PC_P5_M, 0.3, 0.066667, 1e-6);
    const double us[4] = {0.5, 0.75, 1.25, 1.5}, xy[4][2] = {{0.531496, 0.094488}, {0.743119, 0.082569},
                                                              {1.569767, -0.348837}, {-8.1, 7.2}};
    for (int i = 0; i < 4; i++) {
        assert_int_equal(pc_conic_five_scheme(2, A, B, C, D, E, us[i], o), PC_OK);
        pt(o + 3 * PC_P5_M, xy[i][0], xy[i][1], 1e-6);
    }
    /* the special points fix the u of B, D, E: u_B = 1.75, u_D = 1.9, u_E = 2.557692308 */
    pt(o + 3 * PC_P5_UB, 1.75, 0, 1e-12);
    pt(o + 3 * PC_P5_UD, 1.9, 0, 1e-12);
    pt(o + 3 * PC_P5_UE, 2.557692308, 0, 1e-9);
    /* R = (B - C)(p_E(q_D - q_E)/(p_E - p_D) + q_E) + C */
    pt(o + 3 * PC_P5_R, 0, 0.7 * 0.2 / 0.4 + 0.6, 1e-12);
    /* M at the curve's u is the curve's point */
    int st;
    pc_curve *c = pc_conic_five_points(2, A, B, C, D, E, 0, 2.6, 0, NULL, &st);
    double m[2];
    pc_curve_eval(c, 0.6, m);
    assert_int_equal(pc_conic_five_scheme(2, A, B, C, D, E, 0.6, o), PC_OK);
    pt(o + 3 * PC_P5_M, m[0], m[1], 1e-12);
    pc_curve_release(c);
}

static void test_smooth_chain(void **state) {
    (void)state;
    /* §3.6 TV: A(0,0,0), B(4,0,0), C(1,3,0), t = 0.3: M_1..M_5 */
    const double A[3] = {0, 0, 0}, B[3] = {4, 0, 0}, C[3] = {1, 3, 0};
    const double tv[5][2] = {{0.78, 1.26}, {0.6683544304, 1.594936709}, {0.6279310345, 1.716206897},
                             {0.6117362956, 1.764791113}, {0.604988026, 1.785035922}};
    double p[15], q[15], m[3];
    for (int n = 1; n <= 5; n++) {
        assert_int_equal(pc_oneratio_smooth_chain(3, A, B, C, n, 0.3, p, q, m), PC_OK);
        NEAR(m[0], tv[n - 1][0], 1e-9);
        NEAR(m[1], tv[n - 1][1], 1e-9);
        NEAR(m[2], 0, 0);
        /* M is oneratio.smooth's point */
        int st;
        pc_curve *c = pc_oneratio_smooth(3, A, B, C, n, &st);
        double x[3];
        pc_curve_eval(c, 0.3, x);
        for (int k = 0; k < 3; k++) NEAR(x[k], m[k], 1e-12);
        pc_curve_release(c);
    }
    /* n = 2, Fig. 3.9: P1 = A t'/(1 - t't) + C t^2/(1 - t't), Q2 = B t/(1 - t't) + C t'^2/(1 - t't) */
    double t = 0.3, tb = 0.7, d = 1 - tb * t;
    pc_oneratio_smooth_chain(3, A, B, C, 2, t, p, q, m);
    for (int k = 0; k < 3; k++) {
        NEAR(p[k], (A[k] * tb + C[k] * t * t) / d, 1e-12);
        NEAR(p[3 + k], (A[k] * tb * tb + C[k] * t) / d, 1e-12);
        NEAR(q[k], (B[k] * t * t + C[k] * tb) / d, 1e-12);
        NEAR(q[3 + k], (B[k] * t + C[k] * tb * tb) / d, 1e-12);
    }
    const double D[3] = {8, 0, 0};
    assert_int_equal(pc_oneratio_smooth_chain(3, A, B, D, 2, t, p, q, m), PC_ECOLLINEAR);
}

static void test_cones_excluded(void **state) {
    (void)state;
    /* f_P = 0.3, f_Q = 0.4 (Table 2.2's kind: hyperbolas): (2.148)'s pole, (2.151)'s two roots
     * ((1 +- 1/sqrt 0.4)/2, the print's sign corrected) and (2.153)'s two, the printed closed
     * form, each a zero of its denominator */
    double fp = 0.3, fq = 0.4, u[5];
    int n;
    assert_int_equal(pc_cones_excluded(fp, fq, u, &n), PC_OK);
    assert_int_equal(n, 5);
    for (int i = 1; i < n; i++) assert_true(u[i] > u[i - 1]);
    double fpb = 1 - fp, fqb = 1 - fq, r = 1 / sqrt(1 - 2 * fp);
    double want[5] = {fq * fpb / (fq * fpb - fp * fqb), (1 - r) / 2, (1 + r) / 2, 0, 0};
    double den = fq * fq * fpb * fpb + fp * fp * fqb * fqb - 2 * fp * fpb * fqb * fqb;
    double num = fpb * (fpb * fq * fq - fp * fqb * fqb), pm = fpb * fp * fqb * sqrt(fqb - fq);
    want[3] = (num - pm) / den;
    want[4] = (num + pm) / den;
    for (int i = 0; i < 5; i++) {
        int found = 0;
        for (int j = 0; j < n; j++) found |= fabs(u[j] - want[i]) <= 1e-12;
        assert_true(found);
    }
    for (int j = 0; j < n; j++) {
        double x = u[j], xb = 1 - x;
        double dp = fp * (1 - 2 * x) * (1 - 2 * x) + 2 * x * xb;
        double dq = fq * fq * fpb * fpb * xb * xb + fp * fp * fqb * fqb * x * x + 2 * (fp - fp * fp) * fqb * fqb * x * xb;
        double dv = fp * fqb * x + fq * fpb * xb;
        assert_true(fabs(dp) < 1e-12 || fabs(dq) < 1e-12 || fabs(dv) < 1e-12);
    }
    /* ellipses (f > 1/2): no ED pole; only (2.148)'s */
    assert_int_equal(pc_cones_excluded(0.6, 0.9, u, &n), PC_OK);
    assert_int_equal(n, 1);
    NEAR(u[0], 0.9 * 0.4 / (0.9 * 0.4 - 0.6 * 0.1), 1e-12);
}

static void test_foci(void **state) {
    (void)state;
    /* the ellipse x^2/9 + y^2/4 = 1 tilted into 3-D: foci at +- sqrt 5 along CA, e = sqrt5/3,
     * p = 4/3; the hyperbola of vertex A and imaginary semi-axis CB: c = sqrt 13 */
    const double C[3] = {1, 1, 1}, A[3] = {1 + 3 * 0.6, 1 + 3 * 0.8, 1}, B[3] = {1, 1, 3};
    double f1[3], f2[3], e, p;
    assert_int_equal(pc_conic_foci(3, C, A, B, 0, f1, f2, &e, &p), PC_OK);
    NEAR(pc_dist(3, C, f1), sqrt(5), 1e-12);
    NEAR(f1[0], 1 + sqrt(5) * 0.6, 1e-12);
    NEAR(f2[1], 1 - sqrt(5) * 0.8, 1e-12);
    NEAR(e, sqrt(5) / 3, 1e-15);
    NEAR(p, 4.0 / 3, 1e-15);
    /* |MF1| + |MF2| = 2a at a point of the ellipse */
    double M[3];
    for (int k = 0; k < 3; k++) M[k] = C[k] + (A[k] - C[k]) * cos(0.7) + (B[k] - C[k]) * sin(0.7);
    NEAR(pc_dist(3, M, f1) + pc_dist(3, M, f2), 6, 1e-12);
    assert_int_equal(pc_conic_foci(3, C, A, B, 1, f1, f2, &e, &p), PC_OK);
    NEAR(pc_dist(3, C, f1), sqrt(13), 1e-12);
    NEAR(e, sqrt(13) / 3, 1e-15);
    /* CB the major axis: the foci move onto it */
    const double B2[3] = {1, 1, 6};
    pc_conic_foci(3, C, A, B2, 0, f1, f2, &e, &p);
    NEAR(f1[2], 1 + 4, 1e-12);                       /* c = sqrt(25 - 9) = 4 along CB */
    const double D[3] = {2, 2, 2};
    assert_int_equal(pc_conic_foci(3, C, A, D, 0, f1, f2, &e, &p), PC_EDOMAIN);
}

static void test_ceva_scheme(void **state) {
    (void)state;
    /* (2.105) digest §5.7: A1(0,0), A2(4,0), A3(2,3) at t = 0.3: k = 0.25 -> (3.294118,
     * 0.871972), k = 1 -> (3.012658, 0.797468); M is (2.104) at t; t = 2/3 at k = 1/4 gives
     * t3 = r = 1/2 (the print's "t3 = 2/3" is t) */
    const double a1[2] = {0, 0}, a2[2] = {4, 0}, a3[2] = {2, 3};
    double o[4], t3, r;
    assert_int_equal(pc_conic_ceva_scheme(2, a1, a2, a3, 0.25, 0.3, o, &t3, &r), PC_OK);
    NEAR(o[2], 3.294118, 1e-6); NEAR(o[3], 0.871972, 1e-6);
    NEAR(o[1], 0, 0);                                   /* M3 on A1A2 */
    int st;
    pc_curve *c = pc_conic_ceva(2, a1, a2, a3, 0.25, &st);
    double x[2];
    pc_curve_eval(c, 0.3, x);
    NEAR(x[0], o[2], 1e-12); NEAR(x[1], o[3], 1e-12);
    pc_curve_release(c);
    pc_conic_ceva_scheme(2, a1, a2, a3, 1, 0.3, o, &t3, &r);
    NEAR(o[2], 3.012658, 1e-6); NEAR(o[3], 0.797468, 1e-6);
    pc_conic_ceva_scheme(2, a1, a2, a3, 0.25, 2.0 / 3, o, &t3, &r);
    NEAR(t3, 0.5, 1e-15); NEAR(r, 0.5, 1e-15);
    NEAR(o[2], 2, 1e-15); NEAR(o[3], 1.5, 1e-15);
    assert_int_equal(pc_conic_ceva_scheme(2, a1, a2, a3, 0, 0.3, o, &t3, &r), PC_EDOMAIN);
}

static void test_focal_forms(void **state) {
    (void)state;
    /* set E (C(0,0), A(4,0), B(0,2)): (2.18)'s TV, and (2.16) with its factor p gives the same
     * coefficients as (2.17) */
    const double C[2] = {0, 0}, A[2] = {4, 0}, B[2] = {0, 2};
    double o[4], pab[2];
    const double phis[4] = {M_PI / 3, M_PI / 2, M_PI, 4}, tv[4][2] = {{-2.582248, 1.527416}, {-3.464102, 1},
                                                                       {-4, 0}, {-3.881479, -0.483249}};
    for (int i = 0; i < 4; i++) {
        assert_int_equal(pc_conic_focal_point(2, C, A, B, 0, phis[i], o, pab), PC_OK);
        NEAR(o[0], tv[i][0], 1e-6); NEAR(o[1], tv[i][1], 1e-6);
        double a = 4, b = 2, c = sqrt(12), e = c / a, p = b * b / a, ph = phis[i];
        double pa16 = p * a * sin(acos(e) - ph) / ((1 - e * cos(ph)) * (a * b + c * b));
        NEAR(pab[0], pa16, 1e-12);                       /* (2.16) = (2.17) */
    }
    NEAR(o[2], -sqrt(12), 1e-12);                        /* F2 = C - (A - C) e */
    /* set H (C(0,0), A(3,0), B(0,2)): (2.56)'s TV by the corrected (2.55) and (2.54) */
    const double AH[2] = {3, 0};
    const double hp[5] = {0, 0.3, M_PI / 2, 2, 5}, htv[5][2] = {{-3, 0}, {-4.991118, -2.659262},
                                                               {3.605551, 1.333333}, {3.235679, 0.808186},
                                                               {4.179406, -1.939923}};
    for (int i = 0; i < 5; i++) {
        assert_int_equal(pc_conic_focal_point(2, C, AH, B, 1, hp[i], o, pab), PC_OK);
        NEAR(o[0], htv[i][0], 1e-6); NEAR(o[1], htv[i][1], 1e-6);
        double a = 3, b = 2, c = sqrt(13), e = c / a, p = b * b / a, ph = hp[i];
        double pa54 = sqrt(b * b + c * c) * p * sin(asin(b / sqrt(b * b + c * c)) + ph) / ((1 - e * cos(ph)) * (a * b - c * b));
        NEAR(pab[0], pa54, 1e-12);                       /* (2.54) corrected = (2.55) corrected */
    }
    assert_int_equal(pc_conic_focal_point(2, C, AH, B, 1, acos(3 / sqrt(13)), o, pab), PC_EPOLE);
    assert_int_equal(pc_conic_focal_point(2, C, B, A, 0, 1, o, pab), PC_EDOMAIN2);   /* CA the minor axis */
    const double skew[2] = {C[0] + 1, C[1] + 1};   /* CA, CB not perpendicular */
    assert_int_equal(pc_conic_focal_point(2, C, AH, skew, 1, 1, o, pab), PC_EDOMAIN);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ed_scheme), cmocka_unit_test(test_five_scheme),
        cmocka_unit_test(test_smooth_chain), cmocka_unit_test(test_cones_excluded),
        cmocka_unit_test(test_foci), cmocka_unit_test(test_ceva_scheme),
        cmocka_unit_test(test_focal_forms),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
