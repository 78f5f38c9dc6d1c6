/* The print look's walk over the display list (print_backend.h): every op becomes paths,
 * strokes, fills and labels in pt on the page, spoken to one backend.  The screen's pixel
 * (i, j) is the square [i, i+1) x [j, j+1) (as in the SVG writer), mapped at one scale s. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "canvas_internal.h"
#include "dotrun.h"
#include "layout.h"
#include "print_backend.h"

#define TWO_PI 6.283185307179586

typedef struct {
    const pc_canvas *c;
    const pc_page *pg;
    pc_pr_backend *b;
    pc_rgb pal[256];
    char *err; size_t errlen;
    int status;
    uint32_t *seen;           /* fill_dots: a screen pixel's place in idx, plus 1 (0: none) */
    uint32_t *idx; size_t cap;   /* a run's distinct pixels */
    uint8_t *dense;           /* per dot of the canvas: 1 when stroked as part of a curve */
} walk;

static double X(const walk *w, double x) { return w->pg->ox + x * w->pg->s; }
static double Y(const walk *w, double y) { return w->pg->oy + y * w->pg->s; }

pc_rgb pc_print_rgb(const pc_canvas *c, int attr) {
    pc_rgb pal[256];
    pc_theme_palette(c, PC_THEME_PAPER, pal);
    return pc_attr_rgb(c, pal, attr);
}

static pc_rgb rgb(const walk *w, int attr) { return pc_attr_rgb(w->c, w->pal, attr); }

static void pen_of(const walk *w, const pc_op *op, pc_pr_pen *pp) {
    const pc_stroke *p = op->pen < w->c->npens ? &w->c->pens[op->pen] : &w->c->pens[0];
    memset(pp, 0, sizeof *pp);
    double px = p->width * w->pg->s;
    pp->width = p->print_width > 0 ? p->print_width : px > PC_PRINT_PEN_MIN_PT ? px : PC_PRINT_PEN_MIN_PT;
    pp->ndash = p->ndash;
    /* a physical pen's dashes are in pt (kept as 96-dpi pixels); a pixel pen's scale */
    for (int i = 0; i < p->ndash; i++)
        pp->dash[i] = p->print_dash ? p->dash[i] * 0.75 : p->dash[i] * w->pg->s;
    pp->round = p->ndash == 0;
}

/* A pixel of the screen as a square of the page, a hair larger (OVERLAP pt) so that squares
 * side by side leave no seam in a renderer that rounds coordinates. */
#define OVERLAP 0.01
static void pixel(walk *w, long x, long y) {
    w->b->rect(w->b->self, X(w, (double)x), Y(w, (double)y), w->pg->s + OVERLAP, w->pg->s + OVERLAP);
}

/* n distinct pixel indices, sorted: each horizontal run of them one rectangle. */
static void fill_runs(walk *w, const uint32_t *idx, size_t n, int color) {
    uint32_t W = (uint32_t)w->c->width;
    if (w->b->pixels && n > 64) {   /* many: one mask (a PDF image mask, not 10^4 rectangles) */
        w->b->pixels(w->b->self, idx, n, w->c->width, w->pg, rgb(w, color));
        return;
    }
    for (size_t i = 0; i < n;) {
        size_t j = i + 1;
        while (j < n && idx[j] == idx[j - 1] + 1 && idx[j] % W != 0) j++;
        double x = idx[i] % W, y = idx[i] / W;
        w->b->rect(w->b->self, X(w, x), Y(w, y), (double)(j - i) * w->pg->s + OVERLAP,
                   w->pg->s + OVERLAP);
        i = j;
    }
    w->b->fill(w->b->self, rgb(w, color), 0);
}

static int by_color_then_index(const void *a, const void *b) {
    const uint32_t *x = a, *y = b;   /* pairs: colour, pixel index */
    if (x[0] != y[0]) return (x[0] > y[0]) - (x[0] < y[0]);
    return (x[1] > y[1]) - (x[1] < y[1]);
}

/* Runs of dots one after another (ops[0..nops), one clip): each screen pixel gets the colour
 * of the last dot on it, as in the raster (scripts plot the same pixel many times and change
 * colour from dot to dot), and each colour's pixels go as rows of rectangles, so a curve of a
 * million dots is a few thousand rectangles in a handful of fills. */
static void fill_dots(walk *w, const pc_op *ops, size_t nops) {
    const pc_canvas *c = w->c;
    size_t npx = (size_t)c->width * c->height;
    if (!w->seen && !(w->seen = calloc(npx, sizeof *w->seen))) { w->status = PC_ENOMEM; return; }
    size_t n = 0;   /* distinct pixels, in w->idx as (colour, index) pairs */
    for (size_t o = 0; o < nops && w->status == PC_OK; o++) {
        const pc_op *op = &ops[o];
        for (uint32_t k = 0; k < op->count; k++) {
            const pc_xy *d = &c->dots[op->first + k];
            long x = pc_px(d->x), y = pc_px(d->y);
            if (x < 0 || y < 0 || x >= c->width || y >= c->height) continue;
            if (w->dense && w->dense[op->first + k]) continue;   /* stroked (stroke_dots) */
            uint32_t i = (uint32_t)(y * c->width + x);
            if (w->seen[i]) {   /* seen[i]: 1 + its pair's place */
                w->idx[2 * (w->seen[i] - 1)] = op->color;
                continue;
            }
            if (2 * n + 2 > w->cap) {
                size_t cap = w->cap ? 2 * w->cap : 8192;
                uint32_t *b = realloc(w->idx, cap * sizeof *b);
                if (!b) { w->status = PC_ENOMEM; break; }
                w->idx = b;
                w->cap = cap;
            }
            w->idx[2 * n] = op->color;
            w->idx[2 * n + 1] = i;
            w->seen[i] = (uint32_t)++n;
        }
    }
    for (size_t k = 0; k < n; k++) w->seen[w->idx[2 * k + 1]] = 0;
    if (w->status != PC_OK) return;
    if (n) qsort(w->idx, n, 2 * sizeof *w->idx, by_color_then_index);   /* idx may be NULL when no dot was drawn */
    uint32_t *run = malloc(n * sizeof *run + 1);
    if (!run) { w->status = PC_ENOMEM; return; }
    for (size_t i = 0; i < n;) {
        size_t j = i, m = 0;
        while (j < n && w->idx[2 * j] == w->idx[2 * i]) run[m++] = w->idx[2 * j++ + 1];
        fill_runs(w, run, m, (int)w->idx[2 * i]);
        i = j;
    }
    free(run);
}

/* Curves plotted dot by dot (dotrun.h): each dense run of an op's dots one polyline through
 * the dots (a vertex every 0.75 px), stroked with the op's pen and round ends, so a PSET loop
 * prints as a line rather than as the screen's staircase of squares.  The dots stroked are
 * marked for fill_dots to leave out; the isolated ones stay exact pixels. */
static void stroke_dots(walk *w, const pc_op *ops, size_t nops) {
    const pc_canvas *c = w->c;
    for (size_t o = 0; o < nops && w->status == PC_OK; o++) {
        const pc_op *op = &ops[o];
        if (op->count < PC_DOTRUN_MIN) continue;
        const pc_xy *d = &c->dots[op->first];
        size_t *runs = malloc(op->count * sizeof *runs);
        pc_xy *v = malloc(op->count * sizeof *v);
        if (!w->dense) w->dense = calloc(c->ndots ? c->ndots : 1, 1);
        if (!runs || !v || !w->dense) {
            free(runs);
            free(v);
            w->status = PC_ENOMEM;
            return;
        }
        size_t m = pc_dot_runs(d, op->count, runs);
        for (size_t r = 0; r < m; r++) {
            size_t a = runs[2 * r], b = runs[2 * r + 1];
            memset(w->dense + op->first + a, 1, b - a);
            size_t nv = pc_dot_run_thin(d + a, b - a, 0.75, v);
            w->b->move(w->b->self, X(w, v[0].x + 0.5), Y(w, v[0].y + 0.5));
            for (size_t k = 1; k < nv; k++) w->b->line(w->b->self, X(w, v[k].x + 0.5), Y(w, v[k].y + 0.5));
        }
        if (m) {
            pc_pr_pen pen;
            pen_of(w, op, &pen);
            pen.round = 1;
            w->b->stroke(w->b->self, rgb(w, op->color), &pen);
        }
        free(runs);
        free(v);
    }
}

/* Folded dots (by increasing pixel index): each colour's runs of neighbours as rectangles. */
static void fill_pixels(walk *w, const pc_op *op) {
    const pc_canvas *c = w->c;
    uint32_t k = 0;
    while (k < op->count && w->status == PC_OK) {
        int color = c->lpx[op->first + k].color;
        size_t n = 0;
        for (; k < op->count && c->lpx[op->first + k].color == color; k++) {
            if (n == w->cap) {
                size_t cap = w->cap ? 2 * w->cap : 4096;
                uint32_t *b = realloc(w->idx, cap * sizeof *b);
                if (!b) { w->status = PC_ENOMEM; return; }
                w->idx = b;
                w->cap = cap;
            }
            w->idx[n++] = c->lpx[op->first + k].idx;
        }
        fill_runs(w, w->idx, n, color);
    }
}

static void styled_pixel(void *ctx, long x, long y) { pixel(ctx, x, y); }

/* The ellipse arc of an ARC op from a0 to a1 (counter-clockwise on the screen), as cubics of
 * at most a quarter turn each (the usual 4/3 tan(q/4) control distance). */
static void arc_path(walk *w, const pc_op *op, int move) {
    double cx = op->x1 + 0.5, cy = op->y1 + 0.5, rx = fabs(op->rx), ry = fabs(op->ry);
    double a0 = op->a0, a1 = op->a1;
    if (op->flags & PC_ARC_FULL) a0 = 0, a1 = TWO_PI;
    else if (a1 <= a0) a1 += TWO_PI;
    int n = (int)ceil((a1 - a0) / (TWO_PI / 4) - 1e-9);
    if (n < 1) n = 1;
    double q = (a1 - a0) / n, k = 4.0 / 3 * tan(q / 4);
    double px = cx + rx * cos(a0), py = cy - ry * sin(a0);
    if (move) w->b->move(w->b->self, X(w, px), Y(w, py));
    else w->b->line(w->b->self, X(w, px), Y(w, py));
    for (int i = 0; i < n; i++) {
        double t0 = a0 + i * q, t1 = t0 + q;
        double c0 = cos(t0), s0 = sin(t0), c1 = cos(t1), s1 = sin(t1);
        w->b->curve(w->b->self, X(w, cx + rx * (c0 - k * s0)), Y(w, cy - ry * (s0 + k * c0)),
                    X(w, cx + rx * (c1 + k * s1)), Y(w, cy - ry * (s1 - k * c1)),
                    X(w, cx + rx * c1), Y(w, cy - ry * s1));
    }
}

/* A small full circle drawn with the default pen: a "brush" dot of a thick curve (the
 * toolkit's brush = "dot" draws thousands). */
static int is_brush(const pc_op *op) {
    return op->kind == PC_OP_ARC && (op->flags & PC_ARC_FULL) && op->rx == op->ry &&
           op->rx > 0 && op->rx <= 8 && op->pen == 0;
}

/* Brushes one after another, of one colour and radius in one clip: one circle per distinct
 * centre pixel (most of a dense curve's brushes land on a pixel already drawn), one stroke. */
static void draw_brushes(walk *w, const pc_op *ops, size_t n) {
    const pc_canvas *c = w->c;
    size_t npx = (size_t)c->width * c->height, m = 0;
    if (!w->seen && !(w->seen = calloc(npx, sizeof *w->seen))) { w->status = PC_ENOMEM; return; }
    for (size_t k = 0; k < n && w->status == PC_OK; k++) {
        long x = pc_px(ops[k].x1), y = pc_px(ops[k].y1);
        int inside = x >= 0 && y >= 0 && x < c->width && y < c->height;
        if (inside) {
            uint32_t i = (uint32_t)(y * c->width + x);
            if (w->seen[i]) continue;
            if (m == w->cap) {
                size_t cap = w->cap ? 2 * w->cap : 8192;
                uint32_t *b = realloc(w->idx, cap * sizeof *b);
                if (!b) { w->status = PC_ENOMEM; break; }
                w->idx = b;
                w->cap = cap;
            }
            w->idx[m++] = i;
            w->seen[i] = 1;
        }
        arc_path(w, &ops[k], 1);
        w->b->close(w->b->self);
    }
    for (size_t k = 0; k < m; k++) w->seen[w->idx[k]] = 0;
    pc_pr_pen pen;
    pen_of(w, &ops[0], &pen);
    w->b->stroke(w->b->self, rgb(w, ops[0].color), &pen);
}

static void draw_arc(walk *w, const pc_op *op) {
    double cx = op->x1 + 0.5, cy = op->y1 + 0.5;
    if (lrint(fabs(op->rx)) == 0 && lrint(fabs(op->ry)) == 0) {
        pixel(w, pc_px(op->x1), pc_px(op->y1));
        w->b->fill(w->b->self, rgb(w, op->color), 0);
        return;
    }
    int r0 = op->flags & PC_ARC_RADIUS0, r1 = op->flags & PC_ARC_RADIUS1;
    if (r0) w->b->move(w->b->self, X(w, cx), Y(w, cy));
    arc_path(w, op, !r0);
    if (r1) w->b->line(w->b->self, X(w, cx), Y(w, cy));
    if ((op->flags & PC_ARC_FULL)) w->b->close(w->b->self);
    pc_pr_pen pen;
    pen_of(w, op, &pen);
    w->b->stroke(w->b->self, rgb(w, op->color), &pen);
}

/* A path's points with their verbs, as the canvas keeps them. */
static void path_of(walk *w, const pc_op *op, int closed) {
    const pc_canvas *c = w->c;
    uint32_t i = 0;
    int open = 0;
    while (i < op->count) {
        const pc_xy *p = &c->pts[op->first + i];
        uint8_t tag = c->tags[op->first + i];
        if (tag == PC_PATH_CUBIC && i + 2 < op->count) {
            w->b->curve(w->b->self, X(w, p[0].x + 0.5), Y(w, p[0].y + 0.5), X(w, p[1].x + 0.5),
                        Y(w, p[1].y + 0.5), X(w, p[2].x + 0.5), Y(w, p[2].y + 0.5));
            i += 3;
            continue;
        }
        if (tag == PC_PATH_MOVE) {
            if (open && closed) w->b->close(w->b->self);
            w->b->move(w->b->self, X(w, p->x + 0.5), Y(w, p->y + 0.5));
            open = 1;
        } else {
            w->b->line(w->b->self, X(w, p->x + 0.5), Y(w, p->y + 0.5));
        }
        i++;
    }
    if (open && closed) w->b->close(w->b->self);
}

static void stroke_op(walk *w, const pc_op *op) {
    pc_pr_pen pen;
    pen_of(w, op, &pen);
    w->b->stroke(w->b->self, rgb(w, op->color), &pen);
}

/* A label: through the print look's measuring hook (print_measure.c: the resolved copy of a
 * print-look writer has it), in the box the figure layout gave it, so placement and drawing
 * agree; without the hook (a canvas walked directly) on its anchor side of the point, as the
 * VGA look places its cell box (text.c), with a gap of 0.3 em (none for text(), whose box
 * starts at the point). */
static void draw_text(walk *w, const pc_op *op) {
    const pc_canvas *c = w->c;
    if ((size_t)op->first + op->count > c->ntext) return;
    char *s = malloc(op->count + 1);
    if (!s) { w->status = PC_ENOMEM; return; }
    memcpy(s, c->text + op->first, op->count);
    s[op->count] = 0;
    const pc_textstyle *st = op->pen && op->pen <= c->ntstyles ? &c->tstyles[op->pen - 1] : NULL;
    double size = st && st->size > 0 ? st->size : c->figure.size > 0 ? c->figure.size : PC_PRINT_SIZE_PT;
    size *= op->rx >= 1 ? op->rx : 1;
    const char *family;
    int ok = pc_font_family(st && st->font[0] ? st->font : c->figure.font, &family, w->err, w->errlen);
    pc_mlayout L;
    double left, base;
    if (ok == PC_OK) ok = pc_pr_layout(s, op->a0 == 1, family, size, &L, w->err, w->errlen);
    if (ok != PC_OK) {
        w->status = ok;
        free(s);
        return;
    }
    int anchor = op->flags & PC_TEXT_ANCHOR;
    pc_box2 box;
    if (c->measure && !pc_text_op_is_corner(op) && pc_label_op_box(c, op, &box) == PC_OK) {
        /* the box the layout placed it in (its halo inside), measured by the same hook */
        left = X(w, box.x0) + ((box.x1 - box.x0) * w->pg->s - L.width) / 2;
        base = Y(w, box.y0) + ((box.y1 - box.y0) * w->pg->s - L.ascent - L.descent) / 2 + L.ascent;
    } else {
        double px = X(w, pc_px(op->x2) + 0.5), py = Y(w, pc_px(op->y2) + 0.5);
        int is_text = anchor == PC_ANCHOR_SE && lrint(op->x1) == pc_px(op->x2) && lrint(op->y1) == pc_px(op->y2);
        double gap = is_text ? 0 : 0.3 * size;
        if (is_text) px = X(w, op->x1), py = Y(w, op->y1);
        switch (anchor) {
        case PC_ANCHOR_NE: case PC_ANCHOR_E: case PC_ANCHOR_SE: left = px + gap; break;
        case PC_ANCHOR_NW: case PC_ANCHOR_W: case PC_ANCHOR_SW: left = px - gap - L.width; break;
        default: left = px - L.width / 2; break;
        }
        switch (anchor) {
        case PC_ANCHOR_NW: case PC_ANCHOR_N: case PC_ANCHOR_NE: base = py - gap - L.descent; break;
        case PC_ANCHOR_SW: case PC_ANCHOR_S: case PC_ANCHOR_SE: base = py + gap + L.ascent; break;
        default: base = py + (L.ascent - L.descent) / 2; break;
        }
    }
    int halo = st ? st->halo : -1;
    pc_pr_label lab = {&L, family, left, base, rgb(w, op->color), w->pal[0],
                       halo == 0 ? 0 : 0.16 * size, s};
    w->b->text(w->b->self, &lab);
    pc_mlayout_free(&L);
    free(s);
}

int pc_print_walk(const pc_canvas *c, const pc_page *pg, pc_pr_backend *b, char *err,
                  size_t errlen) {
    walk w = {c, pg, b, {{0}}, err, errlen, PC_OK, NULL, NULL, 0, NULL};
    pc_theme_palette(c, PC_THEME_PAPER, w.pal);
    size_t clip = SIZE_MAX;
    for (size_t i = 0; i < c->nops && w.status == PC_OK && !b->failed; i++) {
        const pc_op *op = &c->ops[i];
        size_t k = pc_op_clip(c, i);
        if (k != clip) {
            clip = k;
            const pc_rect *r = &c->clips[k].r;
            b->clip(b->self, X(&w, r->x0), Y(&w, r->y0), X(&w, r->x1 + 1), Y(&w, r->y1 + 1));
        }
        const pc_stroke *pen = op->pen < c->npens ? &c->pens[op->pen] : &c->pens[0];
        if ((op->kind == PC_OP_LINE || op->kind == PC_OP_BOX) && pen->style) {
            pc_styled_pixels(c, op, styled_pixel, &w);   /* QBasic's style bits: its pixels */
            b->fill(b->self, rgb(&w, op->color), 0);
            continue;
        }
        switch (op->kind) {
        case PC_OP_CLEAR: {
            const pc_rect *r = &c->clips[k].r;
            b->rect(b->self, X(&w, r->x0), Y(&w, r->y0), (r->x1 - r->x0 + 1) * pg->s,
                    (r->y1 - r->y0 + 1) * pg->s);
            b->fill(b->self, rgb(&w, op->color), 0);
            break;
        }
        case PC_OP_DOTS: {
            size_t j = i + 1;
            while (j < c->nops && c->ops[j].kind == PC_OP_DOTS && pc_op_clip(c, j) == k) j++;
            stroke_dots(&w, op, j - i);
            if (w.status == PC_OK) fill_dots(&w, op, j - i);
            i = j - 1;
            break;
        }
        case PC_OP_PIXELS: fill_pixels(&w, op); break;
        case PC_OP_LINE: {   /* lines one after another in one colour and pen: one stroke */
            size_t j = i;
            do {
                const pc_op *l = &c->ops[j];
                b->move(b->self, X(&w, l->x1 + 0.5), Y(&w, l->y1 + 0.5));
                b->line(b->self, X(&w, l->x2 + 0.5), Y(&w, l->y2 + 0.5));
                j++;
            } while (j < c->nops && c->ops[j].kind == PC_OP_LINE && c->ops[j].color == op->color &&
                     c->ops[j].pen == op->pen && !c->pens[op->pen].style && j - i < 4096 &&
                     pc_op_clip(c, j) == k);
            stroke_op(&w, op);
            i = j - 1;
            break;
        }
        case PC_OP_BOX: case PC_OP_FILLBOX: {
            double x0 = fmin(op->x1, op->x2), y0 = fmin(op->y1, op->y2);
            double x1 = fmax(op->x1, op->x2), y1 = fmax(op->y1, op->y2);
            if (op->kind == PC_OP_FILLBOX) {
                /* the pixels from corner to corner, both included */
                double l = pc_px(x0), t = pc_px(y0);
                b->rect(b->self, X(&w, l), Y(&w, t), (pc_px(x1) - l + 1) * pg->s,
                        (pc_px(y1) - t + 1) * pg->s);
                b->fill(b->self, rgb(&w, op->color), 0);
            } else {
                b->rect(b->self, X(&w, x0 + 0.5), Y(&w, y0 + 0.5), (x1 - x0) * pg->s, (y1 - y0) * pg->s);
                stroke_op(&w, op);
            }
            break;
        }
        case PC_OP_ARC: {
            size_t j = i + 1;
            if (is_brush(op))
                while (j < c->nops && is_brush(&c->ops[j]) && c->ops[j].color == op->color &&
                       c->ops[j].rx == op->rx && pc_op_clip(c, j) == k)
                    j++;
            if (j > i + 1) draw_brushes(&w, op, j - i);
            else draw_arc(&w, op);
            i = j - 1;
            break;
        }
        case PC_OP_FILL:
            for (uint32_t j = 0; j < op->count; j++) {
                const pc_span *sp = &c->spans[op->first + j];
                b->rect(b->self, X(&w, sp->x0), Y(&w, sp->y), (sp->x1 - sp->x0 + 1) * pg->s,
                        pg->s + OVERLAP);
            }
            b->fill(b->self, rgb(&w, op->color), 0);
            break;
        case PC_OP_PATH:
            path_of(&w, op, op->flags & PC_PATH_CLOSED);
            stroke_op(&w, op);
            break;
        case PC_OP_FILLPATH:
            path_of(&w, op, 1);
            b->fill(b->self, rgb(&w, op->color), (op->flags & 1) == PC_FILL_EVENODD);
            if (op->flags & PC_FILL_TILE) {   /* its outline over the seams (canvas.h) */
                pc_pr_pen seam = {.width = pg->s, .round = 1};
                path_of(&w, op, 1);
                b->stroke(b->self, rgb(&w, op->color), &seam);
            }
            break;
        case PC_OP_TEXT: draw_text(&w, op); break;
        }
    }
    if (w.status == PC_OK && b->failed) w.status = PC_ENOMEM;
    free(w.seen);
    free(w.idx);
    free(w.dense);
    return w.status;
}
