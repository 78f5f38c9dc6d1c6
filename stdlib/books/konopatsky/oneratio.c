/* Curves of one ratio, Konopatsky's chapter 3 (oneratio.h; digest konopatsky_ch3_5.md §1). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "oneratio.h"

static pc_curve *fail(int *status, int st) {
    *status = st;
    return NULL;
}

static void hpoint(int dim, const double *p, double w, double *h) {
    for (int k = 0; k < dim; k++) h[k] = w * p[k];
    h[dim] = w;
}

static int finite_rows(int dim, int m, const double *const *p) {
    for (int i = 0; i < m; i++)
        for (int k = 0; k < dim; k++)
            if (!isfinite(p[i][k])) return 0;
    return 1;
}

/* the quadratic Bezier A, (X + Y)/2, B */
static pc_curve *quad_mid(int dim, const double *a, const double *x, const double *y,
                          const double *b, int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    double cp[3 * (PC_MAXDIM + 1)], mid[PC_MAXDIM];
    for (int k = 0; k < dim; k++) mid[k] = 0.5 * (x[k] + y[k]);
    hpoint(dim, a, 1, cp);
    hpoint(dim, mid, 1, cp + dim + 1);
    hpoint(dim, b, 1, cp + 2 * (dim + 1));
    return pc_curve_bezier(dim, 3, cp, status);
}

pc_curve *pc_oneratio_simplex(int dim, const double *a, const double *b, const double *c,
                              int *status) {
    /* A t'^2 + B t + C t t' = A t'^2 + 2 (B + C)/2 t t' + B t^2 (B t = B t (t + t')) */
    return quad_mid(dim, a, b, c, b, status);
}

pc_curve *pc_oneratio_tetra(int dim, const double *a, const double *b, const double *c,
                            const double *d, int *status) {
    return quad_mid(dim, a, c, d, b, status);   /* (3.3): S = (C + D)/2 */
}

pc_curve *pc_oneratio_smooth(int dim, const double *a, const double *b, const double *c, int n,
                             int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    if (n < 1 || n > 40) return fail(status, PC_EDOMAIN);
    int deg = n + 1;
    double *cp = malloc(sizeof(double) * (size_t)(deg + 1) * (size_t)(dim + 1));
    if (!cp) return fail(status, PC_ENOMEM);
    /* sum_{i=1..n} binom(n+1, i) (2/binom(n+1, i)) t'^(n+1-i) t^i = 2 t t' D_(n-1), and
     * t'^(n+1) + t^(n+1) + 2 t t' D_(n-1) = D_n: the weights reproduce M_n (ours, digest §1.6) */
    hpoint(dim, a, 1, cp);
    double binom = 1;
    for (int i = 1; i <= n; i++) {
        binom = binom * (deg - i + 1) / i;
        hpoint(dim, c, 2 / binom, cp + (size_t)i * (dim + 1));
    }
    hpoint(dim, b, 1, cp + (size_t)deg * (dim + 1));
    pc_curve *cv = pc_curve_bezier(dim, deg + 1, cp, status);
    free(cp);
    return cv;
}

pc_curve *pc_oneratio_desargues(int dim, const double *a, const double *b, const double *c,
                                const double *d, int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    /* A t'^3 + C t'^2 t + B t' t^2 + D t^3 = Bernstein weights 1, 1/3, 1/3, 1 on A, C, B, D;
     * the weights sum to t'^3 + t'^2 t + t' t^2 + t^3 = 2t^2 - 2t + 1 */
    double cp[4 * (PC_MAXDIM + 1)];
    hpoint(dim, a, 1, cp);
    hpoint(dim, c, 1.0 / 3, cp + dim + 1);
    hpoint(dim, b, 1.0 / 3, cp + 2 * (dim + 1));
    hpoint(dim, d, 1, cp + 3 * (dim + 1));
    return pc_curve_bezier(dim, 4, cp, status);
}

/* ---- blends of two engineering-discriminant arcs ------------------------------------------ */

typedef struct {
    int dim, mode;            /* 0 double contact, 1 closed scheme 1, 2 closed scheme 2 */
    double a[PC_MAXDIM], b[PC_MAXDIM], c[PC_MAXDIM];
    double kp, kq;
    pc_blend_fn f;
    void (*ffree)(void *);
    void *ud;
} blend;

static void blend_free(void *p) {
    blend *s = p;
    if (s->ffree) s->ffree(s->ud);
    free(s);
}

/* The arc (2.97) of k in the simplex with initial point o and vertices x (at u = 0) and y
 * (u = 1), over its denominator: numerator row num (dim) and the denominator. */
static double ed_h(int dim, const double *x, const double *y, const double *o, double k,
                   double u, double *num) {
    double ub = 1 - u, den = k * (1 - 2 * u) * (1 - 2 * u) + 2 * u * ub;
    for (int i = 0; i < dim; i++)
        num[i] = (x[i] - o[i]) * k * ub * ub + (y[i] - o[i]) * k * u * u + o[i] * den;
    return den;
}

static int blend_eval(void *ud, double v, int order, double *out) {
    const blend *s = ud;
    int n = s->dim;
    if (order > 0) return PC_EDOMAIN;
    double np[PC_MAXDIM], nq[PC_MAXDIM], dp, dq, f;
    if (s->mode == 0) {
        dp = ed_h(n, s->a, s->b, s->c, s->kp, v, np);
        dq = ed_h(n, s->a, s->b, s->c, s->kq, v, nq);
        f = s->f ? s->f(s->ud, v) : v;
        if (!isfinite(f)) return PC_ENONFINITE;
    } else {
        dp = ed_h(n, s->b, s->a, s->c, s->kp, v, np);          /* P runs B -> A */
        if (s->mode == 1) dq = ed_h(n, s->a, s->b, s->c, s->kq, v, nq);   /* Q: A -> B */
        else dq = ed_h(n, s->c, s->b, s->a, s->kq, v, nq);      /* Q: C -> B, tangents CA, BA */
        f = v;                                                  /* M = P u' + Q u */
    }
    /* M = (1 - f) P + f Q over the product of the denominators */
    for (int i = 0; i < n; i++) out[i] = (1 - f) * np[i] * dq + f * nq[i] * dp;
    out[n] = dp * dq;
    return PC_OK;
}

static pc_curve *new_blend(int mode, int dim, const double *a, const double *b, const double *c,
                           double kp, double kq, pc_blend_fn f, void (*fn_free)(void *),
                           void *ud, int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    const double *pts[3] = {a, b, c};
    if (!finite_rows(dim, 3, pts) || !isfinite(kp) || !isfinite(kq)) return fail(status, PC_ENONFINITE);
    if (kp == 0) return fail(status, PC_EDOMAIN);
    if (kq == 0) return fail(status, PC_EDOMAIN2);
    if (mode == 0 && kp == kq) return fail(status, PC_EDOMAIN3);
    blend *s = malloc(sizeof *s);
    if (!s) return fail(status, PC_ENOMEM);
    s->dim = dim, s->mode = mode, s->kp = kp, s->kq = kq, s->f = f, s->ud = ud, s->ffree = NULL;
    memcpy(s->a, a, sizeof(double) * (size_t)dim);
    memcpy(s->b, b, sizeof(double) * (size_t)dim);
    memcpy(s->c, c, sizeof(double) * (size_t)dim);
    pc_curve *cv = pc_curve_func(dim, 0, 1, mode != 0, blend_eval, blend_free, s, status);
    if (!cv) {
        free(s);
        return NULL;
    }
    s->ffree = fn_free;
    return cv;
}

pc_curve *pc_oneratio_double_contact(int dim, const double *a, const double *b,
                                     const double *c, double kp, double kq, pc_blend_fn f,
                                     void (*fn_free)(void *ud), void *ud, int *status) {
    return new_blend(0, dim, a, b, c, kp, kq, f, fn_free, ud, status);
}

static double const_blend(void *ud, double v) {
    (void)v;
    return *(double *)ud;
}

pc_curve *pc_oneratio_double_contact_const(int dim, const double *a, const double *b,
                                           const double *c, double kp, double kq, double f,
                                           int *status) {
    double *ud = malloc(sizeof *ud);
    if (!ud) return fail(status, PC_ENOMEM);
    *ud = f;
    pc_curve *cv = pc_oneratio_double_contact(dim, a, b, c, kp, kq, const_blend, free, ud, status);
    if (!cv) free(ud);
    return cv;
}

pc_curve *pc_oneratio_bezier3(int dim, const double *a, const double *c1, const double *c2,
                              const double *b, int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    double cp[4 * (PC_MAXDIM + 1)];
    hpoint(dim, a, 1, cp);
    hpoint(dim, c1, 1, cp + dim + 1);
    hpoint(dim, c2, 1, cp + 2 * (dim + 1));
    hpoint(dim, b, 1, cp + 3 * (dim + 1));
    return pc_curve_bezier(dim, 4, cp, status);
}

pc_curve *pc_oneratio_closed(int dim, const double *a, const double *b, const double *c,
                             double kp, double kq, int scheme, int *status) {
    if (scheme != 1 && scheme != 2) return fail(status, PC_EARG);
    return new_blend(scheme, dim, a, b, c, kp, kq, NULL, NULL, NULL, status);
}

/* ---- the schemes' intermediate points ------------------------------------------------------ */

static int finite_arg(int dim, const double *p) {
    for (int k = 0; k < dim; k++)
        if (!isfinite(p[k])) return 0;
    return 1;
}

int pc_oneratio_simplex_scheme(int dim, const double *a, const double *b, const double *c,
                               double t, double *n, double *m) {
    if (dim < 1 || dim > PC_MAXDIM) return PC_EDIM;
    if (!isfinite(t) || !finite_arg(dim, a) || !finite_arg(dim, b) || !finite_arg(dim, c))
        return PC_ENONFINITE;
    for (int k = 0; k < dim; k++) {
        n[k] = a[k] * (1 - t) + c[k] * t;          /* AN/AC = t */
        m[k] = n[k] * (1 - t) + b[k] * t;          /* NM/NB = t */
    }
    return PC_OK;
}

int pc_decasteljau_levels(int dim, int n, const double *pts, double t, double *out) {
    if (dim < 1 || dim > PC_MAXDIM) return PC_EDIM;
    if (n < 2 || n > 16) return PC_EDOMAIN;
    if (!isfinite(t) || !finite_arg(dim * n, pts)) return PC_ENONFINITE;
    const double *prev = pts;
    double *row = out;
    for (int level = 1; level < n; level++) {     /* each link divided in the one ratio t */
        int m = n - level;
        for (int i = 0; i < m; i++)
            for (int k = 0; k < dim; k++)
                row[i * dim + k] = prev[i * dim + k] + t * (prev[(i + 1) * dim + k] - prev[i * dim + k]);
        prev = row;
        row += m * dim;
    }
    return PC_OK;
}

/* h = x X + y Y + z Z + w W (homogeneous: weight x + y + z + w) */
static void hcomb(int dim, double *h, double x, const double *X, double y, const double *Y,
                  double z, const double *Z, double w, const double *W) {
    for (int k = 0; k < dim; k++)
        h[k] = x * X[k] + y * Y[k] + (Z ? z * Z[k] : 0) + (W ? w * W[k] : 0);
    h[dim] = x + y + (Z ? z : 0) + (W ? w : 0);
}

int pc_desargues_scheme(int dim, const double *a, const double *b, const double *c,
                        const double *d, double t, double *h, double pq[2]) {
    if (dim < 1 || dim > PC_MAXDIM) return PC_EDIM;
    if (!isfinite(t) || !finite_arg(dim, a) || !finite_arg(dim, b) || !finite_arg(dim, c) ||
        !finite_arg(dim, d))
        return PC_ENONFINITE;
    double tb = 1 - t;
    int s = dim + 1;
    /* ABT = -t^2/t'^2 (O-theorem on ACB cut by PQT): T = (A t'^2 - B t^2)/(1 - 2t), the weight
     * t'^2 - t^2 = 1 - 2t kept homogeneous so that t = 1/2 gives the point at infinity */
    hcomb(dim, h, tb * tb, a, -t * t, b, 0, NULL, 0, NULL);
    hcomb(dim, h + s, tb * tb, c, -t * t, d, 0, NULL, 0, NULL);                  /* S */
    hcomb(dim, h + 2 * s, tb * tb * tb, a, -t * t * tb, b, tb * tb * t, c, -t * t * t, d); /* R */
    hcomb(dim, h + 3 * s, tb * tb, a, 2 * tb * t, c, t * t, b, 0, NULL);         /* N */
    hcomb(dim, h + 4 * s, tb * tb, c, 2 * tb * t, b, t * t, d, 0, NULL);         /* J */
    hcomb(dim, h + 5 * s, tb, c, t, b, 0, NULL, 0, NULL);                        /* Q */
    /* M = SN x TJ, which is (3.6): weights t'^3, t^2 t', t'^2 t, t^3 summing to 2t^2 - 2t + 1 */
    hcomb(dim, h + 6 * s, tb * tb * tb, a, t * t * tb, b, tb * tb * t, c, t * t * t, d);
    if (pq) pq[0] = 2 * t - 1, pq[1] = t != 0 ? tb / t : INFINITY;
    return PC_OK;
}
