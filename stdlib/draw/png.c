/* PNG through libpng: a palette image (PLTE holds the theme's colours for the canvas's
 * attributes), 1 bit per pixel for 2 colours, 4 for 16, 8 for 256; with true colours, a
 * palette of the colours used while there are at most 256, else RGB (see make_plan).  Indexed pixels are what
 * the canvas holds, so no conversion is needed and zlib has a sixth (16 colours) or a third
 * (256) of the bytes that RGB would give it.  Filters are off (the PNG recommendation for
 * palette images) and zlib runs at its default level 6.  Measured on 640x480 drawings
 * (an oval of 1001 dots; circles, a painted disc, 50 lines and a million dots; a million
 * random dots) and a 1920x1080 256-colour pattern: level 1 takes 1-5 ms and gives files up
 * to 3.7 times larger, level 6 takes 2.5-10 ms, level 9 up to 108 ms for 6% less. */
#include <png.h>
#include <stdlib.h>
#include <string.h>
#include "writers.h"

#define PC_PNG_LEVEL 6

/* How the pixels become PNG samples.  A picture of palette attributes only is written as it
 * always was: the canvas's palette as PLTE, the attributes as indices.  One with true colours
 * gets a PLTE of the distinct colours it uses when there are at most 256 of them (index[attr]
 * gives each attribute's entry), else it is written as RGB. */
typedef struct {
    int depth, rgb, ncol;
    png_color plte[256];
    uint8_t *index;      /* per attribute, when true colours are in an indexed picture */
} png_plan;

static int has_true_colors(const pc_canvas *c) {
    if (!c->ntrue) return 0;
    size_t n = (size_t)c->width * c->height;
    for (size_t i = 0; i < n; i++)
        if (c->pixels[i] >= 256) return 1;
    return 0;
}

static int depth_for(int ncol) { return ncol <= 2 ? 1 : ncol <= 4 ? 2 : ncol <= 16 ? 4 : 8; }

/* The distinct colours of the attributes in use; rgb when there are more than 256. */
static int plan_true_colors(const pc_canvas *c, const pc_rgb pal[256], png_plan *p) {
    size_t nattr = 256 + (size_t)c->ntrue, n = (size_t)c->width * c->height;
    uint8_t *used = calloc(nattr, 1);
    p->index = malloc(nattr);
    if (!used || !p->index) {
        free(used);
        return PC_ENOMEM;
    }
    for (size_t i = 0; i < n; i++) used[c->pixels[i]] = 1;
    p->ncol = 0;
    for (size_t a = 0; a < nattr && !p->rgb; a++) {
        if (!used[a]) continue;
        pc_rgb v = pc_attr_rgb(c, pal, (int)a);
        int k = 0;
        while (k < p->ncol && !(p->plte[k].red == v.r && p->plte[k].green == v.g &&
                                p->plte[k].blue == v.b))
            k++;
        if (k == p->ncol) {
            if (p->ncol == 256) { p->rgb = 1; break; }
            p->plte[p->ncol++] = (png_color){v.r, v.g, v.b};
        }
        p->index[a] = (uint8_t)k;
    }
    free(used);
    p->depth = p->rgb ? 8 : depth_for(p->ncol);
    return PC_OK;
}

static int make_plan(const pc_canvas *c, const pc_rgb pal[256], png_plan *p) {
    memset(p, 0, sizeof *p);
    if (has_true_colors(c)) return plan_true_colors(c, pal, p);
    p->ncol = c->ncolors > 256 ? 256 : c->ncolors;
    p->depth = p->ncol <= 2 ? 1 : p->ncol <= 16 ? 4 : 8;
    for (int i = 0; i < p->ncol; i++) p->plte[i] = (png_color){pal[i].r, pal[i].g, pal[i].b};
    return PC_OK;
}

/* One row of samples: packed indices, or rgb triples. */
static void make_row(const pc_canvas *c, const pc_rgb pal[256], const png_plan *p, int y,
                     uint8_t *dst) {
    const uint16_t *src = c->pixels + (size_t)y * c->width;
    int width = c->width;
    if (p->rgb) {
        for (int x = 0; x < width; x++) {
            pc_rgb v = pc_attr_rgb(c, pal, src[x]);
            dst[3 * x] = v.r;
            dst[3 * x + 1] = v.g;
            dst[3 * x + 2] = v.b;
        }
        return;
    }
    if (p->depth == 8) {
        for (int x = 0; x < width; x++) dst[x] = p->index ? p->index[src[x]] : (uint8_t)src[x];
        return;
    }
    int per = 8 / p->depth, mask = (1 << p->depth) - 1;
    memset(dst, 0, (size_t)(width + per - 1) / per);
    for (int x = 0; x < width; x++) {
        int v = p->index ? p->index[src[x]] : src[x];
        dst[x / per] |= (uint8_t)((v & mask) << (8 - p->depth * (x % per + 1)));
    }
}

/* libpng's default handlers print to stderr; the caller reports the failure itself. */
static void png_fail(png_structp png, png_const_charp msg) {
    (void)msg;
    png_longjmp(png, 1);
}
static void png_warn(png_structp png, png_const_charp msg) { (void)png; (void)msg; }

int pc_encode_png(const pc_canvas *c, pc_theme theme, FILE *out) {
    pc_rgb pal[256];
    pc_theme_palette(c, theme, pal);
    png_plan plan;
    if (make_plan(c, pal, &plan) != PC_OK) return PC_ENOMEM;

    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, png_fail, png_warn);
    if (!png) {
        free(plan.index);
        return PC_ENOMEM;
    }
    png_infop info = png_create_info_struct(png);
    /* volatile: modified between setjmp and a possible longjmp */
    uint8_t *volatile row = NULL;
    if (!info || setjmp(png_jmpbuf(png))) {
        free(row);
        free(plan.index);
        png_destroy_write_struct(&png, &info);
        return PC_EIO;
    }
    row = malloc((size_t)c->width * 3);
    if (!row) png_error(png, "out of memory");
    png_init_io(png, out);
    png_set_IHDR(png, info, (png_uint_32)c->width, (png_uint_32)c->height, plan.depth,
                 plan.rgb ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (!plan.rgb) png_set_PLTE(png, info, plan.plte, plan.ncol);
    png_text text = {0};
    text.compression = PNG_TEXT_COMPRESSION_NONE;
    text.key = (png_charp) "Software";
    text.text = (png_charp) "pointcalc";
    png_set_text(png, info, &text, 1);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_compression_level(png, PC_PNG_LEVEL);
    png_write_info(png, info);
    for (int y = 0; y < c->height; y++) {
        make_row(c, pal, &plan, y, row);
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(row);
    free(plan.index);
    /* flushed here so that a full disk shows as an error of this call */
    return fflush(out) != 0 || ferror(out) ? PC_EIO : PC_OK;
}
