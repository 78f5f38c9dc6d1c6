/* The simple ratio of three collinear points and what is built on it: division of a segment
 * in a given ratio, the harmonic conjugate and the cross ratio (conventions §2 item 3 of the
 * digest; eq. 2.98 for the cross ratio). */
#include "point.h"
#include <math.h>

static double maxabs(int n, const double *a) {
    double m = 0;
    for (int i = 0; i < n; i++) m = fmax(m, fabs(a[i]));
    return m;
}

/* Is direction z parallel to the line direction u (both non-zero)? */
static int parallel(int n, const double *u, const double *z) {
    double lu = pc_norm(n, u), lz = pc_norm(n, z), uh[PC_MAXDIM], r[PC_MAXDIM];
    for (int i = 0; i < n; i++) uh[i] = u[i] / lu;      /* unit: no |u|² to overflow */
    double c = pc_dot(n, uh, z);
    for (int i = 0; i < n; i++) r[i] = z[i] - c * uh[i];
    return pc_norm(n, r) <= PC_ON_TOL * lz;
}

int pc_sr(int n, const double *x, const double *y, const double *z, double *lambda) {
    double e[PC_MAXDIM], d[PC_MAXDIM];
    switch (pc_kind_of(z[n])) {
    case PC_KIND_VECTOR: {
        /* Z at infinity: (X - Z)/(Z - Y) -> -1, if Z is the direction of line XY */
        if (pc_norm(n, z) == 0) return PC_EZERO;
        for (int i = 0; i < n; i++) d[i] = y[i] - x[i];
        if (pc_norm(n, d) != 0 && !parallel(n, d, z)) return PC_ENOTCOLLINEAR;
        *lambda = -1.0;
        return PC_OK;
    }
    case PC_KIND_WEIGHTED:
        return PC_EWEIGHT;
    case PC_KIND_POINT:
        break;
    }
    double w = z[n];
    for (int i = 0; i < n; i++) {
        double zi = z[i] / w;
        e[i] = x[i] - zi;                     /* XZ */
        d[i] = zi - y[i];                     /* ZY */
    }
    double le = pc_norm(n, e), ld = pc_norm(n, d);
    if (ld == 0) {
        if (le == 0) return PC_ECOINCIDENT;   /* X = Y = Z: no line, no ratio */
        *lambda = INFINITY;                   /* Z = Y */
        return PC_OK;
    }
    /* λ = (XZ·ZY)/(ZY·ZY), with ZY divided by its length first: the plain dot products
     * overflow (or underflow to 0/0) for coordinates beyond about 1e154 (or below 1e-154) */
    double dh[PC_MAXDIM];
    for (int i = 0; i < n; i++) dh[i] = d[i] / ld;
    double lam = pc_dot(n, e, dh) / ld;
    /* collinearity: XZ must be a multiple of ZY */
    double r[PC_MAXDIM];
    for (int i = 0; i < n; i++) r[i] = e[i] - lam * d[i];
    double tol = PC_ON_TOL * (le + ld) + 1e-15 * fmax(maxabs(n, x), maxabs(n, y));
    if (pc_norm(n, r) > tol) return PC_ENOTCOLLINEAR;
    *lambda = lam;
    return PC_OK;
}

int pc_divide(int n, const double *x, const double *y, double lambda, double *out) {
    if (isnan(lambda)) return PC_ENONFINITE;
    if (isinf(lambda)) {                      /* lambda -> oo: Z -> Y */
        for (int i = 0; i <= n; i++) out[i] = y[i];
        return PC_OK;
    }
    /* Z = (X + lambda Y)/(1 + lambda): homogeneous, so the weight is divided as well */
    if (fabs(lambda) > 1) {
        /* the same divided by lambda: lambda = 1e308 would overflow X + lambda Y */
        double r = 1.0 / lambda;
        for (int i = 0; i <= n; i++) out[i] = (x[i] * r + y[i]) / (r + 1.0);
    } else {
        for (int i = 0; i <= n; i++) out[i] = x[i] + lambda * y[i];
        double s = 1.0 + lambda;
        if (s == 0) return PC_IMPROPER;       /* lambda = -1: the improper point X - Y */
        for (int i = 0; i <= n; i++) out[i] /= s;
    }
    for (int i = 0; i <= n; i++)
        if (!isfinite(out[i])) return PC_ENONFINITE;
    return PC_OK;
}

int pc_harmonic(int n, const double *a, const double *b, const double *t, double *out) {
    if (pc_dist(n, a, b) == 0) return PC_ECOINCIDENT;
    double lam;
    int st = pc_sr(n, a, b, t, &lam);
    if (st != PC_OK) return st;
    double ah[PC_MAXDIM + 1], bh[PC_MAXDIM + 1];
    for (int i = 0; i < n; i++) { ah[i] = a[i]; bh[i] = b[i]; }
    ah[n] = bh[n] = 1.0;
    /* (ABN) = -(ABT); T = B (lambda = oo) is its own conjugate */
    return pc_divide(n, ah, bh, isinf(lam) ? lam : -lam, out);
}

int pc_cross_ratio(int n, const double *a, const double *b, const double *c, const double *d,
                   double *out) {
    if (pc_dist(n, a, b) == 0) return PC_ECOINCIDENT;
    double lc, ld;
    int st = pc_sr(n, a, b, c, &lc);
    if (st == PC_OK) st = pc_sr(n, a, b, d, &ld);
    if (st != PC_OK) return st;
    /* (ABCD) = (ABC)/(ABD); an infinite numerator or a zero denominator gives oo */
    if (isinf(lc) && isinf(ld)) return PC_ECOINCIDENT;    /* C = D = B */
    if (lc == 0 && ld == 0) return PC_ECOINCIDENT;        /* C = D = A */
    if (isinf(lc) || ld == 0) *out = INFINITY;
    else if (isinf(ld)) *out = 0.0;
    else *out = lc / ld;
    return PC_OK;
}

int pc_vec_ratio(int n, const double *u, const double *v, double *r, double *angle) {
    double vv = 0, uv = 0, uu = 0;
    for (int i = 0; i < n; i++) {
        if (!isfinite(u[i]) || !isfinite(v[i])) return PC_ENONFINITE;
        vv += v[i] * v[i];
        uv += u[i] * v[i];
        uu += u[i] * u[i];
    }
    if (!(vv > 0)) return PC_EZERO;
    double k = uv / vv, off = 0;
    /* the sine of the angle: the part of u off v, over |u| */
    for (int i = 0; i < n; i++) off += (u[i] - k * v[i]) * (u[i] - k * v[i]);
    double sn = uu > 0 ? sqrt(off / uu) : 0;
    if (sn > 1e-9) {
        if (angle) *angle = asin(fmin(1, sn));
        return PC_ENOTCOLLINEAR;
    }
    *r = k;
    return PC_OK;
}
