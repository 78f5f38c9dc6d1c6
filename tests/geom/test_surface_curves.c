/* Surfaces and curves together: exact iso-curves of tensor patches (the boundary curves are
 * the Bezier curves of the boundary rows), ruled surfaces, linear Coons patches on curved
 * (rational) boundaries (Buimov §5.3, §5.4, §9.2 vector 35), surfaces of revolution,
 * FUNC iso-curves, and the references the surfaces hold. */
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

static void hrow(double *r, double x, double y, double z, double w) {
    r[0] = x * w, r[1] = y * w, r[2] = z * w, r[3] = w;
}

static void eval_is(const pc_surface *s, double u, double v, const double *want, double tol) {
    double p[PC_MAXDIM];
    assert_int_equal(pc_surface_eval(s, u, v, p), PC_OK);
    near_vec(s->dim, p, want, tol);
}

/* the largest distance between S along an edge and the curve c over 101 parameters:
 * dir 0: S(value, v) against c, dir 1: S(u, value); both domains mapped onto [0, 1] */
static double edge_error(const pc_surface *s, int dir, double value, const pc_curve *c) {
    double err = 0;
    for (int k = 0; k <= 100; k++) {
        double x = k / 100.0, t = (1 - x) * c->t0 + x * c->t1, p[3], q[3];
        double y = dir == 0 ? (1 - x) * s->v0 + x * s->v1 : (1 - x) * s->u0 + x * s->u1;
        assert_int_equal(pc_curve_eval(c, t, q), PC_OK);
        assert_int_equal(dir == 0 ? pc_surface_eval(s, value, y, p)
                                  : pc_surface_eval(s, y, value, p),
                         PC_OK);
        err = fmax(err, pc_dist(s->dim, p, q));
    }
    return err;
}

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

static void partials_grid(const pc_surface *s, double tol) {
    for (int i = 0; i <= 4; i++)
        for (int j = 0; j <= 4; j++)
            partials_match(s, s->u0 + (s->u1 - s->u0) * (0.0613 + 0.877 * i / 4),
                           s->v0 + (s->v1 - s->v0) * (0.0613 + 0.877 * j / 4), tol);
}

/* a circular arc as a rational quadratic: from a to b with the tangents meeting at m,
 * middle weight w (cos of half the arc's angle) */
static pc_curve *arc(const double *a, const double *m, const double *b, double w) {
    double cp[12];
    hrow(cp, a[0], a[1], a[2], 1);
    hrow(cp + 4, m[0], m[1], m[2], w);
    hrow(cp + 8, b[0], b[1], b[2], 1);
    int st;
    pc_curve *c = pc_curve_bezier(3, 3, cp, &st);
    assert_int_equal(st, PC_OK);
    return c;
}

static pc_curve *line(const double *a, const double *b) {
    double cp[8];
    hrow(cp, a[0], a[1], a[2], 1);
    hrow(cp + 4, b[0], b[1], b[2], 1);
    int st;
    pc_curve *c = pc_curve_bezier(3, 2, cp, &st);
    assert_int_equal(st, PC_OK);
    return c;
}

/* --- iso-curves of tensor patches ------------------------------------------------------------ */

static pc_surface *buimov_net(void) {
    double cp[16 * 4];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            hrow(cp + (i * 4 + j) * 4, i + 0.1 * j * j, j, (i == 1 || i == 2) && (j == 1 || j == 2),
                 1 + 0.2 * ((i * 3 + j) % 4));      /* rational: uneven weights */
    int st;
    pc_surface *s = pc_surface_bezier(3, 3, 3, cp, &st);
    assert_int_equal(st, PC_OK);
    return s;
}

/* the iso-curve (dir, value) against the surface, points and first derivatives */
static void iso_matches(pc_surface *s, int dir, double value, pc_curve_kind kind) {
    int st;
    pc_curve *c = pc_surface_iso(s, dir, value, &st);
    assert_non_null(c);
    assert_int_equal(st, PC_OK);
    assert_int_equal(c->kind, kind);
    NEAR(c->t0, dir == 0 ? s->v0 : s->u0, 0);
    NEAR(c->t1, dir == 0 ? s->v1 : s->u1, 0);
    for (int k = 0; k <= 50; k++) {
        double t = c->t0 + (c->t1 - c->t0) * k / 50, d[9], e[6];
        double u = dir == 0 ? value : t, v = dir == 0 ? t : value;
        assert_int_equal(pc_surface_partials(s, u, v, d), PC_OK);
        assert_int_equal(pc_curve_derivs(c, t, 1, e), PC_OK);
        near_vec(3, e, d, 1e-13);
        near_vec(3, e + 3, d + (dir == 0 ? 6 : 3), kind == PC_CURVE_FUNC ? 1e-7 : 1e-12);
    }
    pc_curve_release(c);
}

static void test_bezier_iso(void **state) {
    (void)state;
    pc_surface *s = buimov_net();
    int st, m = 4;
    /* the four boundaries are the Bezier curves of the boundary rows and columns, exactly */
    for (int e = 0; e < 4; e++) {
        int dir = e >> 1, end = e & 1;
        double row[4 * 4];
        for (int k = 0; k < 4; k++) {
            int i = dir == 0 ? 3 * end : k, j = dir == 0 ? k : 3 * end;
            memcpy(row + k * m, s->cp + (i * 4 + j) * m, (size_t)m * sizeof *row);
        }
        pc_curve *b = pc_curve_bezier(3, 4, row, &st), *c = pc_surface_iso(s, dir, end, &st);
        assert_non_null(c);
        assert_int_equal(c->ncp, 4);
        near_vec(16, c->cp, row, 0);           /* the very control points */
        assert_true(edge_error(s, dir, end, b) < 1e-14);
        pc_curve_release(b);
        pc_curve_release(c);
    }
    for (double x = 0.1; x < 1; x += 0.2) {
        iso_matches(s, 0, x, PC_CURVE_BEZIER);
        iso_matches(s, 1, x, PC_CURVE_BEZIER);
    }
    pc_surface_release(s);
}

static void test_bspline_iso(void **state) {
    (void)state;
    enum { NU = 5, NV = 4 };
    double uk[NU + 3] = {0, 0, 0, 0.3, 0.5, 1.2, 1.2, 1.2}, cp[NU * NV * 4];
    for (int i = 0; i < NU; i++)
        for (int j = 0; j < NV; j++)
            hrow(cp + (i * NV + j) * 4, i + 0.3 * j, j - 0.2 * i * i, sin(i + 2.0 * j),
                 0.5 + 0.25 * ((i + j) % 3));
    int st;
    pc_surface *s = pc_surface_bspline(3, 2, 3, NU, NV, cp, PC_KNOTS_GIVEN, uk,
                                       PC_KNOTS_PERIODIC, NULL, &st);
    assert_int_equal(st, PC_OK);
    for (int k = 0; k <= 6; k++) {
        iso_matches(s, 0, 1.2 * k / 6, PC_CURVE_BSPLINE);
        iso_matches(s, 1, s->v0 + (s->v1 - s->v0) * k / 6, PC_CURVE_BSPLINE);
    }
    /* the boundary u = 0 is the periodic B-spline curve of the first row */
    pc_curve *b = pc_curve_bspline(3, 3, NV, cp, PC_KNOTS_PERIODIC, NULL, &st);
    assert_non_null(b);
    assert_true(edge_error(s, 0, 0, b) < 1e-14);
    pc_curve_release(b);
    pc_surface_release(s);
}

/* --- ruled ------------------------------------------------------------------------------------ */

static void test_ruled(void **state) {
    (void)state;
    double A[3] = {1, 0, 0}, M[3] = {1, 1, 0}, B[3] = {0, 1, 0};
    pc_curve *c0 = arc(A, M, B, R2);         /* the quarter of the unit circle at z = 0 */
    double cp[4 * 4];                        /* a cubic at z = 2 over [0, 1] */
    hrow(cp, 2, 0, 2, 1), hrow(cp + 4, 2, 1, 2.5, 1), hrow(cp + 8, 1, 2, 2, 1);
    hrow(cp + 12, 0, 2, 2, 1);
    int st;
    pc_curve *c1 = pc_curve_bezier(3, 4, cp, &st);
    pc_surface *s = pc_surface_ruled(c0, c1, &st);
    assert_non_null(s);
    assert_int_equal(st, PC_OK);
    pc_curve_release(c0);                    /* the surface holds its own references */
    pc_curve_release(c1);
    assert_true(edge_error(s, 1, 0, s->curves[0]) < 1e-14);
    assert_true(edge_error(s, 1, 1, s->curves[1]) < 1e-14);
    eval_is(s, 0, 0, A, 0);
    eval_is(s, 1, 0, B, 0);
    eval_is(s, 0, 1, (double[]){2, 0, 2}, 0);
    eval_is(s, 1, 1, (double[]){0, 2, 2}, 0);
    /* the rulings are straight: S(u, 0.25) = 0.75 C0 + 0.25 C1 */
    double p[3], q[3];
    assert_int_equal(pc_curve_eval(s->curves[0], 0.4, p), PC_OK);
    assert_int_equal(pc_curve_eval(s->curves[1], 0.4, q), PC_OK);
    eval_is(s, 0.4, 0.25, (double[]){0.75 * p[0] + 0.25 * q[0], 0.75 * p[1] + 0.25 * q[1],
                                     0.75 * p[2] + 0.25 * q[2]}, 1e-15);
    partials_grid(s, 1e-8);
    /* its iso-curves are FUNC curves that follow it */
    iso_matches(s, 0, 0.3, PC_CURVE_FUNC);
    iso_matches(s, 1, 0.7, PC_CURVE_FUNC);
    pc_curve *iso = pc_surface_iso(s, 1, 0, &st);
    pc_surface_release(s);                   /* the iso-curve keeps the surface */
    assert_int_equal(pc_curve_eval(iso, 0.5, p), PC_OK);
    near_vec(3, p, (double[]){R2, R2, 0}, 1e-15);
    double d[9];
    assert_int_equal(pc_curve_derivs(iso, 0.5, 2, d), PC_OK);   /* the core differences */
    NEAR(pc_dot(3, d, d + 6), -pc_dot(3, d + 3, d + 3), 1e-4);  /* |C| = 1: C.C'' = -|C'|^2 */
    pc_curve_release(iso);
    /* dimensions must agree */
    double cp2[6] = {0, 0, 1, 1, 1, 1};
    pc_curve *flat = pc_curve_bezier(2, 2, cp2, &st);
    c0 = arc(A, M, B, R2);
    assert_null(pc_surface_ruled(c0, flat, &st));
    assert_int_equal(st, PC_EDIM);
    assert_null(pc_surface_ruled(c0, NULL, &st));
    assert_int_equal(st, PC_EARG);
    pc_curve_release(flat);
    pc_curve_release(c0);
}

/* --- Coons ------------------------------------------------------------------------------------ */

/* Buimov 35: P(u,0) = (u, 0, sin pi u), P(u,1) = (u, 1, 0), P(0,w) = (0, w, 0), P(1,w) = (1, w, 0) */
static int sine_fn(void *ud, double t, int order, double *out) {
    (void)ud;
    out[0] = t, out[1] = 0, out[2] = sin(M_PI * t), out[3] = 1;
    if (order >= 1) out[4] = 1, out[5] = 0, out[6] = M_PI * cos(M_PI * t), out[7] = 0;
    if (order >= 2) out[8] = 0, out[9] = 0, out[10] = -M_PI * M_PI * sin(M_PI * t), out[11] = 0;
    return PC_OK;
}

static void test_coons_buimov(void **state) {
    (void)state;
    int st;
    double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, Y[3] = {0, 1, 0}, XY[3] = {1, 1, 0};
    pc_curve *cu0 = pc_curve_func(3, 0, 1, 0, sine_fn, NULL, NULL, &st);
    pc_curve *cu1 = line(Y, XY), *c0v = line(O, Y), *c1v = line(X, XY);
    pc_surface *s = pc_surface_coons(cu0, cu1, c0v, c1v, &st);
    assert_non_null(s);
    assert_int_equal(st, PC_OK);
    eval_is(s, 0.5, 0.5, (double[]){0.5, 0.5, 0.5}, 1e-15);
    eval_is(s, 0.25, 0.5, (double[]){0.25, 0.5, 0.353553}, 1e-6);
    eval_is(s, 0.25, 0.5, (double[]){0.25, 0.5, sin(M_PI / 4) / 2}, 1e-15);
    eval_is(s, 0.5, 0, (double[]){0.5, 0, 1}, 1e-15);
    eval_is(s, 0, 0, O, 0);
    eval_is(s, 1, 1, XY, 0);
    partials_grid(s, 1e-8);
    pc_surface_release(s);
    pc_curve_release(cu0), pc_curve_release(cu1), pc_curve_release(c0v), pc_curve_release(c1v);
}

/* curved boundaries: three circle arcs (rational quadratics) and a B-spline over [0, 3] */
static void test_coons_arcs(void **state) {
    (void)state;
    int st;
    double P00[3] = {0, 0, 0}, P10[3] = {1, 0, 0}, P01[3] = {0, 1, 0}, P11[3] = {1, 1, 0};
    /* a quarter circle over P00 P10 in y = 0 (centre (0.5, 0, -0.5)), a third of a circle
     * over P01 P11 in y = 1 (120 degrees: weight cos 60, the tangents meet at height
     * 0.5 tan 60), a quarter circle below P00 P01 in x = 0 */
    pc_curve *cu0 = arc(P00, (double[]){0.5, 0, 0.5}, P10, R2);
    pc_curve *cu1 = arc(P01, (double[]){0.5, 1, 0.5 * sqrt(3)}, P11, 0.5);
    pc_curve *c0v = arc(P00, (double[]){0, 0.5, -0.5}, P01, R2);
    double cp[5 * 4];
    hrow(cp, 1, 0, 0, 1), hrow(cp + 4, 1, 0.2, 0.4, 1), hrow(cp + 8, 1.3, 0.5, 0.1, 2);
    hrow(cp + 12, 1, 0.8, -0.3, 1), hrow(cp + 16, 1, 1, 0, 1);
    pc_curve *c1v = pc_curve_bspline(3, 2, 5, cp, PC_KNOTS_OPEN, NULL, &st);
    assert_non_null(c1v);
    NEAR(c1v->t1, 3, 0);
    pc_surface *s = pc_surface_coons(cu0, cu1, c0v, c1v, &st);
    assert_non_null(s);
    assert_int_equal(st, PC_OK);
    /* the four boundaries, exactly */
    assert_true(edge_error(s, 1, 0, cu0) < 1e-12);
    assert_true(edge_error(s, 1, 1, cu1) < 1e-12);
    assert_true(edge_error(s, 0, 0, c0v) < 1e-12);
    assert_true(edge_error(s, 0, 1, c1v) < 1e-12);
    /* and they are circles: the edge v = 0 keeps its distance from the centre */
    for (int k = 0; k <= 20; k++) {
        double p[3];
        assert_int_equal(pc_surface_eval(s, k / 20.0, 0, p), PC_OK);
        NEAR(pc_dist(3, p, (double[]){0.5, 0, -0.5}), R2, 1e-15);
        assert_int_equal(pc_surface_eval(s, k / 20.0, 1, p), PC_OK);
        NEAR(pc_dist(3, p, (double[]){0.5, 1, -0.5 / sqrt(3)}), 1 / sqrt(3), 1e-15);
    }
    eval_is(s, 0, 0, P00, 1e-15);
    eval_is(s, 1, 0, P10, 1e-15);
    eval_is(s, 0, 1, P01, 1e-15);
    eval_is(s, 1, 1, P11, 1e-15);
    partials_grid(s, 1e-8);
    iso_matches(s, 0, 0.35, PC_CURVE_FUNC);
    iso_matches(s, 1, 0.8, PC_CURVE_FUNC);
    /* along an edge the cross derivative of the boolean sum blends the side tangents:
     * S_v(u, 0) = C1v(0)... checked through differences above; the u-derivative on v = 0 is
     * the curve's own (times its domain length) */
    double d[9], e[6];
    assert_int_equal(pc_surface_partials(s, 0.3, 0, d), PC_OK);
    assert_int_equal(pc_curve_derivs(cu0, 0.3, 1, e), PC_OK);
    near_vec(3, d + 3, e + 3, 1e-13);
    assert_int_equal(pc_surface_partials(s, 1, 0.5, d), PC_OK);
    assert_int_equal(pc_curve_derivs(c1v, 1.5, 1, e), PC_OK);
    near_vec(3, d + 6, (double[]){3 * e[3], 3 * e[4], 3 * e[5]}, 1e-13);

    /* corners that do not meet */
    pc_curve *off = arc(P01, (double[]){0.5, 1, 0.5}, (double[]){1, 1, 1e-6}, R2);
    assert_null(pc_surface_coons(cu0, off, c0v, c1v, &st));
    assert_int_equal(st, PC_EDOMAIN);
    pc_curve_release(off);
    /* but rounding is no mismatch: 1e-12 off is within the relative 1e-9 */
    off = arc(P01, (double[]){0.5, 1, 0.5}, (double[]){1, 1, 1e-12}, R2);
    pc_surface *s2 = pc_surface_coons(cu0, off, c0v, c1v, &st);
    assert_non_null(s2);
    pc_surface_release(s2);
    pc_curve_release(off);
    assert_null(pc_surface_coons(cu0, cu1, c0v, NULL, &st));
    assert_int_equal(st, PC_EARG);
    /* the curves are held: release ours, the patch still evaluates */
    pc_curve_release(cu0), pc_curve_release(cu1), pc_curve_release(c0v), pc_curve_release(c1v);
    eval_is(s, 0.5, 0, (double[]){0.5, 0, R2 - 0.5}, 1e-15);
    pc_surface_release(s);
}

/* --- revolution ------------------------------------------------------------------------------- */

/* the distance of p from the axis through a with the unit direction k, and its abscissa */
static void axis_coords(const double *a, const double *k, const double *p, double *r, double *h) {
    double q[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]}, c[3];
    *h = pc_dot(3, q, k);
    pc_cross3(k, q, c);
    *r = pc_norm(3, c);
}

static void test_revolution(void **state) {
    (void)state;
    int st;
    double cp[4 * 4];
    hrow(cp, 2, 0, 0, 1), hrow(cp + 4, 3, 1, 0.5, 2), hrow(cp + 8, 1, 2, 1, 1);
    hrow(cp + 12, 1.5, 3, -1, 1);
    pc_curve *prof = pc_curve_bezier(3, 4, cp, &st);
    double a[3] = {1, 2, 0}, d[3] = {0, 1, 2}, k[3] = {0, 1 / sqrt(5), 2 / sqrt(5)};
    pc_surface *s = pc_surface_revolution(prof, a, d, 0, 2 * M_PI, &st);
    assert_non_null(s);
    assert_int_equal(st, PC_OK);
    pc_curve_release(prof);
    prof = s->curves[0];
    assert_true(edge_error(s, 1, 0, prof) < 1e-14);          /* v = 0 is the profile */
    assert_true(edge_error(s, 1, 2 * M_PI, prof) < 1e-14);   /* and so is a whole turn */
    double err = 0;
    for (int i = 0; i <= 20; i++) {
        double c[3], r0, h0;
        assert_int_equal(pc_curve_eval(prof, i / 20.0, c), PC_OK);
        axis_coords(a, k, c, &r0, &h0);
        for (int j = 0; j <= 24; j++) {
            double p[3], r, h, v = 2 * M_PI * j / 24;
            assert_int_equal(pc_surface_eval(s, i / 20.0, v, p), PC_OK);
            axis_coords(a, k, p, &r, &h);
            err = fmax(err, fmax(fabs(r - r0), fabs(h - h0)));
            /* the same as the map turning space about the axis */
            pc_map f;
            double q[4], hc[4] = {c[0], c[1], c[2], 1};
            assert_int_equal(pc_map_rotate3(&f, a, d, v), PC_OK);
            pc_map_apply(&f, hc, q);
            near_vec(3, p, q, 1e-14);
        }
    }
    assert_true(err < 1e-14);                                /* radius and height kept */
    partials_grid(s, 1e-7);
    /* S_v = k x (S - a): perpendicular to the axis and to the radius, of length r */
    double D[9], n[3];
    assert_int_equal(pc_surface_partials(s, 0.4, 1.0, D), PC_OK);
    double q[3] = {D[0] - a[0], D[1] - a[1], D[2] - a[2]}, r, h;
    axis_coords(a, k, D, &r, &h);
    NEAR(pc_dot(3, D + 6, k), 0, 1e-15);
    NEAR(pc_dot(3, D + 6, q), 0, 1e-14);
    NEAR(pc_norm(3, D + 6), r, 1e-14);
    assert_int_equal(pc_surface_normal(s, 0.4, 1.0, n), PC_OK);
    NEAR(pc_dot(3, n, D + 3), 0, 1e-14);
    NEAR(pc_dot(3, n, D + 6), 0, 1e-14);
    /* the iso-curve u = const is a parallel circle, closed over the whole turn */
    pc_curve *c = pc_surface_iso(s, 0, 0.4, &st);
    assert_non_null(c);
    assert_true(c->closed);
    for (int j = 0; j <= 12; j++) {
        double p[3], rr, hh;
        assert_int_equal(pc_curve_eval(c, 2 * M_PI * j / 12, p), PC_OK);
        axis_coords(a, k, p, &rr, &hh);
        NEAR(rr, r, 1e-14);
        NEAR(hh, h, 1e-14);
    }
    pc_curve_release(c);
    pc_surface_release(s);
}

/* right-handed: (1, 0, 0) about +z by a quarter turn is (0, 1, 0); a circle turned about a
 * diameter is the unit sphere */
static void test_revolution_sphere(void **state) {
    (void)state;
    int st;
    double cp[5 * 4];   /* the half circle x >= 0 in the xz-plane, two quarters: 0 .. 2 */
    hrow(cp, 0, 0, -1, 1), hrow(cp + 4, 1, 0, -1, R2), hrow(cp + 8, 1, 0, 0, 1);
    hrow(cp + 12, 1, 0, 1, R2), hrow(cp + 16, 0, 0, 1, 1);
    pc_curve *half = pc_curve_bezier_pieces(3, 2, 2, cp, NULL, &st);
    assert_non_null(half);
    double o[3] = {0, 0, 0}, z[3] = {0, 0, 3};
    pc_surface *s = pc_surface_revolution(half, o, z, -M_PI, M_PI, &st);
    assert_non_null(s);
    NEAR(s->u1, 2, 0);
    eval_is(s, 1, M_PI / 2, (double[]){0, 1, 0}, 1e-15);
    eval_is(s, 1, -M_PI / 2, (double[]){0, -1, 0}, 1e-15);
    double err = 0;
    for (int i = 0; i <= 40; i++)
        for (int j = 0; j <= 40; j++) {
            double p[3], n[3];
            assert_int_equal(pc_surface_eval(s, i / 20.0, -M_PI + 2 * M_PI * j / 40, p), PC_OK);
            err = fmax(err, fabs(pc_norm(3, p) - 1));
            if (i == 0 || i == 40) continue;
            assert_int_equal(pc_surface_normal(s, i / 20.0, -M_PI + 2 * M_PI * j / 40, n), PC_OK);
            err = fmax(err, fabs(fabs(pc_dot(3, n, p)) - 1));
        }
    assert_true(err < 1e-12);
    double n[3];
    assert_int_equal(pc_surface_normal(s, 0, 0.3, n), PC_EZERO);   /* the pole */
    /* a meridian is a FUNC curve that breaks where the profile's pieces meet */
    pc_curve *mer = pc_surface_iso(s, 1, 0.7, &st);
    assert_non_null(mer);
    assert_int_equal(mer->nknots, 3);
    near_vec(3, mer->knots, (double[]){0, 1, 2}, 0);
    pc_curve_release(mer);
    pc_surface_release(s);

    /* errors: a zero axis, a plane profile, NaN, an empty range of angles */
    double zero[3] = {0, 0, 0}, bad[3] = {0, NAN, 1};
    assert_null(pc_surface_revolution(half, o, zero, 0, 1, &st));
    assert_int_equal(st, PC_EZERO);
    assert_null(pc_surface_revolution(half, bad, z, 0, 1, &st));
    assert_int_equal(st, PC_ENONFINITE);
    assert_null(pc_surface_revolution(half, o, z, 0, NAN, &st));
    assert_int_equal(st, PC_ENONFINITE);
    assert_null(pc_surface_revolution(half, o, z, 1, 1, &st));
    assert_int_equal(st, PC_EDOMAIN);
    double cp2[6] = {1, 0, 1, 2, 1, 1};
    pc_curve *flat = pc_curve_bezier(2, 2, cp2, &st);
    assert_null(pc_surface_revolution(flat, o, z, 0, 1, &st));
    assert_int_equal(st, PC_EDIM);
    pc_curve_release(flat);
    pc_curve_release(half);
}

/* maps of curve-based surfaces are wrapped: the image of every point */
static void test_map_wrapped(void **state) {
    (void)state;
    int st;
    double A[3] = {1, 0, 0}, M[3] = {1, 1, 0}, B[3] = {0, 1, 0}, C[3] = {0, 0, 2};
    pc_curve *c0 = arc(A, M, B, R2), *c1 = line(C, (double[]){1, 1, 2});
    pc_surface *s = pc_surface_ruled(c0, c1, &st);
    pc_map f;
    assert_int_equal(pc_map_perspective(&f, (double[]){5, 4, 3}, (double[]){0, 0, 0}, NULL),
                     PC_OK);
    pc_surface *t = pc_surface_map(s, &f, &st);
    assert_non_null(t);
    assert_int_equal(t->dim, 2);
    for (int i = 0; i <= 10; i++)
        for (int j = 0; j <= 10; j++) {
            double p[3], h[4], q[3], w[3];
            assert_int_equal(pc_surface_eval(s, i / 10.0, j / 10.0, p), PC_OK);
            memcpy(h, p, sizeof p), h[3] = 1;
            pc_map_apply(&f, h, q);
            w[0] = q[0] / q[2], w[1] = q[1] / q[2];
            eval_is(t, i / 10.0, j / 10.0, w, 1e-13);
        }
    partials_grid(t, 1e-7);
    pc_surface_release(s);
    pc_surface_release(t);
    pc_curve_release(c0);
    pc_curve_release(c1);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bezier_iso),    cmocka_unit_test(test_bspline_iso),
        cmocka_unit_test(test_ruled),         cmocka_unit_test(test_coons_buimov),
        cmocka_unit_test(test_coons_arcs),    cmocka_unit_test(test_revolution),
        cmocka_unit_test(test_revolution_sphere), cmocka_unit_test(test_map_wrapped),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
