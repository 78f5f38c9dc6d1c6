/* Quadrilateral splines and one-stroke curves (stepanov_examples.md examples 5, 10, 33, 34). */
#include "spline.h"
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include "names.h"

void pc_dir2(double u, int ccw, double out[2]) {
    out[0] = cos(u);
    out[1] = ccw ? -sin(u) : sin(u);
}

void pc_dir3(double lon, double lat, double out[3]) {
    out[0] = cos(lon) * cos(lat);
    out[1] = sin(lon) * cos(lat);
    out[2] = sin(lat);
}

void pc_qspline(int d, const double *a, const double *p, const double *q, const double *b,
                double t, double g, double *out) {
    for (int i = 0; i < d; i++) {
        double m = a[i] + t * (p[i] - a[i]);
        double n = q[i] + t * (b[i] - q[i]);
        out[i] = m + g * (n - m);
    }
}

void pc_piece_eval(int d, const pc_piece *pc, double t, double *out) {
    pc_qspline(d, pc->a, pc->p, pc->q, pc->b, t, pc_gfun_eval(&pc->g, t), out);
}

void pc_spline2_piece(int d, const double *A, const double *a, const double *B, const double *b,
                      const pc_gfun *g, pc_piece *out) {
    memset(out, 0, sizeof *out);
    for (int k = 0; k < d; k++) {
        out->a[k] = A[k];
        out->p[k] = A[k] + a[k];
        out->q[k] = B[k] - b[k];
        out->b[k] = B[k];
    }
    out->g = *g;
}

int pc_stroke_npieces(int nnodes, int closed) {
    if (nnodes < 2) return 0;
    return closed ? nnodes : nnodes - 1;
}

static int has_nan(int d, const double *v) {
    for (int i = 0; i < d; i++)
        if (isnan(v[i])) return 1;
    return 0;
}

/* unit vector of v (d doubles) into out; PC_EZERO for a zero vector */
static int unit(int d, const double *v, double *out) {
    double s = 0;
    for (int i = 0; i < d; i++) s += v[i] * v[i];
    s = sqrt(s);
    if (!isfinite(s)) return PC_ENONFINITE;
    if (s == 0) return PC_EZERO;
    for (int i = 0; i < d; i++) out[i] = v[i] / s;
    return PC_OK;
}

static double chord(int d, const double *a, const double *b) {
    double s = 0;
    for (int i = 0; i < d; i++) s += (b[i] - a[i]) * (b[i] - a[i]);
    return sqrt(s);
}

/* the direction at node i: given (row of dir, unless NULL or NaN) or the chord tangent */
static int direction(const pc_stroke_spec *s, const double *dir, int i, double *out) {
    int d = s->d, k = s->nnodes;
    if (dir && !has_nan(d, dir + i * d)) return unit(d, dir + i * d, out);
    int prev = i - 1, next = i + 1;
    if (s->closed) {
        prev = (i + k - 1) % k;
        next = (i + 1) % k;
    } else {
        if (prev < 0) prev = 0;
        if (next > k - 1) next = k - 1;
    }
    double v[PC_CURVE_MAXDIM];
    for (int j = 0; j < d; j++) v[j] = s->nodes[next * d + j] - s->nodes[prev * d + j];
    return unit(d, v, out);
}

int pc_stroke_build(const pc_stroke_spec *s, pc_piece *out, int *bad) {
    int d = s->d, k = s->nnodes;
    if (bad) *bad = -1;
    if (d < 1 || d > PC_CURVE_MAXDIM || k < 2) return PC_EDIM;
    for (int i = 0; i < k * d; i++)
        if (!isfinite(s->nodes[i])) {
            if (bad) *bad = i / d;
            return PC_ENONFINITE;
        }
    int np = pc_stroke_npieces(k, s->closed);
    for (int i = 0; i < np; i++) {
        int j = (i + 1) % k;   /* the node the piece ends at */
        const double *a = s->nodes + i * d, *b = s->nodes + j * d;
        double eo[PC_CURVE_MAXDIM], ei[PC_CURVE_MAXDIM];
        int st = direction(s, s->eout ? s->eout : s->ein, i, eo);
        if (st) {
            if (bad) *bad = i;
            return st;
        }
        st = direction(s, s->ein, j, ei);
        if (st) {
            if (bad) *bad = j;
            return st;
        }
        double c = chord(d, a, b);
        double ro = (s->rout && !isnan(s->rout[i])) ? s->rout[i] : c / 3.0;
        double ri = (s->rin && !isnan(s->rin[j])) ? s->rin[j] : c / 3.0;
        if (!isfinite(ro) || !isfinite(ri)) {
            if (bad) *bad = isfinite(ro) ? j : i;
            return PC_ENONFINITE;
        }
        pc_piece *pc = &out[i];
        memset(pc, 0, sizeof *pc);
        for (int x = 0; x < d; x++) {
            pc->a[x] = a[x];
            pc->b[x] = b[x];
            pc->p[x] = a[x] + ro * eo[x];
            pc->q[x] = b[x] - ri * ei[x];
        }
        pc->g.kind = PC_G_HALF;
        st = pc_hspline_init(&pc->g.h, s->n ? s->n[i] : 2.0, s->m ? s->m[i] : 2.0,
                             s->t0 ? s->t0[i] : 0.5);
        if (st) {
            if (bad) *bad = i;
            return st;
        }
    }
    return PC_OK;
}

/* --- a stroke as a curve of the core --------------------------------------------------------- */
/* g'(t) (order 1) or g''(t) (order 2) of a smoothstep */
static double gfun_deriv(const pc_gfun *g, double t, int order) {
    const double pi = 3.14159265358979323846;
    switch (g->kind) {
    case PC_G_HALF: {
        const pc_hspline *h = &g->h;
        if (order == 1) return pc_hspline_deriv(h, t);
        if (t < h->t0) return h->n == 1 ? 0 : h->n * (h->n - 1) * h->c1 * pow(t, h->n - 2);
        return h->m == 1 ? 0 : -h->m * (h->m - 1) * h->c2 * pow(1 - t, h->m - 2);
    }
    case PC_G_CUBIC: return order == 1 ? 6 * t - 6 * t * t : 6 - 12 * t;
    case PC_G_SINE: return order == 1 ? pi / 2 * sin(pi * t) : pi * pi / 2 * cos(pi * t);
    case PC_G_LINEAR: default: return order == 1 ? 1 : 0;
    }
}

typedef struct {
    int d, np;
    pc_gcall g;               /* NULL: each piece's own smoothstep */
    void (*gfree)(void *ud);
    void *gud;
    pc_piece pieces[];
} stroke_curve;

static void stroke_free(void *ud) {
    stroke_curve *sc = ud;
    if (sc->gfree) sc->gfree(sc->gud);
    free(sc);
}

/* the piece of s in [0, np]: floor(s), the first and last extrapolating */
static int piece_of(const stroke_curve *sc, double s) {
    double f = floor(s);
    return f < 0 ? 0 : (f > sc->np - 1 ? sc->np - 1 : (int)f);
}

/* piece i at its own t, blended by the callback g */
static int piece_by_callback(const stroke_curve *sc, int i, double t, double *out) {
    double g;
    int st = sc->g(sc->gud, t, &g);
    if (st != PC_OK) return st;
    const pc_piece *pc = &sc->pieces[i];
    pc_qspline(sc->d, pc->a, pc->p, pc->q, pc->b, t, g, out);
    return PC_OK;
}

static int stroke_fn(void *ud, double s, int order, double *out) {
    const stroke_curve *sc = ud;
    int i = piece_of(sc, s), d = sc->d, w = d + 1;
    double t = s - i;
    const pc_piece *pc = &sc->pieces[i];
    if (sc->g) {   /* the core differences the callback's values */
        if (order > 0) return PC_EDOMAIN;
        out[d] = 1;
        return piece_by_callback(sc, i, t, out);
    }
    if (pc_gfun_check(&pc->g, t) != PC_OK) return PC_EDOMAIN;
    double g = pc_gfun_eval(&pc->g, t);
    double g1 = order >= 1 ? gfun_deriv(&pc->g, t, 1) : 0, g2 = order >= 2 ? gfun_deriv(&pc->g, t, 2) : 0;
    for (int x = 0; x < d; x++) {
        double m = pc->a[x] + t * (pc->p[x] - pc->a[x]), n = pc->q[x] + t * (pc->b[x] - pc->q[x]);
        double dm = pc->p[x] - pc->a[x], dn = pc->b[x] - pc->q[x];
        out[x] = m + g * (n - m);
        if (order >= 1) out[w + x] = dm + g1 * (n - m) + g * (dn - dm);
        if (order >= 2) out[2 * w + x] = g2 * (n - m) + 2 * g1 * (dn - dm);
    }
    out[d] = 1;
    if (order >= 1) out[w + d] = 0;
    if (order >= 2) out[2 * w + d] = 0;
    return PC_OK;
}

pc_curve *pc_curve_stroke(int d, int npieces, const pc_piece *pieces, int closed, int *status) {
    return pc_curve_stroke_fn(d, npieces, pieces, closed, NULL, NULL, NULL, status);
}

pc_curve *pc_curve_stroke_fn(int d, int npieces, const pc_piece *pieces, int closed, pc_gcall g,
                             void (*gfree)(void *ud), void *gud, int *status) {
    int st = PC_OK;
    if (d < 1 || d > PC_CURVE_MAXDIM || npieces < 1 || npieces > (1 << 24)) st = PC_EDIM;
    else if (!pieces) st = PC_EARG;
    for (int i = 0; !st && i < npieces; i++) {
        const pc_piece *pc = &pieces[i];
        for (int x = 0; x < d; x++)
            if (!isfinite(pc->a[x]) || !isfinite(pc->p[x]) || !isfinite(pc->q[x]) ||
                !isfinite(pc->b[x]))
                st = PC_ENONFINITE;
    }
    stroke_curve *sc = NULL;
    double *brk = NULL;
    if (!st) {
        sc = malloc(sizeof *sc + sizeof(pc_piece) * (size_t)npieces);
        brk = malloc(sizeof(double) * (size_t)npieces);
        if (!sc || !brk) st = PC_ENOMEM;
    }
    pc_curve *c = NULL;
    if (!st) {
        *sc = (stroke_curve){.d = d, .np = npieces, .g = g, .gfree = gfree, .gud = gud};
        memcpy(sc->pieces, pieces, sizeof(pc_piece) * (size_t)npieces);
        for (int i = 1; i < npieces; i++) brk[i - 1] = i;
        /* a callback's function is sampled as a function curve is, from the whole domain */
        c = pc_curve_func_breaks(d, 0, npieces, closed, g ? 0 : npieces - 1, brk, stroke_fn,
                                 stroke_free, sc, &st);
    }
    if (!c) free(sc);
    free(brk);
    if (status) *status = st;
    return c;
}

/* the stroke behind c when c is one over its whole domain */
static const stroke_curve *stroke_of(const pc_curve *c) {
    if (!c || c->kind != PC_CURVE_FUNC || c->func->eval != stroke_fn) return NULL;
    const stroke_curve *sc = c->func->ud;
    return c->t0 == 0 && c->t1 == sc->np ? sc : NULL;
}

const pc_piece *pc_curve_stroke_pieces(const pc_curve *c, int *npieces) {
    const stroke_curve *sc = stroke_of(c);
    if (npieces) *npieces = sc ? sc->np : 0;
    return sc ? sc->pieces : NULL;
}

int pc_stroke_piece_at(const pc_curve *c, int i, double t, double *out) {
    const stroke_curve *sc = stroke_of(c);
    if (!sc || i < 0 || i >= sc->np) return PC_EARG;
    if (sc->g) return piece_by_callback(sc, i, t, out);
    if (pc_gfun_check(&sc->pieces[i].g, t) != PC_OK) return PC_EDOMAIN;
    pc_piece_eval(sc->d, &sc->pieces[i], t, out);
    return PC_OK;
}

const pc_piece *pc_stroke_past(const pc_curve *c, double s, int *piece, double *t) {
    const stroke_curve *sc = stroke_of(c);
    if (!sc || sc->g) return NULL;
    *piece = piece_of(sc, s);
    *t = s - *piece;
    const pc_piece *pc = &sc->pieces[*piece];
    return pc->g.kind == PC_G_HALF && pc_gfun_check(&pc->g, *t) != PC_OK ? pc : NULL;
}

const char *pc_half_why(const pc_piece *pc, double s, int i, double hi, char *why, size_t size) {
    int low = s < 0;
    char deg[40], bound[40];
    snprintf(why, size, "must be %s %s (piece %d's half-spline has the fractional degree %s = %s and does not "
             "extrapolate)", low ? "at least" : "at most", pc_num_text(low ? 0 : hi, bound, sizeof bound), i + 1,
             low ? "n" : "m", pc_num_text(low ? pc->g.h.n : pc->g.h.m, deg, sizeof deg));
    return why;
}

int pc_stroke_value_checked(const char *op, const pc_curve *c, double t, double *h, pc_why_call *why) {
    int st = pc_curve_value(c, t, h), i;
    double s;
    char text[200];
    const pc_piece *pc = st == PC_EDOMAIN ? pc_stroke_past(c, t, &i, &s) : NULL;
    if (!pc) return pc_why_call_set(why, NULL, st, 0, NULL, "");
    return pc_why_call_set(why, op, st, 1, NULL, "%s", pc_half_why(pc, s, i, c->t1, text, sizeof text));
}

int pc_stroke_piece_checked(const char *op, const pc_curve *c, int i, double t, double *x, pc_why_call *why) {
    int np, st = pc_stroke_piece_at(c, i, t, x);
    const pc_piece *pcs = pc_curve_stroke_pieces(c, &np);
    char text[200];
    if (st != PC_EDOMAIN) return pc_why_call_set(why, NULL, st, 0, NULL, "");
    return pc_why_call_set(why, op, st, 2, NULL, "%s", pc_half_why(&pcs[i], t, i, 1, text, sizeof text));
}
