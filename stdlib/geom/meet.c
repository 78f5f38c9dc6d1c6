/* Intersection of two lines in any dimension (§1.3.5, Fig. 1.10, eq. 1.5).
 *
 * The book finds lambda on A1A2 from the zero area of the moving triangle M A3 A4
 * (S-theorem).  We do the same computation in an orthonormal frame of the plane of the two
 * lines: with u = A2 - A1, v = B2 - B1, w = B1 - A1, the conditions
 *     A1 + u lambda = B1 + v mu
 * give lambda = (w x v)/(u x v), mu = (w x u)/(u x v), which is (1.5) written with 2-D cross
 * products.  u x v = 0 means parallel lines: their meet is the improper point, the direction
 * u with weight 0 (the homogeneous form recommended in the digest's §4.8).
 *
 * pc_meet_h takes the four points homogeneously, as the book's meet of lines and improper
 * points does: an end of weight 0 is a point at infinity, so a line may be a point and a
 * direction, or (two directions) the line at infinity of a plane. */
#include "point.h"
#include <math.h>

static double maxabs(int n, const double *a) {
    double m = 0;
    for (int i = 0; i < n; i++) m = fmax(m, fabs(a[i]));
    return m;
}

/* The meet of the lines A + u lambda and B + v mu (u, v nonzero); roundoff: the size of a
 * rounding error in the coordinates of the points that gave them. */
static int meet_dir(int n, const double *a1, const double *u, const double *b1, const double *v,
                    double roundoff, double *out, double *lambda, double *mu, double *residual) {
    double w[PC_MAXDIM];
    for (int i = 0; i < n; i++) w[i] = b1[i] - a1[i];
    double lu = pc_norm(n, u), lv = pc_norm(n, v), lw = pc_norm(n, w);
    double scale = fmax(fmax(lu, lv), lw);
    double on_tol = PC_ON_TOL * scale + roundoff;
    if (residual) *residual = 0;

    /* 2-D coordinates of the unit directions u/|u|, v/|v| and of w in an orthonormal frame
     * (e1 along u, e2 in the plane).  Unit directions keep every cross product a sine times
     * a length, so nothing overflows or underflows however large or small the figure. */
    double u2[2], v2[2], w2[2];
    int parallel;
    if (n == 2) {
        u2[0] = u[0] / lu; u2[1] = u[1] / lu;
        v2[0] = v[0] / lv; v2[1] = v[1] / lv;
        w2[0] = w[0]; w2[1] = w[1];
        parallel = fabs(pc_cross2(u2, v2)) <= PC_DEGEN_TOL;
        if (parallel && fabs(pc_cross2(u2, w2)) <= on_tol) return PC_ESAME_LINE;
    } else {
        double e1[PC_MAXDIM], e2[PC_MAXDIM], r[PC_MAXDIM];
        for (int i = 0; i < n; i++) e1[i] = u[i] / lu;
        double ve1 = pc_dot(n, v, e1);
        for (int i = 0; i < n; i++) e2[i] = v[i] - ve1 * e1[i];
        double le2 = pc_norm(n, e2);
        parallel = le2 <= PC_DEGEN_TOL * lv;
        if (parallel) {
            /* distance of B1 from line A1A2 decides between one line and two parallels */
            double we1 = pc_dot(n, w, e1);
            for (int i = 0; i < n; i++) r[i] = w[i] - we1 * e1[i];
            if (pc_norm(n, r) <= on_tol) return PC_ESAME_LINE;
        } else {
            for (int i = 0; i < n; i++) e2[i] /= le2;
            u2[0] = 1; u2[1] = 0;
            v2[0] = ve1 / lv; v2[1] = pc_dot(n, v, e2) / lv;
            w2[0] = pc_dot(n, w, e1); w2[1] = pc_dot(n, w, e2);
            /* the part of w outside the plane of u, v is the common perpendicular */
            for (int i = 0; i < n; i++) r[i] = w[i] - w2[0] * e1[i] - w2[1] * e2[i];
            double dist = pc_norm(n, r);
            if (dist > on_tol) {
                if (residual) *residual = dist;
                return PC_ESKEW;
            }
        }
    }
    if (parallel) {
        for (int i = 0; i < n; i++) out[i] = u[i];
        out[n] = 0.0;
        if (lambda) *lambda = INFINITY;
        if (mu) *mu = INFINITY;
        return PC_IMPROPER;
    }
    /* with unit directions: lambda = (w x v)/(u x v) = (w x v2)/(den |u|), and likewise mu */
    double den = pc_cross2(u2, v2);
    double lam = pc_cross2(w2, v2) / (den * lu);
    double m = pc_cross2(w2, u2) / (den * lv);
    for (int i = 0; i < n; i++) out[i] = a1[i] + u[i] * lam;
    out[n] = 1.0;
    if (lambda) *lambda = lam;
    if (mu) *mu = m;
    return PC_OK;
}

int pc_meet(int n, const double *a1, const double *a2, const double *b1, const double *b2,
            double *out, double *lambda, double *mu, double *residual) {
    if (n < 2) return PC_EDIM;
    double u[PC_MAXDIM], v[PC_MAXDIM];
    for (int i = 0; i < n; i++) {
        u[i] = a2[i] - a1[i];
        v[i] = b2[i] - b1[i];
    }
    if (pc_norm(n, u) == 0 || pc_norm(n, v) == 0) return PC_ECOINCIDENT;
    double roundoff = 1e-15 * fmax(fmax(maxabs(n, a1), maxabs(n, a2)),
                                   fmax(maxabs(n, b1), maxabs(n, b2)));
    return meet_dir(n, a1, u, b1, v, roundoff, out, lambda, mu, residual);
}

/* ---- the homogeneous meet: ends that are points at infinity ------------------------------- */

/* A line from two homogeneous values: a finite point p with a direction d, or (at_infinity)
 * the line at infinity of the directions d, e: the improper points of the planes spanned by
 * them.  For two finite points d = A2 - A1, as in pc_meet. */
typedef struct {
    int at_infinity;
    int two_points;                /* given by two finite points: pc_meet's own arithmetic */
    double p[PC_MAXDIM], q[PC_MAXDIM], d[PC_MAXDIM], e[PC_MAXDIM];
} hline;

static int is_improper(int n, const double *h) { return pc_kind_of(h[n]) == PC_KIND_VECTOR; }

static int all_finite(int n, const double *x) {
    for (int i = 0; i < n; i++)
        if (!isfinite(x[i])) return 0;
    return 1;
}

static void location(int n, const double *h, double *out) {
    for (int i = 0; i < n; i++) out[i] = h[i] / h[n];
}

/* Is unit vector a (almost) a multiple of unit vector b? */
static int parallel_unit(int n, const double *a, const double *b) {
    double ab = pc_dot(n, a, b), r[PC_MAXDIM];
    for (int i = 0; i < n; i++) r[i] = a[i] - ab * b[i];
    return pc_norm(n, r) <= PC_DEGEN_TOL;
}

static void unit(int n, const double *a, double *out) {
    double l = pc_norm(n, a);
    for (int i = 0; i < n; i++) out[i] = a[i] / l;
}

static int make_line(int n, const double *h1, const double *h2, hline *l) {
    int i1 = is_improper(n, h1), i2 = is_improper(n, h2);
    l->at_infinity = i1 && i2;
    l->two_points = !i1 && !i2;
    if (l->two_points) {
        location(n, h1, l->p);
        location(n, h2, l->q);
        for (int i = 0; i < n; i++) l->d[i] = l->q[i] - l->p[i];
        /* a tiny weight can push a normalised point beyond the doubles */
        if (!all_finite(n, l->p) || !all_finite(n, l->q) || !all_finite(n, l->d))
            return PC_ENONFINITE;
        return pc_norm(n, l->d) == 0 ? PC_ECOINCIDENT : PC_OK;
    }
    if (l->at_infinity) {
        unit(n, h1, l->d);
        unit(n, h2, l->e);
        return parallel_unit(n, l->d, l->e) ? PC_ECOINCIDENT : PC_OK;
    }
    const double *fin = i1 ? h2 : h1, *dir = i1 ? h1 : h2;
    location(n, fin, l->p);
    for (int i = 0; i < n; i++) l->d[i] = dir[i];
    return all_finite(n, l->p) ? PC_OK : PC_ENONFINITE;
}

/* An orthonormal basis e1, e2 of the plane of the directions d, e (unit, not parallel), and
 * the part of x outside that plane. */
static void plane_basis(int n, const double *d, const double *e, double *e1, double *e2) {
    for (int i = 0; i < n; i++) e1[i] = d[i];
    double k = pc_dot(n, e, e1);
    for (int i = 0; i < n; i++) e2[i] = e[i] - k * e1[i];
    double l = pc_norm(n, e2);
    for (int i = 0; i < n; i++) e2[i] /= l;
}

static void off_plane(int n, const double *e1, const double *e2, const double *x, double *r) {
    double k1 = pc_dot(n, x, e1), k2 = pc_dot(n, x, e2);
    for (int i = 0; i < n; i++) r[i] = x[i] - k1 * e1[i] - k2 * e2[i];
}

static int improper_result(int n, const double *dir, double *out, double *lambda, double *mu) {
    for (int i = 0; i < n; i++) out[i] = dir[i];
    out[n] = 0.0;
    if (lambda) *lambda = INFINITY;
    if (mu) *mu = INFINITY;
    return PC_IMPROPER;
}

/* The line at infinity of plane (d, e) and a finite line of direction v: they meet in v's
 * improper point when v lies in the plane (always in 2-D), else not at all. */
static int meet_infinity(int n, const hline *inf, const double *v, double *out, double *lambda,
                         double *mu, double *residual) {
    if (n > 2) {
        double e1[PC_MAXDIM], e2[PC_MAXDIM], vu[PC_MAXDIM], r[PC_MAXDIM];
        plane_basis(n, inf->d, inf->e, e1, e2);
        unit(n, v, vu);
        off_plane(n, e1, e2, vu, r);
        if (pc_norm(n, r) > PC_DEGEN_TOL) {
            if (residual) *residual = INFINITY;
            return PC_ESKEW;
        }
    }
    return improper_result(n, v, out, lambda, mu);
}

/* Two lines at infinity: in 2-D there is only one; in n-D those of planes (d1, e1), (d2, e2)
 * meet in the direction common to both planes, if the planes share one. */
static int meet_two_infinities(int n, const hline *a, const hline *b, double *out,
                               double *lambda, double *mu, double *residual) {
    if (n == 2) return PC_ESAME_LINE;
    double f1[PC_MAXDIM], f2[PC_MAXDIM], r1[PC_MAXDIM], r2[PC_MAXDIM], k[PC_MAXDIM];
    plane_basis(n, b->d, b->e, f1, f2);
    off_plane(n, f1, f2, a->d, r1);      /* the parts of a's directions outside b's plane */
    off_plane(n, f1, f2, a->e, r2);
    double l1 = pc_norm(n, r1), l2 = pc_norm(n, r2);
    if (l1 <= PC_DEGEN_TOL && l2 <= PC_DEGEN_TOL) return PC_ESAME_LINE;
    /* k = x d + y e lies in b's plane when x r1 + y r2 = 0, so r1 and r2 must be dependent:
     * take the combination that cancels the larger of them, then check the rest is gone */
    double c = pc_dot(n, r1, r2), rk[PC_MAXDIM];
    if (l1 >= l2)
        for (int i = 0; i < n; i++) k[i] = a->e[i] - c / (l1 * l1) * a->d[i];
    else
        for (int i = 0; i < n; i++) k[i] = a->d[i] - c / (l2 * l2) * a->e[i];
    unit(n, k, k);
    off_plane(n, f1, f2, k, rk);         /* the sine of k's angle with b's plane */
    if (pc_norm(n, rk) > PC_DEGEN_TOL) {
        if (residual) *residual = INFINITY;
        return PC_ESKEW;
    }
    return improper_result(n, k, out, lambda, mu);
}

int pc_meet_h(int n, const double *a1, const double *a2, const double *b1, const double *b2,
              double *out, double *lambda, double *mu, double *residual) {
    if (n < 2 || n > PC_MAXDIM) return PC_EDIM;
    const double *h[4] = {a1, a2, b1, b2};
    for (int k = 0; k < 4; k++)
        for (int i = 0; i <= n; i++)
            if (!isfinite(h[k][i])) return PC_ENONFINITE;
    for (int k = 0; k < 4; k++)
        if (is_improper(n, h[k]) && pc_norm(n, h[k]) == 0) return PC_EZERO;
    if (residual) *residual = 0;
    hline a, b;
    int st = make_line(n, a1, a2, &a);
    if (st == PC_OK) st = make_line(n, b1, b2, &b);
    if (st != PC_OK) return st;
    if (a.at_infinity && b.at_infinity)
        return meet_two_infinities(n, &a, &b, out, lambda, mu, residual);
    if (a.at_infinity) return meet_infinity(n, &a, b.d, out, lambda, mu, residual);
    if (b.at_infinity) return meet_infinity(n, &b, a.d, out, lambda, mu, residual);
    if (a.two_points && b.two_points)   /* exactly pc_meet on the locations */
        return pc_meet(n, a.p, a.q, b.p, b.q, out, lambda, mu, residual);
    double roundoff = 1e-15 * fmax(fmax(maxabs(n, a.p), maxabs(n, b.p)),
                                   fmax(a.two_points ? maxabs(n, a.q) : 0,
                                        b.two_points ? maxabs(n, b.q) : 0));
    return meet_dir(n, a.p, a.d, b.p, b.d, roundoff, out, lambda, mu, residual);
}
