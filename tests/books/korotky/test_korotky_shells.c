/* Korotky (2015): the four-dimensional key construction of the sail (Fig. 1b, B.4, checks
 * C.3 20), the rotational conic sweep (Fig. 3b) and the composite ridge shell (Fig. 3d)
 * (korotky_curves_surfaces.md B.6). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "pencils4.h"
#include "conic_shells.h"
#include "korotky_parts.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_meet_planes4(void **state) {
    (void)state;
    const double O[5] = {0, 0, 0, 0, 1};
    double xy[3][5] = {{0, 0, 0, 0, 1}, {1, 0, 0, 0, 0}, {0, 1, 0, 0, 0}};
    double zt[3][5] = {{0, 0, 0, 0, 1}, {0, 0, 1, 0, 0}, {0, 0, 0, 1, 0}};
    double out[5];
    assert_int_equal(pc_meet_planes4(xy, zt, out), PC_OK);
    for (int m = 0; m < 5; m++) NEAR(out[m], O[m], 1e-15);
    /* span((1, 1, 0, 0), e_z, e_t) meets the xy plane at (1, 1, 0, 0) */
    double q[3][5] = {{1, 1, 0, 0, 1}, {0, 0, 1, 0, 0}, {0, 0, 0, 1, 0}};
    assert_int_equal(pc_meet_planes4(xy, q, out), PC_OK);
    const double want[5] = {1, 1, 0, 0, 1};
    for (int m = 0; m < 5; m++) NEAR(out[m], want[m], 1e-14);
    /* a plane and a plane through its x axis: a common line */
    double r[3][5] = {{0, 0, 0, 0, 1}, {1, 0, 0, 0, 0}, {0, 0, 1, 1, 0}};
    assert_int_equal(pc_meet_planes4(xy, r, out), PC_ESAME_LINE);
    /* a line (a repeated spanning point) that misses the plane */
    double l[3][5] = {{0, 0, 1, 0, 1}, {0, 0, 1, 0, 1}, {0, 0, 0, 1, 0}};
    assert_int_equal(pc_meet_planes4(xy, l, out), PC_ESKEW);
    l[0][0] = NAN;
    assert_int_equal(pc_meet_planes4(xy, l, out), PC_ENONFINITE);
}

/* The sail of Fig. 1b in the digest's reading: the foot AB a parabola cambered in x whose
 * t is its z (so it lies in the plane y = 0, t = z: the plane tau of the text), the luff AC
 * and the leech BC straight in xyt (x and t linear in y) and bowed in z, Z and X the points
 * at infinity of the z and x axes.  Parameters run with the level y, so the delta pencil
 * pairs the points of AC and BC at one level. */
static pc_curve *bez4(const double *a, const double *m, const double *b) {
    double cp[15];
    memcpy(cp, a, 4 * sizeof(double));
    memcpy(cp + 5, m, 4 * sizeof(double));
    memcpy(cp + 10, b, 4 * sizeof(double));
    cp[4] = cp[9] = cp[14] = 1;
    int st;
    return pc_curve_bezier(4, 3, cp, &st);
}

static void test_sail(void **state) {
    (void)state;
    const double A[4] = {0, 0, 0, 0}, B[4] = {0, 0, 4, 4}, C[4] = {0, 6, .3, 2};
    const double mAB[4] = {.8, 0, 2, 2}, mAC[4] = {0, 3, -.2, 1}, mBC[4] = {0, 3, 2.9, 3};
    pc_curve *ab = bez4(A, mAB, B), *ac = bez4(A, mAC, C), *bc = bez4(B, mBC, C);
    pc_pencil_point om[3] = {{NULL, {0, 6, .3, 2, 1}}, {ab, {0}}, {NULL, {0, 0, 1, 0, 0}}};
    pc_pencil_point de[3] = {{NULL, {1, 0, 0, 0, 0}}, {ac, {0}}, {bc, {0}}};
    int st;
    pc_surface *s = pc_surface_two_pencils(om, de, &st);
    assert_non_null(s);
    for (int i = 0; i <= 8; i++)
        for (int j = 0; j <= 8; j++) {
            double u = i / 8.0, v = j / 8.0, S[4], M[4], Pv[4], Qv[4];
            assert_int_equal(pc_surface_eval(s, u, v, S), PC_OK);
            pc_curve_eval(ab, u, M);
            pc_curve_eval(ac, v, Pv);
            pc_curve_eval(bc, v, Qv);
            /* the key: lambda from the level y on the ruling C M, beta from t on the chord
             * P Q; x from the ruling, z from the chord (B.4 step 4) */
            double lam = (C[1] - Pv[1]) / (C[1] - M[1]);
            double t = C[3] + lam * (M[3] - C[3]);
            double beta = (t - Pv[3]) / (Qv[3] - Pv[3]);
            NEAR(S[0], C[0] + lam * (M[0] - C[0]), 1e-12);
            NEAR(S[1], Pv[1], 1e-12);
            if (j < 8) NEAR(S[2], Pv[2] + beta * (Qv[2] - Pv[2]), 1e-12);   /* P = Q = C at v = 1 */
            NEAR(S[3], t, 1e-12);
            /* in xyt the sail is the cone with vertex C and directrix AB: S on the line C M */
            double cr[3] = {(S[1] - C[1]) * (M[3] - C[3]) - (S[3] - C[3]) * (M[1] - C[1]),
                            (S[3] - C[3]) * (M[0] - C[0]) - (S[0] - C[0]) * (M[3] - C[3]),
                            (S[0] - C[0]) * (M[1] - C[1]) - (S[1] - C[1]) * (M[0] - C[0])};
            NEAR(cr[0], 0, 1e-12);
            NEAR(cr[1], 0, 1e-12);
            NEAR(cr[2], 0, 1e-12);
            /* the contour: the foot at v = 0, the luff at u = 0, the leech at u = 1 */
            if (j == 0)
                for (int k = 0; k < 4; k++) NEAR(S[k], M[k], 1e-12);
            if (i == 0)
                for (int k = 0; k < 4; k++) NEAR(S[k], Pv[k], 1e-12);
            if (i == 8)
                for (int k = 0; k < 4; k++) NEAR(S[k], Qv[k], 1e-12);
        }
    /* the head: delta(1) is the line X C, which meets every omega plane in C */
    double S[4];
    assert_int_equal(pc_surface_eval(s, .3, 1, S), PC_OK);
    for (int k = 0; k < 4; k++) NEAR(S[k], C[k], 1e-12);
    /* the xyz projection is an ordinary 3-D surface (a map from 4-D to 3-D dropping t) */
    pc_map drop;
    const double m[4 * 5] = {1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1};
    assert_int_equal(pc_map_from_matrix(&drop, 4, 3, m, 0), PC_OK);
    pc_surface *s3 = pc_surface_map(s, &drop, &st);
    assert_non_null(s3);
    double S3[3];
    pc_surface_eval(s, .5, .5, S);
    assert_int_equal(pc_surface_eval(s3, .5, .5, S3), PC_OK);
    for (int k = 0; k < 3; k++) NEAR(S3[k], S[k], 1e-12);
    pc_surface_release(s3);
    pc_surface_release(s);
    /* delta planes through the omega axis C Z share a line with every omega plane: no
     * single meet (B.4 step 5: the singular points are reported, not returned) */
    pc_pencil_point de2[3] = {{NULL, {0, 6, .3, 2, 1}}, {NULL, {0, 0, 1, 0, 0}}, {ac, {0}}};
    s = pc_surface_two_pencils(om, de2, &st);
    assert_non_null(s);
    assert_int_equal(pc_surface_eval(s, .5, .5, S), PC_ESAME_LINE);
    pc_surface_release(s);
    /* a 3-D curve is refused */
    double c3[9] = {0, 0, 0, 1, 1, 0, 0, 1, 2};
    pc_curve *bad = pc_curve_bezier(2, 3, c3, &st);
    pc_pencil_point om2[3] = {{NULL, {0, 6, .3, 2, 1}}, {bad, {0}}, {NULL, {0, 0, 1, 0, 0}}};
    assert_null(pc_surface_two_pencils(om2, de, &st));
    assert_int_equal(st, PC_EDIM);
    /* checked: the sail is made, the pencils sharing a line at the centre refused there */
    int meet;
    s = pc_surface_two_pencils_checked(om, de, &st, &meet);
    assert_non_null(s);
    assert_int_equal(meet, PC_OK);
    assert_int_equal(pc_surface_eval(s, .5, 1, S), PC_OK);
    for (int k = 0; k < 4; k++) NEAR(S[k], C[k], 1e-12);
    pc_surface_release(s);
    assert_null(pc_surface_two_pencils_checked(om, de2, &st, &meet));
    assert_int_equal(meet, PC_ESAME_LINE);
    assert_int_equal(st, PC_ESAME_LINE);
    assert_null(pc_surface_two_pencils_checked(om2, de, &st, &meet));
    assert_int_equal(meet, PC_OK);
    assert_int_equal(st, PC_EDIM);
    pc_curve_release(bad);
    pc_curve_release(ab);
    pc_curve_release(ac);
    pc_curve_release(bc);
}

/* A 3-D curve through three points as a quadratic Bezier passing through the middle one at
 * parameter 1/2. */
static pc_curve *through3(const double *a, const double *m, const double *b) {
    double cp[12];
    for (int k = 0; k < 3; k++) {
        cp[k] = a[k];
        cp[4 + k] = 2 * m[k] - (a[k] + b[k]) / 2;
        cp[8 + k] = b[k];
    }
    cp[3] = cp[7] = cp[11] = 1;
    int st;
    return pc_curve_bezier(3, 3, cp, &st);
}

static void test_revolve(void **state) {
    (void)state;
    /* tangent planes at A and B perpendicular to AB and a semicircular ridge of radius 2:
     * every generator is the half circle of radius 2 about the midpoint: a sphere */
    const double A[3] = {0, -2, 0}, B[3] = {0, 2, 0}, n[3] = {0, 1, 0};
    double cp[3 * 4] = {2, 0, 0, 1, 0, 0, 2, 0, -2, 0, 0, 1};   /* x = 2 -> z -> x = -2 */
    int st;
    pc_curve *ridge = pc_curve_bezier(3, 3, cp, &st);
    pc_surface *s = pc_surface_conic_revolve(A, B, n, n, ridge, NULL, &st);
    assert_non_null(s);
    for (int i = 0; i <= 8; i++)
        for (int j = 0; j <= 8; j++) {
            double S[3];
            assert_int_equal(pc_surface_eval(s, i / 8.0, j / 8.0, S), PC_OK);
            NEAR(S[0] * S[0] + S[1] * S[1] + S[2] * S[2], 4, 1e-12);
        }
    pc_surface_release(s);
    pc_curve_release(ridge);
    /* the same over an elliptic ridge (x = 3 cos, z = 1.5 sin): each generator a half
     * ellipse with semi-axes 2 along AB and |T| across, y^2/4 + r^2/|T|^2 = 1 */
    const double T0[3] = {3, 0, 0}, Tm[3] = {3 * sqrt(.5), 0, 1.5 * sqrt(.5)}, T1[3] = {-3, 0, 0};
    ridge = through3(T0, Tm, T1);
    /* tilted tangent planes: the generators lean inward at A and B */
    const double nA[3] = {0, 1, -.5}, nB[3] = {0, 1, .5};
    s = pc_surface_conic_revolve(A, B, nA, nB, ridge, NULL, &st);
    assert_non_null(s);
    for (int i = 0; i <= 8; i++) {
        double u = i / 8.0, T[3], S0[3], S1[3], S2[3];
        pc_curve_eval(ridge, u, T);
        assert_int_equal(pc_surface_eval(s, u, 0, S0), PC_OK);
        for (int k = 0; k < 3; k++) NEAR(S0[k], A[k], 1e-12);
        pc_surface_eval(s, u, 1, S0);
        for (int k = 0; k < 3; k++) NEAR(S0[k], B[k], 1e-12);
        /* the generator lies in the plane A, B, T and its tangent at A in pi_A */
        double nPi[3] = {-T[2], 0, T[0]};   /* (B - A) x (T - A) / 4 */
        pc_surface_eval(s, u, 1e-6, S1);
        pc_surface_eval(s, u, .37, S2);
        NEAR((S2[0] - A[0]) * nPi[0] + (S2[1] - A[1]) * nPi[1] + (S2[2] - A[2]) * nPi[2], 0, 1e-12);
        double d[3] = {S1[0] - A[0], S1[1] - A[1], S1[2] - A[2]};
        double dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        NEAR((d[0] * nA[0] + d[1] * nA[1] + d[2] * nA[2]) / dl, 0, 1e-5);
    }
    pc_surface_release(s);
    /* perpendicular tangent planes over the same ridge: the half ellipses */
    s = pc_surface_conic_revolve(A, B, n, n, ridge, NULL, &st);
    for (int i = 0; i <= 8; i++)
        for (int j = 0; j <= 8; j++) {
            double u = i / 8.0, T[3], S[3];
            pc_curve_eval(ridge, u, T);
            pc_surface_eval(s, u, j / 8.0, S);
            double r2 = S[0] * S[0] + S[2] * S[2], t2 = T[0] * T[0] + T[2] * T[2];
            NEAR(S[1] * S[1] / 4 + r2 / t2, 1, 1e-12);
        }
    pc_surface_release(s);
    /* errors: a ridge through the axis, a tangent plane holding AB, a 2-D ridge */
    const double Q0[3] = {0, 0, 0}, Q1[3] = {0, 1, 1}, Q2[3] = {1, 0, 1};
    pc_curve *through_axis = through3(Q0, Q1, Q2);
    double bad_u = -1;
    assert_null(pc_surface_conic_revolve(A, B, n, n, through_axis, &bad_u, &st));
    assert_int_equal(st, PC_ECOLLINEAR);
    NEAR(bad_u, 0, 0);
    pc_why_call w;   /* explained with the u where it failed */
    assert_null(pc_conic_revolve_explained(A, B, n, n, through_axis, &st, &w));
    assert_int_equal(st, PC_ECOLLINEAR);
    assert_string_equal(w.row[0].text, "the ridge point lies on the axis AB at u = 0");
    s = pc_conic_revolve_explained(A, B, n, n, ridge, &st, &w);
    assert_non_null(s);
    pc_surface_release(s);
    assert_int_equal(pc_sweep_explain(1, PC_EDOMAIN, 0.25, &w), PC_EDOMAIN);
    assert_string_equal(w.row[0].op, "korotky.ridge_shell");
    assert_string_equal(w.row[0].text, "no conic arc of the profile at u = 0.25 (a T must lie between the tangent lines)");
    pc_sweep_explain(0, PC_ESKEW, 0.5, &w);
    assert_string_equal(w.row[0].op, "korotky.conic_sweep");
    assert_non_null(strstr(w.row[0].text, "at u = 0.5 ("));
    pc_sweep_explain(0, PC_ENOMEM, 0.5, &w);
    assert_null(w.row[0].op);
    const double flat[3] = {0, 0, 1};
    assert_null(pc_surface_conic_revolve(A, B, flat, n, ridge, &bad_u, &st));
    assert_int_equal(st, PC_EDOMAIN);
    const double zero[3] = {0, 0, 0};
    assert_null(pc_surface_conic_revolve(A, B, zero, n, ridge, NULL, &st));
    assert_int_equal(st, PC_EZERO);
    assert_null(pc_surface_conic_revolve(A, A, n, n, ridge, NULL, &st));
    assert_int_equal(st, PC_ECOINCIDENT);
    pc_curve_release(through_axis);
    pc_curve_release(ridge);
}

/* A constant 3-D curve: the point (w = 1) or direction (w = 0) h. */
static pc_curve *constant(double x, double y, double z, double w) {
    double cp[8] = {x, y, z, w, x, y, z, w};
    int st;
    return pc_curve_bezier(3, 2, cp, &st);
}

static pc_curve *segment(const double *a, const double *b) {
    double cp[8] = {a[0], a[1], a[2], 1, b[0], b[1], b[2], 1};
    int st;
    return pc_curve_bezier(3, 2, cp, &st);
}

static void test_ridge_shell(void **state) {
    (void)state;
    /* profiles x = const from 0 to 4: a quarter ellipse from U = (x, -2, 0) (vertical tangent)
     * up to the ridge R = (x, 0, 1.5) (horizontal tangent along y), then the straight segment
     * from R down to V = (x, 2, 0) (T2 on the chord: the crease of Fig. 3d) */
    const double c = sqrt(.5);
    const double U0[3] = {0, -2, 0}, U1[3] = {4, -2, 0}, R0[3] = {0, 0, 1.5}, R1[3] = {4, 0, 1.5};
    const double V0[3] = {0, 2, 0}, V1[3] = {4, 2, 0};
    const double T10[3] = {0, -2 * c, 1.5 * c}, T11[3] = {4, -2 * c, 1.5 * c};
    const double T20[3] = {0, 1, .75}, T21[3] = {4, 1, .75};
    pc_ridge_shell g = {segment(U0, U1), segment(R0, R1), segment(V0, V1), segment(T10, T11),
                        segment(T20, T21), constant(0, 0, 1, 0), constant(0, 1, 0, 0),
                        constant(0, 0, 1, 0)};
    int st;
    pc_surface *s = pc_surface_ridge_shell(&g, NULL, &st);
    assert_non_null(s);
    NEAR(s->v1, 2, 0);
    for (int i = 0; i <= 4; i++)
        for (int j = 0; j <= 16; j++) {
            double u = i / 4.0, v = j / 8.0, S[3];
            assert_int_equal(pc_surface_eval(s, u, v, S), PC_OK);
            NEAR(S[0], 4 * u, 1e-12);
            if (v <= 1) NEAR(S[1] * S[1] / 4 + S[2] * S[2] / 2.25, 1, 1e-12);   /* the ellipse */
            else NEAR(S[2], .75 * (2 - S[1]), 1e-12);                              /* the segment */
        }
    /* G1 across the ridge: both arcs arrive along H = (0, 1, 0) at v = 1 */
    double a[3], b[3], m[3];
    pc_surface_eval(s, .5, 1, m);
    pc_surface_eval(s, .5, 1 - 1e-7, a);
    pc_surface_eval(s, .5, 1.01, b);   /* a segment of weight 0 starts at zero speed */
    NEAR(m[1], 0, 1e-12);
    NEAR(m[2], 1.5, 1e-12);
    NEAR((m[2] - a[2]) / (m[1] - a[1]), 0, 1e-6);   /* horizontal from the left */
    /* from the right the segment falls at slope -0.75: a crease, as the text's SL */
    NEAR((b[2] - m[2]) / (b[1] - m[1]), -.75, 1e-6);
    pc_surface_release(s);
    /* a T2 beyond the tangent lines: no conic, the u named */
    pc_curve *t2 = g.T2;
    const double bad0[3] = {0, 3, 3}, bad1[3] = {4, 3, 3};
    g.T2 = segment(bad0, bad1);
    double bad_u = -1;
    assert_null(pc_surface_ridge_shell(&g, &bad_u, &st));
    assert_int_equal(st, PC_EDOMAIN);
    NEAR(bad_u, 0, 0);
    pc_curve_release(g.T2);
    g.T2 = t2;
    pc_curve **all = &g.U;
    for (int i = 0; i < 8; i++) pc_curve_release(all[i]);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_meet_planes4), cmocka_unit_test(test_sail),
        cmocka_unit_test(test_revolve),      cmocka_unit_test(test_ridge_shell),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
