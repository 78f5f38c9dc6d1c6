/* Operations on curves of every kind: split, sub-curve, knot insertion (Boehm), projective
 * images, arc length (adaptive Gauss-Legendre) and the bounding box (convex hulls of Bezier
 * pieces refined by subdivision). */
#include "curve_impl.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static pc_curve *fail_null(int *status, int st) {
    if (status) *status = st;
    return NULL;
}

/* --- knot insertion ---------------------------------------------------------------------- */
static int multiplicity(const pc_curve *c, double u) {
    int s = 0;
    for (int i = 0; i < c->nknots; i++) s += c->knots[i] == u;
    return s;
}

/* Boehm's algorithm, u in [t0, t1], no multiplicity check */
static pc_curve *insert(const pc_curve *c, double u, int *status) {
    int p = c->degree, n = c->ncp, w = c->dim + 1, nk = c->nknots;
    const double *U = c->knots;
    int k = 0;
    for (int i = 0; i < nk; i++)
        if (U[i] <= u) k = i;
    if (k > n - 1) k = n - 1;
    pc_curve *r = pcc_new(PC_CURVE_BSPLINE, c->dim, n + 1, nk + 1, status);
    if (!r) return NULL;
    r->degree = p;
    for (int i = 0; i <= n; i++) {
        double *q = r->cp + (size_t)i * w;
        if (i <= k - p) {
            memcpy(q, c->cp + (size_t)i * w, sizeof(double) * w);
        } else if (i > k) {
            memcpy(q, c->cp + (size_t)(i - 1) * w, sizeof(double) * w);
        } else {
            double den = U[i + p] - U[i], a = den > 0 ? (u - U[i]) / den : 0;
            const double *p0 = c->cp + (size_t)(i - 1) * w, *p1 = p0 + w;
            for (int x = 0; x < w; x++) q[x] = (1 - a) * p0[x] + a * p1[x];
        }
    }
    memcpy(r->knots, U, sizeof(double) * (size_t)(k + 1));
    r->knots[k + 1] = u;
    memcpy(r->knots + k + 2, U + k + 1, sizeof(double) * (size_t)(nk - k - 1));
    r->t0 = r->knots[p];
    r->t1 = r->knots[n + 1];
    return r;
}

pc_curve *pc_curve_insert_knot(const pc_curve *c, double u, int *status) {
    if (!c) return fail_null(status, PC_EARG);
    if (!isfinite(u)) return fail_null(status, PC_ENONFINITE);
    if (c->kind != PC_CURVE_BSPLINE || u < c->t0 || u > c->t1 || multiplicity(c, u) >= c->degree)
        return fail_null(status, PC_EDOMAIN);
    return insert(c, u, status);
}

/* --- split ----------------------------------------------------------------------------------- */
static int split_bezier(const pc_curve *c, double t, pc_curve **left, pc_curve **right) {
    int p = c->degree, w = c->dim + 1, nseg = c->nknots - 1, i = pcc_piece(c, t), st;
    int at_break = c->knots[i] == t;       /* then segments 0..i-1 | i..nseg-1 */
    int nl = at_break ? i : i + 1, nr = nseg - i;
    pc_curve *l = pcc_new(PC_CURVE_BEZIER, c->dim, nl * p + 1, nl + 1, &st);
    pc_curve *r = l ? pcc_new(PC_CURVE_BEZIER, c->dim, nr * p + 1, nr + 1, &st) : NULL;
    if (!r) {
        pc_curve_release(l);
        return st;
    }
    l->degree = r->degree = p;
    memcpy(l->knots, c->knots, sizeof(double) * (size_t)nl);
    l->knots[nl] = t;
    r->knots[0] = t;
    memcpy(r->knots + 1, c->knots + i + 1, sizeof(double) * (size_t)nr);
    size_t row = sizeof(double) * w;
    if (at_break) {
        memcpy(l->cp, c->cp, row * ((size_t)i * p + 1));
        memcpy(r->cp, c->cp + (size_t)i * p * w, row * ((size_t)nr * p + 1));
    } else {
        double d[PCC_ROWS * PCC_W];
        double u = (t - c->knots[i]) / (c->knots[i + 1] - c->knots[i]);
        memcpy(l->cp, c->cp, row * (size_t)i * p);
        memcpy(d, c->cp + (size_t)i * p * w, row * (p + 1));
        double *lp = l->cp + (size_t)i * p * w, *rp = r->cp;
        memcpy(lp, d, row);
        memcpy(rp + (size_t)p * w, d + (size_t)p * w, row);
        for (int lev = 1; lev <= p; lev++) {
            for (int j = 0; j + lev <= p; j++)
                for (int x = 0; x < w; x++) d[j * w + x] += u * (d[(j + 1) * w + x] - d[j * w + x]);
            memcpy(lp + (size_t)lev * w, d, row);
            memcpy(rp + (size_t)(p - lev) * w, d + (size_t)(p - lev) * w, row);
        }
        memcpy(r->cp + (size_t)p * w, c->cp + ((size_t)(i + 1) * p) * w, row * ((size_t)(nr - 1) * p + 1));
    }
    l->t0 = l->knots[0];
    l->t1 = t;
    r->t0 = t;
    r->t1 = r->knots[nr];
    *left = l;
    *right = r;
    return PC_OK;
}

static int split_bspline(const pc_curve *c, double t, pc_curve **left, pc_curve **right) {
    int st = PC_OK, p = c->degree;
    pc_curve *b = pc_curve_retain((pc_curve *)c);
    while (multiplicity(b, t) < p) {
        pc_curve *nb = insert(b, t, &st);
        pc_curve_release(b);
        if (!nb) return st;
        b = nb;
    }
    int n = b->ncp, nk = b->nknots, w = b->dim + 1, m = multiplicity(b, t), f = 0;
    while (b->knots[f] != t) f++;
    int nr = m == p ? n - f + 1 : n - f;
    pc_curve *l = pcc_new(PC_CURVE_BSPLINE, b->dim, f, f + p + 1, &st);
    pc_curve *r = l ? pcc_new(PC_CURVE_BSPLINE, b->dim, nr, nr + p + 1, &st) : NULL;
    if (!r) {
        pc_curve_release(l);
        pc_curve_release(b);
        return st;
    }
    l->degree = r->degree = p;
    memcpy(l->cp, b->cp, sizeof(double) * (size_t)f * w);
    memcpy(l->knots, b->knots, sizeof(double) * (size_t)(f + p));
    l->knots[f + p] = t;
    memcpy(r->cp, b->cp + (size_t)(n - nr) * w, sizeof(double) * (size_t)nr * w);
    memcpy(r->knots + (nr + p + 1) - (nk - f), b->knots + f, sizeof(double) * (size_t)(nk - f));
    r->knots[0] = t;
    l->t0 = l->knots[p];
    l->t1 = l->knots[f];
    r->t0 = r->knots[p];
    r->t1 = r->knots[nr];
    pc_curve_release(b);
    *left = l;
    *right = r;
    return PC_OK;
}

/* the FUNC curve over [a, b] sharing c's callback, with c's breaks inside */
static pc_curve *func_part(const pc_curve *c, double a, double b, int *status) {
    int nb = 0, first = -1;
    for (int i = 1; i + 1 < c->nknots; i++)
        if (c->knots[i] > a && c->knots[i] < b) {
            if (first < 0) first = i;
            nb++;
        }
    return pcc_func_curve(c->dim, a, b, 0, c->func, nb, nb ? c->knots + first : NULL, status);
}

int pc_curve_split(const pc_curve *c, double t, pc_curve **left, pc_curve **right) {
    if (!c || !left || !right) return PC_EARG;
    *left = *right = NULL;
    if (!isfinite(t)) return PC_ENONFINITE;
    if (!(t > c->t0 && t < c->t1)) return PC_EDOMAIN;
    if (c->kind == PC_CURVE_BEZIER) return split_bezier(c, t, left, right);
    if (c->kind == PC_CURVE_BSPLINE) return split_bspline(c, t, left, right);
    int st;
    pc_curve *l = func_part(c, c->t0, t, &st);
    pc_curve *r = l ? func_part(c, t, c->t1, &st) : NULL;
    if (!r) {
        pc_curve_release(l);
        return st;
    }
    *left = l;
    *right = r;
    return PC_OK;
}

pc_curve *pc_curve_sub(const pc_curve *c, double a, double b, int *status) {
    if (!c) return fail_null(status, PC_EARG);
    if (!isfinite(a) || !isfinite(b)) return fail_null(status, PC_ENONFINITE);
    if (!(a < b) || a < c->t0 || b > c->t1) return fail_null(status, PC_EDOMAIN);
    if (c->kind == PC_CURVE_FUNC) return func_part(c, a, b, status);
    pc_curve *cur = pc_curve_retain((pc_curve *)c), *l, *r;
    int st = PC_OK;
    if (a > c->t0) {
        if ((st = pc_curve_split(cur, a, &l, &r))) goto bad;
        pc_curve_release(l);
        pc_curve_release(cur);
        cur = r;
    }
    if (b < cur->t1) {
        if ((st = pc_curve_split(cur, b, &l, &r))) goto bad;
        pc_curve_release(r);
        pc_curve_release(cur);
        cur = l;
    }
    if (cur == c) {      /* the whole curve: a copy, so that the caller owns a new one */
        int w = c->dim + 1;
        pc_curve *k = pcc_new(c->kind, c->dim, c->ncp, c->nknots, &st);
        if (!k) goto bad;
        k->degree = c->degree;
        k->closed = c->closed;
        k->t0 = c->t0;
        k->t1 = c->t1;
        memcpy(k->cp, c->cp, sizeof(double) * (size_t)c->ncp * w);
        memcpy(k->knots, c->knots, sizeof(double) * (size_t)c->nknots);
        pc_curve_release(cur);
        cur = k;
    }
    if (status) *status = PC_OK;
    return cur;
bad:
    pc_curve_release(cur);
    return fail_null(status, st);
}

/* --- images under maps ---------------------------------------------------------------------- */
typedef struct {
    pc_curve_callback *inner;
    int din;
    pc_map f;
} mapped;

static void map_row(const pc_map *f, const double *in, double *out) {
    for (int i = 0; i <= f->nout; i++) {
        double s = 0;
        for (int j = 0; j <= f->nin; j++) s += PC_MAP_AT(f, i, j) * in[j];
        out[i] = s;
    }
}

static int mapped_eval(void *ud, double t, int order, double *out) {
    mapped *m = ud;
    double h[3 * PCC_W];
    int st = m->inner->eval(m->inner->ud, t, order, h);
    if (st) return st;
    for (int r = 0; r <= order; r++) map_row(&m->f, h + r * (m->din + 1), out + r * (m->f.nout + 1));
    return PC_OK;
}

static void mapped_free(void *ud) {
    mapped *m = ud;
    pcc_func_release(m->inner);
    free(m);
}

pc_curve *pc_curve_map(const pc_curve *c, const pc_map *f, int *status) {
    if (!c || !f) return fail_null(status, PC_EARG);
    if (f->nin != c->dim || f->nout < 1 || f->nout > PC_MAXDIM) return fail_null(status, PC_EDIM);
    int nm = (f->nout + 1) * (f->nin + 1);
    if (!pcc_finite((size_t)nm, f->m)) return fail_null(status, PC_ENONFINITE);
    int st;
    if (c->kind == PC_CURVE_FUNC) {
        mapped *m = malloc(sizeof *m);
        pc_curve_callback *fn = m ? pcc_func_new(mapped_eval, mapped_free, m) : NULL;
        if (!fn) {
            free(m);
            return fail_null(status, PC_ENOMEM);
        }
        m->inner = c->func;
        c->func->refs++;
        m->din = c->dim;
        m->f = *f;
        int nb = c->nknots > 2 ? c->nknots - 2 : 0;
        pc_curve *r = pcc_func_curve(f->nout, c->t0, c->t1, c->closed, fn, nb,
                                     nb ? c->knots + 1 : NULL, status);
        pcc_func_release(fn);
        return r;
    }
    pc_curve *r = pcc_new(c->kind, f->nout, c->ncp, c->nknots, &st);
    if (!r) return fail_null(status, st);
    r->degree = c->degree;
    r->closed = c->closed;
    r->t0 = c->t0;
    r->t1 = c->t1;
    memcpy(r->knots, c->knots, sizeof(double) * (size_t)c->nknots);
    for (int i = 0; i < c->ncp; i++)
        map_row(f, c->cp + (size_t)i * (c->dim + 1), r->cp + (size_t)i * (f->nout + 1));
    if (!pcc_finite((size_t)c->ncp * (f->nout + 1), r->cp)) {
        pc_curve_release(r);
        return fail_null(status, PC_ENONFINITE);
    }
    if (status) *status = PC_OK;
    return r;
}

/* --- arc length ------------------------------------------------------------------------ */
static const double GX[3] = {0, 0.5384693101056830910, 0.9061798459386639928};
static const double GW[3] = {0.5688888888888888889, 0.4786286704993664680, 0.2369268850561890875};

/* |C'(t)|; PC_IMPROPER where the weight is 0 or its sign differs from *sg (the piece's) */
static int speed(const pc_curve *c, double t, double *v, int sg) {
    double h[2 * PCC_W], d[PC_MAXDIM];
    int st = pc_curve_eval_h(c, t, 1, h), n = c->dim;
    if (st) return st;
    double w = h[n], w1 = h[2 * n + 1];
    if (w == 0 || (w > 0 ? 1 : -1) != sg) return PC_IMPROPER;
    for (int i = 0; i < n; i++) d[i] = (h[n + 1 + i] - w1 * h[i] / w) / w;
    *v = pc_norm(n, d);
    return isfinite(*v) ? PC_OK : PC_ENONFINITE;
}

static int gauss5(const pc_curve *c, double a, double b, int sg, double *r) {
    double m = (a + b) / 2, h = (b - a) / 2, s = 0, v;
    int st;
    if ((st = speed(c, m, &v, sg))) return st;
    s = GW[0] * v;
    for (int i = 1; i < 3; i++) {
        double v2;
        if ((st = speed(c, m - h * GX[i], &v, sg)) || (st = speed(c, m + h * GX[i], &v2, sg)))
            return st;
        s += GW[i] * (v + v2);
    }
    *r = s * h;
    return PC_OK;
}

/* *budget: the subdivisions left.  A speed known only to its noise (a FUNC curve's derivative
 * by differences, far from its domain) never meets a relative tolerance of 1e-10, and depth 40
 * alone allows 2^40 evaluations: c:length(480, 65535) of such a curve ran for hours (found by
 * the API fuzzer, issue 15).  With the budget spent, the estimate at hand is taken. */
static int adapt(const pc_curve *c, double a, double b, int sg, double whole, double eps,
                 int depth, long *budget, double *r) {
    double m = (a + b) / 2, l, rr;
    int st;
    if ((st = gauss5(c, a, m, sg, &l)) || (st = gauss5(c, m, b, sg, &rr))) return st;
    if (fabs(l + rr - whole) <= eps || depth >= 40 || !(m > a && m < b) || --*budget <= 0) {
        *r = l + rr;
        return PC_OK;
    }
    double r1, r2;
    if ((st = adapt(c, a, m, sg, l, eps / 2, depth + 1, budget, &r1)) ||
        (st = adapt(c, m, b, sg, rr, eps / 2, depth + 1, budget, &r2)))
        return st;
    *r = r1 + r2;
    return PC_OK;
}

int pc_curve_length(const pc_curve *c, double a, double b, double tol, double *len) {
    if (!c || !len) return PC_EARG;
    if (!isfinite(a) || !isfinite(b) || isnan(tol)) return PC_ENONFINITE;
    if (!(a <= b) || tol < 0) return PC_EDOMAIN;
    if (tol < 1e-14) tol = 1e-14;
    double total = 0;
    for (double x = a; x < b;) {
        double y = pcc_next_break(c, x, b);
        for (int q = 0; q < 4; q++) {        /* each piece in 4 before adapting */
            double s = x + (y - x) * q / 4, e = q == 3 ? y : x + (y - x) * (q + 1) / 4, whole, r;
            if (!(e > s)) continue;
            double hs[PCC_W], he[PCC_W];
            int st = pc_curve_eval_h(c, s, 0, hs), n = c->dim;
            if (!st) st = pc_curve_eval_h(c, e, 0, he);
            if (st) return st;
            /* the weight must keep one sign over the piece (checked again at every node) */
            if (hs[n] == 0 || he[n] == 0 || (hs[n] > 0) != (he[n] > 0)) return PC_IMPROPER;
            int sg = hs[n] > 0 ? 1 : -1;
            st = gauss5(c, s, e, sg, &whole);
            long budget = 1L << 13;   /* subdivisions of this quarter piece */
            if (!st)
                st = adapt(c, s, e, sg, whole, tol * fmax(fabs(whole), 1e-300), 0, &budget, &r);
            if (st) return st;
            total += r;
        }
        x = y;
    }
    *len = total;
    return isfinite(total) ? PC_OK : PC_ENONFINITE;
}

/* --- bounding box ------------------------------------------------------------------------ */
#define BBOX_DEPTH 30

typedef struct {
    int n, p;
    double tol, *lo, *hi, *buf;
} bbox_ctx;

static int include_h(bbox_ctx *b, const double *h) {
    double w = h[b->n];
    if (w == 0) return PC_IMPROPER;
    for (int i = 0; i < b->n; i++) {
        double x = h[i] / w;
        if (!isfinite(x)) return PC_ENONFINITE;
        if (x < b->lo[i]) b->lo[i] = x;
        if (x > b->hi[i]) b->hi[i] = x;
    }
    return PC_OK;
}

/* the Bezier piece d (p+1 rows of n+1) at subdivision depth lev */
static int bez_bbox(bbox_ctx *b, const double *d, int lev) {
    int n = b->n, w = n + 1, p = b->p;
    double w0 = d[n], wp = d[p * w + n];
    if (w0 == 0 || wp == 0) return PC_IMPROPER;
    if ((w0 > 0) != (wp > 0)) return PC_IMPROPER;    /* the weight crosses 0 in between */
    int hull = 1;
    for (int j = 0; j <= p; j++)
        if (d[j * w + n] == 0 || (d[j * w + n] > 0) != (w0 > 0)) hull = 0;
    if (hull) {
        double clo[PC_MAXDIM], chi[PC_MAXDIM];
        int inside = 1;
        for (int i = 0; i < n; i++) {
            clo[i] = INFINITY;
            chi[i] = -INFINITY;
            for (int j = 0; j <= p; j++) {
                double x = d[j * w + i] / d[j * w + n];
                clo[i] = fmin(clo[i], x);
                chi[i] = fmax(chi[i], x);
            }
            if (clo[i] < b->lo[i] - b->tol || chi[i] > b->hi[i] + b->tol) inside = 0;
        }
        if (inside) return PC_OK;
        if (lev >= BBOX_DEPTH) {      /* give the hull: an outer bound */
            for (int i = 0; i < n; i++) {
                b->lo[i] = fmin(b->lo[i], clo[i]);
                b->hi[i] = fmax(b->hi[i], chi[i]);
            }
            return PC_OK;
        }
    } else if (lev >= BBOX_DEPTH) {
        return PC_OK;
    }
    size_t sz = (size_t)(p + 1) * w;
    double *L = b->buf + (size_t)lev * 2 * sz, *R = L + sz;
    memcpy(R, d, sizeof(double) * sz);
    memcpy(L, d, sizeof(double) * w);
    for (int lev2 = 1; lev2 <= p; lev2++) {
        for (int j = 0; j + lev2 <= p; j++)
            for (int x = 0; x < w; x++) R[j * w + x] = (R[j * w + x] + R[(j + 1) * w + x]) / 2;
        memcpy(L + (size_t)lev2 * w, R, sizeof(double) * w);
    }
    /* in place, R[j] ends as the last point of level p - j: the right half */
    int st = include_h(b, L + (size_t)p * w);
    if (st) return st;
    if ((st = bez_bbox(b, L, lev + 1))) return st;
    return bez_bbox(b, R, lev + 1);
}


/* FUNC curves: samples, then a golden-section search at each sampled extremum */
static int func_coord(const pc_curve *c, int i, double t, double *x) {
    double v[PC_MAXDIM];
    int st = pc_curve_eval(c, t, v);
    *x = v[i];
    return st;
}

static int func_bbox(const pc_curve *c, bbox_ctx *b) {
    enum { NS = 64 };
    double t[NS + 1], v[(NS + 1) * PC_MAXDIM];
    int n = c->dim, st;
    for (double x = c->t0; x < c->t1;) {
        double y = pcc_next_break(c, x, c->t1);
        for (int s = 0; s <= NS; s++) {
            t[s] = s == NS ? y : x + (y - x) * s / NS;
            if ((st = pc_curve_eval(c, t[s], v + s * n))) return st;
        }
        for (int i = 0; i < n; i++) {
            for (int s = 0; s <= NS; s++) {
                b->lo[i] = fmin(b->lo[i], v[s * n + i]);
                b->hi[i] = fmax(b->hi[i], v[s * n + i]);
            }
            for (int s = 1; s < NS; s++) {
                double a0 = v[(s - 1) * n + i], a1 = v[s * n + i], a2 = v[(s + 1) * n + i];
                for (int sgn = -1; sgn <= 1; sgn += 2) {
                    if (!(sgn * a1 >= sgn * a0 && sgn * a1 >= sgn * a2)) continue;
                    double lo = t[s - 1], hi = t[s + 1], g = (sqrt(5) - 1) / 2;
                    double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo), f1, f2;
                    if ((st = func_coord(c, i, m1, &f1)) || (st = func_coord(c, i, m2, &f2))) return st;
                    for (int it = 0; it < 60 && hi - lo > 1e-15 * fmax(1, fabs(lo)); it++) {
                        if (sgn * f1 > sgn * f2) {
                            hi = m2; m2 = m1; f2 = f1;
                            m1 = hi - g * (hi - lo);
                            if ((st = func_coord(c, i, m1, &f1))) return st;
                        } else {
                            lo = m1; m1 = m2; f1 = f2;
                            m2 = lo + g * (hi - lo);
                            if ((st = func_coord(c, i, m2, &f2))) return st;
                        }
                    }
                    b->lo[i] = fmin(b->lo[i], fmin(f1, f2));
                    b->hi[i] = fmax(b->hi[i], fmax(f1, f2));
                }
            }
        }
        x = y;
    }
    return PC_OK;
}

int pc_curve_bbox(const pc_curve *c, double tol, double *lo, double *hi) {
    if (!c || !lo || !hi) return PC_EARG;
    if (isnan(tol)) return PC_ENONFINITE;
    if (tol < 0) return PC_EDOMAIN;
    int n = c->dim, st;
    double e[PC_MAXDIM];
    if ((st = pc_curve_eval(c, c->t0, e))) return st;
    memcpy(lo, e, sizeof(double) * n);
    memcpy(hi, e, sizeof(double) * n);
    if ((st = pc_curve_eval(c, c->t1, e))) return st;
    for (int i = 0; i < n; i++) {
        lo[i] = fmin(lo[i], e[i]);
        hi[i] = fmax(hi[i], e[i]);
    }
    bbox_ctx b = {n, c->degree, tol, lo, hi, NULL};
    if (c->kind == PC_CURVE_FUNC) return func_bbox(c, &b);
    int p = c->degree, w = n + 1;
    size_t sz = (size_t)(p + 1) * w;
    double scale = 0;
    for (size_t i = 0; i < (size_t)c->ncp * w; i++) scale = fmax(scale, fabs(c->cp[i]));
    b.tol = fmax(tol, 1e-13 * scale);
    b.buf = malloc(sizeof(double) * sz * 2 * (BBOX_DEPTH + 1) + sizeof(double) * sz);
    if (!b.buf) return PC_ENOMEM;
    double *piece = b.buf + sz * 2 * (BBOX_DEPTH + 1);
    st = PC_OK;
    if (c->kind == PC_CURVE_BEZIER) {
        for (int s = 0; !st && s + 1 < c->nknots; s++) {
            memcpy(piece, c->cp + (size_t)s * p * w, sizeof(double) * sz);
            if (!(st = include_h(&b, piece)) && !(st = include_h(&b, piece + (size_t)p * w)))
                st = bez_bbox(&b, piece, 0);
        }
    } else {
        for (int k = p; !st && k < c->ncp; k++) {
            if (!(c->knots[k] < c->knots[k + 1])) continue;
            pcc_bezier_piece(c, k, piece);
            if (!(st = include_h(&b, piece)) && !(st = include_h(&b, piece + (size_t)p * w)))
                st = bez_bbox(&b, piece, 0);
        }
    }
    free(b.buf);
    return st;
}
