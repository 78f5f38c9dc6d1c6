/* Interpolation curves of Konopatsky's chapter 4 (konop_interp.h, pc_curve_interpolate): the
 * test vectors of the digest konopatsky_ch3_5.md §2 and §6: the book's weights and control
 * points for orders 2-6, the contour arcs of §4.9, the adaptive example of §4.10 and the
 * prototypes of §4.11. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "konop_interp.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

/* the exact weights at t = 3/10 and the nodes (j, y_j) (digest §2.3) */
static void test_weights(void **state) {
    (void)state;
    static const double w2[] = {7.0 / 25, 21.0 / 25, -3.0 / 25};
    static const double w3[] = {77.0 / 2000, 2079.0 / 2000, -189.0 / 2000, 33.0 / 2000};
    static const double w4[] = {-21.0 / 625, 504.0 / 625, 189.0 / 625, -56.0 / 625, 9.0 / 625};
    static const double w5[] = {-7.0 / 256, 105.0 / 256, 105.0 / 128, -35.0 / 128, 21.0 / 256, -3.0 / 256};
    static const double w6[] = {-616.0 / 78125, 8316.0 / 78125, 16632.0 / 15625, -3696.0 / 15625,
                                1512.0 / 15625, -2079.0 / 78125, 264.0 / 78125};
    const double *ws[5] = {w2, w3, w4, w5, w6};
    static const double my[5] = {12.0 / 5, 309.0 / 100, 1486.0 / 625, 251.0 / 256, 33729.0 / 78125};
    const double y[7] = {0, 3, 1, 4, 1, 5, 9};
    for (int n = 2; n <= 6; n++) {
        double w[7], s = 0;
        assert_int_equal(pc_lagrange_weights(n + 1, NULL, 0.3, w), PC_OK);
        for (int j = 0; j <= n; j++) {
            NEAR(w[j], ws[n - 2][j], 1e-14);
            s += w[j];
        }
        NEAR(s, 1, 1e-14);
        double p[14], m[2];
        for (int j = 0; j <= n; j++) p[2 * j] = j, p[2 * j + 1] = y[j];
        int st;
        pc_curve *c = pc_curve_interpolate(2, n + 1, p, NULL, &st);
        assert_int_equal(pc_curve_eval(c, 0.3, m), PC_OK);
        NEAR(m[0], n * 0.3, 1e-12);          /* (4.5): x = n l t + b */
        NEAR(m[1], my[n - 2], 1e-12);
        pc_curve_release(c);
    }
    /* the book's printed forms: (4.17) and the corrected (4.28) at t = 0.37 */
    double t = 0.37, tb = 1 - t, w[7];
    pc_lagrange_weights(4, NULL, t, w);
    NEAR(w[0], tb * (2 - 9 * tb * t) / 2, 1e-14);
    NEAR(w[1], 9 * tb * t * (2 - 3 * t) / 2, 1e-14);
    pc_lagrange_weights(7, NULL, t, w);
    NEAR(w[0], pow(tb, 6) - 8.7 * pow(tb, 5) * t + 22.7 * pow(tb, 4) * t * t - 22.7 * pow(tb * t, 3)
               + 8.7 * tb * tb * pow(t, 4) - tb * pow(t, 5), 1e-13);
    NEAR(w[6], -pow(tb, 5) * t + 8.7 * pow(tb, 4) * t * t - 22.7 * pow(tb * t, 3)
               + 22.7 * tb * tb * pow(t, 4) - 8.7 * tb * pow(t, 5) + pow(t, 6), 1e-13);
    double dup[3] = {0, 0.5, 0.5};
    assert_int_equal(pc_lagrange_weights(3, dup, 0.2, w), PC_ECOINCIDENT);
    assert_int_equal(pc_lagrange_weights(7, NULL, 1e300, w), PC_ENONFINITE);   /* the products overflow */
}

/* the Bezier control points of the interpolation curves: (4.9), §4.4, §4.6, §4.7 */
static void test_controls(void **state) {
    (void)state;
    const double M[7] = {0.3, -1.2, 2.5, 0.7, 4.1, -0.6, 1.9};   /* 1-D nodes */
    int st;
    pc_curve *c = pc_curve_interpolate(1, 3, M, NULL, &st);
    NEAR(c->cp[2], -0.5 * M[0] + 2 * M[1] - 0.5 * M[2], 1e-13);
    pc_curve_release(c);
    c = pc_curve_interpolate(1, 4, M, NULL, &st);
    NEAR(c->cp[2], -5.0 / 6 * M[0] + 3 * M[1] - 1.5 * M[2] + M[3] / 3, 1e-13);
    NEAR(c->cp[4], M[0] / 3 - 1.5 * M[1] + 3 * M[2] - 5.0 / 6 * M[3], 1e-13);
    pc_curve_release(c);
    c = pc_curve_interpolate(1, 6, M, NULL, &st);
    NEAR(c->cp[4], 269.0 / 240 * M[0] - 145.0 / 24 * M[1] + 295.0 / 24 * M[2] - 115.0 / 12 * M[3]
                   + 185.0 / 48 * M[4] - 77.0 / 120 * M[5], 1e-12);
    pc_curve_release(c);
    c = pc_curve_interpolate(1, 7, M, NULL, &st);
    NEAR(c->cp[6], -227.0 / 200 * M[0] + 189.0 / 25 * M[1] - 837.0 / 40 * M[2] + 30 * M[3]
                   - 837.0 / 40 * M[4] + 189.0 / 25 * M[5] - 227.0 / 200 * M[6], 1e-11);
    pc_curve_release(c);
}

/* §4.9: four points and two tangents (degree 5); three points and one tangent (cubic) */
static void test_arc(void **state) {
    (void)state;
    double P[8] = {0, 0, 3, 2, 6, 2, 9, 0}, C2[2] = {0, 2}, C5[2] = {9, 2}, m[2], d[4];
    int st;
    pc_curve *c = pc_interp_arc(2, 4, P, C2, C5, &st);
    assert_int_equal(c->degree, 5);
    for (int j = 0; j < 4; j++) {
        pc_curve_eval(c, j / 3.0, m);
        NEAR(m[0], P[2 * j], 1e-12);
        NEAR(m[1], P[2 * j + 1], 1e-12);
    }
    pc_curve_derivs(c, 0, 1, d);
    NEAR(d[2], 5 * (C2[0] - P[0]), 1e-12);
    NEAR(d[3], 5 * (C2[1] - P[1]), 1e-12);
    pc_curve_derivs(c, 1, 1, d);
    NEAR(d[2], 5 * (P[6] - C5[0]), 1e-12);
    NEAR(d[3], 5 * (P[7] - C5[1]), 1e-12);
    /* the book's final equation of §4.9 at u = 0.4 */
    double u = 0.4, ub = 0.6;
    pc_curve_eval(c, u, m);
    for (int k = 0; k < 2; k++) {
        double v = ub * ub * (ub * ub * ub - 5.25 * ub * u * u + 2.5 * u * u * u) * P[k]
                 + 81.0 / 4 * ub * ub * u * u * (2 - 3 * u) * P[2 + k]
                 + 81.0 / 4 * ub * ub * u * u * (3 * u - 1) * P[4 + k]
                 + u * u * (2.5 * ub * ub * ub - 5.25 * ub * ub * u + u * u * u) * P[6 + k]
                 + 5 * ub * u * (1 - 4.5 * ub * u) * (ub * C2[k] + u * C5[k]);
        NEAR(m[k], v, 1e-12);
    }
    pc_curve_release(c);
    /* one tangent: M = u'(1 - 2u)M1 + 8u^2 u' M2 + u^2(2u - 1)M3 + 3u'u(1 - 2u)C2 */
    c = pc_interp_arc(2, 3, P, C2, NULL, &st);
    assert_int_equal(c->degree, 3);
    pc_curve_eval(c, u, m);
    for (int k = 0; k < 2; k++)
        NEAR(m[k], ub * (1 - 2 * u) * P[k] + 8 * u * u * ub * P[2 + k] + u * u * (2 * u - 1) * P[4 + k]
                   + 3 * ub * u * (1 - 2 * u) * C2[k], 1e-12);
    pc_curve_release(c);
}

/* §4.10 the adaptive example: x = 8.89, 1.11, 0.33; y = 5, 7, 8 */
static void test_adaptive(void **state) {
    (void)state;
    double P[6] = {8.89, 5, 1.11, 7, 0.33, 8}, v[3], m[2];
    assert_int_equal(pc_interp_adaptive_params(2, 3, P, 0, v), PC_OK);
    NEAR(v[1], 0.908878504672897, 1e-14);
    int st;
    pc_curve *uni = pc_curve_interpolate(2, 3, P, NULL, &st);
    pc_curve *ada = pc_curve_interpolate(2, 3, P, v, &st);
    double minx_u = 1e9, minx_a = 1e9, miny_a = 1e9;
    for (int i = 0; i <= 100000; i++) {
        double t = i / 100000.0;
        pc_curve_eval(uni, t, m);
        minx_u = fmin(minx_u, m[0]);
        pc_curve_eval(ada, t, m);
        minx_a = fmin(minx_a, m[0]);
        miny_a = fmin(miny_a, m[1]);
    }
    NEAR(minx_u, -0.19846, 1e-5);       /* the universal curve leaves x > 0 */
    NEAR(minx_a, 0.33, 1e-12);          /* the adaptive one does not */
    NEAR(miny_a, 4.0501, 1e-4);
    /* (4.34) with v2 = 0.91: v'(1 - 1.098v), 12.21 v' v, v(11.111v - 10.111) */
    double p91[3] = {0, 0.91, 1}, w[3], t = 0.6;
    pc_lagrange_weights(3, p91, t, w);
    NEAR(w[0], 0.4 * (1 - 1.0989 * t), 1e-4);
    NEAR(w[1], 12.210 * 0.4 * t, 1e-3);
    NEAR(w[2], t * (11.111 * t - 10.111), 1e-3);
    pc_curve_release(uni);
    pc_curve_release(ada);
    double bad[6] = {0, 0, 2, 0, 1, 0};
    assert_int_equal(pc_interp_adaptive_params(2, 3, bad, 0, v), PC_EDOMAIN);
    char why[200];
    assert_true(pc_interp_adaptive_why(PC_EDOMAIN, 0, why, sizeof why));
    assert_non_null(strstr(why, "advance along axis 1 in their order"));
    double same[6] = {0, 0, 2, 0, 0, 1};
    assert_int_equal(pc_interp_adaptive_params(2, 3, same, 0, v), PC_ECOINCIDENT);
    assert_true(pc_interp_adaptive_why(PC_ECOINCIDENT, 0, why, sizeof why));
    assert_string_equal(why, "the first and last nodes have the same coordinate on axis 1");
    assert_false(pc_interp_adaptive_why(PC_OK, 0, why, sizeof why));
    /* interp.adaptive's entry: the axis counted from 1, the failures as rows */
    pc_why_call why_row;
    assert_int_equal(pc_interp_adaptive(2, 3, same, 3, v, &why_row), PC_EDIM);
    assert_int_equal(why_row.row[0].arg, 2);
    assert_string_equal(why_row.row[0].text, "must be an axis number 1..2, got 3");
    assert_int_equal(pc_interp_adaptive(2, 3, same, 1, v, &why_row), PC_ECOINCIDENT);
    assert_string_equal(why_row.row[0].op, "interp.adaptive");
    assert_string_equal(why_row.row[0].text, "the first and last nodes have the same coordinate on axis 1");
    double ok[6] = {0, 0, 1, 5, 3, 1};
    assert_int_equal(pc_interp_adaptive(2, 3, ok, 1, v, &why_row), PC_OK);
    assert_null(why_row.row[0].op);
    NEAR(v[1], 1.0 / 3, 1e-15);
}

/* §4.11 the prototypes against the book's closed forms */
static void test_prototypes(void **state) {
    (void)state;
    double w[4];
    for (double t = 0.05; t < 1; t += 0.15) {
        double d = 4 * t * t - 4 * t + 2;                     /* (4.35) */
        assert_int_equal(pc_interp_prototype_weights(PC_PROTO_DESARGUES, 4, NULL, t, w), PC_OK);
        NEAR(w[0], (-9 * t * t * t + 18 * t * t - 11 * t + 2) / d, 1e-12);
        NEAR(w[1], (15 * t * t * t - 25 * t * t + 10 * t) / d, 1e-12);
        NEAR(w[2], (-15 * t * t * t + 20 * t * t - 5 * t) / d, 1e-12);
        NEAR(w[3], (9 * t * t * t - 9 * t * t + 2 * t) / d, 1e-12);
        d = 6 * (t * t * t + t * t + t + 1);                  /* (4.37) */
        pc_interp_prototype_weights(PC_PROTO_RATIONAL, 4, NULL, t, w);
        NEAR(w[0], (-27 * t * t * t + 54 * t * t - 33 * t + 6) / d, 1e-12);
        NEAR(w[1], (120 * t * t * t - 200 * t * t + 80 * t) / d, 1e-12);
        NEAR(w[2], (-195 * t * t * t + 260 * t * t - 65 * t) / d, 1e-12);
        NEAR(w[3], (108 * t * t * t - 108 * t * t + 24 * t) / d, 1e-12);
        double tt = t * M_PI;                                  /* (4.40) */
        pc_interp_prototype_weights(PC_PROTO_TRIG, 3, NULL, tt, w);
        NEAR(w[0], cos(tt) / 2 - sin(tt) / 2 + 0.5, 1e-12);
        NEAR(w[1], sin(tt), 1e-12);
        NEAR(w[2], -cos(tt) / 2 - sin(tt) / 2 + 0.5, 1e-12);
        /* (4.39): the exponential weights; the constrained variant sums to 1 */
        double k[3] = {0.5, -1, 2}, e1 = exp(k[0] * t), e2 = exp(k[1] * t), e3 = exp(k[2] * t);
        double D = -exp(k[0] / 2 + k[1]) + exp(k[0] / 2 + k[2]) + exp(k[1] / 2 + k[0])
                   - exp(k[1] / 2 + k[2]) - exp(k[2] / 2 + k[0]) + exp(k[2] / 2 + k[1]);
        pc_interp_prototype_weights(PC_PROTO_EXP, 3, k, t, w);
        NEAR(w[1], (e2 * exp(k[0]) - e1 * exp(k[1]) - e3 * exp(k[0]) + e1 * exp(k[2])
                    + e3 * exp(k[1]) - e2 * exp(k[2])) / D, 1e-12);
        pc_interp_prototype_weights(PC_PROTO_EXP_AFFINE, 3, k, t, w);
        NEAR(w[0] + w[1] + w[2], 1, 1e-12);
    }
    /* cardinal at the nodes, and the curve through them */
    double P[8] = {0, 0, 1, 3, 3, 2, 4, 4}, m[2];
    int st;
    pc_curve *c = pc_interp_prototype(PC_PROTO_RATIONAL, 2, 4, P, NULL, NAN, NAN, &st);
    for (int j = 0; j < 4; j++) {
        pc_curve_eval(c, j / 3.0, m);
        NEAR(m[0], P[2 * j], 1e-12);
        NEAR(m[1], P[2 * j + 1], 1e-12);
    }
    pc_curve_release(c);
    double k[3] = {1, 1, 2};         /* equal exponents: a singular collocation matrix */
    assert_null(pc_interp_prototype(PC_PROTO_EXP, 2, 3, P, k, NAN, NAN, &st));
    assert_int_equal(st, PC_ESINGULAR);
}

/* (4.38) the book's numeric example: x = (16t^2 + 2t + 3)/(4t^2 - 4t + 3),
 * y = (136t^2 - 112t + 30)/(16t^2 - 22t + 15) */
static void test_rational22(void **state) {
    (void)state;
    double P[10] = {1, 2, 2, 1, 4, 1, 6, 3, 7, 6}, co[10], m[2];
    int st;
    pc_curve *c = pc_interp_rational22(2, P, co, &st);
    NEAR(co[0], 16.0 / 3, 1e-10);
    NEAR(co[3], 4.0 / 3, 1e-10);
    NEAR(co[5], 136.0 / 15, 1e-10);
    for (double t = 0; t <= 1; t += 0.125) {
        pc_curve_eval(c, t, m);
        NEAR(m[0], (16 * t * t + 2 * t + 3) / (4 * t * t - 4 * t + 3), 1e-11);
        NEAR(m[1], (136 * t * t - 112 * t + 30) / (16 * t * t - 22 * t + 15), 1e-11);
    }
    pc_curve_release(c);
}

static int exp_g(void *ud, double t, int n, double *g) {       /* (4.39), k = (0.5, -1, 2) */
    (void)ud, (void)n;
    g[0] = exp(0.5 * t), g[1] = exp(-t), g[2] = exp(2 * t);
    return PC_OK;
}
static int trig_g(void *ud, double t, int n, double *g) {      /* (4.40) */
    (void)ud, (void)n;
    g[0] = cos(t), g[1] = 1 - cos(t) - sin(t), g[2] = sin(t);
    return PC_OK;
}
static int bern_g(void *ud, double t, int n, double *g) {      /* (4.6) the quadratic Bezier */
    (void)ud, (void)n;
    g[0] = (1 - t) * (1 - t), g[1] = 2 * t * (1 - t), g[2] = t * t;
    return PC_OK;
}

static void test_membership(void **state) {
    (void)state;
    const double half[3] = {0, 0.5, 1}, trig[3] = {0, M_PI / 2, M_PI};
    double dev;
    assert_int_equal(pc_interp_basis_membership(3, half, bern_g, NULL, 0, 1, 33, &dev), PC_OK);
    assert_true(dev < 1e-14);
    assert_int_equal(pc_interp_basis_membership(3, trig, trig_g, NULL, 0, 2 * M_PI, 33, &dev), PC_OK);
    assert_true(dev < 1e-14);
    /* the exponential prototype: cardinal at 0, 1/2, 1 but its weights do not sum to 1 */
    assert_int_equal(pc_interp_basis_membership(3, half, exp_g, NULL, 0, 1, 33, &dev), PC_OK);
    assert_true(dev > 8e-3 && dev < 9e-3);                    /* 0.00848 (ours) */
    double w[3];
    assert_int_equal(pc_interp_prototype_weights(PC_PROTO_EXP, 3, (double[]){0.5, -1, 2}, 0.25, w), PC_OK);
    assert_true(fabs(w[0] + w[1] + w[2] - 1) > 1e-3);
    const double same[3] = {0, 0.5, 0.5};
    assert_int_equal(pc_interp_basis_membership(3, same, bern_g, NULL, 0, 1, 33, &dev), PC_ESINGULAR);
    assert_int_equal(pc_interp_basis_membership(3, half, bern_g, NULL, 0, 1, 1, &dev), PC_EDOMAIN);
}

static int line_basis(void *ud, double t, int n, double *g) {   /* 1, t */
    (void)ud;
    (void)n;
    g[0] = 1, g[1] = t;
    return PC_OK;
}

/* how many nodes and exponents each prototype takes */
static void test_prototype_shape(void **state) {
    (void)state;
    int n, nk;
    pc_interp_prototype_shape(PC_PROTO_DESARGUES, &n, &nk);
    assert_true(n == 4 && nk == 0);
    pc_interp_prototype_shape(PC_PROTO_RATIONAL, &n, &nk);
    assert_true(n == 4 && nk == 0);
    pc_interp_prototype_shape(PC_PROTO_EXP, &n, &nk);
    assert_true(n == 3 && nk == 3);
    pc_interp_prototype_shape(PC_PROTO_EXP_AFFINE, &n, &nk);
    assert_true(n == 3 && nk == 2);
    pc_interp_prototype_shape(PC_PROTO_TRIG, &n, &nk);
    assert_true(n == 3 && nk == 0);
}

/* the engine's domain: the nodes' range by default, and an empty range refused */
static void test_basis_range(void **state) {
    (void)state;
    const double pts[4] = {0, 0, 2, 4}, params[2] = {0.75, 0.25};
    int st;
    pc_curve *c = pc_interp_basis(2, 2, pts, params, line_basis, NULL, NULL, NAN, NAN, &st);
    assert_non_null(c);
    assert_true(c->t0 == 0.25 && c->t1 == 0.75);
    double m[2];
    assert_int_equal(pc_curve_eval(c, 0.5, m), PC_OK);   /* halfway between the nodes */
    assert_true(fabs(m[0] - 1) < 1e-14 && fabs(m[1] - 2) < 1e-14);
    pc_curve_release(c);
    assert_null(pc_interp_basis(2, 2, pts, params, line_basis, NULL, NULL, 0.5, 0.5, &st));
    assert_int_equal(st, PC_EDOMAIN2);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_weights),    cmocka_unit_test(test_controls),
        cmocka_unit_test(test_arc),        cmocka_unit_test(test_adaptive),
        cmocka_unit_test(test_prototypes), cmocka_unit_test(test_rational22),
        cmocka_unit_test(test_membership), cmocka_unit_test(test_basis_range),
        cmocka_unit_test(test_prototype_shape),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
