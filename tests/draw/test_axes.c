/* Axes (axes.h): ticks at round numbers, their labels, arrows, the grid; legends. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"
#include "axes.h"

static void texts(const pc_canvas *c, char *out, size_t n) {
    out[0] = 0;
    for (size_t i = 0; i < c->nops; i++)
        if (c->ops[i].kind == PC_OP_TEXT && strlen(out) + c->ops[i].count + 2 < n) {
            strncat(out, c->text + c->ops[i].first, c->ops[i].count);
            strcat(out, "|");
        }
}

static void test_nice_ticks(void **state) {
    (void)state;
    double a, s;
    int n;
    assert_int_equal(pc_nice_ticks(0, 10, 5, &a, &s, &n), PC_OK);
    assert_true(a == 0 && s == 2 && n == 6);
    assert_int_equal(pc_nice_ticks(0.13, 0.97, 5, &a, &s, &n), PC_OK);
    assert_true(fabs(a - 0.2) < 1e-15 && fabs(s - 0.2) < 1e-15 && n == 4);
    assert_int_equal(pc_nice_ticks(-3.7, 12, 8, &a, &s, &n), PC_OK);
    assert_true(a == -2 && s == 2 && n == 8);
    assert_int_equal(pc_nice_ticks(0, 1, 10, &a, &s, &n), PC_OK);
    assert_true(a == 0 && fabs(s - 0.1) < 1e-15 && n == 11);
    assert_int_equal(pc_nice_ticks(-250, 250, 4, &a, &s, &n), PC_OK);
    assert_true(a == -200 && s == 100 && n == 5);
    assert_int_equal(pc_nice_ticks(1, 1, 4, &a, &s, &n), PC_EARG);
}

static void test_axes(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_window(c, -1, -1, 11, 6, 0);
    pc_axes_spec a = {0, 10, 0, 5, 0, 0, 5, 1, 1, 0, -1};
    int nt = 0;
    assert_int_equal(pc_axes(c, &a, 15, &nt), PC_OK);
    assert_int_equal(nt, 12);
    char s[256];
    texts(c, s, sizeof s);
    assert_string_equal(s, "2|4|6|8|10|1|2|3|4|5|");
    /* the x axis arrow at world (10, 0), screen (586.75, 342.4): its head filled 3 px back */
    double sx, sy;
    pc_world_to_screen(c, 10, 0, &sx, &sy);
    assert_int_equal(c->pixels[(long)nearbyint(sy) * 640 + (long)nearbyint(sx) - 3], 15);
    /* a tick at x = 4 reaches 3 px below the axis */
    pc_world_to_screen(c, 4, 0, &sx, &sy);
    assert_int_equal(c->pixels[((long)nearbyint(sy) + 3) * 640 + (long)nearbyint(sx)], 15);
    /* the labels of the x axis stand below it, of the y axis left of it */
    for (size_t i = 0; i < c->nops; i++)
        if (c->ops[i].kind == PC_OP_TEXT) {
            const pc_op *t = &c->ops[i];
            if (t->flags == PC_ANCHOR_S) assert_true(t->y1 >= nearbyint(sy) + 5);
            else assert_int_equal(t->flags, PC_ANCHOR_W);
        }
    pc_axes_spec bad = {1, 0, 0, 1, 0, 0, 5, 1, 1, 0, -1};
    assert_int_equal(pc_axes(c, &bad, 15, NULL), PC_EARG);
    assert_string_equal(c->error, "axes: the ranges must be finite with x0 < x1 and y0 < y1");
    pc_canvas_free(c);
}

static void test_grid_and_legend(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_window(c, 0, 0, 10, 10, 0);
    pc_axes_spec a = {0, 10, 0, 10, 0, 0, 5, 0, 0, 1, 8};
    assert_int_equal(pc_axes(c, &a, 15, NULL), PC_OK);
    double sx, sy;
    pc_world_to_screen(c, 4, 5, &sx, &sy);   /* on the grid line x = 4, dotted 1 on 3 off */
    int lit = 0;
    for (int d = -2; d <= 2; d++) lit += c->pixels[((long)nearbyint(sy) + d) * 640 + (long)nearbyint(sx)] == 8;
    assert_true(lit >= 1 && lit <= 2);
    const char *names[] = {"sin", "cos"};
    int colors[] = {12, 10};
    size_t before = c->nops;
    assert_int_equal(pc_legend(c, 2, names, colors, PC_ANCHOR_NE, 15), PC_OK);
    /* the box: 6 + 20 + 6 + 24 + 6 = 62 wide, 2 * 18 + 6 = 42 high, 8 px in from the corner */
    assert_int_equal(c->ops[before].kind, PC_OP_BOX);
    assert_true(c->ops[before].x1 == 640 - 8 - 62 && c->ops[before].y1 == 8);
    assert_int_equal(c->pixels[20 * 640 + 580], 12);   /* the first swatch, row 4 + 8 */
    assert_int_equal(c->pixels[38 * 640 + 580], 10);
    assert_int_equal(pc_legend(c, 0, names, colors, PC_ANCHOR_NE, 15), PC_EARG);
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nice_ticks),
        cmocka_unit_test(test_axes),
        cmocka_unit_test(test_grid_and_legend),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
