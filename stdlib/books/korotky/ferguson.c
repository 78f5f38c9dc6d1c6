/* Polynomial and Ferguson splines of Korotky & Vitovtov (2021): eqs (1)-(9), (10), (19)-(29).
 * See ferguson.h and korotky_curves_surfaces.md, part A. */
#include "ferguson.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "linalg.h"
#include "numeric.h"

#define SETBAD(v) do { if (bad) *bad = (v); } while (0)

static double cross2(const double *a, const double *b) { return a[0] * b[1] - a[1] * b[0]; }

/* ---- the polynomial spline y = S(x), eqs (1)-(9) ------------------------------------------ */

int pc_poly_spline(int n, const double *x, const double *y, pc_end_kind ends, double s0,
                   double s1, double *coef, int *bad) {
    SETBAD(-1);
    if (n < 2) return PC_EDIM;
    if (ends != PC_END_NATURAL && ends != PC_END_CLAMPED) return PC_EARG;
    for (int i = 0; i < n; i++)
        if (!isfinite(x[i]) || !isfinite(y[i])) {
            SETBAD(i);
            return PC_ENONFINITE;
        }
    if (ends == PC_END_CLAMPED && (!isfinite(s0) || !isfinite(s1))) return PC_ENONFINITE;
    for (int i = 1; i < n; i++)
        if (!(x[i] > x[i - 1])) {
            SETBAD(i);
            return PC_EDOMAIN;
        }
    /* Moments M_i = S''(x_i): h_(i-1) M_(i-1) + 2 (h_(i-1) + h_i) M_i + h_i M_(i+1)
     * = 6 (slope_i - slope_(i-1)); natural ends M = 0 (eq. (6) and c_1 = 0), clamped ends
     * 2 h M_0 + h M_1 = 6 (slope_0 - s0) and its mirror (eq. (8)). */
    double *w = malloc(sizeof(double) * 4 * (size_t)n);
    if (!w) return PC_ENOMEM;
    double *a = w, *b = w + n, *c = w + 2 * n, *m = w + 3 * n;
    for (int i = 0; i < n; i++) {
        double hl = i > 0 ? x[i] - x[i - 1] : 0, hr = i < n - 1 ? x[i + 1] - x[i] : 0;
        double sl = i > 0 ? (y[i] - y[i - 1]) / hl : 0, sr = i < n - 1 ? (y[i + 1] - y[i]) / hr : 0;
        if (i > 0 && i < n - 1) {
            a[i] = hl; b[i] = 2 * (hl + hr); c[i] = hr; m[i] = 6 * (sr - sl);
        } else if (ends == PC_END_NATURAL) {
            a[i] = 0; b[i] = 1; c[i] = 0; m[i] = 0;
        } else if (i == 0) {
            a[i] = 0; b[i] = 2 * hr; c[i] = hr; m[i] = 6 * (sr - s0);
        } else {
            a[i] = hl; b[i] = 2 * hl; c[i] = 0; m[i] = 6 * (s1 - sl);
        }
    }
    int st = pc_tridiag_solve(n, 1, a, b, c, m, 0);
    if (st == PC_OK)
        for (int i = 0; i < n - 1; i++) {
            double h = x[i + 1] - x[i];
            double *k = coef + 4 * i;
            k[0] = y[i];
            k[1] = (y[i + 1] - y[i]) / h - h * (2 * m[i] + m[i + 1]) / 6;
            k[2] = m[i] / 2;
            k[3] = (m[i + 1] - m[i]) / (6 * h);
        }
    free(w);
    return st;
}

pc_curve *pc_poly_spline_curve(int n, const double *x, const double *coef, int *status) {
    if (n < 2) {
        *status = PC_EDIM;
        return NULL;
    }
    double *w = malloc(sizeof(double) * 4 * (size_t)n);
    if (!w) {
        *status = PC_ENOMEM;
        return NULL;
    }
    double *p = w, *d = w + 2 * n;
    for (int i = 0; i < n; i++) {
        const double *k = coef + 4 * (i < n - 1 ? i : n - 2);
        double h = i < n - 1 ? 0 : x[n - 1] - x[n - 2];
        p[2 * i] = x[i];
        p[2 * i + 1] = k[0] + h * (k[1] + h * (k[2] + h * k[3]));
        d[2 * i] = 1;                                   /* x is the parameter */
        d[2 * i + 1] = k[1] + h * (2 * k[2] + 3 * h * k[3]);
    }
    pc_curve *c = pc_curve_hermite(2, n, p, d, NULL, x, 0, status);
    free(w);
    return c;
}

/* ---- Ferguson splines ---------------------------------------------------------------------- */

/* Unit tangents into u (n rows of 2); PC_EZERO (*bad) for a zero row. */
static int unit_tangents(int n, const double *T, double *u, int *bad) {
    for (int i = 0; i < n; i++) {
        double l = hypot(T[2 * i], T[2 * i + 1]);
        if (!isfinite(l)) {
            SETBAD(i);
            return PC_ENONFINITE;
        }
        if (!(l > 0)) {
            SETBAD(i);
            return PC_EZERO;
        }
        u[2 * i] = T[2 * i] / l;
        u[2 * i + 1] = T[2 * i + 1] / l;
    }
    return PC_OK;
}

pc_curve *pc_ferguson_curve(int n, const double *p, const double *T, const double *mags,
                            int *status) {
    if (n < 2 || n > 100000) {
        *status = PC_EDIM;
        return NULL;
    }
    double *w = malloc(sizeof(double) * 6 * (size_t)n);
    if (!w) {
        *status = PC_ENOMEM;
        return NULL;
    }
    double *u = w, *dout = w + 2 * n, *din = w + 4 * n;
    pc_curve *c = NULL;
    *status = unit_tangents(n, T, u, NULL);
    if (*status == PC_OK) {
        for (int i = 0; i < n; i++) {
            double mo = i < n - 1 ? mags[2 * i] : mags[2 * i - 1];
            double mi = i > 0 ? mags[2 * i - 1] : mags[0];
            for (int k = 0; k < 2; k++) {
                dout[2 * i + k] = mo * u[2 * i + k];
                din[2 * i + k] = mi * u[2 * i + k];
            }
        }
        c = pc_curve_hermite(2, n, p, dout, din, NULL, 0, status);
    }
    free(w);
    return c;
}

int pc_ferguson_lambda(int dim, int n, const double *p, const double *dA, const double *dE,
                       const double *lambda, double *dout, double *din, int *bad) {
    SETBAD(-1);
    if (n < 2 || dim < 1 || dim > PC_MAXDIM) return PC_EDIM;
    for (int i = 0; i < n - 2; i++)
        if (!(lambda[i] > 0) || !isfinite(lambda[i])) {
            SETBAD(i + 1);
            return PC_EDOMAIN;
        }
    for (int k = 0; k < dim; k++) {
        dout[k] = din[k] = dA[k];
        dout[(n - 1) * dim + k] = din[(n - 1) * dim + k] = dE[k];
    }
    int m = n - 2;   /* interior knots 1..n-2 */
    if (m == 0) return PC_OK;
    double *w = malloc(sizeof(double) * (size_t)m * (3 + (size_t)dim));
    if (!w) return PC_ENOMEM;
    double *a = w, *b = w + m, *c = w + 2 * m, *r = w + 3 * m;
    for (int j = 0; j < m; j++) {
        int i = j + 1;
        double l = lambda[j], l2 = l * l;
        a[j] = l2;
        b[j] = 2 * (1 + l);
        c[j] = j < m - 1 ? 1 / lambda[j + 1] : 0;
        for (int k = 0; k < dim; k++) {
            double v = 3 * p[(i + 1) * dim + k] + 3 * p[i * dim + k] * (l2 - 1) -
                       3 * p[(i - 1) * dim + k] * l2;
            if (j == 0) v -= l2 * dA[k];        /* m_0 = w_A T_A is known */
            if (j == m - 1) v -= dE[k];         /* the incoming derivative at E is w_E T_E */
            r[j * dim + k] = v;
        }
    }
    int st = pc_tridiag_solve(m, dim, a, b, c, r, 0);
    if (st == PC_OK)
        for (int j = 0; j < m; j++)
            for (int k = 0; k < dim; k++) {
                dout[(j + 1) * dim + k] = r[j * dim + k];
                din[(j + 1) * dim + k] = r[j * dim + k] / lambda[j];
            }
    else
        SETBAD(1);
    free(w);
    return st;
}

/* System (23) for any n: the unknowns are mags[1..2n-4]. */
typedef struct {
    int n;
    const double *p, *T;
    double *mags;
} fsys;

static int eq23(void *ud, const double *z, double *f) {
    fsys *s = ud;
    int n = s->n;
    const double *p = s->p, *T = s->T;
    double *g = s->mags;
    memcpy(g + 1, z, sizeof(double) * (size_t)(2 * n - 4));
    for (int i = 1; i < n - 1; i++) {
        double zm = g[2 * i - 1], zp = g[2 * i], wprev = g[2 * i - 2], wnext = g[2 * i + 1];
        for (int k = 0; k < 2; k++)
            f[2 * (i - 1) + k] = 3 * zm * zm * (p[2 * (i + 1) + k] - p[2 * i + k]) +
                                 3 * zp * zp * (p[2 * i + k] - p[2 * (i - 1) + k]) -
                                 zp * zp * wprev * T[2 * (i - 1) + k] -
                                 2 * (zm * zm * zp + zm * zp * zp) * T[2 * i + k] -
                                 zm * zm * wnext * T[2 * (i + 1) + k];
    }
    return PC_OK;
}

int pc_ferguson_tangents(int n, const double *p, const double *T, double *mags, int start,
                         int *bad) {
    SETBAD(-1);
    if (n < 2 || n > PC_FERGUSON_MAXN) return PC_EDIM;
    double u[2 * PC_FERGUSON_MAXN];
    int st = unit_tangents(n, T, u, bad);
    if (st != PC_OK) return st;
    for (int i = 0; i < 2 * n; i++)
        if (!isfinite(p[i])) {
            SETBAD(i / 2);
            return PC_ENONFINITE;
        }
    for (int i = 1; i < n; i++)
        if (p[2 * i] == p[2 * i - 2] && p[2 * i + 1] == p[2 * i - 1]) {
            SETBAD(i);
            return PC_ECOINCIDENT;
        }
    if (n == 2) return PC_OK;
    int nz = 2 * n - 4;
    double z[2 * PC_FERGUSON_MAXN];
    for (int j = 0; j < nz; j++) {
        int seg = (j + 1) / 2;   /* mags[j + 1] belongs to segment (j + 1) / 2 */
        z[j] = start ? mags[j + 1]
                     : hypot(p[2 * seg + 2] - p[2 * seg], p[2 * seg + 3] - p[2 * seg + 1]);
    }
    double g[2 * PC_FERGUSON_MAXN];
    memcpy(g, mags, sizeof(double) * (size_t)(2 * n - 2));
    fsys s = {n, p, u, g};
    int worst = -1;
    st = pc_newton(nz, eq23, &s, z, 1e-13, 200, NULL, &worst);
    if (st != PC_OK) {
        /* an unknown or an equation pair belongs to its knot: mags[j+1] to knot (j+2)/2 */
        SETBAD(st == PC_ESINGULAR ? (worst + 2) / 2 : worst / 2 + 1);
        return st;
    }
    double chord = 0;
    for (int i = 1; i < n; i++)
        chord = fmax(chord, hypot(p[2 * i] - p[2 * i - 2], p[2 * i + 1] - p[2 * i - 1]));
    for (int j = 0; j < nz; j++)
        if (!(z[j] > 1e-6 * chord)) {   /* zero or negative: a degenerate root of (23) */
            SETBAD((j + 2) / 2);
            return PC_EDOMAIN;
        }
    memcpy(mags + 1, z, sizeof(double) * (size_t)nz);
    return PC_OK;
}

int pc_ferguson_substitution(int n, const double *p, const double *T, double *mags,
                             int root_max, double *quad, int *bad) {
    SETBAD(-1);
    if (n < 2 || n > PC_FERGUSON_MAXN) return PC_EDIM;
    double u[2 * PC_FERGUSON_MAXN];
    int st = unit_tangents(n, T, u, bad);
    if (st != PC_OK) return st;
    if (!isfinite(mags[0]) || !isfinite(mags[1])) return PC_ENONFINITE;
    if (n == 2) return PC_OK;
    for (int i = 1; i < n - 1; i++) {
        const double *Tp = u + 2 * (i - 1), *Ti = u + 2 * i, *Tn = u + 2 * (i + 1);
        double wprev = mags[2 * i - 2], zm = mags[2 * i - 1];
        if (!(zm > 0)) {
            SETBAD(i);
            return PC_EDOMAIN;
        }
        double a[2], V[2];
        for (int k = 0; k < 2; k++) {
            a[k] = p[2 * (i + 1) + k] - p[2 * i + k];
            V[k] = 3 * (p[2 * i + k] - p[2 * (i - 1) + k]) - wprev * Tp[k];
        }
        double tt = cross2(Ti, Tn);
        double A2 = cross2(V, Tn) - 2 * zm * tt, A1 = -2 * zm * zm * tt;
        double A0 = 3 * zm * zm * cross2(a, Tn);
        if (quad) {
            quad[3 * (i - 1)] = A2;
            quad[3 * (i - 1) + 1] = A1;
            quad[3 * (i - 1) + 2] = A0;
        }
        double roots[2];
        int nr = 0;
        double scale = fmax(fabs(A2), fmax(fabs(A1), fabs(A0)));
        if (!(scale > 0)) {
            SETBAD(i);
            return PC_ESINGULAR;
        }
        if (fabs(A2) <= 1e-12 * scale) {   /* a linear equation */
            if (fabs(A1) > 1e-12 * scale) roots[nr++] = -A0 / A1;
        } else {
            double disc = A1 * A1 - 4 * A2 * A0;
            if (disc >= 0) {
                /* the stable pair of formulas (no cancellation) */
                double q = -0.5 * (A1 + copysign(sqrt(disc), A1));
                roots[nr++] = q / A2;
                if (q != 0) roots[nr++] = A0 / q;
            }
        }
        /* admissible: z+ > 0 and a positive next modulus */
        double best = NAN, bestu = NAN;
        for (int r = 0; r < nr; r++) {
            double zp = roots[r];
            if (!(zp > 0)) continue;
            double R[2];
            for (int k = 0; k < 2; k++)
                R[k] = 3 * zm * zm * a[k] + zp * zp * V[k] - 2 * (zm * zm * zp + zm * zp * zp) * Ti[k];
            double un = (R[0] * Tn[0] + R[1] * Tn[1]) / (zm * zm);
            if (!(un > 0)) continue;
            if (isnan(best) || (root_max ? zp > best : zp < best)) {
                best = zp;
                bestu = un;
            }
        }
        if (isnan(best)) {
            SETBAD(i);
            return PC_EDOMAIN;
        }
        mags[2 * i] = best;
        mags[2 * i + 1] = bestu;
    }
    return PC_OK;
}
