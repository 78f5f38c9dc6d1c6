/* Resolving a canvas for a writer: the pending labels placed among everything drawn.
 * The writers get a copy (pixels and display list duplicated, the rest shared read-only), so
 * the canvas keeps its labels pending and a later save places them again against what was
 * drawn in between. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "canvas_internal.h"
#include "font.h"
#include "layout.h"
#include "math_label.h"

/* The VGA look's box: 8 x 16 cells a character, math as text.c lays it out. */
static int vga_measure(const char *utf8, size_t n, int scale, double *w, double *h) {
    long chars = pc_utf8_count(utf8, n, NULL);
    if (chars < 0) return PC_EARG;
    *w = (double)chars * PC_FONT_W * scale;
    *h = (double)PC_FONT_H * scale;
    if (memchr(utf8, '$', n)) {   /* math: the width the VGA look draws it with (text.c) */
        char *copy = malloc(n + 1);
        if (!copy) return PC_ENOMEM;
        memcpy(copy, utf8, n);
        copy[n] = 0;
        pc_mlayout L = {0};
        char err[160];
        if (pc_has_math(copy) && pc_text_vga_layout(copy, scale, &L, err, sizeof err) == PC_OK)
            *w = L.width;
        pc_mlayout_free(&L);
        free(copy);
    }
    return PC_OK;
}

int pc_text_measure(const pc_canvas *c, const char *utf8, size_t n, int scale, double *w,
                    double *h) {
    if (c && c->measure) return c->measure(c->measure_ctx, utf8, n, scale, w, h);
    return vga_measure(utf8, n, scale, w, h);
}

int pc_text_op_is_corner(const pc_op *op) {
    return (op->flags & PC_TEXT_ANCHOR) == PC_ANCHOR_SE && !(op->flags & PC_TEXT_PLACED) &&
           lrint(op->x1) == pc_px(op->x2) && lrint(op->y1) == pc_px(op->y2);
}

/* The gap a label with a direction was given, read back from the cell box pc_text recorded
 * (text.c's place(): the box's near edge is gap pixels off the point's pixel). */
static double given_gap(const pc_canvas *c, const pc_op *op) {
    long X = pc_px(op->x2), Y = pc_px(op->y2);
    double vw = 0, vh = 0;
    int scale = (int)op->rx;
    if (vga_measure(c->text + op->first, op->count, scale, &vw, &vh) != PC_OK) return 3;
    if (op->ry > 0) vh = op->ry * op->rx;
    switch (op->flags & PC_TEXT_ANCHOR) {
    case PC_ANCHOR_NE: case PC_ANCHOR_E: case PC_ANCHOR_SE: return op->x1 - X;
    case PC_ANCHOR_N: case PC_ANCHOR_NW: return Y - op->y1 - vh + 1;
    case PC_ANCHOR_S: case PC_ANCHOR_SW: return op->y1 - Y;
    case PC_ANCHOR_W: return X - op->x1 - lrint(vw) + 1;
    default: return 0;
    }
}

int pc_label_op_box(const pc_canvas *c, const pc_op *op, pc_box2 *box) {
    double w = 0, h = 0;
    int st = pc_text_measure(c, c->text + op->first, op->count, (int)op->rx, &w, &h);
    if (st != PC_OK) return st;
    if (op->ry > 0 && !c->measure) h = op->ry * op->rx;   /* PRINT's 8x8 and 8x14 cells */
    if (!c->measure || (op->flags & (PC_TEXT_AUTO | PC_TEXT_PLACED)) || pc_text_op_is_corner(op)) {
        *box = (pc_box2){op->x1, op->y1, op->x1 + w, op->y1 + h};
        return PC_OK;
    }
    double g = given_gap(c, op);
    *box = pc_label_box(op->x2, op->y2, w, h, op->flags & PC_TEXT_ANCHOR, g > 0 ? g : 0);
    return PC_OK;
}

int pc_layout_pending(const pc_canvas *c) {
    if (c->attach_resolve || pc_figure_frames(c) || c->ndeferred) return 1;
    for (size_t i = 0; i < c->nops; i++)
        if (c->ops[i].kind == PC_OP_TEXT && (c->ops[i].flags & PC_TEXT_AUTO)) return 1;
    return 0;
}

/* The labels of the display list: every TEXT op, the automatic ones to place. */
static pc_label *collect(const pc_canvas *c, size_t *n) {
    size_t m = 0;
    for (size_t i = 0; i < c->nops; i++) m += c->ops[i].kind == PC_OP_TEXT;
    pc_label *lab = calloc(m ? m : 1, sizeof *lab);
    if (!lab) return NULL;
    m = 0;
    for (size_t i = 0; i < c->nops; i++) {
        const pc_op *op = &c->ops[i];
        if (op->kind != PC_OP_TEXT) continue;
        pc_label *l = &lab[m++];
        pc_box2 b;
        if (pc_label_op_box(c, op, &b) != PC_OK) b = (pc_box2){op->x1, op->y1, op->x1, op->y1};
        l->w = b.x1 - b.x0;
        l->h = b.y1 - b.y0;
        l->px = op->x2;
        l->py = op->y2;
        l->fixed = !(op->flags & PC_TEXT_AUTO);
        l->box = b;
        l->anchor = op->flags & PC_TEXT_ANCHOR;
        /* it stays in its VIEW; a leader is an op at the list's end, in the last VIEW only */
        size_t k = pc_op_clip(c, i);
        const pc_rect *v = &c->clips[k].r;
        l->bounds = (pc_box2){v->x0, v->y0, v->x1 + 1.0, v->y1 + 1.0};
        l->no_leader = k + 1 != c->nclips;
    }
    *n = m;
    return lab;
}

/* The leader of a far label (label_place.c decided where it goes). */
static int leader(pc_canvas *c, const pc_label *l, int color) {
    double seg[4];
    if (!pc_label_leader(l, seg)) return PC_OK;
    return pc_line(c, seg[0], seg[1], seg[2], seg[3], color);
}

/* ---- the ink mask ----------------------------------------------------------------------- */

typedef struct { uint8_t *m; int w, h; pc_rect clip; } ink_mask;

static void mask_seg(ink_mask *k, double x0, double y0, double x1, double y1) {
    if (!pc_clip_segment(&x0, &y0, &x1, &y1, k->clip.x0 - 0.5, k->clip.y0 - 0.5, k->clip.x1 + 0.5,
                         k->clip.y1 + 0.5))
        return;   /* only the part in its VIEW is walked */
    double n = ceil(fmax(fabs(x1 - x0), fabs(y1 - y0)));
    if (!(n < 1e5)) return;
    for (double i = 0; i <= n; i++) {
        double t = n > 0 ? i / n : 0;
        long x = lrint(x0 + t * (x1 - x0)), y = lrint(y0 + t * (y1 - y0));
        if (x >= k->clip.x0 && x <= k->clip.x1 && y >= k->clip.y0 && y <= k->clip.y1 &&
            x >= 0 && y >= 0 && x < k->w && y < k->h)
            k->m[(size_t)y * k->w + x] = 1;
    }
}

/* A dashed or styled stroke drawn solid into the mask: a reader sees the line through its
 * gaps, so a label goes no more in a gap than across the dashes. */
static void mask_dashed(const pc_canvas *r, size_t i, ink_mask *k) {
    const pc_op *op = &r->ops[i];
    if (op->pen >= r->npens) return;
    const pc_stroke *pen = &r->pens[op->pen];
    if (!pen->ndash && !pen->style) return;
    k->clip = r->clips[pc_op_clip(r, i)].r;
    switch (op->kind) {
    case PC_OP_LINE: mask_seg(k, op->x1, op->y1, op->x2, op->y2); break;
    case PC_OP_BOX:
        mask_seg(k, op->x1, op->y1, op->x2, op->y1); mask_seg(k, op->x2, op->y1, op->x2, op->y2);
        mask_seg(k, op->x2, op->y2, op->x1, op->y2); mask_seg(k, op->x1, op->y2, op->x1, op->y1);
        break;
    case PC_OP_ARC: {   /* counter-clockwise as seen, from a0 to a1 (all round when full) */
        double a0 = op->flags & PC_ARC_FULL ? 0 : op->a0, a1 = op->flags & PC_ARC_FULL ? 2 * 3.141592653589793 : op->a1;
        if (a1 < a0) a1 += 2 * 3.141592653589793;
        int n = (int)fmin(4096, fmax(8, (a1 - a0) * fmax(op->rx, op->ry) / 2));
        for (int j = 0; j < n; j++) {
            double t0 = a0 + (a1 - a0) * j / n, t1 = a0 + (a1 - a0) * (j + 1) / n;
            mask_seg(k, op->x1 + op->rx * cos(t0), op->y1 - op->ry * sin(t0), op->x1 + op->rx * cos(t1),
                     op->y1 - op->ry * sin(t1));
        }
        break;
    }
    case PC_OP_PATH: {
        const pc_xy *p = r->pts + op->first;
        const uint8_t *tag = r->tags + op->first;
        size_t start = 0;
        for (size_t j = 1; j < op->count; j++) {
            if (tag[j] == PC_PATH_MOVE) {
                if (op->flags & PC_PATH_CLOSED) mask_seg(k, p[j - 1].x, p[j - 1].y, p[start].x, p[start].y);
                start = j;
            } else if (tag[j] == PC_PATH_CUBIC && j + 2 < op->count) {
                pc_xy q[4] = {p[j - 1], p[j], p[j + 1], p[j + 2]};
                int m = pc_cubic_segments(q, 0.5);
                pc_xy a = q[0];
                for (int s = 1; s <= m; s++) {
                    pc_xy b = pc_cubic_at(q, (double)s / m);
                    mask_seg(k, a.x, a.y, b.x, b.y);
                    a = b;
                }
                j += 2;
            } else {
                mask_seg(k, p[j - 1].x, p[j - 1].y, p[j].x, p[j].y);
            }
        }
        if ((op->flags & PC_PATH_CLOSED) && op->count > 1)
            mask_seg(k, p[op->count - 1].x, p[op->count - 1].y, p[start].x, p[start].y);
        break;
    }
    default: break;
    }
}

static int resolve_into(pc_canvas *r) {
    if (r->attach_resolve) {   /* a 3-D scene first: the labels then avoid its strokes */
        int st = r->attach_resolve(r->attach, r);
        if (st != PC_OK) return st;
        r->attach_extent = NULL;   /* drawn: its strokes are in the list now */
    }
    if (pc_figure_frames(r)) {   /* then the frame of everything, the scene included */
        int st = pc_fit_figure(r);
        if (st != PC_OK) return st;
        r->figure.frame = 0;   /* framed: the copy draws in screen pixels from here on */
    }
    if (r->ndeferred) {   /* furniture of a figure framed no more (a window set since): as called */
        int st = pc_furniture_expand(r, 0, 1, 1, 1, 0, 0);
        pc_furniture_forget(r);
        if (st != PC_OK) return st;
    }
    size_t n;
    pc_label *lab = collect(r, &n);
    if (!lab) return PC_ENOMEM;
    size_t npx = (size_t)r->width * r->height;
    uint8_t *mask = malloc(npx ? npx : 1);
    pc_inkmap ink = {0};
    int st = mask ? PC_OK : PC_ENOMEM;
    if (st == PC_OK) {
        for (size_t i = 0; i < npx; i++) mask[i] = r->pixels[i] != r->paper;
        ink_mask k = {mask, r->width, r->height, {0, 0, 0, 0}};
        for (size_t i = 0; i < r->nops; i++) mask_dashed(r, i, &k);
        st = pc_inkmap_init(&ink, mask, r->width, r->height);
    }
    free(mask);
    if (st == PC_OK) st = pc_place_labels(lab, n, &ink, r->width, r->height);
    pc_inkmap_free(&ink);
    /* the copy draws in screen pixels, each label in its own VIEW, with the default pen */
    r->has_window = 0;
    r->view_screen = 1;
    r->pen = 0;
    size_t nops = r->nops, k = 0;
    for (size_t i = 0; i < nops && st == PC_OK; i++) {
        pc_op *op = &r->ops[i];
        if (op->kind != PC_OP_TEXT) continue;
        const pc_label *l = &lab[k++];
        if (l->fixed) continue;
        op->x1 = l->box.x0;
        op->y1 = l->box.y0;
        op->flags = (uint8_t)(l->anchor | PC_TEXT_PLACED);
        r->view = r->clips[pc_op_clip(r, i)].r;
        pc_text_raster(r, op);
        if (l->leader) st = leader(r, l, op->color);   /* may move r->ops: op is not used after */
    }
    free(lab);
    return st;
}

/* A copy of n elements (room for one at least, so NULL only means no memory). */
static void *dup(const void *p, size_t n, size_t elem, size_t *cap) {
    void *q = malloc((n ? n : 1) * elem);
    if (q && n) memcpy(q, p, n * elem);
    *cap = n ? n : 1;
    return q;
}

const pc_canvas *pc_layout_resolve(const pc_canvas *c) {
    int st;
    return pc_layout_resolve_why(c, &st, NULL, 0);
}

const pc_canvas *pc_layout_resolve_why(const pc_canvas *c, int *status, char *why, size_t whylen) {
    *status = PC_ENOMEM;
    if (!pc_layout_pending(c)) return c;
    pc_canvas *r = malloc(sizeof *r);
    if (!r) return NULL;
    *r = *c;
    r->error[0] = 0;   /* a message from here on is the resolution's */
    /* what the resolution may add to is the copy's own: pixels, ops, path points, pens, text */
    size_t npx = (size_t)c->width * c->height;
    r->pixels = malloc(npx * sizeof *r->pixels);
    r->capops = c->nops + 16;
    r->ops = malloc(r->capops * sizeof *r->ops);
    r->cappts = c->npts + 16;
    r->pts = malloc(r->cappts * sizeof *r->pts);
    r->tags = malloc(r->cappts * sizeof *r->tags);
    r->cappens = c->npens + 4;
    r->pens = malloc(r->cappens * sizeof *r->pens);
    r->captext = c->ntext + 64;
    r->text = malloc(r->captext);
    r->tstyles = dup(c->tstyles, c->ntstyles, sizeof *c->tstyles, &r->captstyles);   /* a scene's labels add */
    r->attach_drop = NULL;   /* the attachment stays the canvas's */
    r->deferred_borrowed = 1;   /* so does its deferred furniture */
    int own = pc_figure_frames(c);   /* framing draws everything again: the copy owns it all */
    if (own) {
        r->dots = dup(c->dots, c->ndots, sizeof *c->dots, &r->capdots);
        r->spans = dup(c->spans, c->nspans, sizeof *c->spans, &r->capspans);
        r->lpx = dup(c->lpx, c->nlpx, sizeof *c->lpx, &r->caplpx);
        r->clips = dup(c->clips, c->nclips, sizeof *c->clips, &r->capclips);
    }
    if (!r->pixels || !r->ops || !r->pts || !r->tags || !r->pens || !r->text || !r->tstyles ||
        (own && (!r->dots || !r->spans || !r->lpx || !r->clips))) {
        pc_layout_release(c, r);
        return NULL;
    }
    memcpy(r->pixels, c->pixels, npx * sizeof *r->pixels);
    if (c->nops) memcpy(r->ops, c->ops, c->nops * sizeof *r->ops);
    if (c->npts) memcpy(r->pts, c->pts, c->npts * sizeof *r->pts);
    if (c->npts) memcpy(r->tags, c->tags, c->npts * sizeof *r->tags);
    if (c->npens) memcpy(r->pens, c->pens, c->npens * sizeof *r->pens);
    if (c->ntext) memcpy(r->text, c->text, c->ntext);
    int st = resolve_into(r);
    if (st != PC_OK) {   /* the copy's message says what failed (a label's math in a scene) */
        *status = st;
        if (why && whylen) snprintf(why, whylen, "%s", r->error[0] ? r->error : "out of memory");
        pc_layout_release(c, r);
        return NULL;
    }
    r->attach_resolve = NULL;   /* resolved: nothing is pending in the copy */
    r->attach_extent = NULL;
    r->attach_frame = NULL;
    r->attach = NULL;
    return r;
}

void pc_layout_release(const pc_canvas *c, const pc_canvas *resolved) {
    if (!resolved || resolved == c) return;
    pc_canvas *r = (pc_canvas *)resolved;   /* our own copy: pc_layout_resolve made it */
    free(r->pixels);
    free(r->ops);
    free(r->pts);
    free(r->tags);
    free(r->pens);
    free(r->text);
    free(r->tstyles);
    /* what framing drew again is the copy's own; else shared with the canvas */
    if (r->dots != c->dots) free(r->dots);
    if (r->spans != c->spans) free(r->spans);
    if (r->lpx != c->lpx) free(r->lpx);
    if (r->clips != c->clips) free(r->clips);
    free(r);
}

int pc_layout_labels(const pc_canvas *c, pc_box2 **out, int **anchors, size_t *n) {
    const pc_canvas *r = pc_layout_resolve(c);
    if (!r) return PC_ENOMEM;
    size_t m;
    pc_label *lab = collect(r, &m);
    int st = lab ? PC_OK : PC_ENOMEM;
    *out = NULL;
    if (anchors) *anchors = NULL;
    if (st == PC_OK) {
        *out = malloc((m ? m : 1) * sizeof **out);
        if (anchors) *anchors = malloc((m ? m : 1) * sizeof **anchors);
        if (!*out || (anchors && !*anchors)) st = PC_ENOMEM;
    }
    for (size_t i = 0; st == PC_OK && i < m; i++) {
        (*out)[i] = lab[i].box;
        if (anchors) (*anchors)[i] = lab[i].anchor;
    }
    if (st != PC_OK) {
        free(*out);
        if (anchors) free(*anchors);
        *out = NULL;
    }
    *n = st == PC_OK ? m : 0;
    free(lab);
    pc_layout_release(c, r);
    return st;
}
