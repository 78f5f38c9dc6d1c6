/* The textbook's constructions of curves and surfaces (buimov.h): the knot vectors of Buimov
 * §4.4 (printed, corrected and derived: digest 9.2 #29), the k = 2 basis table (#30), the
 * book's B-spline against the Bezier curve and the local-control example of Fig 4.9 (#31,
 * #32), Bernstein and Hermite functions (#27, #28), cubic splines with the four kinds of ends
 * and both parameterisations (#25, #26: tangents, coefficients, C2 joints, end conditions,
 * agreement with pc_curve_cubic_spline), the helix, and the sphere's corner table (#33). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "buimov.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))
static const double PI = 3.14159265358979323846;

static void knots_is(int ncp, const double *p, int k, const double *want) {
    double q[64];
    assert_int_equal(pc_book_knots(2, ncp, p, k, q), PC_OK);
    for (int j = 0; j < ncp + k; j++) NEAR(q[j], want[j], 0);
}

static void knot_vectors(void **st) {
    (void)st;
    double p5[10] = {0, 0, 1, 2, 3, 1, 4, 2, 5, 0};            /* n = 4: 5 distinct vertices */
    knots_is(5, p5, 2, (double[]){0, 0, 1, 2, 3, 4, 4});
    knots_is(5, p5, 3, (double[]){0, 0, 0, 1, 2, 3, 3, 3});
    knots_is(4, p5, 2, (double[]){0, 0, 1, 2, 3, 3});
    knots_is(4, p5, 4, (double[]){0, 0, 0, 0, 1, 1, 1, 1});     /* k = n + 1: Bezier */
    /* P1 double: the book prints [0 0 1 1 2 2 3 3 4 4] (10 knots for 6 vertices) */
    double pd[12] = {0, 0, 1, 2, 1, 2, 3, 1, 4, 2, 5, 0};
    knots_is(6, pd, 2, (double[]){0, 0, 1, 1, 2, 3, 4, 4});
    knots_is(6, pd, 3, (double[]){0, 0, 0, 1, 1, 2, 3, 3, 3});  /* "n = 3" is k = 3 */
    double q[16];
    assert_int_equal(pc_book_knots(2, 4, p5, 5, q), PC_EDOMAIN);
    assert_int_equal(pc_book_knots(2, 4, p5, 1, q), PC_EDOMAIN);
}

/* the k = 2 table on [0 0 1 2 3 3]: N02 .. N32 at t = 0, 0.5, ..., 3 (t_max closed) */
static void basis_table(void **st) {
    (void)st;
    double q[6] = {0, 0, 1, 2, 3, 3}, N;
    double want[7][4] = {{1, 0, 0, 0}, {.5, .5, 0, 0}, {0, 1, 0, 0}, {0, .5, .5, 0},
                         {0, 0, 1, 0}, {0, 0, .5, .5}, {0, 0, 0, 1}};
    for (int r = 0; r < 7; r++)
        for (int i = 0; i < 4; i++) {
            assert_int_equal(pc_book_basis(q, 6, i, 2, r * 0.5, &N), PC_OK);
            NEAR(N, want[r][i], 1e-15);
        }
    /* a partition of unity for k = 4 with a double knot, and local support */
    double q4[11] = {0, 0, 0, 0, 1, 1, 2, 3, 3, 3, 3};
    for (double t = 0; t <= 3; t += 0.125) {
        double s = 0;
        for (int i = 0; i < 7; i++) { assert_int_equal(pc_book_basis(q4, 11, i, 4, t, &N), PC_OK); s += N; }
        NEAR(s, 1, 1e-14);
        assert_int_equal(pc_book_basis(q4, 11, 6, 4, t, &N), PC_OK);
        if (t < 2) NEAR(N, 0, 0);                              /* N_6,4 lives on [2, 3] */
    }
    assert_int_equal(pc_book_basis(q, 6, 4, 2, 1, &N), PC_EDOMAIN);
    assert_int_equal(pc_book_basis(q, 6, -1, 2, 1, &N), PC_EDOMAIN);
}

static void eval2(const pc_curve *c, double t, double *x) { assert_int_equal(pc_curve_eval(c, t, x), PC_OK); }

static void book_bspline(void **st) {
    (void)st;
    int s;
    double p[8] = {1, 1, 2, 3, 4, 3, 3, 1}, x[2], y[2];
    /* k = 4 on 4 points is the cubic Bezier of #28 */
    pc_curve *b4 = pc_curve_book_bspline(2, 4, p, 4, &s);
    double h[12];
    for (int i = 0; i < 4; i++) { h[3 * i] = p[2 * i]; h[3 * i + 1] = p[2 * i + 1]; h[3 * i + 2] = 1; }
    pc_curve *bz = pc_curve_bezier(2, 4, h, &s);
    for (double t = 0; t <= 1; t += 0.05) {
        eval2(b4, t, x); eval2(bz, t, y);
        NEAR(x[0], y[0], 1e-14); NEAR(x[1], y[1], 1e-14);
    }
    eval2(bz, 0.5, x); NEAR(x[0], 2.75, 1e-15); NEAR(x[1], 2.5, 1e-15);
    eval2(bz, 0.15, x); NEAR(x[0], 1.504, 5e-4); NEAR(x[1], 1.765, 5e-4);
    eval2(bz, 0.85, x); NEAR(x[0], 3.261, 5e-4); NEAR(x[1], 1.765, 5e-4);
    double d[4];
    assert_int_equal(pc_curve_derivs(bz, 0, 1, d), PC_OK); NEAR(d[2], 3, 1e-14); NEAR(d[3], 6, 1e-14);
    assert_int_equal(pc_curve_derivs(bz, 1, 1, d), PC_OK); NEAR(d[2], -3, 1e-14); NEAR(d[3], -6, 1e-14);
    pc_curve_release(b4);
    pc_curve_release(bz);
    /* k = 3: knots [0 0 0 1 2 2 2]; P(0.5) = (2, 2.5) with weights (.25, .625, .125, 0) */
    pc_curve *b3 = pc_curve_book_bspline(2, 4, p, 3, &s);
    NEAR(b3->t1, 2, 0);
    eval2(b3, 0.5, x); NEAR(x[0], 2, 1e-15); NEAR(x[1], 2.5, 1e-15);
    eval2(b3, 1, x); NEAR(x[0], 3, 1e-15); NEAR(x[1], 3, 1e-15);
    eval2(b3, 1.5, x); NEAR(x[0], 3.5, 1e-15); NEAR(x[1], 2.5, 1e-15);
    double q[7] = {0, 0, 0, 1, 2, 2, 2}, w[4] = {.25, .625, .125, 0}, N;
    for (int i = 0; i < 4; i++) { pc_book_basis(q, 7, i, 3, 0.5, &N); NEAR(N, w[i], 1e-15); }
    pc_curve_release(b3);
    /* Fig 4.9 with k = 4 (the digest's note: with k = 5 the start moves slightly): moving P4
     * leaves the first span alone; P(2) for the three positions */
    double v[14] = {0, 2, 2, 5, 5, 4, 4, 1, 5, 0, 8, 1, 10, 4};
    double p4[3][2] = {{5, 0}, {6, 2}, {7, 4}}, at2[3][2] = {{4.3333, 1.3333}, {4.5, 1.6667}, {4.6667, 2.0}};
    for (int j = 0; j < 3; j++) {
        v[8] = p4[j][0]; v[9] = p4[j][1];
        pc_curve *c = pc_curve_book_bspline(2, 7, v, 4, &s);
        NEAR(c->t1, 4, 0);
        eval2(c, 0.4, x); NEAR(x[0], 2.1333, 5e-5); NEAR(x[1], 4.1280, 5e-5);
        eval2(c, 2, x); NEAR(x[0], at2[j][0], 5e-5); NEAR(x[1], at2[j][1], 5e-5);
        eval2(c, 4, x); NEAR(x[0], 10, 1e-14); NEAR(x[1], 4, 1e-14);     /* ends at P6 */
        pc_curve_release(c);
    }
    /* a double vertex: the curve is a B-spline on the book's knots, ends at the end vertices */
    double pd[12] = {0, 0, 1, 2, 1, 2, 3, 1, 4, 2, 5, 0};
    pc_curve *c = pc_curve_book_bspline(2, 6, pd, 3, &s);
    assert_non_null(c);
    NEAR(c->t1, 3, 0);
    eval2(c, 0, x); NEAR(x[0], 0, 1e-15); NEAR(x[1], 0, 1e-15);
    eval2(c, 1, x); NEAR(x[0], 1, 1e-15); NEAR(x[1], 2, 1e-15);   /* the double vertex is met */
    pc_curve_release(c);
    assert_null(pc_curve_book_bspline(2, 4, p, 5, &s)); assert_int_equal(s, PC_EDOMAIN);
}

static void bernstein_hermite(void **st) {
    (void)st;
    double w1[4] = {8. / 27, 4. / 9, 2. / 9, 1. / 27};
    for (int i = 0; i < 4; i++) {
        NEAR(pc_bernstein(3, i, 1. / 3), w1[i], 1e-15);
        NEAR(pc_bernstein(3, i, 2. / 3), w1[3 - i], 1e-15);
    }
    NEAR(pc_bernstein(3, 0, 0), 1, 0); NEAR(pc_bernstein(3, 3, 1), 1, 0);
    NEAR(pc_bernstein(3, 4, 0.5), 0, 0);
    double s = 0;
    for (int i = 0; i <= 40; i++) s += pc_bernstein(40, i, 0.3);
    NEAR(s, 1, 1e-13);
    double F[4];
    pc_hermite_blend(0.5, F);
    NEAR(F[0], .5, 0); NEAR(F[1], .5, 0); NEAR(F[2], .125, 0); NEAR(F[3], -.125, 0);
    pc_hermite_blend(0.25, F);
    NEAR(F[0], .84375, 0); NEAR(F[1], .15625, 0); NEAR(F[2], .140625, 0); NEAR(F[3], -.046875, 0);
    /* segment 1 of #25: B = (0,0), (1,1), (0,1.8), (0,-1.8) */
    double p1[2] = {0, 0}, p2[2] = {1, 1}, d1[2] = {1, 1}, d2[2] = {1, -0.8}, B[8];
    assert_int_equal(pc_hermite_coeffs(2, p1, p2, d1, d2, 1, B), PC_OK);
    double want[8] = {0, 0, 1, 1, 0, 1.8, 0, -1.8};
    for (int i = 0; i < 8; i++) NEAR(B[i], want[i], 1e-15);
    assert_int_equal(pc_hermite_coeffs(2, p1, p2, d1, d2, 0, B), PC_EDOMAIN);
}

static void derivs(const pc_curve *c, double t, double *out) { assert_int_equal(pc_curve_derivs(c, t, 2, out), PC_OK); }

/* #25, #26 and the other ends */
static void splines(void **st) {
    (void)st;
    int s;
    double p[8] = {0, 0, 1, 1, 2, -1, 3, 0}, d0[2] = {1, 1}, tg[12], x[6], y[6];
    pc_curve *c = pc_curve_book_spline(2, 4, p, 0, PC_BOOK_CLAMPED, d0, d0, tg, &s);
    assert_non_null(c);
    NEAR(tg[2], 1, 1e-14); NEAR(tg[3], -0.8, 1e-14); NEAR(tg[4], 1, 1e-14); NEAR(tg[5], -0.8, 1e-14);
    eval2(c, 0.5, x); NEAR(x[0], 0.5, 1e-14); NEAR(x[1], 0.725, 1e-14);
    eval2(c, 1.5, x); NEAR(x[0], 1.5, 1e-14); NEAR(x[1], 0, 1e-14);
    eval2(c, 2.5, x); NEAR(x[0], 2.5, 1e-14); NEAR(x[1], -0.725, 1e-14);
    double B[8];
    pc_hermite_coeffs(2, p + 2, p + 4, tg + 2, tg + 4, 1, B);
    NEAR(B[4], 0, 1e-14); NEAR(B[5], -3.6, 1e-14); NEAR(B[6], 0, 1e-14); NEAR(B[7], 2.4, 1e-14);
    derivs(c, 1, x); NEAR(x[4], 0, 1e-12); NEAR(x[5], -7.2, 1e-12);
    derivs(c, 2, x); NEAR(x[4], 0, 1e-12); NEAR(x[5], 7.2, 1e-12);
    pc_curve_release(c);
    /* chord length: t = (sqrt 2, sqrt 5, sqrt 2) */
    c = pc_curve_book_spline(2, 4, p, 1, PC_BOOK_CLAMPED, d0, d0, tg, &s);
    NEAR(tg[2], 0.505431, 5e-7); NEAR(tg[3], -0.147724, 5e-7);
    NEAR(tg[4], 0.505431, 5e-7); NEAR(tg[5], -0.147724, 5e-7);
    NEAR(c->t1, 2 * sqrt(2) + sqrt(5), 1e-14);
    pc_hermite_coeffs(2, p, p + 2, tg, tg + 2, sqrt(2), B);
    NEAR(B[4], -0.271607, 5e-7); NEAR(B[5], 0.190243, 5e-7); NEAR(B[6], 0.045609, 5e-7); NEAR(B[7], -0.280969, 5e-7);
    eval2(c, sqrt(2) / 2, x); NEAR(x[0], 0.587428, 5e-7); NEAR(x[1], 0.702891, 5e-7);
    pc_curve_release(c);
    /* every kind of end, both parameters: C2 at the joints and its end conditions; natural
     * and clamped are the general cubic spline of curve.h too */
    double q[12] = {0, 0, 1, 2, 3, 2.5, 4, 0, 2, -1, 0.5, -0.4};
    for (int chord = 0; chord <= 1; chord++)
        for (int e = PC_BOOK_CLAMPED; e <= PC_BOOK_ANTICYCLIC; e++) {
            double dd0[2] = {2, -1}, dd1[2] = {0.5, 3};
            c = pc_curve_book_spline(2, 6, q, chord, e, dd0, dd1, tg, &s);
            assert_non_null(c);
            double tl[5], u = 0;
            pc_book_spline_params(2, 6, q, chord, tl);
            for (int k = 0; k < 5; k++) {
                if (k > 0) {                                /* C2 at the joint u */
                    derivs(c, u - 1e-9, x); derivs(c, u + 1e-9, y);
                    for (int j = 0; j < 6; j++) NEAR(x[j], y[j], 1e-6 * (1 + fabs(x[j])));
                }
                eval2(c, u, x); NEAR(x[0], q[2 * k], 1e-13); NEAR(x[1], q[2 * k + 1], 1e-13);
                u += tl[k];
            }
            derivs(c, c->t0, x); derivs(c, c->t1, y);
            double sg = e == PC_BOOK_ANTICYCLIC ? -1 : 1;
            for (int j = 0; j < 2; j++) {
                if (e == PC_BOOK_CLAMPED) { NEAR(x[2 + j], dd0[j], 1e-12); NEAR(y[2 + j], dd1[j], 1e-12); }
                if (e == PC_BOOK_NATURAL) { NEAR(x[4 + j], 0, 1e-12); NEAR(y[4 + j], 0, 1e-12); }
                if (e >= PC_BOOK_CYCLIC) {
                    NEAR(y[2 + j], sg * x[2 + j], 1e-12);
                    NEAR(y[4 + j], sg * x[4 + j], 1e-11);
                }
            }
            if (e <= PC_BOOK_NATURAL) {
                double uu[6] = {0};
                for (int k = 1; k < 6; k++) uu[k] = uu[k - 1] + tl[k - 1];
                pc_curve *g = pc_curve_cubic_spline(2, 6, q, uu, e == PC_BOOK_CLAMPED ? PC_END_CLAMPED : PC_END_NATURAL, dd0, dd1, &s);
                for (double t = 0; t <= c->t1; t += 0.1) {
                    eval2(c, t, x); eval2(g, t, y);
                    NEAR(x[0], y[0], 1e-12); NEAR(x[1], y[1], 1e-12);
                }
                pc_curve_release(g);
            }
            pc_curve_release(c);
        }
    double r[8] = {0, 0, 1, 1, 1, 1, 2, 0};
    assert_null(pc_curve_book_spline(2, 4, r, 1, PC_BOOK_NATURAL, NULL, NULL, NULL, &s));
    assert_int_equal(s, PC_ECOINCIDENT);
    assert_null(pc_curve_book_spline(2, 3, q, 0, PC_BOOK_CYCLIC, NULL, NULL, NULL, &s));
    assert_int_equal(s, PC_EDOMAIN);
    assert_null(pc_curve_book_spline(2, 3, q, 0, PC_BOOK_CLAMPED, NULL, NULL, NULL, &s));
    assert_int_equal(s, PC_EDOMAIN);
}

static void helix_sphere(void **st) {
    (void)st;
    int s;
    pc_curve *h = pc_curve_helix(2, 0.5, 0, 4 * PI, &s);
    double x[9], len;
    assert_int_equal(pc_curve_eval(h, PI / 2, x), PC_OK);
    NEAR(x[0], 0, 1e-15); NEAR(x[1], 2, 1e-15); NEAR(x[2], PI / 4, 1e-15);
    assert_int_equal(pc_curve_length(h, 0, 2 * PI, 1e-12, &len), PC_OK);
    NEAR(len, 2 * PI * sqrt(4 + 0.25), 1e-9);                  /* one turn */
    double k;
    assert_int_equal(pc_curve_curvature(h, 1, &k), PC_OK);
    NEAR(k, 2 / (4 + 0.25), 1e-12);                            /* a/(a^2 + b^2) */
    pc_curve_release(h);
    assert_null(pc_curve_helix(0, 1, 0, 1, &s)); assert_int_equal(s, PC_EDOMAIN);
    /* the corner table of §5.1 with its errata corrected */
    double f[15], r2 = sqrt(0.5);
    struct { double th, ph, v[15]; } corner[4] = {
        {0, PI / 2, {1, 0, 0, 0, 1, 0, 0, 0, -1, 0, 0, 0, -1, 0, 0}},
        {0, PI / 4, {r2, 0, r2, 0, r2, 0, r2, 0, -r2, 0, r2, 0, -0.5, 0, -0.5}},   /* N_B = -(e1 + e3)/2 */
        {PI / 2, PI / 4, {0, r2, r2, -r2, 0, 0, 0, r2, -r2, -r2, 0, 0, 0, -0.5, -0.5}},
        {PI / 2, PI / 2, {0, 1, 0, -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0}},
    };
    for (int c = 0; c < 4; c++) {
        pc_sphere_frame(corner[c].th, corner[c].ph, f);
        for (int i = 0; i < 15; i++) NEAR(f[i], corner[c].v[i], 1e-15);
    }
    double ctr[3] = {1, 2, 3};
    pc_surface *sp = pc_surface_sphere(ctr, 2, 0, PI / 2, PI / 4, PI / 2, &s);
    assert_non_null(sp);
    double d[9], n[3];
    assert_int_equal(pc_surface_partials(sp, 0.3, 1.1, d), PC_OK);
    pc_sphere_frame(0.3, 1.1, f);
    for (int j = 0; j < 3; j++) {
        NEAR(d[j], ctr[j] + 2 * f[j], 1e-14);
        NEAR(d[3 + j], 2 * f[3 + j], 1e-14);
        NEAR(d[6 + j], 2 * f[6 + j], 1e-14);
    }
    assert_int_equal(pc_surface_normal(sp, 0.3, 1.1, n), PC_OK);      /* -S: inwards */
    for (int j = 0; j < 3; j++) NEAR(n[j], -f[j], 1e-14);
    pc_surface_release(sp);
    assert_null(pc_surface_sphere(ctr, -1, 0, 1, 0, 1, &s)); assert_int_equal(s, PC_EDOMAIN);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(knot_vectors), cmocka_unit_test(basis_table),
        cmocka_unit_test(book_bspline), cmocka_unit_test(bernstein_hermite),
        cmocka_unit_test(splines), cmocka_unit_test(helix_sphere),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
