/* The one curve type (curve.h): evaluation against explicit formulas and the books' vectors
 * (Buimov §4.3, §4.4), B-splines against Bezier curves, knot insertion, split and sub-curves,
 * exact derivatives against finite differences for every kind, conics, arc length, bounding
 * boxes, maps, reference counting, and every error status.  Tolerances are stated per test. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "curve.h"
#include "spline.h"
#include "fourier.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

/* a deterministic pseudo-random number in [-1, 1) */
static double rnd(unsigned *s) {
    *s = *s * 1103515245u + 12345u;
    return ((*s >> 8) & 0xffff) / 32768.0 - 1;
}

static double binom(int n, int k) {
    double r = 1;
    for (int i = 1; i <= k; i++) r = r * (n - k + i) / i;
    return r;
}

static pc_curve *bez2(int ncp, const double *xy) {     /* 2-D polynomial Bezier from (x, y) pairs */
    double cp[3 * 70];
    for (int i = 0; i < ncp; i++) {
        cp[3 * i] = xy[2 * i];
        cp[3 * i + 1] = xy[2 * i + 1];
        cp[3 * i + 2] = 1;
    }
    int st;
    pc_curve *c = pc_curve_bezier(2, ncp, cp, &st);
    assert_int_equal(st, PC_OK);
    return c;
}


/* --- Bezier ---------------------------------------------------------------------------------- */
/* de Casteljau (homogeneous, rational) against the explicit Bernstein sum, degrees 1..10, t in
 * [-0.25, 1.25] (extrapolation included): relative error 1e-12 */
static void test_bezier_bernstein(void **state) {
    (void)state;
    unsigned s = 1;
    for (int deg = 1; deg <= 10; deg++) {
        double cp[11 * 4];
        for (int i = 0; i <= deg; i++) {
            for (int x = 0; x < 3; x++) cp[i * 4 + x] = 10 * rnd(&s);
            cp[i * 4 + 3] = 1 + 0.5 * rnd(&s);      /* weights in [0.5, 1.5] */
            for (int x = 0; x < 3; x++) cp[i * 4 + x] *= cp[i * 4 + 3];
        }
        int st;
        pc_curve *c = pc_curve_bezier(3, deg + 1, cp, &st);
        assert_non_null(c);
        assert_int_equal(c->degree, deg);
        for (int k = 0; k <= 60; k++) {
            double t = -0.25 + 1.5 * k / 60, h[4], sum[4] = {0, 0, 0, 0};
            for (int i = 0; i <= deg; i++) {
                double b = binom(deg, i) * pow(1 - t, deg - i) * pow(t, i);
                for (int x = 0; x < 4; x++) sum[x] += b * cp[i * 4 + x];
            }
            assert_int_equal(pc_curve_eval_h(c, t, 0, h), PC_OK);
            for (int x = 0; x < 4; x++) NEAR(h[x], sum[x], 1e-12 * (1 + fabs(sum[x])));
            double p[3];
            assert_int_equal(pc_curve_eval(c, t, p), PC_OK);
            for (int x = 0; x < 3; x++) NEAR(p[x], sum[x] / sum[3], 1e-11 * (1 + fabs(p[x])));
        }
        pc_curve_release(c);
    }
}

/* Buimov §4.3 / test vectors 28: the cubic on (1,1), (2,3), (4,3), (3,1); 1e-12 */
static void test_bezier_buimov(void **state) {
    (void)state;
    const double xy[8] = {1, 1, 2, 3, 4, 3, 3, 1};
    pc_curve *c = bez2(4, xy);
    double p[6];
    assert_int_equal(pc_curve_eval(c, 0.5, p), PC_OK);
    NEAR(p[0], 2.75, 1e-12);
    NEAR(p[1], 2.5, 1e-12);
    assert_int_equal(pc_curve_eval(c, 0.15, p), PC_OK);
    NEAR(p[0], 1.504, 1e-12);
    NEAR(p[1], 1.765, 1e-12);
    assert_int_equal(pc_curve_eval(c, 0.85, p), PC_OK);
    NEAR(p[0], 3.261, 1e-12);
    NEAR(p[1], 1.765, 1e-12);
    /* P(1/3) = 8/27 P0 + 4/9 P1 + 2/9 P2 + 1/27 P3 */
    assert_int_equal(pc_curve_eval(c, 1.0 / 3, p), PC_OK);
    NEAR(p[0], 8.0 / 27 + 8.0 / 9 + 8.0 / 9 + 3.0 / 27, 1e-12);
    assert_int_equal(pc_curve_derivs(c, 0, 1, p), PC_OK);
    NEAR(p[2], 3, 1e-12);
    NEAR(p[3], 6, 1e-12);
    assert_int_equal(pc_curve_derivs(c, 1, 1, p), PC_OK);
    NEAR(p[2], -3, 1e-12);
    NEAR(p[3], -6, 1e-12);
    pc_curve_release(c);
}

/* --- B-splines --------------------------------------------------------------------------------- */
static pc_curve *bspl2(int deg, int ncp, const double *xy, pc_knot_kind kk, const double *knots) {
    double cp[3 * 64];
    for (int i = 0; i < ncp; i++) {
        cp[3 * i] = xy[2 * i];
        cp[3 * i + 1] = xy[2 * i + 1];
        cp[3 * i + 2] = 1;
    }
    int st;
    pc_curve *c = pc_curve_bspline(2, deg, ncp, cp, kk, knots, &st);
    assert_int_equal(st, PC_OK);
    return c;
}

/* order k (degree k-1) on k points with open knots is the Bezier curve: k = 2..9, 1e-12 */
static void test_bspline_is_bezier(void **state) {
    (void)state;
    unsigned s = 7;
    for (int k = 2; k <= 9; k++) {
        double xy[18];
        for (int i = 0; i < 2 * k; i++) xy[i] = 5 * rnd(&s);
        pc_curve *b = bspl2(k - 1, k, xy, PC_KNOTS_OPEN, NULL), *z = bez2(k, xy);
        NEAR(b->t0, 0, 0);
        NEAR(b->t1, 1, 0);
        for (int i = 0; i <= 100; i++) {
            double t = -0.1 + 1.2 * i / 100, p[6], q[6];
            assert_int_equal(pc_curve_derivs(b, t, 2, p), PC_OK);
            assert_int_equal(pc_curve_derivs(z, t, 2, q), PC_OK);
            for (int x = 0; x < 6; x++) NEAR(p[x], q[x], 1e-10 * (1 + fabs(q[x])));
        }
        pc_curve_release(b);
        pc_curve_release(z);
    }
}

/* Buimov §4.4 / test vectors 29-32 (1e-12; Fig. 4.9 to the printed 4 decimals) */
static void test_bspline_buimov(void **state) {
    (void)state;
    const double P[8] = {1, 1, 2, 3, 4, 3, 3, 1};
    double p[2];
    /* k = 2, knots [0 0 1 2 3 3]: the polygon, t = 0, 0.5, ..., 3 (t = t_max gives P3) */
    pc_curve *c = bspl2(1, 4, P, PC_KNOTS_OPEN, NULL);
    const double k2[6] = {0, 0, 1, 2, 3, 3};
    for (int i = 0; i < 6; i++) NEAR(c->knots[i], k2[i], 0);
    for (int i = 0; i <= 6; i++) {
        double t = i / 2.0;
        int a = i / 2, b = (i + 1) / 2;
        assert_int_equal(pc_curve_eval(c, t, p), PC_OK);
        NEAR(p[0], (P[2 * a] + P[2 * b]) / 2, 1e-12);
        NEAR(p[1], (P[2 * a + 1] + P[2 * b + 1]) / 2, 1e-12);
    }
    pc_curve_release(c);
    /* k = 3: knots [0 0 0 1 2 2 2], P(0.5) = (2, 2.5), P(1) = (3, 3), P(1.5) = (3.5, 2.5) */
    c = bspl2(2, 4, P, PC_KNOTS_OPEN, NULL);
    const double k3[7] = {0, 0, 0, 1, 2, 2, 2};
    for (int i = 0; i < 7; i++) NEAR(c->knots[i], k3[i], 0);
    const double want[3][3] = {{0.5, 2, 2.5}, {1, 3, 3}, {1.5, 3.5, 2.5}};
    for (int i = 0; i < 3; i++) {
        assert_int_equal(pc_curve_eval(c, want[i][0], p), PC_OK);
        NEAR(p[0], want[i][1], 1e-12);
        NEAR(p[1], want[i][2], 1e-12);
    }
    pc_curve_release(c);
    /* Fig. 4.9 with k = 4: P(0.4) = (2.1333, 4.1280) for every P4; P(2) depends on it */
    double F[14] = {0, 2, 2, 5, 5, 4, 4, 1, 5, 0, 8, 1, 10, 4};
    const double p4[3][2] = {{5, 0}, {6, 2}, {7, 4}}, at2[3][2] = {{4.3333, 1.3333}, {4.5, 1.6667},
                                                                    {4.6667, 2.0}};
    for (int v = 0; v < 3; v++) {
        F[8] = p4[v][0];
        F[9] = p4[v][1];
        c = bspl2(3, 7, F, PC_KNOTS_OPEN, NULL);
        assert_int_equal(pc_curve_eval(c, 0.4, p), PC_OK);
        NEAR(p[0], 2.1333, 5e-5);
        NEAR(p[1], 4.1280, 5e-5);
        assert_int_equal(pc_curve_eval(c, 2, p), PC_OK);
        NEAR(p[0], at2[v][0], 5e-5);
        NEAR(p[1], at2[v][1], 5e-5);
        pc_curve_release(c);
    }
}

static double max_dev(const pc_curve *a, const pc_curve *b, double t0, double t1, int n) {
    double m = 0;
    for (int i = 0; i <= n; i++) {
        double t = t0 + (t1 - t0) * i / n, p[PC_MAXDIM], q[PC_MAXDIM];
        assert_int_equal(pc_curve_eval(a, t, p), PC_OK);
        assert_int_equal(pc_curve_eval(b, t, q), PC_OK);
        for (int x = 0; x < a->dim; x++) m = fmax(m, fabs(p[x] - q[x]));
    }
    return m;
}

static pc_curve *nurbs3(unsigned seed, pc_knot_kind kk, const double *knots, int ncp, int deg) {
    double cp[4 * 40];
    unsigned s = seed;
    for (int i = 0; i < ncp; i++) {
        double w = 1 + 0.6 * rnd(&s);
        for (int x = 0; x < 3; x++) cp[4 * i + x] = w * 4 * rnd(&s);
        cp[4 * i + 3] = w;
    }
    int st;
    pc_curve *c = pc_curve_bspline(3, deg, ncp, cp, kk, knots, &st);
    assert_int_equal(st, PC_OK);
    return c;
}

/* Boehm: the curve is kept (max deviation < 1e-12 over 1000 parameters) */
static void test_knot_insertion(void **state) {
    (void)state;
    const double kn[12] = {0, 0, 0, 0, 0.3, 0.3, 1.1, 2, 2.5, 3, 3, 3};
    pc_curve *c = nurbs3(3, PC_KNOTS_GIVEN, kn, 8, 3);   /* 8 cps, 12 knots: deg 3 */
    double us[5] = {0.1, 0.3, 1.1, 2.49, 1.5};
    pc_curve *cur = pc_curve_retain(c);
    int st;
    for (int i = 0; i < 5; i++) {
        pc_curve *n = pc_curve_insert_knot(cur, us[i], &st);
        assert_int_equal(st, PC_OK);
        assert_int_equal(n->ncp, cur->ncp + 1);
        assert_int_equal(n->nknots, cur->nknots + 1);
        assert_true(max_dev(c, n, c->t0, c->t1, 1000) < 1e-12);
        pc_curve_release(cur);
        cur = n;
    }
    /* 0.3 now has multiplicity 3 = degree: full */
    assert_null(pc_curve_insert_knot(cur, 0.3, &st));
    assert_int_equal(st, PC_EDOMAIN);
    pc_curve_release(cur);
    /* uniform knots, inserted at the domain's ends (the curve gets clamped there) */
    pc_curve *u = nurbs3(5, PC_KNOTS_UNIFORM, NULL, 6, 3);
    cur = pc_curve_retain(u);
    for (int i = 0; i < 2; i++) {       /* multiplicity 3 = degree at both ends */
        pc_curve *n = pc_curve_insert_knot(cur, u->t0, &st);
        assert_non_null(n);
        pc_curve_release(cur);
        cur = n;
        n = pc_curve_insert_knot(cur, u->t1, &st);
        assert_non_null(n);
        pc_curve_release(cur);
        cur = n;
    }
    assert_true(max_dev(u, cur, u->t0, u->t1, 1000) < 1e-12);
    double p[3];
    assert_int_equal(pc_curve_eval(u, u->t0, p), PC_OK);   /* clamped: starts at a control point */
    for (int x = 0; x < 3; x++) NEAR(cur->cp[8 + x] / cur->cp[8 + 3], p[x], 1e-12);
    assert_null(pc_curve_insert_knot(cur, u->t0, &st));
    assert_int_equal(st, PC_EDOMAIN);
    pc_curve_release(cur);
    pc_curve_release(u);
    pc_curve_release(c);
}

/* --- split and sub-curves ------------------------------------------------------------------ */
static void check_split(const pc_curve *c, double t) {
    pc_curve *l, *r;
    assert_int_equal(pc_curve_split(c, t, &l, &r), PC_OK);
    assert_int_equal(l->kind, c->kind);
    NEAR(l->t0, c->t0, 0);
    NEAR(l->t1, t, 0);
    NEAR(r->t0, t, 0);
    NEAR(r->t1, c->t1, 0);
    double a[PC_MAXDIM], b[PC_MAXDIM];
    assert_int_equal(pc_curve_eval(l, t, a), PC_OK);    /* the halves meet */
    assert_int_equal(pc_curve_eval(r, t, b), PC_OK);
    for (int x = 0; x < c->dim; x++) NEAR(a[x], b[x], 1e-12 * (1 + fabs(a[x])));
    assert_true(max_dev(c, l, c->t0, t, 500) < 1e-11);
    assert_true(max_dev(c, r, t, c->t1, 500) < 1e-11);
    pc_curve_release(l);
    pc_curve_release(r);
}

static int sine_fn(void *ud, double t, int order, double *out) {
    (void)ud;
    out[0] = cos(t);
    out[1] = sin(2 * t);
    out[2] = 1;
    if (order >= 1) {
        out[3] = -sin(t);
        out[4] = 2 * cos(2 * t);
        out[5] = 0;
    }
    if (order >= 2) {
        out[6] = -cos(t);
        out[7] = -4 * sin(2 * t);
        out[8] = 0;
    }
    return PC_OK;
}

static int nfree;
static void count_free(void *ud) {
    (void)ud;
    nfree++;
}

static int sine_value_only(void *ud, double t, int order, double *out) {
    if (order > 0) return PC_EDOMAIN;
    return sine_fn(ud, t, 0, out);
}

static void test_split(void **state) {
    (void)state;
    unsigned s = 11;
    double cp[10 * 3];
    for (int i = 0; i < 10; i++) {
        cp[3 * i + 2] = 1 + 0.5 * rnd(&s);
        cp[3 * i] = cp[3 * i + 2] * 3 * rnd(&s);
        cp[3 * i + 1] = cp[3 * i + 2] * 3 * rnd(&s);
    }
    const double brk[4] = {0, 1, 1.5, 4};
    int st;
    pc_curve *z = pc_curve_bezier_pieces(2, 3, 3, cp, brk, &st);   /* rational, 3 segments */
    assert_non_null(z);
    check_split(z, 0.3);
    check_split(z, 1);        /* at a breakpoint */
    check_split(z, 1.5);
    check_split(z, 3.9);
    pc_curve *b = nurbs3(13, PC_KNOTS_OPEN, NULL, 9, 4);
    check_split(b, 0.7);
    check_split(b, 1);        /* at a knot */
    check_split(b, 4.5);
    pc_curve *pb = nurbs3(17, PC_KNOTS_PERIODIC, NULL, 6, 3);
    assert_true(pb->closed);
    check_split(pb, 2.2);
    nfree = 0;
    pc_curve *f = pc_curve_func(2, 0, 6, 0, sine_fn, count_free, NULL, &st);
    check_split(f, 2.5);
    /* sub-curves of every kind reproduce the curve; FUNC parts share the callback */
    pc_curve *cs[4] = {z, b, pb, f};
    for (int i = 0; i < 4; i++) {
        double a = cs[i]->t0 + 0.2 * (cs[i]->t1 - cs[i]->t0), e = cs[i]->t0 + 0.7 * (cs[i]->t1 - cs[i]->t0);
        pc_curve *sub = pc_curve_sub(cs[i], a, e, &st);
        assert_int_equal(st, PC_OK);
        NEAR(sub->t0, a, 0);
        NEAR(sub->t1, e, 0);
        assert_true(max_dev(cs[i], sub, a, e, 500) < 1e-11);
        pc_curve *whole = pc_curve_sub(cs[i], cs[i]->t0, cs[i]->t1, &st);
        assert_true(max_dev(cs[i], whole, cs[i]->t0, cs[i]->t1, 100) < 1e-15);
        if (i == 3) {
            assert_ptr_equal(sub->func, f->func);
            assert_int_equal(f->func->refs, 3);
        }
        pc_curve_release(whole);
        pc_curve_release(sub);
        pc_curve_release(cs[i]);
    }
    assert_int_equal(nfree, 1);
}

/* --- derivatives against finite differences -------------------------------------------- */
/* 4th-order central differences of the Cartesian point with step h */
static void fd(const pc_curve *c, double t, double h, double *d1, double *d2) {
    int n = c->dim;
    double p[5][PC_MAXDIM];
    for (int i = -2; i <= 2; i++) assert_int_equal(pc_curve_eval(c, t + i * h, p[i + 2]), PC_OK);
    for (int x = 0; x < n; x++) {
        d1[x] = (p[0][x] - 8 * p[1][x] + 8 * p[3][x] - p[4][x]) / (12 * h);
        d2[x] = (-p[0][x] + 16 * p[1][x] - 30 * p[2][x] + 16 * p[3][x] - p[4][x]) / (12 * h * h);
    }
}

/* first and second derivatives agree with differences to 1e-6 relative to the derivative
 * scale, at 41 parameters (away from breakpoints, where the differences straddle a joint) */
static void check_derivs(const pc_curve *c, double h) {
    int n = c->dim;
    double scale1 = 0, scale2 = 0, e1 = 0, e2 = 0;
    for (int i = 0; i <= 40; i++) {
        double t = c->t0 + (c->t1 - c->t0) * (0.013 + 0.974 * i / 40), d[3 * PC_MAXDIM], a[PC_MAXDIM], b[PC_MAXDIM];
        int near = 0;
        for (int k = 0; k < c->nknots; k++)
            if (fabs(t - c->knots[k]) < 3 * h) near = 1;
        if (near) continue;
        assert_int_equal(pc_curve_derivs(c, t, 2, d), PC_OK);
        fd(c, t, h, a, b);
        for (int x = 0; x < n; x++) {
            scale1 = fmax(scale1, fabs(d[n + x]));
            scale2 = fmax(scale2, fabs(d[2 * n + x]));
            e1 = fmax(e1, fabs(d[n + x] - a[x]));
            e2 = fmax(e2, fabs(d[2 * n + x] - b[x]));
        }
        double h0[3 * PC_MAXDIM + 3];   /* order 0 of derivs is the point */
        assert_int_equal(pc_curve_eval(c, t, h0), PC_OK);
        for (int x = 0; x < n; x++) NEAR(h0[x], d[x], 1e-12 * (1 + fabs(d[x])));
    }
    assert_true(scale1 > 0);
    assert_true(e1 <= 1e-6 * scale1);
    assert_true(e2 <= 1e-6 * fmax(scale2, scale1));
}

static void test_derivs(void **state) {
    (void)state;
    unsigned s = 21;
    int st;
    double cp[8 * 3];
    for (int i = 0; i < 8; i++) {
        cp[3 * i] = 3 * rnd(&s);
        cp[3 * i + 1] = 3 * rnd(&s);
        cp[3 * i + 2] = 1;
    }
    pc_curve *c = pc_curve_bezier(2, 6, cp, &st);           /* Bezier */
    check_derivs(c, 1e-3);
    pc_curve_release(c);
    for (int i = 0; i < 8; i++) {
        double w = 1 + 0.7 * rnd(&s);
        cp[3 * i] *= w;
        cp[3 * i + 1] *= w;
        cp[3 * i + 2] = w;
    }
    c = pc_curve_bezier(2, 5, cp, &st);                       /* rational Bezier */
    check_derivs(c, 1e-3);
    pc_curve_release(c);
    const double kn[12] = {0, 0, 0, 0.5, 1, 1, 2, 3.5, 4, 4, 4, 4};
    c = nurbs3(31, PC_KNOTS_GIVEN, kn, 9, 2);                 /* NURBS, uneven knots */
    check_derivs(c, 1e-3);
    pc_curve_release(c);
    double xy[14];
    for (int i = 0; i < 14; i++) xy[i] = 4 * rnd(&s);
    c = bspl2(3, 7, xy, PC_KNOTS_UNIFORM, NULL);               /* B-spline */
    check_derivs(c, 1e-3);
    pc_curve_release(c);
    const double hp[6] = {0, 0, 1, 2, 3, 1}, hd[6] = {1, 0, 0, 1, 1, -1}, hi[6] = {2, 1, 0, 3, 1, 1};
    const double hu[3] = {0, 1, 3};
    c = pc_curve_hermite(2, 3, hp, hd, hi, hu, 0, &st);       /* Hermite */
    check_derivs(c, 1e-3);
    pc_curve_release(c);
    c = pc_curve_func(2, 0, 6, 0, sine_fn, NULL, NULL, &st);  /* FUNC with derivatives */
    check_derivs(c, 1e-3);
    pc_curve_release(c);
    c = pc_curve_func(2, 0, 6, 0, sine_value_only, NULL, NULL, &st);   /* FUNC, differenced */
    check_derivs(c, 1e-3);
    double d[6];
    assert_int_equal(pc_curve_derivs(c, 1, 2, d), PC_OK);     /* the core's differences: 1e-8 */
    NEAR(d[2], -sin(1.0), 1e-9);
    NEAR(d[3], 2 * cos(2.0), 1e-9);
    NEAR(d[4], -cos(1.0), 1e-8);
    NEAR(d[5], -4 * sin(2.0), 1e-8);
    pc_curve_release(c);
    /* a stroke (example 10's nodes) */
    const double nodes[8] = {100, 300, 200, 150, 300, 50, 400, 100};
    const double n[4] = {2, 4, 6, 2}, m[4] = {7, 5, 3, 2}, t0[4] = {.3, .5, .7, .2};
    pc_stroke_spec spec = {2, 4, 0, nodes, NULL, NULL, NULL, NULL, n, m, t0};
    pc_piece pieces[3];
    assert_int_equal(pc_stroke_build(&spec, pieces, NULL), PC_OK);
    pieces[1].g.kind = PC_G_SINE;
    pieces[2].g.kind = PC_G_CUBIC;
    c = pc_curve_stroke(2, 3, pieces, 0, &st);
    assert_int_equal(st, PC_OK);
    check_derivs(c, 1e-4);
    for (int i = 0; i <= 30; i++) {       /* the curve is the pieces, extrapolating at the ends */
        double t = -0.5 + 4 * i / 30.0, p[2], q[2];
        int k = t < 0 ? 0 : (t >= 2 ? 2 : (int)t);
        pc_piece_eval(2, &pieces[k], t - k, q);
        assert_int_equal(pc_curve_eval(c, t, p), PC_OK);
        NEAR(p[0], q[0], 1e-12);
        NEAR(p[1], q[1], 1e-12);
    }
    pc_curve_release(c);
    /* a Fourier curve */
    double smp[24];
    for (int i = 0; i < 12; i++) {
        double u = i * M_PI / 6;
        smp[2 * i] = cos(u) + 0.3 * rnd(&s);
        smp[2 * i + 1] = sin(u) + 0.3 * rnd(&s);
    }
    c = pc_curve_fourier(2, 6, smp, &st);
    assert_int_equal(st, PC_OK);
    assert_true(c->closed);
    check_derivs(c, 1e-3);
    for (int i = 0; i < 12; i++) {        /* through its samples */
        double p[2];
        assert_int_equal(pc_curve_eval(c, i * M_PI / 6, p), PC_OK);
        NEAR(p[0], smp[2 * i], 1e-12);
        NEAR(p[1], smp[2 * i + 1], 1e-12);
    }
    pc_curve_release(c);
}

/* --- conics ------------------------------------------------------------------------------------ */
/* the arc of angle th on the circle of radius r about (cx, cy), from angle a0 */
static pc_curve *arc(double cx, double cy, double r, double a0, double th) {
    double w = cos(th / 2), m = r / w, am = a0 + th / 2, a1 = a0 + th;
    double cp[9] = {cx + r * cos(a0), cy + r * sin(a0), 1,
                    w * (cx + m * cos(am)), w * (cy + m * sin(am)), w,
                    cx + r * cos(a1), cy + r * sin(a1), 1};
    int st;
    pc_curve *c = pc_curve_bezier(2, 3, cp, &st);
    assert_int_equal(st, PC_OK);
    return c;
}

static void test_circle(void **state) {
    (void)state;
    const double th[3] = {M_PI / 3, 2 * M_PI / 3, M_PI * 0.9};
    for (int j = 0; j < 3; j++) {
        double r = 2.5, cx = 1, cy = -2;
        pc_curve *c = arc(cx, cy, r, 0.4, th[j]);
        double emax = 0, kmax = 0;
        for (int i = 0; i < 1000; i++) {
            double t = i / 999.0, p[2], k;
            assert_int_equal(pc_curve_eval(c, t, p), PC_OK);
            emax = fmax(emax, fabs(hypot(p[0] - cx, p[1] - cy) - r));
            assert_int_equal(pc_curve_curvature(c, t, &k), PC_OK);
            kmax = fmax(kmax, fabs(k - 1 / r));      /* counter-clockwise: positive */
        }
        assert_true(emax < 1e-12);
        assert_true(kmax < 1e-12);
        double len;      /* arc length r th to 1e-12 relative */
        assert_int_equal(pc_curve_length(c, 0, 1, 1e-13, &len), PC_OK);
        NEAR(len, r * th[j], 1e-12 * r * th[j]);
        pc_curve_release(c);
    }
    /* a whole circle as a NURBS (9 control points, degree 2): on the circle, length 2 pi r,
     * bounding box [cx - r, cx + r] x [cy - r, cy + r] within 1e-9 */
    double r = 2, cx = 1, cy = -1, h = sqrt(0.5);
    const double ux[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, uy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    double cp[27];
    for (int i = 0; i < 9; i++) {
        double w = i % 2 ? h : 1;
        cp[3 * i] = w * (cx + r * ux[i]);
        cp[3 * i + 1] = w * (cy + r * uy[i]);
        cp[3 * i + 2] = w;
    }
    const double kn[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    int st;
    pc_curve *c = pc_curve_bspline(2, 2, 9, cp, PC_KNOTS_GIVEN, kn, &st);
    assert_int_equal(st, PC_OK);
    for (int i = 0; i < 1000; i++) {
        double p[2];
        assert_int_equal(pc_curve_eval(c, 4 * i / 999.0, p), PC_OK);
        NEAR(hypot(p[0] - cx, p[1] - cy), r, 1e-12);
    }
    double len, lo[2], hi[2];
    assert_int_equal(pc_curve_length(c, 0, 4, 1e-12, &len), PC_OK);
    NEAR(len, 2 * M_PI * r, 1e-10);
    assert_int_equal(pc_curve_bbox(c, 1e-9, lo, hi), PC_OK);
    NEAR(lo[0], cx - r, 1e-9);
    NEAR(hi[0], cx + r, 1e-9);
    NEAR(lo[1], cy - r, 1e-9);
    NEAR(hi[1], cy + r, 1e-9);
    /* the bbox of a rotated copy: the circle's box does not change */
    pc_map f;
    pc_map_identity(&f, 2);
    double ca = cos(0.3), sa = sin(0.3);
    PC_MAP_AT(&f, 0, 0) = ca; PC_MAP_AT(&f, 0, 1) = -sa; PC_MAP_AT(&f, 0, 2) = cx - ca * cx + sa * cy;
    PC_MAP_AT(&f, 1, 0) = sa; PC_MAP_AT(&f, 1, 1) = ca;  PC_MAP_AT(&f, 1, 2) = cy - sa * cx - ca * cy;
    pc_curve *g = pc_curve_map(c, &f, &st);
    assert_int_equal(st, PC_OK);
    assert_int_equal(pc_curve_bbox(g, 1e-9, lo, hi), PC_OK);
    NEAR(lo[0], cx - r, 1e-9);
    NEAR(hi[1], cy + r, 1e-9);
    pc_curve_release(g);
    pc_curve_release(c);
}

/* the length of a straight Bezier with uneven speed is its chord (1e-12); length over part
 * of the domain and beyond it */
static void test_length(void **state) {
    (void)state;
    const double xy[8] = {0, 0, 2, 1.5, 2.4, 1.8, 4, 3};
    pc_curve *c = bez2(4, xy);
    double len;
    assert_int_equal(pc_curve_length(c, 0, 1, 1e-12, &len), PC_OK);
    NEAR(len, 5, 1e-12);
    assert_int_equal(pc_curve_length(c, 0.5, 0.5, 1e-12, &len), PC_OK);
    NEAR(len, 0, 0);
    pc_curve_release(c);
    /* FUNC: the ellipse-like sine curve against a fine trapezoid sum (1e-9) */
    int st;
    c = pc_curve_func(2, 0, 6, 0, sine_fn, NULL, NULL, &st);
    assert_int_equal(pc_curve_length(c, 0.5, 5, 1e-12, &len), PC_OK);
    double ref = 0, N = 200000;
    for (int i = 0; i < N; i++) {
        double t = 0.5 + 4.5 * (i + 0.5) / N;
        ref += hypot(sin(t), 2 * cos(2 * t)) * 4.5 / N;
    }
    NEAR(len, ref, 1e-8);
    pc_curve_release(c);
}

/* bounding boxes: a cubic whose extremes are interior (derivative roots, 1e-9), a
 * B-spline against dense sampling, a FUNC curve */
static void test_bbox(void **state) {
    (void)state;
    const double xy[8] = {0, 0, 1, 3, 2, -3, 3, 0};      /* y = 9 t (1-t)(1-2t) */
    pc_curve *c = bez2(4, xy);
    double lo[2], hi[2];
    assert_int_equal(pc_curve_bbox(c, 1e-10, lo, hi), PC_OK);
    double t1 = 0.5 - sqrt(3) / 6, ymax = 9 * t1 * (1 - t1) * (1 - 2 * t1);
    NEAR(lo[0], 0, 0);
    NEAR(hi[0], 3, 0);
    NEAR(hi[1], ymax, 1e-9);
    NEAR(lo[1], -ymax, 1e-9);
    pc_curve_release(c);
    pc_curve *b = nurbs3(41, PC_KNOTS_UNIFORM, NULL, 9, 3);
    double slo[3] = {1e9, 1e9, 1e9}, shi[3] = {-1e9, -1e9, -1e9};
    for (int i = 0; i <= 100000; i++) {
        double p[3];
        assert_int_equal(pc_curve_eval(b, b->t0 + (b->t1 - b->t0) * i / 100000, p), PC_OK);
        for (int x = 0; x < 3; x++) {
            slo[x] = fmin(slo[x], p[x]);
            shi[x] = fmax(shi[x], p[x]);
        }
    }
    double lo3[3], hi3[3];
    assert_int_equal(pc_curve_bbox(b, 1e-9, lo3, hi3), PC_OK);
    for (int x = 0; x < 3; x++) {      /* the box holds the samples and is within 1e-8 of them */
        assert_true(lo3[x] <= slo[x] + 1e-12 && hi3[x] >= shi[x] - 1e-12);
        assert_true(slo[x] - lo3[x] < 1e-8 && hi3[x] - shi[x] < 1e-8);
    }
    pc_curve_release(b);
    int st;
    c = pc_curve_func(2, 0, 2 * M_PI, 1, sine_fn, NULL, NULL, &st);
    assert_int_equal(pc_curve_bbox(c, 1e-9, lo, hi), PC_OK);
    NEAR(lo[0], -1, 1e-9);
    NEAR(hi[0], 1, 1e-9);
    NEAR(lo[1], -1, 1e-9);
    NEAR(hi[1], 1, 1e-9);
    pc_curve_release(c);
}

/* --- maps ------------------------------------------------------------------------------------- */
static void test_map(void **state) {
    (void)state;
    pc_map f;      /* a projective map of the plane */
    const double m[9] = {1, 0.2, 3, -0.1, 0.9, 1, 0.05, 0.02, 1};
    pc_map_identity(&f, 2);
    memcpy(f.m, m, sizeof m);
    const double xy[8] = {0, 0, 1, 3, 2, -3, 3, 0};
    pc_curve *c = bez2(4, xy);
    int st;
    pc_curve *g = pc_curve_map(c, &f, &st);
    assert_int_equal(st, PC_OK);
    pc_curve *fc = pc_curve_func(2, 0, 6, 0, sine_fn, NULL, NULL, &st);
    pc_curve *fg = pc_curve_map(fc, &f, &st);
    assert_int_equal(st, PC_OK);
    for (int i = 0; i <= 50; i++) {    /* the image curve is the image of each point: 1e-12 */
        double t = i / 50.0, h[9], hm[9], d[6];
        const pc_curve *src[2] = {c, fc}, *img[2] = {g, fg};
        for (int k = 0; k < 2; k++) {
            double tt = k ? 6 * t : t;
            assert_int_equal(pc_curve_eval_h(src[k], tt, 2, h), PC_OK);
            assert_int_equal(pc_curve_eval_h(img[k], tt, 2, hm), PC_OK);
            for (int r = 0; r < 3; r++)
                for (int a = 0; a < 3; a++) {
                    double s = 0;
                    for (int b = 0; b < 3; b++) s += m[a * 3 + b] * h[r * 3 + b];
                    NEAR(hm[r * 3 + a], s, 1e-12 * (1 + fabs(s)));
                }
            assert_int_equal(pc_curve_derivs(img[k], tt, 2, d), PC_OK);
        }
    }
    check_derivs(g, 1e-3);
    check_derivs(fg, 1e-3);
    /* dimension mismatch */
    pc_map f3;
    pc_map_identity(&f3, 3);
    assert_null(pc_curve_map(c, &f3, &st));
    assert_int_equal(st, PC_EDIM);
    pc_curve_release(fg);
    pc_curve_release(fc);
    pc_curve_release(g);
    pc_curve_release(c);
}

/* --- Hermite, splines, interpolation --------------------------------------------------------- */
static void test_hermite(void **state) {
    (void)state;
    const double p[8] = {0, 0, 1, 2, 3, 1, 4, 4}, dout[8] = {1, 1, 2, 0, 0, -1, 1, 1};
    const double din[8] = {9, 9, 1, 1, 1, -2, 0, 3}, u[4] = {0, 0.5, 2, 3};
    int st;
    pc_curve *c = pc_curve_hermite(2, 4, p, dout, din, u, 0, &st);
    assert_int_equal(st, PC_OK);
    for (int i = 0; i < 4; i++) {      /* nodes, leaving derivatives (right), arriving (left): 1e-12 */
        double d[4];
        assert_int_equal(pc_curve_derivs(c, u[i], 1, d), PC_OK);
        NEAR(d[0], p[2 * i], 1e-12);
        NEAR(d[1], p[2 * i + 1], 1e-12);
        if (i < 3) {
            NEAR(d[2], dout[2 * i], 1e-12);
            NEAR(d[3], dout[2 * i + 1], 1e-12);
        }
        if (i > 0) {
            pc_curve *seg = pc_curve_bezier_pieces(2, 3, 1, c->cp + (i - 1) * 9, c->knots + i - 1, &st);
            assert_int_equal(pc_curve_derivs(seg, u[i], 1, d), PC_OK);
            NEAR(d[2], din[2 * i], 1e-12);
            NEAR(d[3], din[2 * i + 1], 1e-12);
            pc_curve_release(seg);
        }
    }
    pc_curve_release(c);
    /* closed, C1 (din NULL): back to the first node over [u[n-1], u[n-1] + u[1] - u[0]] */
    c = pc_curve_hermite(2, 4, p, dout, NULL, u, 1, &st);
    assert_true(c->closed);
    NEAR(c->t1, 3.5, 0);
    double d[4];
    assert_int_equal(pc_curve_derivs(c, 3.5, 1, d), PC_OK);
    NEAR(d[0], 0, 1e-12);
    NEAR(d[1], 0, 1e-12);
    NEAR(d[2], 1, 1e-12);
    NEAR(d[3], 1, 1e-12);
    pc_curve_release(c);
}

/* second derivatives left and right of the parameter u of a piecewise cubic */
static void second_lr(const pc_curve *c, int i, double *l, double *r) {
    double d[6];
    int st;
    assert_int_equal(pc_curve_derivs(c, c->knots[i], 2, d), PC_OK);
    memcpy(r, d + 4, 2 * sizeof(double));
    pc_curve *seg = pc_curve_bezier_pieces(2, 3, 1, c->cp + (i - 1) * 9, c->knots + i - 1, &st);
    assert_int_equal(pc_curve_derivs(seg, c->knots[i], 2, d), PC_OK);
    memcpy(l, d + 4, 2 * sizeof(double));
    pc_curve_release(seg);
}

static void test_spline_natural(void **state) {
    (void)state;
    const double p[12] = {0, 0, 1, 2, 3, 1, 4, 4, 6, 3, 7, 0};
    int st;
    pc_curve *c = pc_curve_cubic_spline(2, 6, p, NULL, PC_END_NATURAL, NULL, NULL, &st);
    assert_int_equal(st, PC_OK);
    double d[6];
    NEAR(c->knots[1], sqrt(5), 1e-14);            /* accumulated chord length */
    assert_int_equal(pc_curve_derivs(c, c->t0, 2, d), PC_OK);
    NEAR(d[4], 0, 1e-12);
    NEAR(d[5], 0, 1e-12);
    assert_int_equal(pc_curve_derivs(c, c->t1, 2, d), PC_OK);
    NEAR(d[4], 0, 1e-12);
    NEAR(d[5], 0, 1e-12);
    for (int i = 1; i < 5; i++) {      /* C2 at the joints, through the nodes: 1e-12 */
        double l[2], r[2];
        second_lr(c, i, l, r);
        NEAR(l[0], r[0], 1e-12);
        NEAR(l[1], r[1], 1e-12);
        assert_int_equal(pc_curve_eval(c, c->knots[i], d), PC_OK);
        NEAR(d[0], p[2 * i], 1e-12);
        NEAR(d[1], p[2 * i + 1], 1e-12);
    }
    pc_curve_release(c);
    /* Korotky A.5, the natural spline y = S(x) through A..E (u = x): the slopes b_i to 1e-6,
     * values at x = 1.65, 2.45, 3.9, 5.25 to 4 decimals (the digest prints 4.7233 at 3.9, but
     * its own full-precision coefficients give S(3.9) = 4.723245: 4.7232) */
    const double K[10] = {1.2, 0.9, 2.1, 2.3, 2.8, 4, 5, 3.2, 5.5, 2.1}, kx[5] = {1.2, 2.1, 2.8, 5, 5.5};
    c = pc_curve_cubic_spline(2, 5, K, kx, PC_END_NATURAL, NULL, NULL, &st);
    const double b[5] = {1.217395, 2.231877, 2.032919, -2.051608, -2.274196};
    for (int i = 0; i < 5; i++) {
        assert_int_equal(pc_curve_derivs(c, kx[i], 1, d), PC_OK);
        NEAR(d[2], 1, 1e-12);
        NEAR(d[3], b[i], 1e-6);
    }
    const double xs[4] = {1.65, 2.45, 3.9, 5.25}, ys[4] = {1.4859, 3.1674, 4.7232, 2.6639};
    for (int i = 0; i < 4; i++) {
        assert_int_equal(pc_curve_eval(c, xs[i], d), PC_OK);
        NEAR(d[0], xs[i], 1e-12);
        NEAR(d[1], ys[i], 5e-5);
    }
    pc_curve_release(c);
    /* ... and clamped, slopes 0.2 and -0.3: (9) at the same x */
    const double s0[2] = {1, 0.2}, s1[2] = {1, -0.3}, yc[4] = {1.3468, 3.1853, 4.9487, 2.4902};
    c = pc_curve_cubic_spline(2, 5, K, kx, PC_END_CLAMPED, s0, s1, &st);
    assert_int_equal(st, PC_OK);
    for (int i = 0; i < 4; i++) {
        assert_int_equal(pc_curve_eval(c, xs[i], d), PC_OK);
        NEAR(d[1], yc[i], 5e-5);
    }
    assert_int_equal(pc_curve_derivs(c, 2.1, 1, d), PC_OK);
    NEAR(d[3], 2.450398, 1e-6);
    pc_curve_release(c);
}

/* Buimov test vectors 25 (clamped, normalised parameter) and 26 (chord length) */
static void test_spline_buimov(void **state) {
    (void)state;
    const double p[8] = {0, 0, 1, 1, 2, -1, 3, 0}, t1[2] = {1, 1}, u[4] = {0, 1, 2, 3};
    int st;
    pc_curve *c = pc_curve_cubic_spline(2, 4, p, u, PC_END_CLAMPED, t1, t1, &st);
    assert_int_equal(st, PC_OK);
    double d[6];
    for (int i = 1; i <= 2; i++) {
        assert_int_equal(pc_curve_derivs(c, i, 1, d), PC_OK);
        NEAR(d[2], 1, 1e-12);
        NEAR(d[3], -0.8, 1e-12);
    }
    const double mid[3][2] = {{0.5, 0.725}, {1.5, 0}, {2.5, -0.725}};
    for (int i = 0; i < 3; i++) {
        assert_int_equal(pc_curve_eval(c, i + 0.5, d), PC_OK);
        NEAR(d[0], mid[i][0], 1e-12);
        NEAR(d[1], mid[i][1], 1e-12);
    }
    double l[2], r[2];
    second_lr(c, 1, l, r);
    NEAR(l[1], -7.2, 1e-12);
    NEAR(r[1], -7.2, 1e-12);
    second_lr(c, 2, l, r);
    NEAR(l[1], 7.2, 1e-12);
    NEAR(r[1], 7.2, 1e-12);
    pc_curve_release(c);
    c = pc_curve_cubic_spline(2, 4, p, NULL, PC_END_CLAMPED, t1, t1, &st);
    assert_int_equal(st, PC_OK);
    NEAR(c->knots[1], sqrt(2), 1e-15);
    assert_int_equal(pc_curve_derivs(c, sqrt(2), 1, d), PC_OK);
    NEAR(d[2], 0.505431, 1e-6);
    NEAR(d[3], -0.147724, 1e-6);
    assert_int_equal(pc_curve_eval(c, sqrt(2) / 2, d), PC_OK);
    NEAR(d[0], 0.587428, 1e-6);
    NEAR(d[1], 0.702891, 1e-6);
    pc_curve_release(c);
}

static void test_spline_periodic(void **state) {
    (void)state;
    double p[14];
    for (int i = 0; i < 6; i++) {
        p[2 * i] = cos(i * M_PI / 3) * (1 + 0.2 * (i % 2));
        p[2 * i + 1] = sin(i * M_PI / 3);
    }
    p[12] = p[0];
    p[13] = p[1];
    int st;
    pc_curve *c = pc_curve_cubic_spline(2, 7, p, NULL, PC_END_PERIODIC, NULL, NULL, &st);
    assert_int_equal(st, PC_OK);
    assert_true(c->closed);
    double a[6], b[6];    /* C2 across the seam: 1e-12 */
    assert_int_equal(pc_curve_derivs(c, c->t0, 2, a), PC_OK);
    pc_curve *seg = pc_curve_bezier_pieces(2, 3, 1, c->cp + 5 * 9, c->knots + 5, &st);
    assert_int_equal(pc_curve_derivs(seg, c->t1, 2, b), PC_OK);
    for (int x = 0; x < 6; x++) NEAR(a[x], b[x], 1e-12);
    pc_curve_release(seg);
    for (int i = 1; i < 6; i++) {
        double l[2], r[2];
        second_lr(c, i, l, r);
        NEAR(l[0], r[0], 1e-12);
        NEAR(l[1], r[1], 1e-12);
    }
    pc_curve_release(c);
    p[13] += 0.1;       /* not closed */
    assert_null(pc_curve_cubic_spline(2, 7, p, NULL, PC_END_PERIODIC, NULL, NULL, &st));
    assert_int_equal(st, PC_EDOMAIN);
}

static void test_interpolate(void **state) {
    (void)state;
    unsigned s = 51;
    int st;
    for (int n = 2; n <= 12; n++) {     /* through the nodes at their parameters: 1e-9 */
        double p[36], u[12];
        for (int i = 0; i < n; i++) {
            u[i] = i + 0.4 * rnd(&s);
            for (int x = 0; x < 3; x++) p[3 * i + x] = 5 * rnd(&s);
        }
        pc_curve *c = pc_curve_interpolate(3, n, p, u, &st);
        assert_int_equal(st, PC_OK);
        assert_int_equal(c->degree, n - 1);
        for (int i = 0; i < n; i++) {
            double q[3];
            assert_int_equal(pc_curve_eval(c, u[i], q), PC_OK);
            for (int x = 0; x < 3; x++) NEAR(q[x], p[3 * i + x], 1e-9);
        }
        pc_curve_release(c);
    }
    /* Konopatsky §4.2-4.7 (digest's exact vectors): nodes (j, y_j), uniform t, at t = 3/10 */
    const double y[7] = {0, 3, 1, 4, 1, 5, 9};
    const double want[5][2] = {{3.0 / 5, 12.0 / 5}, {9.0 / 10, 309.0 / 100}, {6.0 / 5, 1486.0 / 625},
                               {3.0 / 2, 251.0 / 256}, {9.0 / 5, 33729.0 / 78125}};
    for (int n = 2; n <= 6; n++) {
        double p[14];
        for (int j = 0; j <= n; j++) {
            p[2 * j] = j;
            p[2 * j + 1] = y[j];
        }
        pc_curve *c = pc_curve_interpolate(2, n + 1, p, NULL, &st);
        double q[2];
        assert_int_equal(pc_curve_eval(c, 0.3, q), PC_OK);
        NEAR(q[0], want[n - 2][0], 1e-12);
        NEAR(q[1], want[n - 2][1], 1e-12);
        if (n == 3) {    /* (4.14): C1 = -5/6 M1 + 3 M2 - 3/2 M3 + 1/3 M4 */
            NEAR(c->cp[3 + 1], -5.0 / 6 * 0 + 3 * 3 - 1.5 * 1 + 4.0 / 3, 1e-12);
            NEAR(c->cp[6 + 1], 1.0 / 3 * 0 - 1.5 * 3 + 3 * 1 - 5.0 / 6 * 4, 1e-12);
        }
        pc_curve_release(c);
    }
    const double p2[4] = {0, 0, 1, 1}, u2[2] = {0.5, 0.5};
    assert_null(pc_curve_interpolate(2, 2, p2, u2, &st));
    assert_int_equal(st, PC_ECOINCIDENT);
}

/* --- errors ------------------------------------------------------------------------------------ */
static int fails_with(int st_want, pc_curve *c, const int *st) {
    if (c) pc_curve_release(c);
    return c == NULL && *st == st_want;
}

static int bad_fn(void *ud, double t, int order, double *out) {
    (void)ud;
    (void)order;
    out[0] = t > 1 ? NAN : t;
    out[1] = 0;
    out[2] = 1;
    return t < -1 ? PC_EARG : PC_OK;
}

static void test_errors(void **state) {
    (void)state;
    int st;
    double cp[3 * 70];
    for (int i = 0; i < 3 * 70; i++) cp[i] = i % 3 == 2 ? 1 : i;
    assert_true(fails_with(PC_EDIM, pc_curve_bezier(2, 1, cp, &st), &st));
    assert_true(fails_with(PC_EDIM, pc_curve_bezier(2, PC_CURVE_MAXDEG + 2, cp, &st), &st));
    assert_true(fails_with(PC_EDIM, pc_curve_bezier(0, 3, cp, &st), &st));
    assert_true(fails_with(PC_EDIM, pc_curve_bezier(PC_MAXDIM + 1, 3, cp, &st), &st));
    assert_true(fails_with(PC_EARG, pc_curve_bezier(2, 3, NULL, &st), &st));
    cp[4] = NAN;
    assert_true(fails_with(PC_ENONFINITE, pc_curve_bezier(2, 3, cp, &st), &st));
    cp[4] = INFINITY;
    assert_true(fails_with(PC_ENONFINITE, pc_curve_bspline(2, 2, 4, cp, PC_KNOTS_OPEN, NULL, &st), &st));
    cp[4] = 4;
    const double brk[3] = {0, 1, 1}, brkn[3] = {0, NAN, 2};
    assert_true(fails_with(PC_EDOMAIN, pc_curve_bezier_pieces(2, 2, 2, cp, brk, &st), &st));
    assert_true(fails_with(PC_ENONFINITE, pc_curve_bezier_pieces(2, 2, 2, cp, brkn, &st), &st));
    assert_true(fails_with(PC_EDIM, pc_curve_bezier_pieces(2, 0, 2, cp, NULL, &st), &st));
    assert_true(fails_with(PC_EDIM, pc_curve_bezier_pieces(2, 2, 0, cp, NULL, &st), &st));
    /* B-splines */
    const double kdec[7] = {0, 0, 1, 0.5, 2, 2, 2}, kflat[7] = {0, 0, 0, 1, 1, 1, 1};
    const double kfl2[7] = {1, 1, 1, 1, 1, 1, 1};
    assert_true(fails_with(PC_EDOMAIN, pc_curve_bspline(2, 2, 4, cp, PC_KNOTS_GIVEN, kdec, &st), &st));
    assert_true(fails_with(PC_EDOMAIN, pc_curve_bspline(2, 2, 4, cp, PC_KNOTS_GIVEN, kfl2, &st), &st));
    pc_curve *ok = pc_curve_bspline(2, 2, 4, cp, PC_KNOTS_GIVEN, kflat, &st);   /* repeated knots */
    assert_non_null(ok);
    pc_curve_release(ok);
    assert_true(fails_with(PC_EARG, pc_curve_bspline(2, 2, 4, cp, PC_KNOTS_GIVEN, NULL, &st), &st));
    assert_true(fails_with(PC_EDIM, pc_curve_bspline(2, 4, 4, cp, PC_KNOTS_OPEN, NULL, &st), &st));
    assert_true(fails_with(PC_EDIM, pc_curve_bspline(2, 5, 4, cp, PC_KNOTS_PERIODIC, NULL, &st), &st));
    assert_true(fails_with(PC_EDIM, pc_curve_bspline(2, 0, 4, cp, PC_KNOTS_OPEN, NULL, &st), &st));
    assert_true(fails_with(PC_EDIM, pc_curve_bspline(2, PC_CURVE_MAXDEG + 1, 69, cp, PC_KNOTS_OPEN, NULL, &st), &st));
    assert_true(fails_with(PC_EARG, pc_curve_bspline(2, 2, 4, cp, (pc_knot_kind)9, NULL, &st), &st));
    /* Hermite and splines */
    const double p[6] = {0, 0, 1, 1, 2, 0}, d[6] = {1, 0, 1, 0, 1, 0}, udec[3] = {0, 2, 1};
    assert_true(fails_with(PC_EDIM, pc_curve_hermite(2, 1, p, d, NULL, NULL, 0, &st), &st));
    assert_true(fails_with(PC_EARG, pc_curve_hermite(2, 3, p, NULL, NULL, NULL, 0, &st), &st));
    assert_true(fails_with(PC_EDOMAIN, pc_curve_hermite(2, 3, p, d, NULL, udec, 0, &st), &st));
    assert_true(fails_with(PC_EDOMAIN, pc_curve_cubic_spline(2, 3, p, udec, PC_END_NATURAL, NULL, NULL, &st), &st));
    assert_true(fails_with(PC_EARG, pc_curve_cubic_spline(2, 3, p, NULL, PC_END_CLAMPED, d, NULL, &st), &st));
    assert_true(fails_with(PC_EARG, pc_curve_cubic_spline(2, 3, p, NULL, (pc_end_kind)7, NULL, NULL, &st), &st));
    assert_true(fails_with(PC_EDIM, pc_curve_cubic_spline(2, 1, p, NULL, PC_END_NATURAL, NULL, NULL, &st), &st));
    const double pc2[6] = {0, 0, 0, 0, 1, 1};
    assert_true(fails_with(PC_ECOINCIDENT, pc_curve_cubic_spline(2, 3, pc2, NULL, PC_END_NATURAL, NULL, NULL, &st), &st));
    const double pn[6] = {0, 0, NAN, 1, 2, 0};
    assert_true(fails_with(PC_ENONFINITE, pc_curve_cubic_spline(2, 3, pn, NULL, PC_END_NATURAL, NULL, NULL, &st), &st));
    assert_true(fails_with(PC_ENONFINITE, pc_curve_interpolate(2, 3, pn, NULL, &st), &st));
    assert_true(fails_with(PC_EDIM, pc_curve_interpolate(2, PC_CURVE_MAXDEG + 2, cp, NULL, &st), &st));
    /* FUNC */
    assert_true(fails_with(PC_EDOMAIN, pc_curve_func(2, 1, 1, 0, sine_fn, NULL, NULL, &st), &st));
    assert_true(fails_with(PC_ENONFINITE, pc_curve_func(2, 0, INFINITY, 0, sine_fn, NULL, NULL, &st), &st));
    assert_true(fails_with(PC_EARG, pc_curve_func(2, 0, 1, 0, NULL, NULL, NULL, &st), &st));
    const double fb[2] = {0.5, 0.4};
    assert_true(fails_with(PC_EDOMAIN, pc_curve_func_breaks(2, 0, 1, 0, 2, fb, sine_fn, NULL, NULL, &st), &st));
    /* evaluation */
    pc_curve *c = pc_curve_bezier(2, 3, cp, &st);
    double out[9];
    assert_int_equal(pc_curve_eval_h(c, NAN, 0, out), PC_ENONFINITE);
    assert_int_equal(pc_curve_eval_h(c, 0.5, 3, out), PC_EDOMAIN);
    assert_int_equal(pc_curve_eval_h(NULL, 0.5, 0, out), PC_EARG);
    pc_curve *cq = bez2(3, (const double[6]){0, 0, 1, 5, 2, 0});
    assert_int_equal(pc_curve_eval_h(cq, 1e300, 2, out), PC_ENONFINITE);   /* overflows */
    pc_curve_release(cq);
    pc_curve *l, *r;
    assert_int_equal(pc_curve_split(c, 0, &l, &r), PC_EDOMAIN);
    assert_int_equal(pc_curve_split(c, 1.5, &l, &r), PC_EDOMAIN);
    assert_int_equal(pc_curve_split(c, NAN, &l, &r), PC_ENONFINITE);
    assert_true(fails_with(PC_EDOMAIN, pc_curve_insert_knot(c, 0.5, &st), &st));     /* a Bezier */
    assert_true(fails_with(PC_EDOMAIN, pc_curve_sub(c, 0.6, 0.5, &st), &st));
    assert_true(fails_with(PC_EDOMAIN, pc_curve_sub(c, -0.1, 0.5, &st), &st));
    double len, lo[2], hi[2];
    assert_int_equal(pc_curve_length(c, 1, 0, 1e-9, &len), PC_EDOMAIN);
    assert_int_equal(pc_curve_length(c, 0, 1, NAN, &len), PC_ENONFINITE);
    assert_int_equal(pc_curve_bbox(c, -1, lo, hi), PC_EDOMAIN);
    pc_curve_release(c);
    /* a point at infinity: eval gives the direction, derivs/length/bbox say PC_IMPROPER */
    const double inf[9] = {0, 0, 1, 1, 0, 0, 2, 0, 1};
    c = pc_curve_bezier(2, 3, inf, &st);
    assert_int_equal(pc_curve_eval(c, 0.5, out), PC_OK);
    const double inf2[9] = {0, 0, 1, 1, 1, 0, 2, 0, 1};
    pc_curve *ci = pc_curve_bezier(2, 3, inf2, &st);
    const double w0[9] = {1, 0, 0, 1, 1, 1, 2, 0, 1};     /* starts at infinity */
    pc_curve *c0 = pc_curve_bezier(2, 3, w0, &st);
    assert_int_equal(pc_curve_eval(c0, 0, out), PC_IMPROPER);
    NEAR(out[0], 1, 0);
    NEAR(out[1], 0, 0);
    assert_int_equal(pc_curve_derivs(c0, 0, 1, out), PC_IMPROPER);
    assert_int_equal(pc_curve_length(c0, 0, 1, 1e-9, &len), PC_IMPROPER);
    assert_int_equal(pc_curve_bbox(c0, 1e-9, lo, hi), PC_IMPROPER);
    const double wneg[9] = {0, 0, 1, 1, 1, -3, 2, 0, 1};  /* the weight crosses 0 */
    pc_curve *cn = pc_curve_bezier(2, 3, wneg, &st);
    assert_int_equal(pc_curve_bbox(cn, 1e-9, lo, hi), PC_IMPROPER);
    pc_curve_release(cn);
    pc_curve_release(c0);
    pc_curve_release(ci);
    pc_curve_release(c);
    /* curvature where C' = 0 */
    const double cusp[8] = {0, 0, 1, 1, 1, 1, 2, 0};
    c = bez2(4, cusp);
    double k;
    assert_int_equal(pc_curve_curvature(c, 0.5, &k), PC_OK);
    pc_curve_release(c);
    const double stay[6] = {1, 1, 1, 1, 2, 2};
    c = bez2(3, stay);
    assert_int_equal(pc_curve_curvature(c, 0, &k), PC_EZERO);
    pc_curve_release(c);
    /* callback errors pass through; a NaN from a callback is PC_ENONFINITE */
    c = pc_curve_func(2, -2, 2, 0, bad_fn, NULL, NULL, &st);
    assert_int_equal(pc_curve_eval(c, 1.5, out), PC_ENONFINITE);
    assert_int_equal(pc_curve_eval(c, -1.5, out), PC_EARG);
    assert_int_equal(pc_curve_eval(c, 0.5, out), PC_OK);
    pc_curve_release(c);
    /* stroke and Fourier constructors */
    pc_piece pc;
    memset(&pc, 0, sizeof pc);
    assert_true(fails_with(PC_EDIM, pc_curve_stroke(PC_CURVE_MAXDIM + 1, 1, &pc, 0, &st), &st));
    assert_true(fails_with(PC_EDIM, pc_curve_stroke(2, 0, &pc, 0, &st), &st));
    assert_true(fails_with(PC_EARG, pc_curve_stroke(2, 1, NULL, 0, &st), &st));
    pc.q[1] = NAN;
    assert_true(fails_with(PC_ENONFINITE, pc_curve_stroke(2, 1, &pc, 0, &st), &st));
    assert_true(fails_with(PC_EDOMAIN, pc_curve_fourier(2, 0, cp, &st), &st));
    assert_true(fails_with(PC_EDIM, pc_curve_fourier(0, 2, cp, &st), &st));
    double smp[8] = {0, 1, 2, 3, 4, INFINITY, 6, 7};
    assert_true(fails_with(PC_ENONFINITE, pc_curve_fourier(2, 2, smp, &st), &st));
    /* a half-spline of fractional degree does not extrapolate: PC_EDOMAIN before s = 0 */
    memset(&pc, 0, sizeof pc);
    pc.b[0] = 1;
    pc.g.kind = PC_G_HALF;
    assert_int_equal(pc_hspline_init(&pc.g.h, 2.5, 2, 0.5), PC_OK);
    c = pc_curve_stroke(2, 1, &pc, 0, &st);
    assert_int_equal(pc_curve_eval(c, -0.5, out), PC_EDOMAIN);
    assert_int_equal(pc_curve_eval(c, 1.5, out), PC_OK);
    pc_curve_release(c);
    pc_curve_release(NULL);
}

/* The unit tangent and principal normal of pc_curve_frame: a parabola's vertex in the plane,
 * a quadratic turning in space, a straight stretch and a stop. */
static void test_frame(void **state) {
    (void)state;
    double e[3], n[3];
    const double par[6] = {0, 0, 1, 2, 2, 0};           /* C'(.5) = (2, 0) */
    pc_curve *c = bez2(3, par);
    assert_int_equal(pc_curve_frame(c, 0.5, e, n), PC_OK);
    assert_true(fabs(e[0] - 1) < 1e-15 && fabs(e[1]) < 1e-15);
    assert_true(fabs(n[0]) < 1e-15 && fabs(n[1] - 1) < 1e-15);   /* turned by +90 degrees */
    pc_curve_release(c);
    int st;
    const double turn[12] = {0, 0, 0, 1, 1, 0, 0, 1, 1, 1, 0, 1};   /* C'(0) = (2, 0, 0), C'' = (-2, 2, 0) */
    c = pc_curve_bezier(3, 3, turn, &st);
    assert_int_equal(pc_curve_frame(c, 0, e, n), PC_OK);
    assert_true(fabs(e[0] - 1) < 1e-15 && fabs(e[1]) < 1e-15 && fabs(e[2]) < 1e-15);
    assert_true(fabs(n[0]) < 1e-15 && fabs(n[1] - 1) < 1e-15 && fabs(n[2]) < 1e-15);
    assert_int_equal(pc_curve_frame(c, 0, e, NULL), PC_OK);   /* the tangent alone */
    pc_curve_release(c);
    const double line[12] = {0, 0, 0, 1, 1, 1, 1, 1, 2, 2, 2, 1};
    c = pc_curve_bezier(3, 3, line, &st);
    assert_int_equal(pc_curve_frame(c, 0.3, e, NULL), PC_OK);
    assert_true(fabs(e[0] - 1 / sqrt(3)) < 1e-15);
    assert_int_equal(pc_curve_frame(c, 0.3, e, n), PC_ECOLLINEAR);
    pc_curve_release(c);
    const double stay[6] = {1, 1, 1, 1, 2, 2};
    c = bez2(3, stay);
    assert_int_equal(pc_curve_frame(c, 0, e, n), PC_EZERO);
    pc_curve_release(c);
}

/* c(t) as the binding shows it: a rational value normalised to weight 1, or a vector at infinity */
static void test_curve_value(void **state) {
    (void)state;
    int st;
    double cp[] = {0, 0, 1, 2, 2, 2, 2, 0, 1}, out[3];
    pc_curve *c = pc_curve_bezier(2, 3, cp, &st);
    assert_int_equal(pc_curve_value(c, .5, out), PC_OK);   /* (1.5, 1, 1.5) / 1.5 */
    NEAR(out[0], 1, 1e-15);
    NEAR(out[1], 2.0 / 3, 1e-15);
    assert_true(out[2] == 1);
    pc_curve_release(c);
    double line[] = {0, 0, 1, 2, 4, -1};
    c = pc_curve_bezier(2, 2, line, &st);
    assert_int_equal(pc_curve_value(c, .5, out), PC_OK);   /* (1, 2, 0): the direction */
    NEAR(out[0], 1, 1e-15);
    NEAR(out[1], 2, 1e-15);
    assert_true(out[2] == 0 && !signbit(out[2]));
    pc_curve_release(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_curve_value),
        cmocka_unit_test(test_bezier_bernstein), cmocka_unit_test(test_bezier_buimov),
        cmocka_unit_test(test_bspline_is_bezier), cmocka_unit_test(test_bspline_buimov),
        cmocka_unit_test(test_knot_insertion),   cmocka_unit_test(test_split),
        cmocka_unit_test(test_derivs),           cmocka_unit_test(test_circle),
        cmocka_unit_test(test_length),           cmocka_unit_test(test_bbox),
        cmocka_unit_test(test_map),              cmocka_unit_test(test_hermite),
        cmocka_unit_test(test_spline_natural),   cmocka_unit_test(test_spline_buimov),
        cmocka_unit_test(test_spline_periodic),  cmocka_unit_test(test_interpolate),
        cmocka_unit_test(test_errors),           cmocka_unit_test(test_frame),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
