/* Dots folded into pixels (dotfold.c; issue 15, item 6): memory bounded by the picture.  A
 * long run of dots becomes one PIXELS op; the raster is untouched, the display list stays
 * small, and the SVG, read back, has the raster's pixels. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "canvas_internal.h"
#include "qbscreen.h"
#include "writers.h"

static uint32_t rng = 12345;
static uint32_t next(void) { rng ^= rng << 13; rng ^= rng >> 17; rng ^= rng << 5; return rng; }

/* the same drawing on two canvases: one folds after `budget` dots, one never */
static pc_canvas *canvas(size_t budget) {
    pc_canvas *c = pc_canvas_new(64, 48, 16);
    assert_non_null(c);
    c->dot_budget = budget;
    return c;
}

static char *svg_of(const pc_canvas *c) {
    FILE *f = tmpfile();
    assert_non_null(f);
    assert_int_equal(pc_encode_svg(c, PC_THEME_SCREEN, f), PC_OK);
    long len = ftell(f);
    char *text = malloc((size_t)len + 1);
    rewind(f);
    assert_int_equal(fread(text, 1, (size_t)len, f), (size_t)len);
    text[len] = 0;
    fclose(f);
    return text;
}

/* scattered dots (none within 1.5 px of the one before: all isolated) in changing colours,
 * some outside the view or the screen */
static void scatter(pc_canvas *c, int n, uint32_t seed) {
    rng = seed;
    for (int i = 0; i < n; i++) {
        double x = (double)(next() % 80) - 8 + (next() % 4) * 0.25;
        double y = (double)(next() % 60) - 6;
        assert_int_equal(pc_pset(c, x, y, 1 + (int)(next() % 15)), PC_OK);
        pc_pset(c, x + 3, y + 3, 1 + i % 15);   /* 3 px on: never dense */
    }
}

static void test_bounded_and_same(void **state) {
    (void)state;
    pc_canvas *a = canvas(100), *b = canvas(SIZE_MAX);
    for (int k = 0; k < 2; k++) {
        pc_canvas *c = k ? b : a;
        pc_view(c, 4, 2, 50, 40, -1, -1, 0);
        scatter(c, 5000, 7);
        pc_line(c, 0, 0, 30, 20, 14);            /* another op: the run ends */
        scatter(c, 3000, 8);
    }
    assert_memory_equal(a->pixels, b->pixels, 64 * 48 * sizeof *a->pixels);
    assert_int_equal(b->ndots, 16000);          /* the unfolded list holds every dot */
    assert_true(a->ndots <= 100 + 1);           /* the folded one at most a budget of them */
    assert_true(a->nops <= 2 + 1 + 100 + 2);    /* PIXELS, line, PIXELS, the last dots */
    assert_int_equal(a->ops[0].kind, PC_OP_PIXELS);
    assert_true(a->nlpx <= 2 * 64 * 48);
    /* the painter's order is kept: pixels, then the line, then pixels */
    char *sa = svg_of(a);
    const char *line = strstr(sa, "stroke=\"#ffff55\""), *first = strstr(sa, "crispEdges");
    assert_true(line && first && first < line);
    assert_non_null(strstr(line, "crispEdges"));
    free(sa);
    pc_canvas_free(a);
    pc_canvas_free(b);
}

/* ---- the SVG read back: the pixel layer's paths ("M x y h n v 1 h -n z m dx dy ...") ---- */

static double num(const char **p) {
    char *end;
    double v = strtod(*p, &end);
    assert_true(end != *p);
    *p = end;
    return v;
}

/* Paint every crisp-edged path of the document (the exact pixels) into rgb[64 * 48]; returns
 * how many pixels were painted. */
static int read_pixels(const char *svg, pc_rgb *rgb) {
    int painted = 0;
    for (const char *p = svg; (p = strstr(p, "<path fill=\"#")) != NULL;) {
        unsigned r, g, b;
        assert_int_equal(sscanf(p, "<path fill=\"#%2x%2x%2x\"", &r, &g, &b), 3);
        const char *end = strstr(p, "/>");
        const char *d = strstr(p, " d=\"");
        assert_non_null(strstr(p, "crispEdges"));
        assert_true(d && d < end);
        d += 4;
        double x = 0, y = 0, x0 = 0, y0 = 0;   /* the current point, the subpath's start */
        while (*d != '"') {
            char cmd = *d++;
            if (cmd == '\n' || cmd == ' ') continue;
            if (cmd == 'M') { x0 = x = num(&d); y0 = y = num(&d); }
            else if (cmd == 'm') { x0 = x += num(&d); y0 = y += num(&d); }
            else if (cmd == 'h') {
                double len = num(&d);
                if (len > 0) {   /* the run's top edge: pixels x .. x + len - 1 of row y */
                    assert_true(x >= 0 && x + len <= 64 && y >= 0 && y < 48);
                    for (int i = 0; i < (int)len; i++) {
                        rgb[(int)y * 64 + (int)x + i] = (pc_rgb){(uint8_t)r, (uint8_t)g, (uint8_t)b};
                        painted++;
                    }
                }
                x += len;
            } else if (cmd == 'v') y += num(&d);
            else if (cmd == 'z') { x = x0; y = y0; }
            else fail_msg("unexpected path command %c", cmd);
        }
        p = end;
    }
    return painted;
}

static void test_svg_read_back(void **state) {
    (void)state;
    pc_canvas *c = canvas(500);
    pc_view(c, 2, 3, 60, 44, -1, -1, 0);
    rng = 99;   /* dense runs of one colour (polylines before a fold) mixed with scattered dots */
    for (int i = 0; i < 20000; i++) {
        double t = i * 0.01;
        pc_pset(c, 30 + 25 * sin(3 * t), 22 + 18 * sin(4 * t + 0.5), 1 + (i / 50) % 15);
        if (i % 7 == 0) pc_pset(c, (double)(next() % 70), (double)(next() % 50), 1 + (int)(next() % 15));
    }
    assert_true(c->ndots <= 501);
    char *svg = svg_of(c);
    pc_rgb pal[256], rgb[64 * 48];
    pc_theme_palette(c, PC_THEME_SCREEN, pal);
    for (int i = 0; i < 64 * 48; i++) rgb[i] = pal[0];   /* the background */
    int painted = read_pixels(svg, rgb);
    assert_true(painted > 1000);
    /* what the dots left after the last fold may be polylines: fold them too, then compare */
    free(svg);
    c->dot_budget = 0;
    pc_fold_dots(c);
    assert_int_equal(c->ndots, 0);
    svg = svg_of(c);
    for (int i = 0; i < 64 * 48; i++) rgb[i] = pal[0];
    read_pixels(svg, rgb);
    for (int i = 0; i < 64 * 48; i++) {
        pc_rgb want = pc_attr_rgb(c, pal, c->pixels[i]);
        if (memcmp(&want, &rgb[i], sizeof want) != 0)
            fail_msg("pixel (%d, %d): SVG #%02x%02x%02x, raster #%02x%02x%02x", i % 64, i / 64,
                     rgb[i].r, rgb[i].g, rgb[i].b, want.r, want.g, want.b);
    }
    free(svg);
    pc_canvas_free(c);
}

/* a million dots in changing colours: the display list stays within the budget */
static void test_million(void **state) {
    (void)state;
    pc_canvas *c = canvas(1000);
    for (int i = 0; i < 1000000; i++) pc_pset(c, i % 64, (i / 64) % 48, 1 + i % 15);
    assert_true(c->nops <= 1002);
    assert_true(c->ndots <= 1001);
    assert_true(c->nlpx <= 64 * 48);
    assert_true(c->capops <= 2048 && c->capdots <= 2048);   /* memory, not just counts */
    assert_int_equal(c->pixels[5 * 64 + 3], 1 + (999999 - ((999999 - (5 * 64 + 3)) % 3072)) % 15);
    pc_canvas_free(c);
}

/* SCREEN's reset and a full CLS forget the pixels; PCOPY copies them */
static void test_reset_and_copy(void **state) {
    (void)state;
    pc_canvas *c = canvas(10), *d = canvas(10);
    scatter(c, 100, 3);
    assert_true(c->nlpx > 0);
    assert_int_equal(pc_canvas_copy_picture(d, c), PC_OK);
    assert_int_equal(d->nlpx, c->nlpx);
    char *sc = svg_of(c), *sd = svg_of(d);
    assert_string_equal(sc, sd);
    free(sc);
    free(sd);
    pc_cls(c);
    assert_int_equal(c->nlpx, 0);
    assert_int_equal(c->nops, 0);
    scatter(d, 100, 4);                         /* the copy folds on by itself */
    assert_true(d->ndots <= 11);
    assert_int_equal(pc_canvas_reset(d, 64, 48, 16), PC_OK);
    assert_int_equal(d->nlpx, 0);
    assert_int_equal(d->dot_budget, 65536);     /* max(64 * 48, 65536) */
    pc_canvas_free(c);
    pc_canvas_free(d);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bounded_and_same),
        cmocka_unit_test(test_svg_read_back),
        cmocka_unit_test(test_million),
        cmocka_unit_test(test_reset_and_copy),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
