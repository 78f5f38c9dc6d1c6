/* Canvas state: allocation, SCREEN modes, palettes, WINDOW/VIEW mapping and the display list.
 * The rasterising statements themselves are in raster.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "canvas.h"
#include "canvas_internal.h"
#include "qbscreen.h"

/* VGA DAC values are 6-bit; widen them the way VGA hardware and emulators do. */
static uint8_t dac8(int v) { return (uint8_t)((v << 2) | (v >> 4)); }

static pc_rgb dac(int r, int g, int b) { return (pc_rgb){dac8(r), dac8(g), dac8(b)}; }

/* The 16 EGA/VGA text colours (6-bit DAC levels 0, 21, 42, 63; brown is 42,21,0). */
static const uint8_t ega16[16][3] = {
    {0, 0, 0},    {0, 0, 42},   {0, 42, 0},   {0, 42, 42},  {42, 0, 0},   {42, 0, 42},
    {42, 21, 0},  {42, 42, 42}, {21, 21, 21}, {21, 21, 63}, {21, 63, 21}, {21, 63, 63},
    {63, 21, 21}, {63, 21, 63}, {63, 63, 21}, {63, 63, 63}};

/* The default mode-13h palette: 16 EGA colours, 16 greys, then 3 intensities x 3 saturations
 * of a 24-step hue wheel (blue, magenta, red, yellow, green, cyan and back), then 8 blacks. */
static void vga256(pc_rgb *pal) {
    static const int greys[16] = {0, 5, 8, 11, 14, 17, 20, 24, 28, 32, 36, 40, 45, 50, 56, 63};
    /* per intensity and saturation: the five levels from "off" to "full" */
    static const int levels[3][3][5] = {
        {{0, 16, 31, 47, 63}, {31, 39, 47, 55, 63}, {45, 49, 54, 58, 63}},
        {{0, 7, 14, 21, 28}, {14, 17, 21, 24, 28}, {20, 22, 24, 26, 28}},
        {{0, 4, 8, 12, 16}, {8, 10, 12, 14, 16}, {11, 12, 13, 15, 16}}};
    for (int i = 0; i < 16; i++) pal[i] = dac(ega16[i][0], ega16[i][1], ega16[i][2]);
    for (int i = 0; i < 16; i++) pal[16 + i] = dac(greys[i], greys[i], greys[i]);
    int k = 32;
    for (int in = 0; in < 3; in++)
        for (int sat = 0; sat < 3; sat++) {
            const int *l = levels[in][sat];
            /* hue wheel: each channel ramps up, holds, ramps down over 24 steps */
            for (int h = 0; h < 24; h++) {
                int r, g, b;
                if (h < 4)       { r = l[h];      g = l[0];      b = l[4]; }
                else if (h < 8)  { r = l[4];      g = l[0];      b = l[8 - h]; }
                else if (h < 12) { r = l[4];      g = l[h - 8];  b = l[0]; }
                else if (h < 16) { r = l[16 - h]; g = l[4];      b = l[0]; }
                else if (h < 20) { r = l[0];      g = l[4];      b = l[h - 16]; }
                else             { r = l[0];      g = l[24 - h]; b = l[4]; }
                pal[k++] = dac(r, g, b);
            }
        }
    while (k < 256) pal[k++] = dac(0, 0, 0);
}

void pc_palette_default(pc_rgb *pal, int ncolors) {
    memset(pal, 0, 256 * sizeof *pal);
    if (ncolors > 16) {
        vga256(pal);
        return;
    }
    for (int i = 0; i < 16; i++) pal[i] = dac(ega16[i][0], ega16[i][1], ega16[i][2]);
    if (ncolors == 2) pal[1] = dac(63, 63, 63);   /* two colours: white ink, as SCREEN 2 */
    if (ncolors == 4) {   /* four: SCREEN 1's palette 1, light cyan, light magenta, white */
        pal[1] = dac(21, 63, 63);
        pal[2] = dac(63, 21, 63);
        pal[3] = dac(63, 63, 63);
    }
}

int pc_canvas_reset(pc_canvas *c, int width, int height, int ncolors) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        return pc_fail(c, "screen size %dx%d out of range 1..16384", width, height);
    if (ncolors != 2 && ncolors != 4 && ncolors != 16 && ncolors != 256)
        return pc_fail(c, "number of colours must be 2, 4, 16 or 256, got %d", ncolors);
    uint16_t *px = calloc((size_t)width * height, sizeof *px);
    if (!px) return pc_fail_code(c, PC_ENOMEM, "out of memory for a %dx%d screen", width, height);
    if (!c->palette && !(c->palette = malloc(256 * sizeof *c->palette))) {
        free(px);
        return pc_fail_code(c, PC_ENOMEM, "out of memory for the palette");
    }
    if (!c->pens && !(c->pens = malloc(sizeof *c->pens))) {
        free(px);
        return pc_fail_code(c, PC_ENOMEM, "out of memory for the pens");
    }
    if (!c->cappens) c->cappens = 1;
    free(c->pixels);
    c->pixels = px;
    c->width = width;
    c->height = height;
    c->ncolors = ncolors;
    pc_palette_default(c->palette, ncolors);
    c->ntrue = 0;
    if (c->rgb_index) memset(c->rgb_index, 0, c->rgb_slots * sizeof *c->rgb_index);
    c->pens[0] = (pc_stroke){.width = 1};
    c->npens = 1;
    c->pen = 0;
    c->fg = ncolors - 1 < 15 ? ncolors - 1 : 15;
    c->bg = c->paper = 0;
    c->has_window = c->window_screen = 0;
    c->view = (pc_rect){0, 0, width - 1, height - 1};
    c->view_screen = 0;
    c->nops = c->nspans = c->ndots = c->nclips = c->npts = c->ntext = 0;
    c->ntstyles = 0;
    pc_lpx_clear(c);
    pc_canvas_detach(c);
    c->dot_budget = (size_t)width * (size_t)height > 65536 ? (size_t)width * (size_t)height : 65536;
    c->dirty = 0;
    c->version++;
    c->error[0] = 0;
    if (pc_push_clip(c) != PC_OK) return PC_ENOMEM;
    pc_reset_cursor(c);
    return PC_OK;
}

pc_canvas *pc_canvas_new(int width, int height, int ncolors) {
    pc_canvas *c = calloc(1, sizeof *c);
    if (!c) return NULL;
    if (pc_canvas_reset(c, width, height, ncolors) != PC_OK) {
        pc_canvas_free(c);
        return NULL;
    }
    return c;
}

pc_canvas *pc_canvas_new_mode(int mode) {
    pc_mode_info m;   /* QBasic's modes: qbscreen.c */
    if (pc_mode_info_of(mode, &m) != PC_OK) return NULL;
    return pc_canvas_new(m.width, m.height, m.ncolors);
}

void pc_canvas_detach(pc_canvas *c) {
    if (c->attach_drop) c->attach_drop(c->attach);
    c->attach = NULL;
    c->attach_resolve = NULL;
    c->attach_drop = NULL;
    c->attach_extent = NULL;
    c->attach_frame = NULL;
    pc_furniture_forget(c);
}

void pc_canvas_free(pc_canvas *c) {
    if (!c) return;
    pc_canvas_detach(c);
    free(c->pixels);
    free(c->ops);
    free(c->tstyles);
    free(c->spans);
    free(c->dots);
    free(c->clips);
    free(c->pts);
    free(c->tags);
    free(c->text);
    free(c->lpx);
    free(c->palette);
    free(c->rgb_index);
    free(c->pens);
    free(c);
}

/* ---- errors ------------------------------------------------------------------------------ */

int pc_fail_code(pc_canvas *c, int code, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->error, sizeof c->error, fmt, ap);
    va_end(ap);
    return code;
}

int pc_check_color(pc_canvas *c, int *color, int dflt) {
    if (*color < 0) *color = dflt;
    if (!pc_valid_color(c, *color))
        return pc_fail(c, "colour %d out of range 0..%d", *color, c->ncolors - 1);
    return PC_OK;
}

/* ---- the display list -------------------------------------------------------------------- */

int pc_grow(void **buf, size_t *cap, size_t need, size_t elem) {
    if (need <= *cap) return 1;
    size_t n = *cap ? *cap * 2 : 256;
    while (n < need) n *= 2;
    void *p = realloc(*buf, n * elem);
    if (!p) return 0;
    *buf = p;
    *cap = n;
    return 1;
}

pc_op *pc_push_op(pc_canvas *c, pc_op_kind kind, int color) {
    if (!pc_grow((void **)&c->ops, &c->capops, c->nops + 1, sizeof *c->ops)) {
        pc_fail_code(c, PC_ENOMEM, "out of memory for the display list");
        return NULL;
    }
    pc_op *op = &c->ops[c->nops++];
    memset(op, 0, sizeof *op);
    op->kind = (uint8_t)kind;
    op->color = (uint16_t)color;
    if (kind != PC_OP_CLEAR) c->dirty = 1;
    c->version++;
    return op;
}

int pc_push_span(pc_canvas *c, int y, int x0, int x1) {
    if (!pc_grow((void **)&c->spans, &c->capspans, c->nspans + 1, sizeof *c->spans))
        return pc_fail_code(c, PC_ENOMEM, "out of memory for a painted region");
    c->spans[c->nspans++] = (pc_span){(int16_t)y, (int16_t)x0, (int16_t)x1};
    return PC_OK;
}

int pc_push_dot(pc_canvas *c, double x, double y, int color) {
    pc_op *last = c->nops ? &c->ops[c->nops - 1] : NULL;
    /* a new run: the last op is no dots of this colour, or VIEW changed after it */
    if (!last || last->kind != PC_OP_DOTS || last->color != color ||
        c->clips[c->nclips - 1].first == c->nops) {
        last = pc_push_op(c, PC_OP_DOTS, color);
        if (!last) return PC_ENOMEM;
        last->first = (uint32_t)c->ndots;
    } else {
        c->dirty = 1;
        c->version++;
    }
    if (c->ndots >= UINT32_MAX ||
        !pc_grow((void **)&c->dots, &c->capdots, c->ndots + 1, sizeof *c->dots))
        return pc_fail_code(c, PC_ENOMEM, "out of memory for the display list");
    c->dots[c->ndots++] = (pc_xy){x, y};
    last->count++;
    if (c->ndots > c->fold_mark && c->ndots - c->fold_mark > c->dot_budget) pc_fold_dots(c);
    return PC_OK;
}

static int same_rect(const pc_rect *a, const pc_rect *b) {
    return a->x0 == b->x0 && a->y0 == b->y0 && a->x1 == b->x1 && a->y1 == b->y1;
}

/* The view becomes the clip of the ops drawn from now on.  A clip no op was drawn in yet is
 * replaced (or dropped, when the view returns to the one before it), so every clip but the
 * last has ops and the runs' firsts increase strictly: memory grows with what is drawn, not
 * with the number of VIEW statements. */
int pc_push_clip(pc_canvas *c) {
    if (c->nclips && same_rect(&c->clips[c->nclips - 1].r, &c->view)) return PC_OK;
    if (c->nclips && c->clips[c->nclips - 1].first == c->nops) {
        if (c->nclips >= 2 && same_rect(&c->clips[c->nclips - 2].r, &c->view))
            c->nclips--;
        else
            c->clips[c->nclips - 1].r = c->view;
        return PC_OK;
    }
    if (!pc_grow((void **)&c->clips, &c->capclips, c->nclips + 1, sizeof *c->clips))
        return pc_fail_code(c, PC_ENOMEM, "out of memory for a VIEW change");
    c->clips[c->nclips++] = (pc_clip){c->view, c->nops};
    return PC_OK;
}

size_t pc_op_clip(const pc_canvas *c, size_t i) {
    size_t lo = 0, hi = c->nclips;   /* the last clip whose first is <= i */
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (c->clips[mid].first <= i) lo = mid;
        else hi = mid;
    }
    return lo;
}

/* ---- WINDOW and VIEW ------------------------------------------------------------------- */

/* QBasic puts the graphics cursor at the centre of the view after SCREEN, VIEW and WINDOW. */
void pc_reset_cursor(pc_canvas *c) {
    double sx = (c->view.x0 + c->view.x1) / 2.0, sy = (c->view.y0 + c->view.y1) / 2.0;
    pc_screen_to_world(c, sx, sy, &c->last_x, &c->last_y);
}

/* A figure{} framed to its content (layout.h) has world units with y up and no window yet:
 * the screen is the world mirrored, and the writers frame it. */
int pc_figure_frames(const pc_canvas *c) {
    return c->figure.on && c->figure.frame && !c->has_window && !c->screen_pixels;
}

void pc_world_to_screen(const pc_canvas *c, double wx, double wy, double *sx, double *sy) {
    const pc_rect *v = &c->view;
    if (c->has_window) {
        *sx = v->x0 + (wx - c->wx1) * (v->x1 - v->x0) / (c->wx2 - c->wx1);
        if (c->window_screen)
            *sy = v->y0 + (wy - c->wy1) * (v->y1 - v->y0) / (c->wy2 - c->wy1);
        else
            *sy = v->y0 + (c->wy2 - wy) * (v->y1 - v->y0) / (c->wy2 - c->wy1);
    } else if (c->view_screen) {
        *sx = wx;
        *sy = pc_figure_frames(c) ? -wy : wy;
    } else {
        *sx = wx + v->x0;
        *sy = (pc_figure_frames(c) ? -wy : wy) + v->y0;
    }
}

void pc_screen_to_world(const pc_canvas *c, double sx, double sy, double *wx, double *wy) {
    const pc_rect *v = &c->view;
    if (c->has_window) {
        double w = v->x1 - v->x0, h = v->y1 - v->y0;
        *wx = c->wx1 + (w ? (sx - v->x0) * (c->wx2 - c->wx1) / w : 0);
        if (c->window_screen)
            *wy = c->wy1 + (h ? (sy - v->y0) * (c->wy2 - c->wy1) / h : 0);
        else
            *wy = c->wy2 - (h ? (sy - v->y0) * (c->wy2 - c->wy1) / h : 0);
    } else if (c->view_screen) {
        *wx = sx;
        *wy = pc_figure_frames(c) ? -sy : sy;
    } else {
        *wx = sx - v->x0;
        *wy = pc_figure_frames(c) ? v->y0 - sy : sy - v->y0;
    }
}

double pc_world_xscale(const pc_canvas *c) {
    if (!c->has_window) return 1.0;
    return fabs((c->view.x1 - c->view.x0) / (c->wx2 - c->wx1));
}

int pc_window(pc_canvas *c, double x1, double y1, double x2, double y2, int screen) {
    if (!(isfinite(x1) && isfinite(y1) && isfinite(x2) && isfinite(y2)))
        return pc_fail(c, "window corners must be finite numbers");
    if (x1 == x2 || y1 == y2)
        return pc_fail(c, "window (%g, %g)-(%g, %g) has zero width or height", x1, y1, x2, y2);
    if (!isfinite(x2 - x1) || !isfinite(y2 - y1))   /* its width would be infinite */
        return pc_fail(c, "window (%g, %g)-(%g, %g) is too large", x1, y1, x2, y2);
    /* QBasic orders the corners: the smaller x is left, the smaller y is bottom (top with SCREEN) */
    c->wx1 = fmin(x1, x2);
    c->wx2 = fmax(x1, x2);
    c->wy1 = fmin(y1, y2);
    c->wy2 = fmax(y1, y2);
    c->has_window = 1;
    c->window_screen = screen != 0;
    pc_reset_cursor(c);
    return PC_OK;
}

void pc_window_reset(pc_canvas *c) {
    c->has_window = 0;
    pc_reset_cursor(c);
}

/* Make r the view.  Its clip rectangle is recorded first: when there is no memory for it the
 * view stays as it was, so the raster and the display list never disagree. */
static int set_view(pc_canvas *c, pc_rect r, int screen) {
    pc_rect old = c->view;
    c->view = r;
    if (pc_push_clip(c) != PC_OK) {
        c->view = old;
        return PC_ENOMEM;
    }
    c->view_screen = screen;
    return PC_OK;
}

int pc_view(pc_canvas *c, int x1, int y1, int x2, int y2, int fill, int border, int screen) {
    pc_rect r = {x1 < x2 ? x1 : x2, y1 < y2 ? y1 : y2, x1 < x2 ? x2 : x1, y1 < y2 ? y2 : y1};
    if (r.x0 < 0 || r.y0 < 0 || r.x1 >= c->width || r.y1 >= c->height)
        return pc_fail(c, "view (%d, %d)-(%d, %d) is not inside the %dx%d screen", x1, y1, x2, y2,
                       c->width, c->height);
    if ((fill >= 0 && !pc_valid_color(c, fill)) || (border >= 0 && !pc_valid_color(c, border)))
        return pc_fail(c, "view colour out of range 0..%d", c->ncolors - 1);
    if (border >= 0) {
        /* the border is drawn just outside the viewport, where there is room */
        pc_rect full = {0, 0, c->width - 1, c->height - 1};
        if (set_view(c, full, c->view_screen) != PC_OK) return PC_ENOMEM;
        int ok = pc_box_screen(c, r.x0 - 1, r.y0 - 1, r.x1 + 1, r.y1 + 1, border, 0);
        if (ok != PC_OK) return ok;
    }
    if (set_view(c, r, screen != 0) != PC_OK) return PC_ENOMEM;
    if (fill >= 0) {
        int ok = pc_fill_view(c, fill);
        if (ok != PC_OK) return ok;
    }
    pc_reset_cursor(c);
    return PC_OK;
}

int pc_view_reset(pc_canvas *c) {
    if (set_view(c, (pc_rect){0, 0, c->width - 1, c->height - 1}, 0) != PC_OK)
        return PC_ENOMEM;
    pc_reset_cursor(c);
    return PC_OK;
}

/* ---- colours ------------------------------------------------------------------------------ */

int pc_color(pc_canvas *c, int fg, int bg) {
    if (!pc_valid_color(c, fg))
        return pc_fail(c, "foreground colour %d out of range 0..%d", fg, c->ncolors - 1);
    if (bg >= 0 && !pc_valid_color(c, bg))
        return pc_fail(c, "background colour %d out of range 0..%d", bg, c->ncolors - 1);
    c->fg = fg;
    if (bg >= 0) c->bg = bg;
    return PC_OK;
}

int pc_palette(pc_canvas *c, int attr, pc_rgb rgb) {
    if (attr < 0 || attr >= c->ncolors)
        return pc_fail(c, "palette attribute %d out of range 0..%d", attr, c->ncolors - 1);
    c->palette[attr] = rgb;
    c->version++;
    return PC_OK;
}

int pc_palette_reset(pc_canvas *c) {
    pc_palette_default(c->palette, c->ncolors);   /* the first 256: true colours stay */
    c->version++;
    return PC_OK;
}

/* ---- true colours ------------------------------------------------------------------------- */

/* The true colours are found by an open-addressing hash of their rgb, so a script that uses
 * thousands of colours pays the same per call as one that uses two. */
static size_t rgb_slot(pc_rgb rgb, size_t slots) {
    uint32_t key = (uint32_t)rgb.r << 16 | (uint32_t)rgb.g << 8 | rgb.b;
    return (size_t)((key * 2654435761u) & (slots - 1));
}

static int same_rgb(pc_rgb a, pc_rgb b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

static void rgb_insert(pc_canvas *c, int attr) {
    size_t i = rgb_slot(c->palette[attr], c->rgb_slots);
    while (c->rgb_index[i]) i = (i + 1) & (c->rgb_slots - 1);
    c->rgb_index[i] = (uint16_t)attr;
}

/* Keep the hash at most half full. */
static int rgb_reserve(pc_canvas *c) {
    if ((size_t)(c->ntrue + 1) * 2 <= c->rgb_slots) return 1;
    size_t slots = c->rgb_slots ? c->rgb_slots * 2 : 64;
    uint16_t *idx = calloc(slots, sizeof *idx);
    if (!idx) return 0;
    free(c->rgb_index);
    c->rgb_index = idx;
    c->rgb_slots = slots;
    for (int k = 0; k < c->ntrue; k++) rgb_insert(c, 256 + k);
    return 1;
}

int pc_rgb_color(pc_canvas *c, pc_rgb rgb) {
    if (c->rgb_slots) {
        for (size_t i = rgb_slot(rgb, c->rgb_slots); c->rgb_index[i]; i = (i + 1) & (c->rgb_slots - 1))
            if (same_rgb(c->palette[c->rgb_index[i]], rgb)) return c->rgb_index[i];
    }
    if (256 + c->ntrue > PC_MAX_ATTR) {
        pc_fail(c, "too many colours: at most %d distinct \"#rrggbb\" colours", PC_MAX_ATTR - 255);
        return -1;
    }
    pc_rgb *pal = realloc(c->palette, (size_t)(256 + c->ntrue + 1) * sizeof *pal);
    if (pal) c->palette = pal;   /* before rgb_reserve, which reads it */
    if (!pal || !rgb_reserve(c)) {
        pc_fail_code(c, PC_ENOMEM, "out of memory for a colour");
        return -1;
    }
    int attr = 256 + c->ntrue++;
    c->palette[attr] = rgb;
    rgb_insert(c, attr);
    return attr;
}

static int hex_digit(char ch) {
    if (ch >= '0' && ch <= '9') return ch - '0';
    if (ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
    if (ch >= 'A' && ch <= 'F') return ch - 'A' + 10;
    return -1;
}

/* Digit by digit, not sscanf("%2x"): that takes "5g" as 5, " 1" and "-1" as numbers. */
int pc_rgb_parse(const char *s, size_t len, pc_rgb *out) {
    if (!s || len != 7 || s[0] != '#') return PC_EARG;
    int v[6];
    for (int i = 0; i < 6; i++)
        if ((v[i] = hex_digit(s[i + 1])) < 0) return PC_EARG;
    *out = (pc_rgb){(uint8_t)(v[0] * 16 + v[1]), (uint8_t)(v[2] * 16 + v[3]),
                    (uint8_t)(v[4] * 16 + v[5])};
    return PC_OK;
}

/* ---- pens --------------------------------------------------------------------------------- */

static int same_pen(const pc_stroke *a, const pc_stroke *b) {
    if (a->width != b->width || a->ndash != b->ndash || a->style != b->style ||
        a->print_width != b->print_width || a->print_dash != b->print_dash)
        return 0;
    for (int i = 0; i < a->ndash; i++)
        if (a->dash[i] != b->dash[i]) return 0;
    return 1;
}

int pc_pen_index(pc_canvas *c, const pc_stroke *p) {
    for (size_t i = 0; i < c->npens; i++)
        if (same_pen(&c->pens[i], p)) return (int)i;
    if (c->npens > UINT16_MAX ||
        !pc_grow((void **)&c->pens, &c->cappens, c->npens + 1, sizeof *c->pens)) {
        pc_fail_code(c, PC_ENOMEM, "too many different pens");
        return -1;
    }
    c->pens[c->npens] = *p;
    return (int)c->npens++;
}

int pc_pen(pc_canvas *c, double width, const double *dash, int ndash) {
    if (!(width >= 1 && width <= PC_PEN_MAXWIDTH))
        return pc_fail(c, "pen: width must be 1..%d pixels, got %g", PC_PEN_MAXWIDTH, width);
    if (ndash < 0 || ndash > PC_PEN_MAXDASH || ndash % 2)
        return pc_fail(c, "pen: a dash pattern has an even number of lengths, at most %d, got %d",
                       PC_PEN_MAXDASH, ndash);
    pc_stroke p = {.width = width, .ndash = ndash};
    for (int i = 0; i < ndash; i++) {
        if (!(dash[i] > 0 && dash[i] <= 1e6))
            return pc_fail(c, "pen: dash length %d must be a positive number of pixels, got %g",
                           i + 1, dash[i]);
        p.dash[i] = dash[i];
        p.period += dash[i];
    }
    int k = pc_pen_index(c, &p);
    if (k < 0) return PC_ENOMEM;
    c->pen = k;
    return PC_OK;
}

void pc_pen_reset(pc_canvas *c) { c->pen = 0; }

int pc_pen_physical(pc_canvas *c, double width_pt, const double *dash_pt, int ndash) {
    if (!(width_pt >= 0.1 && width_pt <= 100))
        return pc_fail(c, "pen: width must be 0.1..100 pt (0.035..35 mm), got %g pt", width_pt);
    if (ndash < 0 || ndash > PC_PEN_MAXDASH || ndash % 2)
        return pc_fail(c, "pen: a dash pattern has an even number of lengths, at most %d, got %d",
                       PC_PEN_MAXDASH, ndash);
    /* the VGA look at 96 px to the inch: 0.75 pt a pixel */
    double px = round(width_pt / 0.75);
    pc_stroke p = {.width = px < 1 ? 1 : px, .ndash = ndash, .print_width = width_pt,
                   .print_dash = ndash > 0};
    for (int i = 0; i < ndash; i++) {
        if (!(dash_pt[i] > 0 && dash_pt[i] <= 1e4))
            return pc_fail(c, "pen: dash length %d must be a positive length, got %g pt", i + 1,
                           dash_pt[i]);
        p.dash[i] = dash_pt[i] / 0.75;   /* the VGA look's pixels; print.c uses pt */
        p.period += p.dash[i];
    }
    int k = pc_pen_index(c, &p);
    if (k < 0) return PC_ENOMEM;
    c->pen = k;
    return PC_OK;
}

/* ---- the canvas seen from a host ------------------------------------------------------------ */

void pc_canvas_size(const pc_canvas *c, int *width, int *height) {
    if (width) *width = c->width;
    if (height) *height = c->height;
}

int pc_canvas_ncolors(const pc_canvas *c) { return c->ncolors; }

uint64_t pc_canvas_version(const pc_canvas *c) { return c->version; }

int pc_canvas_dirty(const pc_canvas *c) { return c->dirty; }

void pc_canvas_mark_saved(pc_canvas *c) { c->dirty = 0; }

int pc_canvas_paper(const pc_canvas *c) { return c->paper; }

int pc_canvas_rgb(const pc_canvas *c, int attr, pc_rgb *out) {
    if (!pc_valid_color(c, attr)) return PC_EARG;
    *out = c->palette[attr];
    return PC_OK;
}

const pc_rgb *pc_canvas_palette(const pc_canvas *c) { return c->palette; }

const char *pc_canvas_error(const pc_canvas *c) { return c->error; }

int pc_canvas_clear(pc_canvas *c) {
    pc_rect v = c->view;
    int vs = c->view_screen;
    int full = v.x0 == 0 && v.y0 == 0 && v.x1 == c->width - 1 && v.y1 == c->height - 1;
    double lx = c->last_x, ly = c->last_y;
    /* CLS of the full screen starts the display list afresh; then the view comes back */
    int rc = full ? PC_OK : pc_view_reset(c);
    if (rc == PC_OK) rc = pc_cls(c);
    if (rc == PC_OK && !full) rc = pc_view(c, v.x0, v.y0, v.x1, v.y1, -1, -1, vs);
    c->last_x = lx;
    c->last_y = ly;
    c->dirty = 0;
    return rc;
}
