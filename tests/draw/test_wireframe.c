/* Drawing a surface's iso-lines (wireframe.h) on a small canvas: a 3 x 3 square seen from +z,
 * its lines u, v = 0, 1, 2, 3 on the pixel columns and rows 5, 15, 25, 35; the boundary alone;
 * the hidden-line mode on a plane (which hides none of its own lines); the same lines through a
 * scene. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdlib.h>
#include <cmocka.h>
#include <math.h>
#include "wireframe.h"

/* orthographic from +z, 10 px per unit, y up in space and down on the screen, the origin at
 * pixel (5, 35) */
static pc_map screen_map(void) {
    pc_map ortho, s2, t2, st, out;
    double k[2] = {10, -10}, c[2] = {5, 35};
    assert_int_equal(pc_map_orthographic(&ortho, 'z'), PC_OK);
    pc_map_scale(&s2, 2, k, NULL);
    pc_map_translate(&t2, 2, c);
    assert_int_equal(pc_map_compose(&t2, &s2, &st), PC_OK);
    assert_int_equal(pc_map_compose(&st, &ortho, &out), PC_OK);
    return out;
}

static pc_surface *square3(void) {
    double p00[3] = {0, 0, 0}, p10[3] = {3, 0, 0}, p01[3] = {0, 3, 0}, p11[3] = {3, 3, 0};
    int st;
    pc_surface *s = pc_surface_bilinear(3, p00, p10, p01, p11, &st);
    assert_non_null(s);
    return s;
}

static int at(const pc_canvas *c, int x, int y) { return c->pixels[y * c->width + x]; }

/* the pixels of the lines at every 10th column and row from 5 to 35, or the edges alone */
static void assert_grid(const pc_canvas *c, int step) {
    for (int y = 5; y <= 35; y++)
        for (int x = 5; x <= 35; x++) {
            int on = (x - 5) % step == 0 || (y - 5) % step == 0;
            assert_int_equal(at(c, x, y), on ? 15 : 0);
        }
    assert_int_equal(at(c, 2, 20), 0);
    assert_int_equal(at(c, 38, 20), 0);
}

static pc_canvas *drawn(pc_surface *s, const pc_wireframe_opts *o) {
    pc_map scr = screen_map();
    pc_canvas *c = pc_canvas_new(40, 40, 16);
    int canvas_st;
    assert_int_equal(pc_draw_wireframe(c, s, &scr, o, &canvas_st), PC_OK);
    assert_int_equal(canvas_st, PC_OK);
    return c;
}

static void test_lines_and_boundary(void **state) {
    (void)state;
    pc_surface *s = square3();
    pc_wireframe_opts o = {.nu = 3, .nv = 3, .color = 15, .tol = 0.25, .mesh = 8};
    pc_canvas *c = drawn(s, &o);
    assert_grid(c, 10);
    pc_canvas_free(c);
    o.nu = o.nv = 0;                     /* no family at all: nothing */
    c = drawn(s, &o);
    assert_int_equal(at(c, 5, 20), 0);
    pc_canvas_free(c);
    o.boundary = 1;                      /* the four edges */
    c = drawn(s, &o);
    assert_grid(c, 30);
    pc_canvas_free(c);
    o.hidden = 1;                        /* a plane hides none of its own lines */
    o.nu = o.nv = 3;
    c = drawn(s, &o);
    assert_grid(c, 10);
    pc_canvas_free(c);
    pc_surface_release(s);
}

static void test_scene(void **state) {
    (void)state;
    pc_surface *s = square3();
    pc_map scr = screen_map();
    int st;
    pc_scene *sc = pc_scene_new(&scr, &st);
    assert_non_null(sc);
    pc_wireframe_opts o = {.nu = 3, .nv = 3, .color = 15, .tol = 0.25, .mesh = 8};
    assert_int_equal(pc_scene_wireframe(sc, s, &scr, &o, 0), PC_OK);
    pc_canvas *c = pc_canvas_new(40, 40, 16);
    assert_int_equal(pc_scene_draw(sc, c, PC_HIDDEN_HIDE), PC_OK);
    assert_grid(c, 10);
    pc_canvas_free(c);
    pc_scene_free(sc);
    pc_surface_release(s);
}

/* the square shaded as 3 x 3 quads lit from the viewer: one full shade over its image, and in a
 * scene it hides a line behind it */
static void test_shaded(void **state) {
    (void)state;
    pc_surface *s = square3();
    pc_map scr = screen_map();
    int st;
    pc_scene *sc = pc_scene_new(&scr, &st);
    assert_non_null(sc);
    pc_canvas *c = pc_canvas_new(40, 40, 16);
    pc_shade_opts o = {.nu = 3, .nv = 3, .has_light = 1, .light = {0, 0, 1}};
    size_t n;
    int drawn;
    assert_int_equal(pc_draw_shaded_surface(c, sc, s, &scr, &o, (pc_rgb){200, 120, 40}, -1, &n, &drawn), PC_OK);
    assert_int_equal(drawn, PC_OK);
    assert_int_equal(n, 9);
    int full = pc_rgb_color(c, (pc_rgb){200, 120, 40});
    assert_int_equal(at(c, 20, 20), full);
    assert_int_equal(at(c, 2, 20), 0);
    double behind[6] = {-1, 1.5, -1, 4, 1.5, -1};   /* y = 1.5 under the square, x -1 .. 4 */
    assert_int_equal(pc_scene_add_polyline(sc, 2, behind, NULL, 15, 0), PC_OK);
    assert_int_equal(pc_scene_draw(sc, c, PC_HIDDEN_HIDE), PC_OK);
    assert_int_equal(at(c, 2, 20), 15);    /* beside the square: seen */
    assert_int_equal(at(c, 20, 20), full); /* behind it: hidden */
    pc_canvas_free(c);
    pc_scene_free(sc);
    pc_surface_release(s);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lines_and_boundary),
        cmocka_unit_test(test_scene),
        cmocka_unit_test(test_shaded),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
