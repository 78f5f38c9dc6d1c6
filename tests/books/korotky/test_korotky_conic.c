/* The conic of an arc with its centre, axes and asymptotes (Korotky 2015, Fig. 2c) and
 * graphical differentiation (Korotky & Vitovtov 2021, ref. [11]): korotky_curves_surfaces.md
 * B.3 and the checks C.3 13-15 and 12a. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "conic_props.h"
#include "conic_surface.h"
#include "ferguson.h"
#include "graphdiff.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

/* The conic of the arc U, tU, V, tV, T: its coefficients, checked on the arc's points and
 * tangent lines (the five conditions of B.3 step 5's general route). */
static void arc_conic(const double *U, const double *tU, const double *V, const double *tV,
                      const double *T, double coef[6], pc_conic_elements *el) {
    double cp[9], w;
    assert_int_equal(pc_conic_arc_cp(2, U, tU, V, tV, T, cp, &w), PC_OK);
    assert_int_equal(pc_conic_from_arc(cp, coef), PC_OK);
    int st;
    pc_curve *c = pc_conic_arc(2, U, tU, V, tV, T, &w, &st);
    for (int i = 0; i <= 16; i++) {
        double p[2];
        pc_curve_eval(c, i / 16.0, p);
        NEAR(pc_conic_value(coef, p[0], p[1]), 0, 1e-12);
    }
    pc_curve_release(c);
    NEAR(pc_conic_value(coef, T[0], T[1]), 0, 1e-12);
    /* the gradient at U is normal to tU, at V to tV */
    const double *X[2] = {U, V}, *t[2] = {tU, tV};
    for (int k = 0; k < 2; k++) {
        double gx = 2 * coef[0] * X[k][0] + coef[1] * X[k][1] + coef[3];
        double gy = coef[1] * X[k][0] + 2 * coef[2] * X[k][1] + coef[4];
        NEAR(gx * t[k][0] + gy * t[k][1], 0, 1e-12);
    }
    assert_int_equal(pc_conic_elements_of(coef, el), PC_OK);
}

static void test_quarter_circle(void **state) {
    (void)state;
    /* C.3 13: Q proportional to diag(1, 1, -1), centre (0, 0), a circle of radius 1 */
    const double U[2] = {1, 0}, tU[2] = {0, 1}, V[2] = {0, 1}, tV[2] = {-1, 0};
    const double T[2] = {sqrt(.5), sqrt(.5)};
    double q[6];
    pc_conic_elements el;
    arc_conic(U, tU, V, tV, T, q, &el);
    NEAR(q[0], q[2], 1e-12);
    NEAR(q[5], -q[0], 1e-12);
    NEAR(q[1], 0, 1e-12);
    NEAR(q[3], 0, 1e-12);
    NEAR(q[4], 0, 1e-12);
    assert_int_equal(el.kind, PC_CONIC_ELLIPSE);
    NEAR(el.center[0], 0, 1e-12);
    NEAR(el.center[1], 0, 1e-12);
    NEAR(el.semi[0], 1, 1e-12);
    NEAR(el.semi[1], 1, 1e-12);
    assert_int_equal(el.nasym, 0);
}

static void test_parallel_tangents(void **state) {
    (void)state;
    /* C.3 14: W at infinity; the ellipse (x - 1)^2 + 4 y^2 = 1 */
    const double U[2] = {0, 0}, V[2] = {2, 0}, t[2] = {0, 1}, T[2] = {1, .5};
    double q[6];
    pc_conic_elements el;
    arc_conic(U, t, V, t, T, q, &el);
    NEAR(q[2] / q[0], 4, 1e-12);
    NEAR(q[3] / q[0], -2, 1e-12);
    NEAR(q[5], 0, 1e-12);
    NEAR(el.center[0], 1, 1e-12);
    NEAR(el.center[1], 0, 1e-12);
    NEAR(el.semi[0], 1, 1e-12);     /* the major axis along x */
    NEAR(fabs(el.axis[0][0]), 1, 1e-12);
    NEAR(el.semi[1], .5, 1e-12);
}

static void test_hyperbola(void **state) {
    (void)state;
    /* C.3 15: w = 3 + 2 sqrt 3 = 6.4641.  In the barycentric coordinates of U, W, V the arc
     * is beta^2 = 4 w^2 alpha gamma, which here reads k (eta - eta0)^2 - w^2 (x - 1)^2 = w^2/k
     * with eta = y / sqrt 3, k = w^2 - 1, eta0 = w^2 / k: the centre (1, sqrt 3 w^2/k) =
     * (1, 1.774519), the transverse semi-axis sqrt 3 w / k = 0.274519 along y, the conjugate
     * 1 / sqrt k = 0.156586, asymptote slopes +-sqrt 3 w / sqrt k = +-1.753156. */
    const double s3 = sqrt(3), U[2] = {0, 0}, V[2] = {2, 0}, tU[2] = {1, s3}, tV[2] = {-1, s3};
    const double T[2] = {1, 1.5};
    double q[6];
    pc_conic_elements el;
    arc_conic(U, tU, V, tV, T, q, &el);
    double w = 3 + 2 * s3, k = w * w - 1;
    assert_int_equal(el.kind, PC_CONIC_HYPERBOLA);
    NEAR(el.center[0], 1, 1e-12);
    NEAR(el.center[1], s3 * w * w / k, 1e-12);
    NEAR(el.center[1], 1.774519, 1e-6);
    NEAR(el.semi[0], s3 * w / k, 1e-12);
    NEAR(fabs(el.axis[0][1]), 1, 1e-12);
    NEAR(el.semi[1], 1 / sqrt(k), 1e-12);
    assert_int_equal(el.nasym, 2);
    double m0 = el.asym[0][1] / el.asym[0][0], m1 = el.asym[1][1] / el.asym[1][0];
    NEAR(fmax(m0, m1), s3 * w / sqrt(k), 1e-12);
    NEAR(fmin(m0, m1), -s3 * w / sqrt(k), 1e-12);
    NEAR(fmax(m0, m1), 1.753156, 1e-6);
    /* an asymptote direction nulls the quadratic part */
    for (int s = 0; s < 2; s++) {
        double x = el.asym[s][0], y = el.asym[s][1];
        NEAR(q[0] * x * x + q[1] * x * y + q[2] * y * y, 0, 1e-12);
    }
    /* the parabola: w = 1 (T at the midpoint of the median from W), no centre */
    const double Tp[2] = {1, s3 / 2};
    double cp[9], wp;
    assert_int_equal(pc_conic_arc_cp(2, U, tU, V, tV, Tp, cp, &wp), PC_OK);
    NEAR(wp, 1, 1e-12);
    assert_int_equal(pc_conic_from_arc(cp, q), PC_OK);
    assert_int_equal(pc_conic_elements_of(q, &el), PC_OK);
    assert_int_equal(el.kind, PC_CONIC_PARABOLA);
    assert_int_equal(el.central, 0);
    NEAR(fabs(el.axis[0][1]), 1, 1e-9);   /* the axis of symmetry x = 1 is vertical */
}

static void test_conic_errors(void **state) {
    (void)state;
    /* T on the chord: w = 0, the straight generator: no conic to measure */
    const double U[2] = {0, 0}, V[2] = {2, 0}, tU[2] = {1, 1}, tV[2] = {-1, 1}, T[2] = {1, 0};
    double cp[9], w, q[6];
    assert_int_equal(pc_conic_arc_cp(2, U, tU, V, tV, T, cp, &w), PC_OK);
    NEAR(w, 0, 1e-15);
    assert_int_equal(pc_conic_from_arc(cp, q), PC_ECOLLINEAR);
    cp[0] = NAN;
    assert_int_equal(pc_conic_from_arc(cp, q), PC_ENONFINITE);
    pc_conic_elements el;
    const double none[6] = {0, 0, 0, 1, 1, 1}, pair[6] = {1, 0, -1, 0, 0, 0};
    const double empty[6] = {1, 0, 1, 0, 0, 1};
    assert_int_equal(pc_conic_elements_of(none, &el), PC_EDOMAIN);
    assert_int_equal(pc_conic_elements_of(pair, &el), PC_EDOMAIN);    /* x^2 = y^2: two lines */
    assert_int_equal(pc_conic_elements_of(empty, &el), PC_EDOMAIN);   /* no real points */
}

/* C.3 12a: the polynomial spline (7) sampled every 0.01 in x gives back its knot slopes
 * 1.2174, 2.2319, 2.0329, -2.0516, -2.2742 (one-sided at A and E) */
static void test_graphical_slope(void **state) {
    (void)state;
    const double X[5] = {1.2, 2.1, 2.8, 5, 5.5}, Y[5] = {.9, 2.3, 4, 3.2, 2.1};
    double coef[16];
    assert_int_equal(pc_poly_spline(5, X, Y, PC_END_NATURAL, 0, 0, coef, NULL), PC_OK);
    enum { N = 431 };
    static double xy[2 * N];
    for (int i = 0; i < N; i++) {
        double x = 1.2 + i * 0.01;
        if (i == N - 1) x = 5.5;
        int s = x < 2.1 ? 0 : x < 2.8 ? 1 : x < 5 ? 2 : 3;
        double d = x - X[s];
        const double *k = coef + 4 * s;
        xy[2 * i] = x;
        xy[2 * i + 1] = k[0] + d * (k[1] + d * (k[2] + d * k[3]));
    }
    const double want[5] = {1.2174, 2.2319, 2.0329, -2.0516, -2.2742};
    for (int i = 0; i < 5; i++) {
        double m;
        assert_int_equal(pc_graphical_slope(N, xy, X[i], 7, &m), PC_OK);
        NEAR(m, want[i], 2e-3);
    }
    /* exact for a parabola anywhere, ends included */
    double par[2 * 9];
    for (int i = 0; i < 9; i++) {
        par[2 * i] = i * .25;
        par[2 * i + 1] = 3 * par[2 * i] * par[2 * i] - par[2 * i] + 1;
    }
    double m;
    for (double x = 0; x <= 2; x += .3) {
        assert_int_equal(pc_graphical_slope(9, par, x, 5, &m), PC_OK);
        NEAR(m, 6 * x - 1, 1e-12);
    }
    /* errors */
    assert_int_equal(pc_graphical_slope(9, par, 2.5, 5, &m), PC_EDOMAIN);
    assert_int_equal(pc_graphical_slope(9, par, 1, 11, &m), PC_EDIM);
    assert_int_equal(pc_graphical_slope(2, par, 0, 3, &m), PC_EDIM);
    par[4] = par[2];
    assert_int_equal(pc_graphical_slope(9, par, 1, 5, &m), PC_EDOMAIN);
    assert_int_equal(pc_graphical_slope(9, par, NAN, 5, &m), PC_ENONFINITE);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_quarter_circle), cmocka_unit_test(test_parallel_tangents),
        cmocka_unit_test(test_hyperbola),      cmocka_unit_test(test_conic_errors),
        cmocka_unit_test(test_graphical_slope),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
