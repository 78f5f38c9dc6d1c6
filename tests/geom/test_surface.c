/* Surfaces without curves: bilinear, Bezier (rational), B-spline / NURBS, bicubic Hermite and
 * FUNC patches.  Buimov's test vectors (buimov_textbook.md §9.2: 27, 31, 32, 33, 34, 36),
 * corners, partial derivatives against differences, normals, spheres from rational patches,
 * exact maps of the net, and errors for bad input. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "surface.h"

#define NEAR(a, b, tol) near_((a), (b), (tol), __FILE__, __LINE__)

static void near_(double a, double b, double tol, const char *file, int line) {
    if (!(fabs(a - b) <= tol)) {
        print_error("%.17g != %.17g (tolerance %g)\n", a, b, tol);
        _fail(file, line);
    }
}
#define R2 0.70710678118654752440

static void near_vec(int n, const double *a, const double *b, double tol) {
    for (int i = 0; i < n; i++) NEAR(a[i], b[i], tol);
}

static void eval_is(const pc_surface *s, double u, double v, const double *want, double tol) {
    double p[PC_MAXDIM];
    assert_int_equal(pc_surface_eval(s, u, v, p), PC_OK);
    near_vec(s->dim, p, want, tol);
}

/* pc_surface_partials against central differences of pc_surface_eval (and the point) */
static void partials_match(const pc_surface *s, double u, double v, double tol) {
    int n = s->dim;
    double d[3 * PC_MAXDIM], p[PC_MAXDIM], a[PC_MAXDIM], b[PC_MAXDIM], h = 1e-5;
    assert_int_equal(pc_surface_partials(s, u, v, d), PC_OK);
    assert_int_equal(pc_surface_eval(s, u, v, p), PC_OK);
    near_vec(n, d, p, 1e-14);
    assert_int_equal(pc_surface_eval(s, u + h, v, a), PC_OK);
    assert_int_equal(pc_surface_eval(s, u - h, v, b), PC_OK);
    for (int i = 0; i < n; i++) NEAR(d[n + i], (a[i] - b[i]) / (2 * h), tol);
    assert_int_equal(pc_surface_eval(s, u, v + h, a), PC_OK);
    assert_int_equal(pc_surface_eval(s, u, v - h, b), PC_OK);
    for (int i = 0; i < n; i++) NEAR(d[2 * n + i], (a[i] - b[i]) / (2 * h), tol);
}

/* a 5 x 5 grid over the domain, off the knots (the differences are only O(h) accurate where
 * a second derivative jumps) */
static void partials_grid(const pc_surface *s, double tol) {
    for (int i = 0; i <= 4; i++)
        for (int j = 0; j <= 4; j++) {
            double u = s->u0 + (s->u1 - s->u0) * (0.0613 + 0.877 * i / 4);
            double v = s->v0 + (s->v1 - s->v0) * (0.0613 + 0.877 * j / 4);
            partials_match(s, u, v, tol);
        }
}

/* homogeneous row (x w, y w, z w | w) */
static void hrow(double *r, double x, double y, double z, double w) {
    r[0] = x * w, r[1] = y * w, r[2] = z * w, r[3] = w;
}

/* Buimov 34: bilinear through (0,0,1), (0,1,0), (1,0,0), (1,1,1) (P_uw) */
static void test_bilinear(void **state) {
    (void)state;
    double P00[3] = {0, 0, 1}, P01[3] = {0, 1, 0}, P10[3] = {1, 0, 0}, P11[3] = {1, 1, 1};
    int st;
    pc_surface *s = pc_surface_bilinear(3, P00, P10, P01, P11, &st);
    assert_non_null(s);
    assert_int_equal(st, PC_OK);
    assert_int_equal(s->kind, PC_SURF_BEZIER);
    assert_int_equal(s->pdeg, 1);
    eval_is(s, 0, 0, P00, 0);
    eval_is(s, 1, 0, P10, 0);
    eval_is(s, 0, 1, P01, 0);
    eval_is(s, 1, 1, P11, 0);
    eval_is(s, 0.5, 0.5, (double[]){0.5, 0.5, 0.5}, 1e-15);
    eval_is(s, 0.25, 0.75, (double[]){0.25, 0.75, 0.375}, 1e-15);
    partials_grid(s, 1e-9);
    /* the hyperbolic paraboloid z = 1 - u - v + 2uv: S_u = (1, 0, 2v - 1), S_v = (0, 1, 2u - 1) */
    double d[9];
    assert_int_equal(pc_surface_partials(s, 0.25, 0.75, d), PC_OK);
    near_vec(3, d + 3, (double[]){1, 0, 0.5}, 1e-15);
    near_vec(3, d + 6, (double[]){0, 1, -0.5}, 1e-15);
    pc_surface_release(s);
}

/* Buimov 36: the 4x4 net P_ij = (i, j, z_ij), z = 1 on the inner 2x2 */
static pc_surface *buimov_net(void) {
    double cp[16 * 4];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            hrow(cp + (i * 4 + j) * 4, i, j, (i == 1 || i == 2) && (j == 1 || j == 2), 1);
    int st;
    pc_surface *s = pc_surface_bezier(3, 3, 3, cp, &st);
    assert_int_equal(st, PC_OK);
    return s;
}

static void test_bezier_buimov(void **state) {
    (void)state;
    pc_surface *s = buimov_net();
    eval_is(s, 0.5, 0.5, (double[]){1.5, 1.5, 0.5625}, 1e-15);
    eval_is(s, 0.25, 0.5, (double[]){0.75, 1.5, 0.421875}, 1e-15);
    eval_is(s, 0, 0, (double[]){0, 0, 0}, 0);
    eval_is(s, 1, 0, (double[]){3, 0, 0}, 0);
    eval_is(s, 0, 1, (double[]){0, 3, 0}, 0);
    eval_is(s, 1, 1, (double[]){3, 3, 0}, 0);
    /* the boundary u = 0 is the Bezier curve of the row B_0j: here the line (0, 3v, 0),
     * and its end tangents are 3 (B_01 - B_00) = (0, 3, 0) */
    double d[9];
    assert_int_equal(pc_surface_partials(s, 0, 0, d), PC_OK);
    near_vec(3, d + 3, (double[]){3, 0, 0}, 1e-15);
    near_vec(3, d + 6, (double[]){0, 3, 0}, 1e-15);
    partials_grid(s, 1e-9);
    pc_surface_release(s);
}

/* a rational biquadratic: the unit sphere's octant as a tensor product of two quarter
 * circles (profile (r, z) and the circle (c, s) of longitude): P_ij = (r_i c_j, r_i s_j, z_i)
 * with weight w_i w_j */
static pc_surface *octant(void) {
    double r[3] = {1, 1, 0}, z[3] = {0, 1, 1}, c[3] = {1, 1, 0}, sn[3] = {0, 1, 1};
    double w[3] = {1, R2, 1}, cp[9 * 4];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            hrow(cp + (i * 3 + j) * 4, r[i] * c[j], r[i] * sn[j], z[i], w[i] * w[j]);
    int st;
    pc_surface *s = pc_surface_bezier(3, 2, 2, cp, &st);
    assert_int_equal(st, PC_OK);
    return s;
}

static void test_sphere_octant(void **state) {
    (void)state;
    pc_surface *s = octant();
    double err = 0, nerr = 0;
    for (int i = 0; i <= 20; i++)
        for (int j = 0; j <= 20; j++) {
            double p[3], n[3], u = i / 20.0, v = j / 20.0;
            assert_int_equal(pc_surface_eval(s, u, v, p), PC_OK);
            err = fmax(err, fabs(pc_norm(3, p) - 1));
            if (i == 20) continue;                    /* u = 1 is the pole: no normal */
            assert_int_equal(pc_surface_normal(s, u, v, n), PC_OK);
            for (int k = 0; k < 3; k++) nerr = fmax(nerr, fabs(fabs(pc_dot(3, n, p)) - 1));
        }
    assert_true(err < 1e-12);
    assert_true(nerr < 1e-12);                        /* the normal is along the radius */
    eval_is(s, 0, 0, (double[]){1, 0, 0}, 0);
    eval_is(s, 0, 1, (double[]){0, 1, 0}, 0);
    eval_is(s, 1, 0.3, (double[]){0, 0, 1}, 0);
    /* the middle of the profile is at 45 degrees: (1/sqrt 2, 0, 1/sqrt 2) */
    eval_is(s, 0.5, 0, (double[]){R2, 0, R2}, 1e-15);
    partials_grid(s, 1e-8);
    /* the pole: the whole edge u = 1 is one point, S_v = 0 */
    double n[3];
    assert_int_equal(pc_surface_normal(s, 1, 0.5, n), PC_EZERO);
    pc_surface_release(s);
}

/* A NURBS hemisphere: the quarter-circle profile in u (3 points) times a whole circle in v
 * (9 points, knots 0 0 0 1 1 2 2 3 3 4 4 4, the weights 1, 1/sqrt 2 alternating). */
static void test_nurbs_hemisphere(void **state) {
    (void)state;
    double r[3] = {1, 1, 0}, z[3] = {0, 1, 1}, wu[3] = {1, R2, 1};
    double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    double cp[27 * 4];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 9; j++)
            hrow(cp + (i * 9 + j) * 4, r[i] * cx[j], r[i] * cy[j], z[i],
                 wu[i] * (j % 2 ? R2 : 1));
    double vk[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    int st;
    pc_surface *s = pc_surface_bspline(3, 2, 2, 3, 9, cp, PC_KNOTS_OPEN, NULL, PC_KNOTS_GIVEN,
                                       vk, &st);
    assert_non_null(s);
    assert_int_equal(st, PC_OK);
    NEAR(s->u0, 0, 0);
    NEAR(s->u1, 1, 0);
    NEAR(s->v0, 0, 0);
    NEAR(s->v1, 4, 0);
    double err = 0;
    for (int i = 0; i <= 16; i++)
        for (int j = 0; j <= 40; j++) {
            double p[3];
            assert_int_equal(pc_surface_eval(s, i / 16.0, j / 10.0, p), PC_OK);
            err = fmax(err, fabs(pc_norm(3, p) - 1));
        }
    assert_true(err < 1e-12);
    eval_is(s, 0, 0, (double[]){1, 0, 0}, 0);
    eval_is(s, 0, 1, (double[]){0, 1, 0}, 1e-15);
    eval_is(s, 0, 2, (double[]){-1, 0, 0}, 1e-15);
    eval_is(s, 0, 4, (double[]){1, 0, 0}, 1e-15);
    eval_is(s, 1, 2.5, (double[]){0, 0, 1}, 1e-15);
    /* the equator's tangent at v = 1 (a double knot: C1 in the homogeneous net, the point
     * moves on): the derivatives exist on both sides and match differences */
    partials_grid(s, 1e-8);
    partials_match(s, 0.3, 1 + 1e-3, 1e-8);
    pc_surface_release(s);
}

/* Buimov 31 and 32: B-spline curves of the book as the u-direction of a patch that is linear
 * in v (the rows at z = 0 and z = 1); open integer knots as the book's. */
static pc_surface *lifted(int n, const double *xy, int p) {
    double cp[16 * 2 * 4];
    for (int i = 0; i < n; i++)
        for (int j = 0; j < 2; j++) hrow(cp + (i * 2 + j) * 4, xy[2 * i], xy[2 * i + 1], j, 1);
    int st;
    pc_surface *s =
        pc_surface_bspline(3, p, 1, n, 2, cp, PC_KNOTS_OPEN, NULL, PC_KNOTS_OPEN, NULL, &st);
    assert_int_equal(st, PC_OK);
    return s;
}

static void test_bspline_buimov(void **state) {
    (void)state;
    double xy[8] = {1, 1, 2, 3, 4, 3, 3, 1};
    pc_surface *s = lifted(4, xy, 2);           /* k = 3: knots 0 0 0 1 2 2 2 */
    NEAR(s->u1, 2, 0);
    eval_is(s, 0.5, 0.25, (double[]){2.0, 2.5, 0.25}, 1e-15);
    eval_is(s, 1, 0.5, (double[]){3, 3, 0.5}, 1e-15);
    eval_is(s, 1.5, 1, (double[]){3.5, 2.5, 1}, 1e-15);
    eval_is(s, 2, 1, (double[]){3, 1, 1}, 0);   /* t = t_max gives the last vertex */
    partials_grid(s, 1e-9);
    pc_surface_release(s);
    /* k = 4 on the same points is the Bezier curve: P(0.5) = (2.75, 2.5), P(0.15) */
    s = lifted(4, xy, 3);
    eval_is(s, 0.5, 0, (double[]){2.75, 2.5, 0}, 1e-15);
    eval_is(s, 0.15, 0, (double[]){1.504, 1.765, 0}, 1e-12);
    eval_is(s, 0.85, 0, (double[]){3.261, 1.765, 0}, 1e-12);
    double d[9];
    assert_int_equal(pc_surface_partials(s, 0, 0, d), PC_OK);
    near_vec(3, d + 3, (double[]){3, 6, 0}, 1e-14);
    assert_int_equal(pc_surface_partials(s, 1, 0, d), PC_OK);
    near_vec(3, d + 3, (double[]){-3, -6, 0}, 1e-14);
    pc_surface_release(s);
    /* Fig 4.9 with k = 4: the first span does not see P4 */
    double fig[14] = {0, 2, 2, 5, 5, 4, 4, 1, 5, 0, 8, 1, 10, 4};
    double p4[3][2] = {{5, 0}, {6, 2}, {7, 4}}, at2[3][2] = {{13.0 / 3, 4.0 / 3}, {4.5, 5.0 / 3},
                                                             {14.0 / 3, 2}};
    for (int k = 0; k < 3; k++) {
        fig[8] = p4[k][0], fig[9] = p4[k][1];
        s = lifted(7, fig, 3);
        NEAR(s->u1, 4, 0);
        eval_is(s, 0.4, 0, (double[]){2.1333333333333333, 4.128, 0}, 1e-12);
        eval_is(s, 2, 0, (double[]){at2[k][0], at2[k][1], 0}, 1e-12);
        pc_surface_release(s);
    }
}

/* A clamped B-spline patch of degrees 3 x 3 on a 4 x 4 net is the Bezier patch. */
static void test_bspline_is_bezier(void **state) {
    (void)state;
    pc_surface *b = buimov_net();
    int st;
    pc_surface *s = pc_surface_bspline(3, 3, 3, 4, 4, b->cp, PC_KNOTS_OPEN, NULL, PC_KNOTS_OPEN,
                                       NULL, &st);
    assert_int_equal(st, PC_OK);
    for (int i = 0; i <= 10; i++)
        for (int j = 0; j <= 10; j++) {
            double p[3], q[9], r[9];
            assert_int_equal(pc_surface_eval(b, i / 10.0, j / 10.0, p), PC_OK);
            eval_is(s, i / 10.0, j / 10.0, p, 1e-14);
            assert_int_equal(pc_surface_partials(b, i / 10.0, j / 10.0, q), PC_OK);
            assert_int_equal(pc_surface_partials(s, i / 10.0, j / 10.0, r), PC_OK);
            near_vec(9, q, r, 1e-13);
        }
    pc_surface_release(s);
    pc_surface_release(b);
}

/* the B-spline basis by the Cox-de Boor recursion itself (0/0 = 0), for a reference */
static double cox(int i, int p, const double *U, double t) {
    if (p == 0) return U[i] <= t && t < U[i + 1];
    double a = U[i + p] > U[i] ? (t - U[i]) / (U[i + p] - U[i]) * cox(i, p - 1, U, t) : 0;
    double b = U[i + p + 1] > U[i + 1]
                   ? (U[i + p + 1] - t) / (U[i + p + 1] - U[i + 1]) * cox(i + 1, p - 1, U, t)
                   : 0;
    return a + b;
}

/* a rational 5 x 4 net of degrees 2 x 3 with uneven given knots against the recursion */
static void test_nurbs_general(void **state) {
    (void)state;
    enum { NU = 5, NV = 4 };
    double uk[NU + 3] = {0, 0, 0, 0.3, 0.5, 1.2, 1.2, 1.2};
    double vk[NV + 4] = {-1, -1, -1, -1, 2, 2, 2, 2};
    double cp[NU * NV * 4];
    for (int i = 0; i < NU; i++)
        for (int j = 0; j < NV; j++)
            hrow(cp + (i * NV + j) * 4, i + 0.3 * j, j - 0.2 * i * i, sin(i + 2.0 * j),
                 0.5 + 0.25 * ((i + j) % 3));
    int st;
    pc_surface *s =
        pc_surface_bspline(3, 2, 3, NU, NV, cp, PC_KNOTS_GIVEN, uk, PC_KNOTS_GIVEN, vk, &st);
    assert_int_equal(st, PC_OK);
    NEAR(s->u0, 0, 0);
    NEAR(s->u1, 1.2, 0);
    NEAR(s->v0, -1, 0);
    NEAR(s->v1, 2, 0);
    for (int a = 0; a < 12; a++)
        for (int b = 0; b < 7; b++) {
            double u = a * 0.1 + 0.01, v = -1 + b * 0.45 + 0.01, h[4] = {0};
            for (int i = 0; i < NU; i++)
                for (int j = 0; j < NV; j++) {
                    double f = cox(i, 2, uk, u) * cox(j, 3, vk, v);
                    for (int c = 0; c < 4; c++) h[c] += f * cp[(i * NV + j) * 4 + c];
                }
            eval_is(s, u, v, (double[]){h[0] / h[3], h[1] / h[3], h[2] / h[3]}, 1e-13);
        }
    partials_grid(s, 1e-7);
    /* corners: a clamped net interpolates its corner points */
    eval_is(s, 0, -1, (double[]){0, 0, sin(0)}, 1e-15);
    eval_is(s, 1.2, 2, (double[]){4 + 0.9, 3 - 3.2, sin(10.0)}, 1e-14);
    pc_surface_release(s);
}

/* periodic in v: a closed tube whose seam joins with matching derivatives */
static void test_bspline_periodic(void **state) {
    (void)state;
    enum { NU = 4, NV = 6 };
    double cp[NU * NV * 4];
    for (int i = 0; i < NU; i++)
        for (int j = 0; j < NV; j++)
            hrow(cp + (i * NV + j) * 4, cos(j * M_PI / 3) * (1 + 0.1 * i),
                 sin(j * M_PI / 3) * (1 + 0.1 * i), i, 1);
    int st;
    pc_surface *s = pc_surface_bspline(3, 2, 3, NU, NV, cp, PC_KNOTS_OPEN, NULL,
                                       PC_KNOTS_PERIODIC, NULL, &st);
    assert_int_equal(st, PC_OK);
    assert_int_equal(s->nv, NV + 3);
    NEAR(s->v0, 0, 0);                          /* the curves' periodic knots: [0, NV] */
    NEAR(s->v1, NV, 0);
    for (int i = 0; i <= 8; i++) {
        double a[9], b[9], u = s->u1 * i / 8;
        assert_int_equal(pc_surface_partials(s, u, s->v0, a), PC_OK);
        assert_int_equal(pc_surface_partials(s, u, s->v1, b), PC_OK);
        near_vec(9, a, b, 1e-13);
    }
    partials_grid(s, 1e-8);
    pc_surface_release(s);
}

/* Buimov 27: the Hermite blending functions through single nonzero data, in one dimension */
static void test_hermite_basis(void **state) {
    (void)state;
    double z[4] = {0}, e0[4] = {1, 0, 0, 0}, e1[4] = {0, 1, 0, 0};
    struct { const double *p, *pu; double t, want; } c[] = {
        {e0, z, 0.5, 0.5},       {e0, z, 0.25, 0.84375},   {e1, z, 0.25, 0.15625},
        {z, e0, 0.5, 0.125},     {z, e0, 0.25, 0.140625},  {z, e1, 0.5, -0.125},
        {z, e1, 0.25, -0.046875},
    };
    for (size_t k = 0; k < sizeof c / sizeof *c; k++) {
        int st;
        pc_surface *s = pc_surface_hermite(1, c[k].p, c[k].pu, z, z, &st);
        assert_int_equal(st, PC_OK);
        eval_is(s, c[k].t, 0, &c[k].want, 1e-15);
        /* along v with the same data the blend is F1(v) at u = 0 */
        pc_surface_release(s);
    }
    /* F1(u) F1(v) from P(0,0) = 1: 0.84375 * 0.5 at (0.25, 0.5) */
    int st;
    pc_surface *s = pc_surface_hermite(1, e0, z, z, z, &st);
    eval_is(s, 0.25, 0.5, (double[]){0.84375 * 0.5}, 1e-15);
    pc_surface_release(s);
    /* the twist alone: F3(u) F3(v) Puv(0,0) */
    s = pc_surface_hermite(1, z, z, z, e0, &st);
    eval_is(s, 0.25, 0.5, (double[]){0.140625 * 0.125}, 1e-15);
    pc_surface_release(s);
}

/* a 3-D Hermite patch reproduces its corner points, tangents and twists */
static void test_hermite_corners(void **state) {
    (void)state;
    double P[12], Pu[12], Pv[12], Puv[12];
    for (int k = 0; k < 12; k++) {
        P[k] = sin(1.0 + k), Pu[k] = cos(2.0 * k), Pv[k] = sin(0.5 * k * k), Puv[k] = cos(k + 0.3);
    }
    int st;
    pc_surface *s = pc_surface_hermite(3, P, Pu, Pv, Puv, &st);
    assert_int_equal(st, PC_OK);
    assert_int_equal(s->pdeg, 3);
    for (int k = 0; k < 4; k++) {
        double u = k & 1, v = k >> 1, d[9], a[9], b[9], h = 1e-4;
        assert_int_equal(pc_surface_partials(s, u, v, d), PC_OK);
        near_vec(3, d, P + 3 * k, 1e-15);
        near_vec(3, d + 3, Pu + 3 * k, 1e-14);
        near_vec(3, d + 6, Pv + 3 * k, 1e-14);
        /* the twist: d(S_u)/dv by a one-sided difference of second order into the patch */
        double sg = v == 0 ? 1 : -1;
        assert_int_equal(pc_surface_partials(s, u, v + sg * h, a), PC_OK);
        assert_int_equal(pc_surface_partials(s, u, v + 2 * sg * h, b), PC_OK);
        for (int i = 0; i < 3; i++)
            NEAR((-3 * d[3 + i] + 4 * a[3 + i] - b[3 + i]) / (2 * sg * h), Puv[3 * k + i], 1e-7);
    }
    partials_grid(s, 1e-8);
    pc_surface_release(s);
}

/* Buimov 33: the sphere patch of Fig 5.2 as a FUNC surface, u = Theta, v = Phi */
static int sphere_fn(void *ud, double th, double ph, int order, double *out) {
    int *calls = ud;
    if (calls) ++*calls;
    out[0] = cos(th) * sin(ph), out[1] = sin(th) * sin(ph), out[2] = cos(ph), out[3] = 1;
    if (order == 0) return PC_OK;
    if (calls) return PC_EDOMAIN;             /* the counting variant differences */
    out[4] = -sin(th) * sin(ph), out[5] = cos(th) * sin(ph), out[6] = 0, out[7] = 0;
    out[8] = cos(th) * cos(ph), out[9] = sin(th) * cos(ph), out[10] = -sin(ph), out[11] = 0;
    return PC_OK;
}

static int freed;
static void count_free(void *ud) {
    (void)ud;
    freed++;
}

static void test_func_sphere(void **state) {
    (void)state;
    int st, calls = 0;
    pc_surface *s[2];
    s[0] = pc_surface_func(3, 0, M_PI / 2, M_PI / 4, M_PI / 2, sphere_fn, NULL, NULL, &st);
    assert_int_equal(st, PC_OK);
    s[1] = pc_surface_func(3, 0, M_PI / 2, M_PI / 4, M_PI / 2, sphere_fn, count_free, &calls,
                           &st);
    assert_int_equal(st, PC_OK);
    /* the corner table: (Theta, Phi), S, S_Theta, S_Phi, N = S_Theta x S_Phi */
    struct { double th, ph, S[3], Su[3], Sv[3], N[3]; } c[] = {
        {0, M_PI / 2, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {-1, 0, 0}},
        {0, M_PI / 4, {R2, 0, R2}, {0, R2, 0}, {R2, 0, -R2}, {-0.5, 0, -0.5}},
        {M_PI / 2, M_PI / 4, {0, R2, R2}, {-R2, 0, 0}, {0, R2, -R2}, {0, -0.5, -0.5}},
        {M_PI / 2, M_PI / 2, {0, 1, 0}, {-1, 0, 0}, {0, 0, -1}, {0, -1, 0}},
    };
    for (int k = 0; k < 2; k++) {
        double tol = k ? 1e-8 : 1e-15;       /* exact / differenced derivatives */
        for (int i = 0; i < 4; i++) {
            double d[9], N[3], n[3];
            assert_int_equal(pc_surface_partials(s[k], c[i].th, c[i].ph, d), PC_OK);
            near_vec(3, d, c[i].S, 1e-15);
            near_vec(3, d + 3, c[i].Su, tol);
            near_vec(3, d + 6, c[i].Sv, tol);
            pc_cross3(d + 3, d + 6, N);
            near_vec(3, N, c[i].N, tol);
            /* the unit normal points inward: n = -S */
            assert_int_equal(pc_surface_normal(s[k], c[i].th, c[i].ph, n), PC_OK);
            near_vec(3, n, (double[]){-c[i].S[0], -c[i].S[1], -c[i].S[2]}, tol);
        }
        partials_grid(s[k], 1e-8);
    }
    assert_true(calls > 0);
    pc_surface_release(s[0]);
    freed = 0;
    pc_surface_retain(s[1]);
    pc_surface_release(s[1]);
    assert_int_equal(freed, 0);
    pc_surface_release(s[1]);
    assert_int_equal(freed, 1);
}

/* the normal of a plane patch is the plane's: corners in x + 2y + 2z = 3 */
static void test_plane_normal(void **state) {
    (void)state;
    double P00[3] = {3, 0, 0}, P10[3] = {1, 1, 0}, P01[3] = {1, 0, 1}, P11[3] = {-3, 1, 2};
    int st;
    pc_surface *s = pc_surface_bilinear(3, P00, P10, P01, P11, &st);
    assert_int_equal(st, PC_OK);
    /* S_u x S_v at (0,0): (-2,1,0) x (-2,0,1) = (1, 2, 2) */
    for (int i = 0; i <= 4; i++)
        for (int j = 0; j <= 4; j++) {
            double n[3];
            assert_int_equal(pc_surface_normal(s, i / 4.0, j / 4.0, n), PC_OK);
            near_vec(3, n, (double[]){1.0 / 3, 2.0 / 3, 2.0 / 3}, 1e-15);
        }
    pc_surface_release(s);
}

/* maps: the net mapped exactly (even by a projective map), FUNC surfaces wrapped */
static void map_point(const pc_map *f, const double *p, double *out) {
    double h[4] = {p[0], p[1], p[2], 1}, r[PC_MAXDIM + 1];
    for (int i = 0; i <= f->nout; i++) {
        r[i] = 0;
        for (int j = 0; j <= 3; j++) r[i] += PC_MAP_AT(f, i, j) * h[j];
    }
    for (int i = 0; i < f->nout; i++) out[i] = r[i] / r[f->nout];
}

static void test_map(void **state) {
    (void)state;
    pc_map f = {.nin = 3, .nout = 3};
    double m[16] = {1, 0.5, 0, 2, 0, 1, 0.2, -1, 0.3, 0, 1, 0, 0.1, 0.05, 0.02, 1};
    memcpy(f.m, m, sizeof m);
    pc_map g = {.nin = 3, .nout = 2};          /* drop z: a projection to the plane */
    double mg[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1};
    memcpy(g.m, mg, sizeof mg);
    int st;
    pc_surface *src[3] = {octant(), NULL, NULL};
    double xy[8] = {1, 1, 2, 3, 4, 3, 3, 1};
    src[1] = lifted(4, xy, 2);
    src[2] = pc_surface_func(3, 0, M_PI / 2, M_PI / 4, M_PI / 2, sphere_fn, NULL, NULL, &st);
    for (int k = 0; k < 3; k++) {
        pc_surface *t = pc_surface_map(src[k], &f, &st), *t2 = pc_surface_map(src[k], &g, &st);
        assert_non_null(t);
        assert_non_null(t2);
        assert_int_equal(t->kind, k == 2 ? PC_SURF_FUNC : src[k]->kind);
        assert_int_equal(t2->dim, 2);
        for (int i = 0; i <= 5; i++)
            for (int j = 0; j <= 5; j++) {
                double u = src[k]->u0 + (src[k]->u1 - src[k]->u0) * i / 5;
                double v = src[k]->v0 + (src[k]->v1 - src[k]->v0) * j / 5, p[3], q[3];
                assert_int_equal(pc_surface_eval(src[k], u, v, p), PC_OK);
                map_point(&f, p, q);
                eval_is(t, u, v, q, 1e-13);
                eval_is(t2, u, v, p, 1e-15);
            }
        partials_grid(t, 1e-7);
        pc_surface_release(src[k]);           /* the wrapped copies keep what they need */
        double p[3];
        assert_int_equal(pc_surface_eval(t, t->u0, t->v0, p), PC_OK);
        pc_surface_release(t);
        pc_surface_release(t2);
    }
}

/* a rational patch with a zero weight at a corner: that corner is at infinity */
static void test_improper(void **state) {
    (void)state;
    double cp[4 * 3] = {0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 0};   /* (1,1) has weight 0 */
    int st;
    pc_surface *s = pc_surface_bezier(2, 1, 1, cp, &st);
    assert_int_equal(st, PC_OK);
    double p[2], d[6];
    assert_int_equal(pc_surface_eval(s, 1, 1, p), PC_IMPROPER);
    near_vec(2, p, (double[]){1, 1}, 0);     /* the direction */
    assert_int_equal(pc_surface_partials(s, 1, 1, d), PC_IMPROPER);
    eval_is(s, 0.5, 0.5, (double[]){2.0 / 3, 2.0 / 3}, 1e-15);
    pc_surface_release(s);
}

/* Korotky's elliptic dome on a rectangle (korotky_curves_surfaces.md B.7, 4a): the
 * reconstructed z^2/c0^2 = x (2 a0 - x) y (2 b0 - y) / (a0^2 b0^2) over [0, 2a0] x [0, 2b0] is
 * the tensor product of two semi-ellipses whose middle control points are at infinity (C-1
 * with parallel end tangents: W = (0 | 0) + height e_z, weight 0), a rational biquadratic. */
static void test_korotky_dome(void **state) {
    (void)state;
    double a0 = 2, b0 = 1, c0 = 1.5, cp[9 * 4];
    /* per direction: homogeneous abscissa, height factor and weight of the three points */
    double hx[3] = {0, 0, 2 * a0}, hy[3] = {0, 0, 2 * b0}, hz[3] = {0, 1, 0}, w[3] = {1, 0, 1};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double *r = cp + (i * 3 + j) * 4;
            r[0] = hx[i] * w[j], r[1] = hy[j] * w[i], r[2] = c0 * hz[i] * hz[j], r[3] = w[i] * w[j];
        }
    int st;
    pc_surface *s = pc_surface_bezier(3, 2, 2, cp, &st);
    assert_int_equal(st, PC_OK);
    /* the article's numbers (digest C.3, 18): z(2, 1) = 1.5 at the centre, z(1, 0.5) = 1.125
     * where x = 4 s^2 / ((1-s)^2 + s^2) = 1, i.e. s = 1/(1 + sqrt 3), and likewise for y */
    double k = 1 / (1 + sqrt(3));
    eval_is(s, 0.5, 0.5, (double[]){2, 1, 1.5}, 1e-15);
    eval_is(s, k, k, (double[]){1, 0.5, 1.125}, 1e-14);
    double err = 0;
    for (int i = 0; i <= 20; i++)
        for (int j = 0; j <= 20; j++) {
            double p[3];
            assert_int_equal(pc_surface_eval(s, i / 20.0, j / 20.0, p), PC_OK);
            double rhs = p[0] * (2 * a0 - p[0]) * p[1] * (2 * b0 - p[1]) / (a0 * a0 * b0 * b0);
            err = fmax(err, fabs(p[2] * p[2] / (c0 * c0) - rhs));
        }
    assert_true(err < 1e-12);
    /* it rests on the rectangle and touches the prism's faces: along the side x = 0 the
     * normal is horizontal, (-1, 0, 0) */
    eval_is(s, 0, 0.3, (double[]){0, 2 * 0.09 / 0.58, 0}, 1e-15);
    double n[3];
    assert_int_equal(pc_surface_normal(s, 0, 0.3, n), PC_OK);
    near_vec(3, n, (double[]){-1, 0, 0}, 1e-15);
    assert_int_equal(pc_surface_normal(s, 0.4, 1, n), PC_OK);   /* the side y = 2 b0 */
    near_vec(3, n, (double[]){0, 1, 0}, 1e-15);
    partials_grid(s, 1e-8);
    pc_surface_release(s);
}

/* a callback defined on its domain only, without derivatives: S = (u, v, u^2 v^3) */
static int cubic_fn(void *ud, double u, double v, int order, double *out) {
    (void)ud;
    if (order > 0 || u < 0 || u > 1 || v < 0 || v > 2) return PC_EDOMAIN;
    out[0] = u, out[1] = v, out[2] = u * u * v * v * v, out[3] = 1;
    return PC_OK;
}

/* the differences go one-sided at the edges of such a domain */
static void test_func_edges(void **state) {
    (void)state;
    int st;
    pc_surface *s = pc_surface_func(3, 0, 1, 0, 2, cubic_fn, NULL, NULL, &st);
    assert_int_equal(st, PC_OK);
    double uv[5][2] = {{0, 0}, {1, 2}, {0, 1.5}, {0.5, 2}, {0.3, 0.7}};
    for (int k = 0; k < 5; k++) {
        double u = uv[k][0], v = uv[k][1], d[9];
        assert_int_equal(pc_surface_partials(s, u, v, d), PC_OK);
        near_vec(3, d, (double[]){u, v, u * u * v * v * v}, 0);
        near_vec(3, d + 3, (double[]){1, 0, 2 * u * v * v * v}, 1e-8);
        near_vec(3, d + 6, (double[]){0, 1, 3 * u * u * v * v}, 1e-8);
    }
    double p[3];
    assert_int_equal(pc_surface_eval(s, 1.5, 0, p), PC_EDOMAIN);
    pc_surface_release(s);
}

static int fail_fn(void *ud, double u, double v, int order, double *out) {
    (void)ud, (void)v, (void)order;
    out[0] = u, out[1] = 1;
    return u > 0.5 ? PC_EPOLE : PC_OK;
}

static void test_errors(void **state) {
    (void)state;
    double cp[16 * 4] = {0}, nan = NAN;
    for (int k = 0; k < 16; k++) cp[4 * k + 3] = 1;
    int st = PC_OK;
    assert_null(pc_surface_bezier(3, 0, 3, cp, &st));
    assert_int_equal(st, PC_EDIM);
    assert_null(pc_surface_bezier(0, 1, 1, cp, &st));
    assert_int_equal(st, PC_EDIM);
    assert_null(pc_surface_bezier(PC_MAXDIM + 1, 1, 1, cp, &st));
    assert_int_equal(st, PC_EDIM);
    assert_null(pc_surface_bezier(3, PC_CURVE_MAXDEG + 1, 1, cp, &st));
    assert_int_equal(st, PC_EDIM);
    cp[5] = nan;
    assert_null(pc_surface_bezier(3, 3, 3, cp, &st));
    assert_int_equal(st, PC_ENONFINITE);
    cp[5] = INFINITY;
    assert_null(pc_surface_bspline(3, 1, 1, 4, 4, cp, PC_KNOTS_OPEN, NULL, PC_KNOTS_OPEN, NULL,
                                   &st));
    assert_int_equal(st, PC_ENONFINITE);
    cp[5] = 0;
    double P[3] = {0, 0, 0}, Q[3] = {1, nan, 0};
    assert_null(pc_surface_bilinear(3, P, P, Q, P, &st));
    assert_int_equal(st, PC_ENONFINITE);
    double H[12] = {0};
    H[7] = nan;
    assert_null(pc_surface_hermite(3, H, H, H, H, &st));
    assert_int_equal(st, PC_ENONFINITE);
    /* B-spline sizes and knots */
    assert_null(pc_surface_bspline(3, 4, 1, 4, 4, cp, PC_KNOTS_OPEN, NULL, PC_KNOTS_OPEN, NULL,
                                   &st));
    assert_int_equal(st, PC_EDIM);              /* degree 4 needs 5 points */
    pc_surface *s = pc_surface_bspline(3, 4, 1, 4, 4, cp, PC_KNOTS_PERIODIC, NULL,
                                       PC_KNOTS_OPEN, NULL, &st);
    assert_non_null(s);                         /* a periodic one wraps: degree <= points */
    pc_surface_release(s);
    double dec[6] = {0, 0, 1, 0.5, 2, 2}, flat[6] = {1, 1, 1, 1, 1, 1};
    assert_null(pc_surface_bspline(3, 1, 1, 4, 4, cp, PC_KNOTS_GIVEN, dec, PC_KNOTS_OPEN, NULL,
                                   &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_null(pc_surface_bspline(3, 1, 1, 4, 4, cp, PC_KNOTS_OPEN, NULL, PC_KNOTS_GIVEN, flat,
                                   &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_null(pc_surface_bspline(3, 1, 1, 4, 4, cp, PC_KNOTS_OPEN, NULL, PC_KNOTS_GIVEN, NULL,
                                   &st));
    assert_int_equal(st, PC_EARG);
    /* FUNC */
    assert_null(pc_surface_func(3, 1, 1, 0, 1, sphere_fn, NULL, NULL, &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_null(pc_surface_func(3, 0, nan, 0, 1, sphere_fn, NULL, NULL, &st));
    assert_int_equal(st, PC_ENONFINITE);
    assert_null(pc_surface_func(3, 0, 1, 0, 1, NULL, NULL, NULL, &st));
    assert_int_equal(st, PC_EARG);
    /* evaluation */
    s = pc_surface_func(1, 0, 1, 0, 1, fail_fn, NULL, NULL, &st);
    double p[3], d[9];
    assert_int_equal(pc_surface_eval(s, 0.25, 0, p), PC_OK);
    assert_int_equal(pc_surface_eval(s, 0.75, 0, p), PC_EPOLE);
    assert_int_equal(pc_surface_eval(s, nan, 0, p), PC_ENONFINITE);
    assert_int_equal(pc_surface_normal(s, 0.25, 0, p), PC_EDIM);
    pc_surface_map(s, &(pc_map){.nin = 2, .nout = 2}, &st);
    assert_int_equal(st, PC_EDIM);
    pc_surface_release(s);
    s = pc_surface_bilinear(3, P, (double[]){1, 0, 0}, (double[]){0, 1, 0}, (double[]){1, 1, 0},
                            &st);
    assert_int_equal(pc_surface_eval(s, 0, INFINITY, p), PC_ENONFINITE);
    assert_int_equal(pc_surface_partials(s, nan, 0, d), PC_ENONFINITE);
    assert_null(pc_surface_iso(s, 2, 0.5, &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_null(pc_surface_iso(s, 0, nan, &st));
    assert_int_equal(st, PC_ENONFINITE);
    pc_surface_release(s);
    /* a degenerate patch (all four corners on one line) has no normal */
    s = pc_surface_bilinear(3, P, (double[]){1, 0, 0}, (double[]){2, 0, 0}, (double[]){3, 0, 0},
                            &st);
    assert_int_equal(pc_surface_normal(s, 0.5, 0.5, p), PC_EZERO);
    pc_surface_release(s);
    pc_surface_release(NULL);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bilinear),        cmocka_unit_test(test_bezier_buimov),
        cmocka_unit_test(test_sphere_octant),   cmocka_unit_test(test_nurbs_hemisphere),
        cmocka_unit_test(test_bspline_buimov),  cmocka_unit_test(test_bspline_is_bezier),
        cmocka_unit_test(test_nurbs_general),   cmocka_unit_test(test_bspline_periodic),
        cmocka_unit_test(test_hermite_basis),   cmocka_unit_test(test_hermite_corners),
        cmocka_unit_test(test_func_sphere),     cmocka_unit_test(test_plane_normal),
        cmocka_unit_test(test_map),             cmocka_unit_test(test_improper),
        cmocka_unit_test(test_func_edges),      cmocka_unit_test(test_korotky_dome),    cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
