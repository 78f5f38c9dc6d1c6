/* Figure items the bindings used to build themselves (furniture.h): captions and text in
 * device units, the default axes of the window, the graph of a function, the labels as
 * placed when the picture is written. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "furniture.h"
#include "axes.h"
#include "layout.h"
#include "print.h"
#include "canvas_internal.h"

/* The text op just recorded is in device units: framing leaves it where it is. */
static int device(pc_canvas *c, int st) {
    if (st == PC_OK) c->ops[c->nops - 1].flags |= PC_TEXT_DEVICE;
    return st;
}

int pc_caption(pc_canvas *c, const char *utf8, int top, int color) {
    pc_rect v = c->view;
    int vs = c->view_screen;   /* the whole screen, not the VIEW: a caption is the figure's */
    c->view = (pc_rect){0, 0, c->width - 1, c->height - 1};
    c->view_screen = 1;
    double wx, wy;
    pc_screen_to_world(c, c->width / 2.0, top ? 0 : c->height - 1, &wx, &wy);
    int st = device(c, pc_text(c, wx, wy, utf8, top ? PC_ANCHOR_S : PC_ANCHOR_N, 3, 1, color));
    c->view = v;
    c->view_screen = vs;
    return st;
}

int pc_text_device(pc_canvas *c, double x, double y, const char *utf8, int scale, int color) {
    pc_screen_to_world(c, x, y, &x, &y);   /* device pixels, whatever the window */
    return device(c, pc_text(c, x, y, utf8, PC_ANCHOR_SE, 0, scale, color));
}

void pc_axes_default(const pc_canvas *c, pc_axes_spec *s) {
    double wx0, wy0, wx1, wy1;   /* the window's (or the screen's) extent */
    pc_screen_to_world(c, c->view.x0, c->view.y1, &wx0, &wy0);
    pc_screen_to_world(c, c->view.x1, c->view.y0, &wx1, &wy1);
    *s = (pc_axes_spec){fmin(wx0, wx1), fmax(wx0, wx1), fmin(wy0, wy1), fmax(wy0, wy1), 0, 0, 5, 1, 1, 0, -1};
}

int pc_axes_options(pc_canvas *c, const pc_axes_opts *o, int color, int *nticks) {
    pc_axes_spec s;
    pc_axes_default(c, &s);
    if (o->x) s.x0 = o->x[0], s.x1 = o->x[1];
    if (o->y) s.y0 = o->y[0], s.y1 = o->y[1];
    if (!(s.x0 < s.x1)) return pc_fail(c, "option 'x' must be {lo, hi} with lo < hi");
    if (!(s.y0 < s.y1)) return pc_fail(c, "option 'y' must be {lo, hi} with lo < hi");
    if (o->origin) s.ox = o->origin[0], s.oy = o->origin[1];
    s.ticks = o->ticks, s.labels = o->labels, s.arrows = o->arrows, s.grid = o->grid, s.grid_color = o->grid_color;
    return pc_axes(c, &s, color, nticks);
}

int pc_graph(pc_canvas *c, double x0, double x1, int n, pc_graph_fn f, void *ctx, int color) {
    double *xy = malloc(sizeof(double) * 2 * ((size_t)n + 1));
    uint8_t *verbs = malloc((size_t)n + 1);
    int st = xy && verbs ? PC_OK : PC_ENOMEM;
    size_t m = 0, start = 0;
    for (int k = 0; k <= n && st == PC_OK; k++) {
        double x = x0 + (x1 - x0) * (double)k / (double)n, y;
        int have = 0;
        st = f(ctx, x, &y, &have);
        if (st != PC_OK) break;
        if (!have || !isfinite(y)) {   /* a gap: what came before is one piece */
            if (m - start == 1) m = start;   /* a lone point draws nothing */
            start = m;
            continue;
        }
        xy[2 * m] = x;
        xy[2 * m + 1] = y;
        verbs[m] = m == start ? PC_PATH_MOVE : PC_PATH_LINE;
        m++;
    }
    if (m - start == 1) m = start;
    if (st == PC_OK && m) st = pc_path(c, m, xy, verbs, m, 0, color);
    free(xy);
    free(verbs);
    return st;
}

pc_placed *pc_placed_labels(const pc_canvas *c, size_t *count) {
    static const char *const names[] = {"c", "n", "ne", "e", "se", "s", "sw", "w", "nw"};
    pc_canvas tmp;   /* as a writer gets it: placed (by Pango's boxes in the print look) */
    const pc_canvas *base = c->figure.on ? &tmp : c;
    const pc_canvas *r = c->figure.on ? pc_print_resolve(c, &tmp) : pc_layout_resolve(c);
    pc_box2 *b = NULL;
    int *side = NULL;
    size_t n = 0, k = 0, bytes = 0;
    pc_placed *out = NULL;
    if (r && pc_layout_labels(r, &b, &side, &n) == PC_OK) {
        for (size_t i = 0; i < r->nops; i++)
            if (r->ops[i].kind == PC_OP_TEXT) bytes += r->ops[i].count + 1;
        out = malloc(sizeof *out * n + bytes + 1);
    }
    char *text = out ? (char *)(out + n) : NULL;
    for (size_t i = 0; out && i < r->nops && k < n; i++) {
        const pc_op *op = &r->ops[i];
        if (op->kind != PC_OP_TEXT) continue;
        memcpy(text, r->text + op->first, op->count);
        text[op->count] = 0;
        out[k] = (pc_placed){text, op->count, b[k], names[side[k] >= 0 && side[k] <= 8 ? side[k] : 0],
                             (op->flags & (PC_TEXT_AUTO | PC_TEXT_PLACED)) != 0};
        text += op->count + 1;
        k++;
    }
    free(b);
    free(side);
    if (r) pc_layout_release(base, r);
    *count = k;
    return out;
}

int pc_path_stmt(pc_canvas *c, size_t n, const double *xy, const uint8_t *verbs, int closed, int color, int heads,
                 int filled, int fill_color, int rule) {
    int st;
    if (filled) {
        st = pc_fill_path(c, n, xy, verbs, n, rule, fill_color);
        return st == PC_OK && color >= 0 ? pc_path(c, n, xy, verbs, n, 1, color) : st;
    }
    st = pc_path(c, n, xy, verbs, n, closed, color);
    if (st == PC_OK && (heads & PC_ARROW_END) && n >= 2)
        st = pc_arrow_head(c, xy[2 * n - 4], xy[2 * n - 3], xy[2 * n - 2], xy[2 * n - 1], 9, color);
    if (st == PC_OK && (heads & PC_ARROW_START) && n >= 2) st = pc_arrow_head(c, xy[2], xy[3], xy[0], xy[1], 9, color);
    return st;
}

int pc_fit_options(pc_canvas *c, const pc_fit_opts *o) {
    /* margin (pixels, of what is drawn) and pad (world units, of the points) each belong to one
     * of the two framings, so the other is refused rather than ignored */
    if (o->around && o->has_margin)
        return pc_fail(c, "margin frames what is drawn (in pixels); with around give pad (world units)");
    if (o->around) return pc_fit_around_band(c, o->n, o->xy, o->pad, o->band, o->aspect);
    if (o->has_pad) return pc_fail(c, "pad is the room round the points of around: give around too (or margin)");
    if (o->has_band) return pc_fail(c, "band is the caption's room under the points of around: give around too");
    return pc_fit(c, o->margin, o->aspect);
}

int pc_figure_options(pc_canvas *c, const pc_figure_opts *o) {
    pc_figure f = c->figure;
    if (o->has_width || o->has_height) {
        f.width = o->has_width ? o->width : 0;
        f.height = o->has_height ? o->height : 0;
    }
    if (o->has_dpi) f.dpi = o->dpi;
    if (o->font) {
        if (strlen(o->font) >= sizeof f.font) return pc_fail(c, "option 'font' is too long");
        strcpy(f.font, o->font);
    }
    if (o->has_size) f.size = o->size;
    f.frame = 1;   /* a figure of its own: framed to its content when it sets no window */
    return pc_figure_set(c, &f);
}

int pc_pen_options(pc_canvas *c, const pc_pen_opts *o) {
    int physical = (o->has_width && o->width_len) || (o->has_dash && o->dash_len);   /* lengths with units */
    if (physical && o->has_width && !o->width_len)
        return pc_fail(c, "option 'width' must be a length with its unit, as the dash is, got %.14g", o->width);
    if (physical && o->has_dash && !o->dash_len)
        return pc_fail(c, "option 'dash' must hold lengths with their units, as the width is");
    double width = o->has_width ? o->width : physical ? PC_PRINT_PEN_PT : 1;
    return (physical ? pc_pen_physical : pc_pen)(c, width, o->dash, o->ndash);
}
