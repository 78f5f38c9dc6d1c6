/* Flattening: an adaptive polyline of a curve in a projected plane, broken where the curve
 * passes through a point at infinity or has no finite image.
 *
 * The parameter range is cut at the curve's breakpoints (Bezier breaks, B-spline knots, FUNC
 * breaks) and each piece into NINIT intervals (NINIT_FUNC for a FUNC curve without breaks).
 * An interval is accepted when the projected points at 1/4, 1/2 and 3/4 of it lie within
 * 0.9 tol of its chord (as a segment, so that an S-shaped or doubling-back span is not taken
 * for straight); otherwise it is halved, down to MAXDEPTH halvings.  An interval where the
 * image fails (PC_IMPROPER, PC_ENONFINITE) at one of these five points, or where the sign of
 * the curve's weight differs between them, contains a point at infinity: it is bisected down to
 * BADDEPTH halvings and the polyline is broken there.  At MAXDEPTH an interval still too far
 * from its chord is accepted unless its chord is longer than JUMP tol: then the curve jumps
 * (a pole of the projection, a discontinuous callback) and the polyline is broken instead. */
#include "curve_impl.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { NINIT = 8, NINIT_FUNC = 32, MAXDEPTH = 16, BADDEPTH = 52, JUMP = 64 };

void pc_polyline_free(pc_polyline *pl) {
    if (!pl) return;
    free(pl->xy);
    free(pl->move);
    pl->xy = NULL;
    pl->move = NULL;
    pl->n = pl->cap = 0;
}

int pc_polyline_push(pc_polyline *pl, double x, double y, int move) {
    if (!pl) return PC_EARG;
    if (pl->n == pl->cap) {
        size_t cap = pl->cap ? 2 * pl->cap : 64;
        if (cap > ((size_t)-1) / (2 * sizeof(double))) return PC_ENOMEM;
        double *xy = realloc(pl->xy, sizeof(double) * 2 * cap);
        if (!xy) return PC_ENOMEM;
        pl->xy = xy;
        uint8_t *mv = realloc(pl->move, cap);
        if (!mv) return PC_ENOMEM;
        pl->move = mv;
        pl->cap = cap;
    }
    pl->xy[2 * pl->n] = x;
    pl->xy[2 * pl->n + 1] = y;
    pl->move[pl->n] = move != 0;
    pl->n++;
    return PC_OK;
}

typedef struct {
    double t, xy[2];
    int bad, sg;     /* no image here; the sign of the curve's weight */
} fpt;

typedef struct {
    const pc_curve *c;
    pc_project_fn proj;
    void *ud;
    double tol;
    pc_polyline *out;
    int pen_up;      /* the next vertex starts a new piece */
} flat;

static int point(const flat *f, double t, fpt *p) {
    double h[PCC_W];
    int n = f->c->dim;
    p->t = t;
    p->bad = 0;
    int st = pc_curve_eval_h(f->c, t, 0, h);
    if (st == PC_ENONFINITE || st == PC_IMPROPER) {
        p->bad = 1;
        p->sg = 0;
        return PC_OK;
    }
    if (st) return st;
    p->sg = h[n] > 0 ? 1 : (h[n] < 0 ? -1 : 0);
    if (f->proj) {
        st = f->proj(f->ud, h, p->xy);
        if (st == PC_IMPROPER || st == PC_ENONFINITE) p->bad = 1;
        else if (st) return st;
    } else if (h[n] == 0) {
        p->bad = 1;
    } else {
        p->xy[0] = h[0] / h[n];
        p->xy[1] = h[1] / h[n];
    }
    if (!p->bad && !(isfinite(p->xy[0]) && isfinite(p->xy[1]))) p->bad = 1;
    return PC_OK;
}

static double seg_dist(const double *a, const double *b, const double *q) {
    double vx = b[0] - a[0], vy = b[1] - a[1], wx = q[0] - a[0], wy = q[1] - a[1];
    double l2 = vx * vx + vy * vy, s = l2 > 0 ? (vx * wx + vy * wy) / l2 : 0;
    if (s < 0) s = 0;
    if (s > 1) s = 1;
    return hypot(wx - s * vx, wy - s * vy);
}

static int emit(flat *f, const fpt *a, const fpt *b) {
    int st;
    if (f->pen_up) {
        if ((st = pc_polyline_push(f->out, a->xy[0], a->xy[1], 1))) return st;
        f->pen_up = 0;
    }
    const double *last = f->out->xy + 2 * (f->out->n - 1);
    if (last[0] == b->xy[0] && last[1] == b->xy[1]) return PC_OK;
    return pc_polyline_push(f->out, b->xy[0], b->xy[1], 0);
}

typedef struct {
    fpt a, m, b;
    int depth;
} interval;

static int subdivide(flat *f, const fpt *pa, const fpt *pb) {
    interval stack[BADDEPTH + 4];
    int top = 0, st;
    stack[0].a = *pa;
    stack[0].b = *pb;
    stack[0].depth = 0;
    if ((st = point(f, pa->t + (pb->t - pa->t) / 2, &stack[0].m))) return st;
    top = 1;
    while (top > 0) {
        interval I = stack[--top];
        fpt q1, q3;
        double ta = I.a.t, tm = I.m.t, tb = I.b.t;
        if ((st = point(f, ta + (tm - ta) / 2, &q1)) || (st = point(f, tm + (tb - tm) / 2, &q3)))
            return st;
        const fpt *five[5] = {&I.a, &q1, &I.m, &q3, &I.b};
        int bad = 0;
        for (int i = 0; i < 5; i++)
            if (five[i]->bad || five[i]->sg != I.a.sg || five[i]->sg == 0) bad = 1;
        int can_split = tm > ta && tm < tb && q1.t > ta && q1.t < tm && q3.t > tm && q3.t < tb;
        if (bad) {
            if (I.depth < BADDEPTH && can_split) goto split;
            f->pen_up = 1;
            continue;
        }
        double dev = fmax(seg_dist(I.a.xy, I.b.xy, q1.xy),
                          fmax(seg_dist(I.a.xy, I.b.xy, I.m.xy), seg_dist(I.a.xy, I.b.xy, q3.xy)));
        if (dev <= 0.9 * f->tol) {
            if ((st = emit(f, &I.a, &I.b))) return st;
            continue;
        }
        if (I.depth < MAXDEPTH && can_split) goto split;
        if (hypot(I.b.xy[0] - I.a.xy[0], I.b.xy[1] - I.a.xy[1]) > JUMP * f->tol) {
            f->pen_up = 1;
            continue;
        }
        if ((st = emit(f, &I.a, &I.b))) return st;
        continue;
    split:
        stack[top].a = I.m;
        stack[top].m = q3;
        stack[top].b = I.b;
        stack[top].depth = I.depth + 1;
        top++;
        stack[top].a = I.a;
        stack[top].m = q1;
        stack[top].b = I.m;
        stack[top].depth = I.depth + 1;
        top++;
    }
    return PC_OK;
}

int pc_curve_flatten(const pc_curve *c, double a, double b, pc_project_fn proj, void *ud,
                     double tol, pc_polyline *out) {
    if (!c || !out) return PC_EARG;
    if (!isfinite(a) || !isfinite(b) || !isfinite(tol)) return PC_ENONFINITE;
    if (!(a <= b) || !(tol > 0)) return PC_EDOMAIN;
    if (!proj && c->dim != 2) return PC_EDIM;
    flat f = {c, proj, ud, tol, out, 1};
    fpt pa, pb;
    int st = point(&f, a, &pa);
    if (st) return st;
    if (a == b) {
        if (!pa.bad) return pc_polyline_push(out, pa.xy[0], pa.xy[1], 1);
        return PC_OK;
    }
    int ninit = c->kind == PC_CURVE_FUNC && c->nknots == 0 ? NINIT_FUNC : NINIT;
    for (double x = a; x < b;) {
        double y = pcc_next_break(c, x, b);
        for (int q = 1; q <= ninit; q++) {
            double t = q == ninit ? y : x + (y - x) * q / ninit;
            if (!(t > pa.t)) continue;
            if ((st = point(&f, t, &pb)) || (st = subdivide(&f, &pa, &pb))) return st;
            pa = pb;
        }
        x = y;
    }
    return PC_OK;
}
