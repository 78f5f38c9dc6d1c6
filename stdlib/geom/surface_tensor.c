/* Tensor-product surfaces on a homogeneous control net (surface.h): Bezier patches evaluated
 * by de Casteljau in each direction, B-spline / NURBS patches by their basis functions; exact
 * partial derivatives (the hodograph, the basis derivatives), exact iso-curves and exact
 * images under a projective map.  The bilinear and the bicubic Hermite patches are Bezier
 * patches (Buimov §5.2, §5.5). */
#include "surface.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define HROW (PC_MAXDIM + 1)               /* doubles in the largest homogeneous row */
#define MAXN (PC_CURVE_MAXDEG + 1)         /* control points of the largest degree */
#define MAXNET (1 << 22)                   /* control points of the largest net */

static int all_finite(const double *a, size_t n) {
    for (size_t i = 0; i < n; i++)
        if (!isfinite(a[i])) return 0;
    return 1;
}

/* de Casteljau on the n+1 values of m doubles at pts (stride `stride` doubles) at t: the
 * value into val and, unless der is NULL, the derivative n (b1 - b0) of the last level but
 * one (the hodograph).  t = 0 and t = 1 give the end values exactly. */
static void decasteljau(int n, int m, const double *pts, size_t stride, double t, double *val,
                        double *der) {
    double w[MAXN * HROW];
    for (int i = 0; i <= n; i++) memcpy(w + i * m, pts + i * stride, (size_t)m * sizeof *w);
    if (n == 0) {
        memcpy(val, w, (size_t)m * sizeof *w);
        if (der) memset(der, 0, (size_t)m * sizeof *der);
        return;
    }
    double s = 1 - t;
    for (int k = n; k > 1; k--)
        for (int i = 0; i < k; i++)
            for (int c = 0; c < m; c++) w[i * m + c] = s * w[i * m + c] + t * w[(i + 1) * m + c];
    for (int c = 0; c < m; c++) {
        double b0 = w[c], b1 = w[m + c];
        if (der) der[c] = n * (b1 - b0);
        val[c] = s * b0 + t * b1;
    }
}

/* The knot span of t: U[s] <= t < U[s+1] with p <= s < n (n control points), the last
 * non-empty span at or beyond the right end, the first one before the left end (so a
 * parameter outside the domain extrapolates the end span). */
static int find_span(int p, int n, const double *U, double t) {
    if (t >= U[n]) {
        int s = n - 1;
        while (s > p && U[s] == U[s + 1]) s--;
        return s;
    }
    if (t < U[p]) {
        int s = p;
        while (s < n - 1 && U[s] == U[s + 1]) s++;
        return s;
    }
    int lo = p, hi = n;                     /* U[lo] <= t < U[hi] */
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (t < U[mid]) hi = mid;
        else lo = mid;
    }
    return lo;
}

/* The p+1 basis functions N[a] = N_{s-p+a,p}(t) that do not vanish on the span s
 * (Cox-de Boor, as Piegl & Tiller A2.2) and, unless dN is NULL, their derivatives
 * N'_{i,p} = p N_{i,p-1}/(U_{i+p} - U_i) - p N_{i+1,p-1}/(U_{i+p+1} - U_{i+1}). */
static void basis(int p, const double *U, int s, double t, double *N, double *dN) {
    double left[MAXN], right[MAXN], prev[MAXN];
    N[0] = 1;
    for (int j = 1; j <= p; j++) {
        if (j == p && dN) memcpy(prev, N, (size_t)p * sizeof *N);
        left[j] = t - U[s + 1 - j];
        right[j] = U[s + j] - t;
        double saved = 0;
        for (int r = 0; r < j; r++) {
            double den = right[r + 1] + left[j - r];
            double tmp = den != 0 ? N[r] / den : 0;
            N[r] = saved + right[r + 1] * tmp;
            saved = left[j - r] * tmp;
        }
        N[j] = saved;
    }
    if (!dN) return;
    if (p == 0) {
        dN[0] = 0;
        return;
    }
    for (int a = 0; a <= p; a++) {
        double d = 0;
        if (a > 0) {
            double den = U[s + a] - U[s - p + a];
            if (den != 0) d += prev[a - 1] / den;
        }
        if (a < p) {
            double den = U[s + a + 1] - U[s - p + a + 1];
            if (den != 0) d -= prev[a] / den;
        }
        dN[a] = p * d;
    }
}

/* --- constructors --------------------------------------------------------------------------- */

pc_surface *pc_surface_bezier(int dim, int p, int q, const double *cp, int *status) {
    int st = PC_OK;
    pc_surface *s = NULL;
    if (dim < 1 || dim > PC_MAXDIM || p < 1 || q < 1 || p > PC_CURVE_MAXDEG ||
        q > PC_CURVE_MAXDEG)
        st = PC_EDIM;
    else if (!cp)
        st = PC_EARG;
    else if (!all_finite(cp, (size_t)(p + 1) * (q + 1) * (dim + 1)))
        st = PC_ENONFINITE;
    else if (!(s = pc_surf_alloc(PC_SURF_BEZIER, dim, &st)))
        ;
    else {
        size_t n = (size_t)(p + 1) * (q + 1) * (dim + 1);
        s->pdeg = p, s->qdeg = q, s->nu = p + 1, s->nv = q + 1;
        s->u0 = 0, s->u1 = 1, s->v0 = 0, s->v1 = 1;
        if (!(s->cp = malloc(n * sizeof *s->cp))) {
            pc_surface_release(s);
            s = NULL;
            st = PC_ENOMEM;
        } else
            memcpy(s->cp, cp, n * sizeof *s->cp);
    }
    if (status) *status = st;
    return s;
}

pc_surface *pc_surface_bilinear(int dim, const double *p00, const double *p10,
                                const double *p01, const double *p11, int *status) {
    if (dim < 1 || dim > PC_MAXDIM || !p00 || !p10 || !p01 || !p11) {
        if (status) *status = dim < 1 || dim > PC_MAXDIM ? PC_EDIM : PC_EARG;
        return NULL;
    }
    /* B_ij, i along u: B00 = P00, B01 = P01, B10 = P10, B11 = P11 */
    const double *corner[4] = {p00, p01, p10, p11};
    double cp[4 * HROW];
    int m = dim + 1;
    for (int k = 0; k < 4; k++) {
        memcpy(cp + k * m, corner[k], (size_t)dim * sizeof *cp);
        cp[k * m + dim] = 1;
    }
    return pc_surface_bezier(dim, 1, 1, cp, status);
}

/* Buimov §5.5 by the Bezier form: at the corner (a, b) with the inward signs su, sv (+1 at
 * 0, -1 at 1), B(corner) = P, the neighbours along u and v P + su Pu/3 and P + sv Pv/3,
 * and the inner point P + su Pu/3 + sv Pv/3 + su sv Puv/9 (the twist is 9 times the mixed
 * difference of the four). */
pc_surface *pc_surface_hermite(int dim, const double *p, const double *pu, const double *pv,
                               const double *puv, int *status) {
    if (dim < 1 || dim > PC_MAXDIM || !p || !pu || !pv || !puv) {
        if (status) *status = dim < 1 || dim > PC_MAXDIM ? PC_EDIM : PC_EARG;
        return NULL;
    }
    int m = dim + 1;
    double cp[16 * HROW];
    for (int k = 0; k < 4; k++) {
        int a = k & 1, b = k >> 1;                  /* corners (0,0), (1,0), (0,1), (1,1) */
        int i = 3 * a, j = 3 * b, su = a ? -1 : 1, sv = b ? -1 : 1;
        const double *P = p + k * dim, *U = pu + k * dim, *V = pv + k * dim, *T = puv + k * dim;
        double *b00 = cp + (i * 4 + j) * m, *b10 = cp + ((i + su) * 4 + j) * m;
        double *b01 = cp + (i * 4 + j + sv) * m, *b11 = cp + ((i + su) * 4 + j + sv) * m;
        for (int c = 0; c < dim; c++) {
            b00[c] = P[c];
            b10[c] = P[c] + su * U[c] / 3;
            b01[c] = P[c] + sv * V[c] / 3;
            b11[c] = P[c] + su * U[c] / 3 + sv * V[c] / 3 + su * sv * T[c] / 9;
        }
        b00[dim] = b10[dim] = b01[dim] = b11[dim] = 1;
    }
    return pc_surface_bezier(dim, 3, 3, cp, status);
}

/* The knot vector of one direction into U (n + p + 1 values, n the control points after a
 * periodic net is extended by p), as pc_curve_bspline makes it, so that an iso-curve and a
 * curve built from the same row agree in parameter. */
static int make_knots(pc_knot_kind kind, int p, int n, const double *given, double *U) {
    int nk = n + p + 1;
    switch (kind) {
    case PC_KNOTS_GIVEN:
        if (!given) return PC_EARG;
        if (!all_finite(given, (size_t)nk)) return PC_ENONFINITE;
        for (int i = 0; i < nk; i++) {
            if (i > 0 && given[i] < given[i - 1]) return PC_EDOMAIN;
            U[i] = given[i];
        }
        if (!(U[p] < U[n])) return PC_EDOMAIN;   /* the domain is one empty span */
        return PC_OK;
    case PC_KNOTS_OPEN:                          /* 0 (p+1 times), 1, ..., n-p (p+1 times) */
        for (int i = 0; i < nk; i++) U[i] = i <= p ? 0 : i >= n ? n - p : i - p;
        return PC_OK;
    case PC_KNOTS_UNIFORM:                       /* 0, 1, 2, ...: the domain [p, n] */
        for (int i = 0; i < nk; i++) U[i] = i;
        return PC_OK;
    case PC_KNOTS_PERIODIC:                      /* -p, ..., 0, 1, ...: the domain [0, n-p] */
        for (int i = 0; i < nk; i++) U[i] = i - p;
        return PC_OK;
    }
    return PC_EARG;
}

pc_surface *pc_surface_bspline(int dim, int p, int q, int nu, int nv, const double *cp,
                               pc_knot_kind ukind, const double *uk, pc_knot_kind vkind,
                               const double *vk, int *status) {
    int st = PC_OK, m = dim + 1;
    pc_surface *s = NULL;
    int pu = ukind == PC_KNOTS_PERIODIC, pv = vkind == PC_KNOTS_PERIODIC;
    if (dim < 1 || dim > PC_MAXDIM || p < 1 || q < 1 || p > PC_CURVE_MAXDEG ||
        q > PC_CURVE_MAXDEG || nu < 2 || nv < 2 || (pu ? p > nu : p >= nu) ||
        (pv ? q > nv : q >= nv))
        st = PC_EDIM;
    else if ((long long)(nu + p) * (nv + q) > MAXNET)
        st = PC_ENOMEM;
    else if (!cp)
        st = PC_EARG;
    else if (!all_finite(cp, (size_t)nu * nv * m))
        st = PC_ENONFINITE;
    else if ((s = pc_surf_alloc(PC_SURF_BSPLINE, dim, &st))) {
        int NU = nu + (pu ? p : 0), NV = nv + (pv ? q : 0);   /* periodic: wrap the net */
        s->pdeg = p, s->qdeg = q, s->nu = NU, s->nv = NV;
        s->cp = malloc((size_t)NU * NV * m * sizeof *s->cp);
        s->uknots = malloc((size_t)(NU + p + 1) * sizeof *s->uknots);
        s->vknots = malloc((size_t)(NV + q + 1) * sizeof *s->vknots);
        if (!s->cp || !s->uknots || !s->vknots)
            st = PC_ENOMEM;
        else if ((st = make_knots(ukind, p, NU, uk, s->uknots)) == PC_OK)
            st = make_knots(vkind, q, NV, vk, s->vknots);
        if (st == PC_OK) {
            for (int i = 0; i < NU; i++)
                for (int j = 0; j < NV; j++)
                    memcpy(s->cp + ((size_t)i * NV + j) * m,
                           cp + ((size_t)(i % nu) * nv + j % nv) * m, (size_t)m * sizeof *cp);
            s->u0 = s->uknots[p], s->u1 = s->uknots[NU];
            s->v0 = s->vknots[q], s->v1 = s->vknots[NV];
        } else {
            pc_surface_release(s);
            s = NULL;
        }
    }
    if (status) *status = st;
    return s;
}

/* --- evaluation ----------------------------------------------------------------------------- */

int pc_surf_tensor_eval_h(const pc_surface *s, double u, double v, int order, double *out) {
    int m = s->dim + 1, p = s->pdeg, q = s->qdeg, nv = s->nv;
    double R[MAXN * HROW], Rd[MAXN * HROW];
    if (s->kind == PC_SURF_BEZIER) {
        /* each row (fixed i) in v, then the row values (and their v-derivatives) in u */
        for (int i = 0; i <= p; i++)
            decasteljau(q, m, s->cp + (size_t)i * nv * m, m, v, R + i * m,
                        order ? Rd + i * m : NULL);
        decasteljau(p, m, R, m, u, out, order ? out + m : NULL);
        if (order) decasteljau(p, m, Rd, m, u, out + 2 * m, NULL);
        return PC_OK;
    }
    double Nu[MAXN], dNu[MAXN], Nv[MAXN], dNv[MAXN];
    int su = find_span(p, s->nu, s->uknots, u), sv = find_span(q, s->nv, s->vknots, v);
    basis(p, s->uknots, su, u, Nu, order ? dNu : NULL);
    basis(q, s->vknots, sv, v, Nv, order ? dNv : NULL);
    memset(out, 0, (size_t)(order ? 3 : 1) * m * sizeof *out);
    for (int a = 0; a <= p; a++) {
        const double *row = s->cp + ((size_t)(su - p + a) * nv + (sv - q)) * m;
        for (int c = 0; c < m; c++) {
            double r = 0, rd = 0;
            for (int b = 0; b <= q; b++) {
                r += Nv[b] * row[b * m + c];
                if (order) rd += dNv[b] * row[b * m + c];
            }
            out[c] += Nu[a] * r;
            if (order) {
                out[m + c] += dNu[a] * r;
                out[2 * m + c] += Nu[a] * rd;
            }
        }
    }
    return PC_OK;
}

/* The control points of the iso-curve (dir 0: u = value, a curve in v; dir 1: v = value, a
 * curve in u) into pts (nv or nu rows): each column (row) of the net reduced at value. */
static void iso_points(const pc_surface *s, int dir, double value, double *pts) {
    int m = s->dim + 1, p = s->pdeg, q = s->qdeg, nu = s->nu, nv = s->nv;
    if (s->kind == PC_SURF_BEZIER) {
        if (dir == 0)
            for (int j = 0; j < nv; j++)
                decasteljau(p, m, s->cp + (size_t)j * m, (size_t)nv * m, value, pts + j * m, NULL);
        else
            for (int i = 0; i < nu; i++)
                decasteljau(q, m, s->cp + (size_t)i * nv * m, m, value, pts + i * m, NULL);
        return;
    }
    double N[MAXN];
    if (dir == 0) {
        int sp = find_span(p, nu, s->uknots, value);
        basis(p, s->uknots, sp, value, N, NULL);
        memset(pts, 0, (size_t)nv * m * sizeof *pts);
        for (int a = 0; a <= p; a++) {
            const double *row = s->cp + (size_t)(sp - p + a) * nv * m;
            for (size_t k = 0; k < (size_t)nv * m; k++) pts[k] += N[a] * row[k];
        }
    } else {
        int sp = find_span(q, nv, s->vknots, value);
        basis(q, s->vknots, sp, value, N, NULL);
        for (int i = 0; i < nu; i++) {
            const double *row = s->cp + ((size_t)i * nv + sp - q) * m;
            for (int c = 0; c < m; c++) {
                double r = 0;
                for (int b = 0; b <= q; b++) r += N[b] * row[b * m + c];
                pts[i * m + c] = r;
            }
        }
    }
}

pc_curve *pc_surf_tensor_iso(const pc_surface *s, int dir, double value, int *status) {
    int n = dir == 0 ? s->nv : s->nu, deg = dir == 0 ? s->qdeg : s->pdeg;
    double *pts = malloc((size_t)n * (s->dim + 1) * sizeof *pts);
    if (!pts) {
        if (status) *status = PC_ENOMEM;
        return NULL;
    }
    iso_points(s, dir, value, pts);
    pc_curve *c;
    if (s->kind == PC_SURF_BEZIER)
        c = pc_curve_bezier(s->dim, n, pts, status);
    else
        c = pc_curve_bspline(s->dim, deg, n, pts, PC_KNOTS_GIVEN,
                             dir == 0 ? s->vknots : s->uknots, status);
    free(pts);
    return c;
}

/* The image under f: every control point mapped (a projective map keeps the patch rational
 * and exact), the knots kept. */
pc_surface *pc_surf_tensor_map(const pc_surface *s, const pc_map *f, int *status) {
    int st = PC_OK, m = s->dim + 1, mo = f->nout + 1;
    size_t n = (size_t)s->nu * s->nv;
    pc_surface *r = pc_surf_alloc(s->kind, f->nout, &st);
    if (r) {
        r->pdeg = s->pdeg, r->qdeg = s->qdeg, r->nu = s->nu, r->nv = s->nv;
        r->u0 = s->u0, r->u1 = s->u1, r->v0 = s->v0, r->v1 = s->v1;
        r->cp = malloc(n * mo * sizeof *r->cp);
        if (s->uknots) {
            r->uknots = malloc((size_t)(s->nu + s->pdeg + 1) * sizeof *r->uknots);
            r->vknots = malloc((size_t)(s->nv + s->qdeg + 1) * sizeof *r->vknots);
        }
        if (!r->cp || (s->uknots && (!r->uknots || !r->vknots))) {
            st = PC_ENOMEM;
        } else {
            for (size_t k = 0; k < n; k++)
                for (int i = 0; i < mo; i++) {
                    double x = 0;
                    for (int j = 0; j < m; j++) x += PC_MAP_AT(f, i, j) * s->cp[k * m + j];
                    r->cp[k * mo + i] = x;
                }
            if (!all_finite(r->cp, n * mo)) st = PC_ENONFINITE;
            if (s->uknots) {
                memcpy(r->uknots, s->uknots, (size_t)(s->nu + s->pdeg + 1) * sizeof *r->uknots);
                memcpy(r->vknots, s->vknots, (size_t)(s->nv + s->qdeg + 1) * sizeof *r->vknots);
            }
        }
        if (st != PC_OK) {
            pc_surface_release(r);
            r = NULL;
        }
    }
    if (status) *status = st;
    return r;
}
