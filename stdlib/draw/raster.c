/* The QBasic drawing statements: each rasterises into the pixel array at once and records one
 * display-list operation.  Coordinates are world coordinates (see canvas.c for WINDOW/VIEW);
 * pixels are the nearest integers (ties to even, as the x87 FPU rounds), clipped silently to
 * the view. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "canvas.h"
#include "canvas_internal.h"
#include "qbscreen.h"

#define TWO_PI 6.283185307179586

/* Far-away coordinates are clamped before conversion: the result is off screen either way and
 * the conversion stays defined (a NaN, which no statement lets through, lands far off screen
 * too instead of wherever lrint would put it). */
long pc_px(double v) {
    if (!(v <= 1e9)) v = 1e9;
    if (v < -1e9) v = -1e9;
    return lrint(v);
}
#define px pc_px

/* Up to this many pixels from the screen's origin a far end point still places a line, and a
 * circle's centre and radii are exact (int64 offsets; products under a square root below
 * 2^53): a double's step there is 1/8 pixel. */
#define HUGE_PX 1e15

static int finite2(double x, double y) { return isfinite(x) && isfinite(y); }

static int too_far(pc_canvas *c, const char *stmt) {
    return pc_fail(c, "%s: the segment's ends lie too far out (beyond %g pixels, on a slant) to "
                      "place it to the pixel", stmt, HUGE_PX);
}

/* A statement's point on the screen.  Its coordinates must be finite, and so must their image:
 * WINDOW can map a huge finite coordinate past the largest double. */
static int to_screen(pc_canvas *c, const char *stmt, double x, double y, double *sx, double *sy) {
    if (!finite2(x, y))
        return pc_fail(c, "%s: coordinates must be finite numbers, got (%g, %g)", stmt, x, y);
    pc_world_to_screen(c, x, y, sx, sy);
    if (!finite2(*sx, *sy))
        return pc_fail(c, "%s: coordinates (%g, %g) are too far outside the window", stmt, x, y);
    return PC_OK;
}

void pc_plot(pc_canvas *c, int x, int y, int color) {
    const pc_rect *v = &c->view;
    if (x < v->x0 || x > v->x1 || y < v->y0 || y > v->y1) return;
    c->pixels[(size_t)y * c->width + x] = (uint16_t)color;
}

static void set_cursor(pc_canvas *c, double wx, double wy) {
    c->last_x = wx;
    c->last_y = wy;
}

/* ---- PSET, PRESET, POINT -------------------------------------------------------------- */

static int dot(pc_canvas *c, double x, double y, int color, int dflt) {
    double sx, sy;
    int ok = pc_check_color(c, &color, dflt);
    if (ok == PC_OK) ok = to_screen(c, "pset", x, y, &sx, &sy);
    if (ok != PC_OK) return ok;
    pc_plot(c, (int)px(sx), (int)px(sy), color);
    ok = pc_push_dot(c, sx, sy, color);
    if (ok != PC_OK) return ok;
    set_cursor(c, x, y);
    return PC_OK;
}

int pc_pset(pc_canvas *c, double x, double y, int color) { return dot(c, x, y, color, c->fg); }
int pc_preset(pc_canvas *c, double x, double y, int color) { return dot(c, x, y, color, c->bg); }

int pc_point(const pc_canvas *c, double x, double y) {
    if (!finite2(x, y)) return -1;
    double sx, sy;
    pc_world_to_screen(c, x, y, &sx, &sy);
    if (!finite2(sx, sy)) return -1;
    long ix = px(sx), iy = px(sy);
    const pc_rect *v = &c->view;
    if (ix < v->x0 || ix > v->x1 || iy < v->y0 || iy > v->y1) return -1;
    return c->pixels[(size_t)iy * c->width + ix];
}

/* ---- LINE ------------------------------------------------------------------------------ */

/* Liang-Barsky: the parameters t0 <= t1 of the part of (x, y) + t (dx, dy), 0 <= t <= 1, inside
 * the rectangle, and the edges that cut there (0: x = xmin, 1: x = xmax, 2: y = ymin,
 * 3: y = ymax; -1: not cut); 0 if nothing is inside. */
static int clip_params(double x, double y, double dx, double dy, double xmin, double ymin,
                       double xmax, double ymax, double *t0, double *t1, int *e0, int *e1) {
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {x - xmin, xmax - x, y - ymin, ymax - y};
    *t0 = 0;
    *t1 = 1;
    *e0 = *e1 = -1;
    for (int i = 0; i < 4; i++) {
        if (p[i] == 0) {
            if (q[i] < 0) return 0;
        } else {
            double r = q[i] / p[i];
            if (p[i] < 0) { if (r > *t1) return 0; if (r > *t0) { *t0 = r; *e0 = i; } }
            else          { if (r < *t0) return 0; if (r < *t1) { *t1 = r; *e1 = i; } }
        }
    }
    return 1;
}

/* Where the line through (rx, ry) with direction (dx, dy) crosses edge e: the edge's own
 * coordinate exactly, the other one along the slope from (rx, ry), kept within the rectangle
 * (rounding can only move it along the edge). */
static void cut_at_edge(int e, double rx, double ry, double dx, double dy, double xmin,
                        double ymin, double xmax, double ymax, double *x, double *y) {
    if (e < 2) {
        *x = e == 0 ? xmin : xmax;
        *y = fmin(fmax(ry + (*x - rx) * (dy / dx), ymin), ymax);
    } else {
        *y = e == 2 ? ymin : ymax;
        *x = fmin(fmax(rx + (*y - ry) * (dx / dy), xmin), xmax);
    }
}

/* Clip the segment to the rectangle; 0 if nothing is left.  A cut end lies on the
 * rectangle's edge and is computed from the original end nearer to it, so a segment from the
 * screen to 1e300 keeps its exact pixels.  Off the true line it is by about a rounding step
 * of that end's coordinates (see raster_line_f for when that is too much). */
int pc_clip_segment(double *x0, double *y0, double *x1, double *y1, double xmin, double ymin,
                    double xmax, double ymax) {
    double dx = *x1 - *x0, dy = *y1 - *y0;
    if (!isfinite(dx) || !isfinite(dy)) {
        /* the extent overflows (ends near +-DBL_MAX): clip at half scale, which is exact */
        double a = *x0 / 2, b = *y0 / 2, d = *x1 / 2, e = *y1 / 2;
        if (!pc_clip_segment(&a, &b, &d, &e, xmin / 2, ymin / 2, xmax / 2, ymax / 2)) return 0;
        *x0 = a * 2; *y0 = b * 2; *x1 = d * 2; *y1 = e * 2;
        return 1;
    }
    double t0, t1;
    int e0, e1;
    if (!clip_params(*x0, *y0, dx, dy, xmin, ymin, xmax, ymax, &t0, &t1, &e0, &e1)) return 0;
    const double ax = *x0, ay = *y0, bx = *x1, by = *y1;
    if (e0 >= 0)
        cut_at_edge(e0, t0 <= 0.5 ? ax : bx, t0 <= 0.5 ? ay : by, dx, dy, xmin, ymin, xmax, ymax,
                    x0, y0);
    if (e1 >= 0)
        cut_at_edge(e1, t1 <= 0.5 ? ax : bx, t1 <= 0.5 ? ay : by, dx, dy, xmin, ymin, xmax, ymax,
                    x1, y1);
    return 1;
}

/* ---- strokes: the pen ------------------------------------------------------------------- */

/* What a statement strokes with: the colour, the pen, and for a wide pen the disc stamped at
 * every pixel of the 1-pixel stroke.  dist is the distance along the stroke (for the dash
 * phase) where the next segment starts. */
typedef struct {
    pc_canvas *c;
    int color;
    const pc_stroke *pen;
    int16_t (*disc)[2];
    int ndisc;
    double dist;
    int check_only;     /* walk the geometry, draw nothing: is every segment placeable? */
} stroker;

int pc_dash_on(const pc_stroke *p, double d) {
    if (!p->ndash) return 1;
    d = fmod(d, p->period);
    if (d < 0) d += p->period;
    for (int i = 0; i < p->ndash; i++) {
        if (d < p->dash[i]) return i % 2 == 0;
        d -= p->dash[i];
    }
    return 0;
}

/* The disc of a pen of width w: the pixels whose centres lie within w/2 of the stamp's centre,
 * which is the pixel's centre for odd widths and its lower-right corner for even ones (so a
 * width-2 line is 2 pixels thick, not 3). */
static int make_disc(stroker *s, double w) {
    double r = w / 2, o = fmod(w, 2) == 0 ? 0.5 : 0;
    int k = (int)ceil(r) + 1, n = 0;
    s->disc = malloc((size_t)(2 * k + 1) * (2 * k + 1) * sizeof *s->disc);
    if (!s->disc) return 0;
    for (int j = -k; j <= k; j++)
        for (int i = -k; i <= k; i++)
            if ((i - o) * (i - o) + (j - o) * (j - o) <= r * r + 1e-9) {
                s->disc[n][0] = (int16_t)i;
                s->disc[n][1] = (int16_t)j;
                n++;
            }
    s->ndisc = n;
    return 1;
}

static int stroker_init(stroker *s, pc_canvas *c, int color, int pen) {
    *s = (stroker){.c = c, .color = color, .pen = &c->pens[pen]};
    if (s->pen->width > 1 && !make_disc(s, s->pen->width))
        return pc_fail_code(c, PC_ENOMEM, "out of memory for a pen");
    return PC_OK;
}

static void stroker_free(stroker *s) { free(s->disc); }

static int plain_pen(const pc_stroke *p) { return p->width == 1 && p->ndash == 0; }

/* One pixel of the stroke at distance d along it. */
static void stroke_px(stroker *s, long x, long y, double d) {
    if (!pc_dash_on(s->pen, d)) return;
    if (!s->disc) {
        pc_plot(s->c, (int)x, (int)y, s->color);
        return;
    }
    const pc_rect *v = &s->c->view;
    if (x < v->x0 - PC_PEN_MAXWIDTH || x > v->x1 + PC_PEN_MAXWIDTH ||
        y < v->y0 - PC_PEN_MAXWIDTH || y > v->y1 + PC_PEN_MAXWIDTH)
        return;
    for (int k = 0; k < s->ndisc; k++)
        pc_plot(s->c, (int)(x + s->disc[k][0]), (int)(y + s->disc[k][1]), s->color);
}

/* ---- LINE ------------------------------------------------------------------------------ */

/* Bresenham between pixel centres.  The end points are put in a canonical order first, so a
 * segment covers the same pixels whichever way it is drawn.  Each pixel goes to fn with its
 * step i (0..n) counted from (x0, y0) as given. */
typedef void (*pixel_fn)(void *ctx, long x, long y, long i, long n);

static void bresenham(long x0, long y0, long x1, long y1, pixel_fn fn, void *ctx) {
    long dx = labs(x1 - x0), dy = labs(y1 - y0);
    int steep = dy > dx, swapped = 0;
    if ((steep && y0 > y1) || (!steep && x0 > x1)) {
        long t = x0; x0 = x1; x1 = t;
        t = y0; y0 = y1; y1 = t;
        swapped = 1;
    }
    long sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    long err = (steep ? dy : dx) / 2;
    long n = steep ? dy : dx;
    for (long i = 0; i <= n; i++) {
        fn(ctx, x0, y0, swapped ? n - i : i, n);
        if (steep) {
            y0 += sy;
            err -= dx;
            if (err < 0) { x0 += sx; err += dy; }
        } else {
            x0 += sx;
            err -= dy;
            if (err < 0) { y0 += sy; err += dx; }
        }
    }
}

/* A segment of a stroke: its pixels at their distances along it (d0 at the first, d0 + len
 * at the last). */
typedef struct { stroker *s; double d0, len; } seg_walk;

static void seg_px(void *ctx, long x, long y, long i, long n) {
    seg_walk *w = ctx;
    if (!w->s->disc && !w->s->pen->ndash) {   /* the plain pen: today's pixels, fast */
        pc_plot(w->s->c, (int)x, (int)y, w->s->color);
        return;
    }
    stroke_px(w->s, x, y, w->d0 + (n ? w->len * (double)i / (double)n : 0));
}

/* A segment reaching far off screen is cut first (nearby ones keep their exact pixels).  A
 * cut end is off the true line by about a rounding step of the nearer end's coordinates, each
 * weighted by how much it moves the line sideways: nothing for an axis-parallel line, at most
 * ~0.2 px while that end lies within HUGE_PX.  Returns 1 with the ends cut, -1 when nothing of
 * it is near the screen, 0 when even the better end is too far out on a slant to place the
 * segment to the pixel (e.g. +-1e20 on a diagonal). */
static int far_clip(const pc_canvas *c, double *x0, double *y0, double *x1, double *y1) {
    const double far = 32768;
    if (fabs(*x0) <= far && fabs(*y0) <= far && fabs(*x1) <= far && fabs(*y1) <= far) return 1;
    /* the unit direction's components (halves: no overflow) weigh each coordinate */
    double hx = *x1 / 2 - *x0 / 2, hy = *y1 / 2 - *y0 / 2, hl = hypot(hx, hy);
    double wx = fabs(hy) / hl, wy = fabs(hx) / hl;
    double side0 = fabs(*x0) * wx + fabs(*y0) * wy, side1 = fabs(*x1) * wx + fabs(*y1) * wy;
    if (!pc_clip_segment(x0, y0, x1, y1, -4.0, -4.0, c->width + 4.0, c->height + 4.0))
        return -1;
    if (fmin(side0, side1) > HUGE_PX) return 0;
    return 1;
}

/* A segment of a stroke in screen coordinates; the dash phase runs on past it.  Returns 0 if
 * it cannot be placed to the pixel (nothing drawn). */
static int stroke_seg(stroker *s, double x0, double y0, double x1, double y1) {
    /* the distance along the stroke only matters to dashes: no square root per plain segment */
    double ax = x0, ay = y0, len = s->pen->ndash ? hypot(x1 - x0, y1 - y0) : 0;
    int k = far_clip(s->c, &x0, &y0, &x1, &y1);
    if (k == 0) return 0;
    if (k > 0 && !s->check_only) {
        seg_walk w = {s, s->dist, 0};
        long a = px(x0), b = px(y0), d = px(x1), e = px(y1);
        if (s->pen->ndash) {   /* distances from the uncut start, along the cut part */
            w.d0 += hypot(x0 - ax, y0 - ay);
            w.len = hypot(x1 - x0, y1 - y0);
        }
        bresenham(a, b, d, e, seg_px, &w);
    }
    if (isfinite(len)) s->dist += len;
    return 1;
}

int pc_line(pc_canvas *c, double x1, double y1, double x2, double y2, int color) {
    double a, b, d, e;
    int ok = pc_check_color(c, &color, c->fg);
    if (ok == PC_OK) ok = to_screen(c, "line", x1, y1, &a, &b);
    if (ok == PC_OK) ok = to_screen(c, "line", x2, y2, &d, &e);
    if (ok != PC_OK) return ok;
    stroker s;
    if ((ok = stroker_init(&s, c, color, c->pen)) != PC_OK) return ok;
    int placed = stroke_seg(&s, a, b, d, e);
    stroker_free(&s);
    if (!placed) return too_far(c, "line");
    pc_op *op = pc_push_op(c, PC_OP_LINE, color);
    if (!op) return PC_ENOMEM;
    op->pen = (uint16_t)c->pen;
    op->x1 = a; op->y1 = b; op->x2 = d; op->y2 = e;
    set_cursor(c, x2, y2);
    return PC_OK;
}

/* ---- QBasic's LINE style ----------------------------------------------------------------- */

/* The order is GW-BASIC's, as PC-BASIC reproduces it (pcbasic/basic/display/graphics.py,
 * _draw_line and _draw_box): a line from its upper end (its second point when level), the
 * bit for a pixel chosen by its distance from there along the major axis. */
typedef struct {
    void (*fn)(void *, long, long);
    void *ctx;
    unsigned pattern;
    int steep;
    long m0;   /* the start's coordinate along the major axis */
} style_walk;

static int style_bit(unsigned pattern, long k) { return (pattern >> (15 - k % 16)) & 1; }

static void style_px(void *ctx, long x, long y, long i, long n) {
    (void)i;
    (void)n;
    style_walk *w = ctx;
    if (style_bit(w->pattern, labs((w->steep ? y : x) - w->m0))) w->fn(w->ctx, x, y);
}

/* A side of a styled box from p0 to p1 (along x if horiz, else y) at q; k is the bit index at
 * p0.  Only the part near the screen is visited.  Returns the index after p1. */
static long style_side(style_walk *w, int horiz, long p0, long p1, long q, const pc_canvas *c,
                       long k) {
    long plo = -4, phi = (horiz ? c->width : c->height) + 4;
    long qlo = -4, qhi = (horiz ? c->height : c->width) + 4;
    if (q >= qlo && q <= qhi) {
        long a = p0 < p1 ? p0 : p1, b = p0 < p1 ? p1 : p0;
        if (a < plo) a = plo;
        if (b > phi) b = phi;
        for (long p = a; p <= b; p++)
            if (style_bit(w->pattern, k + labs(p - p0))) {
                if (horiz) w->fn(w->ctx, p, q);
                else w->fn(w->ctx, q, p);
            }
    }
    return k + labs(p1 - p0) + 1;
}

void pc_styled_pixels(const pc_canvas *c, const pc_op *op, void (*fn)(void *, long, long),
                      void *ctx) {
    style_walk w = {fn, ctx, c->pens[op->pen].style & 0xffff, 0, 0};
    long ax = px(op->x1), ay = px(op->y1), bx = px(op->x2), by = px(op->y2);
    if (op->kind == PC_OP_BOX) {
        long k = style_side(&w, 1, bx, ax, by, c, 0);   /* the second corner's row */
        k = style_side(&w, 1, bx, ax, ay, c, k);
        long top = ay < by ? ay : by, bottom = ay < by ? by : ay;
        k = style_side(&w, 0, top, bottom, bx, c, k);
        style_side(&w, 0, top, bottom, ax, c, k);
        return;
    }
    w.steep = labs(by - ay) > labs(bx - ax);
    int from_second = by <= ay;
    w.m0 = w.steep ? (from_second ? by : ay) : (from_second ? bx : ax);
    double x0 = op->x1, y0 = op->y1, x1 = op->x2, y1 = op->y2;
    if (far_clip(c, &x0, &y0, &x1, &y1) <= 0) return;
    bresenham(px(x0), px(y0), px(x1), px(y1), style_px, &w);
}

static void plot_cb(void *ctx, long x, long y) {
    pc_canvas *c = ((void **)ctx)[0];
    pc_plot(c, (int)x, (int)y, *(int *)((void **)ctx)[1]);
}

int pc_line_styled(pc_canvas *c, double x1, double y1, double x2, double y2, int color, int box,
                   unsigned pattern) {
    double a, b, d, e;
    int ok = pc_check_color(c, &color, c->fg);
    if (ok == PC_OK) ok = to_screen(c, "line", x1, y1, &a, &b);
    if (ok == PC_OK) ok = to_screen(c, "line", x2, y2, &d, &e);
    if (ok != PC_OK) return ok;
    double ca = a, cb = b, cd = d, ce = e;
    if (!box && far_clip(c, &ca, &cb, &cd, &ce) == 0) return too_far(c, "line");
    pc_stroke pen = {.width = 1, .style = 0x10000u | (pattern & 0xffffu)};
    int k = pc_pen_index(c, &pen);
    if (k < 0) return PC_ENOMEM;
    pc_op *op = pc_push_op(c, box ? PC_OP_BOX : PC_OP_LINE, color);
    if (!op) return PC_ENOMEM;
    op->pen = (uint16_t)k;
    op->x1 = a; op->y1 = b; op->x2 = d; op->y2 = e;
    void *ctx[2] = {c, &color};
    pc_styled_pixels(c, op, plot_cb, ctx);
    set_cursor(c, x2, y2);
    return PC_OK;
}
/* ---- paths ------------------------------------------------------------------------------ */

int pc_cubic_segments(const pc_xy p[4], double tol) {
    double ax = p[0].x - 2 * p[1].x + p[2].x, ay = p[0].y - 2 * p[1].y + p[2].y;
    double bx = p[1].x - 2 * p[2].x + p[3].x, by = p[1].y - 2 * p[2].y + p[3].y;
    double m = fmax(hypot(ax, ay), hypot(bx, by));
    /* Wang: n segments keep a cubic within 3/4 * m / n^2 of its chords */
    double n = ceil(sqrt(0.75 * m / tol));
    if (!(n >= 1)) return 1;
    return n > 100000 ? 100000 : (int)n;
}

pc_xy pc_cubic_at(const pc_xy p[4], double t) {
    double u = 1 - t, a = u * u * u, b = 3 * u * u * t, c = 3 * u * t * t, d = t * t * t;
    return (pc_xy){a * p[0].x + b * p[1].x + c * p[2].x + d * p[3].x,
                   a * p[0].y + b * p[1].y + c * p[2].y + d * p[3].y};
}

#define CUBIC_TOL 0.1   /* px: how far a flattened cubic may stray from the curve */

/* Stroke the path of op (its points in c->pts): each LINE a segment, each cubic its
 * flattening, each subpath closed when asked; the dash phase restarts at each subpath, as SVG
 * restarts it.  Returns 0 if a segment cannot be placed to the pixel. */
static int stroke_path(stroker *s, const pc_op *op) {
    const pc_xy *p = s->c->pts + op->first;
    const uint8_t *tag = s->c->tags + op->first;
    size_t n = op->count, start = 0;
    pc_xy cur = p[0];
    for (size_t i = 0; i < n;) {
        if (tag[i] == PC_PATH_MOVE) {
            if ((op->flags & PC_PATH_CLOSED) && i > start + 1 &&
                !stroke_seg(s, cur.x, cur.y, p[start].x, p[start].y))
                return 0;
            start = i;
            cur = p[i++];
            s->dist = 0;
        } else if (tag[i] == PC_PATH_LINE) {
            if (!stroke_seg(s, cur.x, cur.y, p[i].x, p[i].y)) return 0;
            cur = p[i++];
        } else {
            const pc_xy q[4] = {cur, p[i], p[i + 1], p[i + 2]};
            int k = pc_cubic_segments(q, CUBIC_TOL);
            for (int j = 1; j <= k; j++) {
                pc_xy e = j == k ? q[3] : pc_cubic_at(q, (double)j / k);
                if (!stroke_seg(s, cur.x, cur.y, e.x, e.y)) return 0;
                cur = e;
            }
            i += 3;
        }
    }
    if ((op->flags & PC_PATH_CLOSED) && n > start + 1)
        return stroke_seg(s, cur.x, cur.y, p[start].x, p[start].y);
    return 1;
}

/* Check the verbs against the number of points; the tag of each point goes to tags. */
static int path_tags(pc_canvas *c, size_t n, const uint8_t *verbs, size_t nverbs, uint8_t *tags) {
    if (!verbs) {
        for (size_t i = 0; i < n; i++) tags[i] = i ? PC_PATH_LINE : PC_PATH_MOVE;
        return PC_OK;
    }
    if (nverbs == 0 || verbs[0] != PC_PATH_MOVE)
        return pc_fail(c, "path: the first verb must be a move");
    size_t k = 0;
    for (size_t v = 0; v < nverbs; v++) {
        int take = verbs[v] == PC_PATH_CUBIC ? 3 : 1;
        if (verbs[v] > PC_PATH_CUBIC) return pc_fail(c, "path: verb %zu is not a move, line or cubic", v + 1);
        if (k + take > n) return pc_fail(c, "path: %zu points are too few for the verbs", n);
        for (int j = 0; j < take; j++) tags[k++] = verbs[v];
    }
    if (k != n) return pc_fail(c, "path: the verbs take %zu points, %zu were given", k, n);
    return PC_OK;
}

/* Room for `need` points and tags (the two arrays share one capacity). */
static int grow_pts(pc_canvas *c, size_t need) {
    if (need <= c->cappts) return 1;
    size_t n = c->cappts ? c->cappts * 2 : 256;
    while (n < need) n *= 2;
    pc_xy *p = realloc(c->pts, n * sizeof *p);
    if (!p) return 0;
    c->pts = p;
    uint8_t *t = realloc(c->tags, n);
    if (!t) return 0;
    c->tags = t;
    c->cappts = n;
    return 1;
}

/* Append the path's screen points to the canvas; *first receives where they start.  stmt
 * names the statement in messages (paths and filled paths share the points). */
/* screen: the points are screen coordinates already (pc_path_screen), else world ones */
static int push_pts(pc_canvas *c, const char *stmt, size_t n, const double *xy,
                    const uint8_t *verbs, size_t nverbs, uint32_t *first, int screen) {
    if (n == 0) return pc_fail(c, "%s: no points", stmt);
    if (c->npts + n > UINT32_MAX) return pc_fail_code(c, PC_ENOMEM, "%s: too many points", stmt);
    if (!grow_pts(c, c->npts + n)) return pc_fail_code(c, PC_ENOMEM, "out of memory for a %s", stmt);
    int ok = path_tags(c, n, verbs, nverbs, c->tags + c->npts);
    for (size_t i = 0; i < n && ok == PC_OK; i++) {
        pc_xy *q = &c->pts[c->npts + i];
        if (!screen) {
            ok = to_screen(c, stmt, xy[2 * i], xy[2 * i + 1], &q->x, &q->y);
        } else if (finite2(xy[2 * i], xy[2 * i + 1])) {
            q->x = xy[2 * i];
            q->y = xy[2 * i + 1];
        } else {
            ok = pc_fail(c, "%s: coordinates must be finite numbers, got (%g, %g)", stmt,
                         xy[2 * i], xy[2 * i + 1]);
        }
    }
    if (ok != PC_OK) return ok;
    *first = (uint32_t)c->npts;
    c->npts += n;
    return PC_OK;
}

int pc_push_path_pts(pc_canvas *c, const char *stmt, size_t n, const double *xy,
                     const uint8_t *verbs, size_t nverbs, uint32_t *first) {
    return push_pts(c, stmt, n, xy, verbs, nverbs, first, 0);
}

static int path(pc_canvas *c, size_t n, const double *xy, const uint8_t *verbs, size_t nverbs,
                int closed, int color, int screen) {
    uint32_t first = 0;
    int ok = pc_check_color(c, &color, c->fg);
    if (ok == PC_OK) ok = push_pts(c, "path", n, xy, verbs, nverbs, &first, screen);
    if (ok != PC_OK) return ok;
    pc_op tmp = {.kind = PC_OP_PATH, .flags = closed ? PC_PATH_CLOSED : 0, .first = first,
                 .count = (uint32_t)n};
    stroker s;
    if ((ok = stroker_init(&s, c, color, c->pen)) != PC_OK) {
        c->npts = first;
        return ok;
    }
    /* first only check that every segment can be placed, so a refused path draws nothing */
    s.check_only = 1;
    int placed = stroke_path(&s, &tmp);
    if (placed) {
        s.check_only = 0;
        s.dist = 0;
        stroke_path(&s, &tmp);
    }
    stroker_free(&s);
    if (!placed) {
        c->npts = first;
        return too_far(c, "path");
    }
    pc_op *op = pc_push_op(c, PC_OP_PATH, color);
    if (!op) return PC_ENOMEM;
    *op = (pc_op){.kind = PC_OP_PATH, .flags = tmp.flags, .color = (uint16_t)color,
                  .pen = (uint16_t)c->pen, .first = first, .count = tmp.count};
    if (screen) pc_screen_to_world(c, xy[2 * n - 2], xy[2 * n - 1], &c->last_x, &c->last_y);
    else set_cursor(c, xy[2 * n - 2], xy[2 * n - 1]);
    return PC_OK;
}

int pc_path(pc_canvas *c, size_t n, const double *xy, const uint8_t *verbs, size_t nverbs,
            int closed, int color) {
    return path(c, n, xy, verbs, nverbs, closed, color, 0);
}

int pc_path_screen(pc_canvas *c, size_t n, const double *sxy, const uint8_t *verbs,
                   size_t nverbs, int closed, int color) {
    return path(c, n, sxy, verbs, nverbs, closed, color, 1);
}

/* ---- boxes ------------------------------------------------------------------------------ */

static void raster_box(pc_canvas *c, long x0, long y0, long x1, long y1, int color, int filled) {
    if (x0 > x1) { long t = x0; x0 = x1; x1 = t; }
    if (y0 > y1) { long t = y0; y0 = y1; y1 = t; }
    /* only the visible part needs visiting */
    const pc_rect *v = &c->view;
    long cx0 = x0 < v->x0 ? v->x0 : x0, cx1 = x1 > v->x1 ? v->x1 : x1;
    long cy0 = y0 < v->y0 ? v->y0 : y0, cy1 = y1 > v->y1 ? v->y1 : y1;
    if (cx0 > cx1 || cy0 > cy1) return;
    for (long y = cy0; y <= cy1; y++) {
        if (filled || y == y0 || y == y1) {
            pc_fill_px(c->pixels + (size_t)y * c->width + cx0, color, (size_t)(cx1 - cx0 + 1));
        } else {
            pc_plot(c, (int)x0, (int)y, color);
            pc_plot(c, (int)x1, (int)y, color);
        }
    }
}

int pc_box_screen(pc_canvas *c, int x0, int y0, int x1, int y1, int color, int filled) {
    raster_box(c, x0, y0, x1, y1, color, filled);
    pc_op *op = pc_push_op(c, filled ? PC_OP_FILLBOX : PC_OP_BOX, color);
    if (!op) return PC_ENOMEM;
    op->x1 = x0; op->y1 = y0; op->x2 = x1; op->y2 = y1;
    return PC_OK;
}

/* The outline of a box with a pen: clockwise on the screen from the top-left corner, as SVG
 * strokes a <rect>, so the dashes fall in the same places. */
static int pen_box(pc_canvas *c, long x0, long y0, long x1, long y1, int color) {
    if (x0 > x1) { long t = x0; x0 = x1; x1 = t; }
    if (y0 > y1) { long t = y0; y0 = y1; y1 = t; }
    stroker s;
    int ok = stroker_init(&s, c, color, c->pen);
    if (ok != PC_OK) return ok;
    const double X0 = (double)x0, Y0 = (double)y0, X1 = (double)x1, Y1 = (double)y1;
    /* axis-parallel sides are always placeable */
    stroke_seg(&s, X0, Y0, X1, Y0);
    stroke_seg(&s, X1, Y0, X1, Y1);
    stroke_seg(&s, X1, Y1, X0, Y1);
    stroke_seg(&s, X0, Y1, X0, Y0);
    stroker_free(&s);
    return PC_OK;
}

int pc_box(pc_canvas *c, double x1, double y1, double x2, double y2, int color, int filled) {
    double a, b, d, e;
    int ok = pc_check_color(c, &color, c->fg);
    if (ok == PC_OK) ok = to_screen(c, "line", x1, y1, &a, &b);
    if (ok == PC_OK) ok = to_screen(c, "line", x2, y2, &d, &e);
    if (ok != PC_OK) return ok;
    int pen = filled ? 0 : c->pen;   /* a filled box has no outline to stroke */
    if (plain_pen(&c->pens[pen])) raster_box(c, px(a), px(b), px(d), px(e), color, filled);
    else if ((ok = pen_box(c, px(a), px(b), px(d), px(e), color)) != PC_OK) return ok;
    pc_op *op = pc_push_op(c, filled ? PC_OP_FILLBOX : PC_OP_BOX, color);
    if (!op) return PC_ENOMEM;
    op->pen = (uint16_t)pen;
    op->x1 = a; op->y1 = b; op->x2 = d; op->y2 = e;
    set_cursor(c, x2, y2);
    return PC_OK;
}

int pc_fill_view(pc_canvas *c, int color) {
    const pc_rect *v = &c->view;
    raster_box(c, v->x0, v->y0, v->x1, v->y1, color, 1);
    pc_op *op = pc_push_op(c, PC_OP_CLEAR, color);
    if (!op) return PC_ENOMEM;
    op->x1 = v->x0; op->y1 = v->y0; op->x2 = v->x1; op->y2 = v->y1;
    return PC_OK;
}

/* CLS clears the view to the background colour.  A full-screen CLS also forgets the display
 * list: nothing drawn before it can show in any output. */
int pc_cls(pc_canvas *c) {
    const pc_rect *v = &c->view;
    if (v->x0 == 0 && v->y0 == 0 && v->x1 == c->width - 1 && v->y1 == c->height - 1) {
        c->nops = c->nspans = c->ndots = c->npts = c->ntext = 0;
        c->ntstyles = 0;
        c->nclips = 0;
        pc_lpx_clear(c);
        pc_canvas_detach(c);   /* a 3-D scene drawn so far goes with the rest */
        pc_push_clip(c);
        pc_fill_px(c->pixels, c->bg, (size_t)c->width * c->height);
        c->paper = c->bg;
        c->version++;   /* the picture changed even when no operation is recorded */
        if (c->bg != 0) {
            int ok = pc_fill_view(c, c->bg);
            if (ok != PC_OK) return ok;
        }
    } else {
        int ok = pc_fill_view(c, c->bg);
        if (ok != PC_OK) return ok;
    }
    pc_reset_cursor(c);
    return PC_OK;
}

/* ---- CIRCLE ---------------------------------------------------------------------------- */

/* Is the parametric angle th (0..2pi) on the arc from a0 to a1 (counter-clockwise), within eps
 * of its ends? */
static int on_arc(double th, double a0, double a1, double eps) {
    if (a0 <= a1) return th >= a0 - eps && th <= a1 + eps;
    return th >= a0 - eps || th <= a1 + eps;
}

static void plot64(pc_canvas *c, int64_t x, int64_t y, int color) {
    const pc_rect *v = &c->view;
    if (x < v->x0 || x > v->x1 || y < v->y0 || y > v->y1) return;
    c->pixels[(size_t)y * c->width + (size_t)x] = (uint16_t)color;
}

/* The offsets i in 0..n for which c0 + i or c0 - i lies in lo..hi: the columns (or rows) of
 * an outline that can be on screen, so that a circle far larger than the screen costs no more
 * than one the size of the screen.  At most two ranges; returns how many. */
typedef struct { int64_t lo, hi; } range;

static int visible_offsets(int64_t c0, int64_t n, int lo, int hi, range out[2]) {
    const range cand[2] = {{lo - c0, hi - c0}, {c0 - hi, c0 - lo}};
    int k = 0;
    for (int j = 0; j < 2; j++) {
        range r = {cand[j].lo < 0 ? 0 : cand[j].lo, cand[j].hi > n ? n : cand[j].hi};
        if (r.lo > r.hi) continue;
        if (k == 1 && r.lo <= out[0].hi + 1 && out[0].lo <= r.hi + 1) {   /* overlap: merge */
            if (r.lo < out[0].lo) out[0].lo = r.lo;
            if (r.hi > out[0].hi) out[0].hi = r.hi;
            continue;
        }
        out[k++] = r;
    }
    return k;
}

/* The outline of the ellipse with integer radii: for every column the nearest row and for
 * every row the nearest column, in all four quadrants, so the outline is closed for any
 * eccentricity.  Only columns and rows that can be visible are visited.  Points off the arc
 * (when full == 0) are skipped.  r*sqrt(1 - i^2/R^2) is computed as r*sqrt((R - i)(R + i))/R,
 * whose integer factors are exact, so a radius of millions of pixels keeps its pixels. */
/* Arc length along an ellipse from parametric angle 0 (counter-clockwise on the screen), by a
 * table of ARC_N steps (Simpson's rule on each), for the dash phase of a circle. */
#define ARC_N 1024
typedef struct { double tab[ARC_N + 1]; } arclen;

static double arc_speed(double rx, double ry, double t) { return hypot(rx * sin(t), ry * cos(t)); }

static void arclen_init(arclen *al, double rx, double ry) {
    const double h = TWO_PI / ARC_N;
    al->tab[0] = 0;
    for (int k = 0; k < ARC_N; k++) {
        double t = k * h;
        al->tab[k + 1] = al->tab[k] + h / 6 * (arc_speed(rx, ry, t) + 4 * arc_speed(rx, ry, t + h / 2) +
                                               arc_speed(rx, ry, t + h));
    }
}

static double arclen_at(const arclen *al, double t) {
    double u = t / TWO_PI * ARC_N;
    int k = (int)u;
    if (k < 0) return 0;
    if (k >= ARC_N) return al->tab[ARC_N];
    return al->tab[k] + (u - k) * (al->tab[k + 1] - al->tab[k]);
}

/* The length of the arc from a0 counter-clockwise to a1. */
static double arclen_between(const arclen *al, double a0, double a1) {
    double d = arclen_at(al, a1) - arclen_at(al, a0);
    return d < 0 ? d + al->tab[ARC_N] : d;
}

/* The pen's stroke along an ellipse: s NULL for the plain pen (pixels plotted as they come);
 * al the arc lengths when the pen is dashed. */
typedef struct { stroker *s; const arclen *al; } ellipse_pen;

static void raster_ellipse(pc_canvas *c, int64_t cx, int64_t cy, int64_t rx, int64_t ry,
                           int color, int full, double a0, double a1, ellipse_pen ep) {
    const pc_rect *v = &c->view;
    /* a wide pen reaches into the view from outside it */
    int m = ep.s && ep.s->disc ? (int)ceil(ep.s->pen->width / 2) + 1 : 0;
    /* an end of the arc lights the pixel its angle falls in: a pixel is on the arc when its
     * centre is within half a pixel of the end along the curve (QBasic's CIRCLE ..., 0, 1.5708
     * and ..., 1.5708, 3.1416 both light the top pixel, though 1.5708 is not exactly pi/2) */
    double eps = 0.5 / (double)(rx > ry ? (rx > 0 ? rx : 1) : (ry > 0 ? ry : 1));
    for (int pass = 0; pass < 2; pass++) {
        range r[2];
        int nr = pass ? visible_offsets(cy, ry, v->y0 - m, v->y1 + m, r)
                      : visible_offsets(cx, rx, v->x0 - m, v->x1 + m, r);
        for (int k = 0; k < nr; k++)
            for (int64_t i = r[k].lo; i <= r[k].hi; i++) {
                int64_t x, y;
                if (pass == 0) {
                    x = i;
                    y = rx ? llrint((double)ry * sqrt((double)(rx - i) * (double)(rx + i)) / (double)rx) : ry;
                } else {
                    y = i;
                    x = ry ? llrint((double)rx * sqrt((double)(ry - i) * (double)(ry + i)) / (double)ry) : rx;
                }
                for (int q = 0; q < 4; q++) {
                    int64_t dx = (q & 1) ? -x : x, dy = (q & 2) ? -y : y;
                    double th = 0;
                    if (!full || ep.al) {
                        th = rx == 0 || ry == 0 ? atan2(-(double)dy, (double)dx)
                                                : atan2(-(double)dy / (double)ry, (double)dx / (double)rx);
                        if (th < 0) th += TWO_PI;
                        if (!full && !on_arc(th, a0, a1, eps)) continue;
                        if (!full && th < a0 && th >= a0 - eps) th = a0;   /* dash phase from 0 */
                    }
                    if (!ep.s) plot64(c, cx + dx, cy + dy, color);
                    else stroke_px(ep.s, cx + dx, cy + dy,
                                   ep.s->dist + (ep.al ? arclen_between(ep.al, a0, th) : 0));
                }
            }
    }
}

/* Can the outline of the ellipse come within two pixels of the view (its pixels lie within a
 * pixel of the true curve)?  The curve meets the grown view rectangle exactly when the
 * rectangle holds points both inside and outside it: decided on the ellipse scaled to the
 * unit circle, by the rectangle's nearest point and farthest corner. */
static int outline_near_view(const pc_canvas *c, double cx, double cy, double rx, double ry) {
    const pc_rect *v = &c->view;
    double x0 = v->x0 - 2 - cx, x1 = v->x1 + 2 - cx, y0 = v->y0 - 2 - cy, y1 = v->y1 + 2 - cy;
    if (rx < 1 || ry < 1)   /* a dot or a straight stroke: its bounding box */
        return x0 <= rx && -rx <= x1 && y0 <= ry && -ry <= y1;
    x0 /= rx; x1 /= rx; y0 /= ry; y1 /= ry;
    double nx = x0 > 0 ? x0 : x1 < 0 ? x1 : 0, ny = y0 > 0 ? y0 : y1 < 0 ? y1 : 0;
    double fx = fmax(fabs(x0), fabs(x1)), fy = fmax(fabs(y0), fabs(y1));
    return nx * nx + ny * ny <= 1 && fx * fx + fy * fy >= 1;
}

/* The pixels of a circle, arc or sector with the current pen.  The dash phase runs as SVG's
 * path of the sector does: the first radius out from the centre, the arc counter-clockwise
 * from a0 (from angle 0 for a full ellipse), the second radius back to the centre. */
static int raster_arc(pc_canvas *c, double cx, double cy, double irx, double iry, int color,
                      int flags, double a0, double a1) {
    stroker s;
    int ok = stroker_init(&s, c, color, c->pen);
    if (ok != PC_OK) return ok;
    arclen *al = NULL;
    if (s.pen->ndash && !(al = malloc(sizeof *al))) {
        stroker_free(&s);
        return pc_fail_code(c, PC_ENOMEM, "out of memory for a circle");
    }
    if (al) arclen_init(al, irx, iry);
    int full = flags & PC_ARC_FULL;
    double e0x = cx + rint(irx * cos(a0)), e0y = cy - rint(iry * sin(a0));
    double e1x = cx + rint(irx * cos(a1)), e1y = cy - rint(iry * sin(a1));
    int placed = 1;
    if (flags & PC_ARC_RADIUS0) placed = stroke_seg(&s, cx, cy, e0x, e0y);
    if (placed && outline_near_view(c, cx, cy, irx, iry)) {
        ellipse_pen ep = {plain_pen(s.pen) ? NULL : &s, al};
        raster_ellipse(c, (int64_t)cx, (int64_t)cy, (int64_t)irx, (int64_t)iry, color, full, a0, a1, ep);
    }
    if (al) s.dist += full ? al->tab[ARC_N] : arclen_between(al, a0, a1);
    if (placed && (flags & PC_ARC_RADIUS1)) placed = stroke_seg(&s, e1x, e1y, cx, cy);
    free(al);
    stroker_free(&s);
    return placed ? PC_OK : too_far(c, "circle");
}

int pc_circle(pc_canvas *c, double x, double y, double r, int color, double start, double end,
              double aspect) {
    double sx, sy;
    int ok = pc_check_color(c, &color, c->fg);
    if (ok == PC_OK) ok = to_screen(c, "circle", x, y, &sx, &sy);
    if (ok != PC_OK) return ok;
    if (!(r >= 0) || !isfinite(r)) return pc_fail(c, "circle: radius must be a non-negative number, got %g", r);
    if (!isnan(start) && !(fabs(start) <= TWO_PI + 1e-6))
        return pc_fail(c, "circle: start angle %g is outside -2*pi..2*pi", start);
    if (!isnan(end) && !(fabs(end) <= TWO_PI + 1e-6))
        return pc_fail(c, "circle: end angle %g is outside -2*pi..2*pi", end);
    if (!isnan(aspect) && !(aspect > 0 && isfinite(aspect)))
        return pc_fail(c, "circle: aspect must be a positive number, got %g", aspect);

    int full = isnan(start) && isnan(end);
    int flags = full ? PC_ARC_FULL : 0;
    double a0 = isnan(start) ? 0 : start, a1 = isnan(end) ? TWO_PI : end;
    /* a negative angle asks for a radius from the centre to that end of the arc */
    if (a0 < 0 || (a0 == 0 && signbit(a0))) { flags |= PC_ARC_RADIUS0; a0 = -a0; }
    if (a1 < 0 || (a1 == 0 && signbit(a1))) { flags |= PC_ARC_RADIUS1; a1 = -a1; }
    if (a0 >= TWO_PI) a0 = TWO_PI;
    if (a1 >= TWO_PI) a1 = TWO_PI;

    /* QBasic's aspect rule: below 1 it shrinks the y radius, above 1 the x radius */
    double rr = r * pc_world_xscale(c), rx = rr, ry = rr;
    if (!isfinite(rr)) return pc_fail(c, "circle: radius %g is too large for the window", r);
    if (!isnan(aspect)) {
        if (aspect < 1) ry = rr * aspect;
        else rx = rr / aspect;
    }
    /* the pixel figure: centre and radii rounded to whole pixels */
    double cx = rint(sx), cy = rint(sy), irx = rint(rx), iry = rint(ry);
    if (outline_near_view(c, cx, cy, irx, iry) &&
        (fmax(fabs(cx), fabs(cy)) > HUGE_PX || fmax(irx, iry) > HUGE_PX))
        return pc_fail(c, "circle: radius %g (%g pixels) is too large to draw", r, fmax(rx, ry));
    if ((ok = raster_arc(c, cx, cy, irx, iry, color, flags, a0, a1)) != PC_OK) return ok;

    pc_op *op = pc_push_op(c, PC_OP_ARC, color);
    if (!op) return PC_ENOMEM;
    op->pen = (uint16_t)c->pen;
    op->flags = (uint8_t)flags;
    op->x1 = sx; op->y1 = sy;
    op->rx = rx; op->ry = ry;
    op->a0 = a0; op->a1 = a1;
    set_cursor(c, x, y);
    return PC_OK;
}

/* ---- PAINT ------------------------------------------------------------------------------ */

typedef struct { int x, y; } seed;

/* Scanline flood fill of the region of non-border pixels connected (4-way) to the start,
 * inside the view, in one colour (each filled run one span of the display-list operation) or,
 * with a tile, in the tile's pattern (the painted box recorded as pixels: qbscreen.h). */
static int flood(pc_canvas *c, double x, double y, int color, int border, const pc_tile *tile) {
    double fx, fy;
    int ok = tile ? PC_OK : pc_check_color(c, &color, c->fg);
    if (ok == PC_OK) ok = to_screen(c, "paint", x, y, &fx, &fy);
    if (ok != PC_OK) return ok;
    if (border < 0) border = tile ? c->fg : color;
    if (!pc_valid_color(c, border))
        return pc_fail(c, "paint: border colour %d out of range 0..%d", border, c->ncolors - 1);
    set_cursor(c, x, y);

    long sx = px(fx), sy = px(fy);
    const pc_rect v = c->view;
    if (sx < v.x0 || sx > v.x1 || sy < v.y0 || sy > v.y1) return PC_OK;
    const int w = c->width;
    uint16_t *pix = c->pixels;
    if (pix[(size_t)sy * w + sx] == border) return PC_OK;

    uint8_t *seen = calloc((size_t)w * c->height, 1);
    size_t cap = 1024, n = 0;
    seed *stack = malloc(cap * sizeof *stack);
    if (!seen || !stack) {
        free(seen);
        free(stack);
        return pc_fail_code(c, PC_ENOMEM, "paint: out of memory");
    }
    uint32_t first = (uint32_t)c->nspans;
    int bx0 = (int)sx, bx1 = (int)sx, by0 = (int)sy, by1 = (int)sy;   /* the painted box */
    stack[n++] = (seed){(int)sx, (int)sy};
#define FILLABLE(X, Y) (!seen[(size_t)(Y) * w + (X)] && pix[(size_t)(Y) * w + (X)] != border)
    while (n > 0) {
        seed s = stack[--n];
        if (!FILLABLE(s.x, s.y)) continue;
        int xl = s.x, xr = s.x;
        while (xl > v.x0 && FILLABLE(xl - 1, s.y)) xl--;
        while (xr < v.x1 && FILLABLE(xr + 1, s.y)) xr++;
        memset(seen + (size_t)s.y * w + xl, 1, (size_t)(xr - xl + 1));
        if (tile) {   /* the tile is aligned to the screen: pixel (x, y) takes its (x, y) mod size */
            const uint16_t *row = tile->attr + (size_t)(s.y % tile->h) * tile->w;
            for (int xx = xl; xx <= xr; xx++) pix[(size_t)s.y * w + xx] = row[xx % tile->w];
            if (xl < bx0) bx0 = xl;
            if (xr > bx1) bx1 = xr;
            if (s.y < by0) by0 = s.y;
            if (s.y > by1) by1 = s.y;
        } else {
            pc_fill_px(pix + (size_t)s.y * w + xl, color, (size_t)(xr - xl + 1));
            if (pc_push_span(c, s.y, xl, xr) != PC_OK) { ok = PC_ENOMEM; break; }
        }
        for (int dy = -1; dy <= 1; dy += 2) {
            int yy = s.y + dy;
            if (yy < v.y0 || yy > v.y1) continue;
            for (int xx = xl; xx <= xr; xx++) {
                if (!FILLABLE(xx, yy)) continue;
                if (n == cap) {
                    seed *grown = realloc(stack, 2 * cap * sizeof *stack);
                    if (!grown) { ok = pc_fail_code(c, PC_ENOMEM, "paint: out of memory"); goto done; }
                    stack = grown;
                    cap *= 2;
                }
                stack[n++] = (seed){xx, yy};
                while (xx < xr && FILLABLE(xx + 1, yy)) xx++;   /* one seed per run */
            }
        }
    }
#undef FILLABLE
done:
    free(seen);
    free(stack);
    if (ok != PC_OK) return ok;
    if (tile) return pc_record_pixels(c, bx0, by0, bx1, by1);
    pc_op *op = pc_push_op(c, PC_OP_FILL, color);
    if (!op) return PC_ENOMEM;
    op->x1 = fx; op->y1 = fy;
    op->first = first;
    op->count = (uint32_t)(c->nspans - first);
    return PC_OK;
}

int pc_paint(pc_canvas *c, double x, double y, int color, int border) {
    return flood(c, x, y, color, border, NULL);
}

int pc_paint_tile(pc_canvas *c, double x, double y, const pc_tile *tile, int border) {
    if (!tile || tile->w < 1 || tile->h < 1 || tile->w * tile->h > 8 * 64)
        return pc_fail(c, "paint: the tile is empty");
    for (int i = 0; i < tile->w * tile->h; i++)
        if (!pc_valid_color(c, tile->attr[i]))
            return pc_fail(c, "paint: tile colour %d out of range 0..%d", tile->attr[i], c->ncolors - 1);
    return flood(c, x, y, -1, border, tile);
}
