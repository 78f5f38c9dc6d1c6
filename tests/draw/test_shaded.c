/* Drawing shaded quads (shaded.h) on a small canvas: a lit plane covers its image exactly
 * (every pixel once, in the full colour), the mesh is drawn over the fills, the nearer of two
 * overlapping quads is the one seen, and WINDOW is undone for the drawing statements. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdlib.h>
#include <cmocka.h>
#include <math.h>
#include "shaded.h"

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

static pc_shade_quad *quads(const pc_surface *s, const pc_map *scr, int nu, int nv, size_t *n) {
    pc_shade_opts o = {.nu = nu, .nv = nv, .has_light = 1, .light = {0, 0, 1}};
    pc_shade_quad *q;
    assert_int_equal(pc_shade_quads(s, scr, &o, &q, n), PC_OK);
    return q;
}

static void test_plane_covered_once(void **state) {
    (void)state;
    pc_surface *s = square3();
    pc_map scr = screen_map();
    size_t n;
    pc_shade_quad *q = quads(s, &scr, 3, 3, &n);
    assert_int_equal(n, 9);
    pc_canvas *c = pc_canvas_new(40, 40, 16);
    assert_int_equal(pc_draw_shaded(c, q, n, (pc_rgb){200, 120, 40}, -1), PC_OK);
    int full = pc_rgb_color(c, (pc_rgb){200, 120, 40});
    assert_int_equal(c->ntrue, 1);   /* one shade: one colour */
    /* the image is x 5..35, y 5..35: centres 5..34 both ways */
    for (int y = 0; y < 40; y++)
        for (int x = 0; x < 40; x++)
            assert_int_equal(at(c, x, y), (x >= 5 && x < 35 && y >= 5 && y < 35) ? full : 0);
    /* nine FILLPATH ops, no outlines */
    assert_int_equal(c->nops, 9);
    for (size_t k = 0; k < c->nops; k++) assert_int_equal(c->ops[k].kind, PC_OP_FILLPATH);
    pc_canvas_free(c);
    free(q);
    pc_surface_release(s);
}

static void test_mesh_on_top(void **state) {
    (void)state;
    pc_surface *s = square3();
    pc_map scr = screen_map();
    size_t n;
    pc_shade_quad *q = quads(s, &scr, 3, 3, &n);
    pc_canvas *c = pc_canvas_new(40, 40, 16);
    assert_int_equal(pc_draw_shaded(c, q, n, (pc_rgb){200, 120, 40}, 14), PC_OK);
    int full = pc_rgb_color(c, (pc_rgb){200, 120, 40});
    for (int y = 5; y <= 35; y++)
        for (int x = 5; x <= 35; x++) {
            int line = (x - 5) % 10 == 0 || (y - 5) % 10 == 0;
            assert_int_equal(at(c, x, y), line ? 14 : full);
        }
    assert_int_equal(c->nops, 18);   /* fill, outline, fill, outline, ... */
    assert_int_equal(c->ops[0].kind, PC_OP_FILLPATH);
    assert_int_equal(c->ops[1].kind, PC_OP_PATH);
    pc_canvas_free(c);
    free(q);
    pc_surface_release(s);
}

/* u in [0, 1]: the unit square z = 0; u in [1, 2]: folded back over it at 45 degrees, up
 * (h = 1) or down (h = -1).  Lit from +z: the flat quad full, the fold cos 45. */
static int fold_fn(void *ud, double u, double v, int order, double *out) {
    double h = *(double *)ud;
    if (order > 0) return PC_EDOMAIN;
    out[0] = u <= 1 ? u : 2 - u;
    out[1] = v;
    out[2] = u <= 1 ? 0 : h * (u - 1);
    out[3] = 1;
    return PC_OK;
}

static void test_nearer_on_top(void **state) {
    (void)state;
    pc_map scr = screen_map();
    for (int up = 0; up < 2; up++) {
        double h = up ? 1 : -1;
        int st;
        pc_surface *s = pc_surface_func(3, 0, 2, 0, 1, fold_fn, NULL, &h, &st);
        size_t n;
        pc_shade_quad *q = quads(s, &scr, 2, 1, &n);
        assert_int_equal(n, 2);
        pc_canvas *c = pc_canvas_new(40, 40, 16);
        assert_int_equal(pc_draw_shaded(c, q, n, (pc_rgb){200, 200, 200}, -1), PC_OK);
        int flat = pc_rgb_color(c, (pc_rgb){200, 200, 200});
        int fold = pc_rgb_color(c, (pc_rgb){141, 141, 141});   /* 200 cos 45 = 141.4 */
        int seen = up ? fold : flat;
        for (int y = 25; y < 35; y++)
            for (int x = 5; x < 15; x++) assert_int_equal(at(c, x, y), seen);
        pc_canvas_free(c);
        free(q);
        pc_surface_release(s);
    }
}

/* With WINDOW set, the screen corners go back to world coordinates: the same pixels. */
static void test_window(void **state) {
    (void)state;
    pc_surface *s = square3();
    pc_map scr = screen_map();
    size_t n;
    pc_shade_quad *q = quads(s, &scr, 3, 3, &n);
    pc_canvas *c = pc_canvas_new(40, 40, 16);
    assert_int_equal(pc_window(c, -1, -1, 1, 1, 0), PC_OK);
    assert_int_equal(pc_draw_shaded(c, q, n, (pc_rgb){255, 255, 255}, -1), PC_OK);
    int white = pc_rgb_color(c, (pc_rgb){255, 255, 255});
    int ink = 0;
    for (int i = 0; i < 1600; i++) ink += c->pixels[i] == white;
    assert_int_equal(ink, 900);
    assert_int_equal(at(c, 5, 5), white);
    assert_int_equal(at(c, 35, 35), 0);
    pc_canvas_free(c);
    free(q);
    pc_surface_release(s);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_plane_covered_once),
        cmocka_unit_test(test_mesh_on_top),
        cmocka_unit_test(test_nearer_on_top),
        cmocka_unit_test(test_window),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
