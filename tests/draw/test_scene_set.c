/* The scenes attached to a canvas (scene.h: pc_canvas_scene, pc_scene_add_curve): the same map
 * and mode give the same scene, another mode a new one after it; a canvas with something
 * else attached gives none; a sampled curve is drawn at its pixels when the canvas resolves
 * its attachment, as a writer does. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>
#include "canvas.h"
#include "curve.h"
#include "furniture.h"
#include "scene.h"

/* seen from +z: screen x = 320 + x, y = 240 - y */
static pc_map screen(double shift) {
    pc_map f;
    double a[12] = {1, 0, 0, 320 + shift,  0, -1, 0, 240,  0, 0, 0, 1};
    assert_int_equal(pc_map_from_matrix(&f, 3, 2, a, 0), PC_OK);
    return f;
}

static int other_resolve(void *p, pc_canvas *copy) {
    (void)p, (void)copy;
    return PC_OK;
}

static void test_scene_set(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_map f = screen(0), g = screen(5);
    int st;
    pc_scene *a = pc_canvas_scene(c, &f, PC_HIDDEN_HIDE, &st);
    assert_non_null(a);
    assert_int_equal(st, PC_OK);
    assert_ptr_equal(pc_canvas_scene(c, &f, PC_HIDDEN_HIDE, &st), a);
    pc_scene *b = pc_canvas_scene(c, &f, PC_HIDDEN_DASHED, &st);
    assert_non_null(b);
    assert_ptr_not_equal(b, a);
    pc_scene *d = pc_canvas_scene(c, &g, PC_HIDDEN_DASHED, &st);
    assert_ptr_not_equal(d, b);
    for (int i = 0; i < 5; i++) assert_non_null(pc_canvas_scene(c, i % 2 ? &f : &g, PC_HIDDEN_SHOW, &st));
    /* the straight Bezier curve from (-100, 0, 0) to (100, 0, 0), 8 pieces, in colour 14 */
    double cp[8] = {-100, 0, 0, 1, 100, 0, 0, 1};
    pc_curve *k = pc_curve_bezier(3, 2, cp, &st);
    assert_non_null(k);
    assert_int_equal(pc_scene_add_curve(a, k, 8, 14, 0), PC_OK);
    assert_int_equal(pc_scene_nstrokes(a), 1);
    assert_int_equal(c->attach_resolve(c->attach, c), PC_OK);
    assert_int_equal(c->pixels[240 * 640 + 320], 14);
    assert_int_equal(c->pixels[240 * 640 + 220], 14);
    assert_int_equal(c->pixels[240 * 640 + 420], 14);
    assert_int_equal(c->pixels[240 * 640 + 430], 0);
    assert_int_equal(c->pixels[250 * 640 + 320], 0);
    pc_curve_release(k);
    pc_canvas_free(c);   /* drops the scenes */
    /* another attachment: no scene, no failure */
    c = pc_canvas_new(640, 480, 16);
    int dummy;
    c->attach = &dummy;
    c->attach_resolve = other_resolve;
    assert_null(pc_canvas_scene(c, &f, PC_HIDDEN_HIDE, &st));
    assert_int_equal(st, PC_OK);
    c->attach = NULL;
    c->attach_resolve = NULL;
    pc_canvas_free(c);
}

/* a closed 3-D path: the closing side drawn too; a head at its end */
static void test_scene_path(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    pc_map f = screen(0);
    int st;
    pc_scene *sc = pc_canvas_scene(c, &f, PC_HIDDEN_SHOW, &st);
    double tri[9] = {0, 0, 0, 100, 0, 0, 100, 100, 0};
    assert_int_equal(pc_scene_add_path(sc, 3, tri, 1, 0, 13, 0), PC_OK);
    double seg[6] = {-200, -100, 0, -100, -100, 0};
    assert_int_equal(pc_scene_add_path(sc, 2, seg, 0, PC_ARROW_END, 11, 0), PC_OK);
    assert_int_equal(c->attach_resolve(c->attach, c), PC_OK);
    assert_int_equal(c->pixels[240 * 640 + 370], 13);   /* (50, 0) */
    assert_int_equal(c->pixels[190 * 640 + 370], 13);   /* (50, 50): the closing side */
    assert_int_equal(c->pixels[190 * 640 + 420], 13);   /* (100, 50) */
    assert_int_equal(c->pixels[340 * 640 + 170], 11);   /* (-150, -100) */
    int head = 0;
    for (int y = 336; y <= 344; y++)
        for (int x = 208; x <= 219; x++) head += c->pixels[y * 640 + x] == 11 && y != 340;
    assert_true(head > 6);   /* the head's triangle at (-100, -100) */
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_scene_set), cmocka_unit_test(test_scene_path)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
