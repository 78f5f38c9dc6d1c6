/* Intersection of two lines in any dimension (§1.3.5, Fig. 1.10, eq. 1.5).
 *
 * The book finds lambda on A1A2 from the zero area of the moving triangle M A3 A4
 * (S-theorem).  We do the same computation in an orthonormal frame of the plane of the two
 * lines: with u = A2 - A1, v = B2 - B1, w = B1 - A1, the conditions
 *     A1 + u lambda = B1 + v mu
 * give lambda = (w x v)/(u x v), mu = (w x u)/(u x v), which is (1.5) written with 2-D cross
 * products.  u x v = 0 means parallel lines: their meet is the improper point, the direction
 * u with weight 0 (the homogeneous form recommended in the digest's §4.8). */
#include "point.h"
#include <math.h>

static double maxabs(int n, const double *a) {
    double m = 0;
    for (int i = 0; i < n; i++) m = fmax(m, fabs(a[i]));
    return m;
}

int pc_meet(int n, const double *a1, const double *a2, const double *b1, const double *b2,
            double *out, double *lambda, double *mu, double *residual) {
    if (n < 2) return PC_EDIM;
    double u[PC_MAXDIM], v[PC_MAXDIM], w[PC_MAXDIM];
    for (int i = 0; i < n; i++) {
        u[i] = a2[i] - a1[i];
        v[i] = b2[i] - b1[i];
        w[i] = b1[i] - a1[i];
    }
    double lu = pc_norm(n, u), lv = pc_norm(n, v), lw = pc_norm(n, w);
    if (lu == 0 || lv == 0) return PC_ECOINCIDENT;
    double scale = fmax(fmax(lu, lv), lw);
    double roundoff = 1e-15 * fmax(fmax(maxabs(n, a1), maxabs(n, a2)),
                                   fmax(maxabs(n, b1), maxabs(n, b2)));
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
