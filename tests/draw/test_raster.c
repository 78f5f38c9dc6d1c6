/* Exact-pixel tests of the QBasic drawing statements on small canvases. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"
#include "canvas_internal.h"

#define PI 3.14159265358979

static pc_canvas *small(int w, int h) {
    pc_canvas *c = pc_canvas_new(w, h, 16);
    assert_non_null(c);
    return c;
}

static int at(const pc_canvas *c, int x, int y) { return c->pixels[y * c->width + x]; }

static int count(const pc_canvas *c, int color) {
    int n = 0;
    for (int i = 0; i < c->width * c->height; i++) n += c->pixels[i] == color;
    return n;
}

/* The picture as rows of '#' (any non-zero colour) and '.', for whole-shape comparisons. */
static void assert_shape(const pc_canvas *c, const char *const rows[]) {
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++) {
            int want = rows[y][x] == '#';
            if ((at(c, x, y) != 0) != want) fail_msg("pixel (%d, %d): want %s", x, y, want ? "ink" : "none");
        }
}

static void test_screen_modes(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new_mode(12);
    assert_int_equal(c->width, 640);
    assert_int_equal(c->height, 480);
    assert_int_equal(c->ncolors, 16);
    assert_int_equal(c->fg, 15);
    assert_int_equal(count(c, 0), 640 * 480);
    /* the VGA palette of the Stepanov digest, section B */
    assert_int_equal(c->palette[6].r, 0xAA); assert_int_equal(c->palette[6].g, 0x55);
    assert_int_equal(c->palette[6].b, 0x00);
    assert_int_equal(c->palette[14].r, 0xFF); assert_int_equal(c->palette[14].g, 0xFF);
    assert_int_equal(c->palette[14].b, 0x55);
    assert_int_equal(c->palette[8].r, 0x55);
    pc_canvas_free(c);
    c = pc_canvas_new_mode(13);
    assert_int_equal(c->width, 320);
    assert_int_equal(c->height, 200);
    /* mode 13: greys 16..31 from black to white, then the hue wheel starting at blue */
    assert_int_equal(c->palette[16].r, 0);
    assert_int_equal(c->palette[31].r, 255);
    assert_int_equal(c->palette[32].b, 255); assert_int_equal(c->palette[32].r, 0);
    assert_int_equal(c->palette[40].r, 255); assert_int_equal(c->palette[40].b, 0);
    pc_canvas_free(c);
    /* QBasic's other modes are qbscreen.h's (test_qbscreen.c); 10 (monochrome EGA) is none */
    assert_non_null(c = pc_canvas_new_mode(7));
    assert_int_equal(c->ncolors, 16);
    pc_canvas_free(c);
    assert_null(pc_canvas_new_mode(10));
}

static void test_pset_rounding(void **state) {
    (void)state;
    pc_canvas *c = small(8, 8);
    /* nearest pixel, ties to even as the FPU rounds: 2.5 -> 2, 3.5 -> 4, 0.5 -> 0 */
    assert_int_equal(pc_pset(c, 2.5, 3.5, 4), PC_OK);
    assert_int_equal(at(c, 2, 4), 4);
    pc_pset(c, 0.5, 1.49, 5);
    assert_int_equal(at(c, 0, 1), 5);
    pc_pset(c, 5.51, 6.2, 6);
    assert_int_equal(at(c, 6, 6), 6);
    pc_pset(c, 1, 1, -1);        /* default colour: the foreground, 15 */
    assert_int_equal(at(c, 1, 1), 15);
    pc_preset(c, 1, 1, -1);      /* PRESET's default is the background */
    assert_int_equal(at(c, 1, 1), 0);
    assert_int_equal(count(c, 0), 64 - 3);
    assert_int_equal(pc_pset(c, 1, 1, 16), PC_EARG);
    assert_non_null(strstr(c->error, "colour 16 out of range 0..15"));
    assert_int_equal(pc_pset(c, NAN, 1, 1), PC_EARG);
    pc_canvas_free(c);
}

static void test_line_endpoints_and_direction(void **state) {
    (void)state;
    static const char *const shape[] = {
        "##......",
        "..##....",
        "....##..",
        "........"};
    pc_canvas *a = small(8, 4), *b = small(8, 4);
    pc_line(a, 0, 0, 5, 2, 1);
    pc_line(b, 5, 2, 0, 0, 1);
    assert_shape(a, shape);
    assert_shape(b, shape);
    assert_memory_equal(a->pixels, b->pixels, 32 * sizeof *a->pixels);
    /* the graphics cursor ends at the second point */
    assert_true(a->last_x == 5 && a->last_y == 2);
    /* a steep line, both directions */
    pc_canvas *s = small(3, 6), *t = small(3, 6);
    pc_line(s, 0, 0, 2, 5, 1);
    pc_line(t, 2, 5, 0, 0, 1);
    assert_memory_equal(s->pixels, t->pixels, 18 * sizeof *s->pixels);
    assert_int_equal(count(s, 1), 6);
    assert_int_equal(at(s, 0, 0), 1);
    assert_int_equal(at(s, 2, 5), 1);
    /* a single-point line is one pixel */
    pc_canvas *d = small(3, 3);
    pc_line(d, 1, 1, 1, 1, 2);
    assert_int_equal(count(d, 2), 1);
    pc_canvas_free(a); pc_canvas_free(b); pc_canvas_free(s); pc_canvas_free(t); pc_canvas_free(d);
}

static void test_boxes(void **state) {
    (void)state;
    static const char *const outline[] = {
        "......",
        ".####.",
        ".#..#.",
        ".####.",
        "......"};
    pc_canvas *c = small(6, 5);
    pc_box(c, 4, 3, 1, 1, 3, 0);     /* corners in any order */
    assert_shape(c, outline);
    assert_int_equal(count(c, 3), 10);
    pc_canvas *f = small(6, 5);
    pc_box(f, 1, 1, 4, 3, 3, 1);
    assert_int_equal(count(f, 3), 12);
    assert_int_equal(at(f, 2, 2), 3);
    assert_int_equal(f->nops, 1);
    assert_int_equal(f->ops[0].kind, PC_OP_FILLBOX);
    pc_canvas_free(c);
    pc_canvas_free(f);
}

static void test_circle_small_radii(void **state) {
    (void)state;
    pc_canvas *c = small(7, 7);
    pc_circle(c, 3, 3, 0, 2, NAN, NAN, NAN);
    assert_int_equal(count(c, 2), 1);
    assert_int_equal(at(c, 3, 3), 2);
    pc_canvas_free(c);

    static const char *const r1[] = {
        ".......", ".......", "...#...", "..#.#..", "...#...", ".......", "......."};
    c = small(7, 7);
    pc_circle(c, 3, 3, 1, 2, NAN, NAN, NAN);
    assert_shape(c, r1);
    pc_canvas_free(c);

    static const char *const r2[] = {
        ".......", "..###..", ".#...#.", ".#...#.", ".#...#.", "..###..", "......."};
    c = small(7, 7);
    pc_circle(c, 3, 3, 2, 2, NAN, NAN, NAN);
    assert_shape(c, r2);
    pc_canvas_free(c);
}

static void test_circle_radius5(void **state) {
    (void)state;
    static const char *const r5[] = {
        "....#####....",
        "...#.....#...",
        "..#.......#..",
        ".#.........#.",
        ".#.........#.",
        ".#.........#.",
        ".#.........#.",
        ".#.........#.",
        "..#.......#..",
        "...#.....#...",
        "....#####....",
        "............."};
    pc_canvas *c = small(13, 12);
    pc_circle(c, 6, 5, 5, 9, NAN, NAN, NAN);
    assert_shape(c, r5);
    assert_int_equal(count(c, 9), 28);
    assert_int_equal(c->ops[0].kind, PC_OP_ARC);
    assert_true(c->ops[0].flags & PC_ARC_FULL);
    pc_canvas_free(c);
}

/* Extent of the ink: min and max x and y. */
static void extent(const pc_canvas *c, int *x0, int *y0, int *x1, int *y1) {
    *x0 = *y0 = 1 << 30;
    *x1 = *y1 = -1;
    for (int y = 0; y < c->height; y++)
        for (int x = 0; x < c->width; x++)
            if (at(c, x, y)) {
                if (x < *x0) *x0 = x;
                if (x > *x1) *x1 = x;
                if (y < *y0) *y0 = y;
                if (y > *y1) *y1 = y;
            }
}

static void test_circle_aspect(void **state) {
    (void)state;
    int x0, y0, x1, y1;
    pc_canvas *c = small(41, 41);
    pc_circle(c, 20, 20, 10, 1, NAN, NAN, 0.5);     /* below 1: x radius 10, y radius 5 */
    extent(c, &x0, &y0, &x1, &y1);
    assert_int_equal(x0, 10); assert_int_equal(x1, 30);
    assert_int_equal(y0, 15); assert_int_equal(y1, 25);
    pc_canvas_free(c);
    c = small(41, 41);
    pc_circle(c, 20, 20, 10, 1, NAN, NAN, 2);       /* above 1: y radius 10, x radius 5 */
    extent(c, &x0, &y0, &x1, &y1);
    assert_int_equal(x0, 15); assert_int_equal(x1, 25);
    assert_int_equal(y0, 10); assert_int_equal(y1, 30);
    pc_canvas_free(c);
    c = small(41, 41);
    pc_circle(c, 20, 20, 4, 1, NAN, NAN, 5);        /* Stepanov ex. 34's sliver: 0.8 x 4 */
    extent(c, &x0, &y0, &x1, &y1);
    assert_int_equal(x1 - x0, 2);
    assert_int_equal(y1 - y0, 8);
    pc_canvas_free(c);
}

static void test_arcs_and_radii(void **state) {
    (void)state;
    pc_canvas *c = small(41, 41);
    /* a quarter arc from 0 to pi/2 lies in the upper-right quadrant (angles run
     * counter-clockwise, y is down on screen) */
    pc_circle(c, 20, 20, 10, 1, 0, PI / 2, NAN);
    for (int y = 0; y < 41; y++)
        for (int x = 0; x < 41; x++)
            if (at(c, x, y)) assert_true(x >= 20 && y <= 20);
    assert_int_equal(at(c, 30, 20), 1);
    assert_int_equal(at(c, 20, 10), 1);
    assert_int_equal(at(c, 10, 20), 0);
    assert_int_equal(at(c, 20, 20), 0);            /* no radii without negative angles */
    pc_canvas_free(c);

    c = small(41, 41);
    /* negative angles: the same arc plus radii from the centre to both ends */
    pc_circle(c, 20, 20, 10, 1, -PI / 2, -PI, NAN);
    assert_int_equal(at(c, 20, 20), 1);
    for (int i = 0; i <= 10; i++) {
        assert_int_equal(at(c, 20, 20 - i), 1);    /* radius up to pi/2 */
        assert_int_equal(at(c, 20 - i, 20), 1);    /* radius left to pi */
    }
    assert_int_equal(at(c, 13, 13), 1);            /* on the arc between them */
    assert_int_equal(at(c, 27, 27), 0);
    assert_true(c->ops[0].flags & PC_ARC_RADIUS0);
    assert_true(c->ops[0].flags & PC_ARC_RADIUS1);
    /* an arc that wraps through angle 0: from 3pi/2 to pi/2 is the right half */
    pc_canvas *w = small(41, 41);
    pc_circle(w, 20, 20, 10, 1, 3 * PI / 2, PI / 2, NAN);
    assert_int_equal(at(w, 30, 20), 1);
    assert_int_equal(at(w, 10, 20), 0);
    assert_int_equal(pc_circle(w, 20, 20, 10, 1, 7, 1, NAN), PC_EARG);
    assert_int_equal(pc_circle(w, 20, 20, -1, 1, NAN, NAN, NAN), PC_EARG);
    assert_non_null(strstr(w->error, "radius"));
    pc_canvas_free(c);
    pc_canvas_free(w);
}

static void test_paint_enclosed_region(void **state) {
    (void)state;
    pc_canvas *c = small(12, 10);
    pc_box(c, 2, 2, 9, 7, 15, 0);     /* outline: interior 6 x 4 */
    pc_pset(c, 0, 0, 4);
    assert_int_equal(pc_paint(c, 5, 5, 1, 15), PC_OK);
    assert_int_equal(count(c, 1), 24);
    assert_int_equal(count(c, 15), 24);   /* the border is intact */
    assert_int_equal(at(c, 0, 0), 4);     /* outside untouched */
    assert_int_equal(at(c, 1, 1), 0);
    /* the region is recorded as 4 spans of 6 pixels */
    const pc_op *op = &c->ops[c->nops - 1];
    assert_int_equal(op->kind, PC_OP_FILL);
    assert_int_equal(op->count, 4);
    for (uint32_t i = 0; i < op->count; i++) {
        const pc_span *s = &c->spans[op->first + i];
        assert_int_equal(s->x0, 3);
        assert_int_equal(s->x1, 8);
    }
    /* starting on the border does nothing */
    pc_paint(c, 2, 2, 3, 15);
    assert_int_equal(count(c, 3), 0);
    /* with border = paint colour (the default) the fill stops at its own colour */
    pc_canvas *d = small(12, 10);
    pc_circle(d, 6, 5, 3, 14, NAN, NAN, NAN);
    pc_paint(d, 6, 5, 14, -1);
    int inside = count(d, 14);
    assert_int_equal(at(d, 0, 0), 0);
    assert_int_equal(at(d, 6, 5), 14);
    assert_true(inside > 28 && inside < 50);
    pc_canvas_free(c);
    pc_canvas_free(d);
}

static void test_paint_leaks_through_gaps_but_not_other_colours(void **state) {
    (void)state;
    pc_canvas *c = small(10, 5);
    /* a wall of colour 2 across the canvas with a pixel of colour 3 in it */
    pc_line(c, 4, 0, 4, 4, 2);
    pc_pset(c, 4, 2, 3);
    pc_paint(c, 0, 0, 1, 2);               /* border 2: colour 3 is not a border */
    assert_int_equal(at(c, 9, 4), 1);      /* leaked through the gap */
    assert_int_equal(at(c, 4, 2), 1);
    assert_int_equal(count(c, 2), 4);
    pc_canvas_free(c);
}

static void test_clipping(void **state) {
    (void)state;
    pc_canvas *c = small(10, 10);
    assert_int_equal(pc_pset(c, -1, 5, 1), PC_OK);
    assert_int_equal(pc_pset(c, 10, 5, 1), PC_OK);
    assert_int_equal(pc_pset(c, 1e12, -1e12, 1), PC_OK);
    assert_int_equal(count(c, 1), 0);
    /* a diagonal from far outside to far outside crosses the whole canvas */
    pc_line(c, -1e7, -1e7, 1e7, 1e7, 2);
    for (int i = 0; i < 10; i++) assert_int_equal(at(c, i, i), 2);
    assert_int_equal(count(c, 2), 10);
    /* a line partly outside keeps its visible pixels exactly */
    pc_canvas *d = small(10, 10);
    pc_line(d, -5, 3, 20, 3, 3);
    assert_int_equal(count(d, 3), 10);
    pc_circle(d, 100, 100, 3, 4, NAN, NAN, NAN);
    pc_circle(d, 5, 5, 1e9, 4, NAN, NAN, NAN);
    assert_int_equal(count(d, 4), 0);
    pc_box(d, -100, -100, 100, 100, 5, 1);
    assert_int_equal(count(d, 5), 100);
    pc_canvas_free(c);
    pc_canvas_free(d);
}

static void test_window_y_up(void **state) {
    (void)state;
    pc_canvas *c = small(11, 11);
    assert_int_equal(pc_window(c, 0, 0, 10, 10, 0), PC_OK);
    pc_pset(c, 0, 0, 1);       /* world origin: bottom left */
    pc_pset(c, 10, 10, 2);     /* top right */
    pc_pset(c, 2, 7, 3);
    assert_int_equal(at(c, 0, 10), 1);
    assert_int_equal(at(c, 10, 0), 2);
    assert_int_equal(at(c, 2, 3), 3);
    assert_int_equal(pc_point(c, 2, 7), 3);
    /* corners in any order; WINDOW SCREEN keeps y down */
    pc_window(c, 10, 10, 0, 0, 1);
    pc_pset(c, 1, 2, 4);
    assert_int_equal(at(c, 1, 2), 4);
    /* a world twice as big: circle radius is measured along x */
    pc_window(c, -20, -20, 20, 20, 0);
    double sx, sy;
    pc_world_to_screen(c, 4, 4, &sx, &sy);
    assert_true(fabs(sx - 6) < 1e-12 && fabs(sy - 4) < 1e-12);
    assert_true(fabs(pc_world_xscale(c) - 0.25) < 1e-12);
    pc_window_reset(c);
    pc_pset(c, 3, 3, 5);
    assert_int_equal(at(c, 3, 3), 5);
    assert_int_equal(pc_window(c, 0, 0, 0, 5, 0), PC_EARG);
    pc_canvas_free(c);
}

/* pc_path_screen takes screen points as pc_path's world points become under WINDOW and VIEW:
 * the same pixels, the same display-list points, and the cursor at the world end point. */
static void test_path_screen(void **state) {
    (void)state;
    pc_canvas *a = small(21, 21), *b = small(21, 21);
    for (int k = 0; k < 2; k++) {
        pc_canvas *c = k ? b : a;
        assert_int_equal(pc_view(c, 2, 2, 18, 18, -1, -1, 0), PC_OK);
        assert_int_equal(pc_window(c, -1, -1, 1, 1, 0), PC_OK);
    }
    const double w[8] = {-1, -1, 0.5, -0.25, 0.25, 1, -1, 0.5};
    double s[8];
    for (int i = 0; i < 4; i++) pc_world_to_screen(b, w[2 * i], w[2 * i + 1], &s[2 * i], &s[2 * i + 1]);
    const uint8_t verbs[4] = {PC_PATH_MOVE, PC_PATH_LINE, PC_PATH_LINE, PC_PATH_MOVE};
    assert_int_equal(pc_path(a, 4, w, verbs, 4, 1, 3), PC_OK);
    assert_int_equal(pc_path_screen(b, 4, s, verbs, 4, 1, 3), PC_OK);
    assert_memory_equal(a->pixels, b->pixels, sizeof(uint16_t) * 21 * 21);
    assert_true(count(b, 3) > 20);
    assert_int_equal(at(b, 2, 18), 3);              /* the world corner (-1, -1) */
    assert_int_equal(b->npts, 4);
    for (int i = 0; i < 4; i++) {
        assert_true(b->pts[i].x == s[2 * i] && b->pts[i].y == s[2 * i + 1]);
        assert_int_equal(b->tags[i], a->tags[i]);
    }
    assert_true(fabs(b->last_x + 1) < 1e-12 && fabs(b->last_y - 0.5) < 1e-12);
    const double bad[4] = {0, 0, NAN, 1};
    assert_int_equal(pc_path_screen(b, 2, bad, NULL, 0, 0, 3), PC_EARG);
    assert_non_null(strstr(b->error, "finite"));
    pc_canvas_free(a);
    pc_canvas_free(b);
}

static void test_view_and_point(void **state) {
    (void)state;
    pc_canvas *c = small(10, 10);
    assert_int_equal(pc_view(c, 2, 2, 5, 5, -1, -1, 0), PC_OK);
    pc_pset(c, 0, 0, 1);               /* relative to the view */
    assert_int_equal(at(c, 2, 2), 1);
    pc_line(c, 0, 1, 9, 1, 2);         /* clipped to the view */
    assert_int_equal(count(c, 2), 4);
    assert_int_equal(pc_point(c, 0, 0), 1);
    assert_int_equal(pc_point(c, 8, 8), -1);   /* outside the view */
    pc_cls(c);                          /* clears only the view */
    assert_int_equal(count(c, 0), 100);
    pc_view_reset(c);
    pc_view(c, 1, 1, 8, 8, 6, 7, 1);   /* VIEW SCREEN with fill and border */
    assert_int_equal(at(c, 0, 0), 7);
    assert_int_equal(at(c, 4, 4), 6);
    pc_pset(c, 1, 1, 3);               /* absolute coordinates */
    assert_int_equal(at(c, 1, 1), 3);
    assert_int_equal(pc_view(c, 0, 0, 10, 10, -1, -1, 0), PC_EARG);
    pc_canvas_free(c);
}

/* No limit on VIEW changes (issue 15, item 5: a 16-bit clip index lost the drawing after
 * 65,535): 100,000 views, each drawn in, are all recorded, each op in its own; VIEWs with
 * nothing drawn in them cost nothing; the op header stays 8 bytes. */
static void test_view_no_limit(void **state) {
    (void)state;
    assert_int_equal(sizeof(pc_op), 80);
    pc_canvas *c = small(10, 10);
    for (int i = 0; i < 100000; i++) {
        assert_int_equal(pc_view(c, i % 2, 0, 5 + i % 2, 5, -1, -1, 0), PC_OK);
        assert_int_equal(pc_pset(c, 0, 0, 1 + i % 2), PC_OK);   /* relative to the view */
    }
    assert_int_equal(c->nclips, 100000);   /* one per view (the full screen was not drawn in) */
    assert_int_equal(c->nops, 100000);
    for (size_t i = 0; i < c->nops; i += 9973) {
        size_t k = pc_op_clip(c, i);
        assert_int_equal(k, i);
        assert_int_equal(c->clips[k].r.x0, (int)(i % 2));
        assert_int_equal(c->ops[i].color, 1 + i % 2);
    }
    assert_int_equal(at(c, 0, 0), 1);                   /* the last dot in view 0: (0, 0) */
    assert_int_equal(at(c, 1, 0), 2);                   /* the last in view 1: (1, 0) */
    /* views nobody draws in replace one another */
    for (int i = 0; i < 1000; i++) pc_view(c, 2 + i % 3, 1, 7, 7, -1, -1, 0);
    assert_int_equal(c->nclips, 100001);
    pc_view(c, 1, 0, 6, 5, -1, -1, 0);                  /* back to the one before: dropped */
    assert_int_equal(c->nclips, 100000);
    pc_pset(c, 1, 1, 3);
    assert_int_equal(pc_op_clip(c, c->nops - 1), c->nclips - 1);
    assert_int_equal(c->ops[c->nops - 1].count, 1);     /* the view of the run before */
    pc_canvas_free(c);
}

/* Dots of one colour share one DOTS operation (16 bytes a dot); a new colour, another
 * operation or a VIEW change starts a new run. */
static void test_dot_runs(void **state) {
    (void)state;
    pc_canvas *c = small(10, 10);
    for (int i = 0; i < 5; i++) pc_pset(c, i, 1, 2);
    pc_preset(c, 7.25, 3.5, 2);        /* same colour: same run, fractional position kept */
    assert_int_equal(c->nops, 1);
    assert_int_equal(c->ops[0].kind, PC_OP_DOTS);
    assert_int_equal(c->ops[0].first, 0);
    assert_int_equal(c->ops[0].count, 6);
    assert_true(c->dots[5].x == 7.25 && c->dots[5].y == 3.5);
    pc_pset(c, 1, 2, 3);               /* new colour */
    pc_line(c, 0, 0, 1, 1, 3);
    pc_pset(c, 2, 2, 3);               /* after a line: a new run */
    pc_view(c, 1, 1, 8, 8, -1, -1, 0);
    pc_pset(c, 3, 3, 3);               /* new clip: a new run */
    assert_int_equal(c->nops, 5);
    assert_int_equal(c->ops[1].count, 1);
    assert_int_equal(c->ops[3].first, 7);
    assert_int_equal(pc_op_clip(c, 4), c->nclips - 1);
    assert_int_equal(c->ndots, 9);
    uint64_t v = c->version;
    pc_pset(c, 4, 4, 3);               /* appending still counts as a change of the picture */
    assert_true(c->version > v);
    pc_canvas_free(c);
}

static void test_cls_and_display_list(void **state) {
    (void)state;
    pc_canvas *c = small(10, 10);
    assert_false(c->dirty);
    pc_pset(c, 1, 1, 1);
    pc_line(c, 0, 0, 3, 3, 2);
    pc_circle(c, 5, 5, 2, 3, NAN, NAN, NAN);
    assert_true(c->dirty);
    assert_int_equal(c->nops, 3);
    assert_int_equal(c->ops[0].kind, PC_OP_DOTS);
    assert_int_equal(c->ops[1].kind, PC_OP_LINE);
    assert_true(c->ops[1].x2 == 3 && c->ops[1].y2 == 3);
    pc_cls(c);
    assert_int_equal(c->nops, 0);
    assert_int_equal(c->ndots, 0);
    assert_int_equal(count(c, 0), 100);
    /* after CLS the cursor is the centre of the screen */
    assert_true(c->last_x == 4.5 && c->last_y == 4.5);
    pc_color(c, 9, 4);
    assert_int_equal(c->paper, 0);      /* COLOR's background waits for the next CLS */
    pc_cls(c);
    assert_int_equal(c->paper, 4);
    assert_int_equal(count(c, 4), 100);
    assert_int_equal(c->nops, 1);
    assert_int_equal(c->ops[0].kind, PC_OP_CLEAR);
    pc_pset(c, 0, 0, -1);
    assert_int_equal(at(c, 0, 0), 9);
    assert_int_equal(pc_color(c, 16, -1), PC_EARG);
    pc_rgb red = {255, 0, 0};
    assert_int_equal(pc_palette(c, 9, red), PC_OK);
    assert_int_equal(c->palette[9].r, 255);
    pc_palette_reset(c);
    assert_int_equal(c->palette[9].r, 0x55);
    pc_canvas_free(c);
}

/* Far end points.  A cut end is computed from the nearer original end, so a segment from the
 * screen to 1e300 keeps its exact pixels; one crossing the screen between two ends that are
 * both too far to place it to the pixel is an error, not a guess. */
static void test_lines_to_far_away(void **state) {
    (void)state;
    pc_canvas *c = small(10, 10);
    assert_int_equal(pc_line(c, -1e300, -1e300, 5, 5, 2), PC_OK);
    for (int i = 0; i <= 5; i++) assert_int_equal(at(c, i, i), 2);
    assert_int_equal(count(c, 2), 6);
    assert_int_equal(pc_line(c, 7, 9, 7, -1e20, 3), PC_OK);
    for (int y = 0; y < 10; y++) assert_int_equal(at(c, 7, y), 3);
    assert_int_equal(count(c, 3), 10);
    pc_canvas *d = small(10, 10);
    assert_int_equal(pc_line(d, -1e14, -1e14, 1e14, 1e14, 4), PC_OK);
    for (int i = 0; i < 10; i++) assert_int_equal(at(d, i, i), 4);
    assert_int_equal(count(d, 4), 10);
    assert_int_equal(pc_line(d, -1e308, -1e308, 1e308, 1e308, 5), PC_EARG);
    assert_non_null(strstr(d->error, "line: the segment's ends lie too far out (beyond 1e+15"));
    assert_int_equal(pc_line(d, -1e20, 1e20, 1e20, -1e20, 5), PC_EARG);
    assert_int_equal(count(d, 5), 0);
    assert_int_equal(d->nops, 1);
    /* far ends along an axis, or on a shallow slope with small y, place the line exactly:
     * y = 3 + 4 (x + 1e20) / 2e20 is 5.0000 across the screen */
    pc_canvas *f = small(10, 10);
    assert_int_equal(pc_line(f, -1.7e308, 2, 1.7e308, 2, 7), PC_OK);
    assert_int_equal(pc_line(f, 8, -1e300, 8, 1e300, 8), PC_OK);
    assert_int_equal(pc_line(f, -1e20, 3, 1e20, 7, 9), PC_OK);
    for (int i = 0; i < 10; i++) {
        assert_int_equal(at(f, i, 5), 9);                  /* drawn last */
        if (i != 5) assert_int_equal(at(f, 8, i), 8);
        if (i != 8) assert_int_equal(at(f, i, 2), 7);
    }
    assert_int_equal(count(f, 7), 9);
    assert_int_equal(count(f, 8), 9);
    assert_int_equal(count(f, 9), 10);
    pc_canvas_free(f);
    /* both ends far but the segment nowhere near the screen: silently clipped */
    assert_int_equal(pc_line(d, -1e300, -1e20, 1e300, -1e20, 5), PC_OK);
    /* the clipper itself survives an extent that overflows to infinity */
    double x0 = -1e308, y0 = 0, x1 = 1e308, y1 = 0;
    assert_int_equal(pc_clip_segment(&x0, &y0, &x1, &y1, 0, -1, 10, 1), 1);
    assert_true(isfinite(x0) && isfinite(x1) && y0 == 0 && y1 == 0);
    /* a radius line of a circle far larger than the screen is a line like any other */
    pc_canvas *e = small(10, 10);
    assert_int_equal(pc_circle(e, 5, 5, 1e12, 6, -PI / 2, -PI, NAN), PC_OK);
    for (int i = 0; i <= 5; i++) {
        assert_int_equal(at(e, 5, i), 6);
        assert_int_equal(at(e, i, 5), 6);
    }
    assert_int_equal(count(e, 6), 11);
    pc_canvas_free(c);
    pc_canvas_free(d);
    pc_canvas_free(e);
}

/* Finite world coordinates that WINDOW maps beyond any double are an error naming the
 * statement, never a pixel put somewhere arbitrary; so is a window too large to map. */
static void test_window_overflow_is_an_error(void **state) {
    (void)state;
    pc_canvas *c = small(10, 10);
    assert_int_equal(pc_window(c, -1e308, -1e308, 1e308, 1e308, 0), PC_EARG);
    assert_non_null(strstr(c->error, "too large"));
    assert_int_equal(pc_window(c, 0, 0, 1, 1, 0), PC_OK);
    assert_int_equal(pc_pset(c, 1e308, 0, 1), PC_EARG);
    assert_non_null(strstr(c->error, "pset: coordinates (1e+308, 0) are too far outside the window"));
    assert_int_equal(pc_line(c, 0, 0, 1e308, 1e308, 1), PC_EARG);
    assert_non_null(strstr(c->error, "line:"));
    assert_int_equal(pc_box(c, 0, 0, -1e308, 1, 1, 1), PC_EARG);
    assert_int_equal(pc_paint(c, 1e308, 0, 1, -1), PC_EARG);
    assert_int_equal(pc_circle(c, 0.5, 0.5, 1e308, 1, NAN, NAN, NAN), PC_EARG);
    assert_non_null(strstr(c->error, "circle: radius"));
    assert_int_equal(pc_point(c, 1e308, 0), -1);
    assert_int_equal(count(c, 0), 100);          /* nothing was drawn */
    assert_int_equal(c->nops, 0);
    /* the largest coordinates that do map still clip silently */
    assert_int_equal(pc_pset(c, 1e300, -1e300, 1), PC_OK);
    assert_int_equal(count(c, 0), 100);
    pc_canvas_free(c);
}

/* A circle far larger than the screen: the visible part of its outline is exact.  Centre
 * (-99995, 5), radius 100000 on a 10x10 canvas: the rightmost point is (5, 5) and over rows
 * 0..9 the outline stays within 0.000125 px of column 5 (x = -99995 + sqrt(1e10 - dy^2)). */
/* An arc's end lights the pixel its angle falls in, at either end: QBasic programs give
 * pi/2 as 1.5708 (3.7e-6 past it), and CIRCLE (320,240),100,15,1.5708,3.1416 must light the
 * top pixel (320,140) as CIRCLE ..., 0, 1.5708 does; a pixel past the end stays dark. */
static void test_arc_end_pixels(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_circle(c, 320, 240, 100, 15, 1.5708, 3.1416, NAN), PC_OK);
    assert_int_equal(at(c, 320, 140), 15);         /* the first pixel, at about pi/2 */
    assert_int_equal(at(c, 220, 240), 15);         /* the last, at about pi */
    assert_int_equal(at(c, 321, 140), 0);          /* before the start: clockwise of it */
    assert_int_equal(at(c, 220, 241), 0);          /* past the end */
    pc_canvas_free(c);
    c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_circle(c, 320, 240, 100, 15, 0, 1.5708, NAN), PC_OK);
    assert_int_equal(at(c, 320, 140), 15);
    assert_int_equal(at(c, 420, 240), 15);
    assert_int_equal(at(c, 319, 140), 0);
    assert_int_equal(at(c, 420, 241), 0);
    pc_canvas_free(c);
}

static void test_huge_circle_visible_arc(void **state) {
    (void)state;
    pc_canvas *c = small(10, 10);
    assert_int_equal(pc_circle(c, -99995, 5, 100000, 4, NAN, NAN, NAN), PC_OK);
    for (int y = 0; y < 10; y++) assert_int_equal(at(c, 5, y), 4);
    assert_int_equal(count(c, 4), 10);
    /* ten times larger and off to the right: the leftmost point is (4, 5) */
    pc_canvas *d = small(10, 10);
    assert_int_equal(pc_circle(d, 1000004, 5, 1000000, 4, NAN, NAN, NAN), PC_OK);
    for (int y = 0; y < 10; y++) assert_int_equal(at(d, 4, y), 4);
    assert_int_equal(count(d, 4), 10);
    /* an arc of it: the upper half (0..pi) keeps rows 0..5 only */
    pc_canvas *e = small(10, 10);
    pc_circle(e, -99995, 5, 100000, 4, 0, PI, NAN);
    for (int y = 0; y <= 5; y++) assert_int_equal(at(e, 5, y), 4);
    assert_int_equal(count(e, 4), 6);
    /* a radius beyond what a pixel grid can hold passing through the screen is an error */
    assert_int_equal(pc_circle(e, -1e16, 5, 1e16 + 5, 4, NAN, NAN, NAN), PC_EARG);
    assert_non_null(strstr(e->error, "circle: radius"));
    /* far away and small: nothing to draw, no error */
    assert_int_equal(pc_circle(e, 1e300, 5, 3, 4, NAN, NAN, NAN), PC_OK);
    pc_canvas_free(c);
    pc_canvas_free(d);
    pc_canvas_free(e);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_screen_modes),
        cmocka_unit_test(test_pset_rounding),
        cmocka_unit_test(test_line_endpoints_and_direction),
        cmocka_unit_test(test_boxes),
        cmocka_unit_test(test_circle_small_radii),
        cmocka_unit_test(test_circle_radius5),
        cmocka_unit_test(test_circle_aspect),
        cmocka_unit_test(test_arcs_and_radii),
        cmocka_unit_test(test_paint_enclosed_region),
        cmocka_unit_test(test_paint_leaks_through_gaps_but_not_other_colours),
        cmocka_unit_test(test_clipping),
        cmocka_unit_test(test_path_screen),
        cmocka_unit_test(test_window_y_up),
        cmocka_unit_test(test_view_and_point),
        cmocka_unit_test(test_view_no_limit),
        cmocka_unit_test(test_dot_runs),
        cmocka_unit_test(test_cls_and_display_list),
        cmocka_unit_test(test_lines_to_far_away),
        cmocka_unit_test(test_window_overflow_is_an_error),
        cmocka_unit_test(test_huge_circle_visible_arc),
        cmocka_unit_test(test_arc_end_pixels),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
