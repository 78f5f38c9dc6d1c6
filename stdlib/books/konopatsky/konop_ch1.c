/* Konopatsky's chapter 1: the theorems and the moving simplex (konop_ch1.h). */
#include "konop_ch1.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "linalg.h"
#include "point.h"
#include "names.h"
#include "konop_why.h"

static int finite_rows(int n, int rows, const double *x) {
    for (int i = 0; i < n * rows; i++)
        if (!isfinite(x[i])) return 0;
    return 1;
}

int pc_k_area_k(double l1, double l2, double l3, double *k) {
    if (!isfinite(l1) || !isfinite(l2) || !isfinite(l3)) return PC_ENONFINITE;
    double den = (1 + l1) * (1 + l2) * (1 + l3);
    if (den == 0) return PC_EPOLE;
    *k = (1 + l1 * l2 * l3) / den;
    return PC_OK;
}

/* (B A1 A2) = (B - A2)/(A2 - A1) for B on line A1A2: a finite number even at B = A2, where
 * the lambda of the theorem is infinite; PC_ENOTCOLLINEAR off the line. */
static int side_param(int n, const double *a1, const double *a2, const double *b, double size,
                      double *out) {
    double d[PC_MAXDIM], e[PC_MAXDIM], dd = 0, de = 0;
    for (int i = 0; i < n; i++) {
        d[i] = a2[i] - a1[i];
        e[i] = b[i] - a2[i];
        dd += d[i] * d[i];
        de += d[i] * e[i];
    }
    double s = de / dd, off = 0;
    for (int i = 0; i < n; i++) off = fmax(off, fabs(e[i] - s * d[i]));
    if (off > 1e-9 * size) return PC_ENOTCOLLINEAR;
    *out = s;
    return PC_OK;
}

int pc_k_area_theorem(int n, const double *a, const double *b, pc_k_areas *out) {
    if (n < 2 || n > PC_MAXDIM) return PC_EDIM;
    if (!finite_rows(n, 3, a) || !finite_rows(n, 3, b)) return PC_ENONFINITE;
    double size = fmax(pc_dist(n, a, a + n), fmax(pc_dist(n, a + n, a + 2 * n), pc_dist(n, a, a + 2 * n)));
    if (!(pc_area(n, a, a + n, a + 2 * n) > PC_DEGEN_TOL * size * size)) return PC_ECOLLINEAR;
    for (int i = 0; i < 3; i++) {
        const double *ai = a + n * i, *aj = a + n * ((i + 1) % 3);
        int st = side_param(n, ai, aj, b + n * i, size, &out->abc[i]);
        if (st != PC_OK) return st;
        /* a = -1/(1 + l) of the proof, so l = -(1 + a)/a */
        out->lambda[i] = out->abc[i] == 0 ? INFINITY : -(1 + out->abc[i]) / out->abc[i];
    }
    double x = out->abc[0], y = out->abc[1], z = out->abc[2];
    out->k = 1 + x + y + z + x * y + x * z + y * z;
    out->collinear = fabs(out->k) <= 1e-12 * (1 + fabs(x) + fabs(y) + fabs(z)) * (1 + fabs(x) + fabs(y) + fabs(z));
    return PC_OK;
}

int pc_k_o_theorem(int n, int m, const double *poly, const double *d1, const double *d2,
                   double *ratios, double *bpts, double *prod) {
    if (n < 2 || n > PC_MAXDIM || m < 3) return PC_EDIM;
    if (!finite_rows(n, m, poly) || !finite_rows(n, 1, d1) || !finite_rows(n, 1, d2)) return PC_ENONFINITE;
    double p = 1;
    for (int i = 0; i < m; i++) {
        const double *ai = poly + n * i, *aj = poly + n * ((i + 1) % m);
        double k[PC_MAXDIM + 1], lam, mu, res, r;
        int st = pc_meet(n, ai, aj, d1, d2, k, &lam, &mu, &res);
        if (st == PC_IMPROPER) {
            r = -1;      /* Bi at infinity: (XYZ) = -1, the identity holds projectively */
        } else if (st != PC_OK) {
            return st;
        } else {
            if (pc_dist(n, k, ai) <= 1e-12 * pc_dist(n, ai, aj) || pc_dist(n, k, aj) <= 1e-12 * pc_dist(n, ai, aj))
                return PC_EDOMAIN;                         /* d through a vertex */
            k[n] = 1;
            if ((st = pc_sr(n, ai, aj, k, &r)) != PC_OK) return st;
        }
        if (ratios) ratios[i] = r;
        if (bpts) memcpy(bpts + (size_t)(n + 1) * i, k, sizeof(double) * (size_t)(n + 1));
        p *= r;
    }
    *prod = p;
    return PC_OK;
}

int pc_k_simplex_ratio(int k, const double *rows, double *ratio) {
    if (k < 1 || k > 8) return PC_EDIM;
    int d = k + 1;
    for (int i = 0; i < d; i++) {
        double s = 0;
        for (int j = 0; j < d; j++) {
            if (!isfinite(rows[d * i + j])) return PC_ENONFINITE;
            s += rows[d * i + j];
        }
        if (fabs(s - 1) > 1e-12 * fmax(1, fabs(s))) return PC_EDOMAIN;
    }
    *ratio = pc_det(d, rows);
    return PC_OK;
}

int pc_k_simplex_ratio_rows(int nr, int nc, const double *rows, double *ratio, pc_why_call *w) {
    const char *op = "konopatsky.simplex_ratio";
    if (nr != nc || nr < 2 || nr > 9)
        return pc_why_call_set(w, op, PC_EDIM, 1, NULL,
                               "must hold 2 to 9 rows of as many numbers (a square matrix), got %d rows of %d", nr, nc);
    int st = pc_k_simplex_ratio(nr - 1, rows, ratio);
    const pc_why *row = pc_why_find(pc_konop_why, op, st);
    return pc_why_call_set(w, row ? op : NULL, st, row ? row->arg : 0, row ? row->key : NULL, "%s", row ? row->text : "");
}

int pc_k_meet_line_plane(int n, const double *a1, const double *a2, const double *p1,
                         const double *p2, const double *p3, double *out, double *lambda,
                         double *pq) {
    if (n < 3 || n > PC_MAXDIM) return PC_EDIM;
    if (!finite_rows(n, 1, a1) || !finite_rows(n, 1, a2) || !finite_rows(n, 1, p1) ||
        !finite_rows(n, 1, p2) || !finite_rows(n, 1, p3))
        return PC_ENONFINITE;
    double u[PC_MAXDIM], r[PC_MAXDIM], e1[PC_MAXDIM], e2[PC_MAXDIM];
    for (int i = 0; i < n; i++) {
        u[i] = a2[i] - a1[i];
        r[i] = a1[i] - p3[i];
        e1[i] = p1[i] - p3[i];
        e2[i] = p2[i] - p3[i];
    }
    double lu = pc_norm(n, u), l1 = pc_norm(n, e1), l2 = pc_norm(n, e2);
    if (!(lu > 0)) return PC_ECOINCIDENT;
    if (!(pc_area(n, p1, p2, p3) > PC_DEGEN_TOL * fmax(l1, l2) * fmax(l1, l2))) return PC_ECOLLINEAR;
    /* The V-theorem's zero volume of M P1 P2 P3 in any dimension: the parts of u and r off the
     * plane's directions (an orthonormal pair f1, f2 by Gram-Schmidt) must cancel,
     * r_perp + lambda u_perp = 0. */
    double f1[PC_MAXDIM], f2[PC_MAXDIM], up[PC_MAXDIM], rp[PC_MAXDIM];
    for (int i = 0; i < n; i++) f1[i] = e1[i] / l1;
    double c = pc_dot(n, e2, f1);
    for (int i = 0; i < n; i++) f2[i] = e2[i] - c * f1[i];
    double l2p = pc_norm(n, f2);
    for (int i = 0; i < n; i++) f2[i] /= l2p;
    double u1 = pc_dot(n, u, f1), u2 = pc_dot(n, u, f2), r1 = pc_dot(n, r, f1), r2 = pc_dot(n, r, f2);
    for (int i = 0; i < n; i++) {
        up[i] = u[i] - u1 * f1[i] - u2 * f2[i];
        rp[i] = r[i] - r1 * f1[i] - r2 * f2[i];
    }
    double nu = pc_norm(n, up), size = fmax(lu, fmax(l1, fmax(l2, pc_norm(n, r))));
    if (nu <= PC_DEGEN_TOL * lu) {
        if (pc_norm(n, rp) <= 1e-12 * size) return PC_ESAME_LINE;   /* the line lies in the plane */
        memcpy(out, u, sizeof(double) * (size_t)n);
        out[n] = 0;
        *lambda = INFINITY;
        return PC_IMPROPER;
    }
    double lam = -pc_dot(n, rp, up) / (nu * nu), off = 0;
    for (int i = 0; i < n; i++) off = fmax(off, fabs(rp[i] + lam * up[i]));
    if (off > 1e-9 * size) return PC_ESKEW;
    for (int i = 0; i < n; i++) out[i] = a1[i] + lam * u[i];
    out[n] = 1;
    *lambda = lam;
    if (pq) {
        /* K - P3 = e1 p + e2 q: in the frame f1, f2, e1 = (l1, 0), e2 = (c, l2p) */
        double k1 = r1 + lam * u1, k2 = r2 + lam * u2;
        pq[1] = k2 / l2p;
        pq[0] = (k1 - c * pq[1]) / l1;
    }
    return PC_OK;
}

int pc_k_polar(int n, const double *c, const double *a, const double *b, double rho, double phi,
               double *out) {
    if (n < 2 || n > PC_MAXDIM) return PC_EDIM;
    if (!finite_rows(n, 1, a) || !finite_rows(n, 1, b) || !finite_rows(n, 1, c) || !isfinite(rho) ||
        !isfinite(phi))
        return PC_ENONFINITE;
    /* §5.0: a = |CB|, b = |CA|, cos gamma = Sigma^C_AB/(ab), sin gamma in (0, 1] */
    double la = pc_dist(n, c, b), lb = pc_dist(n, c, a);
    if (!(la > 0) || !(lb > 0)) return PC_ECOLLINEAR;
    double cg = pc_sigma(n, c, a, b) / (la * lb), sg = sqrt(fmax(0, 1 - cg * cg));
    if (!(sg > PC_DEGEN_TOL)) return PC_ECOLLINEAR;
    double g = atan2(sg, cg);
    double p = rho * sin(g - phi) / (lb * sg), q = rho * sin(phi) / (la * sg);
    for (int i = 0; i < n; i++) out[i] = (a[i] - c[i]) * p + (b[i] - c[i]) * q + c[i];
    return PC_OK;
}

/* ---- the moving simplex ------------------------------------------------------------------ */

typedef struct {
    pc_curve *g[3], *gen;   /* NA, NB, NC and the generator (p, q) */
} msimplex;

static void ms_free(void *ud) {
    msimplex *m = ud;
    for (int i = 0; i < 3; i++) pc_curve_release(m->g[i]);
    pc_curve_release(m->gen);
    free(m);
}

static int ms_eval(void *ud, double u, double v, int order, double *out) {
    const msimplex *m = ud;
    int n = m->g[0]->dim, ord = order ? 1 : 0;
    double N[3][2 * PC_MAXDIM], G[4];
    for (int i = 0; i < 3; i++) {
        int st = pc_curve_derivs(m->g[i], u, ord, N[i]);
        if (st != PC_OK) return st;
    }
    int st = pc_curve_derivs(m->gen, v, ord, G);
    if (st != PC_OK) return st;
    double p = G[0], q = G[1];
    /* M = (NA - NC) p + (NB - NC) q + NC; homogeneous rows of n + 1 with weight 1 (0 for the
     * derivatives) */
    for (int i = 0; i < n; i++) {
        double A = N[0][i], B = N[1][i], C = N[2][i];
        out[i] = (A - C) * p + (B - C) * q + C;
        if (order) {
            double dA = N[0][n + i], dB = N[1][n + i], dC = N[2][n + i];
            out[(n + 1) + i] = (dA - dC) * p + (dB - dC) * q + dC;
            out[2 * (n + 1) + i] = (A - C) * G[2] + (B - C) * G[3];
        }
    }
    out[n] = 1;
    if (order) out[2 * n + 1] = out[3 * n + 2] = 0;
    return PC_OK;
}

int pc_k_moving_simplex_why(int st, const pc_curve *na, const pc_curve *nb, const pc_curve *nc,
                            const pc_curve *gen, char *buf, size_t n) {
    char t0[32], t1[32];
    if (st == PC_EDIM)
        snprintf(buf, n, "the guides must have one dimension (%d-D, %d-D, %d-D) and the generator gen must be 2-D "
                 "(its coordinates are p and q), got %d-D", na->dim, nb->dim, nc->dim, gen->dim);
    else if (st == PC_EDOMAIN)
        snprintf(buf, n, "the guides must run over one domain of u (NA over [%s, %s])",
                 pc_num_text(na->t0, t0, sizeof t0), pc_num_text(na->t1, t1, sizeof t1));
    return st == PC_EDIM || st == PC_EDOMAIN;
}

pc_surface *pc_k_moving_simplex(pc_curve *na, pc_curve *nb, pc_curve *nc, pc_curve *gen,
                                int *status) {
    pc_curve *g[3] = {na, nb, nc};
    for (int i = 1; i < 3; i++)
        if (g[i]->dim != na->dim) {
            *status = PC_EDIM;
            return NULL;
        }
    if (gen->dim != 2) {
        *status = PC_EDIM;
        return NULL;
    }
    for (int i = 1; i < 3; i++)
        if (fabs(g[i]->t0 - na->t0) > 1e-12 || fabs(g[i]->t1 - na->t1) > 1e-12) {
            *status = PC_EDOMAIN;
            return NULL;
        }
    msimplex *m = malloc(sizeof *m);
    if (!m) {
        *status = PC_ENOMEM;
        return NULL;
    }
    for (int i = 0; i < 3; i++) m->g[i] = pc_curve_retain(g[i]);
    m->gen = pc_curve_retain(gen);
    pc_surface *s = pc_surface_func(na->dim, na->t0, na->t1, gen->t0, gen->t1, ms_eval, ms_free, m, status);
    if (!s) ms_free(m);
    return s;
}
