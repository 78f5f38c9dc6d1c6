/* Evaluating curves: de Boor on the homogeneous coordinates (a Bezier segment is a span with
 * its end knots repeated), exact derivatives from the last two levels of the same scheme (the
 * blossom differentiated in one or two of its arguments), then the quotient rule; FUNC curves
 * through their callback, differenced when it offers no derivatives. */
#include "curve_impl.h"
#include <math.h>
#include <string.h>

void pcc_deboor(int q, int w, double *d, const double *U, int k, double x, int order,
                double *out) {
    for (int r = 1; r <= q - 2; r++) {
        for (int j = q; j >= r; j--) {
            int i = j + k - q;
            double a = (x - U[i]) / (U[j + 1 + k - r] - U[i]);
            double *dj = d + j * w, *dm = dj - w;
            for (int c = 0; c < w; c++) dj[c] = dm[c] + a * (dj[c] - dm[c]);
        }
    }
    double den = U[k + 1] - U[k], a = (x - U[k]) / den;
    if (q == 1) {
        const double *e0 = d, *e1 = d + w;
        for (int c = 0; c < w; c++) {
            out[c] = e0[c] + a * (e1[c] - e0[c]);
            if (order >= 1) out[w + c] = (e1[c] - e0[c]) / den;
            if (order >= 2) out[2 * w + c] = 0;
        }
        return;
    }
    const double *e0 = d + (q - 2) * w, *e1 = e0 + w, *e2 = e1 + w;
    double den1 = U[k + 1] - U[k - 1], den2 = U[k + 2] - U[k];
    double a1 = (x - U[k - 1]) / den1, a2 = (x - U[k]) / den2;
    for (int c = 0; c < w; c++) {
        double f1 = e0[c] + a1 * (e1[c] - e0[c]), f2 = e1[c] + a2 * (e2[c] - e1[c]);
        out[c] = f1 + a * (f2 - f1);
        if (order >= 1) out[w + c] = q * (f2 - f1) / den;
        if (order >= 2) {
            double g1 = (e1[c] - e0[c]) / den1, g2 = (e2[c] - e1[c]) / den2;
            out[2 * w + c] = q * (q - 1) * (g2 - g1) / den;
        }
    }
}

/* --- FUNC: the callback, or central differences of its values ------------------------------ */
static int func_value(const pc_curve *c, double t, double *out) {
    int st = c->func->eval(c->func->ud, t, 0, out);
    if (st) return st;
    return pcc_finite((size_t)c->dim + 1, out) ? PC_OK : PC_ENONFINITE;
}

/* 4th-order central differences with steps h1 = 1e-3 s (first derivative) and h2 = 2e-3 s
 * (second), s = min(width of the domain, max(1, |t|)).  If the callback refuses a point outside the domain, the stencil is
 * moved inside it and the result carried back by a Taylor step (less accurate there). */
static int func_diff(const pc_curve *c, double t, int order, double *out) {
    int w = c->dim + 1;
    double s = fmin(c->t1 - c->t0, fmax(1, fabs(t)));
    double h1 = 1e-3 * s, h2 = 2e-3 * s;
    double f[5][PCC_W], g[5][PCC_W];
    double tc = t;
    for (int attempt = 0; attempt < 2; attempt++) {
        int st = func_value(c, tc, f[2]);
        for (int i = -2; !st && i <= 2; i++)
            if (i) st = func_value(c, tc + i * h1, f[2 + i]);
        if (!st && order >= 2) {
            memcpy(g[2], f[2], sizeof(double) * w);
            for (int i = -2; !st && i <= 2; i++)
                if (i) st = func_value(c, tc + i * h2, g[2 + i]);
        }
        if (!st) break;
        double lo = c->t0 + 2 * h2, hi = c->t1 - 2 * h2;
        if (attempt == 1 || lo > hi || (tc >= lo && tc <= hi) ||
            (tc - 2 * h2 >= c->t0 && tc + 2 * h2 <= c->t1))
            return st;
        tc = tc < lo ? lo : hi;
    }
    double d1[PCC_W], d2[PCC_W];
    for (int x = 0; x < w; x++) {
        d1[x] = (f[0][x] - 8 * f[1][x] + 8 * f[3][x] - f[4][x]) / (12 * h1);
        d2[x] = order >= 2 ? (-g[0][x] + 16 * g[1][x] - 30 * g[2][x] + 16 * g[3][x] - g[4][x]) /
                             (12 * h2 * h2) : 0;
    }
    if (tc != t) {      /* carried back from the shifted stencil */
        double dt = t - tc;
        int st = func_value(c, t, out);
        if (st) return st;
        if (order < 2) {   /* need a second derivative for the Taylor step */
            for (int i = -2; i <= 2; i++)
                if (i && (st = func_value(c, tc + i * h2, g[2 + i]))) return st;
            memcpy(g[2], f[2], sizeof(double) * w);
            for (int x = 0; x < w; x++)
                d2[x] = (-g[0][x] + 16 * g[1][x] - 30 * g[2][x] + 16 * g[3][x] - g[4][x]) /
                        (12 * h2 * h2);
        }
        for (int x = 0; x < w; x++) {
            out[w + x] = d1[x] + dt * d2[x];
            if (order >= 2) out[2 * w + x] = d2[x];
        }
        return PC_OK;
    }
    memcpy(out, f[2], sizeof(double) * w);
    memcpy(out + w, d1, sizeof(double) * w);
    if (order >= 2) memcpy(out + 2 * w, d2, sizeof(double) * w);
    return PC_OK;
}

/* --- the value and its derivatives ------------------------------------------------------- */
int pc_curve_value(const pc_curve *c, double t, double *out) {
    int st = pc_curve_eval_h(c, t, 0, out);
    if (st != PC_OK) return st;
    double w = out[c->dim];
    for (int k = 0; w != 0 && k < c->dim; k++) out[k] /= w;
    out[c->dim] = w != 0;
    return PC_OK;
}

int pc_curve_eval_h(const pc_curve *c, double t, int order, double *out) {
    if (!c || !out) return PC_EARG;
    if (order < 0 || order > 2) return PC_EDOMAIN;
    if (!isfinite(t)) return PC_ENONFINITE;
    int w = c->dim + 1;
    if (c->kind == PC_CURVE_FUNC) {
        int st = c->func->eval(c->func->ud, t, order, out);
        if (st == PC_EDOMAIN && order > 0) st = func_diff(c, t, order, out);
        if (st) return st;
    } else {
        double d[PCC_ROWS * PCC_W], Ub[2 * PCC_ROWS];
        int p = c->degree, k = pcc_piece(c, t);
        const double *U = c->knots, *rows;
        if (c->kind == PC_CURVE_BEZIER) {
            rows = c->cp + (size_t)k * p * w;
            k = pcc_bezier_knots(c, k, Ub);
            U = Ub;
        } else {
            rows = c->cp + (size_t)(k - p) * w;
        }
        memcpy(d, rows, sizeof(double) * (size_t)(p + 1) * w);
        pcc_deboor(p, w, d, U, k, t, order, out);
    }
    return pcc_finite((size_t)(order + 1) * w, out) ? PC_OK : PC_ENONFINITE;
}

int pc_curve_eval(const pc_curve *c, double t, double *out) {
    double h[PCC_W];
    int st = pc_curve_eval_h(c, t, 0, h);
    if (st) return st;
    int n = c->dim;
    if (h[n] == 0) {
        memcpy(out, h, sizeof(double) * n);
        return PC_IMPROPER;
    }
    for (int i = 0; i < n; i++) out[i] = h[i] / h[n];
    return pcc_finite((size_t)n, out) ? PC_OK : PC_ENONFINITE;
}

int pc_curve_derivs(const pc_curve *c, double t, int order, double *out) {
    double h[3 * PCC_W];
    int st = pc_curve_eval_h(c, t, order, h);
    if (st) return st;
    int n = c->dim, w = n + 1;
    double wt = h[n];
    if (wt == 0) return PC_IMPROPER;
    double *c0 = out, *c1 = out + n, *c2 = out + 2 * n;
    for (int i = 0; i < n; i++) {
        c0[i] = h[i] / wt;
        if (order >= 1) c1[i] = (h[w + i] - h[w + n] * c0[i]) / wt;
        if (order >= 2) c2[i] = (h[2 * w + i] - 2 * h[w + n] * c1[i] - h[2 * w + n] * c0[i]) / wt;
    }
    return pcc_finite((size_t)(order + 1) * n, out) ? PC_OK : PC_ENONFINITE;
}

int pc_curve_curvature(const pc_curve *c, double t, double *k) {
    double d[3 * PC_MAXDIM];
    if (!k) return PC_EARG;
    int st = pc_curve_derivs(c, t, 2, d);
    if (st) return st;
    int n = c->dim;
    const double *d1 = d + n, *d2 = d + 2 * n;
    double s11 = 0, s22 = 0, s12 = 0;
    for (int i = 0; i < n; i++) {
        s11 += d1[i] * d1[i];
        s22 += d2[i] * d2[i];
        s12 += d1[i] * d2[i];
    }
    if (s11 == 0) return PC_EZERO;
    double v3 = s11 * sqrt(s11);
    if (n == 2) {
        *k = (d1[0] * d2[1] - d1[1] * d2[0]) / v3;
    } else {
        double a = s11 * s22 - s12 * s12;     /* |C' x C''|^2 (Lagrange's identity) */
        *k = sqrt(a > 0 ? a : 0) / v3;
    }
    return isfinite(*k) ? PC_OK : PC_ENONFINITE;
}

int pc_curve_frame(const pc_curve *c, double t, double *e, double *nrm) {
    double d[3 * PC_MAXDIM];
    int n = c->dim, st = pc_curve_derivs(c, t, nrm && n != 2 ? 2 : 1, d);
    if (st) return st;
    if (pc_unit(n, d + n, e) != PC_OK) return PC_EZERO;
    if (!nrm) return PC_OK;
    if (n == 2) {
        pc_perp2(e, nrm);
        return PC_OK;
    }
    double a = pc_dot(n, d + 2 * n, e);   /* C'' less its part along the tangent */
    for (int i = 0; i < n; i++) nrm[i] = d[2 * n + i] - a * e[i];
    return pc_unit(n, nrm, nrm) == PC_OK ? PC_OK : PC_ECOLLINEAR;
}
