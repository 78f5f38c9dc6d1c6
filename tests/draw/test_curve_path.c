/* A curve drawn as one path (stdlib/draw/curve_path.h): the screen map of WINDOW, the
 * flattening in equal parts joined without a break, and the stroke of the polyline. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include <string.h>
#include "curve_path.h"

/* WINDOW (0, 0)-(10, 10) on 11 x 11 pixels: world (x, y) is pixel (x, 10 - y), y up */
static void test_screen_map(void **state) {
    (void)state;
    pc_canvas *cv = pc_canvas_new(11, 11, 16);
    assert_int_equal(pc_window(cv, 0, 0, 10, 10, 0), PC_OK);
    pc_map m;
    pc_screen_map(cv, NULL, &m);
    double h[3] = {2, 3, 1}, o[3];
    pc_map_apply(&m, h, o);
    assert_float_equal(o[0] / o[2], 2, 1e-12);
    assert_float_equal(o[1] / o[2], 7, 1e-12);
    pc_canvas_free(cv);
}

/* a perspective-like map (x, y, z) -> (x, y) / (z + 1): images, infinity, another dimension */
static void test_image_xy(void **state) {
    (void)state;
    pc_map f;
    double axes[6] = {1, 0, 0, 1, 0, 0}, o[2] = {0, 0};
    assert_int_equal(pc_map_frame(&f, 2, 3, o, axes), PC_OK);
    PC_MAP_AT(&f, 2, 2) = 1;   /* w' = z + w */
    double x, y, h[4] = {2, 4, 1, 1}, far[4] = {2, 4, -1, 1}, flat[3] = {1, 1, 1};
    assert_int_equal(pc_map_image_xy(&f, 3, h, &x, &y), PC_OK);
    assert_float_equal(x, 1, 1e-15);
    assert_float_equal(y, 2, 1e-15);
    assert_int_equal(pc_map_image_xy(&f, 3, far, &x, &y), PC_IMPROPER);
    assert_int_equal(pc_map_image_xy(&f, 2, flat, &x, &y), PC_EDIM);
    assert_int_equal(pc_map_image_xy(NULL, 3, h, &x, &y), PC_EDIM);
    /* a drawn point's place: 2-D as it is (the camera is for n-D points), n-D through it */
    double w2[3] = {3, -6, 2};
    assert_int_equal(pc_place_xy(&f, 2, w2, &x, &y), PC_OK);
    assert_float_equal(x, 1.5, 1e-15);
    assert_float_equal(y, -3, 1e-15);
    assert_int_equal(pc_place_xy(&f, 3, h, &x, &y), PC_OK);
    assert_float_equal(x, 1, 1e-15);
    assert_int_equal(pc_place_xy(NULL, 3, h, &x, &y), PC_EDIM);
    /* a list element's place and why it has none */
    double xy[2], one[3] = {4, 6, 1}, vec[3] = {1, 1, 0};
    char why[200];
    assert_int_equal(pc_place_why(&f, 2, one, xy, why, sizeof why), PC_OK);
    assert_float_equal(xy[0], 4, 1e-15);
    assert_float_equal(xy[1], 6, 1e-15);
    assert_int_equal(pc_place_why(&f, 2, w2, xy, why, sizeof why), PC_EARG);
    assert_string_equal(why, ": %s has weight 2, not 1: a location must be a point (the membership condition; "
                             "normalize(p) for a projective point)");
    assert_int_equal(pc_place_why(&f, 2, vec, xy, why, sizeof why), PC_EARG);
    assert_non_null(strstr(why, "has weight 0, not 1"));
    assert_int_equal(pc_place_why(&f, 3, h, xy, why, sizeof why), PC_OK);
    assert_float_equal(xy[1], 2, 1e-15);
    assert_int_equal(pc_place_why(&f, 3, far, xy, why, sizeof why), PC_IMPROPER);
    assert_string_equal(why, ": %s projects to infinity (it lies in the camera's vanishing plane)");
    assert_int_equal(pc_place_why(NULL, 3, h, xy, why, sizeof why), PC_EDIM);
    assert_string_equal(why, " must be a 2-D point, got the 3-D %s (3-D points need a camera)");
}

/* rows of points placed: 2-D as they are, 3-D through the camera; the first without a place */
static void test_place_rows(void **state) {
    (void)state;
    pc_map f;
    double axes[6] = {1, 0, 0, 1, 0, 0}, o[2] = {0, 0}, xy[6] = {0};
    assert_int_equal(pc_map_frame(&f, 2, 3, o, axes), PC_OK);
    PC_MAP_AT(&f, 2, 2) = 1;   /* w' = z + w */
    double flat[4] = {1.5, -2, 3, 4}, space[9] = {2, 4, 1, 6, 8, 3, 2, 4, -1};
    assert_int_equal(pc_place_rows(&f, 2, 2, flat, xy), -1);
    assert_float_equal(xy[0], 1.5, 1e-15);
    assert_float_equal(xy[3], 4, 1e-15);
    assert_int_equal(pc_place_rows(&f, 2, 3, space, xy), -1);
    assert_float_equal(xy[0], 1, 1e-15);
    assert_float_equal(xy[1], 2, 1e-15);
    assert_float_equal(xy[2], 1.5, 1e-15);
    assert_float_equal(xy[3], 2, 1e-15);
    assert_int_equal(pc_place_rows(&f, 3, 3, space, xy), 2);   /* (2, 4, -1): to infinity */
    assert_int_equal(pc_place_rows(NULL, 1, 3, space, xy), 0);   /* 3-D without a camera */
    assert_int_equal(pc_place_rows(NULL, 0, 3, NULL, xy), -1);
}

/* a straight segment from (0, 0) to (8, 0) flattened in 4 parts: one unbroken polyline from
 * end to end, the joins kept once */
static void test_flatten_parts(void **state) {
    (void)state;
    double cp[] = {0, 0, 1, 8, 0, 1};
    int st;
    pc_curve *c = pc_curve_bezier(2, 2, cp, &st);
    assert_non_null(c);
    pc_polyline pl = {0};
    assert_int_equal(pc_curve_flatten_parts(c, 0, 1, 4, NULL, 0.25, &pl), PC_OK);
    assert_true(pl.n >= 2);
    assert_float_equal(pl.xy[0], 0, 1e-12);
    assert_float_equal(pl.xy[2 * pl.n - 2], 8, 1e-12);
    for (size_t i = 1; i < pl.n; i++) {
        assert_true(pl.xy[2 * i] > pl.xy[2 * i - 2]);   /* no vertex twice */
        assert_float_equal(pl.xy[2 * i + 1], 0, 1e-12);
    }
    assert_int_equal(pc_polyline_broken(&pl), 0);
    pc_polyline_free(&pl);
    pc_curve_release(c);
}

/* a 3-D curve needs a map to the plane */
static void test_flatten_needs_map(void **state) {
    (void)state;
    double cp[] = {0, 0, 0, 1, 1, 1, 1, 1};
    int st;
    pc_curve *c = pc_curve_bezier(3, 2, cp, &st);
    pc_polyline pl = {0};
    assert_int_equal(pc_curve_flatten_parts(c, 0, 1, 1, NULL, 0.25, &pl), PC_EDIM);
    assert_int_equal((int)pl.n, 0);
    pc_curve_release(c);
}

/* c:flatten's map: to the plane from the curve's dimension, needed for a 3-D curve */
static void test_flatten_checked(void **state) {
    (void)state;
    double cp[] = {0, 0, 0, 1, 1, 1, 1, 1}, axes[6] = {1, 0, 0, 1, 0, 0}, o[2] = {0, 0};
    int st;
    pc_curve *c = pc_curve_bezier(3, 2, cp, &st);
    pc_map cam3, plane;
    assert_int_equal(pc_map_frame(&cam3, 2, 3, o, axes), PC_OK);
    pc_map_identity(&plane, 2);
    pc_polyline pl = {0};
    pc_why_call w;
    assert_int_equal(pc_curve_flatten_checked("c:flatten", c, NULL, 1e-3, &pl, &w), PC_EDIM);
    assert_string_equal(w.row[0].op, "c:flatten");
    assert_int_equal(w.row[0].arg, 0);
    assert_string_equal(w.row[0].text, "a 3-D curve needs a map to the plane (argument #2)");
    assert_int_equal(pc_curve_flatten_checked("c:flatten", c, &plane, 1e-3, &pl, &w), PC_EDIM);
    assert_int_equal(w.row[0].arg, 2);
    assert_string_equal(w.row[0].text, "must be a map from 3-D to 2-D");
    assert_int_equal((int)pl.n, 0);
    assert_int_equal(pc_curve_flatten_checked("c:flatten", c, &cam3, 1e-3, &pl, &w), PC_OK);
    assert_null(w.row[0].op);
    assert_int_equal((int)pl.n, 2);   /* a straight segment: its two ends */
    assert_float_equal(pl.xy[2], 1, 1e-15);
    assert_float_equal(pl.xy[3], 1, 1e-15);
    pc_polyline_free(&pl);
    pc_curve_release(c);
}

/* the segment from world (1, 5) to (9, 5) under WINDOW lands on row 5, pixels 1..9 */
static void test_stroke(void **state) {
    (void)state;
    pc_canvas *cv = pc_canvas_new(11, 11, 16);
    assert_int_equal(pc_window(cv, 0, 0, 10, 10, 0), PC_OK);
    double cp[] = {1, 5, 1, 9, 5, 1};
    int st;
    pc_curve *c = pc_curve_bezier(2, 2, cp, &st);
    pc_polyline pl = {0};
    assert_int_equal(pc_curve_flatten_screen(cv, c, NULL, 1, 0.25, &pl), PC_OK);
    assert_null(pl.clip);
    assert_float_equal(pl.xy[0], 1, 1e-12);
    assert_float_equal(pl.xy[1], 5, 1e-12);
    assert_int_equal(pc_polyline_stroke(cv, &pl, 12, 0), PC_OK);
    for (int x = 0; x < 11; x++) assert_int_equal(pc_point(cv, x, 5), x >= 1 && x <= 9 ? 12 : 0);
    assert_int_equal(pc_point(cv, 5, 4), 0);
    pc_polyline_free(&pl);
    assert_int_equal(pc_polyline_stroke(cv, &pl, 12, 0), PC_OK);   /* nothing to draw */
    pc_curve_release(c);
    pc_canvas_free(cv);
}

/* pc_curve_draw strokes the segment from world (1, 5) to (9, 5) on row 5, pixels 1..9; a 3-D
 * curve without a map is refused with the status alone */
static void test_curve_draw(void **state) {
    (void)state;
    pc_canvas *cv = pc_canvas_new(11, 11, 16);
    assert_int_equal(pc_window(cv, 0, 0, 10, 10, 0), PC_OK);
    double cp[] = {1, 5, 1, 9, 5, 1}, cp3[] = {0, 0, 0, 1, 1, 1, 1, 1};
    int st;
    char why[200];
    pc_curve *c = pc_curve_bezier(2, 2, cp, &st), *c3 = pc_curve_bezier(3, 2, cp3, &st);
    assert_int_equal(pc_curve_draw(cv, NULL, 0, c, NULL, 1, 0.25, 12, 0, why, sizeof why), PC_OK);
    assert_string_equal(why, "");
    for (int x = 0; x < 11; x++) assert_int_equal(pc_point(cv, x, 5), x >= 1 && x <= 9 ? 12 : 0);
    assert_int_equal(pc_point(cv, 5, 6), 0);
    assert_int_equal(pc_curve_draw(cv, NULL, 0, c3, NULL, 1, 0.25, 12, 0, why, sizeof why), PC_EDIM);
    assert_string_equal(why, "");
    pc_curve_release(c);
    pc_curve_release(c3);
    pc_canvas_free(cv);
}

/* the map for a dim-D object: a given map checked, else the camera of that dimension */
static void test_drawing_map(void **state) {
    (void)state;
    pc_map cam3, plane;
    double axes[6] = {1, 0, 0, 1, 0, 0}, o[2] = {0, 0};
    assert_int_equal(pc_map_frame(&cam3, 2, 3, o, axes), PC_OK);
    pc_map_identity(&plane, 2);
    char why[160];
    assert_ptr_equal(pc_drawing_map(&cam3, 1, NULL, 3, why, sizeof why), &cam3);
    assert_null(pc_drawing_map(&cam3, 1, NULL, 2, why, sizeof why));
    assert_string_equal(why, "map must be a map from 2-D to 2-D");
    assert_null(pc_drawing_map(NULL, 1, &cam3, 3, why, sizeof why));
    assert_string_equal(why, "map must be a map from 3-D to 2-D");
    assert_ptr_equal(pc_drawing_map(NULL, 0, &cam3, 3, why, sizeof why), &cam3);
    assert_null(pc_drawing_map(NULL, 0, &cam3, 2, why, sizeof why));   /* a 3-D camera: 2-D as it is */
    assert_string_equal(why, "");
    assert_ptr_equal(pc_drawing_map(NULL, 0, &plane, 2, why, sizeof why), &plane);
    assert_null(pc_drawing_map(NULL, 0, NULL, 3, why, sizeof why));
    assert_string_equal(why, "a 3-D object needs a projection: set one with camera(f) or give map = f");
    assert_null(pc_drawing_map(NULL, 0, &plane, 3, why, sizeof why));
    assert_string_equal(why, "the camera takes 2-D points, but this is 3-D");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_screen_map),
        cmocka_unit_test(test_image_xy),
        cmocka_unit_test(test_flatten_parts),
        cmocka_unit_test(test_place_rows),
        cmocka_unit_test(test_flatten_needs_map),
        cmocka_unit_test(test_flatten_checked),
        cmocka_unit_test(test_stroke),
        cmocka_unit_test(test_curve_draw),
        cmocka_unit_test(test_drawing_map),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
