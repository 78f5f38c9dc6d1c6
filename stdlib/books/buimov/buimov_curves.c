/* The textbook's B-spline knots and basis, Bernstein and Hermite functions, cubic splines and
 * the helix (Buimov ch. 4): see buimov.h. */
#include "buimov.h"
#include "linalg.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* --- B-splines ------------------------------------------------------------------------------ */

int pc_book_knots(int dim, int ncp, const double *p, int k, double *q) {
    if (dim < 1 || dim > PC_MAXDIM || k < 2 || k > ncp || k > PC_CURVE_MAXDEG + 1) return PC_EDOMAIN;
    int n = ncp - 1;
    for (int j = 0; j < k; j++) q[j] = 0;
    for (int j = k; j <= n + 1; j++) {    /* a new knot unless P_(j-k) and P_(j-k+1) coincide */
        const double *a = p + (size_t)(j - k) * dim, *b = a + dim;
        q[j] = q[j - 1] + (memcmp(a, b, sizeof(double) * (size_t)dim) != 0);
    }
    for (int j = n + 2; j <= n + k; j++) q[j] = q[j - 1];
    return PC_OK;
}

int pc_book_basis(const double *q, int nq, int i, int k, double t, double *out) {
    if (i < 0 || k < 1 || k > PC_CURVE_MAXDEG + 1 || i + k >= nq) return PC_EDOMAIN;
    if (!isfinite(t)) return PC_ENONFINITE;
    double N[PC_CURVE_MAXDEG + 2];
    int last = -1;                         /* the last non-empty interval, closed at t_max */
    for (int j = nq - 2; j >= 0 && last < 0; j--) if (q[j] < q[j + 1]) last = j;
    for (int j = 0; j < k; j++) {
        int a = i + j;
        N[j] = (q[a] <= t && t < q[a + 1]) || (a == last && t == q[a + 1]) ? 1 : 0;
    }
    for (int r = 2; r <= k; r++) {         /* N_{a,r} from N_{a,r-1} and N_{a+1,r-1}, 0/0 = 0 */
        for (int j = 0; j <= k - r; j++) {
            int a = i + j;
            double d1 = q[a + r - 1] - q[a], d2 = q[a + r] - q[a + 1];
            double v = 0;
            if (d1 != 0) v += (t - q[a]) * N[j] / d1;
            if (d2 != 0) v += (q[a + r] - t) * N[j + 1] / d2;
            N[j] = v;
        }
    }
    *out = N[0];
    return PC_OK;
}

pc_curve *pc_curve_book_bspline(int dim, int ncp, const double *p, int k, int *status) {
    if (dim < 1 || dim > PC_MAXDIM || ncp < 2 || ncp > 100000) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    double *q = malloc(sizeof(double) * (size_t)(ncp + k + 1));
    double *h = malloc(sizeof(double) * (size_t)ncp * (dim + 1));
    pc_curve *c = NULL;
    if (!q || !h) *status = PC_ENOMEM;
    else if ((*status = pc_book_knots(dim, ncp, p, k, q)) == PC_OK) {
        for (int i = 0; i < ncp; i++) {
            memcpy(h + (size_t)i * (dim + 1), p + (size_t)i * dim, sizeof(double) * (size_t)dim);
            h[(size_t)i * (dim + 1) + dim] = 1;
        }
        c = pc_curve_bspline(dim, k - 1, ncp, h, PC_KNOTS_GIVEN, q, status);
    }
    free(q);
    free(h);
    return c;
}

/* --- Bezier and Hermite --------------------------------------------------------------------- */

double pc_bernstein(int n, int i, double t) {
    if (i < 0 || i > n || n > 1000) return 0;
    double c = 1;                          /* C(n, i), built up without overflow for n <= 1000 */
    for (int j = 1; j <= i; j++) c = c * (n - i + j) / j;
    return c * pow(t, i) * pow(1 - t, n - i);   /* pow(0, 0) = 1 */
}

void pc_hermite_blend(double t, double F[4]) {
    double t2 = t * t, t3 = t2 * t;
    F[0] = 2 * t3 - 3 * t2 + 1;
    F[1] = -2 * t3 + 3 * t2;
    F[2] = t3 - 2 * t2 + t;
    F[3] = t3 - t2;
}

int pc_hermite_coeffs(int dim, const double *p1, const double *p2, const double *d1,
                      const double *d2, double tl, double *B) {
    if (!(tl > 0) || !isfinite(tl) || dim < 1 || dim > PC_MAXDIM) return PC_EDOMAIN;
    for (int j = 0; j < dim; j++) {
        double dp = p2[j] - p1[j];
        B[j] = p1[j];
        B[dim + j] = d1[j];
        B[2 * dim + j] = 3 * dp / (tl * tl) - 2 * d1[j] / tl - d2[j] / tl;
        /* + d1/tl^2 + d2/tl^2: the book's B4 misprints the signs */
        B[3 * dim + j] = -2 * dp / (tl * tl * tl) + d1[j] / (tl * tl) + d2[j] / (tl * tl);
        for (int r = 0; r < 4; r++) if (!isfinite(B[r * dim + j])) return PC_ENONFINITE;
    }
    return PC_OK;
}

/* --- cubic splines -------------------------------------------------------------------------- */

int pc_book_spline_params(int dim, int n, const double *p, int chord, double *tl) {
    for (int k = 0; k + 1 < n; k++) {
        if (!chord) { tl[k] = 1; continue; }
        double s = 0;
        for (int j = 0; j < dim; j++) s = hypot(s, p[(size_t)(k + 1) * dim + j] - p[(size_t)k * dim + j]);
        if (!isfinite(s)) return PC_ENONFINITE;
        if (s == 0) return PC_ECOINCIDENT;
        tl[k] = s;
    }
    return PC_OK;
}

/* The right-hand side of the joint at node j between the segments of lengths tb (before) and
 * ta (after), the differences dprev = P_j - P_(j-1) and dnext = P_(j+1) - P_j, into rhs. */
static void joint_rhs(int dim, double tb, double ta, const double *pm, const double *p0,
                      const double *pn_, const double *pe, double sign, double *rhs) {
    /* dnext = pn_ - p0 (the segment after), dprev = pe - pm (the segment before) */
    for (int d = 0; d < dim; d++)
        rhs[d] = 3 / (tb * ta) * (tb * tb * (pn_[d] - p0[d]) + sign * ta * ta * (pe[d] - pm[d]));
}

int pc_book_spline_tangents(int dim, int n, const double *p, const double *tl, pc_book_ends ends,
                            const double *d0, const double *d1, double *tg) {
    int cyc = ends == PC_BOOK_CYCLIC || ends == PC_BOOK_ANTICYCLIC;
    if (dim < 1 || dim > PC_MAXDIM || n < (cyc ? 4 : 2) || n > 10000000) return PC_EDOMAIN;
    for (int k = 0; k + 1 < n; k++) if (!(tl[k] > 0) || !isfinite(tl[k])) return PC_EDOMAIN;
    if (ends == PC_BOOK_CLAMPED && (!d0 || !d1)) return PC_EDOMAIN;
    int m = cyc ? n - 1 : n;               /* unknowns: cyclic ends share P'_n = +-P'_1 */
    double sg = ends == PC_BOOK_ANTICYCLIC ? -1 : 1;
    double *a = malloc(sizeof(double) * 3 * (size_t)m), *b = a + m, *c = b + m;
    if (!a) return PC_ENOMEM;
    const double *P = p;
#define PT(k) (P + (size_t)(k) * dim)
    for (int j = 1; j + 1 < n && j < m; j++) {       /* the joints at nodes 1 .. n-2 */
        double tb = tl[j - 1], ta = tl[j];
        a[j] = ta;
        b[j] = 2 * (tb + ta);
        c[j] = tb;
        joint_rhs(dim, tb, ta, PT(j - 1), PT(j), PT(j + 1), PT(j), 1, tg + (size_t)j * dim);
    }
    if (cyc) {
        /* the joint at the start closes over the last segment: before it is P_(n-2) -> P_(n-1)
         * with P'_(n-1) = sg P'_0, so the corners of the system carry the sign */
        double tb = tl[n - 2], ta = tl[0];
        a[0] = sg * ta;
        b[0] = 2 * (tb + ta);
        c[0] = tb;
        joint_rhs(dim, tb, ta, PT(n - 2), PT(0), PT(1), PT(n - 1), sg, tg);
        c[m - 1] *= sg;                   /* row n-2 meets P'_(n-1) = sg P'_0 */
    } else if (ends == PC_BOOK_CLAMPED) {
        a[0] = 0; b[0] = 1; c[0] = 0;
        a[n - 1] = 0; b[n - 1] = 1; c[n - 1] = 0;
        memcpy(tg, d0, sizeof(double) * (size_t)dim);
        memcpy(tg + (size_t)(n - 1) * dim, d1, sizeof(double) * (size_t)dim);
    } else {                                /* natural: P''(0) = 0 and P''(t_n) = 0 */
        a[0] = 0; b[0] = 2; c[0] = 1;
        a[n - 1] = 1; b[n - 1] = 2; c[n - 1] = 0;
        for (int d = 0; d < dim; d++) {
            tg[d] = 3 * (PT(1)[d] - PT(0)[d]) / tl[0];
            tg[(size_t)(n - 1) * dim + d] = 3 * (PT(n - 1)[d] - PT(n - 2)[d]) / tl[n - 2];
        }
    }
#undef PT
    int st = pc_tridiag_solve(m, dim, a, b, c, tg, cyc);
    free(a);
    if (st == PC_OK && cyc)
        for (int d = 0; d < dim; d++) tg[(size_t)(n - 1) * dim + d] = sg * tg[d];
    return st;
}

pc_curve *pc_curve_book_spline(int dim, int n, const double *p, int chord, pc_book_ends ends,
                               const double *d0, const double *d1, double *tangents,
                               int *status) {
    if (dim < 1 || dim > PC_MAXDIM || n < 2 || n > 10000000) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    double *tl = malloc(sizeof(double) * (size_t)n);
    if (!tl) {
        *status = PC_ENOMEM;
        return NULL;
    }
    pc_curve *c = NULL;
    *status = pc_book_spline_params(dim, n, p, chord, tl);
    if (*status == PC_OK) c = pc_curve_book_spline_tl(dim, n, p, tl, ends, d0, d1, tangents, status);
    free(tl);
    return c;
}

pc_curve *pc_curve_book_spline_tl(int dim, int n, const double *p, const double *tl,
                                  pc_book_ends ends, const double *d0, const double *d1,
                                  double *tangents, int *status) {
    if (dim < 1 || dim > PC_MAXDIM || n < 2 || n > 10000000) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    for (int k = 0; k < n - 1; k++)
        if (!isfinite(tl[k]) || !(tl[k] > 0)) {
            *status = isfinite(tl[k]) ? PC_EDOMAIN : PC_ENONFINITE;
            return NULL;
        }
    double *u = malloc(sizeof(double) * (size_t)n * (1 + (size_t)dim));
    if (!u) {
        *status = PC_ENOMEM;
        return NULL;
    }
    double *tg = u + n;
    pc_curve *c = NULL;
    *status = pc_book_spline_tangents(dim, n, p, tl, ends, d0, d1, tg);
    if (*status == PC_OK) {
        u[0] = 0;
        for (int k = 1; k < n; k++) u[k] = u[k - 1] + tl[k - 1];
        c = pc_curve_hermite(dim, n, p, tg, NULL, u, 0, status);
        if (c && tangents) memcpy(tangents, tg, sizeof(double) * (size_t)n * dim);
    }
    free(u);
    return c;
}

/* --- the helix ------------------------------------------------------------------------------ */

static int helix_eval(void *ud, double t, int order, double *out) {
    const double *ab = ud, a = ab[0], b = ab[1], c = cos(t), s = sin(t);
    double rows[3][4] = {{a * c, a * s, b * t, 1}, {-a * s, a * c, b, 0}, {-a * c, -a * s, 0, 0}};
    memcpy(out, rows, sizeof(double) * 4 * (size_t)(order + 1));
    return PC_OK;
}

pc_curve *pc_curve_helix(double a, double b, double t0, double t1, int *status) {
    if (!isfinite(a) || !isfinite(b) || !isfinite(t0) || !isfinite(t1)) {
        *status = PC_ENONFINITE;
        return NULL;
    }
    if (!(t1 > t0) || a == 0) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    double *ab = malloc(2 * sizeof(double));
    if (!ab) {
        *status = PC_ENOMEM;
        return NULL;
    }
    ab[0] = a;
    ab[1] = b;
    pc_curve *c = pc_curve_func(3, t0, t1, 0, helix_eval, free, ab, status);
    if (!c) free(ab);
    return c;
}

int pc_bezier_g1_next(int dim, int n, const double *p, int m, double g, double *q0, double *q1) {
    if (dim < 1 || dim > PC_MAXDIM || n < 1 || m < 1) return PC_EDIM;
    if (!isfinite(g)) return PC_ENONFINITE;
    if (!(g > 0)) return PC_EDOMAIN;
    const double *pn = p + (size_t)n * dim, *pm = pn - dim;
    for (int k = 0; k < dim; k++) {
        if (!isfinite(pn[k]) || !isfinite(pm[k])) return PC_ENONFINITE;
        q0[k] = pn[k];
        q1[k] = pn[k] + n * (pn[k] - pm[k]) / (g * m);   /* Q1 - Q0 = n (Pn - Pn-1)/(g m) */
    }
    return PC_OK;
}

int pc_bezier_joint(int dim, int n, const double *p, int m, const double *q, int *kind, double *g) {
    if (dim < 1 || dim > PC_MAXDIM || n < 1 || m < 1) return PC_EDIM;
    const double *pn = p + (size_t)n * dim, *pm = pn - dim, *q1 = q + dim;
    double size = 0, gap = 0, u[PC_MAXDIM], v[PC_MAXDIM], uu = 0, uv = 0, vv = 0;
    for (int k = 0; k < dim; k++) {
        size = fmax(size, fmax(fabs(pn[k] - pm[k]), fabs(q1[k] - q[k])));
        gap = fmax(gap, fabs(pn[k] - q[k]));
        u[k] = n * (pn[k] - pm[k]);     /* P'(1) */
        v[k] = m * (q1[k] - q[k]);      /* Q'(0) */
        uu += u[k] * u[k], uv += u[k] * v[k], vv += v[k] * v[k];
    }
    *g = NAN;
    if (gap > 1e-9 * fmax(size, 1)) {
        *kind = 0;
        return PC_OK;
    }
    if (!(uu > 0) || !(vv > 0)) {     /* a zero end derivative: no tangent to compare */
        *kind = 1;
        return PC_OK;
    }
    double gg = uv / vv, off = 0;
    for (int k = 0; k < dim; k++) off = fmax(off, fabs(u[k] - gg * v[k]));
    if (gg > 0 && off <= 1e-9 * sqrt(uu)) {
        *g = gg;
        *kind = fabs(gg - 1) <= 1e-9 ? 3 : 2;
    } else {
        *kind = 1;
    }
    return PC_OK;
}
