/* Automatic label placement (layout.h): a crowd of labels round close points gets no overlap
 * and stays inside; a label never sits across a line when a free place exists; a label given
 * a direction keeps it; the resolved copy draws the glyphs and leaves the canvas pending; the
 * measuring hook sets the boxes. */
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
#include "font.h"
#include "layout.h"

static size_t overlaps(const pc_box2 *b, size_t n) {
    size_t k = 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) k += pc_box2_overlap(b[i], b[j]);
    return k;
}

static int inside(pc_box2 b, double w, double h) {
    return b.x0 >= 0 && b.y0 >= 0 && b.x1 <= w && b.y1 <= h;
}

/* 30 labels round 10 points 12 px apart, in the picture's corner: 0 overlaps, all inside. */
static void test_crowd_of_thirty(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    for (int i = 0; i < 10; i++) {
        double x = 20 + 12 * (i % 5), y = 20 + 12 * (i / 5);
        pc_pset(c, x, y, 15);
        for (int k = 0; k < 3; k++) {
            char s[8];
            snprintf(s, sizeof s, "%c%d", 'A' + k, i);
            assert_int_equal(pc_text(c, x, y, s, PC_ANCHOR_AUTO, 0, 1, 14), PC_OK);
        }
    }
    pc_box2 *b;
    size_t n;
    assert_int_equal(pc_layout_labels(c, &b, NULL, &n), PC_OK);
    assert_int_equal(n, 30);
    assert_int_equal(overlaps(b, n), 0);
    for (size_t i = 0; i < n; i++) {
        assert_true(inside(b[i], 640, 480));
        assert_int_equal(b[i].x1 - b[i].x0, 16);   /* two VGA cells */
        assert_int_equal(b[i].y1 - b[i].y0, 16);
    }
    free(b);
    pc_canvas_free(c);
}

/* A label on a point of a horizontal line and a vertical one: the four sides across them are
 * taken by ink, so it goes to a free diagonal quadrant; with the NE quadrant hatched, not NE. */
static void test_never_across_a_line(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_line(c, 0, 200, 639, 200, 15);
    pc_line(c, 300, 0, 300, 479, 15);
    for (int y = 100; y < 200; y += 4) pc_line(c, 301, y, 400, y, 15);   /* NE filled with ink */
    pc_text(c, 300, 200, "Label", PC_ANCHOR_AUTO, 0, 1, 14);
    pc_box2 *b;
    int *anchor;
    size_t n;
    assert_int_equal(pc_layout_labels(c, &b, &anchor, &n), PC_OK);
    assert_int_equal(n, 1);
    assert_int_equal(anchor[0], PC_ANCHOR_SE);   /* the next free side in the order NE SE NW SW */
    /* SE, 8 px off pixel (300, 200): at 3 px its glyphs' ascent (layout.h: pc_label_clear)
     * would touch the line; the box's top-left pixel is (308, 208) */
    assert_int_equal(b[0].x0, 308);
    assert_int_equal(b[0].y0, 208);
    /* and no ink under it in the resolved picture but its own */
    const pc_canvas *r = pc_layout_resolve(c);
    assert_non_null(r);
    assert_ptr_not_equal(r, c);
    int own = 0;
    for (int y = (int)b[0].y0 - 1; y < b[0].y1 + 1; y++)
        for (int x = (int)b[0].x0 - 1; x < b[0].x1 + 1; x++) {
            assert_int_equal(c->pixels[y * 640 + x], 0);   /* the canvas was free there */
            own += r->pixels[y * 640 + x] == 14;
        }
    assert_true(own > 40);   /* the glyphs of "Label" are drawn in the copy */
    assert_int_equal(c->pixels[210 * 640 + 310], 0);   /* the canvas itself stays pending */
    assert_true(pc_layout_pending(c));
    assert_false(pc_layout_pending(r));
    pc_layout_release(c, r);
    free(b);
    free(anchor);
    pc_canvas_free(c);
}

/* A dashed line is an obstacle through its gaps: a vertical line 5 px right of the point,
 * 1 px on and 40 off, leaves the NE and SE boxes free of drawn pixels, yet the label goes
 * to the west of it, clear of its column. */
static void test_dashes_are_obstacles(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    double dash[2] = {1, 40};
    assert_int_equal(pc_pen(c, 1, dash, 2), PC_OK);
    pc_line(c, 305, 160, 305, 240, 15);   /* on at 160, 201; off across 162..200 and 202..240 */
    pc_pen_reset(c);
    pc_text(c, 300, 200, "Q", PC_ANCHOR_AUTO, 0, 1, 14);
    pc_box2 *b;
    int *anchor;
    size_t n;
    assert_int_equal(pc_layout_labels(c, &b, &anchor, &n), PC_OK);
    assert_true(b[0].x1 + 1 <= 305 || b[0].x0 - 1 > 305);   /* its clearance misses x = 305 */
    assert_int_equal(anchor[0], PC_ANCHOR_NW);
    free(b);
    free(anchor);
    pc_canvas_free(c);
}

/* A label with a direction keeps it and is an obstacle: an automatic one on the same point
 * avoids it; at the picture's top-right corner the automatic one goes inside (SW). */
static void test_fixed_kept_and_inside(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_text(c, 100, 100, "fixed", PC_ANCHOR_NE, 3, 1, 15);
    pc_text(c, 100, 100, "auto", PC_ANCHOR_AUTO, 0, 1, 15);
    pc_text(c, 637, 2, "corner", PC_ANCHOR_AUTO, 0, 1, 15);
    pc_box2 *b;
    int *anchor;
    size_t n;
    assert_int_equal(pc_layout_labels(c, &b, &anchor, &n), PC_OK);
    assert_int_equal(n, 3);
    assert_int_equal(anchor[0], PC_ANCHOR_NE);
    assert_int_equal(b[0].x0, 103);
    assert_int_equal(b[0].y0, 100 - 3 - 16 + 1);
    assert_int_equal(anchor[1], PC_ANCHOR_SE);
    assert_int_equal(overlaps(b, n), 0);
    assert_int_equal(anchor[2], PC_ANCHOR_SW);
    assert_true(inside(b[2], 640, 480));
    free(b);
    free(anchor);
    pc_canvas_free(c);
}

/* The measuring hook: a print look's font 10 px per character and 12 px high. */
static int measure10(void *ctx, const char *s, size_t n, int scale, double *w, double *h) {
    (void)ctx;
    (void)s;
    *w = 10.0 * (double)n * scale;
    *h = 12.0 * scale;
    return PC_OK;
}

static void test_measure_hook(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    c->measure = measure10;
    pc_text(c, 50, 50, "abc", PC_ANCHOR_AUTO, 0, 1, 15);
    pc_box2 *b;
    size_t n;
    assert_int_equal(pc_layout_labels(c, &b, NULL, &n), PC_OK);
    assert_int_equal(b[0].x1 - b[0].x0, 30);
    assert_int_equal(b[0].y1 - b[0].y0, 12);
    free(b);
    pc_canvas_free(c);
}

/* Far out with a leader: a point walled in by labels on every near side gets a leader line
 * drawn from it towards its box. */
static void test_leader(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    /* fill the neighbourhood with ink out to 30 px, leaving the rest free */
    for (int y = 170; y <= 230; y++) pc_line(c, 270, y, 330, y, 7);
    pc_text(c, 300, 200, "X", PC_ANCHOR_AUTO, 0, 1, 14);
    pc_box2 *b;
    size_t n;
    assert_int_equal(pc_layout_labels(c, &b, NULL, &n), PC_OK);
    pc_box2 near = {269, 169, 332, 232};
    assert_false(pc_box2_overlap(b[0], near));
    const pc_canvas *r = pc_layout_resolve(c);
    assert_true(r->nops == c->nops + 1);   /* the leader */
    assert_int_equal(r->ops[r->nops - 1].kind, PC_OP_LINE);
    pc_layout_release(c, r);
    free(b);
    pc_canvas_free(c);
}

/* The ink map counts exactly. */
static void test_inkmap(void **state) {
    (void)state;
    uint8_t mask[4 * 3] = {1, 0, 0, 1,
                           0, 1, 0, 0,
                           1, 1, 1, 1};
    pc_inkmap m;
    assert_int_equal(pc_inkmap_init(&m, mask, 4, 3), PC_OK);
    assert_int_equal(pc_inkmap_count(&m, (pc_box2){0, 0, 4, 3}), 7);
    assert_int_equal(pc_inkmap_count(&m, (pc_box2){1, 0, 3, 2}), 1);
    assert_int_equal(pc_inkmap_count(&m, (pc_box2){-5, 2, 9, 9}), 4);
    assert_int_equal(pc_inkmap_count(&m, (pc_box2){3, 3, 9, 9}), 0);
    pc_inkmap_free(&m);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_crowd_of_thirty),
        cmocka_unit_test(test_dashes_are_obstacles),
        cmocka_unit_test(test_never_across_a_line),
        cmocka_unit_test(test_fixed_kept_and_inside),
        cmocka_unit_test(test_measure_hook),
        cmocka_unit_test(test_leader),
        cmocka_unit_test(test_inkmap),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
