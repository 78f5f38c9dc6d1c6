/* TEXT: strings in the built-in VGA font (font.h), placed beside a point.  Like every other
 * statement it rasterises at once (transparent background: only the glyphs' ink is plotted)
 * and records one display-list operation, so the SVG writer puts a <text> at the same place. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "canvas.h"
#include "canvas_internal.h"
#include "font.h"
#include "math_label.h"

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

/* ---- math in the VGA look: the layout of math_label.c over 8-pixel cells; a script is the
 * 8x8 font (half the height of the 8x16 cell), so it is smaller and sits lower or higher ---- */

static double vga_measure(void *ctx, const char *s, size_t n, int italic, double size) {
    (void)italic; (void)size;
    long k = pc_utf8_count(s, n, NULL);
    return (double)(k < 0 ? 0 : k) * PC_FONT_W * *(const int *)ctx;
}

int pc_text_vga_layout(const char *utf8, int scale, pc_mlayout *L, char *err, size_t errlen) {
    return pc_math_layout(utf8, PC_FONT_H * scale, (double)PC_FONT_BASELINE / PC_FONT_H,
                          (double)(PC_FONT_H - PC_FONT_BASELINE) / PC_FONT_H, vga_measure, &scale,
                          L, err, errlen);
}

/* The nearest VGA character of one the font lacks (primes, dots, angle, parallel, perp). */
uint32_t pc_vga_fallback(const pc_font *f, uint32_t cp) {
    if (pc_font_glyph_in(f, cp) != f->replacement) return cp;
    static const uint32_t map[][2] = {{0x2032, '\''}, {0x2033, '"'}, {0x2034, '"'},
        {0x22c5, 0xb7}, {0x2220, '<'}, {0x2225, '|'}, {0x22a5, 'T'}, {0x2213, 0xb1},
        {0x2009, ' '}, {0x03f5, 0x03b5}, {0x03d5, 0x03c6}, {0x03d1, 0x03b8}, {0x2026, ':'},
        {0x2218, 'o'}, {0x25b3, '^'}, {0x2260, '#'}, {0x2245, '='}, {0x223c, '~'}};
    for (size_t i = 0; i < sizeof map / sizeof map[0]; i++)
        if (map[i][0] == cp) return map[i][1];
    return cp;
}

static void raster_glyph_in(pc_canvas *c, const pc_font *f, long x, long y, int glyph,
                            int scale, int color) {
    const uint8_t *rows = f->bits + (size_t)glyph * f->h;
    for (int r = 0; r < f->h; r++)
        for (int b = 0; b < PC_FONT_W; b++) {
            if (!(rows[r] & (0x80 >> b))) continue;
            for (int j = 0; j < scale; j++)
                for (int i = 0; i < scale; i++)
                    pc_plot(c, (int)(x + b * scale + i), (int)(y + r * scale + j), color);
        }
}

/* A math label with its cell box's top-left pixel at (left, top). */
static void raster_math(pc_canvas *c, const pc_mlayout *L, long left, long top, int scale,
                        int color) {
    long base = top + PC_FONT_BASELINE * scale;   /* the baseline row of the 8x16 cells */
    for (size_t i = 0; i < L->nruns; i++) {
        const pc_mrun *r = &L->runs[i];
        const pc_font *f = r->size >= PC_FONT_H * scale ? &pc_font_desc : &pc_font8_desc;
        long x = left + lrint(r->x), y = base - lrint(r->rise) - f->baseline * scale;
        size_t k = 0;
        uint32_t cp;
        while (pc_utf8_next(L->text + r->first, r->len, &k, &cp)) {
            raster_glyph_in(c, f, x, y, pc_font_glyph_in(f, pc_vga_fallback(f, cp)), scale, color);
            x += PC_FONT_W * scale;
        }
    }
    for (size_t i = 0; i < L->ndecos; i++) {   /* bars, arrows and waves: a row of pixels */
        const pc_mdeco *d = &L->decos[i];
        long y = base - lrint(d->rise), x0 = left + lrint(d->x0), x1 = left + lrint(d->x1) - 1;
        if (d->kind == PC_DECO_UNDER) y = pc_vga_under_y(base, y, scale);
        for (long x = x0; x <= x1; x++)
            pc_plot(c, (int)x, (int)(y + (d->kind == PC_DECO_TILDE ? pc_vga_tilde_dy(x - x0, x1 - x0 + 1, scale) : 0)), color);
        if (d->kind == PC_DECO_VEC)
            for (int k = 1; k <= 2 * scale; k++) {
                pc_plot(c, (int)(x1 - k), (int)(y - k), color);
                pc_plot(c, (int)(x1 - k), (int)(y + k), color);
            }
    }
}

long pc_vga_under_y(long base, long y, int scale) {
    long last = base + (long)(PC_FONT_H - PC_FONT_BASELINE) * scale - 1;
    return y > last ? last : y;
}

long pc_vga_tilde_dy(long i, long n, int scale) {
    if (n <= 0) return 0;
    /* rounded with ties (and a rounding error's worth) toward the middle row: the same
     * pixels on every machine where sin(pi/6) comes out a hair either side of 1/2 */
    double v = scale * sin(2 * M_PI * (i + 0.5) / n);
    return -(long)trunc(v + (v > 0 ? 0.4 : -0.4));
}

int pc_text_style(pc_canvas *c, const char *font, double size_pt, int halo) {
    if (!c->nops || c->ops[c->nops - 1].kind != PC_OP_TEXT)
        return pc_fail(c, "label: no text to style");
    if (size_pt && !(size_pt >= 1 && size_pt <= 200))
        return pc_fail(c, "label: size must be 1..200 pt, got %g", size_pt);
    if (font && strlen(font) >= sizeof c->tstyles->font)
        return pc_fail(c, "label: font name too long");
    if (c->ntstyles >= UINT16_MAX ||
        !pc_grow((void **)&c->tstyles, &c->captstyles, c->ntstyles + 1, sizeof *c->tstyles))
        return pc_fail_code(c, PC_ENOMEM, "out of memory for label styles");
    pc_textstyle *st = &c->tstyles[c->ntstyles++];
    memset(st, 0, sizeof *st);
    if (font) strcpy(st->font, font);
    st->size = size_pt;
    st->halo = halo;
    c->ops[c->nops - 1].pen = (uint16_t)c->ntstyles;   /* 1-based: 0 is the default style */
    return PC_OK;
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
    pc_mlayout L = {0};
    int math = pc_has_math(utf8);
    if (math) {   /* labels without '$' are drawn exactly as before */
        char err[sizeof c->error];
        ok = pc_text_vga_layout(utf8, scale, &L, err, sizeof err);
        if (ok != PC_OK) return pc_fail_code(c, ok, "%s", err);
        w = lrint(L.width);
    }
    place(anchor, pc_px(sx), pc_px(sy), lrint(gap), w, h, &left, &top);
    uint32_t first = 0;
    if ((ok = push_text(c, utf8, n, &first)) != PC_OK) {
        pc_mlayout_free(&L);
        return ok;
    }
    size_t i = 0;
    uint32_t cp;
    if (math) {
        if (!autoplace) raster_math(c, &L, left, top, scale, color);
        pc_mlayout_free(&L);
    } else {
        for (long k = 0; !autoplace && pc_utf8_next(utf8, n, &i, &cp); k++)
            raster_glyph(c, left + k * PC_FONT_W * scale, top, pc_font_glyph(cp), scale, color);
    }
    pc_op *op = pc_push_op(c, PC_OP_TEXT, color);
    if (!op) return PC_ENOMEM;
    op->flags = (uint8_t)(anchor | (autoplace ? PC_TEXT_AUTO : 0));
    op->x1 = (double)left;
    op->y1 = (double)top;
    op->x2 = sx;
    op->y2 = sy;
    op->rx = scale;
    op->a0 = math;   /* the print look lays out math only where pc_text found it (not PRINT) */
    op->first = first;
    op->count = (uint32_t)n;
    return PC_OK;   /* the graphics cursor stays: QBasic's PRINT does not move it either */
}

void pc_text_raster(pc_canvas *c, const pc_op *op) {
    const char *s = c->text + op->first;
    size_t n = op->count, i = 0;
    int scale = (int)op->rx;
    long left = lrint(op->x1), top = lrint(op->y1);
    if (op->a0) {   /* a math label, laid out again as pc_text did (it parsed then) */
        char *copy = malloc(n + 1);
        pc_mlayout L = {0};
        if (!copy) return;
        memcpy(copy, s, n);
        copy[n] = 0;
        char err[160];
        if (pc_text_vga_layout(copy, scale, &L, err, sizeof err) == PC_OK)
            raster_math(c, &L, left, top, scale, op->color);
        pc_mlayout_free(&L);
        free(copy);
        return;
    }
    uint32_t cp;
    for (long k = 0; pc_utf8_next(s, n, &i, &cp); k++)
        raster_glyph(c, left + k * PC_FONT_W * scale, top, pc_font_glyph(cp), scale, op->color);
}
