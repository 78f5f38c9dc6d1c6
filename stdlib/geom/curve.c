/* The one curve type: life, validation and the direct constructors (Bezier, piecewise Bezier,
 * B-spline/NURBS, Hermite, callback).  Evaluation is in curve_eval.c, split/map/length/bbox in
 * curve_ops.c, the spline and interpolation builders in curve_build.c, flattening in
 * curve_flatten.c. */
#include "curve_impl.h"
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* --- life ---------------------------------------------------------------------------------- */
pc_curve *pc_curve_retain(pc_curve *c) {
    if (c) c->refs++;
    return c;
}

void pcc_func_release(pc_curve_callback *f) {
    if (!f || --f->refs > 0) return;
    if (f->free) f->free(f->ud);
    free(f);
}

void pc_curve_release(pc_curve *c) {
    if (!c || --c->refs > 0) return;
    free(c->cp);
    free(c->knots);
    pcc_func_release(c->func);
    free(c);
}

int pcc_finite(size_t n, const double *v) {
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i])) return 0;
    return 1;
}

static int fail(int *status, int st) {
    if (status) *status = st;
    return st;
}

pc_curve *pcc_new(pc_curve_kind kind, int dim, int ncp, int nknots, int *status) {
    pc_curve *c = calloc(1, sizeof *c);
    if (!c) goto nomem;
    c->refs = 1;
    c->kind = kind;
    c->dim = dim;
    c->ncp = ncp;
    c->nknots = nknots;
    if (ncp > 0 && !(c->cp = malloc(sizeof(double) * (size_t)ncp * (size_t)(dim + 1)))) goto nomem;
    if (nknots > 0 && !(c->knots = malloc(sizeof(double) * (size_t)nknots))) goto nomem;
    if (status) *status = PC_OK;
    return c;
nomem:
    pc_curve_release(c);
    fail(status, PC_ENOMEM);
    return NULL;
}

pc_curve_callback *pcc_func_new(pc_curve_fn eval, void (*fn_free)(void *), void *ud) {
    pc_curve_callback *f = malloc(sizeof *f);
    if (!f) return NULL;
    f->refs = 1;
    f->eval = eval;
    f->free = fn_free;
    f->ud = ud;
    return f;
}

/* --- where the pieces are ---------------------------------------------------------------- */
/* the last index i in [lo, hi] with v[i] <= x, or lo - 1 */
static int last_le(const double *v, int lo, int hi, double x) {
    int a = lo - 1, b = hi + 1;     /* v[a] <= x < v[b] (sentinels) */
    while (b - a > 1) {
        int m = a + (b - a) / 2;
        if (v[m] <= x) a = m; else b = m;
    }
    return a;
}

int pcc_piece(const pc_curve *c, double t) {
    if (c->kind == PC_CURVE_BEZIER) {
        int nseg = c->nknots - 1, i = last_le(c->knots, 0, nseg, t);
        return i < 0 ? 0 : (i > nseg - 1 ? nseg - 1 : i);
    }
    int p = c->degree, n = c->ncp;
    const double *U = c->knots;
    int k = last_le(U, p, n, t);
    if (k < p) k = p;
    if (k > n - 1) k = n - 1;
    if (U[k] == U[k + 1]) {       /* an empty span: before the domain or at its end */
        if (t >= c->t1) {
            while (k > p && U[k] == U[k + 1]) k--;
        } else {
            while (k < n - 1 && U[k] == U[k + 1]) k++;
        }
    }
    return k;
}

/* The blossom of the span k of a B-spline (q + 1 rows of w in d, destroyed) at nlow copies of
 * U[k] and q - nlow of U[k+1]: a Bezier control point of the span (Ramshaw). */
static void blossom(int q, int w, double *d, const double *U, int k, int nlow, double *out) {
    for (int r = 1; r <= q; r++) {
        double x = r <= nlow ? U[k] : U[k + 1];
        for (int j = q; j >= r; j--) {
            int i = j + k - q;
            double a = (x - U[i]) / (U[j + 1 + k - r] - U[i]);
            for (int c = 0; c < w; c++)
                d[j * w + c] = d[(j - 1) * w + c] + a * (d[j * w + c] - d[(j - 1) * w + c]);
        }
    }
    memcpy(out, d + (size_t)q * w, sizeof(double) * w);
}

void pcc_bezier_piece(const pc_curve *c, int k, double *out) {
    int q = c->degree, w = c->dim + 1;
    size_t sz = (size_t)(q + 1) * w;
    if (c->kind == PC_CURVE_BEZIER) {
        memcpy(out, c->cp + (size_t)k * q * w, sizeof(double) * sz);
        return;
    }
    double d[PCC_ROWS * PCC_W];
    for (int j = 0; j <= q; j++) {
        memcpy(d, c->cp + (size_t)(k - q) * w, sizeof(double) * sz);
        blossom(q, w, d, c->knots, k, q - j, out + (size_t)j * w);
    }
}

double pcc_next_break(const pc_curve *c, double x, double b) {
    const double *v = c->knots;
    int lo = 0, hi = c->nknots - 1;
    if (c->kind == PC_CURVE_BSPLINE) {
        lo = c->degree;
        hi = c->ncp;
    }
    double r;
    if (hi < lo || !v) {            /* a FUNC curve without breaks: the domain ends */
        r = x < c->t0 ? c->t0 : (x < c->t1 ? c->t1 : b);
    } else {
        int i = last_le(v, lo, hi, x) + 1;
        r = i <= hi ? v[i] : b;
    }
    return r < b ? r : b;
}

int pcc_bezier_knots(const pc_curve *c, int i, double *U) {
    int p = c->degree;
    for (int j = 0; j <= p; j++) {
        U[j] = c->knots[i];
        U[p + 1 + j] = c->knots[i + 1];
    }
    return p;
}

/* --- constructors ---------------------------------------------------------------------- */
static int check_rows(int dim, int n, const double *cp) {
    if (dim < 1 || dim > PC_MAXDIM) return PC_EDIM;
    if (!cp) return PC_EARG;
    if (!pcc_finite((size_t)n * (size_t)(dim + 1), cp)) return PC_ENONFINITE;
    return PC_OK;
}

pc_curve *pc_curve_bezier(int dim, int ncp, const double *cp, int *status) {
    double brk[2] = {0, 1};
    return pc_curve_bezier_pieces(dim, ncp - 1, 1, cp, brk, status);
}

pc_curve *pc_curve_bezier_pieces(int dim, int degree, int nseg, const double *cp,
                                 const double *brk, int *status) {
    if (degree < 1 || degree > PC_CURVE_MAXDEG || nseg < 1 || nseg > (INT_MAX - 1) / degree - 1) {
        fail(status, PC_EDIM);
        return NULL;
    }
    int ncp = nseg * degree + 1, st = check_rows(dim, ncp, cp);
    if (!st && brk) {
        if (!pcc_finite((size_t)nseg + 1, brk)) st = PC_ENONFINITE;
        for (int i = 0; !st && i < nseg; i++)
            if (!(brk[i] < brk[i + 1])) st = PC_EDOMAIN;
    }
    if (st) {
        fail(status, st);
        return NULL;
    }
    pc_curve *c = pcc_new(PC_CURVE_BEZIER, dim, ncp, nseg + 1, status);
    if (!c) return NULL;
    c->degree = degree;
    memcpy(c->cp, cp, sizeof(double) * (size_t)ncp * (size_t)(dim + 1));
    for (int i = 0; i <= nseg; i++) c->knots[i] = brk ? brk[i] : i;
    c->t0 = c->knots[0];
    c->t1 = c->knots[nseg];
    return c;
}

pc_curve *pc_curve_bspline(int dim, int degree, int ncp, const double *cp, pc_knot_kind kk,
                           const double *knots, int *status) {
    int st = PC_OK;
    if (degree < 1 || degree > PC_CURVE_MAXDEG || ncp < 1 || ncp > INT_MAX / 2 - 2 * degree - 2)
        st = PC_EDIM;
    else if (kk == PC_KNOTS_PERIODIC ? degree > ncp : degree >= ncp) st = PC_EDIM;
    else if (kk < PC_KNOTS_GIVEN || kk > PC_KNOTS_PERIODIC) st = PC_EARG;
    else st = check_rows(dim, ncp, cp);
    int n = kk == PC_KNOTS_PERIODIC ? ncp + degree : ncp, nk = n + degree + 1;
    if (!st && kk == PC_KNOTS_GIVEN) {
        if (!knots) st = PC_EARG;
        else if (!pcc_finite((size_t)nk, knots)) st = PC_ENONFINITE;
        for (int i = 0; !st && i + 1 < nk; i++)
            if (!(knots[i] <= knots[i + 1])) st = PC_EDOMAIN;
        if (!st && !(knots[degree] < knots[n])) st = PC_EDOMAIN;
    }
    if (st) {
        fail(status, st);
        return NULL;
    }
    pc_curve *c = pcc_new(PC_CURVE_BSPLINE, dim, n, nk, status);
    if (!c) return NULL;
    size_t w = (size_t)dim + 1;
    c->degree = degree;
    memcpy(c->cp, cp, sizeof(double) * (size_t)ncp * w);
    for (int i = ncp; i < n; i++) memcpy(c->cp + i * w, cp + (i - ncp) * w, sizeof(double) * w);
    for (int i = 0; i < nk; i++) {
        switch (kk) {
        case PC_KNOTS_GIVEN: c->knots[i] = knots[i]; break;
        case PC_KNOTS_OPEN:
            c->knots[i] = i <= degree ? 0 : (i >= n ? n - degree : i - degree);
            break;
        case PC_KNOTS_UNIFORM: c->knots[i] = i; break;
        case PC_KNOTS_PERIODIC: c->knots[i] = i - degree; break;
        }
    }
    c->t0 = c->knots[degree];
    c->t1 = c->knots[n];
    c->closed = kk == PC_KNOTS_PERIODIC;
    return c;
}

pc_curve *pc_curve_hermite(int dim, int n, const double *p, const double *dout,
                           const double *din, const double *u, int closed, int *status) {
    int st = PC_OK;
    if (dim < 1 || dim > PC_MAXDIM || n < 2 || n > INT_MAX / 4) st = PC_EDIM;
    else if (!p || !dout) st = PC_EARG;
    else if (!pcc_finite((size_t)n * dim, p) || !pcc_finite((size_t)n * dim, dout) ||
             (din && !pcc_finite((size_t)n * dim, din)) || (u && !pcc_finite((size_t)n, u)))
        st = PC_ENONFINITE;
    for (int i = 0; !st && u && i + 1 < n; i++)
        if (!(u[i] < u[i + 1])) st = PC_EDOMAIN;
    if (st) {
        fail(status, st);
        return NULL;
    }
    if (!din) din = dout;
    int nseg = closed ? n : n - 1;
    double *brk = malloc(sizeof(double) * (size_t)(nseg + 1));
    double *cp = malloc(sizeof(double) * (size_t)(3 * nseg + 1) * (size_t)(dim + 1));
    pc_curve *c = NULL;
    if (!brk || !cp) {
        fail(status, PC_ENOMEM);
        goto done;
    }
    for (int i = 0; i < n; i++) brk[i] = u ? u[i] : i;
    if (closed) brk[n] = brk[n - 1] + (u ? u[1] - u[0] : 1);
    if (!isfinite(brk[nseg]) || !(brk[nseg] > brk[nseg - 1])) {
        fail(status, isfinite(brk[nseg]) ? PC_EDOMAIN : PC_ENONFINITE);
        goto done;
    }
    int w = dim + 1;
    for (int s = 0; s < nseg; s++) {
        int i = s, j = (s + 1) % n;
        double h = brk[s + 1] - brk[s];
        double *b = cp + (size_t)3 * s * w;
        for (int x = 0; x < dim; x++) {
            b[x] = p[i * dim + x];
            b[w + x] = p[i * dim + x] + h / 3 * dout[i * dim + x];
            b[2 * w + x] = p[j * dim + x] - h / 3 * din[j * dim + x];
            b[3 * w + x] = p[j * dim + x];
        }
        b[dim] = b[w + dim] = b[2 * w + dim] = b[3 * w + dim] = 1;
    }
    if (!pcc_finite((size_t)(3 * nseg + 1) * w, cp)) {
        fail(status, PC_ENONFINITE);
        goto done;
    }
    c = pc_curve_bezier_pieces(dim, 3, nseg, cp, brk, status);
    if (c) c->closed = closed != 0;
done:
    free(brk);
    free(cp);
    return c;
}

pc_curve *pcc_func_curve(int dim, double t0, double t1, int closed, pc_curve_callback *f,
                         int nbrk, const double *brk, int *status) {
    pc_curve *c = pcc_new(PC_CURVE_FUNC, dim, 0, nbrk > 0 ? nbrk + 2 : 0, status);
    if (!c) return NULL;
    c->t0 = t0;
    c->t1 = t1;
    c->closed = closed != 0;
    if (nbrk > 0) {
        c->knots[0] = t0;
        memcpy(c->knots + 1, brk, sizeof(double) * (size_t)nbrk);
        c->knots[nbrk + 1] = t1;
    }
    f->refs++;
    c->func = f;
    return c;
}

pc_curve *pc_curve_func_breaks(int dim, double t0, double t1, int closed, int nbrk,
                               const double *brk, pc_curve_fn eval, void (*fn_free)(void *ud),
                               void *ud, int *status) {
    int st = PC_OK;
    if (dim < 1 || dim > PC_MAXDIM || nbrk < 0 || nbrk > INT_MAX - 2) st = PC_EDIM;
    else if (!eval || (nbrk > 0 && !brk)) st = PC_EARG;
    else if (!isfinite(t0) || !isfinite(t1) || (nbrk > 0 && !pcc_finite((size_t)nbrk, brk)))
        st = PC_ENONFINITE;
    else if (!(t0 < t1)) st = PC_EDOMAIN;
    for (int i = 0; !st && i < nbrk; i++)
        if (!((i == 0 ? t0 : brk[i - 1]) < brk[i]) || !(brk[i] < t1)) st = PC_EDOMAIN;
    if (st) {
        fail(status, st);
        return NULL;
    }
    pc_curve_callback *f = pcc_func_new(eval, fn_free, ud);
    if (!f) {
        fail(status, PC_ENOMEM);
        return NULL;
    }
    pc_curve *c = pcc_func_curve(dim, t0, t1, closed, f, nbrk, brk, status);
    if (!c) f->free = NULL;     /* on failure the caller keeps ud */
    pcc_func_release(f);        /* the curve holds the only reference */
    return c;
}

pc_curve *pc_curve_func(int dim, double t0, double t1, int closed, pc_curve_fn eval,
                        void (*fn_free)(void *ud), void *ud, int *status) {
    return pc_curve_func_breaks(dim, t0, t1, closed, 0, NULL, eval, fn_free, ud, status);
}
