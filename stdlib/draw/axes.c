/* Axes, round ticks and legends (axes.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "axes.h"
#include "canvas_internal.h"
#include "furniture.h"
#include "layout.h"

int pc_nice_ticks(double lo, double hi, int target, double *first, double *step, int *n) {
    if (!(isfinite(lo) && isfinite(hi) && lo < hi)) return PC_EARG;
    if (target < 1) target = 1;
    double raw = (hi - lo) / target, p = pow(10, floor(log10(raw))), f = raw / p;
    /* the nearest of 1, 2, 5, 10 times the power (by ratio: the geometric midpoints) */
    double m = f < sqrt(2) ? 1 : f < sqrt(10) ? 2 : f < sqrt(50) ? 5 : 10;
    double s = m * p, a = ceil(lo / s - 1e-9) * s;
    int k = (int)floor((hi - a) / s + 1e-9) + 1;
    if (k > 1000) return PC_EARG;
    *first = fabs(a) < 1e-12 * s ? 0 : a;   /* no -0 */
    *step = s;
    *n = k;
    return PC_OK;
}

static int wline(pc_canvas *c, double x0, double y0, double x1, double y1, int color) {
    return pc_line(c, x0, y0, x1, y1, color);
}

/* A tick across the axis at world (x, y): dx, dy the unit normal on the screen. */
static int tick(pc_canvas *c, double x, double y, double nx, double ny, int color) {
    double sx, sy, ax, ay, bx, by;
    pc_world_to_screen(c, x, y, &sx, &sy);
    pc_screen_to_world(c, sx - 3 * nx, sy - 3 * ny, &ax, &ay);
    pc_screen_to_world(c, sx + 3 * nx, sy + 3 * ny, &bx, &by);
    return wline(c, ax, ay, bx, by, color);
}

static int dotted(pc_canvas *c, double x0, double y0, double x1, double y1, int color) {
    pc_stroke old = c->pens[c->pen];
    static const double dash[2] = {1, 3};
    int st = pc_pen(c, old.width, dash, 2);
    if (st == PC_OK) st = wline(c, x0, y0, x1, y1, color);
    int back = pc_pen(c, old.width, old.ndash ? old.dash : NULL, old.ndash);
    return st != PC_OK ? st : back;
}

int pc_axes(pc_canvas *c, const pc_axes_spec *a, int color, int *nticks) {
    if (!(isfinite(a->x0) && isfinite(a->x1) && isfinite(a->y0) && isfinite(a->y1) &&
          a->x0 < a->x1 && a->y0 < a->y1))
        return pc_fail(c, "axes: the ranges must be finite with x0 < x1 and y0 < y1");
    if (!(isfinite(a->ox) && isfinite(a->oy))) return pc_fail(c, "axes: the origin must be finite");
    int st0;   /* in a figure framed when written: drawn once the frame is known */
    if (pc_furniture_defer_axes(c, a, color, nticks, &st0)) return st0;
    double ox = fmin(fmax(a->ox, a->x0), a->x1), oy = fmin(fmax(a->oy, a->y0), a->y1);
    int st = PC_OK, count = 0, gc = a->grid_color >= 0 ? a->grid_color : color;
    for (int axis = 0; axis < 2 && st == PC_OK; axis++) {
        double lo = axis ? a->y0 : a->x0, hi = axis ? a->y1 : a->x1, first = 0, step = 1;
        int n = 0;
        if (a->ticks > 0 && pc_nice_ticks(lo, hi, a->ticks, &first, &step, &n) != PC_OK)
            return pc_fail(c, "axes: too many ticks");
        /* the screen direction of the axis, for the ticks' normal */
        double sx0, sy0, sx1, sy1;
        pc_world_to_screen(c, axis ? ox : lo, axis ? lo : oy, &sx0, &sy0);
        pc_world_to_screen(c, axis ? ox : hi, axis ? hi : oy, &sx1, &sy1);
        double len = hypot(sx1 - sx0, sy1 - sy0);
        if (!(len > 0)) return pc_fail(c, "axes: an axis has no length on the screen");
        double nx = -(sy1 - sy0) / len, ny = (sx1 - sx0) / len;
        for (int k = 0; k < n && st == PC_OK; k++) {
            double v = first + k * step;
            if (fabs(v) < 1e-12 * step) v = 0;
            double x = axis ? ox : v, y = axis ? v : oy;
            if (a->grid)
                st = axis ? dotted(c, a->x0, v, a->x1, v, gc) : dotted(c, v, a->y0, v, a->y1, gc);
            if (st == PC_OK) st = tick(c, x, y, nx, ny, color);
            count++;
            if (st == PC_OK && a->labels && fabs(v - (axis ? oy : ox)) > 1e-9 * step) {
                char buf[32];
                snprintf(buf, sizeof buf, "%g", v);
                st = pc_text(c, x, y, buf, axis ? PC_ANCHOR_W : PC_ANCHOR_S, 5, 1, color);
            }
        }
        if (st == PC_OK && a->arrows)
            st = pc_arrow(c, axis ? ox : lo, axis ? lo : oy, axis ? ox : hi, axis ? hi : oy,
                          PC_ARROW_END, 9, color);
        else if (st == PC_OK)
            st = wline(c, axis ? ox : lo, axis ? lo : oy, axis ? ox : hi, axis ? hi : oy, color);
    }
    if (nticks) *nticks = count;
    return st;
}

int pc_legend(pc_canvas *c, int n, const char *const *names, const int *colors, int corner,
              int color) {
    if (n < 1 || n > 100) return pc_fail(c, "legend: 1..100 entries, got %d", n);
    if (corner != PC_ANCHOR_NE && corner != PC_ANCHOR_NW && corner != PC_ANCHOR_SE && corner != PC_ANCHOR_SW)
        return pc_fail(c, "legend: the corner must be ne, nw, se or sw");
    int st0;   /* in a figure framed when written: drawn after the framing, in device units */
    double w = 0, h = 0;
    for (int i = 0; i < n; i++) {
        double tw, th;
        if (pc_text_measure(c, names[i], strlen(names[i]), 1, &tw, &th) != PC_OK)
            return pc_fail(c, "legend: invalid UTF-8 in entry %d", i + 1);
        w = fmax(w, tw);
        h += th + 2;
    }
    if (pc_furniture_defer_legend(c, n, names, colors, corner, color, &st0)) return st0;
    double bw = 6 + 20 + 6 + w + 6, bh = h + 6;
    int east = corner == PC_ANCHOR_NE || corner == PC_ANCHOR_SE;
    int south = corner == PC_ANCHOR_SE || corner == PC_ANCHOR_SW;
    double x0 = east ? c->width - 8 - bw : 8, y0 = south ? c->height - 8 - bh : 8;
    /* drawn in device units: the window and VIEW set aside for it */
    pc_rect v = c->view;
    int vs = c->view_screen, hw = c->has_window;
    c->view = (pc_rect){0, 0, c->width - 1, c->height - 1};
    c->view_screen = 1;
    c->has_window = 0;
    int st = pc_box(c, x0, y0, x0 + bw, y0 + bh, color, 0);
    double y = y0 + 4;
    for (int i = 0; i < n && st == PC_OK; i++) {
        double th = 16;
        st = pc_line(c, x0 + 6, y + th / 2, x0 + 26, y + th / 2, colors[i]);
        if (st == PC_OK) st = pc_text(c, x0 + 32, y, names[i], PC_ANCHOR_SE, 0, 1, color);
        y += th + 2;
    }
    c->view = v;
    c->view_screen = vs;
    c->has_window = hw;
    return st;
}
