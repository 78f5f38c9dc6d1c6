/* The print look on cairo (print.h): PDF, PostScript, EPS and PNG surfaces behind the one
 * interface of print_backend.h, text through Pango.  Every surface renders into memory
 * (cairo's *_for_stream surfaces) and the bytes go to the stream the one file-writing routine
 * (write_file.c) gave, so a failed render leaves no file. */
#include <cairo-pdf.h>
#include <cairo-ps.h>
#include <cairo.h>
#include <math.h>
#include <pango/pangocairo.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>
#include "print_backend.h"

int pc_encode_print_svg(const pc_canvas *c, const pc_page *pg, FILE *out, char *err, size_t errlen);

typedef struct { cairo_t *cr; } cbe;

static void set_rgb(cairo_t *cr, pc_rgb c) {
    cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0);
}

static void c_clip(void *s, double x0, double y0, double x1, double y1) {
    cairo_t *cr = ((cbe *)s)->cr;
    cairo_new_path(cr);
    cairo_reset_clip(cr);
    cairo_rectangle(cr, x0, y0, x1 - x0, y1 - y0);
    cairo_clip(cr);
}
static void c_move(void *s, double x, double y) { cairo_move_to(((cbe *)s)->cr, x, y); }
static void c_line(void *s, double x, double y) { cairo_line_to(((cbe *)s)->cr, x, y); }
static void c_curve(void *s, double x1, double y1, double x2, double y2, double x3, double y3) {
    cairo_curve_to(((cbe *)s)->cr, x1, y1, x2, y2, x3, y3);
}
static void c_close(void *s) { cairo_close_path(((cbe *)s)->cr); }
static void c_rect(void *s, double x, double y, double w, double h) {
    cairo_rectangle(((cbe *)s)->cr, x, y, w, h);
}

static void c_stroke(void *s, pc_rgb color, const pc_pr_pen *p) {
    cairo_t *cr = ((cbe *)s)->cr;
    set_rgb(cr, color);
    cairo_set_line_width(cr, p->width);
    cairo_set_line_cap(cr, p->round ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
    cairo_set_line_join(cr, p->round ? CAIRO_LINE_JOIN_ROUND : CAIRO_LINE_JOIN_MITER);
    cairo_set_dash(cr, p->dash, p->ndash, 0);
    cairo_stroke(cr);
}

static void c_fill(void *s, pc_rgb color, int evenodd) {
    cairo_t *cr = ((cbe *)s)->cr;
    set_rgb(cr, color);
    cairo_set_fill_rule(cr, evenodd ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
    cairo_fill(cr);
}

/* Each run a Pango layout on its baseline; the halo first, every run's outline stroked in the
 * paper colour, then the ink, so a halo never covers a neighbouring run. */
static void c_text(void *s, const pc_pr_label *lab) {
    cairo_t *cr = ((cbe *)s)->cr;
    const pc_mlayout *L = lab->layout;
    PangoLayout *pl = pango_layout_new(pc_pr_context());
    cairo_new_path(cr);
    for (int pass = lab->halo > 0 ? 0 : 1; pass < 2; pass++) {
        if (pass == 1) set_rgb(cr, lab->color);
        for (size_t i = 0; i < L->nruns; i++) {
            const pc_mrun *r = &L->runs[i];
            PangoFontDescription *d = pc_pr_font(lab->family, r->italic, r->size);
            pango_layout_set_font_description(pl, d);
            pango_font_description_free(d);
            pango_layout_set_text(pl, L->text + r->first, (int)r->len);
            double base = pango_layout_get_baseline(pl) / (double)PANGO_SCALE;
            cairo_move_to(cr, lab->x + r->x, lab->y - r->rise - base);
            if (pass == 0) pango_cairo_layout_path(cr, pl);
            else pango_cairo_show_layout(cr, pl);
        }
        for (size_t i = 0; i < L->ndecos; i++) {
            const pc_mdeco *dc = &L->decos[i];
            double y = lab->y - dc->rise, x0 = lab->x + dc->x0, x1 = lab->x + dc->x1;
            double w = 0.05 * (L->runs[0].size ? L->runs[0].size : 10);
            if (dc->kind == PC_DECO_TILDE) {   /* the wave of print_svg.c */
                cairo_move_to(cr, x0, y + w);
                cairo_curve_to(cr, x0 + (x1 - x0) / 3, y - 3 * w, x0 + 2 * (x1 - x0) / 3, y + 3 * w, x1, y - w);
            } else {
                cairo_move_to(cr, x0, y);
                cairo_line_to(cr, x1, y);
            }
            if (dc->kind == PC_DECO_VEC) {   /* the arrow's head at the right end */
                cairo_move_to(cr, x1 - 4 * w, y - 2 * w);
                cairo_line_to(cr, x1, y);
                cairo_line_to(cr, x1 - 4 * w, y + 2 * w);
            }
            if (pass == 0) {
                cairo_set_line_width(cr, w);
                continue;
            }
            set_rgb(cr, lab->color);
            cairo_set_line_width(cr, w);
            cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
            cairo_set_dash(cr, NULL, 0, 0);
            cairo_stroke(cr);
        }
        if (pass == 0) {
            set_rgb(cr, lab->halo_color);
            cairo_set_line_width(cr, lab->halo);
            cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
            cairo_set_dash(cr, NULL, 0, 0);
            cairo_stroke(cr);
        }
    }
    g_object_unref(pl);
}

/* Pixels as an A8 mask over their bounding box, scaled with nearest-neighbour filtering: the
 * squares exactly, in one image however many there are. */
static void c_pixels(void *s, const uint32_t *idx, size_t n, int width, const pc_page *pg,
                     pc_rgb color) {
    cairo_t *cr = ((cbe *)s)->cr;
    int x0 = width, x1 = -1, y0 = (int)(idx[0] / (uint32_t)width), y1 = (int)(idx[n - 1] / (uint32_t)width);
    for (size_t i = 0; i < n; i++) {
        int x = (int)(idx[i] % (uint32_t)width);
        if (x < x0) x0 = x;
        if (x > x1) x1 = x;
    }
    int w = x1 - x0 + 1, h = y1 - y0 + 1;
    cairo_surface_t *m = cairo_image_surface_create(CAIRO_FORMAT_A8, w, h);
    if (cairo_surface_status(m) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(m);
        return;
    }
    cairo_surface_flush(m);
    unsigned char *data = cairo_image_surface_get_data(m);
    int stride = cairo_image_surface_get_stride(m);
    for (size_t i = 0; i < n; i++) {
        int x = (int)(idx[i] % (uint32_t)width) - x0, y = (int)(idx[i] / (uint32_t)width) - y0;
        data[y * stride + x] = 255;
    }
    cairo_surface_mark_dirty(m);
    cairo_save(cr);
    cairo_new_path(cr);
    cairo_translate(cr, pg->ox + x0 * pg->s, pg->oy + y0 * pg->s);
    cairo_scale(cr, pg->s, pg->s);
    set_rgb(cr, color);
    cairo_pattern_t *pat = cairo_pattern_create_for_surface(m);
    cairo_pattern_set_filter(pat, CAIRO_FILTER_NEAREST);
    cairo_mask(cr, pat);
    cairo_pattern_destroy(pat);
    cairo_restore(cr);
    cairo_surface_destroy(m);
}

/* ---- surfaces into memory --------------------------------------------------------------------- */

typedef struct { char *buf; size_t n, cap; int nomem; } membuf;

static cairo_status_t to_mem(void *closure, const unsigned char *data, unsigned int len) {
    membuf *m = closure;
    if (m->n + len > m->cap) {
        size_t cap = m->cap ? m->cap * 2 : 65536;
        while (cap < m->n + len) cap *= 2;
        char *b = realloc(m->buf, cap);
        if (!b) { m->nomem = 1; return CAIRO_STATUS_NO_MEMORY; }
        m->buf = b;
        m->cap = cap;
    }
    memcpy(m->buf + m->n, data, len);
    m->n += len;
    return CAIRO_STATUS_SUCCESS;
}

/* The image as an RGB PNG through libpng, at a faster zlib level than cairo's own writer
 * (which a figure's whole-process time was mostly spent in): the SUB filter suits rows of
 * white paper with antialiased ink. */
static void png_fail(png_structp png, png_const_charp msg) {
    (void)msg;
    png_longjmp(png, 1);
}
static void png_warn(png_structp png, png_const_charp msg) { (void)png; (void)msg; }

static int write_png(cairo_surface_t *sf, FILE *out) {
    int w = cairo_image_surface_get_width(sf), h = cairo_image_surface_get_height(sf);
    int stride = cairo_image_surface_get_stride(sf);
    cairo_surface_flush(sf);
    const unsigned char *px = cairo_image_surface_get_data(sf);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, png_fail, png_warn);
    if (!png) return PC_ENOMEM;
    png_infop info = png_create_info_struct(png);
    unsigned char *volatile row = NULL;   /* volatile: set between setjmp and a longjmp */
    if (!info || setjmp(png_jmpbuf(png))) {
        free(row);
        png_destroy_write_struct(&png, &info);
        return PC_EIO;
    }
    row = malloc((size_t)w * 3);
    if (!row) png_error(png, "out of memory");
    png_init_io(png, out);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_text text = {0};
    text.compression = PNG_TEXT_COMPRESSION_NONE;
    text.key = (png_charp) "Software";
    text.text = (png_charp) "pointcalc";
    png_set_text(png, info, &text, 1);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_set_compression_level(png, 3);
    png_write_info(png, info);
    for (int y = 0; y < h; y++) {
        const uint32_t *src = (const uint32_t *)(px + (size_t)y * stride);   /* xRGB words */
        for (int x = 0; x < w; x++) {
            row[3 * x] = (unsigned char)(src[x] >> 16);
            row[3 * x + 1] = (unsigned char)(src[x] >> 8);
            row[3 * x + 2] = (unsigned char)src[x];
        }
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(row);
    return fflush(out) != 0 || ferror(out) ? PC_EIO : PC_OK;
}

static int render(const pc_canvas *c, const pc_page *pg, cairo_t *cr, char *err, size_t errlen) {
    cbe self = {cr};
    pc_pr_backend b = {&self, c_clip, c_move, c_line, c_curve, c_close, c_rect, c_stroke, c_fill,
                       c_text, c_pixels, 0};
    set_rgb(cr, pc_print_rgb(c, 0));   /* the paper */
    cairo_paint(cr);
    return pc_print_walk(c, pg, &b, err, errlen);
}

int pc_encode_print(const pc_canvas *c, pc_format fmt, FILE *out, char *err, size_t errlen) {
    pc_page pg;
    pc_print_page(c, &pg);
    if (fmt == PC_FMT_SVG) return pc_encode_print_svg(c, &pg, out, err, errlen);
    membuf m = {0};
    cairo_surface_t *sf;
    if (fmt == PC_FMT_PDF) {
        sf = cairo_pdf_surface_create_for_stream(to_mem, &m, pg.width, pg.height);
        cairo_pdf_surface_set_metadata(sf, CAIRO_PDF_METADATA_CREATOR, "pointcalc");
    } else if (fmt == PC_FMT_EPS || fmt == PC_FMT_PS) {
        sf = cairo_ps_surface_create_for_stream(to_mem, &m, pg.width, pg.height);
        cairo_ps_surface_set_eps(sf, fmt == PC_FMT_EPS);
    } else {
        int w = (int)lrint(pg.width * pg.dpi / 72), h = (int)lrint(pg.height * pg.dpi / 72);
        sf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w < 1 ? 1 : w, h < 1 ? 1 : h);
    }
    cairo_t *cr = cairo_create(sf);
    if (fmt == PC_FMT_PNG) cairo_scale(cr, pg.dpi / 72, pg.dpi / 72);
    int st = render(c, &pg, cr, err, errlen);
    if (st == PC_OK && cairo_status(cr) != CAIRO_STATUS_SUCCESS) st = PC_ENOMEM;
    cairo_destroy(cr);
    if (st == PC_OK && fmt == PC_FMT_PNG) st = write_png(sf, out);
    cairo_surface_finish(sf);
    if (st == PC_OK && (m.nomem || cairo_surface_status(sf) != CAIRO_STATUS_SUCCESS)) st = PC_ENOMEM;
    cairo_surface_destroy(sf);
    if (st == PC_OK && m.n && fwrite(m.buf, 1, m.n, out) != m.n) st = PC_EIO;
    free(m.buf);
    return st;
}
