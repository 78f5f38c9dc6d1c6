/* Engineering-drawing furniture (furniture.h): each piece is built on the screen, where its
 * sizes are, and drawn through the ordinary statements (pc_path, pc_fill_path, pc_line,
 * pc_text) after mapping its points back to world coordinates, so the display list and every
 * writer see only ops they know. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "canvas_internal.h"
#include "furniture.h"
#include "axes.h"
#include "layout.h"

#define PI 3.14159265358979323846

typedef struct { double x, y; } v2;

static v2 add(v2 a, v2 b) { return (v2){a.x + b.x, a.y + b.y}; }
static v2 sub(v2 a, v2 b) { return (v2){a.x - b.x, a.y - b.y}; }
static v2 mul(v2 a, double k) { return (v2){a.x * k, a.y * k}; }
static double len2(v2 a) { return hypot(a.x, a.y); }

static v2 scr(const pc_canvas *c, double x, double y) {
    v2 s;
    pc_world_to_screen(c, x, y, &s.x, &s.y);
    return s;
}

static int finite_pts(pc_canvas *c, const char *stmt, int n, const double *v) {
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i])) return pc_fail(c, "%s: coordinates must be finite numbers", stmt);
    return PC_OK;
}

/* A path through n screen points (mapped back to world coordinates for the statement). */
static int spath(pc_canvas *c, int n, const v2 *p, int closed, int filled, int color) {
    double xy[2 * 64];
    if (n > 64) return pc_fail(c, "furniture: too many points");
    for (int i = 0; i < n; i++) pc_screen_to_world(c, p[i].x, p[i].y, &xy[2 * i], &xy[2 * i + 1]);
    if (filled) return pc_fill_path(c, (size_t)n, xy, NULL, 0, PC_FILL_NONZERO, color);
    return pc_path(c, (size_t)n, xy, NULL, 0, closed, color);
}

static int sline(pc_canvas *c, v2 a, v2 b, int color) { return spath(c, 2, (v2[]){a, b}, 0, 0, color); }

/* The paths drawn since op `from` are pixel-sized round `at` (PC_OP_RIGID): framing moves
 * them with their anchor and keeps their size.  Passes st through. */
static int rigid(pc_canvas *c, size_t from, v2 at, int st) {
    for (size_t i = from; st == PC_OK && i < c->nops; i++) {
        pc_op *op = &c->ops[i];
        if (op->kind != PC_OP_PATH && op->kind != PC_OP_FILLPATH) continue;
        op->flags |= PC_OP_RIGID;
        op->x1 = at.x;
        op->y1 = at.y;
    }
    return st;
}

/* The side of a point that a label pointing along screen direction d takes. */
static int anchor_toward(v2 d) {
    double a = atan2(-d.y, d.x);   /* counter-clockwise from east, as seen */
    int k = (int)lrint(a / (PI / 4));
    static const int side[8] = {PC_ANCHOR_E, PC_ANCHOR_NE, PC_ANCHOR_N, PC_ANCHOR_NW,
                                PC_ANCHOR_W, PC_ANCHOR_SW, PC_ANCHOR_S, PC_ANCHOR_SE};
    return side[((k % 8) + 8) % 8];
}

static int stext(pc_canvas *c, v2 p, const char *text, int anchor, int color) {
    double wx, wy;
    pc_screen_to_world(c, p.x, p.y, &wx, &wy);
    return pc_text(c, wx, wy, text, anchor, 3, 1, color);
}

/* ---- furniture deferred to the frame ------------------------------------------------------ */

/* In a figure framed when written, the pixels between two world points are not known at the
 * call: a dimension's offset, an angle mark's text distance, a centre line's overshoot and
 * dashes, a hatch's spacing would all scale with the frame.  The call is kept with its points'
 * pixels of the moment (the figure's mirror of the world) and drawn once framed. */
enum { DEF_DIMENSION, DEF_ANGLE, DEF_CENTRE, DEF_HATCH, DEF_LEGEND, DEF_AXES };
struct pc_deferred {
    int kind, color, pen;
    size_t at;          /* the number of ops when it was called: its place in the drawing order */
    double v[8];        /* its points in pixels, then its sizes */
    char *text;         /* its text, the measured value formatted at the call (owned); a
                           legend's names, one after another with their NULs */
    double *xy; size_t n;   /* a hatch's region in pixels (owned); a legend's colours */
    pc_axes_spec *axes;     /* axes' spec in world units (owned); v: the view's origin then */
};

static int deferring(const pc_canvas *c) { return pc_figure_frames(c); }

static int defer(pc_canvas *c, struct pc_deferred d, const char *text) {
    if (!pc_grow((void **)&c->deferred, &c->capdeferred, c->ndeferred + 1, sizeof *c->deferred)) {
        free(d.xy);
        return pc_fail_code(c, PC_ENOMEM, "furniture: out of memory");
    }
    if (text) {
        size_t n = strlen(text);
        if (!(d.text = malloc(n + 1))) {
            free(d.xy);
            return pc_fail_code(c, PC_ENOMEM, "furniture: out of memory");
        }
        memcpy(d.text, text, n + 1);
    }
    d.at = c->nops;
    d.pen = c->pen;
    c->deferred[c->ndeferred++] = d;
    return PC_OK;
}

void pc_furniture_forget(pc_canvas *c) {
    if (!c->deferred_borrowed) {
        for (size_t i = 0; i < c->ndeferred; i++)
            free(c->deferred[i].text), free(c->deferred[i].xy), free(c->deferred[i].axes);
        free(c->deferred);
    }
    c->deferred = NULL;
    c->ndeferred = c->capdeferred = 0;
}

void pc_furniture_extent(const pc_canvas *c, pc_extent_fn put, void *ctx) {
    for (size_t i = 0; i < c->ndeferred; i++) {
        const struct pc_deferred *d = &c->deferred[i];
        if (d->kind == DEF_LEGEND) continue;   /* in device units: no part of the frame */
        if (d->kind == DEF_AXES) {   /* the corners of its ranges, in the pixels of the call */
            const pc_axes_spec *a = d->axes;
            double w = 0, h = 0;   /* room for the tick labels: below x's, left of y's */
            if (a->labels) {
                char buf[64];
                for (int k = 0; k < 4; k++) {
                    double tw, th, val = k == 0 ? a->x0 : k == 1 ? a->x1 : k == 2 ? a->y0 : a->y1;
                    snprintf(buf, sizeof buf, "%g", val);
                    if (pc_text_measure(c, buf, strlen(buf), 1, &tw, &th) != PC_OK) continue;
                    w = fmax(w, tw + 5), h = fmax(h, th + 5);
                }
            }
            put(ctx, a->x0 + d->v[0], -a->y0 + d->v[1], -w, 0, 0, h);
            put(ctx, a->x1 + d->v[0], -a->y1 + d->v[1], 0, 0, 0, 0);
            put(ctx, a->x1 + d->v[0], -a->y0 + d->v[1], 0, 0, w / 2, h);
            put(ctx, a->x0 + d->v[0], -a->y1 + d->v[1], -w, -h / 2, 0, 0);
            continue;
        }
        int np = d->kind == DEF_ANGLE ? 3 : d->kind == DEF_HATCH ? 0 : 2;
        for (int k = 0; k < np; k++) put(ctx, d->v[2 * k], d->v[2 * k + 1], 0, 0, 0, 0);
        for (size_t k = 0; k < d->n; k++) put(ctx, d->xy[2 * k], d->xy[2 * k + 1], 0, 0, 0, 0);
    }
}

/* Axes drawn through a window that puts the world where the frame put the figure's mirror of
 * it (canvas.c: sx = x + view.x0, sy = view.y0 - y at the call), in the view being drawn: its
 * tick labels keep the world's numbers, its ticks and heads their pixels. */
static int expand_axes(pc_canvas *c, const struct pc_deferred *d, double sx, double sy, double tx,
                       double ty) {
    pc_rect V = c->view;
    if (!(sx > 0 && sy > 0) || V.x1 <= V.x0 || V.y1 <= V.y0) return PC_OK;   /* nothing to draw in */
    int hw = c->has_window, ws = c->window_screen;
    double w1 = c->wx1, w2 = c->wx2, h1 = c->wy1, h2 = c->wy2;
    c->wx1 = (V.x0 - tx) / sx - d->v[0];
    c->wx2 = c->wx1 + (V.x1 - V.x0) / sx;
    c->wy2 = d->v[1] - (V.y0 - ty) / sy;
    c->wy1 = c->wy2 - (V.y1 - V.y0) / sy;
    c->has_window = 1;
    c->window_screen = 0;
    int st = pc_axes(c, d->axes, d->color, NULL);
    c->has_window = hw;
    c->window_screen = ws;
    c->wx1 = w1, c->wx2 = w2, c->wy1 = h1, c->wy2 = h2;
    return st;
}

int pc_furniture_defer_axes(pc_canvas *c, const pc_axes_spec *a, int color, int *nticks, int *st) {
    if (!deferring(c)) return 0;
    int count = 0;
    for (int axis = 0; axis < 2 && a->ticks > 0; axis++) {
        double first, step;
        int n;
        if (pc_nice_ticks(axis ? a->y0 : a->x0, axis ? a->y1 : a->x1, a->ticks, &first, &step, &n) != PC_OK) {
            *st = pc_fail(c, "axes: too many ticks");
            return 1;
        }
        count += n;
    }
    pc_axes_spec *copy = malloc(sizeof *copy);
    if (!copy) {
        *st = pc_fail_code(c, PC_ENOMEM, "axes: out of memory");
        return 1;
    }
    *copy = *a;
    double ox, oy;   /* the view's origin of the call: the figure's mirror is x + ox, oy - y */
    pc_world_to_screen(c, 0, 0, &ox, &oy);
    *st = defer(c, (struct pc_deferred){.kind = DEF_AXES, .color = color, .v = {ox, oy}, .axes = copy}, NULL);
    if (*st != PC_OK) free(copy);
    if (nticks) *nticks = count;
    return 1;
}

int pc_furniture_expand(pc_canvas *c, size_t at, int all, double sx, double sy, double tx, double ty) {
    int st = PC_OK, pen = c->pen;
    for (size_t i = 0; i < c->ndeferred && st == PC_OK; i++) {
        const struct pc_deferred *d = &c->deferred[i];
        if (all ? d->at < at : d->at != at) continue;
        double p[6];
        for (int k = 0; k < 3; k++) p[2 * k] = sx * d->v[2 * k] + tx, p[2 * k + 1] = sy * d->v[2 * k + 1] + ty;
        double wp[6];   /* the points in the canvas's world as it is now (pixels once framed) */
        for (int k = 0; k < 3; k++) pc_screen_to_world(c, p[2 * k], p[2 * k + 1], &wp[2 * k], &wp[2 * k + 1]);
        c->pen = d->pen < (int)c->npens ? d->pen : 0;
        switch (d->kind) {
        case DEF_DIMENSION:
            st = pc_dimension(c, wp[0], wp[1], wp[2], wp[3], d->v[4], d->text, d->color, NULL);
            break;
        case DEF_ANGLE:
            st = pc_angle_mark(c, wp[0], wp[1], wp[2], wp[3], wp[4], wp[5], d->v[6], d->text, d->color, NULL);
            break;
        case DEF_CENTRE:
            st = pc_centre_line(c, wp[0], wp[1], wp[2], wp[3], d->v[4], d->color);
            break;
        case DEF_HATCH: {
            double *w = malloc(2 * d->n * sizeof *w);
            if (!w) { st = pc_fail_code(c, PC_ENOMEM, "hatch: out of memory"); break; }
            for (size_t k = 0; k < d->n; k++)
                pc_screen_to_world(c, sx * d->xy[2 * k] + tx, sy * d->xy[2 * k + 1] + ty, &w[2 * k], &w[2 * k + 1]);
            st = pc_hatch(c, d->n, w, d->v[0], d->v[1], d->color, NULL);
            free(w);
            break;
        }
        case DEF_AXES:
            st = expand_axes(c, d, sx, sy, tx, ty);
            break;
        case DEF_LEGEND: {
            const char *names[100];
            int colors[100];
            const char *q = d->text;
            for (size_t k = 0; k < d->n && k < 100; k++) {
                names[k] = q;
                q += strlen(q) + 1;
                colors[k] = (int)d->xy[k];
            }
            st = pc_legend(c, (int)d->n, names, colors, (int)d->v[0], d->color);
            break;
        }
        default: break;
        }
    }
    c->pen = pen;
    return st;
}

int pc_furniture_defer_legend(pc_canvas *c, int n, const char *const *names, const int *colors,
                              int corner, int color, int *st) {
    if (!deferring(c)) return 0;
    size_t len = 0;
    for (int i = 0; i < n; i++) len += strlen(names[i]) + 1;
    char *t = malloc(len ? len : 1);
    double *cs = malloc((size_t)n * sizeof *cs);
    if (!t || !cs) {
        free(t);
        free(cs);
        *st = pc_fail_code(c, PC_ENOMEM, "legend: out of memory");
        return 1;
    }
    char *q = t;
    for (int i = 0; i < n; i++) {
        size_t k = strlen(names[i]) + 1;
        memcpy(q, names[i], k);
        q += k;
        cs[i] = colors[i];
    }
    *st = defer(c, (struct pc_deferred){.kind = DEF_LEGEND, .color = color, .v = {corner},
                                        .xy = cs, .n = (size_t)n}, NULL);
    if (*st == PC_OK) c->deferred[c->ndeferred - 1].text = t;
    else free(t);
    return 1;
}

/* ---- markers and arrows -------------------------------------------------------------------- */

static int mark_shape(pc_canvas *c, v2 o, int style, double size, int color);

int pc_mark(pc_canvas *c, double x, double y, int style, double size, int color) {
    if (finite_pts(c, "mark", 2, (double[]){x, y}) != PC_OK) return PC_EARG;
    if (!(size >= 1 && size <= 200)) return pc_fail(c, "mark: size must be 1..200 pixels, got %g", size);
    v2 o = scr(c, x, y);
    size_t from = c->nops;
    return rigid(c, from, o, mark_shape(c, o, style, size, color));
}

static int mark_shape(pc_canvas *c, v2 o, int style, double size, int color) {
    v2 p[32];
    double r = size / 2;
    switch (style) {
    case PC_MARK_DOT: case PC_MARK_OPEN:
        for (int i = 0; i < 32; i++)
            p[i] = add(o, (v2){r * cos(2 * PI * i / 32), r * sin(2 * PI * i / 32)});
        return spath(c, 32, p, 1, style == PC_MARK_DOT, color);
    case PC_MARK_SQUARE:
        p[0] = add(o, (v2){-r, -r}); p[1] = add(o, (v2){r, -r});
        p[2] = add(o, (v2){r, r}); p[3] = add(o, (v2){-r, r});
        return spath(c, 4, p, 1, 0, color);
    case PC_MARK_CROSS: case PC_MARK_PLUS: {
        double k = style == PC_MARK_CROSS ? r * sqrt(0.5) : r;
        v2 a = style == PC_MARK_CROSS ? (v2){k, k} : (v2){r, 0};
        v2 b = style == PC_MARK_CROSS ? (v2){k, -k} : (v2){0, r};
        int st = sline(c, sub(o, a), add(o, a), color);
        return st == PC_OK ? sline(c, sub(o, b), add(o, b), color) : st;
    }
    default:
        return pc_fail(c, "mark: unknown style %d", style);
    }
}

int pc_arrow_head(pc_canvas *c, double x1, double y1, double x2, double y2, double len, int color) {
    if (finite_pts(c, "arrow", 4, (double[]){x1, y1, x2, y2}) != PC_OK) return PC_EARG;
    if (!(len >= 1 && len <= 200)) return pc_fail(c, "arrow: head length must be 1..200 pixels, got %g", len);
    v2 a = scr(c, x1, y1), t = scr(c, x2, y2), d = sub(t, a);
    double l = len2(d);
    if (!(l > 0)) return pc_fail(c, "arrow: the two points coincide: no direction for the head");
    v2 u = mul(d, 1 / l), n = {-u.y, u.x}, base = sub(t, mul(u, len));
    size_t from = c->nops;
    return rigid(c, from, t, spath(c, 3, (v2[]){t, add(base, mul(n, 0.3 * len)), sub(base, mul(n, 0.3 * len))},
                                   1, 1, color));
}

int pc_arrow(pc_canvas *c, double x1, double y1, double x2, double y2, int heads, double len,
             int color) {
    if (finite_pts(c, "arrow", 4, (double[]){x1, y1, x2, y2}) != PC_OK) return PC_EARG;
    if (heads < 0 || heads > 3) return pc_fail(c, "arrow: heads must be 0..3, got %d", heads);
    v2 a = scr(c, x1, y1), b = scr(c, x2, y2), d = sub(b, a);
    double l = len2(d);
    if (!(l > 0) && heads) return pc_fail(c, "arrow: the two points coincide: no direction for the head");
    v2 u = l > 0 ? mul(d, 1 / l) : (v2){0, 0};
    /* the shaft stops inside the head (at two thirds of it) so no pen blunts the tip; not in
     * a figure framed when written, whose pixels are not known yet (the head is rigid) */
    double back = pc_figure_frames(c) ? 0 : fmin(len * 0.66, l / 2);
    v2 s0 = heads & PC_ARROW_START ? add(a, mul(u, back)) : a;
    v2 s1 = heads & PC_ARROW_END ? sub(b, mul(u, back)) : b;
    int st = sline(c, s0, s1, color);
    if (st == PC_OK && (heads & PC_ARROW_END)) st = pc_arrow_head(c, x1, y1, x2, y2, len, color);
    if (st == PC_OK && (heads & PC_ARROW_START)) st = pc_arrow_head(c, x2, y2, x1, y1, len, color);
    return st;
}

/* ---- dimensions and angles ------------------------------------------------------------------ */

int pc_dimension(pc_canvas *c, double ax, double ay, double bx, double by, double offset,
                 const char *text, int color, double *length) {
    if (finite_pts(c, "dimension", 5, (double[]){ax, ay, bx, by, offset}) != PC_OK) return PC_EARG;
    v2 a = scr(c, ax, ay), b = scr(c, bx, by), d = sub(b, a);
    double l = len2(d), world = hypot(bx - ax, by - ay);
    if (!(l > 0)) return pc_fail(c, "dimension: the two points coincide: nothing to measure");
    if (fabs(offset) > 1e5) return pc_fail(c, "dimension: offset must be within 1e5 pixels, got %g", offset);
    v2 u = mul(d, 1 / l), n = {u.y, -u.x};   /* the left of A->B as seen (y is down) */
    double side = offset < 0 ? -1 : 1, gap = 2, over = 3;
    v2 a1 = add(a, mul(n, offset)), b1 = add(b, mul(n, offset));
    char buf[64];
    if (!text) {
        snprintf(buf, sizeof buf, "%.4g", world);
        text = buf;
    }
    if (length) *length = world;
    if (deferring(c))   /* offset and arrows in pixels of the frame: drawn once it is known */
        return defer(c, (struct pc_deferred){.kind = DEF_DIMENSION, .color = color,
                                             .v = {a.x, a.y, b.x, b.y, offset}}, text);
    int st = PC_OK;
    if (fabs(offset) > gap) {   /* extension lines, from a gap off the object to past the line */
        st = sline(c, add(a, mul(n, side * gap)), add(a1, mul(n, side * over)), color);
        if (st == PC_OK) st = sline(c, add(b, mul(n, side * gap)), add(b1, mul(n, side * over)), color);
    }
    double wa, wb, wc, wd;
    pc_screen_to_world(c, a1.x, a1.y, &wa, &wb);
    pc_screen_to_world(c, b1.x, b1.y, &wc, &wd);
    if (st == PC_OK) st = pc_arrow(c, wa, wb, wc, wd, PC_ARROW_BOTH, fmin(8, l / 3), color);
    v2 mid = mul(add(a1, b1), 0.5), out = offset == 0 ? n : mul(n, side);
    if (st == PC_OK) st = stext(c, mid, text, anchor_toward(out), color);
    return st;
}

int pc_angle_mark(pc_canvas *c, double ax, double ay, double ox, double oy, double bx, double by,
                  double r, const char *text, int color, double *angle) {
    if (finite_pts(c, "angle_mark", 7, (double[]){ax, ay, ox, oy, bx, by, r}) != PC_OK) return PC_EARG;
    if (!(r >= 2 && r <= 1000)) return pc_fail(c, "angle_mark: radius must be 2..1000 pixels, got %g", r);
    double wa = hypot(ax - ox, ay - oy), wb = hypot(bx - ox, by - oy);
    v2 o = scr(c, ox, oy), da = sub(scr(c, ax, ay), o), db = sub(scr(c, bx, by), o);
    if (!(wa > 0 && wb > 0 && len2(da) > 0 && len2(db) > 0))
        return pc_fail(c, "angle_mark: a side has no length (A or B is the vertex O)");
    /* the angle in world units, from the cross and dot products (exact near 0 and pi) */
    double cr = (ax - ox) * (by - oy) - (ay - oy) * (bx - ox), dt = (ax - ox) * (bx - ox) + (ay - oy) * (by - oy);
    double th = atan2(fabs(cr), dt);
    v2 u = mul(da, 1 / len2(da)), v = mul(db, 1 / len2(db));
    if (angle) *angle = th;
    char buf[64];
    if (!text) {
        snprintf(buf, sizeof buf, "%.4g\xc2\xb0", th * 180 / PI);
        text = buf;
    }
    if (deferring(c)) {   /* its text r + 2 px off the vertex, its square: in the frame's pixels */
        v2 a = add(o, da), b = add(o, db);
        return defer(c, (struct pc_deferred){.kind = DEF_ANGLE, .color = color,
                                             .v = {a.x, a.y, o.x, o.y, b.x, b.y, r}}, text);
    }
    int st;
    size_t from = c->nops;
    if (fabs(th - PI / 2) < 1e-9) {   /* the right-angle square, its side 0.7 r */
        double s = 0.7 * r;
        st = spath(c, 3, (v2[]){add(o, mul(u, s)), add(o, add(mul(u, s), mul(v, s))), add(o, mul(v, s))},
                   0, 0, color);
    } else {   /* the arc the short way round on the screen */
        double a0 = atan2(u.y, u.x), sweep = atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y);
        int m = (int)fmin(63, fmax(8, fabs(sweep) * r / 3));
        v2 p[64];
        for (int i = 0; i <= m; i++) {
            double t = a0 + sweep * i / m;
            p[i] = add(o, (v2){r * cos(t), r * sin(t)});
        }
        st = spath(c, m + 1, p, 0, 0, color);
    }
    st = rigid(c, from, o, st);
    v2 w = add(u, v);
    if (len2(w) < 1e-9) w = (v2){-u.y, u.x};
    w = mul(w, 1 / len2(w));
    if (st == PC_OK && *text) st = stext(c, add(o, mul(w, r + 2)), text, anchor_toward(w), color);
    return st;
}

int pc_ticks(pc_canvas *c, double ax, double ay, double bx, double by, int n, double size,
             int color) {
    if (finite_pts(c, "ticks", 4, (double[]){ax, ay, bx, by}) != PC_OK) return PC_EARG;
    if (n < 1 || n > 5) return pc_fail(c, "ticks: the number of ticks must be 1..5, got %d", n);
    if (!(size >= 1 && size <= 200)) return pc_fail(c, "ticks: size must be 1..200 pixels, got %g", size);
    v2 a = scr(c, ax, ay), b = scr(c, bx, by), d = sub(b, a);
    double l = len2(d);
    if (!(l > 0)) return pc_fail(c, "ticks: the two points coincide: no segment to mark");
    v2 u = mul(d, 1 / l), nrm = {-u.y, u.x}, m = mul(add(a, b), 0.5);
    int st = PC_OK;
    size_t from = c->nops;
    for (int i = 0; i < n && st == PC_OK; i++) {
        v2 q = add(m, mul(u, 3.0 * (i - (n - 1) / 2.0)));
        st = sline(c, sub(q, mul(nrm, size / 2)), add(q, mul(nrm, size / 2)), color);
    }
    return rigid(c, from, m, st);
}

/* ---- hatching and centre lines ------------------------------------------------------------- */

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int pc_hatch(pc_canvas *c, size_t n, const double *xy, double spacing, double angle, int color,
             size_t *nlines) {
    if (n < 3) return pc_fail(c, "hatch: a region needs at least 3 points, got %zu", n);
    if (!(spacing >= 1 && spacing <= 1e4)) return pc_fail(c, "hatch: spacing must be 1..1e4 pixels, got %g", spacing);
    if (!isfinite(angle)) return pc_fail(c, "hatch: the angle must be a finite number of degrees");
    for (size_t i = 0; i < 2 * n; i++)
        if (!isfinite(xy[i])) return pc_fail(c, "hatch: coordinates must be finite numbers");
    if (deferring(c)) {   /* the spacing is in pixels of the frame: the region kept in today's */
        double *px = malloc(2 * n * sizeof *px);
        if (!px) return pc_fail_code(c, PC_ENOMEM, "hatch: out of memory");
        for (size_t i = 0; i < n; i++) pc_world_to_screen(c, xy[2 * i], xy[2 * i + 1], &px[2 * i], &px[2 * i + 1]);
        if (nlines) *nlines = 0;   /* not known till the frame is */
        return defer(c, (struct pc_deferred){.kind = DEF_HATCH, .color = color, .v = {spacing, angle},
                                             .xy = px, .n = n}, NULL);
    }
    double a = angle * PI / 180;
    v2 d = {cos(a), -sin(a)}, nr = {sin(a), cos(a)};   /* along the hatch (as seen), across it */
    v2 *p = malloc(n * sizeof *p);
    double *cuts = malloc(n * sizeof *cuts);
    if (!p || !cuts) {
        free(p);
        free(cuts);
        return pc_fail_code(c, PC_ENOMEM, "hatch: out of memory");
    }
    double t0 = INFINITY, t1 = -INFINITY;
    int st = PC_OK;
    for (size_t i = 0; i < n; i++) {
        if (!isfinite(xy[2 * i]) || !isfinite(xy[2 * i + 1])) st = pc_fail(c, "hatch: coordinates must be finite numbers");
        v2 s = scr(c, xy[2 * i], xy[2 * i + 1]);
        p[i] = (v2){s.x * d.x + s.y * d.y, s.x * nr.x + s.y * nr.y};   /* (along, across) */
        t0 = fmin(t0, p[i].y);
        t1 = fmax(t1, p[i].y);
    }
    size_t count = 0;
    if (st == PC_OK && t1 - t0 > 1e6 * spacing) st = pc_fail(c, "hatch: the region spans too many lines");
    /* lines at whole multiples of the spacing across: neighbouring regions' hatches line up */
    for (double k = ceil(t0 / spacing); st == PC_OK && k * spacing <= t1; k++) {
        double t = k * spacing;
        size_t m = 0;
        for (size_t i = 0; i < n; i++) {   /* edges cut half-open in t: a vertex counts once */
            v2 e0 = p[i], e1 = p[(i + 1) % n];
            if ((e0.y <= t) == (e1.y <= t)) continue;
            cuts[m++] = e0.x + (t - e0.y) * (e1.x - e0.x) / (e1.y - e0.y);
        }
        qsort(cuts, m, sizeof *cuts, cmp_double);
        for (size_t j = 0; j + 1 < m && st == PC_OK; j += 2) {
            v2 s0 = add(mul(d, cuts[j]), mul(nr, t)), s1 = add(mul(d, cuts[j + 1]), mul(nr, t));
            st = sline(c, s0, s1, color);
            count++;
        }
    }
    free(p);
    free(cuts);
    if (nlines) *nlines = count;
    return st;
}

int pc_centre_line(pc_canvas *c, double ax, double ay, double bx, double by, double extend,
                   int color) {
    if (finite_pts(c, "centre_line", 5, (double[]){ax, ay, bx, by, extend}) != PC_OK) return PC_EARG;
    v2 a = scr(c, ax, ay), b = scr(c, bx, by), d = sub(b, a);
    double l = len2(d);
    if (!(l > 0)) return pc_fail(c, "centre_line: the two points coincide: no direction");
    if (!(extend >= 0 && extend <= 1e5)) return pc_fail(c, "centre_line: extend must be 0..1e5 pixels, got %g", extend);
    if (deferring(c))   /* its overshoot and its dashes in pixels of the frame */
        return defer(c, (struct pc_deferred){.kind = DEF_CENTRE, .color = color,
                                             .v = {a.x, a.y, b.x, b.y, extend}}, NULL);
    v2 u = mul(d, 1 / l);
    pc_stroke old = c->pens[c->pen];
    double dash[4] = {12 * old.width, 3 * old.width, 2 * old.width, 3 * old.width};   /* ISO 128 type 04 */
    int st = pc_pen(c, old.width, dash, 4);
    if (st == PC_OK) st = sline(c, sub(a, mul(u, extend)), add(b, mul(u, extend)), color);
    int back = pc_pen(c, old.width, old.ndash ? old.dash : NULL, old.ndash);
    return st != PC_OK ? st : back;
}
