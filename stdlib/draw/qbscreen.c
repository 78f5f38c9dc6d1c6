/* QBasic's screen modes, text in character cells, recorded pixel regions and page copies
 * (qbscreen.h).  GET/PUT are in qbblock.c, DRAW in qbdraw.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "canvas_internal.h"
#include "font.h"
#include "qbscreen.h"

/* The VGA card's modes as QBasic 1.1 has them (its help, "SCREEN statement": sizes, colours,
 * text columns/rows and character boxes, pages with 256K of video memory). */
static const pc_mode_info modes[] = {
    /* mode  w    h    colours pages cols rows cell aspect */
    {1, 320, 200, 4, 1, 40, 25, 8, 0},
    {2, 640, 200, 2, 1, 80, 25, 8, 0},
    {7, 320, 200, 16, 8, 40, 25, 8, 0},
    {8, 640, 200, 16, 4, 80, 25, 8, 0},
    {9, 640, 350, 16, 2, 80, 25, 14, 0},
    {12, 640, 480, 16, 1, 80, 30, 16, 0},
    {13, 320, 200, 256, 1, 40, 25, 8, 0},
};

int pc_mode_info_of(int mode, pc_mode_info *out) {
    for (size_t i = 0; i < sizeof modes / sizeof *modes; i++)
        if (modes[i].mode == mode) {
            *out = modes[i];
            /* square pixels need width:height = 4:3; a pixel is (4/3) / (w/h) as high as wide */
            out->aspect = 4.0 / 3.0 * out->height / out->width;
            return PC_OK;
        }
    return PC_EARG;
}

int pc_mode_of_canvas(const pc_canvas *c, pc_mode_info *out) {
    for (size_t i = 0; i < sizeof modes / sizeof *modes; i++) {
        const pc_mode_info *m = &modes[i];
        if (m->width == c->width && m->height == c->height && m->ncolors == c->ncolors) {
            pc_mode_info_of(m->mode, out);
            return m->mode;
        }
    }
    return 0;
}

int pc_cell_height(const pc_canvas *c) {
    pc_mode_info m;
    return pc_mode_of_canvas(c, &m) ? m.cell_h : 16;
}

int pc_canvas_set_mode(pc_canvas *c, int mode) {
    pc_mode_info m;
    if (pc_mode_info_of(mode, &m) != PC_OK)
        return pc_fail(c, "screen: mode %d is not one of 1, 2, 7, 8, 9, 12, 13", mode);
    int st = pc_canvas_reset(c, m.width, m.height, m.ncolors);
    if (st == PC_OK) c->screen_pixels = 1;   /* a QBasic screen: pixel coordinates */
    return st;
}

/* ---- PAINT tiles ------------------------------------------------------------------------ */

int pc_paint_tile_bytes(pc_canvas *c, double x, double y, const unsigned char *bytes, size_t n, int border) {
    pc_tile t;
    int st = pc_tile_from_bytes(c, bytes, n, &t);
    return st == PC_OK ? pc_paint_tile(c, x, y, &t, border) : st;
}

int pc_tile_from_bytes(pc_canvas *c, const unsigned char *bytes, size_t n, pc_tile *out) {
    if (n < 1 || n > 64) return pc_fail(c, "paint: a tile has 1..64 bytes, got %zu", n);
    memset(out, 0, sizeof *out);
    if (c->ncolors == 2 || c->ncolors == 4) {
        /* packed pixels: a byte is one row, high bits leftmost */
        int bits = c->ncolors == 2 ? 1 : 2;
        out->w = 8 / bits;
        out->h = (int)n;
        for (size_t r = 0; r < n; r++)
            for (int x = 0; x < out->w; x++)
                out->attr[r * out->w + x] = (uint16_t)((bytes[r] >> (8 - bits * (x + 1))) & ((1 << bits) - 1));
    } else if (c->ncolors == 16) {
        /* planar: a row is 4 bytes, one bit plane each (blue 1, green 2, red 4, intensity 8) */
        out->w = 8;
        out->h = (int)((n + 3) / 4);
        for (size_t i = 0; i < n; i++)
            for (int x = 0; x < 8; x++)
                if (bytes[i] & (0x80 >> x)) out->attr[(i / 4) * 8 + x] |= (uint16_t)(1 << (i % 4));
    } else {
        /* a byte a pixel, 8 pixels a row (a short last row: colour 0) */
        out->w = 8;
        out->h = (int)((n + 7) / 8);
        for (size_t i = 0; i < n; i++) out->attr[i] = bytes[i];
    }
    return PC_OK;
}

/* ---- recorded pixels --------------------------------------------------------------------- */

int pc_record_pixels(pc_canvas *c, int x0, int y0, int x1, int y1) {
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 >= c->width) x1 = c->width - 1;
    if (y1 >= c->height) y1 = c->height - 1;
    if (x0 > x1 || y0 > y1) return PC_OK;
    /* the recorded pixels are the screen's: no clip but the screen */
    pc_rect saved = c->view;
    c->view = (pc_rect){0, 0, c->width - 1, c->height - 1};
    int ok = pc_push_clip(c);
    size_t nattr = 256 + (size_t)c->ntrue;
    uint8_t *seen = ok == PC_OK ? calloc(nattr, 1) : NULL;
    if (ok == PC_OK && !seen) ok = pc_fail_code(c, PC_ENOMEM, "out of memory");
    for (int y = y0; ok == PC_OK && y <= y1; y++)
        for (int x = x0; x <= x1; x++) seen[c->pixels[(size_t)y * c->width + x]] = 1;
    for (size_t col = 0; ok == PC_OK && col < nattr; col++) {
        if (!seen[col]) continue;
        pc_op *op = pc_push_op(c, PC_OP_FILL, (int)col);
        if (!op) { ok = PC_ENOMEM; break; }
        op->first = (uint32_t)c->nspans;
        for (int y = y0; ok == PC_OK && y <= y1; y++) {
            const uint16_t *row = c->pixels + (size_t)y * c->width;
            for (int x = x0; x <= x1; x++) {
                if (row[x] != col) continue;
                int s = x;
                while (x + 1 <= x1 && row[x + 1] == col) x++;
                if ((ok = pc_push_span(c, y, s, x)) != PC_OK) break;
            }
        }
        op = &c->ops[c->nops - 1];
        op->count = (uint32_t)(c->nspans - op->first);
    }
    free(seen);
    c->view = saved;
    if (ok == PC_OK) ok = pc_push_clip(c);
    return ok;
}

/* ---- text cells -------------------------------------------------------------------------- */

int pc_text_cells(pc_canvas *c, int row, int col, const char *bytes, size_t n, int cell_h,
                  int fg, int bg) {
    const pc_font *f = pc_font_of_height(cell_h);
    if (!f) return pc_fail(c, "print: character cells are 8, 14 or 16 pixels high, got %d", cell_h);
    int ok = pc_check_color(c, &fg, c->fg);
    if (ok == PC_OK) ok = pc_check_color(c, &bg, c->bg);
    if (ok != PC_OK) return ok;
    if (row < 1 || col < 1) return pc_fail(c, "print: row and column start at 1, got %d, %d", row, col);
    long left = (long)(col - 1) * 8, top = (long)(row - 1) * cell_h;
    if (n == 0 || left >= c->width || top >= c->height) return PC_OK;
    if ((long)n > (c->width - left + 7) / 8) n = (size_t)((c->width - left + 7) / 8);

    pc_rect saved = c->view;   /* text is not clipped by VIEW */
    c->view = (pc_rect){0, 0, c->width - 1, c->height - 1};
    ok = pc_push_clip(c);
    long right = left + (long)n * 8 - 1, bottom = top + cell_h - 1;
    if (ok == PC_OK)
        ok = pc_box_screen(c, (int)left, (int)top, (int)(right < c->width ? right : c->width - 1),
                           (int)(bottom < c->height ? bottom : c->height - 1), bg, 1);
    /* the glyphs, and the same characters as UTF-8 for the TEXT op */
    char *utf8 = ok == PC_OK ? malloc(3 * n + 1) : NULL;
    if (ok == PC_OK && !utf8) ok = pc_fail_code(c, PC_ENOMEM, "out of memory for text");
    size_t u = 0;
    for (size_t k = 0; ok == PC_OK && k < n; k++) {
        uint32_t cp = pc_cp437[(unsigned char)bytes[k]];
        if (cp == 0) cp = ' ';   /* CHR$(0): a blank cell, as on QBasic's screen */
        else if (cp < 0x20) cp = 0xfffd;   /* a control PRINT acts on in QBasic: the replacement */
        const uint8_t *rows = f->bits + (size_t)pc_font_glyph_in(f, cp) * f->h;
        for (int r = 0; r < f->h; r++)
            for (int b = 0; b < 8; b++)
                if (rows[r] & (0x80 >> b)) pc_plot(c, (int)(left + 8 * (long)k + b), (int)(top + r), fg);
        if (cp < 0x80) utf8[u++] = (char)cp;
        else if (cp < 0x800) {
            utf8[u++] = (char)(0xc0 | cp >> 6);
            utf8[u++] = (char)(0x80 | (cp & 0x3f));
        } else {
            utf8[u++] = (char)(0xe0 | cp >> 12);
            utf8[u++] = (char)(0x80 | ((cp >> 6) & 0x3f));
            utf8[u++] = (char)(0x80 | (cp & 0x3f));
        }
    }
    if (ok == PC_OK) {
        size_t first = c->ntext;
        if (c->ntext + u > UINT32_MAX || !pc_grow((void **)&c->text, &c->captext, c->ntext + u, 1))
            ok = pc_fail_code(c, PC_ENOMEM, "out of memory for text");
        else {
            memcpy(c->text + c->ntext, utf8, u);
            c->ntext += u;
            pc_op *op = pc_push_op(c, PC_OP_TEXT, fg);
            if (!op) ok = PC_ENOMEM;
            else {
                op->flags = PC_ANCHOR_SE;
                op->x1 = op->x2 = (double)left;
                op->y1 = op->y2 = (double)top;
                op->rx = 1;
                op->ry = cell_h;
                op->first = (uint32_t)first;
                op->count = (uint32_t)u;
            }
        }
    }
    free(utf8);
    c->view = saved;
    if (ok == PC_OK) ok = pc_push_clip(c);
    return ok;
}

int pc_text_scroll(pc_canvas *c, int top, int bottom, int cell_h, int bg) {
    int ok = pc_check_color(c, &bg, c->bg);
    if (ok != PC_OK) return ok;
    if (!pc_font_of_height(cell_h)) return pc_fail(c, "print: character cells are 8, 14 or 16 pixels high, got %d", cell_h);
    if (top < 1 || bottom < top) return pc_fail(c, "print: text rows %d..%d", top, bottom);
    int y0 = (top - 1) * cell_h, y1 = bottom * cell_h - 1;
    if (y1 >= c->height) y1 = c->height - 1;
    if (y0 > y1) return PC_OK;
    size_t w = (size_t)c->width;
    for (int y = y0; y <= y1; y++) {
        uint16_t *dst = c->pixels + (size_t)y * w;
        if (y + cell_h <= y1) memcpy(dst, dst + (size_t)cell_h * w, w * sizeof *dst);
        else pc_fill_px(dst, bg, w);
    }
    c->version++;
    return pc_record_pixels(c, 0, y0, c->width - 1, y1);
}

/* ---- pages ------------------------------------------------------------------------------- */

static int copy_array(void **dst, size_t *cap, const void *src, size_t n, size_t elem) {
    if (!pc_grow(dst, cap, n ? n : 1, elem)) return 0;
    if (n) memcpy(*dst, src, n * elem);
    return 1;
}

int pc_canvas_copy_picture(pc_canvas *dst, const pc_canvas *src) {
    if (dst == src) return PC_OK;
    if (dst->width != src->width || dst->height != src->height || dst->ncolors != src->ncolors)
        return pc_fail(dst, "pcopy: the pages differ in size or colours");
    if (src->ntrue > dst->ntrue)
        return pc_fail(dst, "pcopy: the source page has true colours the destination lacks");
    if (!copy_array((void **)&dst->ops, &dst->capops, src->ops, src->nops, sizeof *src->ops) ||
        !copy_array((void **)&dst->spans, &dst->capspans, src->spans, src->nspans, sizeof *src->spans) ||
        !copy_array((void **)&dst->dots, &dst->capdots, src->dots, src->ndots, sizeof *src->dots) ||
        !copy_array((void **)&dst->clips, &dst->capclips, src->clips, src->nclips, sizeof *src->clips) ||
        !copy_array((void **)&dst->pts, &dst->cappts, src->pts, src->npts, sizeof *src->pts) ||
        !copy_array((void **)&dst->text, &dst->captext, src->text, src->ntext, 1) ||
        !copy_array((void **)&dst->lpx, &dst->caplpx, src->lpx, src->nlpx, sizeof *src->lpx) ||
        !copy_array((void **)&dst->pens, &dst->cappens, src->pens, src->npens, sizeof *src->pens))
        return pc_fail_code(dst, PC_ENOMEM, "pcopy: out of memory");
    /* path tags live beside pts with the same capacity */
    uint8_t *tags = realloc(dst->tags, dst->cappts ? dst->cappts : 1);
    if (!tags) return pc_fail_code(dst, PC_ENOMEM, "pcopy: out of memory");
    dst->tags = tags;
    if (src->npts) memcpy(dst->tags, src->tags, src->npts);
    dst->nops = src->nops;
    dst->nspans = src->nspans;
    dst->ndots = src->ndots;
    dst->nclips = src->nclips;
    dst->npts = src->npts;
    dst->ntext = src->ntext;
    dst->nlpx = src->nlpx;
    dst->fold_mark = src->fold_mark;
    dst->npens = src->npens;
    if ((size_t)dst->pen >= dst->npens) dst->pen = 0;
    memcpy(dst->pixels, src->pixels, (size_t)src->width * src->height * sizeof *src->pixels);
    dst->paper = src->paper;
    dst->dirty = 1;
    dst->version++;
    /* dst's own VIEW stays in force for what it draws next */
    return pc_push_clip(dst);
}
