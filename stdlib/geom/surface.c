/* The one surface type (surface.h): life, FUNC surfaces, evaluation of every kind (the
 * dispatch), partial derivatives, normals, iso-curves and images under maps.  The tensor
 * kinds live in surface_tensor.c, the curve-based kinds in surface_curves.c. */
#include "surface.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define HROW (PC_MAXDIM + 1)
#define TWO_PI 6.283185307179586

pc_surface *pc_surf_alloc(pc_surface_kind kind, int dim, int *status) {
    pc_surface *s = calloc(1, sizeof *s);
    if (!s) {
        if (status) *status = PC_ENOMEM;
        return NULL;
    }
    s->refs = 1;
    s->kind = kind;
    s->dim = dim;
    if (status) *status = PC_OK;
    return s;
}

pc_surface *pc_surface_retain(pc_surface *s) {
    if (s) s->refs++;
    return s;
}

void pc_surface_release(pc_surface *s) {
    if (!s || --s->refs > 0) return;
    free(s->cp);
    free(s->uknots);
    free(s->vknots);
    for (int k = 0; k < 4; k++) pc_curve_release(s->curves[k]);
    if (s->fn_free) s->fn_free(s->ud);
    free(s);
}

pc_surface *pc_surface_func(int dim, double u0, double u1, double v0, double v1,
                            pc_surface_fn fn, void (*fn_free)(void *ud), void *ud, int *status) {
    int st = PC_OK;
    pc_surface *s = NULL;
    if (dim < 1 || dim > PC_MAXDIM)
        st = PC_EDIM;
    else if (!fn)
        st = PC_EARG;
    else if (!isfinite(u0) || !isfinite(u1) || !isfinite(v0) || !isfinite(v1))
        st = PC_ENONFINITE;
    else if (!(u0 < u1) || !(v0 < v1))
        st = PC_EDOMAIN;
    else if ((s = pc_surf_alloc(PC_SURF_FUNC, dim, &st))) {
        s->u0 = u0, s->u1 = u1, s->v0 = v0, s->v1 = v1;
        s->fn = fn, s->fn_free = fn_free, s->ud = ud;
    }
    if (status) *status = st;
    return s;
}

/* --- evaluation ----------------------------------------------------------------------------- */

int pc_surface_eval_h(const pc_surface *s, double u, double v, int order, double *out) {
    if (!s || !out || order < 0 || order > 1) return PC_EARG;
    if (!isfinite(u) || !isfinite(v)) return PC_ENONFINITE;
    int st;
    switch (s->kind) {
    case PC_SURF_BEZIER:
    case PC_SURF_BSPLINE: st = pc_surf_tensor_eval_h(s, u, v, order, out); break;
    case PC_SURF_FUNC: st = s->fn(s->ud, u, v, order, out); break;
    default: st = pc_surf_curves_eval_h(s, u, v, order, out); break;
    }
    if (st != PC_OK) return st;
    for (int k = 0; k < (2 * order + 1) * (s->dim + 1); k++)
        if (!isfinite(out[k])) return PC_ENONFINITE;
    return PC_OK;
}

int pc_surface_eval(const pc_surface *s, double u, double v, double *out) {
    double h[HROW];
    int st = pc_surface_eval_h(s, u, v, 0, h);
    if (st != PC_OK && st != PC_IMPROPER) return st;
    int n = s->dim;
    if (st == PC_IMPROPER || h[n] == 0) {
        memcpy(out, h, (size_t)n * sizeof *out);
        return PC_IMPROPER;
    }
    for (int i = 0; i < n; i++) out[i] = h[i] / h[n];
    for (int i = 0; i < n; i++)
        if (!isfinite(out[i])) return PC_ENONFINITE;
    return PC_OK;
}

/* The Cartesian point at (u, v) with one parameter moved to x (dir 0: u, 1: v). */
static int eval_at(const pc_surface *s, double u, double v, int dir, double x, double *out) {
    return dir == 0 ? pc_surface_eval(s, x, v, out) : pc_surface_eval(s, u, x, out);
}

/* Partial derivatives by differences of Cartesian values, for a FUNC callback without
 * derivatives: central where both neighbours evaluate, else one-sided of second order
 * (-3 f0 + 4 f1 - f2)/2h (at the edge of a callback's domain). */
static int diff_partials(const pc_surface *s, double u, double v, double *out) {
    int n = s->dim, st = pc_surface_eval(s, u, v, out);
    if (st != PC_OK) return st;
    for (int dir = 0; dir < 2; dir++) {
        double x = dir == 0 ? u : v, w = dir == 0 ? s->u1 - s->u0 : s->v1 - s->v0;
        double h = 6.0e-6 * fmax(w, fabs(x));          /* about cbrt(eps) of the scale */
        double fp[PC_MAXDIM], fm[PC_MAXDIM], f2[PC_MAXDIM], *d = out + (dir + 1) * n;
        double xp = x + h, xm = x - h;
        int okp = eval_at(s, u, v, dir, xp, fp) == PC_OK;
        if (okp && eval_at(s, u, v, dir, xm, fm) == PC_OK) {
            for (int i = 0; i < n; i++) d[i] = (fp[i] - fm[i]) / (xp - xm);
            continue;
        }
        double x1 = okp ? xp : xm, x2 = okp ? x + 2 * h : x - 2 * h;
        if (!okp && (st = eval_at(s, u, v, dir, x1, fp)) != PC_OK) return st;
        if ((st = eval_at(s, u, v, dir, x2, f2)) != PC_OK) return st;
        for (int i = 0; i < n; i++) d[i] = (-3 * out[i] + 4 * fp[i] - f2[i]) / (x2 - x);
    }
    return PC_OK;
}

int pc_surface_partials(const pc_surface *s, double u, double v, double *out) {
    double h[3 * HROW];
    int st = pc_surface_eval_h(s, u, v, 1, h);
    if (st == PC_EDOMAIN && s->kind == PC_SURF_FUNC) return diff_partials(s, u, v, out);
    if (st != PC_OK && st != PC_IMPROPER) return st;
    int n = s->dim, m = n + 1;
    double w = h[n];
    if (st == PC_IMPROPER || w == 0) return PC_IMPROPER;
    /* P = x/w, P_u = (x_u - P w_u)/w, P_v = (x_v - P w_v)/w */
    for (int i = 0; i < n; i++) {
        double p = h[i] / w;
        out[i] = p;
        out[n + i] = (h[m + i] - p * h[m + n]) / w;
        out[2 * n + i] = (h[2 * m + i] - p * h[2 * m + n]) / w;
    }
    for (int i = 0; i < 3 * n; i++)
        if (!isfinite(out[i])) return PC_ENONFINITE;
    return PC_OK;
}

int pc_surface_normal(const pc_surface *s, double u, double v, double *nrm) {
    if (!s) return PC_EARG;
    if (s->dim != 3) return PC_EDIM;
    double d[9], c[3];
    int st = pc_surface_partials(s, u, v, d);
    if (st != PC_OK) return st;
    pc_cross3(d + 3, d + 6, c);
    double len = pc_norm(3, c), lu = pc_norm(3, d + 3), lv = pc_norm(3, d + 6);
    if (!(len > PC_DEGEN_TOL * lu * lv) || !(len > 0)) return PC_EZERO;
    for (int i = 0; i < 3; i++) nrm[i] = c[i] / len;
    return PC_OK;
}

/* --- iso-curves ----------------------------------------------------------------------------- */

typedef struct {
    pc_surface *s;
    int dir;
    double value;
} iso_ud;

static int iso_fn(void *ud, double t, int order, double *out) {
    iso_ud *d = ud;
    if (order > 1) return PC_EDOMAIN;
    int m = d->s->dim + 1;
    double h[3 * HROW];
    int st = d->dir == 0 ? pc_surface_eval_h(d->s, d->value, t, order, h)
                         : pc_surface_eval_h(d->s, t, d->value, order, h);
    if (st != PC_OK) return st;
    memcpy(out, h, (size_t)m * sizeof *out);
    if (order == 1) memcpy(out + m, h + (d->dir == 0 ? 2 : 1) * m, (size_t)m * sizeof *out);
    return PC_OK;
}

static void iso_free(void *ud) {
    iso_ud *d = ud;
    pc_surface_release(d->s);
    free(d);
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The interior breakpoints of curve c (Bezier breaks, B-spline knots, FUNC breaks) with its
 * domain mapped onto [0, 1] (map01) or kept, appended to brk. */
static int add_breaks(const pc_curve *c, int map01, double *brk, int n) {
    if (!c || !c->knots) return n;
    for (int i = 0; i < c->nknots; i++) {
        double t = c->knots[i];
        if (t > c->t0 && t < c->t1) brk[n++] = map01 ? (t - c->t0) / (c->t1 - c->t0) : t;
    }
    return n;
}

/* The breakpoints of a FUNC iso-curve: where the curves the surface is made of break along
 * it (sorted, distinct, inside the domain), so that flattening starts there.  *brk is NULL
 * or malloc'd. */
static int iso_breaks(const pc_surface *s, int dir, double **brk) {
    const pc_curve *a = NULL, *b = NULL;
    int map01 = 1;
    *brk = NULL;
    if (s->kind == PC_SURF_RULED && dir == 1) a = s->curves[0], b = s->curves[1];
    else if (s->kind == PC_SURF_COONS) a = s->curves[2 * dir], b = s->curves[2 * dir + 1];
    else if (s->kind == PC_SURF_REVOLUTION && dir == 1) a = s->curves[0], map01 = 0;
    if (!a) return 0;
    size_t cap = (size_t)a->nknots + (b ? (size_t)b->nknots : 0);
    if (cap == 0 || !(*brk = malloc(cap * sizeof **brk))) return 0;
    int n = add_breaks(b, map01, *brk, add_breaks(a, map01, *brk, 0)), k = 0;
    qsort(*brk, (size_t)n, sizeof **brk, cmp_double);
    double t0 = dir == 0 ? s->v0 : s->u0, t1 = dir == 0 ? s->v1 : s->u1;
    for (int i = 0; i < n; i++)
        if ((*brk)[i] > (k ? (*brk)[k - 1] : t0) && (*brk)[i] < t1) (*brk)[k++] = (*brk)[i];
    return k;
}

pc_curve *pc_surface_iso(pc_surface *s, int dir, double value, int *status) {
    int st = PC_OK;
    pc_curve *c = NULL;
    if (!s)
        st = PC_EARG;
    else if (dir != 0 && dir != 1)
        st = PC_EDOMAIN;
    else if (!isfinite(value))
        st = PC_ENONFINITE;
    else if (s->kind == PC_SURF_BEZIER || s->kind == PC_SURF_BSPLINE)
        return pc_surf_tensor_iso(s, dir, value, status);
    else {
        iso_ud *d = malloc(sizeof *d);
        if (!d) {
            st = PC_ENOMEM;
        } else {
            d->s = pc_surface_retain(s), d->dir = dir, d->value = value;
            double t0 = dir == 0 ? s->v0 : s->u0, t1 = dir == 0 ? s->v1 : s->u1;
            int closed = s->kind == PC_SURF_REVOLUTION && dir == 0 &&
                         fabs(t1 - t0 - TWO_PI) <= 1e-12 * TWO_PI;
            double *brk;
            int nbrk = iso_breaks(s, dir, &brk);
            c = pc_curve_func_breaks(s->dim, t0, t1, closed, nbrk, brk, iso_fn, iso_free, d,
                                     &st);
            free(brk);
            if (!c) iso_free(d);
        }
    }
    if (status) *status = st;
    return c;
}

/* --- maps ----------------------------------------------------------------------------------- */

typedef struct {
    pc_surface *s;
    pc_map f;
} map_ud;

/* h' = M h (as pc_map_apply; kept here so that surfaces need no more of map.c) */
static void apply(const pc_map *f, const double *in, double *out) {
    for (int i = 0; i <= f->nout; i++) {
        double x = 0;
        for (int j = 0; j <= f->nin; j++) x += PC_MAP_AT(f, i, j) * in[j];
        out[i] = x;
    }
}

static int map_fn(void *ud, double u, double v, int order, double *out) {
    map_ud *d = ud;
    double h[3 * HROW];
    int st = pc_surface_eval_h(d->s, u, v, order, h);
    if (st != PC_OK) return st;
    for (int r = 0; r <= 2 * order; r++)     /* value, d/du, d/dv: the map is linear */
        apply(&d->f, h + r * (d->f.nin + 1), out + r * (d->f.nout + 1));
    return PC_OK;
}

static void map_free(void *ud) {
    map_ud *d = ud;
    pc_surface_release(d->s);
    free(d);
}

pc_surface *pc_surface_map(pc_surface *s, const pc_map *f, int *status) {
    int st = PC_OK;
    pc_surface *r = NULL;
    if (!s || !f)
        st = PC_EARG;
    else if (f->nin != s->dim || f->nout < 1 || f->nout > PC_MAXDIM)
        st = PC_EDIM;
    else if (s->kind == PC_SURF_BEZIER || s->kind == PC_SURF_BSPLINE)
        return pc_surf_tensor_map(s, f, status);
    else {
        map_ud *d = malloc(sizeof *d);
        if (!d) {
            st = PC_ENOMEM;
        } else {
            d->s = pc_surface_retain(s), d->f = *f;
            r = pc_surface_func(f->nout, s->u0, s->u1, s->v0, s->v1, map_fn, map_free, d, &st);
            if (!r) map_free(d);
        }
    }
    if (status) *status = st;
    return r;
}
