/* Framing what is drawn (layout.h: pc_drawn_extent, pc_fit).  The canvas rasterises as it
 * draws, so framing after the fact replays the display list through the framing map: every op
 * is drawn again, its points moved, its pixel sizes (pens, markers, text) kept, and the window
 * changes so that later drawing lands in the same frame. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "canvas_internal.h"
#include "font.h"
#include "layout.h"

/* An item of the extent: a point p, and the box [p + d0, p + d1] it needs round it (a text's
 * cell, which does not scale). */
typedef struct { double x, y, dx0, dy0, dx1, dy1; } item;
typedef struct { item *v; size_t n, cap; int nomem; } items;

static void put(items *it, double x, double y, double dx0, double dy0, double dx1, double dy1) {
    if (!isfinite(x) || !isfinite(y)) return;
    if (it->n == it->cap) {
        size_t cap = it->cap ? 2 * it->cap : 256;
        item *p = realloc(it->v, cap * sizeof *p);
        if (!p) { it->nomem = 1; return; }
        it->v = p;
        it->cap = cap;
    }
    it->v[it->n++] = (item){x, y, dx0, dy0, dx1, dy1};
}

static void put_cb(void *ctx, double x, double y, double dx0, double dy0, double dx1, double dy1) {
    put(ctx, x, y, dx0, dy0, dx1, dy1);
}

/* Everything drawn as items (CLEAR, the background, is not content), and what the attached
 * scene will draw when the picture is written (through the camera). */
static int gather(const pc_canvas *c, items *it) {
    if (c->attach_extent) {
        int st = c->attach_extent(c->attach, c, put_cb, it);
        if (st != PC_OK) return st;
    }
    pc_furniture_extent(c, put_cb, it);   /* furniture to be drawn once framed: its points */
    for (size_t i = 0; i < c->nops; i++) {
        const pc_op *op = &c->ops[i];
        switch (op->kind) {
        case PC_OP_DOTS:
            for (uint32_t k = 0; k < op->count; k++) put(it, c->dots[op->first + k].x, c->dots[op->first + k].y, 0, 0, 0, 0);
            break;
        case PC_OP_PIXELS:
            for (uint32_t k = 0; k < op->count; k++) {
                uint32_t idx = c->lpx[op->first + k].idx;
                put(it, idx % (uint32_t)c->width, idx / (uint32_t)c->width, 0, 0, 0, 0);
            }
            break;
        case PC_OP_LINE: case PC_OP_BOX: case PC_OP_FILLBOX:
            put(it, op->x1, op->y1, 0, 0, 0, 0);
            put(it, op->x2, op->y2, 0, 0, 0, 0);
            break;
        case PC_OP_ARC:
            put(it, op->x1 - op->rx, op->y1 - op->ry, 0, 0, 0, 0);
            put(it, op->x1 + op->rx, op->y1 + op->ry, 0, 0, 0, 0);
            break;
        case PC_OP_FILL:
            for (uint32_t k = 0; k < op->count; k++) {
                const pc_span *s = &c->spans[op->first + k];
                put(it, s->x0, s->y, 0, 0, 0, 0);
                put(it, s->x1, s->y, 0, 0, 0, 0);
            }
            break;
        case PC_OP_PATH: case PC_OP_FILLPATH:
            if (op->flags & PC_OP_RIGID) {   /* its size in pixels round the anchor */
                double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
                for (uint32_t k = 0; k < op->count; k++) {
                    double dx = c->pts[op->first + k].x - op->x1, dy = c->pts[op->first + k].y - op->y1;
                    x0 = fmin(x0, dx); y0 = fmin(y0, dy); x1 = fmax(x1, dx); y1 = fmax(y1, dy);
                }
                put(it, op->x1, op->y1, x0, y0, x1, y1);
                break;
            }
            for (uint32_t k = 0; k < op->count; k++) put(it, c->pts[op->first + k].x, c->pts[op->first + k].y, 0, 0, 0, 0);
            break;
        case PC_OP_TEXT: {
            double w, h, X = nearbyint(op->x2), Y = nearbyint(op->y2);
            if (op->flags & PC_TEXT_DEVICE) break;   /* not framed: it stays where it is */
            if (pc_text_measure(c, c->text + op->first, op->count, (int)op->rx, &w, &h) != PC_OK) break;
            if (op->flags & PC_TEXT_AUTO) {   /* not placed yet: room for it on any side */
                double gx = w + PC_FIT_LABEL_GAP, gy = h + PC_FIT_LABEL_GAP;
                put(it, op->x2, op->y2, -gx, -gy, gx, gy);
            } else {
                put(it, op->x2, op->y2, op->x1 - X, op->y1 - Y, op->x1 - X + w, op->y1 - Y + h);
            }
            break;
        }
        default: break;
        }
    }
    return it->nomem ? PC_ENOMEM : PC_OK;
}

int pc_drawn_extent(const pc_canvas *c, pc_box2 *out) {
    items it = {0};
    int st = gather(c, &it);
    if (st == PC_OK && it.n == 0) st = PC_EARG;
    if (st == PC_OK) {
        *out = (pc_box2){INFINITY, INFINITY, -INFINITY, -INFINITY};
        for (size_t i = 0; i < it.n; i++) {
            const item *p = &it.v[i];
            out->x0 = fmin(out->x0, p->x + p->dx0);
            out->y0 = fmin(out->y0, p->y + p->dy0);
            out->x1 = fmax(out->x1, p->x + p->dx1);
            out->y1 = fmax(out->y1, p->y + p->dy1);
        }
    }
    free(it.v);
    return st;
}

/* The width along axis a (0: x, 1: y) of everything under the scale s. */
static double width_at(const items *it, int a, double s, double *lo) {
    double mn = INFINITY, mx = -INFINITY;
    for (size_t i = 0; i < it->n; i++) {
        const item *p = &it->v[i];
        double q = s * (a ? p->y : p->x);
        mn = fmin(mn, q + (a ? p->dy0 : p->dx0));
        mx = fmax(mx, q + (a ? p->dy1 : p->dx1));
    }
    *lo = mn;
    return mx - mn;
}

/* The largest scale (up to cap) at which the width fits `room`: the width is convex in s
 * (a max of linear functions minus a min of them), so the scales that fit form an interval
 * from 0; bisection finds its end.  0 when even s = 0 does not fit. */
static double largest_scale(const items *it, int a, double room, double cap) {
    double lo;
    if (width_at(it, a, 0, &lo) > room) return 0;
    if (width_at(it, a, cap, &lo) <= room) return cap;
    double s0 = 0, s1 = cap;
    for (int k = 0; k < 100; k++) {
        double m = (s0 + s1) / 2;
        if (width_at(it, a, m, &lo) <= room) s0 = m;
        else s1 = m;
    }
    return s0;
}

/* ---- the replay --------------------------------------------------------------------------- */

typedef struct { double sx, sy, tx, ty; } frame;

static void fmap(const frame *f, double x, double y, double *ox, double *oy) {
    *ox = f->sx * x + f->tx;
    *oy = f->sy * y + f->ty;
}

/* The old display list, taken out of the canvas while it is drawn again. */
typedef struct {
    pc_op *ops; size_t nops;
    pc_xy *dots, *pts; uint8_t *tags; pc_span *spans; pc_lpx *lpx; pc_clip *clips; size_t nclips;
    char *text;
} old_list;

static int replay_op(pc_canvas *c, const old_list *o, const pc_op *op, const frame *f) {
    double a, b, d, e;
    c->pen = op->pen < c->npens ? op->pen : 0;
    switch (op->kind) {
    case PC_OP_CLEAR: {   /* the background of a view: where it was */
        pc_rect v = c->view;
        c->view = (pc_rect){(int)op->x1, (int)op->y1, (int)op->x2, (int)op->y2};
        int st = pc_fill_view(c, op->color);
        c->view = v;
        return st;
    }
    case PC_OP_DOTS:
        for (uint32_t k = 0; k < op->count; k++) {
            fmap(f, o->dots[op->first + k].x, o->dots[op->first + k].y, &a, &b);
            int st = pc_pset(c, a, b, op->color);
            if (st != PC_OK) return st;
        }
        return PC_OK;
    case PC_OP_PIXELS:
        for (uint32_t k = 0; k < op->count; k++) {
            uint32_t idx = o->lpx[op->first + k].idx;
            fmap(f, idx % (uint32_t)c->width, idx / (uint32_t)c->width, &a, &b);
            int st = pc_pset(c, a, b, o->lpx[op->first + k].color);
            if (st != PC_OK) return st;
        }
        return PC_OK;
    case PC_OP_LINE:
        fmap(f, op->x1, op->y1, &a, &b);
        fmap(f, op->x2, op->y2, &d, &e);
        return pc_line(c, a, b, d, e, op->color);
    case PC_OP_BOX: case PC_OP_FILLBOX:
        fmap(f, op->x1, op->y1, &a, &b);
        fmap(f, op->x2, op->y2, &d, &e);
        return pc_box(c, a, b, d, e, op->color, op->kind == PC_OP_FILLBOX);
    case PC_OP_ARC: {
        double rx = op->rx * f->sx, ry = op->ry * f->sy, r = fmax(rx, ry);
        double aspect = rx > 0 && ry != rx ? ry / rx : NAN;
        double s0 = op->flags & PC_ARC_FULL ? NAN : (op->flags & PC_ARC_RADIUS0 ? -op->a0 : op->a0);
        double s1 = op->flags & PC_ARC_FULL ? NAN : (op->flags & PC_ARC_RADIUS1 ? -op->a1 : op->a1);
        fmap(f, op->x1, op->y1, &a, &b);
        return pc_circle(c, a, b, r, op->color, s0, s1, aspect);
    }
    case PC_OP_FILL:   /* each painted run as the filled rectangle of its pixels */
        for (uint32_t k = 0; k < op->count; k++) {
            const pc_span *s = &o->spans[op->first + k];
            double q[8];
            fmap(f, s->x0 - 0.5, s->y - 0.5, &q[0], &q[1]);
            fmap(f, s->x1 + 0.5, s->y - 0.5, &q[2], &q[3]);
            fmap(f, s->x1 + 0.5, s->y + 0.5, &q[4], &q[5]);
            fmap(f, s->x0 - 0.5, s->y + 0.5, &q[6], &q[7]);
            int st = pc_fill_path(c, 4, q, NULL, 0, PC_FILL_NONZERO, op->color);
            if (st != PC_OK) return st;
        }
        return PC_OK;
    case PC_OP_PATH: case PC_OP_FILLPATH: {
        double *xy = malloc(2 * (size_t)op->count * sizeof *xy + 1);
        uint8_t *verbs = malloc((size_t)op->count + 1);
        if (!xy || !verbs) {
            free(xy);
            free(verbs);
            return pc_fail_code(c, PC_ENOMEM, "fit: out of memory");
        }
        size_t nv = 0;
        int rigid = op->flags & PC_OP_RIGID;
        double ax = 0, ay = 0;
        if (rigid) fmap(f, op->x1, op->y1, &ax, &ay);
        for (uint32_t k = 0; k < op->count; k++) {
            const pc_xy *q = &o->pts[op->first + k];
            if (rigid) {   /* moved with its anchor, its size kept */
                xy[2 * k] = ax + (q->x - op->x1);
                xy[2 * k + 1] = ay + (q->y - op->y1);
            } else {
                fmap(f, q->x, q->y, &xy[2 * k], &xy[2 * k + 1]);
            }
        }
        for (uint32_t k = 0; k < op->count; k += o->tags[op->first + k] == PC_PATH_CUBIC ? 3 : 1)
            verbs[nv++] = o->tags[op->first + k];   /* a cubic's three points are one verb */
        int st = op->kind == PC_OP_PATH
            ? pc_path(c, op->count, xy, verbs, nv, op->flags & PC_PATH_CLOSED, op->color)
            : pc_fill_path(c, op->count, xy, verbs, nv, op->flags & (1 | PC_FILL_TILE), op->color);
        free(xy);
        free(verbs);
        if (st == PC_OK && rigid) {   /* still rigid for a later framing */
            pc_op *t = &c->ops[c->nops - 1];
            t->flags |= PC_OP_RIGID;
            t->x1 = ax;
            t->y1 = ay;
        }
        return st;
    }
    case PC_OP_TEXT: {
        char *s = malloc((size_t)op->count + 1);
        if (!s) return pc_fail_code(c, PC_ENOMEM, "fit: out of memory");
        memcpy(s, o->text + op->first, op->count);
        s[op->count] = 0;
        int anchor = op->flags & PC_TEXT_ANCHOR, st;
        fmap(f, op->x2, op->y2, &a, &b);
        if (op->flags & PC_TEXT_DEVICE) a = op->x2, b = op->y2;   /* in device pixels: kept */
        if (op->flags & PC_TEXT_AUTO) {
            st = pc_text(c, a, b, s, PC_ANCHOR_AUTO, 0, (int)op->rx, op->color);
        } else {   /* the cell box keeps its offset from the point, in pixels */
            double X = nearbyint(op->x2), Y = nearbyint(op->y2);
            double left = nearbyint(a) + (op->x1 - X), top = nearbyint(b) + (op->y1 - Y);
            st = pc_text(c, left, top, s, PC_ANCHOR_SE, 0, (int)op->rx, op->color);
            if (st == PC_OK) {   /* drawn by its cell's corner; it remembers its point */
                pc_op *t = &c->ops[c->nops - 1];
                t->x2 = a;
                t->y2 = b;
                t->flags = (uint8_t)(anchor | (op->flags & PC_TEXT_DEVICE));
            }
        }
        free(s);
        if (st == PC_OK) c->ops[c->nops - 1].pen = op->pen;   /* its {font, size, halo} (pc_text_style) */
        return st;
    }
    default:
        return PC_OK;
    }
}

/* Draw the old list again through f.  The pixels are cleared to the paper first; each op is
 * drawn in its old VIEW moved by f. */
static int replay(pc_canvas *c, const frame *f) {
    old_list o = {c->ops, c->nops, c->dots, c->pts, c->tags, c->spans, c->lpx, c->clips,
                  c->nclips, c->text};
    pc_rect view = c->view;
    int vs = c->view_screen, has_window = c->has_window, pen = c->pen;
    c->ops = NULL; c->nops = c->capops = 0;
    c->dots = NULL; c->ndots = c->capdots = 0;
    c->pts = NULL; c->tags = NULL; c->npts = c->cappts = 0;
    c->spans = NULL; c->nspans = c->capspans = 0;
    c->lpx = NULL; c->nlpx = c->caplpx = 0;
    c->clips = NULL; c->nclips = c->capclips = 0;
    c->text = NULL; c->ntext = c->captext = 0;
    c->fold_mark = 0;
    pc_fill_px(c->pixels, c->paper, (size_t)c->width * c->height);
    c->has_window = 0;
    c->view_screen = 1;
    int frames = c->figure.frame;
    c->figure.frame = 0;   /* drawn again in screen pixels, not through a figure's mirror */
    int st = PC_OK;
    size_t k = 0;
    for (size_t i = 0; i < o.nops && st == PC_OK; i++) {
        while (k + 1 < o.nclips && o.clips[k + 1].first <= i) k++;
        const pc_rect *r = &o.clips[k].r;
        double x0, y0, x1, y1;
        fmap(f, r->x0, r->y0, &x0, &y0);
        fmap(f, r->x1, r->y1, &x1, &y1);
        int full = r->x0 == 0 && r->y0 == 0 && r->x1 == c->width - 1 && r->y1 == c->height - 1;
        c->view = full ? *r : (pc_rect){(int)fmax(0, floor(x0)), (int)fmax(0, floor(y0)),
                                        (int)fmin(c->width - 1, ceil(x1)), (int)fmin(c->height - 1, ceil(y1))};
        if ((st = pc_push_clip(c)) == PC_OK && c->ndeferred)   /* furniture called before op i */
            st = pc_furniture_expand(c, i, 0, f->sx, f->sy, f->tx, f->ty);
        if (st == PC_OK) st = replay_op(c, &o, &o.ops[i], f);
    }
    if (st == PC_OK && c->ndeferred) {   /* and after the last op, in the whole view */
        c->view = view;
        if ((st = pc_push_clip(c)) == PC_OK) st = pc_furniture_expand(c, o.nops, 1, f->sx, f->sy, f->tx, f->ty);
    }
    pc_furniture_forget(c);   /* drawn: ops now (a writer's copy only lets go of its borrowed list) */
    c->view = view;
    c->view_screen = vs;
    c->has_window = has_window;
    c->pen = pen;
    c->figure.frame = frames;
    if (st == PC_OK) st = pc_push_clip(c);
    free(o.ops); free(o.dots); free(o.pts); free(o.tags); free(o.spans); free(o.lpx);
    free(o.clips); free(o.text);
    return st;
}

/* The frame that puts what c has drawn in its view, margin pixels in;
 * 0 with *st PC_OK when nothing is drawn. */
static int framing(pc_canvas *c, double margin, int aspect, frame *f, int *st) {
    if (!(margin >= 0 && margin < 0.5 * fmin(c->view.x1 - c->view.x0, c->view.y1 - c->view.y0))) {
        *st = pc_fail(c, "fit: margin must be 0 up to half the view, got %g pixels", margin);
        return 0;
    }
    if (aspect != PC_FIT_EQUAL && aspect != PC_FIT_FILL) {
        *st = pc_fail(c, "fit: unknown aspect %d", aspect);
        return 0;
    }
    items it = {0};
    *st = gather(c, &it);
    if (*st != PC_OK || it.n == 0) {
        free(it.v);
        return 0;   /* nothing drawn: nothing to frame */
    }
    pc_rect vv = c->view;   /* less the bands that captions (device text) take */
    for (size_t i = 0; i < c->nops; i++) {
        const pc_op *op = &c->ops[i];
        double w, h;
        if (op->kind != PC_OP_TEXT || !(op->flags & PC_TEXT_DEVICE) ||
            pc_text_measure(c, c->text + op->first, op->count, (int)op->rx, &w, &h) != PC_OK)
            continue;
        if (op->y1 + h / 2 > (vv.y0 + vv.y1) / 2.0) vv.y1 = (int)fmin(vv.y1, floor(op->y1) - 1);
        else vv.y0 = (int)fmax(vv.y0, ceil(op->y1 + h));
    }
    const pc_rect *v = &vv;
    double roomx = v->x1 - v->x0 - 2 * margin, roomy = v->y1 - v->y0 - 2 * margin;
    if (!(roomy > 0)) {
        free(it.v);
        *st = pc_fail(c, "fit: the captions leave no room for the figure");
        return 0;
    }
    double cap = 1e6;
    double sx = largest_scale(&it, 0, roomx, cap), sy = largest_scale(&it, 1, roomy, cap);
    if (aspect == PC_FIT_EQUAL) sx = sy = fmin(sx, sy);
    if (!(sx > 0 && sy > 0)) {
        free(it.v);
        *st = pc_fail(c, "fit: the labels alone are larger than the view: nothing can frame them");
        return 0;
    }
    double lox, loy;
    double wx = width_at(&it, 0, sx, &lox), wy = width_at(&it, 1, sy, &loy);
    free(it.v);
    /* centred in the view: the box [lo, lo + w] under s goes to the middle */
    *f = (frame){sx, sy, v->x0 + margin + (roomx - wx) / 2 - lox,
                 v->y0 + margin + (roomy - wy) / 2 - loy};
    return 1;
}

int pc_fit(pc_canvas *c, double margin, int aspect) {
    frame f;
    int st;
    if (!framing(c, margin, aspect, &f, &st)) return st;
    const pc_rect *v = &c->view;
    /* the window that keeps later drawing in this frame: world -> old screen -> f */
    double corner[4];
    for (int k = 0; k < 2; k++) {
        double qx = k ? v->x1 : v->x0, qy = k ? v->y1 : v->y0;
        pc_screen_to_world(c, (qx - f.tx) / f.sx, (qy - f.ty) / f.sy, &corner[2 * k], &corner[2 * k + 1]);
    }
    int screen = c->has_window ? c->window_screen : !pc_figure_frames(c);   /* y up in a figure */
    if ((st = replay(c, &f)) != PC_OK) return st;
    if (c->attach_frame) c->attach_frame(c->attach, f.sx, f.sy, f.tx, f.ty);
    return pc_window(c, corner[0], corner[1], corner[2], corner[3], screen);
}

int pc_fit_figure(pc_canvas *c) {
    frame f;
    int st;
    if (!framing(c, PC_FIT_MARGIN, PC_FIT_EQUAL, &f, &st)) return st;
    return replay(c, &f);
}
