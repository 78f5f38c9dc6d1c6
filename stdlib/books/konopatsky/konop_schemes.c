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
