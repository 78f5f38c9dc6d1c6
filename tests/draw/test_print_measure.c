/* The print look's label boxes (print_measure.c): the measuring hook gives Pango's box with
 * the halo, in screen pixels, whatever the dpi; labels placed with it overlap nothing and stay
 * inside; a label with a direction keeps its side and gap; the print walk draws each label in
 * the box the layout gave it (the halo's 0.16 em on every side). */
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
#include "layout.h"
#include "math_label.h"
#include "print.h"
#include "print_backend.h"

#define NEAR(a, b, e) assert_true(fabs((a) - (b)) < (e))

/* A 640 x 480 canvas as a figure of 480 x 360 pt: one screen pixel is 0.75 pt. */
static pc_canvas *figure(double dpi, double size) {
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_figure f = {0};
    f.width = 480;
    f.dpi = dpi;
    f.size = size;
    assert_int_equal(pc_figure_set(c, &f), PC_OK);
    return c;
}

/* Pango's box of a label at a size, halo included, in pixels of 0.75 pt. */
static void pango_box(const char *s, int math, double size, double *w, double *h) {
    pc_mlayout L;
    char err[200];
    assert_int_equal(pc_pr_layout(s, math, "CMU Serif", size, &L, err, sizeof err), PC_OK);
    *w = (L.width + 0.32 * size) / 0.75;
    *h = (L.ascent + L.descent + 0.32 * size) / 0.75;
    pc_mlayout_free(&L);
}

static void test_box_is_pango(void **state) {
    (void)state;
    pc_canvas *c = figure(96, 10);
    double w, h, ew, eh;
    assert_int_equal(pc_print_measure(c, "Дельта", strlen("Дельта"), 1, &w, &h), PC_OK);
    pango_box("Дельта", 0, 10, &ew, &eh);
    NEAR(w, ew, 1e-9);
    NEAR(h, eh, 1e-9);
    assert_true(w > 30 && w < 48);   /* not the VGA look's six cells of 8 pixels */
    assert_true(h > 18 && h < 22);   /* CMU Serif: ascent + descent 1.19 em */
    /* math is measured as it is drawn: the subscript is smaller than a letter */
    assert_int_equal(pc_print_measure(c, "$M_{12}$", 8, 1, &w, &h), PC_OK);
    pango_box("$M_{12}$", 1, 10, &ew, &eh);
    NEAR(w, ew, 1e-9);
    double plain;
    assert_int_equal(pc_print_measure(c, "M12", 3, 1, &plain, &h), PC_OK);
    assert_true(w < plain);
    /* scale 2 is the size 20 pt */
    assert_int_equal(pc_print_measure(c, "A", 1, 2, &w, &h), PC_OK);
    pango_box("A", 0, 20, &ew, &eh);
    NEAR(w, ew, 1e-9);
    NEAR(h, eh, 1e-9);
    pc_canvas_free(c);
    /* the dpi does not enter: a 300-dpi PNG places labels as the PDF does */
    pc_canvas *d = figure(300, 10);
    double w3, h3;
    assert_int_equal(pc_print_measure(d, "Дельта", strlen("Дельта"), 1, &w3, &h3), PC_OK);
    pango_box("Дельта", 0, 10, &ew, &eh);
    NEAR(w3, ew, 1e-9);
    NEAR(h3, eh, 1e-9);
    pc_canvas_free(d);
}

static size_t overlaps(const pc_box2 *b, size_t n) {
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) k += pc_box2_overlap(b[i], b[j]);
    return k;
}

/* 30 labels round 10 close points, placed by their Pango boxes: 0 overlaps, all inside, and
 * every box is the label's print box (not its VGA cells). */
static void test_crowd_placed_by_print_boxes(void **state) {
    (void)state;
    pc_canvas *c = figure(96, 10);
    for (int i = 0; i < 10; i++) {
        double x = 30 + 14 * (i % 5), y = 30 + 14 * (i / 5);
        pc_pset(c, x, y, 15);
        for (int k = 0; k < 3; k++) {
            char s[16];
            snprintf(s, sizeof s, "$%c_{%d}$", 'A' + k, i);
            assert_int_equal(pc_text(c, x, y, s, PC_ANCHOR_AUTO, 0, 1, 14), PC_OK);
        }
    }
    pc_canvas tmp;
    const pc_canvas *r = pc_print_resolve(c, &tmp);
    assert_non_null(r);
    pc_box2 *b;
    size_t n;
    assert_int_equal(pc_layout_labels(r, &b, NULL, &n), PC_OK);
    assert_int_equal(n, 30);
    assert_int_equal(overlaps(b, n), 0);
    for (size_t i = 0; i < n; i++) {
        assert_true(b[i].x0 >= 0 && b[i].y0 >= 0 && b[i].x1 <= 640 && b[i].y1 <= 480);
        char s[16];
        snprintf(s, sizeof s, "$%c_{%d}$", (int)('A' + i % 3), (int)(i / 3 % 10));
        double ew, eh;
        pango_box(s, 1, 10, &ew, &eh);
        NEAR(b[i].x1 - b[i].x0, ew, 1e-9);
        NEAR(b[i].y1 - b[i].y0, eh, 1e-9);
    }
    free(b);
    pc_layout_release(&tmp, r);
    /* the canvas itself keeps its labels pending and the VGA look's cells */
    assert_true(pc_layout_pending(c));
    assert_int_equal(pc_layout_labels(c, &b, NULL, &n), PC_OK);
    NEAR(b[0].y1 - b[0].y0, 16, 1e-9);
    free(b);
    pc_canvas_free(c);
}

/* A label with a direction keeps its side and its gap with its print box: "ne" 3 px off
 * (100, 100) starts at column 103 and ends on row 97; "w" 5 px off ends at column 95. */
static void test_fixed_side_and_gap(void **state) {
    (void)state;
    pc_canvas *c = figure(96, 10);
    pc_text(c, 100, 100, "A", PC_ANCHOR_NE, 3, 1, 15);
    pc_text(c, 100, 200, "Bc", PC_ANCHOR_W, 5, 1, 15);
    pc_text(c, 300, 300, "$P_0$", PC_ANCHOR_S, 4, 1, 15);
    pc_canvas tmp;
    const pc_canvas *r = pc_print_resolve(c, &tmp);
    pc_box2 *b;
    size_t n;
    assert_int_equal(pc_layout_labels(r, &b, NULL, &n), PC_OK);
    assert_int_equal(n, 3);
    double w, h;
    pango_box("A", 0, 10, &w, &h);
    NEAR(b[0].x0, 103, 1e-9);
    NEAR(b[0].y1, 98, 1e-9);
    NEAR(b[0].x1 - b[0].x0, w, 1e-9);
    pango_box("Bc", 0, 10, &w, &h);
    NEAR(b[1].x1, 96, 1e-9);
    NEAR(b[1].y0, 200 - floor(h / 2), 1e-9);
    pango_box("$P_0$", 1, 10, &w, &h);
    NEAR(b[2].y0, 304, 1e-9);
    NEAR(b[2].x0, 300 - floor(w / 2), 1e-9);
    free(b);
    pc_layout_release(&tmp, r);
    pc_canvas_free(c);
}

/* A backend that keeps the labels the walk draws. */
typedef struct { double x[8], y[8], halo[8]; int n; } seen;
static void nop_clip(void *s, double a, double b, double c, double d) { (void)s, (void)a, (void)b, (void)c, (void)d; }
static void nop_xy(void *s, double x, double y) { (void)s, (void)x, (void)y; }
static void nop_curve(void *s, double a, double b, double c, double d, double e, double f) {
    (void)s, (void)a, (void)b, (void)c, (void)d, (void)e, (void)f;
}
static void nop(void *s) { (void)s; }
static void nop_rect(void *s, double a, double b, double c, double d) { (void)s, (void)a, (void)b, (void)c, (void)d; }
static void nop_stroke(void *s, pc_rgb c, const pc_pr_pen *p) { (void)s, (void)c, (void)p; }
static void nop_fill(void *s, pc_rgb c, int e) { (void)s, (void)c, (void)e; }
static void keep_text(void *self, const pc_pr_label *l) {
    seen *s = self;
    if (s->n < 8) {
        s->x[s->n] = l->x;
        s->y[s->n] = l->y;
        s->halo[s->n] = l->halo;
        s->n++;
    }
}

/* The walk draws a placed label in its box: the layout's left end a halo (1.6 pt at 10 pt)
 * in from the box's left side, its ascent a halo below the box's top. */
static void test_drawn_in_its_box(void **state) {
    (void)state;
    pc_canvas *c = figure(96, 10);
    pc_line(c, 0, 240, 639, 240, 15);
    pc_text(c, 320, 240, "$M_1$", PC_ANCHOR_AUTO, 0, 1, 15);
    pc_text(c, 100, 100, "A", PC_ANCHOR_NE, 3, 1, 15);
    pc_canvas tmp;
    const pc_canvas *r = pc_print_resolve(c, &tmp);
    pc_box2 *b;
    size_t n;
    assert_int_equal(pc_layout_labels(r, &b, NULL, &n), PC_OK);
    seen s = {0};
    pc_pr_backend be = {&s, nop_clip, nop_xy, nop_xy, nop_curve, nop, nop_rect, nop_stroke,
                        nop_fill, keep_text, NULL, 0};
    pc_page pg;
    pc_print_page(r, &pg);
    char err[200];
    assert_int_equal(pc_print_walk(r, &pg, &be, err, sizeof err), PC_OK);
    assert_int_equal(s.n, 2);
    const char *text[2] = {"$M_1$", "A"};
    for (int i = 0; i < 2; i++) {
        pc_mlayout L;
        assert_int_equal(pc_pr_layout(text[i], i == 0, "CMU Serif", 10, &L, err, sizeof err), PC_OK);
        NEAR(s.x[i] - (pg.ox + b[i].x0 * pg.s), 1.6, 1e-9);
        NEAR(s.y[i] - L.ascent - (pg.oy + b[i].y0 * pg.s), 1.6, 1e-9);
        NEAR(s.halo[i], 1.6, 1e-9);
        pc_mlayout_free(&L);
    }
    assert_true(b[0].y1 <= 240 || b[0].y0 > 240);   /* the automatic one clear of the line */
    free(b);
    pc_layout_release(&tmp, r);
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_box_is_pango),
        cmocka_unit_test(test_crowd_placed_by_print_boxes),
        cmocka_unit_test(test_fixed_side_and_gap),
        cmocka_unit_test(test_drawn_in_its_box),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
