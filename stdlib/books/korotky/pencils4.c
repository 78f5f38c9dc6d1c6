/* Meets of 2-planes in four dimensions and the surface of two pencils (pencils4.h). */
#include "pencils4.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* An orthonormal basis of the span of k homogeneous 5-vectors (modified Gram-Schmidt, a
 * vector dropped when less than tol of its length remains); the rank. */
static int span_basis(int k, const double v[][5], double b[][5]) {
    int r = 0;
    for (int i = 0; i < k; i++) {
        double x[5], len0 = 0, len = 0;
        memcpy(x, v[i], sizeof x);
        for (int m = 0; m < 5; m++) len0 += x[m] * x[m];
        for (int pass = 0; pass < 2; pass++)   /* twice is enough (Kahan) */
            for (int j = 0; j < r; j++) {
                double d = 0;
                for (int m = 0; m < 5; m++) d += x[m] * b[j][m];
                for (int m = 0; m < 5; m++) x[m] -= d * b[j][m];
            }
        for (int m = 0; m < 5; m++) len += x[m] * x[m];
        if (!(len > 1e-20 * len0) || !(len0 > 0)) continue;
        len = sqrt(len);
        for (int m = 0; m < 5; m++) b[r][m] = x[m] / len;
        r++;
    }
    return r;
}

int pc_meet_planes4(const double p[3][5], const double q[3][5], double out[5]) {
    for (int i = 0; i < 3; i++)
        for (int m = 0; m < 5; m++)
            if (!isfinite(p[i][m]) || !isfinite(q[i][m])) return PC_ENONFINITE;
    double P[3][5], Q[3][5];
    int rp = span_basis(3, p, P), rq = span_basis(3, q, Q);
    /* the common subspace: the part of the flat Q's span inside P's span is found as the
     * null space of [P | -Q] (5 x (rp + rq)), by elimination with complete pivoting */
    int n = rp + rq;
    double A[5][6], piv_scale = 0;
    for (int m = 0; m < 5; m++) {
        for (int j = 0; j < rp; j++) A[m][j] = P[j][m];
        for (int j = 0; j < rq; j++) A[m][rp + j] = -Q[j][m];
    }
    int col[6] = {0}, rank = 0;
    for (int j = 0; j < n; j++) col[j] = j;
    for (int r = 0; r < 5 && r < n; r++) {
        int bi = r, bj = r;
        double best = 0;
        for (int i = r; i < 5; i++)
            for (int j = r; j < n; j++)
                if (fabs(A[i][j]) > best) best = fabs(A[i][j]), bi = i, bj = j;
        if (r == 0) piv_scale = best;
        if (!(best > 1e-10 * piv_scale) || !(best > 0)) break;
        for (int j = 0; j < n; j++) { double t = A[r][j]; A[r][j] = A[bi][j]; A[bi][j] = t; }
        for (int i = 0; i < 5; i++) { double t = A[i][r]; A[i][r] = A[i][bj]; A[i][bj] = t; }
        int t = col[r]; col[r] = col[bj]; col[bj] = t;
        for (int i = 0; i < 5; i++) {
            if (i == r) continue;
            double f = A[i][r] / A[r][r];
            for (int j = r; j < n; j++) A[i][j] -= f * A[r][j];
        }
        rank++;
    }
    int nullity = n - rank;
    if (nullity == 0) return PC_ESKEW;
    if (nullity > 1) return PC_ESAME_LINE;
    /* the null vector: the free column set to 1, the pivots solved back */
    double x[6] = {0};
    x[col[rank]] = 1;
    for (int r = 0; r < rank; r++) x[col[r]] = -A[r][rank] / A[r][r];
    double h[5] = {0};
    for (int j = 0; j < rp; j++)
        for (int m = 0; m < 5; m++) h[m] += x[j] * P[j][m];
    double len = 0;
    for (int m = 0; m < 5; m++) len += h[m] * h[m];
    if (!(len > 0)) return PC_ESAME_LINE;
    if (fabs(h[4]) > 1e-12 * sqrt(len))
        for (int m = 0; m < 5; m++) h[m] /= h[4];
    memcpy(out, h, sizeof h);
    return PC_OK;
}

typedef struct { pc_pencil_point g[6]; } pencils;

static void pencils_free(void *ud) {
    pencils *d = ud;
    for (int i = 0; i < 6; i++) pc_curve_release(d->g[i].c);
    free(d);
}

static int gen_at(const pc_pencil_point *g, double s, double *h) {
    if (!g->c) {
        memcpy(h, g->h, sizeof(double) * 5);
        return PC_OK;
    }
    return pc_curve_eval_h(g->c, g->c->t0 + s * (g->c->t1 - g->c->t0), 0, h);
}

static int pencils_eval(void *ud, double u, double v, int order, double *out) {
    if (order > 0) return PC_EDOMAIN;
    const pencils *d = ud;
    double p[3][5], q[3][5];
    for (int i = 0; i < 3; i++) {
        int st = gen_at(&d->g[i], u, p[i]);
        if (st == PC_OK) st = gen_at(&d->g[3 + i], v, q[i]);
        if (st != PC_OK) return st;
    }
    return pc_meet_planes4(p, q, out);
}

pc_surface *pc_surface_two_pencils(const pc_pencil_point om[3], const pc_pencil_point de[3],
                                   int *status) {
    pencils *d = calloc(1, sizeof *d);
    if (!d) {
        *status = PC_ENOMEM;
        return NULL;
    }
    for (int i = 0; i < 6; i++) {
        const pc_pencil_point *g = i < 3 ? &om[i] : &de[i - 3];
        if (g->c && g->c->dim != 4) {
            for (int j = 0; j < i; j++) pc_curve_release(d->g[j].c);
            free(d);
            *status = PC_EDIM;
            return NULL;
        }
        for (int m = 0; m < 5 && !g->c; m++)
            if (!isfinite(g->h[m])) {
                for (int j = 0; j < i; j++) pc_curve_release(d->g[j].c);
                free(d);
                *status = PC_ENONFINITE;
                return NULL;
            }
        d->g[i] = *g;
        if (g->c) pc_curve_retain(g->c);
    }
    pc_surface *s = pc_surface_func(4, 0, 1, 0, 1, pencils_eval, pencils_free, d, status);
    if (!s) pencils_free(d);
    return s;
}

pc_surface *pc_surface_two_pencils_checked(const pc_pencil_point om[3], const pc_pencil_point de[3],
                                           int *status, int *meet) {
    double out[5];
    pc_surface *s = pc_surface_two_pencils(om, de, status);
    *meet = s ? pc_surface_eval_h(s, .5, .5, 0, out) : PC_OK;
    if (*meet == PC_OK) return s;
    pc_surface_release(s);
    *status = *meet;
    return NULL;
}
