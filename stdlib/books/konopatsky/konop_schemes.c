/* The points of the ruler schemes of §2.1.4 and §2.1.6 (konop_schemes.h). */
#include "konop_schemes.h"
#include <math.h>
#include <string.h>
#include "point.h"
#include "linalg.h"

static void hom(int n, const double *x, double *h) {
    memcpy(h, x, sizeof(double) * (size_t)n);
    h[n] = 1;
}

/* the meet of lines a1a2 and b1b2 (homogeneous ends) into out; PC_EDOMAIN where it is not one
 * point (coincident lines or ends) */
static int meet(int n, const double *a1, const double *a2, const double *b1, const double *b2,
                double *out) {
    int st = pc_meet_h(n, a1, a2, b1, b2, out, NULL, NULL, NULL);
    if (st == PC_IMPROPER) return PC_OK;
    if (st == PC_ESAME_LINE || st == PC_ECOINCIDENT || st == PC_EZERO) return PC_EDOMAIN;
    return st;
}

static int flat(int n, const double *a, const double *b, const double *c) {
    double s = fmax(pc_dist(n, a, b), fmax(pc_dist(n, b, c), pc_dist(n, a, c)));
    return !(pc_area(n, a, b, c) > PC_DEGEN_TOL * s * s);
}

static int finite_pt(int n, const double *x) {
    for (int i = 0; i < n; i++)
        if (!isfinite(x[i])) return 0;
    return 1;
}

int pc_conic_ed_scheme(int dim, const double *a, const double *b, const double *c, double k,
                       double u, double *out) {
    if (dim < 2 || dim > PC_MAXDIM) return PC_EDIM;
    if (!finite_pt(dim, a) || !finite_pt(dim, b) || !finite_pt(dim, c) || !isfinite(k) || !isfinite(u))
        return PC_ENONFINITE;
    if (flat(dim, a, b, c)) return PC_ECOLLINEAR;
    if (k == 0) return PC_EDOMAIN;
    int w = dim + 1;
    double A[PC_MAXDIM + 1], B[PC_MAXDIM + 1], C[PC_MAXDIM + 1];
    hom(dim, a, A), hom(dim, b, B), hom(dim, c, C);
    double *T1 = out + w * PC_ED_T1, *K = out + w * PC_ED_K, *T = out + w * PC_ED_T,
           *N = out + w * PC_ED_N, *Pp = out + w * PC_ED_P, *Q = out + w * PC_ED_Q,
           *M = out + w * PC_ED_M;
    for (int i = 0; i < dim; i++) {
        T1[i] = (a[i] + b[i]) / 2;
        K[i] = (T1[i] - c[i]) * k + c[i];       /* K = A k/2 + B k/2 + C k' */
        T[i] = a[i] * (1 - u) + b[i] * u;
    }
    T1[dim] = K[dim] = T[dim] = 1;
    int st = pc_harmonic(dim, a, b, T, N);      /* N = A u'/(1 - 2u) - B u/(1 - 2u) */
    if (st != PC_OK && st != PC_IMPROPER) return st;
    if ((st = meet(dim, A, K, C, T, Pp)) != PC_OK) return st;   /* P = AK x CT */
    if ((st = meet(dim, B, K, C, T, Q)) != PC_OK) return st;    /* Q = BK x CT */
    /* M = AQ x BP (the prose's version; the same point as KN x BP) */
    return meet(dim, A, Q, B, Pp, M);
}

int pc_conic_five_scheme(int dim, const double *a, const double *b, const double *c,
                         const double *d, const double *e, double u, double *out) {
    if (dim < 2 || dim > PC_MAXDIM) return PC_EDIM;
    if (!finite_pt(dim, a) || !finite_pt(dim, b) || !finite_pt(dim, c) || !finite_pt(dim, d) ||
        !finite_pt(dim, e) || !isfinite(u))
        return PC_ENONFINITE;
    if (flat(dim, a, b, c)) return PC_ECOLLINEAR;
    int w = dim + 1;
    double A[PC_MAXDIM + 1], B[PC_MAXDIM + 1], C[PC_MAXDIM + 1], D[PC_MAXDIM + 1], E[PC_MAXDIM + 1];
    hom(dim, a, A), hom(dim, b, B), hom(dim, c, C), hom(dim, d, D), hom(dim, e, E);
    double *S = out + w * PC_P5_S, *U = out + w * PC_P5_U, *V = out + w * PC_P5_V,
           *M = out + w * PC_P5_M, *UB = out + w * PC_P5_UB, *UD = out + w * PC_P5_UD,
           *R = out + w * PC_P5_R, *UE = out + w * PC_P5_UE;
    int st;
    if ((st = meet(dim, B, E, A, D, S)) != PC_OK) return st;     /* S = BE x AD */
    for (int i = 0; i < dim; i++) U[i] = (a[i] - c[i]) * u + c[i];
    U[dim] = 1;
    if ((st = meet(dim, S, U, C, B, V)) != PC_OK) return st;     /* V = SU x CB */
    if ((st = meet(dim, U, E, V, D, M)) != PC_OK) return st;     /* M = UE x VD */
    if ((st = meet(dim, B, E, C, A, UB)) != PC_OK) return st;
    if ((st = meet(dim, C, A, E, D, UD)) != PC_OK) return st;
    if ((st = meet(dim, C, B, E, D, R)) != PC_OK) return st;
    return meet(dim, R, S, C, A, UE);
}

/* the chain's ratios on one side: x_0 = 0, x_(n+1) = 1, (1 - t) x_(i-1) - x_i + t x_(i+1) = 0 */
static int chain(int n, double t, double *x) {
    double M[40 * 40];
    memset(M, 0, sizeof(double) * (size_t)(n * n));
    for (int i = 0; i < n; i++) {
        M[i * n + i] = -1;
        if (i > 0) M[i * n + i - 1] = 1 - t;
        if (i < n - 1) M[i * n + i + 1] = t;
        x[i] = i == n - 1 ? -t : 0;    /* the known x_(n+1) = 1 moved right */
    }
    return pc_lu_solve(n, M, x);
}

int pc_oneratio_smooth_chain(int dim, const double *a, const double *b, const double *c, int n,
                             double t, double *p, double *q, double *m) {
    if (dim < 2 || dim > PC_MAXDIM || n < 1 || n > 40) return PC_EDIM;
    if (!finite_pt(dim, a) || !finite_pt(dim, b) || !finite_pt(dim, c) || !isfinite(t)) return PC_ENONFINITE;
    if (flat(dim, a, b, c)) return PC_ECOLLINEAR;
    double x[40];
    int st = chain(n, t, x);
    if (st != PC_OK) return st;
    for (int i = 0; i < n; i++)
        for (int k = 0; k < dim; k++) {
            p[i * dim + k] = a[k] + x[i] * (c[k] - a[k]);   /* P_i on A..C */
            q[i * dim + k] = c[k] + x[i] * (b[k] - c[k]);   /* Q_i on C..B, the same ratios */
        }
    for (int k = 0; k < dim; k++) m[k] = p[(n - 1) * dim + k] + t * (q[k] - p[(n - 1) * dim + k]);
    return PC_OK;
}

static void add_root(double *u, int *n, double x) {
    if (!isfinite(x)) return;
    for (int i = 0; i < *n; i++)
        if (fabs(u[i] - x) <= 1e-12 * fmax(1, fabs(x))) return;     /* a double root once */
    u[(*n)++] = x;
}

int pc_cones_excluded(double fp, double fq, double *u, int *n) {
    if (!isfinite(fp) || !isfinite(fq)) return PC_ENONFINITE;
    double fpb = 1 - fp, fqb = 1 - fq;
    *n = 0;
    /* (2.148) v = fP fQ' u/(fP fQ' u + fQ fP' u'): the denominator vanishes at this u */
    double den = fq * fpb - fp * fqb;
    if (den != 0) add_root(u, n, fq * fpb / den);
    /* (2.151) fP (1 - 2u)^2 + 2 u u' = 0, i.e. (4 fP - 2) u^2 - (4 fP - 2) u + fP = 0 */
    if (fp < 0.5) {
        double r = 1 / sqrt(1 - 2 * fp);
        add_root(u, n, (1 - r) / 2);
        add_root(u, n, (1 + r) / 2);
    }
    /* (2.153): Q's denominator as a quadratic in u: a u'^2 + b u^2 + c u u' = 0 with
     * a = fQ^2 fP'^2, b = fP^2 fQ'^2, c = 2 (fP - fP^2) fQ'^2; in powers of u:
     * (a + b - c) u^2 + (c - 2a) u + a = 0 */
    double a = fq * fq * fpb * fpb, b = fp * fp * fqb * fqb, c = 2 * (fp - fp * fp) * fqb * fqb;
    double A2 = a + b - c, B1 = c - 2 * a, C0 = a;
    if (fabs(A2) > 1e-15 * fmax(fabs(a), fmax(fabs(b), fabs(c)))) {
        double disc = B1 * B1 - 4 * A2 * C0;
        if (disc >= 0) {
            double sq = sqrt(disc);
            add_root(u, n, (-B1 - sq) / (2 * A2));
            add_root(u, n, (-B1 + sq) / (2 * A2));
        }
    } else if (B1 != 0) {
        add_root(u, n, -C0 / B1);
    }
    for (int i = 1; i < *n; i++)        /* sort */
        for (int j = i; j > 0 && u[j - 1] > u[j]; j--) {
            double t = u[j];
            u[j] = u[j - 1];
            u[j - 1] = t;
        }
    return PC_OK;
}

int pc_conic_foci(int dim, const double *c, const double *a, const double *b, int hyperbola,
                  double *f1, double *f2, double *e, double *p) {
    if (dim < 2 || dim > PC_MAXDIM) return PC_EDIM;
    if (!finite_pt(dim, a) || !finite_pt(dim, b) || !finite_pt(dim, c)) return PC_ENONFINITE;
    double la = pc_dist(dim, c, a), lb = pc_dist(dim, c, b);
    if (!(la > 0) || !(lb > 0)) return PC_ECOLLINEAR;
    if (fabs(pc_sigma(dim, c, a, b)) > 1e-9 * la * lb) return PC_EDOMAIN;   /* not the axes */
    /* the axis with the foci: CA for a hyperbola, the longer one for an ellipse */
    const double *ax = a;
    double major = la, minor = lb;
    if (!hyperbola && lb > la) ax = b, major = lb, minor = la;
    double cf = hyperbola ? hypot(major, minor) : sqrt(fmax(0, major * major - minor * minor));
    for (int k = 0; k < dim; k++) {
        double u = (ax[k] - c[k]) / major;
        f1[k] = c[k] + cf * u;
        f2[k] = c[k] - cf * u;
    }
    *e = cf / major;
    *p = minor * minor / major;
    return PC_OK;
}

int pc_conic_ceva_scheme(int dim, const double *a1, const double *a2, const double *a3, double k,
                         double t, double *out, double *t3, double *r) {
    if (dim < 2 || dim > PC_MAXDIM) return PC_EDIM;
    if (!finite_pt(dim, a1) || !finite_pt(dim, a2) || !finite_pt(dim, a3) || !isfinite(k) || !isfinite(t))
        return PC_ENONFINITE;
    if (flat(dim, a1, a2, a3)) return PC_ECOLLINEAR;
    if (k == 0) return PC_EDOMAIN;
    double tb = 1 - t, d3 = k * t * t + tb * tb, dr = 1 - t * (1 - k * t);
    if (d3 == 0 || dr == 0) return PC_EPOLE;
    *t3 = tb * tb / d3;
    *r = t * tb / dr;
    for (int i = 0; i < dim; i++) {
        out[i] = a1[i] * (1 - *t3) + a2[i] * *t3;
        out[dim + i] = out[i] * (1 - *r) + a3[i] * *r;
    }
    return PC_OK;
}

int pc_conic_focal_point(int dim, const double *c, const double *a, const double *b,
                         int hyperbola, double phi, double *out, double pab[2]) {
    if (dim < 2 || dim > PC_MAXDIM) return PC_EDIM;
    if (!finite_pt(dim, a) || !finite_pt(dim, b) || !finite_pt(dim, c) || !isfinite(phi)) return PC_ENONFINITE;
    double la = pc_dist(dim, c, a), lb = pc_dist(dim, c, b);
    if (!(la > 0) || !(lb > 0)) return PC_ECOLLINEAR;
    if (fabs(pc_sigma(dim, c, a, b)) > 1e-9 * la * lb || (!hyperbola && !(la > lb)))
        return hyperbola ? PC_EDOMAIN : PC_EDOMAIN2;
    double cf = hyperbola ? hypot(la, lb) : sqrt(la * la - lb * lb), e = cf / la;
    double den = la * (1 - e * cos(phi));
    if (!(fabs(den) > 1e-14 * la)) return PC_EPOLE;
    double pa = hyperbola ? lb * (lb * cos(phi) + cf * sin(phi)) / (den * (la - cf))
                          : lb * (lb * cos(phi) - cf * sin(phi)) / (den * (la + cf));
    double pb = lb * sin(phi) / den;
    double *M = out, *F = out + dim;
    for (int i = 0; i < dim; i++) {
        F[i] = c[i] + (hyperbola ? e : -e) * (a[i] - c[i]);
        M[i] = (a[i] - F[i]) * pa + (b[i] - F[i]) * pb + F[i];
    }
    pab[0] = pa, pab[1] = pb;
    return PC_OK;
}
