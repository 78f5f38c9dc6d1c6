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
 * BADDEPTH halvings and the polyline is broken there (an interval with no image at any of
 * the five points is skipped whole).  At MAXDEPTH an interval still too far
 * from its chord is accepted unless its chord is longer than JUMP tol: then the curve jumps
 * (a pole of the projection, a discontinuous callback) and the polyline is broken instead.
 *
 * With a clip box (pc_polyline.clip), a Bezier piece whose control polygon lies outside the
 * box is not subdivided: the polyline moves to its end (the piece lies in the polygon's hull,
 * so nothing of it is visible), and the cost follows the visible part of the curve.  Every
 * polyline is capped at PC_POLYLINE_MAX vertices. */
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
    if (pl->n >= PC_POLYLINE_MAX) return PC_ENOMEM;
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

/* The squared distance of q from the segment ab (squares: no square root per probe). */
static double seg_dist2(const double *a, const double *b, const double *q) {
    double vx = b[0] - a[0], vy = b[1] - a[1], wx = q[0] - a[0], wy = q[1] - a[1];
    double l2 = vx * vx + vy * vy, s = l2 > 0 ? (vx * wx + vy * wy) / l2 : 0;
    if (s < 0) s = 0;
    if (s > 1) s = 1;
    double dx = wx - s * vx, dy = wy - s * vy;
    return dx * dx + dy * dy;
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
        int bad = 0, nbad = 0;
        for (int i = 0; i < 5; i++) {
            if (five[i]->bad || five[i]->sg != I.a.sg || five[i]->sg == 0) bad = 1;
            nbad += five[i]->bad;
        }
        int can_split = tm > ta && tm < tb && q1.t > ta && q1.t < tm && q3.t > tm && q3.t < tb;
        if (bad) {
            /* bisect towards where the image begins or the weight changes sign; an interval
             * without an image at all five points is skipped (halving it all the way down
             * would cost 2^BADDEPTH evaluations) */
            if (nbad < 5 && I.depth < BADDEPTH && can_split) goto split;
            f->pen_up = 1;
            continue;
        }
        double dev2 = fmax(seg_dist2(I.a.xy, I.b.xy, q1.xy),
                           fmax(seg_dist2(I.a.xy, I.b.xy, I.m.xy), seg_dist2(I.a.xy, I.b.xy, q3.xy)));
        if (dev2 <= 0.81 * f->tol * f->tol) {
            if ((st = emit(f, &I.a, &I.b))) return st;
            continue;
        }
        if (I.depth < MAXDEPTH && can_split) goto split;
        double cx = I.b.xy[0] - I.a.xy[0], cy = I.b.xy[1] - I.a.xy[1];
        if (cx * cx + cy * cy > (double)JUMP * JUMP * f->tol * f->tol) {
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

/* Sample [x, y] (inside one piece) as described at the top, continuing the polyline. */
static int sample_range(flat *f, double x, double y, int ninit) {
    fpt pa, pb;
    int st = point(f, x, &pa);
    if (st) return st;
    for (int q = 1; q <= ninit; q++) {
        double t = q == ninit ? y : x + (y - x) * q / ninit;
        if (!(t > pa.t)) continue;
        if ((st = point(f, t, &pb)) || (st = subdivide(f, &pa, &pb))) return st;
        pa = pb;
    }
    return PC_OK;
}

static int check_args(const pc_curve *c, double a, double b, double tol, pc_polyline *out) {
    if (!c || !out) return PC_EARG;
    if (!isfinite(a) || !isfinite(b) || !isfinite(tol)) return PC_ENONFINITE;
    if (!(a <= b) || !(tol > 0)) return PC_EDOMAIN;
    return PC_OK;
}

/* a == b: the one point, if it has an image */
static int single_point(flat *f, double a) {
    fpt pa;
    int st = point(f, a, &pa);
    if (st || pa.bad) return st;
    return pc_polyline_push(f->out, pa.xy[0], pa.xy[1], 1);
}

int pc_curve_flatten(const pc_curve *c, double a, double b, pc_project_fn proj, void *ud,
                     double tol, pc_polyline *out) {
    int st = check_args(c, a, b, tol, out);
    if (st) return st;
    if (!proj && c->dim != 2) return PC_EDIM;
    flat f = {c, proj, ud, tol, out, 1};
    if (a == b) return single_point(&f, a);
    int ninit = c->kind == PC_CURVE_FUNC && c->nknots == 0 ? NINIT_FUNC : NINIT;
    for (double x = a; x < b;) {
        double y = pcc_next_break(c, x, b);
        if ((st = sample_range(&f, x, y, ninit))) return st;
        x = y;
    }
    return PC_OK;
}

/* ---- polynomial and rational pieces through a map: the control polygon -----------------------
 * A projective map keeps a (rational) Bezier piece a rational Bezier piece of the plane, its
 * control points mapped.  When their weights have one sign the piece lies in the convex hull of
 * its Cartesian control points, so once the inner ones are within tol of the chord, so is the
 * piece: the chord is accepted.  Otherwise the piece is halved by de Casteljau, which costs less
 * than evaluating points and never misses a wiggle.  A piece whose weights change sign passes
 * through infinity and is sampled as above. */

enum { HULLDEPTH = 24 };

static int map_proj(void *ud, const double *h, double xy[2]) {
    const pc_map *m = ud;
    double o[3];
    pc_map_apply(m, h, o);
    if (o[2] == 0) return PC_IMPROPER;
    xy[0] = o[0] / o[2];
    xy[1] = o[1] / o[2];
    return isfinite(xy[0]) && isfinite(xy[1]) ? PC_OK : PC_ENONFINITE;
}

/* b (q+1 rows of 3) cut at s: left and right (either may be NULL) */
static void split3(int q, const double *b, double s, double *left, double *right) {
    double tmp[PCC_ROWS * 3];
    memcpy(tmp, b, sizeof(double) * 3 * (size_t)(q + 1));
    for (int c = 0; c < 3; c++) {
        if (left) left[c] = tmp[c];
        if (right) right[3 * q + c] = tmp[3 * q + c];
    }
    for (int r = 1; r <= q; r++) {
        for (int j = 0; j + r <= q; j++)
            for (int c = 0; c < 3; c++)
                tmp[3 * j + c] = tmp[3 * j + c] + s * (tmp[3 * (j + 1) + c] - tmp[3 * j + c]);
        for (int c = 0; c < 3; c++) {
            if (left) left[3 * r + c] = tmp[c];
            if (right) right[3 * (q - r) + c] = tmp[3 * (q - r) + c];
        }
    }
}

static int push_xy(flat *f, double x, double y) {
    if (f->pen_up) {
        f->pen_up = 0;
        return pc_polyline_push(f->out, x, y, 1);
    }
    const double *last = f->out->xy + 2 * (f->out->n - 1);
    if (last[0] == x && last[1] == y) return PC_OK;
    return pc_polyline_push(f->out, x, y, 0);
}

/* Whether the control polygon n (q+1 rows of 3, weights of one sign) lies outside the box. */
static int outside_clip(const double *box, int q, const double *n) {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int j = 0; j <= q; j++)
        for (int k = 0; k < 2; k++) {
            double v = n[3 * j + k] / n[3 * j + 2];
            lo[k] = fmin(lo[k], v);
            hi[k] = fmax(hi[k], v);
        }
    return hi[0] < box[0] || lo[0] > box[2] || hi[1] < box[1] || lo[1] > box[3];
}

/* the planar piece b (q+1 rows of 3, weights of one sign) flattened from its start */
static int hull_flatten(flat *f, int q, const double *b) {
    size_t rows = (size_t)(q + 1) * 3;
    double *stack = malloc(sizeof(double) * rows * (HULLDEPTH + 2));
    int depth[HULLDEPTH + 2], top = 0, st;
    if (!stack) return PC_ENOMEM;
    memcpy(stack, b, sizeof(double) * rows);
    depth[0] = 0;
    top = 1;
    if ((st = push_xy(f, b[0] / b[2], b[1] / b[2]))) goto done;
    double tol2 = f->tol * f->tol;
    while (top > 0) {
        double *n = stack + rows * (size_t)(top - 1);
        double a[2] = {n[0] / n[2], n[1] / n[2]}, e[2] = {n[3 * q] / n[3 * q + 2], n[3 * q + 1] / n[3 * q + 2]};
        int flat_enough = 1;
        for (int j = 1; j < q && flat_enough; j++) {
            double p[2] = {n[3 * j] / n[3 * j + 2], n[3 * j + 1] / n[3 * j + 2]};
            flat_enough = seg_dist2(a, e, p) <= tol2;
        }
        int d = depth[top - 1];
        if (!flat_enough && f->out->clip && outside_clip(f->out->clip, q, n)) {
            top--;   /* invisible: move past it */
            f->pen_up = 1;
            if ((st = push_xy(f, e[0], e[1]))) goto done;
            continue;
        }
        if (flat_enough || d >= HULLDEPTH || !isfinite(a[0] + a[1] + e[0] + e[1])) {
            top--;
            if ((st = push_xy(f, e[0], e[1]))) goto done;
            continue;
        }
        /* replace the node by its right half, push its left half above it */
        double *left = stack + rows * (size_t)top;
        split3(q, n, 0.5, left, n);
        depth[top - 1] = depth[top] = d + 1;
        top++;
    }
done:
    free(stack);
    return st;
}

int pc_curve_flatten_map(const pc_curve *c, double a, double b, const pc_map *m, double tol,
                         pc_polyline *out) {
    int st = check_args(c, a, b, tol, out);
    if (st) return st;
    if (m ? (m->nin != c->dim || m->nout != 2) : c->dim != 2) return PC_EDIM;
    flat f = {c, m ? map_proj : NULL, (void *)m, tol, out, 1};
    if (a == b) return single_point(&f, a);
    if (c->kind == PC_CURVE_FUNC) return pc_curve_flatten(c, a, b, f.proj, f.ud, tol, out);
    int q = c->degree, w = c->dim + 1;
    double piece[PCC_ROWS * PCC_W], pl[PCC_ROWS * 3], part[PCC_ROWS * 3];
    for (double x = a; x < b;) {
        double y = pcc_next_break(c, x, b);
        int k = pcc_piece(c, x + (y - x) / 2);
        double lo = c->knots[k], hi = c->knots[k + 1];   /* the piece's own interval */
        pcc_bezier_piece(c, k, piece);
        for (int j = 0; j <= q; j++) {
            if (m) {
                pc_map_apply(m, piece + (size_t)j * w, pl + 3 * j);
            } else {
                pl[3 * j] = piece[(size_t)j * w];
                pl[3 * j + 1] = piece[(size_t)j * w + 1];
                pl[3 * j + 2] = piece[(size_t)j * w + 2];
            }
        }
        /* the part over [x, y] in the piece's own parameter */
        double s0 = (x - lo) / (hi - lo), s1 = (y - lo) / (hi - lo);
        if (s1 != 0 && (s0 != 0 || s1 != 1)) {
            split3(q, pl, s1, part, NULL);
            split3(q, part, s0 / s1, NULL, pl);
        } else if (s1 == 0) {            /* extrapolated before the piece: s0 < s1 = 0 < 1 */
            split3(q, pl, s0, NULL, part);
            split3(q, part, (s1 - s0) / (1 - s0), pl, NULL);
        }
        int pos = 0, neg = 0;
        for (int j = 0; j <= q; j++) {
            pos += pl[3 * j + 2] > 0;
            neg += pl[3 * j + 2] < 0;
        }
        if (neg == q + 1)
            for (int j = 0; j < 3 * (q + 1); j++) pl[j] = -pl[j];
        if ((pos == q + 1 || neg == q + 1) && pcc_finite((size_t)3 * (q + 1), pl))
            st = hull_flatten(&f, q, pl);
        else
            st = sample_range(&f, x, y, NINIT);
        if (st) return st;
        x = y;
    }
    return PC_OK;
}
