/* Interpolation curves of Konopatsky's chapter 4 (konop_interp.h; digest konopatsky_ch3_5.md
 * §2). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "konop_interp.h"
#include "linalg.h"

#define MAXN (PC_CURVE_MAXDEG + 1)

static pc_curve *fail(int *status, int st) {
    *status = st;
    return NULL;
}

int pc_lagrange_weights(int n, const double *params, double t, double *w) {
    if (n < 1 || n > MAXN) return PC_EDIM;
    if (!isfinite(t)) return PC_ENONFINITE;
    for (int j = 0; j < n; j++) {
        double tj = params ? params[j] : (n > 1 ? (double)j / (n - 1) : 0), p = 1;
        for (int m = 0; m < n; m++) {
            if (m == j) continue;
            double tm = params ? params[m] : (double)m / (n - 1);
            if (tj == tm) return PC_ECOINCIDENT;
            p *= (t - tm) / (tj - tm);
        }
        w[j] = p;
        if (!isfinite(p)) return PC_ENONFINITE;   /* a t far outside the nodes overflows the products */
    }
    return PC_OK;
}

int pc_lagrange_weight_coefs(int n, const double *params, double *coef) {
    if (n < 1 || n > MAXN) return PC_EDIM;
    for (int j = 0; j < n; j++) {
        /* phi_j = prod_{m != j} (t - t_m)/(t_j - t_m), multiplied out factor by factor */
        double *c = coef + (size_t)j * n, tj = params ? params[j] : (n > 1 ? (double)j / (n - 1) : 0);
        for (int i = 0; i < n; i++) c[i] = i == 0;
        int deg = 0;
        for (int m = 0; m < n; m++) {
            if (m == j) continue;
            double tm = params ? params[m] : (double)m / (n - 1);
            if (!isfinite(tm) || !isfinite(tj)) return PC_ENONFINITE;
            if (tj == tm) return PC_ECOINCIDENT;
            double k = 1 / (tj - tm);
            for (int i = deg + 1; i >= 0; i--)
                c[i] = ((i > 0 ? c[i - 1] : 0) - tm * (i <= deg ? c[i] : 0)) * k;
            deg++;
        }
    }
    return PC_OK;
}

pc_curve *pc_interp_arc(int dim, int p, const double *pts, const double *c2, const double *cn,
                        int *status) {
    return pc_interp_arc_u(dim, p, pts, NULL, c2, cn, status);
}

pc_curve *pc_interp_arc_u(int dim, int p, const double *pts, const double *params,
                          const double *c2, const double *cn, int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    if (p < 2 || p > PC_CURVE_MAXDEG - 1) return fail(status, PC_EDOMAIN);
    if (params)
        for (int j = 0; j < p; j++)
            if (!isfinite(params[j]) || (j > 0 && !(params[j] > params[j - 1]))) return fail(status, PC_EDOMAIN);
    int N = cn ? p + 1 : p, nc = N + 1;            /* degree, control points */
    double *cp = calloc((size_t)nc * (size_t)(dim + 1), sizeof(double));
    int *known = calloc((size_t)nc, sizeof(int));
    double *m = malloc(sizeof(double) * (size_t)(p * p + p + 1) * 2);
    double *bern = malloc(sizeof(double) * (size_t)nc * (size_t)p);
    if (!cp || !known || !m || !bern) {
        free(cp), free(known), free(m), free(bern);
        return fail(status, PC_ENOMEM);
    }
#define CP(i, k) cp[(size_t)(i) * (dim + 1) + (k)]
    for (int k = 0; k < dim; k++) {
        CP(0, k) = pts[k];
        CP(1, k) = c2[k];
        CP(N, k) = pts[(size_t)(p - 1) * dim + k];
        if (cn) CP(N - 1, k) = cn[k];
    }
    known[0] = known[1] = known[N] = 1;
    if (cn) known[N - 1] = 1;
    int nu = 0, idx[MAXN];                        /* the unknown control points */
    for (int i = 0; i < nc; i++)
        if (!known[i]) idx[nu++] = i;
    /* Bernstein values at the interior nodes u_j = j/(p - 1), j = 1..p-2 */
    for (int j = 1; j <= p - 2; j++) {
        /* the node's place on the Bezier's own [0, 1] */
        double u = params ? (params[j] - params[0]) / (params[p - 1] - params[0]) : (double)j / (p - 1), binom = 1;
        for (int i = 0; i <= N; i++) {
            if (i > 0) binom = binom * (N - i + 1) / i;
            bern[(size_t)(j - 1) * nc + i] = binom * pow(1 - u, N - i) * pow(u, i);
        }
    }
    int st = PC_OK;
    for (int k = 0; k < dim && st == PC_OK && nu > 0; k++) {
        double *a = m, *rhs = m + nu * nu;
        for (int j = 0; j < nu; j++) {            /* row j: the node M_(j+2) */
            rhs[j] = pts[(size_t)(j + 1) * dim + k];
            for (int i = 0; i < nc; i++)
                if (known[i]) rhs[j] -= bern[(size_t)j * nc + i] * CP(i, k);
            for (int q = 0; q < nu; q++) a[j * nu + q] = bern[(size_t)j * nc + idx[q]];
        }
        st = pc_lu_solve(nu, a, rhs);
        for (int q = 0; q < nu && st == PC_OK; q++) CP(idx[q], k) = rhs[q];
    }
    for (int i = 0; i < nc; i++) CP(i, dim) = 1;
#undef CP
    double brk[2] = {params ? params[0] : 0, params ? params[p - 1] : 1};
    pc_curve *cv = st ? fail(status, st) : pc_curve_bezier_pieces(dim, N, 1, cp, brk, status);
    free(cp), free(known), free(m), free(bern);
    return cv;
}

int pc_interp_adaptive_params(int dim, int n, const double *pts, int axis, double *v) {
    if (dim < 1 || dim > PC_MAXDIM || axis < 0 || axis >= dim || n < 2) return PC_EDIM;
    double x1 = pts[axis], xn = pts[(size_t)(n - 1) * dim + axis];
    if (x1 == xn) return PC_ECOINCIDENT;
    for (int j = 0; j < n; j++) {
        v[j] = (x1 - pts[(size_t)j * dim + axis]) / (x1 - xn);
        if (!isfinite(v[j])) return PC_ENONFINITE;
        if (j > 0 && !(v[j] > v[j - 1])) return PC_EDOMAIN;
    }
    return PC_OK;
}

int pc_interp_adaptive_why(int st, int axis, char *buf, size_t n) {
    if (st == PC_ECOINCIDENT)
        snprintf(buf, n, "the first and last nodes have the same coordinate on axis %d", axis + 1);
    else if (st == PC_EDOMAIN)
        snprintf(buf, n, "the nodes must advance along axis %d in their order (the book's limitation: the order of "
                 "the nodes must be the order of the parameters)", axis + 1);
    return st == PC_ECOINCIDENT || st == PC_EDOMAIN;
}

int pc_interp_adaptive(int dim, int n, const double *pts, int axis, double *v, pc_why_call *w) {
    const char *op = "interp.adaptive";
    if (axis < 1 || axis > dim)
        return pc_why_call_set(w, op, PC_EDIM, 2, NULL, "must be an axis number 1..%d, got %d", dim, axis);
    int st = pc_interp_adaptive_params(dim, n, pts, axis - 1, v);
    char why[200] = "";
    if (!pc_interp_adaptive_why(st, axis - 1, why, sizeof why)) op = NULL;   /* unexplained: the status */
    return pc_why_call_set(w, op, st, 0, NULL, "%s", why);
}

/* ---- the basis engine ------------------------------------------------------------------------- */

typedef struct {
    int dim, n;
    pc_basis_fn g;
    void (*gfree)(void *);
    void *ud;
    double *ginv;     /* n x n */
    double *pts;      /* n rows of dim */
} basis;

static void basis_free(void *p) {
    basis *s = p;
    if (s->gfree) s->gfree(s->ud);
    free(s->ginv);
    free(s->pts);
    free(s);
}

/* phi_j(t) = sum_i g_i(t) ginv[i][j] */
static int basis_phi(pc_basis_fn g, void *ud, const double *ginv, int n, double t, double *phi) {
    double gv[MAXN];
    int st = g(ud, t, n, gv);
    if (st) return st;
    for (int j = 0; j < n; j++) {
        double s = 0;
        for (int i = 0; i < n; i++) s += gv[i] * ginv[i * n + j];
        phi[j] = s;
        if (!isfinite(s)) return PC_ENONFINITE;
    }
    return PC_OK;
}

static int basis_eval(void *ud, double t, int order, double *out) {
    const basis *s = ud;
    if (order > 0) return PC_EDOMAIN;
    double phi[MAXN];
    int st = basis_phi(s->g, s->ud, s->ginv, s->n, t, phi);
    if (st) return st;
    for (int k = 0; k < s->dim; k++) {
        double x = 0;
        for (int j = 0; j < s->n; j++) x += phi[j] * s->pts[(size_t)j * s->dim + k];
        out[k] = x;
    }
    out[s->dim] = 1;    /* coordinatewise, as the book computes (4.39) */
    return PC_OK;
}

/* ginv = inverse of G_ji = g_i(t_j), column by column */
static int collocation_inverse(pc_basis_fn g, void *ud, int n, const double *params,
                               double *ginv) {
    double G[MAXN * MAXN], a[MAXN * MAXN], e[MAXN];
    for (int j = 0; j < n; j++) {
        int st = g(ud, params[j], n, G + j * n);
        if (st) return st;
        for (int i = 0; i < n; i++)
            if (!isfinite(G[j * n + i])) return PC_ENONFINITE;
    }
    /* phi = g G^-1: with G x = e_c, column c of G^-1 */
    for (int c = 0; c < n; c++) {
        memcpy(a, G, sizeof(double) * (size_t)(n * n));
        for (int i = 0; i < n; i++) e[i] = i == c;
        int st = pc_lu_solve(n, a, e);
        if (st) return st;
        for (int i = 0; i < n; i++) ginv[i * n + c] = e[i];
    }
    return PC_OK;
}

pc_curve *pc_interp_basis(int dim, int n, const double *pts, const double *params,
                          pc_basis_fn g, void (*fn_free)(void *ud), void *ud, double t0,
                          double t1, int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    if (n < 1 || n > 16) return fail(status, PC_EDOMAIN);
    if (isnan(t0) && isnan(t1)) {                     /* the nodes' range */
        t0 = t1 = params[0];
        for (int i = 1; i < n; i++) t0 = fmin(t0, params[i]), t1 = fmax(t1, params[i]);
    }
    if (!(t1 > t0)) return fail(status, PC_EDOMAIN2);
    basis *s = calloc(1, sizeof *s);
    if (!s) return fail(status, PC_ENOMEM);
    s->dim = dim, s->n = n, s->g = g, s->ud = ud;
    s->ginv = malloc(sizeof(double) * (size_t)(n * n));
    s->pts = malloc(sizeof(double) * (size_t)(n * dim));
    int st = (!s->ginv || !s->pts) ? PC_ENOMEM : collocation_inverse(g, ud, n, params, s->ginv);
    if (st) {
        basis_free(s);    /* gfree is not set yet: the caller keeps ud */
        return fail(status, st);
    }
    memcpy(s->pts, pts, sizeof(double) * (size_t)(n * dim));
    pc_curve *cv = pc_curve_func(dim, t0, t1, 0, basis_eval, basis_free, s, status);
    if (!cv) {
        basis_free(s);
        return NULL;
    }
    s->gfree = fn_free;
    return cv;
}

int pc_interp_basis_membership(int n, const double *params, pc_basis_fn g, void *ud, double t0,
                               double t1, int samples, double *dev) {
    if (n < 1 || n > 16 || samples < 2 || !(t1 > t0)) return PC_EDOMAIN;
    double ginv[MAXN * MAXN], phi[MAXN], worst = 0;
    int st = collocation_inverse(g, ud, n, params, ginv);
    for (int i = 0; !st && i < samples + n; i++) {
        double t = i < samples ? t0 + (t1 - t0) * i / (samples - 1) : params[i - samples];
        st = basis_phi(g, ud, ginv, n, t, phi);
        double sum = 0;
        for (int j = 0; !st && j < n; j++) sum += phi[j];
        if (!st) worst = fmax(worst, fabs(sum - 1));
    }
    if (st) return st;
    *dev = worst;
    return PC_OK;
}

/* ---- the book's prototypes ---------------------------------------------------------------------- */

typedef struct { pc_proto_kind kind; double k[3]; } proto;

static int proto_g(void *ud, double t, int n, double *g) {
    const proto *p = ud;
    double tb = 1 - t;
    switch (p->kind) {
    case PC_PROTO_DESARGUES: {        /* (3.6): A t'^3 + B t^2 t' + C t'^2 t + D t^3 */
        double d = 2 * t * t - 2 * t + 1;
        g[0] = tb * tb * tb / d, g[1] = t * t * tb / d, g[2] = tb * tb * t / d, g[3] = t * t * t / d;
        break;
    }
    case PC_PROTO_RATIONAL: {         /* (4.36) */
        double d = t * t * t + t * t + t + 1;
        g[0] = t * t * t / d, g[1] = t * t / d, g[2] = t / d, g[3] = 1 / d;
        break;
    }
    case PC_PROTO_EXP:                /* (4.39) */
        for (int i = 0; i < 3; i++) g[i] = exp(p->k[i] * t);
        break;
    case PC_PROTO_EXP_AFFINE:         /* e^(k3 t) replaced so that the weights sum to 1 */
        g[0] = exp(p->k[0] * t), g[1] = exp(p->k[1] * t), g[2] = 1 - g[0] - g[1];
        break;
    case PC_PROTO_TRIG:               /* (4.40): A1 cos t + A3 sin t + A2 (1 - cos t - sin t) */
        g[0] = cos(t), g[1] = 1 - cos(t) - sin(t), g[2] = sin(t);
        break;
    }
    (void)n;
    return PC_OK;
}

static int proto_setup(pc_proto_kind kind, int n, const double *k, proto *p, double *params) {
    int want = (kind == PC_PROTO_DESARGUES || kind == PC_PROTO_RATIONAL) ? 4 : 3;
    if (n != want) return PC_EDOMAIN;
    p->kind = kind;
    p->k[0] = p->k[1] = p->k[2] = 0;
    if (kind == PC_PROTO_EXP || kind == PC_PROTO_EXP_AFFINE) {
        int nk = kind == PC_PROTO_EXP ? 3 : 2;
        if (!k) return PC_EDOMAIN;
        for (int i = 0; i < nk; i++) {
            if (!isfinite(k[i])) return PC_ENONFINITE;
            p->k[i] = k[i];
        }
    }
    for (int j = 0; j < n; j++)
        params[j] = kind == PC_PROTO_TRIG ? j * M_PI / 2 : (double)j / (n - 1);
    return PC_OK;
}

int pc_interp_prototype_weights(pc_proto_kind kind, int n, const double *k, double t, double *w) {
    proto p;
    double params[4], ginv[16];
    int st = proto_setup(kind, n, k, &p, params);
    if (!st) st = collocation_inverse(proto_g, &p, n, params, ginv);
    if (!st) st = basis_phi(proto_g, &p, ginv, n, t, w);
    return st;
}

void pc_interp_prototype_shape(pc_proto_kind kind, int *n, int *nk) {
    *n = kind == PC_PROTO_DESARGUES || kind == PC_PROTO_RATIONAL ? 4 : 3;
    *nk = kind == PC_PROTO_EXP ? 3 : kind == PC_PROTO_EXP_AFFINE ? 2 : 0;
}

pc_curve *pc_interp_prototype(pc_proto_kind kind, int dim, int n, const double *pts,
                              const double *k, double t0, double t1, int *status) {
    proto *p = malloc(sizeof *p);
    double params[4];
    if (!p) return fail(status, PC_ENOMEM);
    int st = proto_setup(kind, n, k, p, params);
    if (st) {
        free(p);
        return fail(status, st);
    }
    if (isnan(t0)) t0 = params[0];
    if (isnan(t1)) t1 = params[n - 1];
    pc_curve *cv = pc_interp_basis(dim, n, pts, params, proto_g, free, p, t0, t1, status);
    if (!cv) free(p);
    return cv;
}

/* ---- (4.38) ----------------------------------------------------------------------------------- */

typedef struct { int dim; double c[PC_MAXDIM * 5]; } r22;

static int r22_eval(void *ud, double t, int order, double *out) {
    const r22 *s = ud;
    if (order > 0) return PC_EDOMAIN;
    for (int k = 0; k < s->dim; k++) {
        const double *a = s->c + 5 * k;
        double den = a[3] * t * t + a[4] * t + 1;
        if (den == 0) return PC_EPOLE;
        out[k] = (a[0] * t * t + a[1] * t + a[2]) / den;
    }
    out[s->dim] = 1;
    return PC_OK;
}

pc_curve *pc_interp_rational22(int dim, const double *pts, double *coef, int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    r22 *s = malloc(sizeof *s);
    if (!s) return fail(status, PC_ENOMEM);
    s->dim = dim;
    for (int k = 0; k < dim; k++) {
        /* x_j (a4 t^2 + a5 t + 1) = a1 t^2 + a2 t + a3 at t = j/4: linear in a1..a5 */
        double a[25], r[5];
        for (int j = 0; j < 5; j++) {
            double t = j / 4.0, x = pts[j * dim + k];
            if (!isfinite(x)) {
                free(s);
                return fail(status, PC_ENONFINITE);
            }
            double row[5] = {t * t, t, 1, -x * t * t, -x * t};
            memcpy(a + 5 * j, row, sizeof row);
            r[j] = x;
        }
        int st = pc_lu_solve(5, a, r);
        if (st) {
            free(s);
            return fail(status, st);
        }
        memcpy(s->c + 5 * k, r, sizeof r);
    }
    if (coef) memcpy(coef, s->c, sizeof(double) * (size_t)(5 * dim));
    pc_curve *cv = pc_curve_func(dim, 0, 1, 0, r22_eval, free, s, status);
    if (!cv) free(s);
    return cv;
}
