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

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ed_scheme), cmocka_unit_test(test_five_scheme),
        cmocka_unit_test(test_smooth_chain),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
