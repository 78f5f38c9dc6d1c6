/* TEXT: strings in the built-in VGA font (font.h), placed beside a point.  Like every other
 * statement it rasterises at once (transparent background: only the glyphs' ink is plotted)
 * and records one display-list operation, so the SVG writer puts a <text> at the same place. */
#include <math.h>
#include <string.h>
#include "canvas.h"
#include "canvas_internal.h"
#include "font.h"

#define MAX_SCALE 8

int pc_text_size(const char *utf8, int scale, int *w, int *h) {
    if (!utf8 || scale < 1 || scale > MAX_SCALE) return PC_EARG;
    long n = pc_utf8_count(utf8, strlen(utf8), NULL);
    if (n < 0 || n > 1000000) return PC_EARG;
    *w = (int)n * PC_FONT_W * scale;
    *h = PC_FONT_H * scale;
    return PC_OK;
}

/* The top-left pixel of a w x h box on the `anchor` side of pixel (X, Y), g pixels off it. */
static void place(int anchor, long X, long Y, long g, long w, long h, long *left, long *top) {
    switch (anchor) {   /* columns: the box's left edge */
    case PC_ANCHOR_NE: case PC_ANCHOR_E: case PC_ANCHOR_SE: *left = X + g; break;
    case PC_ANCHOR_NW: case PC_ANCHOR_W: case PC_ANCHOR_SW: *left = X - g - w + 1; break;
    default: *left = X - w / 2; break;
    }
    switch (anchor) {   /* rows: the box's top edge */
    case PC_ANCHOR_NW: case PC_ANCHOR_N: case PC_ANCHOR_NE: *top = Y - g - h + 1; break;
    case PC_ANCHOR_SW: case PC_ANCHOR_S: case PC_ANCHOR_SE: *top = Y + g; break;
    default: *top = Y - h / 2; break;
    }
}

/* One glyph with its top-left pixel at (x, y), each font pixel a scale x scale block. */
static void raster_glyph(pc_canvas *c, long x, long y, int glyph, int scale, int color) {
    const uint8_t *rows = pc_font_bits[glyph];
    const pc_rect *v = &c->view;
    if (x > v->x1 || y > v->y1 || x + PC_FONT_W * scale <= v->x0 || y + PC_FONT_H * scale <= v->y0)
        return;
    for (int r = 0; r < PC_FONT_H; r++)
        for (int b = 0; b < PC_FONT_W; b++) {
            if (!(rows[r] & (0x80 >> b))) continue;
            for (int j = 0; j < scale; j++)
                for (int i = 0; i < scale; i++)
                    pc_plot(c, (int)(x + b * scale + i), (int)(y + r * scale + j), color);
        }
}

static int push_text(pc_canvas *c, const char *s, size_t n, uint32_t *first) {
    if (c->ntext + n > UINT32_MAX ||
        !pc_grow((void **)&c->text, &c->captext, c->ntext + n, 1))
        return pc_fail_code(c, PC_ENOMEM, "out of memory for text");
    memcpy(c->text + c->ntext, s, n);
    *first = (uint32_t)c->ntext;
    c->ntext += n;
    return PC_OK;
}

int pc_text(pc_canvas *c, double x, double y, const char *utf8, int anchor, double gap,
            int scale, int color) {
    int ok = pc_check_color(c, &color, c->fg);
    if (ok != PC_OK) return ok;
    if (!utf8) return pc_fail(c, "text: no text");
    if (anchor < PC_ANCHOR_C || anchor > PC_ANCHOR_AUTO)
        return pc_fail(c, "text: anchor %d is not one of the nine sides", anchor);
    if (scale < 1 || scale > MAX_SCALE)
        return pc_fail(c, "text: scale must be an integer 1..%d, got %d", MAX_SCALE, scale);
    if (!(gap >= 0 && gap <= 1e6))
        return pc_fail(c, "text: gap must be 0..1e6 pixels, got %g", gap);
    size_t n = strlen(utf8), bad = 0;
    long nchars = pc_utf8_count(utf8, n, &bad);
    if (nchars < 0) return pc_fail(c, "text: invalid UTF-8 at byte %zu", bad + 1);
    if (!(isfinite(x) && isfinite(y)))
        return pc_fail(c, "text: coordinates must be finite numbers, got (%g, %g)", x, y);
    double sx, sy;
    pc_world_to_screen(c, x, y, &sx, &sy);
    if (!(isfinite(sx) && isfinite(sy)))
        return pc_fail(c, "text: coordinates (%g, %g) are too far outside the window", x, y);

    long w = nchars * PC_FONT_W * scale, h = PC_FONT_H * scale, left, top;
    int autoplace = anchor == PC_ANCHOR_AUTO;   /* recorded now, placed and drawn at write */
    if (autoplace) anchor = PC_ANCHOR_NE, gap = 3;
    place(anchor, pc_px(sx), pc_px(sy), lrint(gap), w, h, &left, &top);
    uint32_t first = 0;
    if ((ok = push_text(c, utf8, n, &first)) != PC_OK) return ok;
    size_t i = 0;
    uint32_t cp;
    for (long k = 0; !autoplace && pc_utf8_next(utf8, n, &i, &cp); k++)
        raster_glyph(c, left + k * PC_FONT_W * scale, top, pc_font_glyph(cp), scale, color);
    pc_op *op = pc_push_op(c, PC_OP_TEXT, color);
    if (!op) return PC_ENOMEM;
    op->flags = (uint8_t)(anchor | (autoplace ? PC_TEXT_AUTO : 0));
    op->x1 = (double)left;
    op->y1 = (double)top;
    op->x2 = sx;
    op->y2 = sy;
    op->rx = scale;
    op->first = first;
    op->count = (uint32_t)n;
    return PC_OK;   /* the graphics cursor stays: QBasic's PRINT does not move it either */
}

void pc_text_raster(pc_canvas *c, const pc_op *op) {
    const char *s = c->text + op->first;
    size_t n = op->count, i = 0;
    int scale = (int)op->rx;
    long left = lrint(op->x1), top = lrint(op->y1);
    uint32_t cp;
    for (long k = 0; pc_utf8_next(s, n, &i, &cp); k++)
        raster_glyph(c, left + k * PC_FONT_W * scale, top, pc_font_glyph(cp), scale, op->color);
}
