/* Derivatives of any order, from either side of a joint, and the power-basis coefficients of
 * a piece (curve.h): on the piece's Bezier control points, by repeated differences (the k-th
 * hodograph) and de Casteljau, then the quotient rule generalised by Leibniz for rational
 * curves. */
#include "curve_impl.h"
#include <math.h>
#include <string.h>

/* The piece used at t from the side (-1 left, +1 right, 0 the default of pcc_piece), and its
 * parameter interval. */
static int piece_at(const pc_curve *c, double t, int side, double *a, double *b) {
    int k = pcc_piece(c, t), first = c->kind == PC_CURVE_BEZIER ? 0 : c->degree;
    const double *U = c->knots;
    if (side < 0 && k > first && t <= U[k]) {        /* at a joint: the piece ending there */
        k--;
        while (k > first && U[k] == U[k + 1]) k--;
    }
    if (side > 0 && t >= U[k + 1]) {
        int last = c->kind == PC_CURVE_BEZIER ? c->nknots - 2 : c->ncp - 1, j = k + 1;
        while (j <= last && U[j] == U[j + 1]) j++;
        if (j <= last) k = j;
    }
    *a = U[k];
    *b = U[k + 1];
    return k;
}

int pc_curve_eval_hn(const pc_curve *c, double t, int order, int side, double *out) {
    if (!c || !out) return PC_EARG;
    if (order < 0 || order > PC_CURVE_MAXDEG) return PC_EDOMAIN;
    if (!isfinite(t)) return PC_ENONFINITE;
    int w = c->dim + 1;
    if (c->kind == PC_CURVE_FUNC) {
        /* the callback's own (order <= 2); one side only (its breaks are its business) */
        if (order > 2) return PC_EDOMAIN;
        return pc_curve_eval_h(c, t, order, out);
    }
    double a, b;
    int k = piece_at(c, t, side, &a, &b), p = c->degree;
    double d[PCC_ROWS * PCC_W], e[PCC_ROWS * PCC_W];
    pcc_bezier_piece(c, k, d);
    double h = b - a, s = (t - a) / h;
    for (int j = 0; j <= order; j++) {
        int q = p - j;           /* the j-th hodograph has degree p - j */
        if (q < 0) {
            memset(out + (size_t)j * w, 0, sizeof(double) * w);
            continue;
        }
        memcpy(e, d, sizeof(double) * (size_t)(q + 1) * w);
        for (int r = 1; r <= q; r++)
            for (int i = 0; i <= q - r; i++)
                for (int x = 0; x < w; x++) e[i * w + x] += s * (e[(i + 1) * w + x] - e[i * w + x]);
        memcpy(out + (size_t)j * w, e, sizeof(double) * w);
        /* the next hodograph: q (P_{i+1} - P_i) / h */
        for (int i = 0; i < q; i++)
            for (int x = 0; x < w; x++) d[i * w + x] = q * (d[(i + 1) * w + x] - d[i * w + x]) / h;
    }
    return pcc_finite((size_t)(order + 1) * w, out) ? PC_OK : PC_ENONFINITE;
}

int pc_curve_derivs_n(const pc_curve *c, double t, int order, int side, double *out) {
    if (order < 0 || order > PC_CURVE_MAXDEG) return PC_EDOMAIN;
    double h[(PC_CURVE_MAXDEG + 1) * PCC_W];
    int st = pc_curve_eval_hn(c, t, order, side, h);
    if (st) return st;
    int n = c->dim, w = n + 1;
    double wt = h[n];
    if (wt == 0) return PC_IMPROPER;
    /* H = w C, so H^(k) = sum_i binom(k, i) w^(i) C^(k-i) (Leibniz) */
    for (int k = 0; k <= order; k++) {
        for (int x = 0; x < n; x++) {
            double v = h[k * w + x], bin = 1;
            for (int i = 1; i <= k; i++) {
                bin = bin * (k - i + 1) / i;
                v -= bin * h[i * w + n] * out[(k - i) * n + x];
            }
            out[k * n + x] = v / wt;
        }
    }
    return pcc_finite((size_t)(order + 1) * n, out) ? PC_OK : PC_ENONFINITE;
}

int pc_curve_monomial(const pc_curve *c, int piece, double *coef, int *degree) {
    if (!c || !coef) return PC_EARG;
    if (c->kind == PC_CURVE_FUNC) return PC_EDOMAIN;
    int npieces = c->kind == PC_CURVE_BEZIER ? c->nknots - 1 : c->ncp - c->degree;
    if (piece < 0 || piece >= npieces) return PC_EDOMAIN;
    int p = c->degree, w = c->dim + 1, k;
    if (c->kind == PC_CURVE_BEZIER) {
        k = piece;
    } else {      /* the piece-th non-empty span */
        k = c->degree - 1;
        for (int i = 0; i <= piece; i++) {
            k++;
            while (k < c->ncp - 1 && c->knots[k] == c->knots[k + 1]) k++;
        }
        if (c->knots[k] == c->knots[k + 1]) return PC_EDOMAIN;
    }
    /* Taylor at t = 0 of the piece's polynomial: coef_j = H^(j)(0)/j! */
    double d[PCC_ROWS * PCC_W], a = c->knots[k], h = c->knots[k + 1] - a, s = -a / h;
    pcc_bezier_piece(c, k, d);
    double fact = 1;
    for (int j = 0; j <= p; j++) {
        int q = p - j;
        double e[PCC_ROWS * PCC_W];
        memcpy(e, d, sizeof(double) * (size_t)(q + 1) * w);
        for (int r = 1; r <= q; r++)
            for (int i = 0; i <= q - r; i++)
                for (int x = 0; x < w; x++) e[i * w + x] += s * (e[(i + 1) * w + x] - e[i * w + x]);
        if (j > 0) fact *= j;
        for (int x = 0; x < w; x++) coef[j * w + x] = e[x] / fact;
        for (int i = 0; i < q; i++)
            for (int x = 0; x < w; x++) d[i * w + x] = q * (d[(i + 1) * w + x] - d[i * w + x]) / h;
    }
    *degree = p;
    return pcc_finite((size_t)(p + 1) * w, coef) ? PC_OK : PC_ENONFINITE;
}

int pc_curve_npieces(const pc_curve *c) {
    if (c->kind == PC_CURVE_FUNC) return 0;
    if (c->kind == PC_CURVE_BEZIER) return c->nknots - 1;
    int n = 0;
    for (int k = c->degree; k < c->ncp; k++) n += c->knots[k] < c->knots[k + 1];
    return n;
}

int pc_curve_monomial_rows(const pc_curve *c, int piece, double *rows, int *degree, int *rational) {
    double coef[PCC_ROWS * PCC_W];
    int st = pc_curve_monomial(c, piece, coef, degree);
    if (st != PC_OK) return st;
    int p = *degree, w = c->dim + 1;
    *rational = 0;
    for (int j = 0; j <= p; j++) {
        for (int x = 0; x < w; x++) rows[x * (p + 1) + j] = coef[j * w + x] + 0.0;   /* no -0 */
        if (fabs(coef[j * w + c->dim] - (j == 0)) > 1e-12) *rational = 1;
    }
    return PC_OK;
}
