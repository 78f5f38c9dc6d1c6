/* The 3-D scene (scene.h): a line behind a sphere is dashed or absent at the right pixels and
 * solid elsewhere, the same whatever the order the line and the sphere were added in; a line in
 * front is whole; a hidden marker is left out. */
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
#include "furniture.h"
#include "scene.h"
#include "writers.h"

static int sphere_fn(void *ud, double u, double v, int order, double *out) {
    (void)ud;
    if (order > 0) return PC_EDOMAIN;
    out[0] = 100 * cos(u) * cos(v); out[1] = 100 * sin(u) * cos(v); out[2] = 100 * sin(v); out[3] = 1;
    return PC_OK;
}

/* seen from +z: screen x = 320 + x, y = 240 - y */
static pc_map screen(void) {
    pc_map f;
    double a[12] = {1, 0, 0, 320,  0, -1, 0, 240,  0, 0, 0, 1};
    assert_int_equal(pc_map_from_matrix(&f, 3, 2, a, 0), PC_OK);
    return f;
}

static int at(const pc_canvas *c, int x, int y) { return c->pixels[y * c->width + x]; }

/* The row y = 240 of a canvas with the scene drawn: the sphere and the line z = zline from
 * x = -200 to 200, added line first or sphere first. */
static pc_canvas *draw(double zline, int sphere_first, pc_hidden_mode mode) {
    int st;
    pc_map f = screen();
    pc_scene *sc = pc_scene_new(&f, &st);
    assert_non_null(sc);
    pc_surface *s = pc_surface_func(3, 0, 2 * M_PI, -M_PI / 2, M_PI / 2, sphere_fn, NULL, NULL, &st);
    double line[6] = {-200, 0, zline, 200, 0, zline}, dot[3] = {0, 30, -120};
    if (sphere_first) assert_int_equal(pc_scene_add_surface(sc, s, 48), PC_OK);
    assert_int_equal(pc_scene_add_polyline(sc, 2, line, NULL, 14, 0), PC_OK);
    assert_int_equal(pc_scene_add_mark(sc, dot, PC_MARK_DOT, 5, 12), PC_OK);
    if (!sphere_first) assert_int_equal(pc_scene_add_surface(sc, s, 48), PC_OK);
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_scene_draw(sc, c, mode), PC_OK);
    pc_scene_free(sc);
    pc_surface_release(s);
    return c;
}

static void test_line_behind_sphere(void **state) {
    (void)state;
    for (int order = 0; order < 2; order++) {
        pc_canvas *c = draw(-150, order, PC_HIDDEN_HIDE);
        for (int x = 120; x <= 520; x++) {
            int d = abs(x - 320);
            if (d < 95) assert_int_equal(at(c, x, 240), 0);     /* behind the sphere: absent */
            if (d > 101) assert_int_equal(at(c, x, 240), 14);   /* beside it: solid */
        }
        assert_int_equal(at(c, 320, 210), 0);   /* the marker behind: left out */
        pc_canvas_free(c);
    }
    /* the same in either order, pixel for pixel */
    pc_canvas *a = draw(-150, 0, PC_HIDDEN_DASHED), *b = draw(-150, 1, PC_HIDDEN_DASHED);
    assert_memory_equal(a->pixels, b->pixels, 640 * 480 * sizeof *a->pixels);
    /* dashed: 4 on, 3 off along the hidden part, so 4/7 of it drawn */
    int on = 0;
    for (int x = 225; x <= 415; x++) on += at(a, x, 240) == 14;
    assert_true(abs(on - 191 * 4 / 7) <= 4);
    assert_int_equal(at(a, 150, 240), 14);
    assert_int_equal(at(a, 320, 210), 0);    /* the hidden marker drawn open: empty inside */
    assert_true(at(a, 322, 210) == 12 || at(a, 323, 210) == 12);   /* its ring, 2.5 px out */
    pc_canvas_free(a);
    pc_canvas_free(b);
}

static void test_line_in_front(void **state) {
    (void)state;
    pc_canvas *c = draw(150, 0, PC_HIDDEN_HIDE);
    for (int x = 120; x <= 520; x++) assert_int_equal(at(c, x, 240), 14);
    pc_canvas_free(c);
    c = draw(-150, 0, PC_HIDDEN_SHOW);   /* "show": everything as drawn */
    for (int x = 120; x <= 520; x++) assert_int_equal(at(c, x, 240), 14);
    pc_canvas_free(c);
}

/* Labels of 3-D points: written only where their point is seen; placed with the others. */
static void test_labels(void **state) {
    (void)state;
    int st;
    pc_map f = screen();
    pc_scene *sc = pc_scene_new(&f, &st);
    pc_surface *s = pc_surface_func(3, 0, 2 * M_PI, -M_PI / 2, M_PI / 2, sphere_fn, NULL, NULL, &st);
    double front[3] = {0, 0, 100}, back[3] = {0, 0, -100};
    assert_int_equal(pc_scene_add_label(sc, back, "back", PC_ANCHOR_AUTO, 1, 14), PC_OK);
    assert_int_equal(pc_scene_add_label(sc, front, "front", PC_ANCHOR_NE, 1, 14), PC_OK);
    assert_int_equal(pc_scene_add_surface(sc, s, 48), PC_OK);
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_scene_draw(sc, c, PC_HIDDEN_HIDE), PC_OK);
    assert_int_equal(c->nops, 1);   /* only the front label */
    assert_int_equal(c->ops[0].kind, PC_OP_TEXT);
    assert_memory_equal(c->text + c->ops[0].first, "front", 5);
    assert_true(c->ops[0].x2 == 320 && c->ops[0].y2 == 240);
    pc_canvas_free(c);
    c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_scene_draw(sc, c, PC_HIDDEN_SHOW), PC_OK);
    assert_int_equal(c->nops, 2);
    assert_true(c->ops[0].flags & PC_TEXT_AUTO);   /* "back", to be placed */
    pc_canvas_free(c);
    pc_scene_free(sc);
    pc_surface_release(s);
}

/* A label's {font, size, halo} is kept till the scene draws it, then applied to its text. */
static void test_label_style(void **state) {
    (void)state;
    int st;
    pc_map f = screen();
    pc_scene *sc = pc_scene_new(&f, &st);
    double x[3] = {10, 20, 0};
    assert_int_equal(pc_scene_style_label(sc, "Serif", 9, 0), PC_EARG);   /* no label yet */
    assert_int_equal(pc_scene_add_label(sc, x, "A", PC_ANCHOR_NE, 1, 14), PC_OK);
    assert_int_equal(pc_scene_style_label(sc, "Serif", 9, 0), PC_OK);
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_scene_draw(sc, c, PC_HIDDEN_HIDE), PC_OK);
    assert_int_equal(c->nops, 1);
    assert_int_equal(c->ops[0].pen, 1);   /* the first text style */
    assert_int_equal(c->ntstyles, 1);
    assert_string_equal(c->tstyles[0].font, "Serif");
    assert_true(c->tstyles[0].size == 9 && c->tstyles[0].halo == 0);
    pc_canvas_free(c);
    pc_scene_free(sc);
}

static int resolve_hide(void *attach, pc_canvas *copy) { return pc_scene_draw(attach, copy, PC_HIDDEN_HIDE); }

/* A label with bad math that reaches the scene (the C API does not check it) fails its drawing
 * with the markup's message, and a writer says that message, not "out of memory". */
static void test_label_bad_math(void **state) {
    (void)state;
    int st;
    pc_map f = screen();
    pc_scene *sc = pc_scene_new(&f, &st);
    double x[3] = {10, 20, 0};
    assert_int_equal(pc_scene_add_label(sc, x, "$\\nosuch A$", PC_ANCHOR_NE, 1, 14), PC_OK);
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_scene_draw(sc, c, PC_HIDDEN_HIDE), PC_EARG);
    assert_non_null(strstr(pc_canvas_error(c), "unknown command '\\nosuch' at character 2"));
    pc_canvas_free(c);
    c = pc_canvas_new(640, 480, 16);
    c->attach = sc;
    c->attach_resolve = resolve_hide;
    char why[200] = "";
    FILE *out = tmpfile();
    assert_non_null(out);
    assert_int_equal(pc_encode(c, PC_FMT_PNG, PC_THEME_SCREEN, out, why, sizeof why), PC_EARG);
    assert_non_null(strstr(why, "label '$\\nosuch A$': unknown command '\\nosuch' at character 2"));
    fclose(out);
    c->attach = NULL;
    c->attach_resolve = NULL;
    pc_canvas_free(c);
    pc_scene_free(sc);
}

static void extent_put(void *ctx, double x, double y, double dx0, double dy0, double dx1, double dy1) {
    double *b = ctx;   /* the box of everything: x0, y0, x1, y1 */
    b[0] = fmin(b[0], x + dx0); b[1] = fmin(b[1], y + dy0);
    b[2] = fmax(b[2], x + dx1); b[3] = fmax(b[3], y + dy1);
}

/* The scene's extent is what it draws, through the camera; reframed, it is drawn through the
 * framing, and its depth order is kept (the line behind the sphere stays hidden). */
static void test_extent_and_reframe(void **state) {
    (void)state;
    int st;
    pc_map f = screen();
    pc_scene *sc = pc_scene_new(&f, &st);
    pc_surface *s = pc_surface_func(3, 0, 2 * M_PI, -M_PI / 2, M_PI / 2, sphere_fn, NULL, NULL, &st);
    double line[6] = {-200, 0, -150, 200, 0, -150}, dot[3] = {0, 150, 0};
    assert_int_equal(pc_scene_add_surface(sc, s, 48), PC_OK);
    assert_int_equal(pc_scene_add_polyline(sc, 2, line, NULL, 14, 0), PC_OK);
    assert_int_equal(pc_scene_add_mark(sc, dot, PC_MARK_DOT, 6, 12), PC_OK);
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    double b[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    assert_int_equal(pc_scene_extent(sc, c, extent_put, b), PC_OK);
    /* the line's ends at x = 120 and 520, the dot's top 3 px above y = 240 - 150 */
    assert_true(b[0] == 120 && b[2] == 520 && b[1] == 87 && b[3] == 240);
    pc_scene_reframe(sc, 0.5, 0.5, 100, 50);   /* half size: x -> x/2 + 100 */
    assert_int_equal(pc_scene_draw(sc, c, PC_HIDDEN_HIDE), PC_OK);
    assert_int_equal(at(c, 165, 170), 14);       /* 330 -> 265: beside the sphere, solid */
    assert_int_equal(at(c, 260, 170), 0);        /* the middle, behind it: absent */
    assert_int_equal(at(c, 360, 170), 14);
    assert_int_equal(at(c, 260, 95), 12);        /* the dot at (320, 90) -> (260, 95) */
    /* PSET dots: hidden ones left out even when the hidden lines are dashed */
    double front[3] = {-50, 0, 120}, back[3] = {50, 0, -120};
    assert_int_equal(pc_scene_add_dot(sc, front, 10), PC_OK);
    assert_int_equal(pc_scene_add_dot(sc, back, 11), PC_OK);
    assert_int_equal(pc_scene_draw(sc, c, PC_HIDDEN_DASHED), PC_OK);
    assert_int_equal(at(c, 235, 170), 10);       /* (270, 240) -> (235, 170) */
    assert_int_not_equal(at(c, 285, 170), 11);   /* (370, 240) -> (285, 170): hidden */
    pc_canvas_free(c);
    pc_scene_free(sc);
    pc_surface_release(s);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_extent_and_reframe),
        cmocka_unit_test(test_label_style),
        cmocka_unit_test(test_label_bad_math),
        cmocka_unit_test(test_line_behind_sphere),
        cmocka_unit_test(test_line_in_front),
        cmocka_unit_test(test_labels),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
