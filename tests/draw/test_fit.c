/* Framing what is drawn (layout.h: pc_fit): every point and label cell ends inside the view
 * with its margin, at equal units on both axes (a circle stays round, lengths keep their
 * ratios), as large as that allows and centred; later drawing in the old coordinates lands in
 * the new frame; PC_FIT_FILL fills both axes. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"
#include "furniture.h"
#include "layout.h"

static const pc_op *first_of(const pc_canvas *c, int kind) {
    for (size_t i = 0; i < c->nops; i++)
        if (c->ops[i].kind == kind) return &c->ops[i];
    return NULL;
}

static void test_fit_equal(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    /* a small figure in the corner: a 40 x 20 segment pair, a circle, a label at its right */
    pc_line(c, 10, 10, 50, 10, 15);
    pc_line(c, 10, 10, 10, 30, 15);
    pc_circle(c, 30, 20, 5, 14, NAN, NAN, NAN);
    pc_text(c, 50, 10, "B", PC_ANCHOR_E, 3, 1, 15);   /* its cell: 53..60, 2..17 */
    assert_int_equal(pc_fit(c, 20, PC_FIT_EQUAL), PC_OK);
    pc_box2 b;
    assert_int_equal(pc_drawn_extent(c, &b), PC_OK);
    assert_true(b.x0 >= 20 - 1e-9 && b.y0 >= 20 - 1e-9 && b.x1 <= 619 + 1e-9 && b.y1 <= 459 + 1e-9);
    /* as large as it can be: one axis fills the view from margin to margin */
    int tight_x = fabs(b.x0 - 20) < 1e-6 && fabs(b.x1 - 619) < 1e-6;
    int tight_y = fabs(b.y0 - 20) < 1e-6 && fabs(b.y1 - 459) < 1e-6;
    assert_true(tight_x || tight_y);
    /* equal units: the segments keep their 2:1 ratio, the circle its roundness */
    const pc_op *h = &c->ops[0], *v = &c->ops[1];
    double lh = hypot(h->x2 - h->x1, h->y2 - h->y1), lv = hypot(v->x2 - v->x1, v->y2 - v->y1);
    assert_true(fabs(lh / lv - 2) < 1e-12);
    const pc_op *arc = first_of(c, PC_OP_ARC);
    assert_non_null(arc);
    assert_true(fabs(arc->rx - arc->ry) < 1e-9);
    assert_true(fabs(arc->rx / lh - 5.0 / 40) < 1e-12);
    /* the label kept its 3 px gap from its point, its cell unscaled */
    const pc_op *t = first_of(c, PC_OP_TEXT);
    assert_true(fabs(t->x1 - nearbyint(t->x2) - 3) < 1e-9);
    assert_int_equal(t->flags, PC_ANCHOR_E);
    /* the raster follows: the far end of the horizontal segment is lit */
    assert_int_equal(c->pixels[(long)nearbyint(h->y2) * 640 + (long)nearbyint(h->x2)], 15);
    /* later drawing in the old coordinates lands on the new frame */
    size_t n = c->nops;
    pc_line(c, 10, 10, 50, 10, 12);
    assert_true(fabs(c->ops[n].x1 - h->x1) < 1e-9 && fabs(c->ops[n].y2 - h->y2) < 1e-9);
    pc_canvas_free(c);
}

static void test_fit_fill_and_window(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_window(c, 0, 0, 100, 100, 0);   /* world y up */
    pc_line(c, 10, 10, 20, 10, 15);
    pc_line(c, 10, 10, 10, 30, 15);
    assert_int_equal(pc_fit(c, 0, PC_FIT_FILL), PC_OK);
    pc_box2 b;
    assert_int_equal(pc_drawn_extent(c, &b), PC_OK);
    assert_true(fabs(b.x0) < 1e-9 && fabs(b.x1 - 639) < 1e-9);
    assert_true(fabs(b.y0) < 1e-9 && fabs(b.y1 - 479) < 1e-9);
    /* the world point (20, 10) is now the bottom-right corner, (10, 30) the top-left */
    double sx, sy;
    pc_world_to_screen(c, 20, 10, &sx, &sy);
    assert_true(fabs(sx - 639) < 1e-9 && fabs(sy - 479) < 1e-9);
    pc_world_to_screen(c, 10, 30, &sx, &sy);
    assert_true(fabs(sx) < 1e-9 && fabs(sy) < 1e-9);
    /* errors and nothing drawn */
    assert_int_equal(pc_fit(c, -1, PC_FIT_EQUAL), PC_EARG);
    assert_string_equal(c->error, "fit: margin must be 0 up to half the view, got -1 pixels");
    pc_canvas *e = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_fit(e, 10, PC_FIT_EQUAL), PC_OK);
    assert_int_equal(e->has_window, 0);
    pc_canvas_free(e);
    pc_canvas_free(c);
}

/* A crowd of automatic labels after fit: still placed inside, no overlaps. */
static void test_fit_then_labels(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    for (int i = 0; i < 5; i++) {
        pc_pset(c, 100 + 3 * i, 100, 15);
        pc_text(c, 100 + 3 * i, 100, "Pt", PC_ANCHOR_AUTO, 0, 1, 15);
    }
    assert_int_equal(pc_fit(c, 30, PC_FIT_EQUAL), PC_OK);
    pc_box2 *b;
    size_t n;
    assert_int_equal(pc_layout_labels(c, &b, NULL, &n), PC_OK);
    assert_int_equal(n, 5);
    for (size_t i = 0; i < n; i++) {
        assert_true(b[i].x0 >= 0 && b[i].y0 >= 0 && b[i].x1 <= 640 && b[i].y1 <= 480);
        for (size_t j = i + 1; j < n; j++) assert_false(pc_box2_overlap(b[i], b[j]));
    }
    free(b);
    pc_canvas_free(c);
}

/* A figure{} without a window (pc_figure.frame): the writers' copy is framed, y up, at equal
 * units, PC_FIT_MARGIN in; the canvas itself is untouched; a window, or no figure{} (a VGA
 * script sent to PDF keeps its pixels), leaves the picture where it was drawn. */
static void test_figure_frames(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_line(c, 0, 0, 4, 0, 15);
    assert_false(pc_layout_pending(c));          /* no figure{}: pixels, as drawn */
    c->figure.on = 1;                             /* --print on a VGA script: still pixels */
    assert_false(pc_layout_pending(c));
    c->figure.frame = 1;                          /* the script's own figure{} */
    assert_true(pc_figure_frames(c));
    pc_cls(c);
    pc_line(c, 0, 0, 4, 0, 15);   /* world units: a 4 x 3 right triangle's legs, y up */
    pc_line(c, 0, 0, 0, 3, 15);
    const pc_op *v0 = &c->ops[c->nops - 1];
    assert_true(v0->y2 == -3);                    /* the screen is the world mirrored */
    const pc_canvas *r = pc_layout_resolve(c);
    assert_non_null(r);
    assert_ptr_not_equal(r, c);
    const pc_op *h = &r->ops[r->nops - 2], *v = &r->ops[r->nops - 1];
    /* y up: the vertical leg goes up the screen from the corner; equal units: 4:3 */
    assert_true(v->y2 < v->y1);
    double lh = hypot(h->x2 - h->x1, h->y2 - h->y1), lv = hypot(v->x2 - v->x1, v->y2 - v->y1);
    assert_true(fabs(lh / lv - 4.0 / 3) < 1e-12);
    /* the taller axis fills the view but for the margin, the wider one is centred */
    double m = PC_FIT_MARGIN;
    assert_true(fabs(v->y1 - (479 - m)) < 1e-9 && fabs(v->y2 - m) < 1e-9);
    assert_true(fabs((h->x1 + h->x2) / 2 - 319.5) < 1e-9);
    assert_int_equal(r->pixels[(long)nearbyint(v->y2) * 640 + (long)nearbyint(v->x2)], 15);
    assert_true(c->ops[c->nops - 1].y2 == -3);    /* the canvas keeps its list */
    pc_layout_release(c, r);
    c->screen_pixels = 1;                         /* SCREEN 12: pixel coordinates */
    assert_false(pc_layout_pending(c));
    c->screen_pixels = 0;
    pc_window(c, -1, -1, 5, 4, 0);                /* a window: the script framed it itself */
    assert_false(pc_layout_pending(c));
    pc_canvas_free(c);
}

/* A marker keeps its size in pixels through framing (PC_OP_RIGID), its centre on its point. */
static void test_fit_keeps_marks(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_line(c, 10, 10, 20, 10, 15);
    assert_int_equal(pc_mark(c, 20, 10, PC_MARK_SQUARE, 6, 14), PC_OK);
    assert_int_equal(pc_fit(c, 20, PC_FIT_EQUAL), PC_OK);   /* some 60 times larger */
    const pc_op *l = first_of(c, PC_OP_LINE), *sq = first_of(c, PC_OP_PATH);
    assert_true(l->x2 - l->x1 > 500);                       /* scaled up */
    double x0 = INFINITY, x1 = -INFINITY;
    for (uint32_t k = 0; k < sq->count; k++) {
        x0 = fmin(x0, c->pts[sq->first + k].x);
        x1 = fmax(x1, c->pts[sq->first + k].x);
    }
    assert_true(fabs(x1 - x0 - 6) < 1e-9);                  /* still 6 px across */
    assert_true(fabs((x0 + x1) / 2 - l->x2) < 1e-9);        /* on the line's end */
    assert_true(sq->flags & PC_OP_RIGID);
    pc_canvas_free(c);
}

/* A caption (text in device pixels) stays where it was put, and the figure is framed above
 * it, clear of its band. */
static void test_figure_frames_captions(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    c->figure.on = c->figure.frame = 1;
    pc_line(c, 0, 0, 0, 3, 15);   /* world units: a tall segment would fill the height */
    double wx, wy;
    pc_screen_to_world(c, 320, 479, &wx, &wy);
    assert_int_equal(pc_text(c, wx, wy, "caption", PC_ANCHOR_N, 3, 1, 15), PC_OK);
    c->ops[c->nops - 1].flags |= PC_TEXT_DEVICE;
    const pc_op *t0 = &c->ops[c->nops - 1];
    const pc_canvas *r = pc_layout_resolve(c);
    assert_non_null(r);
    const pc_op *l = first_of(r, PC_OP_LINE), *t = first_of(r, PC_OP_TEXT);
    assert_true(t->x1 == t0->x1 && t->y1 == t0->y1);                 /* the caption kept */
    assert_true(fmax(l->y1, l->y2) <= t->y1 - 1 - PC_FIT_MARGIN + 1e-9); /* framed above it */
    assert_true(fmin(l->y1, l->y2) >= PC_FIT_MARGIN - 1e-9);
    pc_layout_release(c, r);
    pc_canvas_free(c);
}

/* An automatic label in a framed figure: its box stays inside whatever side it takes. */
static void test_figure_frames_labels(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    c->figure.on = c->figure.frame = 1;
    pc_line(c, 0, 0, 10, 0, 15);
    const char *names[] = {"A", "B", "C"};
    for (int i = 0; i < 3; i++) pc_text(c, 5 * i, 0, names[i], PC_ANCHOR_AUTO, 0, 1, 15);
    pc_box2 *b;
    size_t n;
    assert_int_equal(pc_layout_labels(c, &b, NULL, &n), PC_OK);
    assert_int_equal(n, 3);
    for (size_t i = 0; i < n; i++)
        assert_true(b[i].x0 >= 0 && b[i].y0 >= 0 && b[i].x1 <= 640 && b[i].y1 <= 480);
    assert_true(b[0].x0 < PC_FIT_MARGIN + 2 * 8 + 4);   /* A at the left end: framed, not lost */
    free(b);
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fit_equal),
        cmocka_unit_test(test_fit_fill_and_window),
        cmocka_unit_test(test_fit_then_labels),
        cmocka_unit_test(test_figure_frames),
        cmocka_unit_test(test_fit_keeps_marks),
        cmocka_unit_test(test_figure_frames_labels),
        cmocka_unit_test(test_figure_frames_captions),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
