/* Conic arcs from three points and two tangents, the conic sweep and the elliptic domes of
 * Korotky (2015) (korotky_curves_surfaces.md, B.3, B.5, B.7 and the checks C.3 13-19). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "conic_surface.h"
#include "korotky_parts.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

/* the arc passes through U, T, V and has the given tangent lines at U and V */
static void check_arc(int dim, const double *U, const double *tU, const double *V,
                      const double *tV, const double *T) {
    double w;
    int st;
    pc_curve *c = pc_conic_arc(dim, U, tU, V, tV, T, &w, &st);
    assert_non_null(c);
    double p[2 * 3];
    pc_curve_derivs(c, 0, 1, p);
    for (int k = 0; k < dim; k++) NEAR(p[k], U[k], 1e-12);
    /* tangent parallel to tU: the 2-D cross product or its 3-D norm vanishes */
    double cr = 0;
    for (int a = 0; a < dim; a++)
        for (int b = a + 1; b < dim; b++) {
            double x = p[dim + a] * tU[b] - p[dim + b] * tU[a];
            cr += x * x;
        }
    assert_true(sqrt(cr) < 1e-9);
    pc_curve_derivs(c, 1, 1, p);
    for (int k = 0; k < dim; k++) NEAR(p[k], V[k], 1e-12);
    cr = 0;
    for (int a = 0; a < dim; a++)
        for (int b = a + 1; b < dim; b++) {
            double x = p[dim + a] * tV[b] - p[dim + b] * tV[a];
            cr += x * x;
        }
    assert_true(sqrt(cr) < 1e-9);
    /* through T: the nearest sample then bisection on the distance */
    double best = INFINITY;
    for (int i = 0; i <= 20000; i++) {
        pc_curve_eval(c, i / 20000.0, p);
        double d = 0;
        for (int k = 0; k < dim; k++) d += (p[k] - T[k]) * (p[k] - T[k]);
        best = fmin(best, sqrt(d));
    }
    assert_true(best < 1e-3);
    pc_curve_release(c);
}

static void test_arcs(void **state) {
    (void)state;
    /* quarter circle: W = (1, 1), w = sqrt(2)/2, the unit circle */
    double U[2] = {1, 0}, V[2] = {0, 1}, tU[2] = {0, 1}, tV[2] = {-1, 0};
    double T[2] = {sqrt(.5), sqrt(.5)}, cp[9], w;
    assert_int_equal(pc_conic_arc_cp(2, U, tU, V, tV, T, cp, &w), PC_OK);
    NEAR(w, sqrt(2) / 2, 1e-12);
    NEAR(cp[3] / cp[5], 1, 1e-12);
    NEAR(cp[4] / cp[5], 1, 1e-12);
    assert_string_equal(pc_conic_kind(w), "ellipse");
    int st;
    pc_curve *c = pc_conic_arc(2, U, tU, V, tV, T, &w, &st);
    for (int i = 0; i <= 10; i++) {
        double p[2];
        pc_curve_eval(c, i / 10.0, p);
        NEAR(hypot(p[0], p[1]), 1, 1e-12);
    }
    pc_curve_release(c);
    check_arc(2, U, tU, V, tV, T);
    /* parallel tangents: W at infinity, middle point (0, 0.5, 0), (x - 1)^2 + 4 y^2 = 1 */
    double U2[2] = {0, 0}, V2[2] = {2, 0}, up[2] = {0, 1}, T2[2] = {1, .5};
    assert_int_equal(pc_conic_arc_cp(2, U2, up, V2, up, T2, cp, &w), PC_OK);
    NEAR(cp[3], 0, 1e-12);
    NEAR(cp[4], .5, 1e-12);
    NEAR(cp[5], 0, 0);
    c = pc_conic_arc(2, U2, up, V2, up, T2, &w, &st);
    for (int i = 0; i <= 10; i++) {
        double p[2];
        pc_curve_eval(c, i / 10.0, p);
        NEAR((p[0] - 1) * (p[0] - 1) + 4 * p[1] * p[1], 1, 1e-12);
    }
    pc_curve_release(c);
    /* hyperbola: tangents (1, sqrt 3), (-1, sqrt 3), T = (1, 1.5): W = (1, sqrt 3), w = 6.4641 */
    double a[2] = {1, sqrt(3)}, b[2] = {-1, sqrt(3)}, T3[2] = {1, 1.5};
    assert_int_equal(pc_conic_arc_cp(2, U2, a, V2, b, T3, cp, &w), PC_OK);
    NEAR(w, 6.4641, 1e-4);
    NEAR(cp[3] / cp[5], 1, 1e-12);
    NEAR(cp[4] / cp[5], sqrt(3), 1e-12);
    assert_string_equal(pc_conic_kind(w), "hyperbola");
    check_arc(2, U2, a, V2, b, T3);
    /* below the chord: the concave arc, w = -0.14763 */
    double T4[2] = {1, -.3};
    assert_int_equal(pc_conic_arc_cp(2, U2, a, V2, b, T4, cp, &w), PC_OK);
    NEAR(w, -0.14763, 1e-5);
    check_arc(2, U2, a, V2, b, T4);
    /* T on the chord: w = 0, the straight generator */
    double T5[2] = {1, 0};
    assert_int_equal(pc_conic_arc_cp(2, U2, a, V2, b, T5, cp, &w), PC_OK);
    NEAR(w, 0, 1e-15);
    assert_string_equal(pc_conic_kind(w), "segment");
    assert_string_equal(pc_conic_kind(1), "parabola");
    /* in space: a semi-ellipse of height 2 in the plane y = 3 */
    double P0[3] = {0, 3, 0}, P1[3] = {4, 3, 0}, vz[3] = {0, 0, 1}, Tm[3] = {2, 3, 2};
    check_arc(3, P0, vz, P1, vz, Tm);
    /* errors */
    double off[3] = {0, 1, 1};
    assert_int_equal(pc_conic_arc_cp(3, P0, off, P1, vz, Tm, cp, &w), PC_ESKEW);
    assert_int_equal(pc_conic_arc_cp(2, U2, a, U2, b, T3, cp, &w), PC_ECOINCIDENT);
    double z[2] = {0, 0};
    assert_int_equal(pc_conic_arc_cp(2, U2, z, V2, b, T3, cp, &w), PC_EZERO);
    double Tout[2] = {-1, 1};   /* outside the angle of the tangents */
    assert_int_equal(pc_conic_arc_cp(2, U2, a, V2, b, Tout, cp, &w), PC_EDOMAIN);
    /* alpha = 4, beta = -3.01, gamma = 0.01: w = -7.525, the arc would run through infinity */
    double Tinf[2] = {-3.01 + .02, -3.01 * sqrt(3)};
    assert_int_equal(pc_conic_arc_cp(2, U2, a, V2, b, Tinf, cp, &w), PC_EDOMAIN);
    double Tn[2] = {NAN, 0};
    assert_int_equal(pc_conic_arc_cp(2, U2, a, V2, b, Tn, cp, &w), PC_ENONFINITE);
}

static void test_dome_rect(void **state) {
    (void)state;
    int st;
    pc_surface *s = pc_surface_dome_rect(2, 1, 1.5, NULL, &st);
    assert_non_null(s);
    double p[3];
    pc_surface_eval(s, .5, .5, p);   /* the top over the centre (2, 1) */
    NEAR(p[0], 2, 1e-12); NEAR(p[1], 1, 1e-12); NEAR(p[2], 1.5, 1e-12);
    NEAR(pc_dome_rect_height(2, 1, 1.5, 1, .5), 1.125, 1e-12);
    NEAR(pc_dome_rect_height(1, 1, 1, .5, .5), .75, 1e-12);
    /* every point satisfies z^2/c0^2 = x (2a0 - x) y (2b0 - y)/(a0^2 b0^2) (degree 4) */
    for (int i = 0; i <= 8; i++)
        for (int j = 0; j <= 8; j++) {
            assert_int_equal(pc_surface_eval(s, i / 8.0, j / 8.0, p), PC_OK);
            NEAR(p[2] * p[2] / 2.25, p[0] * (4 - p[0]) * p[1] * (2 - p[1]) / 4, 1e-12);
            NEAR(p[2], pc_dome_rect_height(2, 1, 1.5, p[0], p[1]), 1e-12);
        }
    /* the sides lie on the base, and the section x = const is a semi-ellipse with vertical
     * tangents at its feet: near y = 0, z ~ sqrt(y) */
    pc_surface_eval(s, 0, .3, p);
    NEAR(p[0], 0, 1e-15); NEAR(p[2], 0, 1e-15);
    pc_surface_eval(s, .7, 1, p);
    NEAR(p[1], 2, 1e-12); NEAR(p[2], 0, 1e-15);
    /* near the corner the dome is the elliptic cone z^2/c0^2 = 4xy/(a0 b0) */
    double x = 1e-6, y = 2e-6, z = pc_dome_rect_height(2, 1, 1.5, x, y);
    NEAR((z * z / 2.25) / (4 * x * y / 2), 1, 1e-5);
    pc_surface_release(s);
    double o[3] = {10, 20, 1};
    s = pc_surface_dome_rect(1, 1, 1, o, &st);
    pc_surface_eval(s, .5, .5, p);
    NEAR(p[0], 11, 1e-12); NEAR(p[1], 21, 1e-12); NEAR(p[2], 2, 1e-12);
    pc_surface_release(s);
    assert_null(pc_surface_dome_rect(0, 1, 1, NULL, &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_null(pc_surface_dome_rect(1, NAN, 1, NULL, &st));
    assert_int_equal(st, PC_ENONFINITE);
}

static void test_dome_tri(void **state) {
    (void)state;
    double A[3] = {0, 0, 0}, B[3] = {1, 0, 0}, C[3] = {0, 1, 0}, p[3];
    int st;
    pc_surface *s = pc_surface_dome_tri(A, B, C, 1, &st);
    assert_non_null(s);
    /* z^2 = 27 x y (1 - x - y): the apex 1 over the centroid, 0.918559 over (0.5, 0.25) */
    pc_surface_eval(s, 2.0 / 3, .5, p);
    NEAR(p[0], 1.0 / 3, 1e-12); NEAR(p[1], 1.0 / 3, 1e-12); NEAR(p[2], 1, 1e-12);
    pc_surface_eval(s, .75, 1.0 / 3, p);   /* l1 = .25, l2 = .5, l3 = .25 */
    NEAR(p[0], .5, 1e-12); NEAR(p[1], .25, 1e-12); NEAR(p[2], 0.918559, 1e-6);
    for (int i = 0; i <= 10; i++)
        for (int j = 0; j <= 10; j++) {
            pc_surface_eval(s, i / 10.0, j / 10.0, p);
            NEAR(p[2] * p[2], 27 * p[0] * p[1] * (1 - p[0] - p[1]), 1e-12);
        }
    /* the sections x + y = c are ellipses: z^2 = K (1 - c) x (c - x) (family a, the
     * corrected "x + y = const") */
    for (int j = 0; j <= 10; j++) {
        pc_surface_eval(s, .5, j / 10.0, p);   /* on x + y = 0.5 */
        NEAR(p[0] + p[1], .5, 1e-12);
        NEAR(p[2] * p[2], 27 * .5 * p[0] * (.5 - p[0]), 1e-12);
    }
    /* the generator at x = 0.25 (family b): centre y = 0.375, semi-axes 0.375, 0.974279 */
    double ymid = .375, zmax = sqrt(27 * .25 * ymid * (1 - .25 - ymid));
    NEAR(zmax, 0.974279, 1e-6);
    pc_surface_release(s);
    /* through a given apex D: h from D */
    double D[3] = {1.0 / 3, 1.0 / 3, 2}, h;
    assert_int_equal(pc_dome_tri_height_through(A, B, C, D, &h), PC_OK);
    NEAR(h, 2, 1e-12);
    double Dout[3] = {1, 1, 1};
    assert_int_equal(pc_dome_tri_height_through(A, B, C, Dout, &h), PC_EDOMAIN);
    pc_why_call w;   /* explained: D is argument #4, its value shown by the raiser */
    assert_int_equal(pc_dome_tri_height_checked(A, B, C, Dout, &h, &w), PC_EDOMAIN);
    assert_int_equal(w.row[0].arg, 4);
    assert_string_equal(w.row[0].text, "must stand above the inside of the triangle, got %s");
    assert_int_equal(pc_dome_tri_height_checked(A, B, C, D, &h, &w), PC_OK);
    NEAR(h, 2, 1e-12);
    /* korotky.dome_tri's: the height, or (h 0) the apex D, each failure explained */
    s = pc_dome_tri_explained(A, B, C, 0, D, &st, &w);
    assert_non_null(s);
    assert_null(w.row[0].op);
    pc_surface_eval(s, 2.0 / 3, .5, p);
    NEAR(p[2], 2, 1e-12);   /* the apex over the centroid */
    pc_surface_release(s);
    assert_null(pc_dome_tri_explained(A, B, C, 0, Dout, &st, &w));
    assert_int_equal(w.row[0].arg, 4);
    double F[3] = {2, 0, 0};
    assert_null(pc_dome_tri_explained(A, B, F, 1, NULL, &st, &w));
    assert_int_equal(st, PC_ECOLLINEAR);
    assert_string_equal(w.row[0].text, "the triangle ABC is flat in plan");
    assert_null(pc_dome_tri_explained(A, B, C, -1, NULL, &st, &w));
    assert_null(w.row[0].op);   /* no row: the status as it is */
    assert_null(pc_surface_dome_tri(A, B, F, 1, &st));
    assert_int_equal(st, PC_ECOLLINEAR);
    assert_null(pc_surface_dome_tri(A, B, C, -1, &st));
    assert_int_equal(st, PC_EDOMAIN);
}

/* the conic sweep over Fig. 2's default contour (digest B.8) */
static pc_curve *line3(double x0, double y0, double z0, double x1, double y1, double z1) {
    double cp[8] = {x0, y0, z0, 1, x1, y1, z1, 1};
    int st;
    return pc_curve_bezier(3, 2, cp, &st);
}

static void test_sweep(void **state) {
    (void)state;
    /* u runs from DC (y = 0) to AB (y = 4); AD: x = 0, BC: x = 6 (straight, z = 0 here);
     * l from L' (3, 0, 2) to L (3, 4, 3); tangent points p: z = x tan 45..60 at x = 1 */
    pc_curve *U = line3(0, 0, 0, 0, 4, 0), *V = line3(6, 0, 0, 6, 4, 0);
    pc_curve *T = line3(3, 0, 2, 3, 4, 3);
    pc_curve *P = line3(1, 0, 1, 1, 4, sqrt(3)), *Q = line3(5, 0, 1, 5, 4, sqrt(3));
    int st;
    pc_surface *s = pc_surface_conic_sweep(U, V, T, P, Q, NULL, &st);
    assert_non_null(s);
    /* the frontal link DC at u = 0: the conic through D, L', C tangent at 45 degrees */
    double D[3] = {0, 0, 0}, C[3] = {6, 0, 0}, L2[3] = {3, 0, 2}, t1[3] = {1, 0, 1}, t2[3] = {-1, 0, 1};
    double w, p[3], q[3];
    pc_curve *dc = pc_conic_arc(3, D, t1, C, t2, L2, &w, &st);
    for (int j = 0; j <= 8; j++) {
        pc_surface_eval(s, 0, j / 8.0, p);
        pc_curve_eval(dc, j / 8.0, q);
        for (int k = 0; k < 3; k++) NEAR(p[k], q[k], 1e-9);
    }
    /* every generator lies in its plane y = 4u, passes through T(u) at its middle (symmetric
     * data) and starts and ends on the guides */
    for (int i = 0; i <= 4; i++) {
        double u = i / 4.0;
        pc_surface_eval(s, u, .5, p);
        NEAR(p[0], 3, 1e-12); NEAR(p[1], 4 * u, 1e-12); NEAR(p[2], 2 + u, 1e-12);
        pc_surface_eval(s, u, 0, p);
        NEAR(p[0], 0, 1e-12); NEAR(p[2], 0, 1e-12);
        pc_surface_eval(s, u, .3, q);
        NEAR(q[1], 4 * u, 1e-12);
    }
    pc_surface_release(s);
    /* degenerate data: T outside the tangents' angle from u = 0.5 on */
    pc_curve *Tbad = line3(3, 0, 2, -3, 4, -3);
    double bad_u = -1;
    assert_null(pc_surface_conic_sweep(U, V, Tbad, P, Q, &bad_u, &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_true(bad_u > 0.3 && bad_u < 0.7);
    double cp2[6] = {0, 0, 1, 1, 1, 1};
    pc_curve *flat = pc_curve_bezier(2, 2, cp2, &st);
    assert_null(pc_surface_conic_sweep(U, V, T, P, flat, NULL, &st));
    assert_int_equal(st, PC_EDIM);
    pc_curve_release(flat);
    pc_curve_release(Tbad);
    pc_curve_release(dc);
    pc_curve_release(U); pc_curve_release(V); pc_curve_release(T);
    pc_curve_release(P); pc_curve_release(Q);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_arcs), cmocka_unit_test(test_dome_rect),
        cmocka_unit_test(test_dome_tri), cmocka_unit_test(test_sweep),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
