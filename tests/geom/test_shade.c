/* Shaded surfaces (shade.h) and the viewer (hidden.h): Lambert's cosine law on plane quads (a
 * plane facing the light at full colour, one at 60 degrees at half), the headlight, two-sided
 * lighting, ambient light, the painter's order of overlapping quads in parallel and central
 * projections, the screen corners, quads left out, the colours, and the errors. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdlib.h>
#include <cmocka.h>
#include <math.h>
#include "shade.h"

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

static pc_map from_plus_z(void) {
    pc_map ortho;
    assert_int_equal(pc_map_orthographic(&ortho, 'z'), PC_OK);
    return screen_of(&ortho);
}

/* The unit square turned by `tilt` radians about the x axis: its normal makes that angle with
 * the z axis. */
static pc_surface *tilted_square(double tilt) {
    double c = cos(tilt), s = sin(tilt);
    double p00[3] = {0, 0, 0}, p10[3] = {1, 0, 0}, p01[3] = {0, c, s}, p11[3] = {1, c, s};
    int st;
    pc_surface *sf = pc_surface_bilinear(3, p00, p10, p01, p11, &st);
    assert_non_null(sf);
    return sf;
}

static pc_shade_opts lit(int nu, int nv, double lx, double ly, double lz) {
    return (pc_shade_opts){.nu = nu, .nv = nv, .has_light = 1, .light = {lx, ly, lz}};
}

static void test_viewer(void **state) {
    (void)state;
    pc_map scr = from_plus_z();
    pc_viewer v;
    assert_int_equal(pc_viewer_of(&scr, &v), PC_OK);
    assert_int_equal(v.perspective, 0);
    assert_true(fabs(v.eye[0]) < 1e-15 && fabs(v.eye[1]) < 1e-15 && fabs(v.eye[2] - 1) < 1e-15);
    double a[3] = {0, 0, 2}, b[3] = {5, -3, 1}, t[3];
    assert_true(pc_viewer_depth(&v, a) > pc_viewer_depth(&v, b));
    assert_int_equal(pc_viewer_toward(&v, b, t), PC_OK);
    assert_true(t[2] == 1);
    pc_map persp;
    double eye[3] = {0, 0, 5}, p0[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    assert_int_equal(pc_map_perspective(&persp, eye, p0, up), PC_OK);
    pc_map ps = screen_of(&persp);
    assert_int_equal(pc_viewer_of(&ps, &v), PC_OK);
    assert_int_equal(v.perspective, 1);
    for (int k = 0; k < 3; k++) assert_true(fabs(v.eye[k] - eye[k]) < 1e-12);
    double q[3] = {3, 0, 1};   /* 5 from the eye: (3, 0, -4)/5 towards it */
    assert_int_equal(pc_viewer_toward(&v, q, t), PC_OK);
    assert_true(fabs(t[0] + 0.6) < 1e-15 && fabs(t[1]) < 1e-15 && fabs(t[2] - 0.8) < 1e-15);
    assert_true(fabs(pc_viewer_depth(&v, q) + 5) < 1e-12);
    assert_int_equal(pc_viewer_toward(&v, eye, t), PC_EZERO);
    pc_map id2;
    pc_map_identity(&id2, 2);
    assert_int_equal(pc_viewer_of(&id2, &v), PC_EDIM);
}

/* A plane facing the light: the full colour; the light behind it: dark (its lit side does
 * not show); ambient lifts both. */
static void test_facing_light(void **state) {
    (void)state;
    pc_surface *s = tilted_square(0);
    pc_map scr = from_plus_z();
    pc_shade_quad *q;
    size_t n;
    pc_shade_opts o = lit(3, 2, 0, 0, 5);
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_OK);
    assert_int_equal(n, 6);
    for (size_t k = 0; k < n; k++) assert_true(q[k].shade == 1);
    uint8_t base[3] = {200, 100, 51}, rgb[3];
    pc_shade_rgb(base, q[0].shade, rgb);
    assert_true(rgb[0] == 200 && rgb[1] == 100 && rgb[2] == 51);
    free(q);
    o = lit(3, 2, 0, 0, -1);
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_OK);
    for (size_t k = 0; k < n; k++) assert_true(q[k].shade == 0);
    free(q);
    o.ambient = 0.25;
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_OK);
    for (size_t k = 0; k < n; k++) assert_true(q[k].shade == 0.25);
    free(q);
    pc_surface_release(s);
}

/* At 60 degrees to the light: cos 60 = 1/2, half the colour, whichever of the plane and the
 * light is turned; with ambient a: a + (1 - a)/2. */
static void test_sixty_degrees(void **state) {
    (void)state;
    pc_map scr = from_plus_z();
    pc_shade_quad *q;
    size_t n;
    pc_surface *flat = tilted_square(0), *tilted = tilted_square(M_PI / 3);
    pc_shade_opts o = lit(2, 2, sin(M_PI / 3), 0, cos(M_PI / 3));
    assert_int_equal(pc_shade_quads(flat, &scr, &o, &q, &n), PC_OK);
    assert_int_equal(n, 4);
    for (size_t k = 0; k < n; k++) assert_true(fabs(q[k].shade - 0.5) < 1e-15);
    uint8_t base[3] = {200, 100, 51}, rgb[3];
    pc_shade_rgb(base, q[0].shade, rgb);
    assert_true(rgb[0] == 100 && rgb[1] == 50 && rgb[2] == 26);   /* 25.5 rounds to even: 26 */
    free(q);
    o = lit(2, 2, 0, 0, 1);
    assert_int_equal(pc_shade_quads(tilted, &scr, &o, &q, &n), PC_OK);
    for (size_t k = 0; k < n; k++) assert_true(fabs(q[k].shade - 0.5) < 1e-15);
    free(q);
    o.ambient = 0.2;
    assert_int_equal(pc_shade_quads(tilted, &scr, &o, &q, &n), PC_OK);
    for (size_t k = 0; k < n; k++) assert_true(fabs(q[k].shade - 0.6) < 1e-15);
    free(q);
    /* the headlight (no light given): the viewer is at +z, so the same cosines */
    o = (pc_shade_opts){.nu = 2, .nv = 2};
    assert_int_equal(pc_shade_quads(tilted, &scr, &o, &q, &n), PC_OK);
    for (size_t k = 0; k < n; k++) assert_true(fabs(q[k].shade - 0.5) < 1e-15);
    free(q);
    assert_int_equal(pc_shade_quads(flat, &scr, &o, &q, &n), PC_OK);
    for (size_t k = 0; k < n; k++) assert_true(q[k].shade == 1);
    free(q);
    pc_surface_release(flat);
    pc_surface_release(tilted);
}

/* Two-sided: seen from below (-z), the plane's underside shows; a light below lights it. */
static void test_two_sided(void **state) {
    (void)state;
    pc_surface *s = tilted_square(0);
    pc_map flip, from_below, scr;
    double a[3] = {0, 0, 0}, d[3] = {1, 0, 0};
    assert_int_equal(pc_map_rotate3(&flip, a, d, M_PI), PC_OK);   /* z -> -z */
    from_below = from_plus_z();
    assert_int_equal(pc_map_compose(&from_below, &flip, &scr), PC_OK);
    pc_shade_quad *q;
    size_t n;
    pc_shade_opts o = lit(1, 1, 0, 0, -1);
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_OK);
    assert_int_equal(n, 1);
    assert_true(fabs(q[0].shade - 1) < 1e-15);
    free(q);
    o = lit(1, 1, 0, 0, 1);
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_OK);
    assert_true(q[0].shade == 0);
    free(q);
    pc_surface_release(s);
}

/* The screen corners, in the order (i, j), (i+1, j), (i+1, j+1), (i, j+1). */
static void test_corners(void **state) {
    (void)state;
    pc_surface *s = tilted_square(0);
    pc_map scr = from_plus_z();
    pc_shade_quad *q;
    size_t n;
    pc_shade_opts o = lit(2, 1, 0, 0, 1);
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_OK);
    assert_int_equal(n, 2);
    /* equal depths: by grid position */
    assert_int_equal(q[0].i, 0);
    assert_int_equal(q[1].i, 1);
    const double want[8] = {370, 240, 420, 240, 420, 140, 370, 140};
    for (int k = 0; k < 8; k++) assert_true(fabs(q[1].xy[k] - want[k]) < 1e-12);
    free(q);
    pc_surface_release(s);
}

/* A surface folded over itself: u in [0, 1] the square z = 0, u in [1, 2] folded back over it
 * at height h.  Seen from +z the folded quad covers the flat one; it is drawn after it (nearer)
 * when h > 0 and before it when h < 0. */
static int fold_fn(void *ud, double u, double v, int order, double *out) {
    double h = *(double *)ud;
    if (order > 0) return PC_EDOMAIN;
    out[0] = u <= 1 ? u : 2 - u;
    out[1] = v;
    out[2] = u <= 1 ? 0 : h * (u - 1);
    out[3] = 1;
    return PC_OK;
}

static void order_of_fold(const pc_map *scr, double h, int first_i) {
    int st;
    pc_surface *s = pc_surface_func(3, 0, 2, 0, 1, fold_fn, NULL, &h, &st);
    assert_non_null(s);
    pc_shade_quad *q;
    size_t n;
    pc_shade_opts o = lit(2, 1, 0, 0, 1);
    assert_int_equal(pc_shade_quads(s, scr, &o, &q, &n), PC_OK);
    assert_int_equal(n, 2);
    assert_int_equal(q[0].i, first_i);
    assert_int_equal(q[1].i, 1 - first_i);
    assert_true(q[0].depth < q[1].depth);
    free(q);
    pc_surface_release(s);
}

static void test_painter_order(void **state) {
    (void)state;
    pc_map scr = from_plus_z();
    order_of_fold(&scr, 1, 0);    /* the fold above: flat first, fold on top */
    order_of_fold(&scr, -1, 1);   /* the fold below: fold first */
    /* a central projection from (0.5, 0.5, 5): the same, nearer the eye is later */
    pc_map persp;
    double eye[3] = {0.5, 0.5, 5}, p0[3] = {0.5, 0.5, 0}, up[3] = {0, 1, 0};
    assert_int_equal(pc_map_perspective(&persp, eye, p0, up), PC_OK);
    pc_map ps = screen_of(&persp);
    order_of_fold(&ps, 1, 0);
    order_of_fold(&ps, -1, 1);
}

/* Corners without a finite image leave their quads out: a NaN at (u, v) = (1, 1) of a 2 x 2
 * grid touches all four quads; at (2, 2) only one. */
static int nan_fn(void *ud, double u, double v, int order, double *out) {
    const double *bad = ud;
    if (order > 0) return PC_EDOMAIN;
    out[0] = u;
    out[1] = v;
    out[2] = (u == bad[0] && v == bad[1]) ? NAN : 0;
    out[3] = 1;
    return PC_OK;
}

static void test_left_out(void **state) {
    (void)state;
    pc_map scr = from_plus_z();
    double centre[2] = {1, 1}, corner[2] = {2, 2};
    int st;
    pc_shade_quad *q;
    size_t n;
    pc_shade_opts o = lit(2, 2, 0, 0, 1);
    pc_surface *s = pc_surface_func(3, 0, 2, 0, 2, nan_fn, NULL, centre, &st);
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_OK);
    assert_int_equal(n, 0);
    assert_null(q);
    pc_surface_release(s);
    s = pc_surface_func(3, 0, 2, 0, 2, nan_fn, NULL, corner, &st);
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_OK);
    assert_int_equal(n, 3);
    for (size_t k = 0; k < n; k++) assert_false(q[k].i == 1 && q[k].j == 1);
    free(q);
    pc_surface_release(s);
}

/* A callback's failure is passed on. */
static int failing_fn(void *ud, double u, double v, int order, double *out) {
    (void)ud;
    if (order > 0) return PC_EDOMAIN;
    if (u > 0.5 && v > 0.5) return PC_EARG;
    out[0] = u;
    out[1] = v;
    out[2] = 0;
    out[3] = 1;
    return PC_OK;
}

static void test_errors(void **state) {
    (void)state;
    pc_map scr = from_plus_z(), id2;
    pc_map_identity(&id2, 2);
    pc_surface *s = tilted_square(0);
    pc_shade_quad *q = (pc_shade_quad *)&q;
    size_t n = 7;
    pc_shade_opts o = lit(2, 2, 0, 0, 1);
    assert_int_equal(pc_shade_quads(s, &id2, &o, &q, &n), PC_EDIM);
    assert_null(q);
    assert_int_equal(n, 0);
    o.nu = 0;
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_EDOMAIN);
    o.nu = 1025;
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_EDOMAIN);
    o = lit(2, 2, 0, 0, 0);
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_EZERO);
    o = lit(2, 2, NAN, 0, 1);
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_ENONFINITE);
    o = lit(2, 2, 0, 0, 1);
    o.ambient = 1.5;
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_EDOMAIN);
    o.ambient = NAN;
    assert_int_equal(pc_shade_quads(s, &scr, &o, &q, &n), PC_EDOMAIN);
    pc_map flat = scr;   /* rank 2 */
    for (int j = 0; j < 4; j++) PC_MAP_AT(&flat, 1, j) = PC_MAP_AT(&flat, 0, j);
    o.ambient = 0;
    assert_int_equal(pc_shade_quads(s, &flat, &o, &q, &n), PC_ESINGULAR);
    pc_surface_release(s);
    double p[2][2] = {{0, 0}, {1, 1}};
    int st;
    pc_surface *s2 = pc_surface_bilinear(2, p[0], p[1], p[0], p[1], &st);
    assert_int_equal(pc_shade_quads(s2, &scr, &o, &q, &n), PC_EDIM);
    pc_surface_release(s2);
    pc_surface *f = pc_surface_func(3, 0, 1, 0, 1, failing_fn, NULL, NULL, &st);
    assert_int_equal(pc_shade_quads(f, &scr, &o, &q, &n), PC_EARG);
    assert_null(q);
    pc_surface_release(f);
    uint8_t base[3] = {10, 20, 30}, rgb[3];
    pc_shade_rgb(base, NAN, rgb);
    assert_true(rgb[0] == 0 && rgb[1] == 0 && rgb[2] == 0);
    pc_shade_rgb(base, 2, rgb);
    assert_true(rgb[0] == 10 && rgb[1] == 20 && rgb[2] == 30);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_viewer),       cmocka_unit_test(test_facing_light),
        cmocka_unit_test(test_sixty_degrees), cmocka_unit_test(test_two_sided),
        cmocka_unit_test(test_corners),      cmocka_unit_test(test_painter_order),
        cmocka_unit_test(test_left_out),     cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
