/* The print look: lengths and sizes, the named pens, the figure's checks and page, and the
 * renderer's outputs (PNG size and antialiasing, PDF/EPS headers, the SVG's <text>), fonts. */
#define _GNU_SOURCE   /* open_memstream */
#include <cairo.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"
#include "print.h"
#include "print_backend.h"

#define NEAR(a, b) assert_true(fabs((a) - (b)) < 1e-9)

static void test_lengths(void **state) {
    (void)state;
    double pt, w, h;
    char err[200];
    assert_int_equal(pc_parse_length("12cm", "w", &pt, err, sizeof err), PC_OK);
    NEAR(pt, 12 * 72 / 2.54);
    assert_int_equal(pc_parse_length("0.5mm", "w", &pt, err, sizeof err), PC_OK);
    NEAR(pt, 0.5 * 72 / 25.4);
    assert_int_equal(pc_parse_length("3in", "w", &pt, err, sizeof err), PC_OK);
    NEAR(pt, 216);
    assert_int_equal(pc_parse_length("0.8pt", "w", &pt, err, sizeof err), PC_OK);
    NEAR(pt, 0.8);
    assert_int_equal(pc_parse_length("96px", "w", &pt, err, sizeof err), PC_OK);
    NEAR(pt, 72);
    assert_int_equal(pc_parse_length("12", "width", &pt, err, sizeof err), PC_EARG);
    assert_string_equal(err, "width: the length '12' needs a unit (cm, mm, in, pt or px)");
    assert_int_equal(pc_parse_length("12em", "width", &pt, err, sizeof err), PC_EARG);
    assert_string_equal(err, "width: unknown unit 'em' in '12em' (cm, mm, in, pt or px)");
    assert_int_equal(pc_parse_length("-1cm", "width", &pt, err, sizeof err), PC_EARG);
    assert_string_equal(err, "width: a length must be positive, got '-1cm'");
    assert_int_equal(pc_parse_length("infcm", "width", &pt, err, sizeof err), PC_EARG);
    assert_int_equal(pc_parse_length("0x10cm", "width", &pt, err, sizeof err), PC_EARG);
    assert_int_equal(pc_parse_length("", "width", &pt, err, sizeof err), PC_EARG);
    assert_int_equal(pc_parse_size("12cmx8cm", &w, &h, err, sizeof err), PC_OK);
    NEAR(w, 12 * 72 / 2.54);
    NEAR(h, 8 * 72 / 2.54);
    assert_int_equal(pc_parse_size("5in", &w, &h, err, sizeof err), PC_OK);
    NEAR(w, 360);
    NEAR(h, 0);
    assert_int_equal(pc_parse_size("12cmx", &w, &h, err, sizeof err), PC_EARG);
    assert_string_equal(err, "--size (height): expected a length such as \"12cm\", got an empty string");
}

static void test_pens(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(64, 48, 16);
    assert_int_equal(pc_pen_named(c, "main"), PC_OK);
    NEAR(c->pens[c->pen].print_width, 0.5 * 72 / 25.4);
    assert_int_equal(c->pens[c->pen].ndash, 0);
    NEAR(c->pens[c->pen].width, 2);   /* the VGA look: 1.42 pt at 0.75 pt a pixel */
    assert_int_equal(pc_pen_named(c, "hidden"), PC_OK);
    assert_int_equal(c->pens[c->pen].ndash, 2);
    NEAR(c->pens[c->pen].dash[0] * 0.75, 3 * 72 / 25.4);   /* 3 mm dashes */
    assert_int_equal(pc_pen_named(c, "centre"), PC_OK);
    assert_int_equal(c->pens[c->pen].ndash, 4);
    int centre = c->pen;
    assert_int_equal(pc_pen_named(c, "center"), PC_OK);
    assert_int_equal(c->pen, centre);   /* one pen, two spellings */
    assert_int_equal(pc_pen_named(c, "bold"), PC_EARG);
    assert_string_equal(c->error, "pen: unknown pen \"bold\" (the named pens are \"main\", \"thin\", "
                                  "\"hidden\" and \"centre\")");
    assert_int_equal(pc_pen_physical(c, 0.01, NULL, 0), PC_EARG);
    assert_string_equal(c->error, "pen: width must be 0.1..100 pt (0.035..35 mm), got 0.01 pt");
    pc_canvas_free(c);
}

static void test_figure_page(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_page pg;
    pc_print_page(c, &pg);   /* no figure: the canvas at 96 px to the inch */
    NEAR(pg.width, 480);
    NEAR(pg.height, 360);
    pc_figure f = {0};
    f.width = 12 * 72 / 2.54;
    f.dpi = 300;
    assert_int_equal(pc_figure_set(c, &f), PC_OK);
    assert_true(c->figure.on);
    pc_print_page(c, &pg);
    assert_int_equal(lrint(pg.width * pg.dpi / 72), 1417);   /* 12 cm at 300 dpi */
    NEAR(pg.height, pg.width * 0.75);                        /* the window's aspect */
    f.height = f.width;   /* a square page: the canvas centred at one scale */
    assert_int_equal(pc_figure_set(c, &f), PC_OK);
    pc_print_page(c, &pg);
    NEAR(pg.s, pg.width / 640);
    NEAR(pg.oy, (pg.height - 480 * pg.s) / 2);
    pc_figure bad = f;
    bad.dpi = 5;
    assert_int_equal(pc_figure_set(c, &bad), PC_EARG);
    assert_string_equal(c->error, "figure: dpi must be 10..2400, got 5");
    bad = f;
    bad.width = 100 * 72;   /* 100 in at 300 dpi: 30000 pixels */
    assert_int_equal(pc_figure_set(c, &bad), PC_EARG);
    assert_non_null(strstr(c->error, "at most 20000 a side"));
    bad = f;
    strcpy(bad.font, "No Such Font Family");
    assert_int_equal(pc_figure_set(c, &bad), PC_EARG);
    assert_string_equal(c->error, "font 'No Such Font Family' is not installed (fc-list lists the "
                                  "fonts; the defaults are serif, sans and mono)");
    const char *family;
    char err[200];
    assert_int_equal(pc_font_family("serif", &family, err, sizeof err), PC_OK);
    assert_string_equal(family, "CMU Serif");
    assert_int_equal(pc_font_family("mono", &family, err, sizeof err), PC_OK);
    assert_string_equal(family, "DejaVu Sans Mono");
    pc_canvas_free(c);
}

typedef struct { char *buf; size_t len; } mem;

static mem render(const pc_canvas *c, pc_format fmt) {
    mem m = {0};
    FILE *f = open_memstream(&m.buf, &m.len);
    char err[200];
    assert_int_equal(pc_encode_print(c, fmt, f, err, sizeof err), PC_OK);
    fclose(f);
    return m;
}

typedef struct { const char *p; size_t left; } reader;
static cairo_status_t read_mem(void *closure, unsigned char *data, unsigned int len) {
    reader *r = closure;
    if (len > r->left) return CAIRO_STATUS_READ_ERROR;
    memcpy(data, r->p, len);
    r->p += len;
    r->left -= len;
    return CAIRO_STATUS_SUCCESS;
}

static void test_outputs(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_figure f = {0};
    f.width = 12 * 72 / 2.54;
    f.dpi = 300;
    assert_int_equal(pc_figure_set(c, &f), PC_OK);
    assert_int_equal(pc_line(c, 0, 0, 639, 479, 15), PC_OK);
    assert_int_equal(pc_text(c, 320, 100, "$A_1$ угол", PC_ANCHOR_NE, 3, 1, 15), PC_OK);

    mem png = render(c, PC_FMT_PNG);
    reader r = {png.buf, png.len};
    cairo_surface_t *img = cairo_image_surface_create_from_png_stream(read_mem, &r);
    assert_int_equal(cairo_surface_status(img), CAIRO_STATUS_SUCCESS);
    assert_int_equal(cairo_image_surface_get_width(img), 1417);
    assert_int_equal(cairo_image_surface_get_height(img), 1063);
    /* the diagonal is antialiased: along a row across it, grey levels between ink and paper */
    const unsigned char *px = cairo_image_surface_get_data(img);
    int stride = cairo_image_surface_get_stride(img), greys = 0, black = 0;
    for (int y = 500; y < 520; y++)
        for (int x = 600; x < 760; x++) {
            int g = px[y * stride + 4 * x + 1];   /* green of a BGRx pixel */
            if (g > 20 && g < 235) greys++;
            if (g <= 20) black++;
        }
    assert_true(greys > 20);
    assert_true(black > 20);
    cairo_surface_destroy(img);
    free(png.buf);

    mem pdf = render(c, PC_FMT_PDF);
    assert_true(pdf.len > 1000 && !memcmp(pdf.buf, "%PDF-", 5));
    free(pdf.buf);
    mem eps = render(c, PC_FMT_EPS);
    assert_true(!memcmp(eps.buf, "%!PS-Adobe-3.0 EPSF-3.0", 23));
    free(eps.buf);

    /* the SVG keeps the label as text: a run a tspan, the letter italic, the digit smaller */
    mem svg = render(c, PC_FMT_SVG);
    svg.buf = realloc(svg.buf, svg.len + 1);
    svg.buf[svg.len] = 0;
    assert_non_null(strstr(svg.buf, "font-family=\"CMU Serif\""));
    assert_non_null(strstr(svg.buf, "font-style=\"italic\">A</tspan>"));
    assert_non_null(strstr(svg.buf, "font-size=\"7.000\">1</tspan>"));
    assert_non_null(strstr(svg.buf, "угол</tspan>"));
    assert_non_null(strstr(svg.buf, "paint-order=\"stroke\""));   /* the halo */
    assert_non_null(strstr(svg.buf, "width=\"340.157pt\""));        /* 12 cm */
    free(svg.buf);

    /* a label's style: no halo, a size */
    assert_int_equal(pc_text_style(c, "sans", 14, 0), PC_OK);
    svg = render(c, PC_FMT_SVG);
    svg.buf = realloc(svg.buf, svg.len + 1);
    svg.buf[svg.len] = 0;
    assert_non_null(strstr(svg.buf, "font-family=\"DejaVu Sans\" font-size=\"14.000\""));
    assert_null(strstr(svg.buf, "paint-order"));
    free(svg.buf);
    assert_int_equal(pc_text_style(c, NULL, 500, -1), PC_EARG);
    assert_string_equal(c->error, "label: size must be 1..200 pt, got 500");
    pc_line(c, 0, 0, 1, 1, 15);
    assert_int_equal(pc_text_style(c, NULL, 10, -1), PC_EARG);   /* the last op is a line */
    assert_string_equal(c->error, "label: no text to style");

    /* a font that is not installed is an error at write time, not a silent box */
    pc_text(c, 10, 10, "x", PC_ANCHOR_NE, 3, 1, 15);
    assert_int_equal(pc_text_style(c, "Nonexistent Sans", 0, -1), PC_OK);
    char err[200];
    FILE *nul = fopen("/dev/null", "wb");
    assert_int_equal(pc_encode_print(c, PC_FMT_PDF, nul, err, sizeof err), PC_EARG);
    fclose(nul);
    assert_string_equal(err, "font 'Nonexistent Sans' is not installed (fc-list lists the fonts; "
                             "the defaults are serif, sans and mono)");
    pc_canvas_free(c);
}

/* Pango's layout of a math label: the subscript smaller and lower, the letter italic. */
static void test_pango_layout(void **state) {
    (void)state;
    pc_mlayout L;
    char err[200];
    assert_int_equal(pc_pr_layout("$A_1$", 1, "CMU Serif", 10, &L, err, sizeof err), PC_OK);
    assert_int_equal(L.nruns, 2);
    assert_true(L.runs[0].italic && !L.runs[1].italic);
    assert_true(L.runs[1].size < L.runs[0].size && L.runs[1].rise < 0);
    assert_true(L.runs[1].x > 5 && L.runs[1].x < 9);   /* after an A of about 0.75 em */
    assert_true(L.width > L.runs[1].x);
    pc_mlayout_free(&L);
    /* QBasic's PRINT: the text as it is, '$' included */
    assert_int_equal(pc_pr_layout("A$ = 5", 0, "CMU Serif", 10, &L, err, sizeof err), PC_OK);
    assert_int_equal(L.nruns, 1);
    assert_string_equal(L.text, "A$ = 5");
    pc_mlayout_free(&L);
}

static cairo_surface_t *png_of(const pc_canvas *c) {
    mem png = render(c, PC_FMT_PNG);
    reader r = {png.buf, png.len};
    cairo_surface_t *img = cairo_image_surface_create_from_png_stream(read_mem, &r);
    free(png.buf);
    assert_int_equal(cairo_surface_status(img), CAIRO_STATUS_SUCCESS);
    return img;
}

/* The share of white pixels in a box of the picture. */
static double white_share(cairo_surface_t *img, int x0, int y0, int x1, int y1) {
    const unsigned char *px = cairo_image_surface_get_data(img);
    int stride = cairo_image_surface_get_stride(img), n = 0, w = 0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++, n++) w += px[y * stride + 4 * x + 1] > 200;
    return (double)w / n;
}

/* A label over ink: its halo clears a margin of paper round the letters; halo = false not. */
static void test_halo_and_colours(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(200, 100, 16);
    pc_figure f = {0};
    f.dpi = 96;   /* 1 pt = 4/3 px; the canvas at 96 px to the inch: one screen pixel a pixel */
    f.size = 40;
    assert_int_equal(pc_figure_set(c, &f), PC_OK);
    assert_int_equal(pc_box(c, 0, 0, 199, 99, 15, 1), PC_OK);   /* white ink: black on paper */
    assert_int_equal(pc_text(c, 50, 50, "$x$", PC_ANCHOR_C, 0, 1, 0), PC_OK);   /* paper-coloured text */
    cairo_surface_t *img = png_of(c);
    double with = white_share(img, 20, 20, 80, 80);
    cairo_surface_destroy(img);
    assert_int_equal(pc_text_style(c, NULL, 0, 0), PC_OK);
    img = png_of(c);
    double without = white_share(img, 20, 20, 80, 80);
    cairo_surface_destroy(img);
    assert_true(without > 0.02);              /* the letter itself, in the paper's colour */
    assert_true(with > without + 0.02);       /* and the halo round it */

    /* the print theme: yellow (14) prints dark gold, white ink black, "#rrggbb" exactly */
    pc_canvas *d = pc_canvas_new(64, 48, 16);
    assert_int_equal(pc_figure_set(d, &f), PC_OK);
    pc_line(d, 0, 0, 10, 10, 14);
    pc_line(d, 0, 10, 10, 20, 15);
    pc_line(d, 0, 20, 10, 30, pc_rgb_color(d, (pc_rgb){0x12, 0x34, 0x56}));
    mem svg = render(d, PC_FMT_SVG);
    svg.buf = realloc(svg.buf, svg.len + 1);
    svg.buf[svg.len] = 0;
    assert_non_null(strstr(svg.buf, "stroke=\"#a07800\""));
    assert_non_null(strstr(svg.buf, "stroke=\"#000000\""));
    assert_non_null(strstr(svg.buf, "stroke=\"#123456\""));
    assert_non_null(strstr(svg.buf, "fill=\"#ffffff\"/>"));   /* white paper */
    free(svg.buf);
    pc_canvas_free(c);
    pc_canvas_free(d);
}

/* The lightest pixel along the diagonal of a square filled as two triangles in ink (black). */
static int diagonal_seam(int rule) {
    pc_canvas *c = pc_canvas_new(100, 100, 16);
    pc_figure f = {0};
    f.dpi = 96;
    assert_int_equal(pc_figure_set(c, &f), PC_OK);
    const double upper[6] = {10, 10, 90, 10, 90, 90}, lower[6] = {10, 10, 90, 90, 10, 90};
    assert_int_equal(pc_fill_path(c, 3, upper, NULL, 0, rule, 15), PC_OK);
    assert_int_equal(pc_fill_path(c, 3, lower, NULL, 0, rule, 15), PC_OK);
    cairo_surface_t *img = png_of(c);
    const unsigned char *px = cairo_image_surface_get_data(img);
    int stride = cairo_image_surface_get_stride(img), lightest = 0;
    for (int x = 20; x < 80; x++) {
        int g = px[x * stride + 4 * x + 1];
        if (g > lightest) lightest = g;
    }
    cairo_surface_destroy(img);
    pc_canvas_free(c);
    return lightest;
}

/* Adjacent antialiased fills let the paper through along their shared edge; tiles
 * (PC_FILL_TILE, a shaded surface's quads) have their outline stroked over it. */
static void test_tiles_without_seams(void **state) {
    (void)state;
    assert_true(diagonal_seam(PC_FILL_NONZERO) > 40);
    assert_true(diagonal_seam(PC_FILL_NONZERO | PC_FILL_TILE) < 8);
    pc_canvas *c = pc_canvas_new(10, 10, 16);
    const double tri[6] = {1, 1, 8, 1, 8, 8};
    assert_int_equal(pc_fill_path(c, 3, tri, NULL, 0, 4 | PC_FILL_TILE, 15), PC_EARG);
    assert_non_null(strstr(c->error, "the fill rule must be even-odd (1) or nonzero (0), got 4"));
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lengths),
        cmocka_unit_test(test_pens),
        cmocka_unit_test(test_figure_page),
        cmocka_unit_test(test_outputs),
        cmocka_unit_test(test_pango_layout),
        cmocka_unit_test(test_halo_and_colours),
        cmocka_unit_test(test_tiles_without_seams),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
