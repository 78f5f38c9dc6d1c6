/* Flattening (curve.h: pc_curve_flatten, pc_curve_flatten_map): for every kind of curve the
 * polyline's vertices lie on the (projected) curve and the curve stays within the tolerance of
 * the polyline, measured at 4000 parameters; a curve through infinity is broken, not drawn
 * across; sub-ranges and extrapolated ranges start and end at the curve's points there. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "curve.h"
#include "spline.h"
#include "fourier.h"

#define SAMPLES 4000

/* the image of c(t) in the plane through m (NULL: c is 2-D); 0 where there is none */
static int image(const pc_curve *c, const pc_map *m, double t, double xy[2]) {
    double h[PC_MAXDIM + 1], o[3];
    if (pc_curve_eval_h(c, t, 0, h) != PC_OK) return 0;
    if (m) pc_map_apply(m, h, o);
    else o[0] = h[0], o[1] = h[1], o[2] = h[2];
    if (o[2] == 0) return 0;
    xy[0] = o[0] / o[2];
    xy[1] = o[1] / o[2];
    return isfinite(xy[0]) && isfinite(xy[1]);
}

static double seg_dist(const double *a, const double *b, const double *q) {
    double vx = b[0] - a[0], vy = b[1] - a[1], wx = q[0] - a[0], wy = q[1] - a[1];
    double l2 = vx * vx + vy * vy, s = l2 > 0 ? (vx * wx + vy * wy) / l2 : 0;
    s = s < 0 ? 0 : (s > 1 ? 1 : s);
    return hypot(wx - s * vx, wy - s * vy);
}

/* the largest distance from the curve over [a, b] to the polyline, and from a vertex to the
 * curve (the nearest of the samples, refined by golden-section search) */
static void deviations(const pc_curve *c, const pc_map *m, double a, double b,
                       const pc_polyline *pl, double *curve_to_pl, double *vertex_to_curve) {
    *curve_to_pl = 0;
    for (int i = 0; i <= SAMPLES; i++) {
        double q[2];
        if (!image(c, m, a + (b - a) * i / SAMPLES, q)) continue;
        double best = INFINITY;
        for (size_t k = 0; k < pl->n; k++) {
            if (k + 1 < pl->n && !pl->move[k + 1])
                best = fmin(best, seg_dist(pl->xy + 2 * k, pl->xy + 2 * k + 2, q));
            best = fmin(best, hypot(q[0] - pl->xy[2 * k], q[1] - pl->xy[2 * k + 1]));
        }
        *curve_to_pl = fmax(*curve_to_pl, best);
    }
    *vertex_to_curve = 0;
    for (size_t k = 0; k < pl->n; k++) {
        const double *v = pl->xy + 2 * k;
        double best = INFINITY, bt = a, q[2];
        for (int i = 0; i <= SAMPLES; i++) {
            double t = a + (b - a) * i / SAMPLES;
            if (image(c, m, t, q) && hypot(q[0] - v[0], q[1] - v[1]) < best)
                best = hypot(q[0] - v[0], q[1] - v[1]), bt = t;
        }
        double lo = fmax(a, bt - (b - a) / SAMPLES), hi = fmin(b, bt + (b - a) / SAMPLES);
        for (int it = 0; it < 60; it++) {    /* the nearest point between the neighbours */
            double t1 = lo + (hi - lo) * 0.382, t2 = lo + (hi - lo) * 0.618, q1[2], q2[2];
            int ok1 = image(c, m, t1, q1), ok2 = image(c, m, t2, q2);
            double d1 = ok1 ? hypot(q1[0] - v[0], q1[1] - v[1]) : INFINITY;
            double d2 = ok2 ? hypot(q2[0] - v[0], q2[1] - v[1]) : INFINITY;
            best = fmin(best, fmin(d1, d2));
            if (d1 < d2) hi = t2; else lo = t1;
        }
        *vertex_to_curve = fmax(*vertex_to_curve, best);
    }
}

/* flatten c over [a, b] both ways and check the tolerance */
static void check_flatten(const pc_curve *c, const pc_map *m, double a, double b, double tol) {
    for (int way = 0; way < 2; way++) {
        pc_polyline pl = {0};
        int st = way == 0 ? pc_curve_flatten_map(c, a, b, m, tol, &pl)
                          : pc_curve_flatten(c, a, b, NULL, NULL, tol, &pl);
        if (way == 1 && m) {   /* the callback form through the same map */
            pc_polyline_free(&pl);
            break;
        }
        assert_int_equal(st, PC_OK);
        assert_true(pl.n >= 2);
        double dev, vdev;
        deviations(c, m, a, b, &pl, &dev, &vdev);
        if (!(dev <= tol * 1.0001 && vdev <= tol * 1e-6 + 1e-9))
            fail_msg("way %d: curve to polyline %g, vertex to curve %g, tol %g (%zu vertices)",
                     way, dev, vdev, tol, pl.n);
        double q[2] = {0, 0};
        assert_true(image(c, m, a, q));
        assert_true(fabs(q[0] - pl.xy[0]) <= 1e-9 * (1 + fabs(q[0])));
        assert_true(image(c, m, b, q));
        assert_true(fabs(q[1] - pl.xy[2 * pl.n - 1]) <= 1e-9 * (1 + fabs(q[1])));
        pc_polyline_free(&pl);
    }
}

static pc_curve *bez(int ncp, const double *xyw) {   /* 2-D, rows of (x, y, w) Cartesian */
    double h[64 * 3];
    for (int i = 0; i < ncp; i++) {
        h[3 * i] = xyw[3 * i] * xyw[3 * i + 2];
        h[3 * i + 1] = xyw[3 * i + 1] * xyw[3 * i + 2];
        h[3 * i + 2] = xyw[3 * i + 2];
    }
    int st;
    pc_curve *c = pc_curve_bezier(2, ncp, h, &st);
    assert_non_null(c);
    return c;
}

static void test_polynomial(void **state) {
    (void)state;
    const double cubic[] = {60, 420, 1, 160, 40, 1, 480, 40, 1, 580, 420, 1};
    pc_curve *c = bez(4, cubic);
    check_flatten(c, NULL, 0, 1, 0.25);
    check_flatten(c, NULL, 0, 1, 0.01);
    check_flatten(c, NULL, 0.3, 0.7, 0.25);          /* a sub-range */
    check_flatten(c, NULL, -0.5, 1.5, 0.25);         /* extrapolated on both sides */
    const double s_shape[] = {0, 0, 1, 100, 100, 1, -100, 100, 1, 0, 200, 1};
    pc_curve *s = bez(4, s_shape);                   /* doubles back on itself */
    check_flatten(s, NULL, 0, 1, 0.25);
    pc_curve_release(c);
    pc_curve_release(s);
    /* a degree-7 B-spline on 12 zigzag points, open knots, the whole domain and part of it */
    double h[12 * 3];
    for (int i = 0; i < 12; i++) {
        h[3 * i] = 40 + 50 * i;
        h[3 * i + 1] = i % 2 ? 80 : 400;
        h[3 * i + 2] = 1;
    }
    int st;
    pc_curve *b = pc_curve_bspline(2, 7, 12, h, PC_KNOTS_OPEN, NULL, &st);
    assert_non_null(b);
    check_flatten(b, NULL, b->t0, b->t1, 0.25);
    check_flatten(b, NULL, b->t0 + 0.3, b->t1 - 0.7, 0.1);
    pc_curve_release(b);
}

static void test_rational(void **state) {
    (void)state;
    /* a quarter of the circle of radius 200: weights (1, cos 45°, 1) */
    const double arc[] = {200, 0, 1, 200, 200, M_SQRT1_2, 0, 200, 1};
    pc_curve *c = bez(3, arc);
    check_flatten(c, NULL, 0, 1, 0.25);
    /* every vertex is on the circle */
    pc_polyline pl = {0};
    assert_int_equal(pc_curve_flatten_map(c, 0, 1, NULL, 0.25, &pl), PC_OK);
    for (size_t k = 0; k < pl.n; k++)
        assert_true(fabs(hypot(pl.xy[2 * k], pl.xy[2 * k + 1]) - 200) < 1e-9);
    pc_polyline_free(&pl);
    pc_curve_release(c);
    /* a NURBS with uneven weights */
    double h[6 * 3];
    const double w[6] = {1, 3, 0.5, 2, 1, 4};
    for (int i = 0; i < 6; i++) {
        h[3 * i] = (30 + 60 * i) * w[i];
        h[3 * i + 1] = (i % 3 ? 50 : 300) * w[i];
        h[3 * i + 2] = w[i];
    }
    int st;
    pc_curve *n = pc_curve_bspline(2, 3, 6, h, PC_KNOTS_OPEN, NULL, &st);
    assert_non_null(n);
    check_flatten(n, NULL, n->t0, n->t1, 0.25);
    pc_curve_release(n);
}

static void test_through_maps(void **state) {
    (void)state;
    /* a 3-D cubic Bezier through an isometric view scaled to pixels, and through a perspective */
    double h[4 * 4] = {0, 0, 0, 1, 1, 0, 2, 1, 2, 2, -1, 1, 3, 1, 1, 1};
    int st;
    pc_curve *c = pc_curve_bezier(3, 4, h, &st);
    assert_non_null(c);
    pc_map iso, scale, m;
    pc_map_isometric(&iso);
    double k[2] = {100, -100};
    pc_map_scale(&scale, 2, k, NULL);
    assert_int_equal(pc_map_compose(&scale, &iso, &m), PC_OK);
    check_flatten(c, &m, 0, 1, 0.25);
    pc_map persp, pm;
    double eye[3] = {8, -6, 5}, p0[3] = {1, 1, 0};
    assert_int_equal(pc_map_perspective(&persp, eye, p0, NULL), PC_OK);
    assert_int_equal(pc_map_compose(&scale, &persp, &pm), PC_OK);
    check_flatten(c, &pm, 0, 1, 0.25);
    assert_int_equal(pc_curve_flatten_map(c, 0, 1, NULL, 0.25, &(pc_polyline){0}), PC_EDIM);
    pc_curve_release(c);
}

static void test_func_kinds(void **state) {
    (void)state;
    /* Fourier curve through 8 points, and a stroke: FUNC curves are sampled */
    const double pts[16] = {300, 100, 400, 150, 450, 250, 400, 350, 300, 400, 200, 350, 150, 250, 200, 150};
    int st;
    pc_curve *f = pc_curve_fourier(2, 4, pts, &st);
    assert_non_null(f);
    check_flatten(f, NULL, f->t0, f->t1, 0.25);
    pc_curve_release(f);
    double nodes[8] = {100, 100, 300, 50, 400, 300, 200, 400};
    pc_stroke_spec spec = {.d = 2, .nnodes = 4, .closed = 0, .nodes = nodes};
    pc_piece pieces[3];
    int bad;
    assert_int_equal(pc_stroke_build(&spec, pieces, &bad), PC_OK);
    pc_curve *s = pc_curve_stroke(2, 3, pieces, 0, &st);
    assert_non_null(s);
    check_flatten(s, NULL, s->t0, s->t1, 0.25);
    pc_curve_release(s);
}

static void test_infinity(void **state) {
    (void)state;
    /* weights (1, -1, 1): the weight (1 - 2t)^2 vanishes at t = 1/2, where the curve runs off
     * to infinity and comes back: two pieces, neither crossing the picture */
    const double hyp[] = {100, 0, 1, 0, 0, -1, 0, 100, 1};
    pc_curve *c = bez(3, hyp);
    pc_polyline pl = {0};
    assert_int_equal(pc_curve_flatten_map(c, 0, 1, NULL, 0.25, &pl), PC_OK);
    int pieces = 0;
    for (size_t k = 0; k < pl.n; k++) pieces += k == 0 || pl.move[k];
    assert_int_equal(pieces, 2);
    pc_polyline_free(&pl);
    pc_curve_release(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_polynomial), cmocka_unit_test(test_rational),
        cmocka_unit_test(test_through_maps), cmocka_unit_test(test_func_kinds),
        cmocka_unit_test(test_infinity),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
