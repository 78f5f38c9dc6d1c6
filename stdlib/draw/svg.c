/* SVG: the display list as vectors, so a figure stays small and sharp when zoomed.
 *
 * Geometry is aligned with the raster: pixel (i, j) covers the square i..i+1, j..j+1, so a
 * point at screen coordinate (x, y), which the raster puts in pixel (round(x), round(y)), is
 * drawn centred at (x + 0.5, y + 0.5).  Strokes are 1 pixel wide with square caps, like the
 * pixels at the ends of a rasterised line.  Numbers have at most two decimals.
 *
 *   PIXELS             dots folded into pixels (a long run of dots, dotfold.c): exact
 *                      pixels like isolated dots, in the same layer.
 *   DOTS runs          consecutive dots of one colour and clip, each within DENSE px of the
 *                      previous, become one polyline <path> (points closer than TOL px to the
 *                      polyline are dropped: a million dots on an oval give a few hundred
 *                      vertices).  Dots with no dense neighbour are exact 1x1 pixel squares,
 *                      all those of one run in one filled <path>.
 *   runs of LINEs      one <path> per run of one colour and clip; connected segments (LINE
 *                      -(x, y), polygons) continue the same subpath.
 *   BOX                <rect> stroked; FILLBOX and CLEAR: <rect> filled, on whole pixels.
 *   ARC                full: <circle> or <ellipse>; partial: <path> with an A command, plus
 *                      the radius lines that negative angles ask for.
 *   runs of brushes    small full circles (radius up to BRUSH_R: the listings' "thick dot"
 *                      circle (x, y), 1) of one colour, radius and clip, each centre within
 *                      BRUSH_DENSE px of the previous, become one polyline stroked as wide as
 *                      the ring (2r + 1 px) with round ends; sparse ones stay circles.
 *   FILL (PAINT)       one filled <path>: the outline of the painted pixels, traced along
 *                      pixel edges (holes included), so it has no seams at any zoom.
 *   PATH               one <path> with absolute M, L and C commands (Z when closed).
 *   FILLPATH           one filled <path> (M, L, C, every subpath closed by Z) with the op's
 *                      fill-rule, crisp edges; subpaths reaching far off are cut to the clip.
 *   TEXT               <text> in monospace at the raster's cell box (font.h's baseline),
 *                      stretched by textLength to exactly the raster's width.
 *   styled LINE, BOX   QBasic's style bits: the exact pixels, as isolated dots are written.
 *
 * A pen other than the default adds stroke-width (with round caps and joins) and
 * stroke-dasharray (see pen_attrs) to the element of a LINE run, BOX, ARC or PATH; a boxed
 * outline drawn with a pen is a path, a dashed full circle a path of two arcs.
 *
 * Colours are the theme's palette at write time.  VIEW clip rectangles other than the whole
 * screen become <clipPath>s; what lies far outside the clip (more than MARGIN px) is left out.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "writers.h"
#include "canvas_internal.h"
#include "font.h"

#define DENSE 1.5    /* max distance between consecutive dots of one polyline, px */
#define TOL 0.05     /* max distance of a dropped dot from the polyline, px */
#define MARGIN 3.0   /* stroke geometry further than this outside the clip is invisible */
#define TWO_PI 6.283185307179586
#define BRUSH_R 2.0      /* largest circle radius treated as a brush, px */
#define BRUSH_DENSE 2.0  /* max distance between consecutive brush centres of one stroke, px */

typedef struct { long x, y; } hpt;      /* a point in hundredths of a pixel */

typedef struct { uint32_t idx, seq; uint16_t color; } layer_px;

typedef struct {
    FILE *out;
    const pc_canvas *c;
    pc_rgb pal[256];
    int group;                 /* clip index whose <g> is open, -1 for none */
    size_t clip;               /* the clip of the op being written (index into c->clips) */
    size_t *canon;             /* per clip: the first clip of the same rectangle (its id) */
    unsigned char *clip_done; /* clipPath already written, per clip index */
    int col;                   /* column within path data, to wrap long lines */
    int numlast;               /* the path data so far ends with a number */
    hpt cur;                   /* current point of the path data */
    hpt *pts; size_t npts, cappts;     /* polyline being built */
    layer_px *layer; size_t nlayer, caplayer;   /* isolated dots not yet written */
    int nomem;
} svgw;

/* ---- numbers and path data ---------------------------------------------------------------- */

/* Coordinates are clamped to +-1e7 px (far beyond any screen), so hundredths fit in a long
 * even where it has 32 bits. */
static long hund(double v) {
    if (!(v <= 1e7)) v = 1e7;   /* NaN too: never garbage from lrint */
    if (v < -1e7) v = -1e7;
    return lrint(v * 100);
}

/* v hundredths -> "12", "12.5", "12.25", ".5", "-.05" */
static int fmt_num(char *buf, long v) {
    char *p = buf;
    if (v < 0) { *p++ = '-'; v = -v; }
    long ip = v / 100, fp = v % 100;
    if (ip || !fp) p += sprintf(p, "%ld", ip);
    if (fp) {
        *p++ = '.';
        *p++ = (char)('0' + fp / 10);
        if (fp % 10) *p++ = (char)('0' + fp % 10);
    }
    *p = 0;
    return (int)(p - buf);
}

static void put_attr_num(svgw *w, const char *name, long v) {
    char b[32];
    fmt_num(b, v);
    fprintf(w->out, " %s=\"%s\"", name, b);
}

static void color_attr(svgw *w, const char *what, int color) {
    pc_rgb p = pc_attr_rgb(w->c, w->pal, color);
    fprintf(w->out, " %s=\"#%02x%02x%02x\"", what, p.r, p.g, p.b);
}

static void d_begin(svgw *w) {
    fputs(" d=\"", w->out);
    w->col = 0;
    w->numlast = 0;
}

static void d_end(svgw *w) { fputs("\"/>\n", w->out); }

static void d_cmd(svgw *w, char letter) {
    if (w->col > 200) { fputc('\n', w->out); w->col = 0; }
    fputc(letter, w->out);
    w->col++;
    w->numlast = 0;
}

/* a number, separated from the previous one by a space unless its sign separates it */
static void d_num(svgw *w, long v) {
    char b[32];
    int n = fmt_num(b, v);
    if (w->col > 200 && b[0] != '-') {
        fputc('\n', w->out);
        w->col = 0;
    } else if (w->numlast && b[0] != '-') {
        fputc(' ', w->out);
        w->col++;
    }
    fputs(b, w->out);
    w->col += n;
    w->numlast = 1;
}

static void d_move(svgw *w, hpt p) {
    d_cmd(w, 'M');
    d_num(w, p.x);
    d_num(w, p.y);
    w->cur = p;
}

/* after d_cmd the next number needs no separator */
static void d_letter(svgw *w, char letter) {
    d_cmd(w, letter);
}

static void flush_layer(svgw *w);

/* ---- clip groups -------------------------------------------------------------------------- */

static int is_full(const svgw *w, size_t k) {
    const pc_rect *r = &w->c->clips[k].r;
    return r->x0 <= 0 && r->y0 <= 0 && r->x1 >= w->c->width - 1 && r->y1 >= w->c->height - 1;
}

/* The clip of the op being written (every op is written in its turn: w->clip follows). */
static pc_rect clip_of(const svgw *w, const pc_op *op) {
    (void)op;
    if (w->clip < w->c->nclips) return w->c->clips[w->clip].r;
    return (pc_rect){0, 0, w->c->width - 1, w->c->height - 1};
}

/* canon[k]: the first clip with clip k's rectangle, found through a hash of the rectangles,
 * so a drawing with a million VIEW changes is written in linear time. */
static int make_canon(svgw *w) {
    size_t n = w->c->nclips, slots = 16;
    while (slots < 2 * n) slots *= 2;
    size_t *table = malloc(slots * sizeof *table);
    w->canon = malloc((n ? n : 1) * sizeof *w->canon);
    if (!table || !w->canon) { free(table); return 0; }
    for (size_t i = 0; i < slots; i++) table[i] = SIZE_MAX;
    for (size_t k = 0; k < n; k++) {
        const pc_rect *r = &w->c->clips[k].r;
        uint64_t h = (uint64_t)(uint32_t)r->x0 * 73856093u ^ (uint64_t)(uint32_t)r->y0 * 19349663u ^
                     (uint64_t)(uint32_t)r->x1 * 83492791u ^ (uint64_t)(uint32_t)r->y1 * 2654435761u;
        size_t s = (size_t)(h * 0x9E3779B97F4A7C15ull >> 20) & (slots - 1);
        while (table[s] != SIZE_MAX &&
               memcmp(&w->c->clips[table[s]].r, r, sizeof *r) != 0)
            s = (s + 1) & (slots - 1);
        if (table[s] == SIZE_MAX) table[s] = k;
        w->canon[k] = table[s];
    }
    free(table);
    return 1;
}

/* Make sure the elements that follow are inside the group clipping to the current clip. */
static void enter_clip(svgw *w, const pc_op *op) {
    (void)op;
    int k = -1;   /* the same rectangle may appear under several indices: the first is its id */
    if (w->clip < w->c->nclips && !is_full(w, w->clip)) k = (int)w->canon[w->clip];
    if (k == w->group) return;
    flush_layer(w);
    if (w->group >= 0) fputs("</g>\n", w->out);
    w->group = k;
    if (k < 0) return;
    if (!w->clip_done[k]) {
        const pc_rect *r = &w->c->clips[k].r;
        fprintf(w->out, "<clipPath id=\"c%d\"><rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\"/></clipPath>\n",
                k, r->x0, r->y0, r->x1 - r->x0 + 1, r->y1 - r->y0 + 1);
        w->clip_done[k] = 1;
    }
    fprintf(w->out, "<g clip-path=\"url(#c%d)\">\n", k);
}

/* ---- growable point lists ----------------------------------------------------------------- */

static void push(svgw *w, hpt **buf, size_t *n, size_t *cap, hpt p) {
    if (*n == *cap) {
        size_t nc = *cap ? *cap * 2 : 256;
        hpt *g = realloc(*buf, nc * sizeof *g);
        if (!g) { w->nomem = 1; return; }
        *buf = g;
        *cap = nc;
    }
    (*buf)[(*n)++] = p;
}

static void add_point(svgw *w, double x, double y) {
    hpt p = {hund(x), hund(y)};
    if (w->npts && w->pts[w->npts - 1].x == p.x && w->pts[w->npts - 1].y == p.y) return;
    push(w, &w->pts, &w->npts, &w->cappts, p);
}

/* ---- the pixel layer ---------------------------------------------------------------------- */

/* Isolated dots are exact pixels, as the raster has them.  Pixels do not overlap one another,
 * so the dots collected since the last other element only need their final colour per pixel
 * (the last dot wins) and can be written grouped by colour, one path per colour with
 * horizontal runs of pixels merged.  The layer is written out before any other element, so
 * the painter's order of the display list is kept exactly. */
static void add_dot(svgw *w, double x, double y, int color, pc_rect clip) {
    long ix = pc_px(x), iy = pc_px(y);
    if (ix < clip.x0 || ix > clip.x1 || iy < clip.y0 || iy > clip.y1) return;
    if (w->nlayer == w->caplayer) {
        size_t nc = w->caplayer ? w->caplayer * 2 : 1024;
        layer_px *g = realloc(w->layer, nc * sizeof *g);
        if (!g) { w->nomem = 1; return; }
        w->layer = g;
        w->caplayer = nc;
    }
    w->layer[w->nlayer] = (layer_px){(uint32_t)(iy * w->c->width + ix), (uint32_t)w->nlayer,
                                     (uint16_t)color};
    w->nlayer++;
}

static int by_pixel_then_order(const void *a, const void *b) {
    const layer_px *p = a, *q = b;
    if (p->idx != q->idx) return p->idx < q->idx ? -1 : 1;
    return p->seq < q->seq ? -1 : p->seq > q->seq;
}

static int by_color_then_pixel(const void *a, const void *b) {
    const layer_px *p = a, *q = b;
    if (p->color != q->color) return p->color < q->color ? -1 : 1;
    return p->idx < q->idx ? -1 : p->idx > q->idx;
}

static void flush_layer(svgw *w) {
    if (!w->nlayer) return;
    layer_px *L = w->layer;
    size_t n = w->nlayer;
    qsort(L, n, sizeof *L, by_pixel_then_order);
    size_t k = 0;   /* keep the last dot of each pixel */
    for (size_t i = 0; i < n; i++) {
        if (i + 1 < n && L[i + 1].idx == L[i].idx) continue;
        L[k++] = L[i];
    }
    n = k;
    qsort(L, n, sizeof *L, by_color_then_pixel);
    long W = w->c->width;
    for (size_t i = 0; i < n;) {
        int color = L[i].color;
        fputs("<path", w->out);
        color_attr(w, "fill", color);
        fputs(" shape-rendering=\"crispEdges\"", w->out);
        d_begin(w);
        int first = 1;
        while (i < n && L[i].color == color) {
            size_t j = i + 1;   /* a horizontal run of pixels of this colour */
            while (j < n && L[j].color == color && L[j].idx == L[j - 1].idx + 1 &&
                   (long)(L[j].idx % W) != 0)
                j++;
            hpt p = {(long)(L[i].idx % W) * 100, (long)(L[i].idx / W) * 100};
            if (first) d_move(w, p);
            else {
                d_letter(w, 'm');
                d_num(w, p.x - w->cur.x);
                d_num(w, p.y - w->cur.y);
                w->cur = p;
            }
            first = 0;
            long len = (long)(j - i) * 100;
            d_letter(w, 'h'); d_num(w, len);
            d_letter(w, 'v'); d_num(w, 100);
            d_letter(w, 'h'); d_num(w, -len);
            d_letter(w, 'z');
            i = j;
        }
        d_end(w);
    }
    w->nlayer = 0;
}

/* Every element other than the pixel layer starts here, after the layer is written. */
static void open_el(svgw *w, const char *tag) {
    flush_layer(w);
    fprintf(w->out, "<%s", tag);
}

/* ---- runs of dots ------------------------------------------------------------------------- */

/* Streaming polyline simplification by sleeve fitting: from the anchor, keep the wedge of
 * directions that passes within TOL of every dot seen since; when a dot falls outside it (or
 * the run turns back), the last dot that fitted becomes a vertex and the new anchor. */
typedef struct {
    double ax, ay;             /* anchor (already emitted) */
    int has_cand; double cx, cy, maxd, lo, hi;
    int has_pending; double px, py;
} sleeve;

static void sleeve_start(svgw *w, sleeve *s, double x, double y) {
    memset(s, 0, sizeof *s);
    s->ax = x;
    s->ay = y;
    w->npts = 0;
    add_point(w, x, y);
}

static void sleeve_add(svgw *w, sleeve *s, double x, double y) {
    for (;;) {
        double dx = x - s->ax, dy = y - s->ay, d = hypot(dx, dy);
        if (!s->has_cand) {
            if (d <= TOL) {
                s->has_pending = 1;
                s->px = x;
                s->py = y;
                return;
            }
            double th = atan2(dy, dx), de = asin(TOL / d);
            s->lo = th - de;
            s->hi = th + de;
            s->has_cand = 1;
            s->has_pending = 0;
            s->cx = x;
            s->cy = y;
            s->maxd = d;
            return;
        }
        if (d > TOL && d >= s->maxd) {
            double th = atan2(dy, dx), mid = (s->lo + s->hi) / 2;
            th += TWO_PI * rint((mid - th) / TWO_PI);
            if (th >= s->lo && th <= s->hi) {
                double de = asin(TOL / d);
                if (th - de > s->lo) s->lo = th - de;
                if (th + de < s->hi) s->hi = th + de;
                s->cx = x;
                s->cy = y;
                s->maxd = d;
                return;
            }
        }
        /* does not fit: the candidate becomes a vertex; try again from it */
        add_point(w, s->cx, s->cy);
        s->ax = s->cx;
        s->ay = s->cy;
        s->has_cand = s->has_pending = 0;
    }
}

static void sleeve_end(svgw *w, sleeve *s) {
    if (s->has_cand) add_point(w, s->cx, s->cy);
    else if (s->has_pending) add_point(w, s->px, s->py);
}

static void emit_polyline(svgw *w, int color, double width) {
    open_el(w, "path");
    color_attr(w, "stroke", color);
    fputs(" stroke-linejoin=\"round\"", w->out);
    if (width != 1) {
        char buf[32];
        fmt_num(buf, hund(width));
        fprintf(w->out, " stroke-width=\"%s\" stroke-linecap=\"round\"", buf);
    }
    d_begin(w);
    d_move(w, w->pts[0]);
    d_letter(w, 'l');
    for (size_t i = 1; i < w->npts; i++) {
        d_num(w, w->pts[i].x - w->cur.x);
        d_num(w, w->pts[i].y - w->cur.y);
        w->cur = w->pts[i];
    }
    d_end(w);
}

/* The simplified polyline through the pixel centres of d[0..n), into w->pts. */
static void fit_polyline(svgw *w, const pc_xy *d, size_t n) {
    sleeve s;
    sleeve_start(w, &s, d[0].x + 0.5, d[0].y + 0.5);
    for (size_t i = 1; i < n; i++) sleeve_add(w, &s, d[i].x + 0.5, d[i].y + 0.5);
    sleeve_end(w, &s);
}

/* One dense subrun d[0..n): a polyline, or an isolated dot if it has no extent. */
static void dense_subrun(svgw *w, const pc_xy *d, size_t n, int color, pc_rect clip) {
    fit_polyline(w, d, n);
    if (w->nomem) return;
    int extent = w->npts > 2 ||
                 (w->npts == 2 && hypot((double)(w->pts[1].x - w->pts[0].x),
                                        (double)(w->pts[1].y - w->pts[0].y)) > TOL * 100);
    if (extent) emit_polyline(w, color, 1);
    else add_dot(w, d[0].x, d[0].y, color, clip);
}

static int far_outside(double x, double y, pc_rect r) {
    /* x, y: pixel-centre coordinates; the clip covers r.x0 .. r.x1 + 1 */
    return x < r.x0 - MARGIN || x > r.x1 + 1 + MARGIN || y < r.y0 - MARGIN || y > r.y1 + 1 + MARGIN;
}

/* The end of the dense run that starts at d[i] (not far outside the clip): consecutive
 * points at most `dense` px apart, none of them far outside. */
static size_t run_end(const pc_xy *d, size_t i, size_t n, double dense, pc_rect clip) {
    size_t j = i + 1;
    while (j < n && hypot(d[j].x - d[j - 1].x, d[j].y - d[j - 1].y) <= dense &&
           !far_outside(d[j].x + 0.5, d[j].y + 0.5, clip))
        j++;
    return j;
}

/* A DOTS run: split where consecutive dots are further apart than DENSE. */
static void emit_dots(svgw *w, const pc_op *op) {
    pc_rect clip = clip_of(w, op);
    if ((size_t)op->first + op->count > w->c->ndots) return;
    const pc_xy *d = w->c->dots + op->first;
    size_t n = op->count, i = 0;
    while (i < n) {
        if (far_outside(d[i].x + 0.5, d[i].y + 0.5, clip)) { i++; continue; }
        size_t j = run_end(d, i, n, DENSE, clip);
        if (j - i == 1) add_dot(w, d[i].x, d[i].y, op->color, clip);
        else dense_subrun(w, d + i, j - i, op->color, clip);
        i = j;
    }
}

/* PIXELS: dots folded into whole pixels (dotfold.c) join the layer of exact pixels, as
 * isolated dots do: the same pixels, grouped by colour into horizontal runs. */
static void emit_pixels(svgw *w, const pc_op *op) {
    const pc_canvas *c = w->c;
    if ((size_t)op->first + op->count > c->nlpx) return;
    pc_rect clip = clip_of(w, op);
    long W = c->width;
    for (size_t i = op->first; i < (size_t)op->first + op->count && !w->nomem; i++)
        add_dot(w, (double)(c->lpx[i].idx % W), (double)(c->lpx[i].idx / W), c->lpx[i].color,
                clip);
}

/* ---- runs of brushes ---------------------------------------------------------------------- */

static int is_brush(const pc_op *op) {
    return op->kind == PC_OP_ARC && (op->flags & PC_ARC_FULL) && op->rx == op->ry &&
           op->rx > 0 && op->rx <= BRUSH_R && op->pen == 0;
}

static void emit_arc(svgw *w, const pc_op *op);

/* ops[0..n): brushes of one colour, radius and clip. */
static void emit_brushes(svgw *w, const pc_op *ops, size_t n) {
    pc_rect clip = clip_of(w, &ops[0]);
    /* the ring of radius r covers the pixels from the centre - round(r) to centre + round(r) */
    double width = 2 * lrint(ops[0].rx) + 1;
    /* the centres, so that runs split and fit exactly as dots do */
    pc_xy *d = malloc(n * sizeof *d);
    if (!d) { w->nomem = 1; return; }
    for (size_t k = 0; k < n; k++) d[k] = (pc_xy){ops[k].x1, ops[k].y1};
    size_t i = 0;
    while (i < n && !w->nomem) {
        if (far_outside(d[i].x + 0.5, d[i].y + 0.5, clip)) { i++; continue; }
        size_t j = run_end(d, i, n, BRUSH_DENSE, clip);
        if (j - i < 3) {
            for (size_t k = i; k < j; k++) emit_arc(w, &ops[k]);
        } else {
            fit_polyline(w, d + i, j - i);
            if (w->nomem) break;
            if (w->npts == 1) add_point(w, d[i].x + 0.5, d[i].y + 0.5);
            emit_polyline(w, ops[i].color, width);
        }
        i = j;
    }
    free(d);
}

/* ---- the pen ------------------------------------------------------------------------------ */

static const pc_stroke *pen_of(const svgw *w, const pc_op *op) {
    return op->pen < w->c->npens ? &w->c->pens[op->pen] : &w->c->pens[0];
}

static int is_styled(const svgw *w, const pc_op *op) {
    return (op->kind == PC_OP_LINE || op->kind == PC_OP_BOX) && pen_of(w, op)->style;
}

/* How far outside the clip a stroke of op may start and still show. */
static double margin_of(const svgw *w, const pc_op *op) {
    double width = pen_of(w, op)->width;
    return width > 1 ? MARGIN + width / 2 : MARGIN;
}

/* The pen's attributes (none for the default pen, so plain figures stay as they were).  The
 * raster puts a pixel (or a disc) at every point of the stroke whose distance lies in a dash,
 * so a dash of length L covers L pixels: in SVG each dash is drawn 1 px shorter and each gap
 * 1 px longer, and the caps (square, or round when wide), half the width at each end, make up
 * the pixel centres' extent: exactly the raster's pixels along an axis. */
static void pen_attrs(svgw *w, const pc_op *op, int join) {
    const pc_stroke *p = pen_of(w, op);
    char b[32];
    if (p->width != 1) {
        fmt_num(b, hund(p->width));
        fprintf(w->out, " stroke-width=\"%s\" stroke-linecap=\"round\"", b);
        if (join) fputs(" stroke-linejoin=\"round\"", w->out);   /* unless the element has it */
    }
    if (!p->ndash) return;
    fputs(" stroke-dasharray=\"", w->out);
    for (int i = 0; i < p->ndash; i++) {
        double v = i % 2 ? p->dash[i] + 1 : fmax(p->dash[i] - 1, 0);
        fmt_num(b, hund(v));
        fprintf(w->out, "%s%s", i ? " " : "", b);
    }
    fputc('"', w->out);
}

/* A LINE or BOX with QBasic's style: the exact pixels, as the raster has them. */
typedef struct { svgw *w; int color; pc_rect clip; } styled_ctx;

static void styled_dot(void *ctx, long x, long y) {
    styled_ctx *s = ctx;
    add_dot(s->w, (double)x, (double)y, s->color, s->clip);
}

static void emit_styled(svgw *w, const pc_op *op) {
    styled_ctx s = {w, op->color, clip_of(w, op)};
    pc_styled_pixels(w->c, op, styled_dot, &s);
}

/* ---- runs of lines ------------------------------------------------------------------------ */

/* ops[0..n): LINEs of one colour, pen and clip, as one path.  With a dashed pen every LINE is
 * its own subpath, as the dash pattern restarts at each LINE in the raster. */
static void emit_lines(svgw *w, const pc_op *ops, size_t n) {
    pc_rect clip = clip_of(w, &ops[0]);
    int pen = ops[0].pen, dashed = pen_of(w, &ops[0])->ndash > 0;
    double m = margin_of(w, &ops[0]);
    int open = 0;
    for (size_t i = 0; i < n; i++) {
        const pc_op *op = &ops[i];
        if (pen == 0 && op->x1 == op->x2 && op->y1 == op->y2) {   /* one pixel */
            add_dot(w, op->x1, op->y1, op->color, clip);
            continue;
        }
        double x0 = op->x1 + 0.5, y0 = op->y1 + 0.5, x1 = op->x2 + 0.5, y1 = op->y2 + 0.5;
        if (!pc_clip_segment(&x0, &y0, &x1, &y1, clip.x0 - m, clip.y0 - m,
                          clip.x1 + 1 + m, clip.y1 + 1 + m))
            continue;
        hpt a = {hund(x0), hund(y0)}, b = {hund(x1), hund(y1)};
        if (pen == 0 && a.x == b.x && a.y == b.y) {
            add_dot(w, op->x1, op->y1, op->color, clip);
            continue;
        }
        if (!open) {
            open_el(w, "path");
            color_attr(w, "stroke", op->color);
            fputs(" stroke-linejoin=\"round\"", w->out);
            pen_attrs(w, op, 0);
            d_begin(w);
            d_move(w, a);
            d_letter(w, 'l');
            open = 1;
        } else if (dashed || a.x != w->cur.x || a.y != w->cur.y) {
            d_letter(w, 'm');    /* the pairs after a relative move are relative lines */
            d_num(w, a.x - w->cur.x);
            d_num(w, a.y - w->cur.y);
        }
        d_num(w, b.x - a.x);
        d_num(w, b.y - a.y);
        w->cur = b;
    }
    if (open) d_end(w);
}

/* ---- boxes -------------------------------------------------------------------------------- */

static void fill_rect(svgw *w, long x0, long y0, long x1, long y1, int color) {
    open_el(w, "rect");
    fprintf(w->out, " x=\"%ld\" y=\"%ld\" width=\"%ld\" height=\"%ld\"", x0, y0, x1 - x0 + 1,
            y1 - y0 + 1);
    color_attr(w, "fill", color);
    fputs(" shape-rendering=\"crispEdges\"/>\n", w->out);
}

/* BOX, FILLBOX and CLEAR cover whole pixels, exactly as rasterised. */
static void emit_box(svgw *w, const pc_op *op) {
    pc_rect clip = clip_of(w, op);
    long x0 = pc_px(op->x1), y0 = pc_px(op->y1), x1 = pc_px(op->x2), y1 = pc_px(op->y2);
    if (x0 > x1) { long t = x0; x0 = x1; x1 = t; }
    if (y0 > y1) { long t = y0; y0 = y1; y1 = t; }
    if (x1 < clip.x0 || x0 > clip.x1 || y1 < clip.y0 || y0 > clip.y1) return;
    if (op->kind != PC_OP_BOX) {
        if (x0 < clip.x0) x0 = clip.x0;
        if (y0 < clip.y0) y0 = clip.y0;
        if (x1 > clip.x1) x1 = clip.x1;
        if (y1 > clip.y1) y1 = clip.y1;
        fill_rect(w, x0, y0, x1, y1, op->color);
        return;
    }
    /* sides far outside the clip move to just outside it: still invisible, numbers stay small */
    long m = 2 + (long)ceil(pen_of(w, op)->width / 2);
    if (x0 < clip.x0 - m) x0 = clip.x0 - m;
    if (y0 < clip.y0 - m) y0 = clip.y0 - m;
    if (x1 > clip.x1 + m) x1 = clip.x1 + m;
    if (y1 > clip.y1 + m) y1 = clip.y1 + m;
    if (op->pen != 0) {   /* a path, so a flat box still strokes and dashes run round it */
        open_el(w, "path");
        color_attr(w, "stroke", op->color);
        pen_attrs(w, op, 1);
        d_begin(w);
        d_move(w, (hpt){x0 * 100 + 50, y0 * 100 + 50});
        d_letter(w, 'H'); d_num(w, x1 * 100 + 50);
        d_letter(w, 'V'); d_num(w, y1 * 100 + 50);
        d_letter(w, 'H'); d_num(w, x0 * 100 + 50);
        d_letter(w, 'Z');
        d_end(w);
        return;
    }
    if (x0 == x1 || y0 == y1) {   /* a flat box is a row or column of pixels */
        fill_rect(w, x0, y0, x1, y1, op->color);
        return;
    }
    open_el(w, "rect");
    fprintf(w->out, " x=\"%ld.5\" y=\"%ld.5\" width=\"%ld\" height=\"%ld\"", x0, y0, x1 - x0,
            y1 - y0);
    color_attr(w, "stroke", op->color);
    fputs("/>\n", w->out);
}

/* ---- circles, ellipses, arcs -------------------------------------------------------------- */

static void emit_arc(svgw *w, const pc_op *op) {
    pc_rect clip = clip_of(w, op);
    double cx = op->x1 + 0.5, cy = op->y1 + 0.5, rx = fabs(op->rx), ry = fabs(op->ry);
    if (!isfinite(cx) || !isfinite(cy) || !isfinite(rx) || !isfinite(ry)) return;
    if (lrint(rx) == 0 && lrint(ry) == 0) {   /* radius 0: the centre pixel */
        add_dot(w, op->x1, op->y1, op->color, clip);
        return;
    }
    /* wholly outside the clip: nothing to draw */
    double m = margin_of(w, op);
    if (cx + rx < clip.x0 - m || cx - rx > clip.x1 + 1 + m || cy + ry < clip.y0 - m ||
        cy - ry > clip.y1 + 1 + m)
        return;
    long hcx = hund(cx), hcy = hund(cy), hrx = hund(rx), hry = hund(ry);
    /* a dashed full ellipse is a path from angle 0 counter-clockwise, where the raster starts
     * its dashes (a <circle> would start them clockwise) */
    int dashed = pen_of(w, op)->ndash > 0;
    if ((op->flags & PC_ARC_FULL) && !dashed) {
        if (hrx == hry) {
            open_el(w, "circle");
            put_attr_num(w, "cx", hcx);
            put_attr_num(w, "cy", hcy);
            put_attr_num(w, "r", hrx);
        } else {
            open_el(w, "ellipse");
            put_attr_num(w, "cx", hcx);
            put_attr_num(w, "cy", hcy);
            put_attr_num(w, "rx", hrx);
            put_attr_num(w, "ry", hry);
        }
        color_attr(w, "stroke", op->color);
        pen_attrs(w, op, 1);
        fputs("/>\n", w->out);
        return;
    }
    /* counter-clockwise on the screen (y up sense) from a0 to a1: sweep-flag 0 in SVG */
    double a0 = op->a0, a1 = op->a1;
    double ext = a1 >= a0 ? a1 - a0 : a1 - a0 + TWO_PI;
    hpt c = {hcx, hcy};
    hpt p0 = {hund(cx + rx * cos(a0)), hund(cy - ry * sin(a0))};
    hpt p1 = {hund(cx + rx * cos(a1)), hund(cy - ry * sin(a1))};
    open_el(w, "path");
    color_attr(w, "stroke", op->color);
    pen_attrs(w, op, 1);
    d_begin(w);
    if (op->flags & PC_ARC_RADIUS0) {
        d_move(w, c);
        d_letter(w, 'L');
        d_num(w, p0.x);
        d_num(w, p0.y);
    } else {
        d_move(w, p0);
    }
    /* an arc of (nearly) a whole turn is drawn as two halves: A needs distinct end points */
    int halves = ext > TWO_PI - 1e-4 || (p0.x == p1.x && p0.y == p1.y && ext > 1);
    double am = a0 + ext / 2;
    hpt pm = {hund(cx + rx * cos(am)), hund(cy - ry * sin(am))};
    for (int k = halves ? 0 : 1; k < 2; k++) {
        hpt to = (halves && k == 0) ? pm : p1;
        int large = !halves && ext > TWO_PI / 2;
        d_letter(w, 'A');
        d_num(w, hrx);
        d_num(w, hry);
        d_num(w, 0);
        d_num(w, large * 100);
        d_num(w, 0);
        d_num(w, to.x);
        d_num(w, to.y);
    }
    if (op->flags & PC_ARC_RADIUS1) {
        if (op->flags & PC_ARC_RADIUS0) d_letter(w, 'Z');
        else {
            d_letter(w, 'L');
            d_num(w, c.x);
            d_num(w, c.y);
        }
    }
    d_end(w);
}

/* ---- painted regions ---------------------------------------------------------------------- */

/* The outline of the painted pixels.  Boundary edges run clockwise on the screen around the
 * region (inside on the right), so holes run the other way and the nonzero rule leaves them
 * empty.  At a vertex where two inside pixels touch only diagonally the trace turns right,
 * hugging the pixel it follows.  Directions: 0 +x, 1 +y, 2 -x, 3 -y. */
static void emit_fill(svgw *w, const pc_op *op) {
    const pc_canvas *c = w->c;
    if (op->count == 0 || (size_t)op->first + op->count > c->nspans) return;
    const pc_span *sp = c->spans + op->first;
    long minx = sp[0].x0, maxx = sp[0].x1, miny = sp[0].y, maxy = sp[0].y;
    for (uint32_t i = 1; i < op->count; i++) {
        if (sp[i].x0 < minx) minx = sp[i].x0;
        if (sp[i].x1 > maxx) maxx = sp[i].x1;
        if (sp[i].y < miny) miny = sp[i].y;
        if (sp[i].y > maxy) maxy = sp[i].y;
    }
    /* the mask has a border of one empty pixel all round */
    long W = maxx - minx + 3, H = maxy - miny + 3;
    unsigned char *m = calloc((size_t)W * H, 1);
    if (!m) { w->nomem = 1; return; }
    for (uint32_t i = 0; i < op->count; i++)
        if (sp[i].x1 >= sp[i].x0)
            memset(m + (size_t)(sp[i].y - miny + 1) * W + (sp[i].x0 - minx + 1), 1,
                   (size_t)(sp[i].x1 - sp[i].x0 + 1));
#define IN(X, Y) (m[(size_t)(Y) * W + (X)] & 1)
#define TOP_DONE 2
    static const int DX[4] = {1, 0, -1, 0}, DY[4] = {0, 1, 0, -1};
    open_el(w, "path");
    color_attr(w, "fill", op->color);
    fputs(" shape-rendering=\"crispEdges\"", w->out);
    d_begin(w);
    for (long y = 1; y < H - 1; y++)
        for (long x = 1; x < W - 1; x++) {
            if (!IN(x, y) || IN(x, y - 1) || (m[y * W + x] & TOP_DONE)) continue;
            long vx = x, vy = y;
            d_move(w, (hpt){(vx - 1 + minx) * 100, (vy - 1 + miny) * 100});
            int dir = 0;
            long len = 0;
            /* a loop has at most 4 edges per pixel: the bound only guards against a bug */
            for (long steps = 0; steps <= 4 * W * H; steps++) {
                if (dir == 0) m[vy * W + vx] |= TOP_DONE;   /* top edge of pixel (vx, vy) */
                vx += DX[dir];
                vy += DY[dir];
                len++;
                int a = IN(vx - 1, vy - 1), b = IN(vx, vy - 1), cc = IN(vx - 1, vy), d = IN(vx, vy);
                int exists[4] = {d && !b, cc && !d, a && !cc, b && !a};
                int nd = -1;
                for (int t = 1; t >= -1; t--) {   /* right, straight, left */
                    int cand = (dir + t + 4) % 4;
                    if (exists[cand]) { nd = cand; break; }
                }
                int closing = vx == x && vy == y && nd == 0;
                if (nd != dir || closing) {
                    if (!(closing && dir != 0)) {   /* the last side is drawn by z */
                        d_letter(w, (dir & 1) ? 'v' : 'h');
                        d_num(w, (dir >= 2 ? -len : len) * 100);
                    }
                    dir = nd;
                    len = 0;
                }
                if (closing || nd < 0) break;
            }
            d_letter(w, 'z');
        }
#undef IN
#undef TOP_DONE
    d_end(w);
    free(m);
}

/* ---- paths -------------------------------------------------------------------------------- */

/* Coordinates up to this far from the screen are written as they are (hundredths fit); a
 * segment reaching further is cut to the clip first, a cubic flattened and cut. */
#define NEAR_PX 1e6

static int near_pt(pc_xy p) { return fabs(p.x) <= NEAR_PX && fabs(p.y) <= NEAR_PX; }

typedef struct {
    svgw *w;
    pc_rect clip;
    double m;
    int broken;    /* a cut moved the current point: the subpath no longer ends where it began */
} path_out;

static void path_line(path_out *o, pc_xy a, pc_xy b) {
    svgw *w = o->w;
    double x0 = a.x + 0.5, y0 = a.y + 0.5, x1 = b.x + 0.5, y1 = b.y + 0.5;
    if (!near_pt(a) || !near_pt(b)) {
        if (!pc_clip_segment(&x0, &y0, &x1, &y1, o->clip.x0 - o->m, o->clip.y0 - o->m,
                             o->clip.x1 + 1 + o->m, o->clip.y1 + 1 + o->m)) {
            o->broken = 1;
            return;
        }
    }
    hpt p = {hund(x0), hund(y0)}, q = {hund(x1), hund(y1)};
    if (p.x != w->cur.x || p.y != w->cur.y) {
        d_move(w, p);
        o->broken = 1;
    }
    d_letter(w, 'L');
    d_num(w, q.x);
    d_num(w, q.y);
    w->cur = q;
}

static void path_cubic(path_out *o, const pc_xy q[4]) {
    svgw *w = o->w;
    if (near_pt(q[0]) && near_pt(q[1]) && near_pt(q[2]) && near_pt(q[3])) {
        d_letter(w, 'C');
        for (int k = 1; k <= 3; k++) {
            d_num(w, hund(q[k].x + 0.5));
            d_num(w, hund(q[k].y + 0.5));
        }
        w->cur = (hpt){hund(q[3].x + 0.5), hund(q[3].y + 0.5)};
        return;
    }
    int n = pc_cubic_segments(q, 0.1);
    pc_xy a = q[0];
    for (int j = 1; j <= n; j++) {
        pc_xy b = j == n ? q[3] : pc_cubic_at(q, (double)j / n);
        path_line(o, a, b);
        a = b;
    }
}

/* The end of a subpath that started at p0, the current point being `cur`. */
static void path_close(path_out *o, int closed, pc_xy cur, pc_xy p0) {
    if (!closed) return;
    if (o->broken) path_line(o, cur, p0);
    else d_letter(o->w, 'Z');
}

/* Is the path's hull (its points, controls included) near the clip? */
static int path_near_clip(const pc_xy *p, size_t n, pc_rect clip, double m) {
    double x0 = p[0].x, x1 = p[0].x, y0 = p[0].y, y1 = p[0].y;
    for (size_t i = 1; i < n; i++) {
        x0 = fmin(x0, p[i].x); x1 = fmax(x1, p[i].x);
        y0 = fmin(y0, p[i].y); y1 = fmax(y1, p[i].y);
    }
    return !(x1 + 0.5 < clip.x0 - m || x0 + 0.5 > clip.x1 + 1 + m || y1 + 0.5 < clip.y0 - m ||
             y0 + 0.5 > clip.y1 + 1 + m);
}

/* A PATH: one <path> with M, L and C commands (absolute), Z closing each subpath if asked. */
static void emit_path(svgw *w, const pc_op *op) {
    const pc_canvas *c = w->c;
    if (op->count == 0 || (size_t)op->first + op->count > c->npts) return;
    const pc_xy *p = c->pts + op->first;
    const uint8_t *tag = c->tags + op->first;
    path_out o = {w, clip_of(w, op), margin_of(w, op), 0};
    if (!path_near_clip(p, op->count, o.clip, o.m)) return;
    int closed = op->flags & PC_PATH_CLOSED;
    open_el(w, "path");
    color_attr(w, "stroke", op->color);
    fputs(" stroke-linejoin=\"round\"", w->out);
    pen_attrs(w, op, 0);
    d_begin(w);
    pc_xy cur = p[0], start = p[0];
    size_t nsub = 0;
    for (size_t i = 0; i < op->count;) {
        if (tag[i] == PC_PATH_MOVE) {
            if (nsub > 1) path_close(&o, closed, cur, start);
            start = cur = p[i++];
            nsub = 1;
            o.broken = 0;
            if (near_pt(cur)) d_move(w, (hpt){hund(cur.x + 0.5), hund(cur.y + 0.5)});
            else o.broken = 1;   /* the first segment moves to where it enters */
        } else if (tag[i] == PC_PATH_LINE) {
            path_line(&o, cur, p[i]);
            cur = p[i++];
            nsub++;
        } else {
            const pc_xy q[4] = {cur, p[i], p[i + 1], p[i + 2]};
            path_cubic(&o, q);
            cur = q[3];
            i += 3;
            nsub += 3;
        }
    }
    if (nsub > 1) path_close(&o, closed, cur, start);
    d_end(w);
}

/* ---- filled paths ------------------------------------------------------------------------- */

/* A subpath reaching beyond NEAR_PX is flattened and cut to the clip rectangle grown by
 * MARGIN (Sutherland-Hodgman, one side at a time): the cut replaces what lies outside by
 * pieces of the rectangle's sides, which keeps the winding number of every point inside it,
 * so either fill rule fills the same pixels there. */
typedef struct { double *v; size_t n, cap; } poly_buf;

static int poly_push(poly_buf *b, double x, double y) {
    if (!pc_grow((void **)&b->v, &b->cap, 2 * (b->n + 1), sizeof *b->v)) return 0;
    b->v[2 * b->n] = x;
    b->v[2 * b->n + 1] = y;
    b->n++;
    return 1;
}

/* Keep the part of the closed polygon in with coordinate `axis` (0: x, 1: y) on the side
 * sign * (coord - lim) <= 0; the result goes to out. */
static int poly_cut(const poly_buf *in, poly_buf *out, int axis, double lim, double sign) {
    out->n = 0;
    for (size_t i = 0; i < in->n; i++) {
        const double *a = in->v + 2 * i, *b = in->v + 2 * ((i + 1) % in->n);
        double da = sign * (a[axis] - lim), db = sign * (b[axis] - lim);
        if (da <= 0 && !poly_push(out, a[0], a[1])) return 0;
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
            double t = da / (da - db);
            double x = axis == 0 ? lim : a[0] + t * (b[0] - a[0]);
            double y = axis == 1 ? lim : a[1] + t * (b[1] - a[1]);
            if (!poly_push(out, x, y)) return 0;
        }
    }
    return 1;
}

/* Write the flattened subpath in buf (SVG coordinates) cut to r: M, L..., Z. */
static void emit_cut_subpath(svgw *w, poly_buf *buf, poly_buf *tmp, const double r[4]) {
    const int axis[4] = {0, 0, 1, 1};
    const double sign[4] = {-1, 1, -1, 1};
    for (int k = 0; k < 4 && buf->n; k++) {
        if (!poly_cut(buf, tmp, axis[k], r[k], sign[k])) { w->nomem = 1; return; }
        poly_buf t = *buf; *buf = *tmp; *tmp = t;
    }
    if (buf->n < 3) return;
    for (size_t i = 0; i < buf->n; i++) {
        hpt p = {hund(buf->v[2 * i]), hund(buf->v[2 * i + 1])};
        if (i == 0) d_move(w, p);
        else {
            d_letter(w, 'L');
            d_num(w, p.x);
            d_num(w, p.y);
        }
    }
    d_letter(w, 'Z');
}

/* The far case: every subpath flattened (cubics to 0.1 px) and cut. */
static void emit_fill_far(svgw *w, const pc_xy *p, const uint8_t *tag, size_t n, pc_rect clip) {
    const double r[4] = {clip.x0 - MARGIN, clip.x1 + 1 + MARGIN, clip.y0 - MARGIN,
                         clip.y1 + 1 + MARGIN};
    poly_buf buf = {0}, tmp = {0};
    pc_xy cur = p[0];
    for (size_t i = 0; i < n && !w->nomem;) {
        if (tag[i] == PC_PATH_MOVE) {
            if (buf.n) emit_cut_subpath(w, &buf, &tmp, r);
            buf.n = 0;
            cur = p[i++];
            if (!poly_push(&buf, cur.x + 0.5, cur.y + 0.5)) w->nomem = 1;
        } else if (tag[i] == PC_PATH_LINE) {
            cur = p[i++];
            if (!poly_push(&buf, cur.x + 0.5, cur.y + 0.5)) w->nomem = 1;
        } else {
            const pc_xy q[4] = {cur, p[i], p[i + 1], p[i + 2]};
            int k = pc_cubic_segments(q, 0.1);
            for (int j = 1; j <= k && !w->nomem; j++) {
                pc_xy e = j == k ? q[3] : pc_cubic_at(q, (double)j / k);
                if (!poly_push(&buf, e.x + 0.5, e.y + 0.5)) w->nomem = 1;
            }
            cur = q[3];
            i += 3;
        }
    }
    if (buf.n && !w->nomem) emit_cut_subpath(w, &buf, &tmp, r);
    free(buf.v);
    free(tmp.v);
}

/* A FILLPATH: one filled <path> (every subpath closed by Z), its fill-rule the op's.  Edges
 * are crisp: the raster's pixels are whole, and adjacent fills (a shaded mesh) show no seams. */
static void emit_fillpath(svgw *w, const pc_op *op) {
    const pc_canvas *c = w->c;
    if (op->count == 0 || (size_t)op->first + op->count > c->npts) return;
    const pc_xy *p = c->pts + op->first;
    const uint8_t *tag = c->tags + op->first;
    pc_rect clip = clip_of(w, op);
    if (!path_near_clip(p, op->count, clip, MARGIN)) return;
    open_el(w, "path");
    color_attr(w, "fill", op->color);
    if ((op->flags & 1) == PC_FILL_EVENODD) fputs(" fill-rule=\"evenodd\"", w->out);
    fputs(" shape-rendering=\"crispEdges\"", w->out);
    d_begin(w);
    int far = 0;
    for (size_t i = 0; i < op->count; i++) far |= !near_pt(p[i]);
    if (far) {
        emit_fill_far(w, p, tag, op->count, clip);
    } else {
        size_t nsub = 0;
        for (size_t i = 0; i < op->count;) {
            if (tag[i] == PC_PATH_MOVE) {
                if (nsub > 1) d_letter(w, 'Z');
                d_move(w, (hpt){hund(p[i].x + 0.5), hund(p[i].y + 0.5)});
                nsub = 1;
                i++;
            } else if (tag[i] == PC_PATH_LINE) {
                d_letter(w, 'L');
                d_num(w, hund(p[i].x + 0.5));
                d_num(w, hund(p[i].y + 0.5));
                nsub++;
                i++;
            } else {
                d_letter(w, 'C');
                for (int k = 0; k < 3; k++) {
                    d_num(w, hund(p[i + k].x + 0.5));
                    d_num(w, hund(p[i + k].y + 0.5));
                }
                nsub += 3;
                i += 3;
            }
        }
        if (nsub > 1) d_letter(w, 'Z');
    }
    d_end(w);
}

/* ---- text --------------------------------------------------------------------------------- */

/* A code point as XML character data: markup characters escaped; characters XML cannot hold
 * (controls, U+FFFE, U+FFFF) become U+FFFD, as the raster shows them with the font's
 * replacement glyph. */
static void put_xml_char(FILE *out, uint32_t cp) {
    switch (cp) {
    case '&': fputs("&amp;", out); return;
    case '<': fputs("&lt;", out); return;
    case '>': fputs("&gt;", out); return;
    case '"': fputs("&quot;", out); return;
    case '\'': fputs("&apos;", out); return;
    }
    if (cp < 0x20 || cp == 0xfffe || cp == 0xffff) cp = 0xfffd;
    char b[4];
    int n;
    if (cp < 0x80) { b[0] = (char)cp; n = 1; }
    else if (cp < 0x800) { b[0] = (char)(0xc0 | cp >> 6); b[1] = (char)(0x80 | (cp & 0x3f)); n = 2; }
    else if (cp < 0x10000) {
        b[0] = (char)(0xe0 | cp >> 12); b[1] = (char)(0x80 | ((cp >> 6) & 0x3f));
        b[2] = (char)(0x80 | (cp & 0x3f)); n = 3;
    } else {
        b[0] = (char)(0xf0 | cp >> 18); b[1] = (char)(0x80 | ((cp >> 12) & 0x3f));
        b[2] = (char)(0x80 | ((cp >> 6) & 0x3f)); b[3] = (char)(0x80 | (cp & 0x3f)); n = 4;
    }
    fwrite(b, 1, (size_t)n, out);
}

/* A math label (text.c lays it out over VGA cells): one <tspan> a run, each run's cells where
 * the raster has them (scripts in the 8x8 cells), bars and arrows as lines. */
static void emit_math_text(svgw *w, const pc_op *op, const char *s, size_t n) {
    char *z = malloc(n + 1);
    if (!z) { w->nomem = 1; return; }
    memcpy(z, s, n);
    z[n] = 0;
    pc_mlayout L;
    long scale = lrint(op->rx);
    int st = pc_text_vga_layout(z, (int)scale, &L, NULL, 0);
    free(z);
    if (st != PC_OK) { w->nomem = st == PC_ENOMEM; return; }
    long left = lrint(op->x1), base = lrint(op->y1) + PC_FONT_BASELINE * scale;
    open_el(w, "text");
    fprintf(w->out, " font-family=\"monospace\" xml:space=\"preserve\"");
    color_attr(w, "fill", op->color);
    fputs(" stroke=\"none\">", w->out);
    for (size_t i = 0; i < L.nruns; i++) {
        const pc_mrun *r = &L.runs[i];
        const pc_font *f = r->size >= PC_FONT_H * scale ? &pc_font_desc : &pc_font8_desc;
        long nch = pc_utf8_count(L.text + r->first, r->len, NULL);
        long y = base - lrint(r->rise), top = y - f->baseline * scale;
        fprintf(w->out, "<tspan x=\"%ld\" y=\"%ld\" font-size=\"%ld\" textLength=\"%ld\" "
                "lengthAdjust=\"spacingAndGlyphs\">", left + lrint(r->x), top + f->baseline * scale,
                (long)f->h * scale, nch * PC_FONT_W * scale);
        size_t k = 0;
        uint32_t cp;
        while (pc_utf8_next(L.text + r->first, r->len, &k, &cp)) put_xml_char(w->out, cp);
        fputs("</tspan>", w->out);
    }
    fputs("</text>\n", w->out);
    for (size_t i = 0; i < L.ndecos; i++) {
        const pc_mdeco *d = &L.decos[i];
        long y = base - lrint(d->rise), x0 = left + lrint(d->x0), x1 = left + lrint(d->x1);
        if (d->kind == PC_DECO_UNDER) y = pc_vga_under_y(base, y, (int)scale);
        open_el(w, "path");
        if (d->kind == PC_DECO_TILDE) {   /* the raster's wave: one piece per row it is on */
            fputs(" d=\"", w->out);
            for (long x = x0; x < x1;) {
                long dy = pc_vga_tilde_dy(x - x0, x1 - x0, (int)scale), e = x + 1;
                while (e < x1 && pc_vga_tilde_dy(e - x0, x1 - x0, (int)scale) == dy) e++;
                fprintf(w->out, "M%ld %ld.5H%ld", x, y + dy, e);
                x = e;
            }
            fputc('"', w->out);
        } else {
            fprintf(w->out, " d=\"M%ld %ld.5H%ld\"", x0, y, x1);
        }
        color_attr(w, "stroke", op->color);
        fputs("/>\n", w->out);
    }
    pc_mlayout_free(&L);
}

/* TEXT: a <text> whose cell box is the raster's: x at the box's left edge, y on the font's
 * baseline, and textLength stretching the glyphs to exactly 8*scale px per character. */
static void emit_text(svgw *w, const pc_op *op) {
    const pc_canvas *c = w->c;
    if ((size_t)op->first + op->count > c->ntext) return;
    const char *s = c->text + op->first;
    size_t n = op->count, i = 0;
    long nchars = pc_utf8_count(s, n, NULL);
    if (nchars <= 0) return;
    long scale = lrint(op->rx), x = lrint(op->x1), y = lrint(op->y1);
    /* ry: the cell height of QBasic's PRINT on the 8x8 and 8x14 screens (0: the 8x16 font) */
    const pc_font *f = pc_font_of_height(op->ry > 0 ? (int)op->ry : PC_FONT_H);
    if (!f) f = pc_font_of_height(PC_FONT_H);
    long wd = nchars * PC_FONT_W * scale, ht = f->h * scale;
    pc_rect clip = clip_of(w, op);
    if (x > clip.x1 || y > clip.y1 || x + wd <= clip.x0 || y + ht <= clip.y0) return;
    if (op->a0 == 1) {
        emit_math_text(w, op, s, n);
        return;
    }
    open_el(w, "text");
    fprintf(w->out, " x=\"%ld\" y=\"%ld\" font-family=\"monospace\" font-size=\"%ld\" "
                    "textLength=\"%ld\" lengthAdjust=\"spacingAndGlyphs\" xml:space=\"preserve\"",
            x, y + f->baseline * scale, f->h * scale, wd);
    color_attr(w, "fill", op->color);
    fputs(" stroke=\"none\">", w->out);
    uint32_t cp;
    while (pc_utf8_next(s, n, &i, &cp)) put_xml_char(w->out, cp);
    fputs("</text>\n", w->out);
}

/* ---- the document ------------------------------------------------------------------------- */

int pc_encode_svg(const pc_canvas *c, pc_theme theme, FILE *out) {
    svgw w;
    memset(&w, 0, sizeof w);
    w.out = out;
    w.c = c;
    w.group = -1;
    pc_theme_palette(c, theme, w.pal);
    w.clip_done = calloc(c->nclips ? c->nclips : 1, 1);
    if (!w.clip_done || !make_canon(&w)) {
        free(w.clip_done);
        free(w.canon);
        return PC_ENOMEM;
    }

    fprintf(out,
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"%d\" height=\"%d\" "
            "viewBox=\"0 0 %d %d\">\n",
            c->width, c->height, c->width, c->height);
    fprintf(out, "<rect width=\"%d\" height=\"%d\"", c->width, c->height);
    color_attr(&w, "fill", 0);
    fputs("/>\n", out);
    fputs("<g fill=\"none\" stroke-width=\"1\" stroke-linecap=\"square\">\n", out);

    size_t i = 0;
    while (i < c->nops && !w.nomem && !ferror(out)) {
        const pc_op *op = &c->ops[i];
        while (w.clip + 1 < c->nclips && c->clips[w.clip + 1].first <= i) w.clip++;
        size_t clip_end = pc_clip_end(c, w.clip);   /* runs below stay within the clip */
        enter_clip(&w, op);
        size_t j = i + 1;
        if (op->kind == PC_OP_DOTS) {
            emit_dots(&w, op);
        } else if (op->kind == PC_OP_PIXELS) {
            emit_pixels(&w, op);
        } else if (is_styled(&w, op)) {
            emit_styled(&w, op);
        } else if (op->kind == PC_OP_LINE) {
            while (j < c->nops && c->ops[j].kind == op->kind && c->ops[j].color == op->color &&
                   j < clip_end && c->ops[j].pen == op->pen)
                j++;
            emit_lines(&w, op, j - i);
        } else if (op->kind == PC_OP_PATH) {
            emit_path(&w, op);
        } else if (op->kind == PC_OP_TEXT) {
            emit_text(&w, op);
        } else if (is_brush(op)) {
            while (j < c->nops && is_brush(&c->ops[j]) && c->ops[j].color == op->color &&
                   c->ops[j].rx == op->rx && j < clip_end)
                j++;
            emit_brushes(&w, op, j - i);
        } else if (op->kind == PC_OP_ARC) {
            emit_arc(&w, op);
        } else if (op->kind == PC_OP_FILL) {
            emit_fill(&w, op);
        } else if (op->kind == PC_OP_FILLPATH) {
            emit_fillpath(&w, op);
        } else {
            emit_box(&w, op);
        }
        i = j;
    }
    flush_layer(&w);
    if (w.group >= 0) fputs("</g>\n", out);
    fputs("</g>\n</svg>\n", out);
    free(w.clip_done);
    free(w.canon);
    free(w.pts);
    free(w.layer);
    if (w.nomem) return PC_ENOMEM;
    return fflush(out) != 0 || ferror(out) ? PC_EIO : PC_OK;
}
