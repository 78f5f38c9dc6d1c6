/* Engineering-drawing furniture (furniture.h): markers, arrows, dimension lines with the
 * measured length, angle marks with the angle (and the right-angle square), ticks, ISO
 * hatching, centre lines: their pixels, their numbers and their errors. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"
#include "furniture.h"
#include "layout.h"

static int at(const pc_canvas *c, int x, int y) { return c->pixels[y * c->width + x]; }

/* The strings of the TEXT ops, in order, joined by '|'. */
static void texts(const pc_canvas *c, char *out, size_t n) {
    out[0] = 0;
    for (size_t i = 0; i < c->nops; i++)
        if (c->ops[i].kind == PC_OP_TEXT) {
            strncat(out, c->text + c->ops[i].first, c->ops[i].count < n - strlen(out) - 2 ? c->ops[i].count : 0);
            strcat(out, "|");
        }
}

static void test_marks(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_mark(c, 100, 100, PC_MARK_DOT, 5, 14), PC_OK);
    for (int d = -2; d <= 2; d++) {   /* a disc of diameter 5: the centres within 2.5 px */
        assert_int_equal(at(c, 100 + d, 100), 14);
        assert_int_equal(at(c, 100, 100 + d), 14);
    }
    assert_int_equal(at(c, 103, 100), 0);
    assert_int_equal(at(c, 102, 102), 0);   /* 2.83 px off: outside */
    assert_int_equal(pc_mark(c, 200, 100, PC_MARK_OPEN, 9, 14), PC_OK);
    assert_int_equal(at(c, 200, 100), 0);   /* open: nothing in the middle */
    assert_int_equal(at(c, 204, 100) + at(c, 205, 100) > 0, 1);
    assert_int_equal(pc_mark(c, 300, 100, PC_MARK_PLUS, 9, 14), PC_OK);
    assert_int_equal(at(c, 300, 96), 14);
    assert_int_equal(at(c, 304, 100), 14);
    assert_int_equal(at(c, 302, 102), 0);
    assert_int_equal(pc_mark(c, 400, 100, PC_MARK_SQUARE, 8, 14), PC_OK);
    assert_int_equal(at(c, 396, 96), 14);
    assert_int_equal(at(c, 400, 100), 0);
    assert_int_equal(pc_mark(c, 1, 1, 9, 5, 14), PC_EARG);
    assert_int_equal(pc_mark(c, 1, 1, PC_MARK_DOT, 0, 14), PC_EARG);
    assert_string_equal(c->error, "mark: size must be 1..200 pixels, got 0");
    assert_int_equal(pc_mark(c, NAN, 1, PC_MARK_DOT, 3, 14), PC_EARG);
    pc_canvas_free(c);
}

static void test_arrow(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_arrow(c, 100, 200, 300, 200, PC_ARROW_END, 10, 12), PC_OK);
    assert_int_equal(at(c, 150, 200), 12);   /* shaft */
    assert_int_equal(at(c, 299, 200), 12);   /* the tip, filled */
    assert_int_equal(at(c, 292, 202), 12);   /* the head is 6 px wide at its base */
    assert_int_equal(at(c, 292, 204), 0);
    assert_int_equal(at(c, 110, 202), 0);    /* no head at the start */
    assert_int_equal(pc_arrow(c, 5, 5, 5, 5, PC_ARROW_END, 10, 12), PC_EARG);
    assert_string_equal(c->error, "arrow: the two points coincide: no direction for the head");
    pc_canvas_free(c);
}

/* A dimension of AB = (1, 1)-(4, 5) under a window with equal units writes "5"; its
 * dimension line runs parallel to AB, offset pixels to the left. */
static void test_dimension(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    double len = 0;
    char s[256];
    assert_int_equal(pc_dimension(c, 100, 300, 300, 300, 20, NULL, 15, &len), PC_OK);
    assert_true(len == 200);
    texts(c, s, sizeof s);
    assert_string_equal(s, "200|");
    assert_int_equal(at(c, 200, 280), 15);   /* the dimension line, 20 px above (left of A->B) */
    assert_int_equal(at(c, 100, 290), 15);   /* the extension line from A */
    assert_int_equal(at(c, 100, 299), 0);    /* 2 px clear of the object */
    assert_int_equal(at(c, 101, 280), 15);   /* a head at each end */
    assert_int_equal(at(c, 299, 280), 15);
    /* the text stands above the line's middle (anchor N) */
    const pc_op *t = &c->ops[c->nops - 1];
    assert_int_equal(t->kind, PC_OP_TEXT);
    assert_int_equal(t->flags, PC_ANCHOR_N);
    assert_true(t->y1 + 16 <= 280 - 2);
    pc_canvas_free(c);

    c = pc_canvas_new(640, 480, 16);
    pc_window(c, 0, 0, 8, 6, 0);   /* 80 px per unit on both axes */
    assert_int_equal(pc_dimension(c, 1, 1, 4, 5, -15, NULL, 15, &len), PC_OK);
    assert_true(fabs(len - 5) < 1e-12);
    texts(c, s, sizeof s);
    assert_string_equal(s, "5|");
    assert_int_equal(pc_dimension(c, 1, 1, 4, 5, 15, "L", 15, NULL), PC_OK);
    texts(c, s, sizeof s);
    assert_string_equal(s, "5|L|");
    assert_int_equal(pc_dimension(c, 1, 1, 1, 1, 15, NULL, 15, NULL), PC_EARG);
    assert_string_equal(c->error, "dimension: the two points coincide: nothing to measure");
    pc_canvas_free(c);
}

/* The PATH ops of r after op `from` with n points, in order. */
static const pc_op *nth_path(const pc_canvas *r, size_t from, uint32_t n, int k) {
    for (size_t i = from; i < r->nops; i++)
        if (r->ops[i].kind == PC_OP_PATH && r->ops[i].count == n && k-- == 0) return &r->ops[i];
    return NULL;
}

/* In a figure framed when written, a dimension, an angle mark, a centre line and a hatch are
 * drawn once the frame is known: their pixel sizes (offset, gap, square, overshoot, spacing)
 * come out in the frame's pixels, their numbers are the world's. */
static void test_furniture_in_framed_figure(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    c->figure.on = c->figure.frame = 1;
    pc_line(c, 0, 0, 4, 0, 15);   /* world units: legs of a 4 x 3 right triangle, y up */
    pc_line(c, 0, 0, 0, 3, 15);
    double len = 0, ang = 0;
    size_t nl = 99;
    assert_int_equal(pc_dimension(c, 0, 0, 4, 0, -20, NULL, 15, &len), PC_OK);
    assert_true(len == 4);
    assert_int_equal(pc_angle_mark(c, 4, 0, 0, 0, 0, 3, 20, NULL, 15, &ang), PC_OK);
    assert_true(fabs(ang - M_PI / 2) < 1e-15);
    assert_int_equal(pc_centre_line(c, 0, 1.5, 4, 1.5, 10, 15), PC_OK);
    assert_int_equal(pc_hatch(c, 4, (double[]){1, 1, 2, 1, 2, 2, 1, 2}, 8, 45, 15, &nl), PC_OK);
    assert_int_equal(c->nops, 2);          /* kept for the frame, not drawn yet */
    assert_int_equal(c->ndeferred, 4);
    const pc_canvas *r = pc_layout_resolve(c);
    assert_non_null(r);
    const pc_op *h = &r->ops[0], *v = &r->ops[1];
    double m = PC_FIT_MARGIN, ox = h->x1, oy = h->y1, ex = h->x2, s = (479 - 2 * m) / 3;
    assert_true(fabs(oy - (479 - m)) < 1e-9 && fabs(v->y2 - m) < 1e-9);   /* framed as ever */
    /* the dimension: extension lines from 2 px under the leg to 3 px past the line 20 px under */
    const pc_op *e1 = nth_path(r, 2, 2, 0), *e2 = nth_path(r, 2, 2, 1), *shaft = nth_path(r, 2, 2, 2);
    assert_non_null(shaft);
    const pc_xy *p = &r->pts[e1->first];
    assert_true(fabs(p[0].x - ox) < 1e-9 && fabs(p[0].y - (oy + 2)) < 1e-9 && fabs(p[1].y - (oy + 23)) < 1e-9);
    assert_true(fabs(r->pts[e2->first].x - ex) < 1e-9);
    p = &r->pts[shaft->first];
    assert_true(fabs(p[0].y - (oy + 20)) < 1e-9 && fabs(p[1].y - (oy + 20)) < 1e-9);
    char t[64];
    texts(r, t, sizeof t);
    assert_string_equal(t, "4|90\xc2\xb0|");   /* the world's length and angle */
    /* the right-angle square: 0.7 of 20 px along each side from the vertex */
    const pc_op *sq = nth_path(r, 2, 3, 0);
    assert_non_null(sq);
    p = &r->pts[sq->first];
    assert_true(fabs(p[0].x - (ox + 14)) < 1e-9 && fabs(p[0].y - oy) < 1e-9);
    assert_true(fabs(p[2].x - ox) < 1e-9 && fabs(p[2].y - (oy - 14)) < 1e-9);
    /* the centre line: 10 px past each end, at the middle height, dashed */
    const pc_op *cl = NULL;
    for (int k = 0; (cl = nth_path(r, 2, 2, k)) && fabs(r->pts[cl->first].y - (oy - 1.5 * s)) > 1e-6; k++) {}
    assert_non_null(cl);
    assert_true(fabs(r->pts[cl->first].x - (ox - 10)) < 1e-9 && fabs(r->pts[cl->first + 1].x - (ex + 10)) < 1e-9);
    assert_int_equal(r->pens[cl->pen].ndash, 4);
    /* the hatch: 45 degree lines 8 px apart across (the frame's pixels, not 8 world units) */
    size_t first = (size_t)(cl - r->ops) + 1, nh = 0;
    double prev = NAN;
    for (size_t i = first; i < r->nops; i++) {
        if (r->ops[i].kind != PC_OP_PATH) continue;
        const pc_xy *q = &r->pts[r->ops[i].first];
        double across = (q[0].x + q[0].y) * sqrt(0.5);   /* nr = (sin 45, cos 45) */
        if (nh++) assert_true(fabs(across - prev - 8) < 1e-6 || fabs(prev - across - 8) < 1e-6);
        prev = across;
    }
    assert_true(nh >= (size_t)floor(s * sqrt(2) / 8) - 1 && nh <= (size_t)ceil(s * sqrt(2) / 8) + 1);
    pc_layout_release(c, r);
    assert_int_equal(c->ndeferred, 4);     /* the canvas keeps them: each write frames its own */
    /* fit{} on the canvas itself draws them and lets them go */
    assert_int_equal(pc_fit(c, 12, PC_FIT_EQUAL), PC_OK);
    assert_int_equal(c->ndeferred, 0);
    assert_true(c->nops > 10);
    assert_int_equal(pc_dimension(c, 0, 0, 4, 0, -20, NULL, 15, NULL), PC_OK);
    assert_int_equal(c->ndeferred, 0);     /* framed now (a window): drawn at once */
    pc_canvas_free(c);
    c = pc_canvas_new(640, 480, 16);
    c->figure.on = c->figure.frame = 1;
    assert_int_equal(pc_dimension(c, 0, 0, 4, 0, -20, NULL, 15, NULL), PC_OK);
    assert_int_equal(c->ndeferred, 1);
    pc_cls(c);                              /* a full CLS forgets them with the rest */
    assert_int_equal(c->ndeferred, 0);
    assert_int_equal(pc_centre_line(c, 0, 0, 4, 0, 5, 15), PC_OK);
    pc_canvas_free(c);                      /* and freeing the canvas frees them */
}

static void test_angle_mark(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    double th = 0;
    char s[256];
    /* 45 degrees on the screen (y down: B is up and to the right of O) */
    assert_int_equal(pc_angle_mark(c, 200, 100, 100, 100, 200, 0, 30, NULL, 15, &th), PC_OK);
    assert_true(fabs(th - M_PI / 4) < 1e-15);
    assert_int_equal(at(c, 130, 100), 15);   /* the arc starts on OA at radius 30 */
    assert_int_equal(at(c, 121, 79), 15);    /* and ends on OB: (100 + 30 cos 45, 100 - 30 sin 45) */
    /* a right angle: the square of side 21 (0.7 r), no arc */
    assert_int_equal(pc_angle_mark(c, 400, 300, 300, 300, 300, 200, 30, NULL, 15, &th), PC_OK);
    assert_true(fabs(th - M_PI / 2) < 1e-15);
    assert_int_equal(at(c, 321, 290), 15);   /* its side parallel to OB */
    assert_int_equal(at(c, 310, 279), 15);   /* its side parallel to OA */
    assert_int_equal(at(c, 330, 300), 0);    /* no arc at radius 30 */
    texts(c, s, sizeof s);
    assert_string_equal(s, "45\xc2\xb0|90\xc2\xb0|");
    /* measured in world units: a window with unequal units keeps the world's 90 */
    pc_window(c, 0, 0, 1, 10, 0);
    assert_int_equal(pc_angle_mark(c, 0.5, 5, 0.2, 5, 0.2, 8, 20, "phi", 15, &th), PC_OK);
    assert_true(fabs(th - M_PI / 2) < 1e-15);
    assert_int_equal(pc_angle_mark(c, 0.2, 5, 0.2, 5, 0.2, 8, 20, NULL, 15, NULL), PC_EARG);
    assert_string_equal(c->error, "angle_mark: a side has no length (A or B is the vertex O)");
    pc_canvas_free(c);
}

static void test_ticks_hatch_centre(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_ticks(c, 100, 100, 200, 100, 2, 8, 15), PC_OK);
    assert_int_equal(at(c, 148, 96), 15);   /* ticks 3 px apart about the middle: x = 148.5, 151.5 */
    assert_int_equal(at(c, 150, 96), 0);
    assert_int_equal(pc_ticks(c, 100, 100, 200, 100, 6, 8, 15), PC_EARG);

    /* ISO hatching of a 100 x 100 square at 45 degrees, 10 px apart: across the hatch the
     * square spans t = (x + y) / sqrt 2 = 424.3 .. 565.7, so 14 lines (t = 430 .. 560), every
     * pixel of them inside the square */
    double sq[8] = {300, 300, 400, 300, 400, 400, 300, 400};
    size_t nl = 0;
    assert_int_equal(pc_hatch(c, 4, sq, 10, 45, 9, &nl), PC_OK);
    assert_int_equal(nl, 14);
    int inside = 0;
    for (int y = 0; y < 480; y++)
        for (int x = 0; x < 640; x++)
            if (at(c, x, y) == 9) {
                assert_true(x >= 300 && x <= 400 && y >= 300 && y <= 400);
                inside++;
            }
    /* the lines' total length is the area over the spacing, 1000 px; a 45-degree line has one
     * pixel per sqrt 2 of length: about 707, one more at each line's ends */
    assert_true(inside >= 700 && inside <= 730);
    /* horizontal hatching at spacing 10: the lines at y = 300 .. 390 */
    pc_canvas_free(c);
    c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_hatch(c, 4, sq, 10, 0, 9, &nl), PC_OK);
    assert_int_equal(nl, 10);
    assert_int_equal(at(c, 350, 310), 9);
    assert_int_equal(at(c, 350, 315), 0);
    assert_int_equal(pc_hatch(c, 2, sq, 10, 0, 9, &nl), PC_EARG);

    /* the centre line: long dash 12, gap 3, dot 2, gap 3 from the extended start */
    assert_int_equal(pc_centre_line(c, 110, 450, 200, 450, 10, 15), PC_OK);
    char got[21] = {0};
    for (int i = 0; i < 20; i++) got[i] = at(c, 100 + i, 450) == 15 ? '#' : '.';
    assert_string_equal(got, "############...##...");
    assert_int_equal(c->pens[c->pen].ndash, 0);   /* the pen is restored */
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_marks),
        cmocka_unit_test(test_arrow),
        cmocka_unit_test(test_dimension),
        cmocka_unit_test(test_furniture_in_framed_figure),
        cmocka_unit_test(test_angle_mark),
        cmocka_unit_test(test_ticks_hatch_centre),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
