/* Hidden lines (hidden.h): a unit sphere and a plane patch seen through parallel and central
 * projections onto a y-down screen; which points are seen, and the depth's orientation. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "hidden.h"

static int sphere_fn(void *ud, double u, double v, int order, double *out) {
    (void)ud;
    if (order > 0) return PC_EDOMAIN;
    out[0] = cos(u) * cos(v);
    out[1] = sin(u) * cos(v);
    out[2] = sin(v);
    out[3] = 1;
    return PC_OK;
}

static pc_surface *sphere(void) {
    int st;
    pc_surface *s = pc_surface_func(3, 0, 2 * M_PI, -M_PI / 2, M_PI / 2, sphere_fn, NULL, NULL, &st);
    assert_non_null(s);
    return s;
}

/* the picture map: proj (3 -> 2, world y up) then 100 px per unit, y flipped, centre (320, 240) */
static pc_map screen_of(const pc_map *proj) {
    pc_map s2, t2, st, out;
    double k[2] = {100, -100}, c[2] = {320, 240};
    pc_map_scale(&s2, 2, k, NULL);
    pc_map_translate(&t2, 2, c);
    assert_int_equal(pc_map_compose(&t2, &s2, &st), PC_OK);
    assert_int_equal(pc_map_compose(&st, proj, &out), PC_OK);
    return out;
}

static void test_sphere_parallel(void **state) {
    (void)state;
    pc_surface *s = sphere();
    pc_map ortho;
    assert_int_equal(pc_map_orthographic(&ortho, 'z'), PC_OK);   /* seen from +z */
    pc_map scr = screen_of(&ortho);
    int st;
    pc_occluder *o = pc_occluder_new(s, &scr, 48, 48, &st);
    assert_non_null(o);
    double front[3] = {0, 0, 1}, back[3] = {0, 0, -1};
    assert_true(pc_occluder_depth(o, front) > pc_occluder_depth(o, back));
    assert_int_equal(pc_occluder_visible(o, front), 1);
    assert_int_equal(pc_occluder_visible(o, back), 0);
    /* every point of the sphere: seen exactly when z > 0 (away from the rim) */
    int wrong = 0;
    for (int i = 0; i < 40; i++)
        for (int j = 1; j < 20; j++) {
            double u = 2 * M_PI * i / 40, v = -M_PI / 2 + M_PI * j / 20, x[4];
            sphere_fn(NULL, u, v, 0, x);
            if (fabs(x[2]) < 0.2) continue;
            wrong += pc_occluder_visible(o, x) != (x[2] > 0);
        }
    assert_int_equal(wrong, 0);
    /* a point outside the sphere's image is seen; one inside the ball is hidden */
    double beside[3] = {2, 0, -5}, inside[3] = {0.2, 0.1, -0.5};
    assert_int_equal(pc_occluder_visible(o, beside), 1);
    assert_int_equal(pc_occluder_visible(o, inside), 0);
    pc_occluder_free(o);
    pc_surface_release(s);
}

static void test_plane_and_isometric(void **state) {
    (void)state;
    double p00[3] = {-1, -1, 0}, p10[3] = {1, -1, 0}, p01[3] = {-1, 1, 0}, p11[3] = {1, 1, 0};
    int st;
    pc_surface *s = pc_surface_bilinear(3, p00, p10, p01, p11, &st);
    assert_non_null(s);
    pc_map iso, tilt, proj;
    pc_map_isometric(&iso);
    /* the textbook's axonometry has y up: turn the plane z = 0 to face the viewer first */
    double a[3] = {0, 0, 0}, d[3] = {1, 0, 0};
    assert_int_equal(pc_map_rotate3(&tilt, a, d, -M_PI / 2), PC_OK);   /* z -> y */
    assert_int_equal(pc_map_compose(&iso, &tilt, &proj), PC_OK);
    pc_map scr = screen_of(&proj);
    pc_occluder *o = pc_occluder_new(s, &scr, 8, 8, &st);
    assert_non_null(o);
    double above[3] = {0, 0, 0.5}, below[3] = {0, 0, -0.5}, on[3] = {0.3, 0.3, 0};
    assert_int_equal(pc_occluder_visible(o, on), 1);               /* its own points */
    /* which side faces the viewer: the one the depth says */
    int up_nearer = pc_occluder_depth(o, above) > pc_occluder_depth(o, below);
    assert_int_equal(pc_occluder_visible(o, above), up_nearer);
    assert_int_equal(pc_occluder_visible(o, below), !up_nearer);
    pc_occluder_free(o);
    pc_surface_release(s);
}

static void test_perspective(void **state) {
    (void)state;
    pc_surface *s = sphere();
    pc_map persp;
    double eye[3] = {0, 0, 5}, p0[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    assert_int_equal(pc_map_perspective(&persp, eye, p0, up), PC_OK);
    pc_map scr = screen_of(&persp);
    int st;
    pc_occluder *o = pc_occluder_new(s, &scr, 48, 48, &st);
    assert_non_null(o);
    double front[3] = {0, 0, 1}, back[3] = {0, 0, -1}, side[3] = {0.6, 0, 0.8};
    assert_int_equal(pc_occluder_visible(o, front), 1);
    assert_int_equal(pc_occluder_visible(o, back), 0);
    assert_int_equal(pc_occluder_visible(o, side), 1);
    double behind[3] = {0.6, 0, -0.8};
    assert_int_equal(pc_occluder_visible(o, behind), 0);
    pc_occluder_free(o);
    pc_surface_release(s);
}

/* A line behind the unit sphere seen from +z: hidden exactly where its image falls inside the
 * sphere's (|x| < 1), so its seen runs are x in [-2, -1] and [1, 2], its hidden run between. */
static void test_split(void **state) {
    (void)state;
    pc_surface *s = sphere();
    pc_map ortho;
    pc_map_orthographic(&ortho, 'z');
    pc_map scr = screen_of(&ortho);
    int st;
    pc_occluder *o = pc_occluder_new(s, &scr, 48, 48, &st);
    assert_non_null(o);
    double cp[8] = {-2, 0, -0.5, 1, 2, 0, -0.5, 1};
    pc_curve *c = pc_curve_bezier(3, 2, cp, &st);
    assert_non_null(c);
    pc_polyline seen = {0}, hidden = {0};
    assert_int_equal(pc_occluder_split(o, &scr, c, 40, &seen, &hidden), PC_OK);
    /* seen: 120 .. 220 then a move to 420 .. 520 (y 240 throughout) */
    assert_true(seen.n > 4 && hidden.n >= 2);
    assert_int_equal(seen.move[0], 1);
    assert_float_equal(seen.xy[0], 120, 1e-9);
    assert_float_equal(seen.xy[2 * seen.n - 2], 520, 1e-9);
    int moves = 0;
    for (size_t i = 0; i < seen.n; i++) {
        assert_float_equal(seen.xy[2 * i + 1], 240, 1e-9);
        if (seen.move[i] && i > 0) {
            moves++;
            assert_float_equal(seen.xy[2 * i - 2], 220, 1.0);   /* the change, bisected */
            assert_float_equal(seen.xy[2 * i], 420, 1.0);
        }
    }
    assert_int_equal(moves, 1);
    assert_int_equal(hidden.move[0], 1);
    assert_float_equal(hidden.xy[0], 220, 1.0);
    assert_float_equal(hidden.xy[2 * hidden.n - 2], 420, 1.0);
    for (size_t i = 1; i < hidden.n; i++) assert_int_equal(hidden.move[i], 0);
    pc_polyline_free(&seen);
    pc_polyline_free(&hidden);
    pc_curve_release(c);
    pc_occluder_free(o);
    pc_surface_release(s);
}

static void test_errors(void **state) {
    (void)state;
    pc_surface *s = sphere();
    pc_map id2, ortho;
    pc_map_identity(&id2, 2);
    pc_map_orthographic(&ortho, 'z');
    int st = PC_OK;
    assert_null(pc_occluder_new(s, &id2, 8, 8, &st));
    assert_int_equal(st, PC_EDIM);
    assert_null(pc_occluder_new(s, &ortho, 0, 8, &st));
    assert_int_equal(st, PC_EDOMAIN);
    pc_map flat = ortho;   /* rank 2: both rows along x */
    for (int j = 0; j < 4; j++) PC_MAP_AT(&flat, 1, j) = PC_MAP_AT(&flat, 0, j);
    assert_null(pc_occluder_new(s, &flat, 8, 8, &st));
    assert_int_equal(st, PC_ESINGULAR);
    pc_surface_release(s);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_parallel),
        cmocka_unit_test(test_plane_and_isometric),
        cmocka_unit_test(test_perspective),
        cmocka_unit_test(test_split),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
