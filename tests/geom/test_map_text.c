/* A map as text and the image by the one weight rule (map_text.c, weight_rule.c): the exact
 * lines tostring(f) and f:show() print (the rounding noise of cos 90 degrees kept by tostring,
 * shown as 0 by show),
 * a truncated buffer, the weight snapped within 1e-9 and a weight of 1e-17 read as a direction
 * (the vanishing point of a calibrated camera), the pole of a central projection. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "map.h"

static void test_text(void **state) {
    (void)state;
    pc_map f;
    double c[2] = {1, 1};
    pc_map_rotate2(&f, M_PI / 2, c);
    char buf[256];
    size_t len = pc_map_text(&f, buf, sizeof buf);
    assert_string_equal(buf, "affine map 2-D -> 2-D [6.1232339957368e-17 -1 | 2; 1 6.1232339957368e-17 | -6.1232339957368e-17]");
    assert_int_equal(len, strlen(buf));
    char small[12];
    assert_int_equal(pc_map_text(&f, small, sizeof small), len);   /* the length it needs */
    assert_string_equal(small, "affine map ");
    pc_map_show(&f, 0, buf, sizeof buf);
    assert_string_equal(buf, "affine map 2-D -> 2-D, column vectors p' = M p:\n"
                             "   0  -1  | 2\n   1   0  | 0\n   0   0  | 1");
    double v[2] = {1, 2};
    pc_map_translate(&f, 2, v);
    pc_map_show(&f, 1, buf, sizeof buf);
    assert_string_equal(buf, "affine map 2-D -> 2-D, row vectors p' = p T:\n"
                             "   1  0  | 0\n   0  1  | 0\n   1  2  | 1");
}

static void test_weight_rule(void **state) {
    (void)state;
    double h[3] = {2 * (1 + 1e-12), 4 * (1 + 1e-12), 1 + 1e-12};
    assert_int_equal(pc_snap_weight(2, h), PC_KIND_POINT);
    assert_true(h[2] == 1 && fabs(h[0] - 2) < 1e-15 && fabs(h[1] - 4) < 1e-15);
    double d[3] = {1, 0, 1e-17};
    assert_int_equal(pc_snap_weight(2, d), PC_KIND_VECTOR);
    assert_true(d[2] == 0 && d[0] == 1);
    double w[3] = {1, 0, 2};
    assert_int_equal(pc_snap_weight(2, w), PC_KIND_WEIGHTED);
    assert_true(w[2] == 2 && w[0] == 1);

    /* map.matrix({{1, 0, 0}, {0, 1, 0}, {0, 1e-17, 1}}): V(0, 1) stays the direction V(0, 1) */
    pc_map f;
    double m[9] = {1, 0, 0, 0, 1, 0, 0, 1e-17, 1};
    assert_int_equal(pc_map_from_matrix(&f, 2, 2, m, 0), PC_OK);
    double in[3] = {0, 1, 0}, out[3];
    assert_int_equal(pc_map_image_rule(&f, in, out), PC_OK);
    assert_true(out[0] == 0 && out[1] == 1 && out[2] == 0);
    /* a point through it stays a point, weight exactly 1 */
    double p[3] = {3, 4, 1};
    assert_int_equal(pc_map_image_rule(&f, p, out), PC_OK);
    assert_true(out[2] == 1 && fabs(out[0] - 3) < 1e-12 && fabs(out[1] - 4) < 1e-12);
    /* a central projection: the eye has no image */
    double eye[3] = {0, -10, 2}, p0[3] = {0, 0, 0}, e4[4] = {0, -10, 2, 1}, o[3];
    assert_int_equal(pc_map_perspective(&f, eye, p0, NULL), PC_OK);
    assert_int_equal(pc_map_image_rule(&f, e4, o), PC_EPOLE);
}

/* map.scale(1e308, 2)(P(10, 10)): the image overflows, an error, never P(inf, inf) */
static void test_image_overflow(void **state) {
    (void)state;
    pc_map f;
    double m[9] = {1e308, 0, 0, 0, 2, 0, 0, 0, 1}, p[3] = {10, 10, 1}, out[3];
    assert_int_equal(pc_map_from_matrix(&f, 2, 2, m, 0), PC_OK);
    assert_int_equal(pc_map_image_rule(&f, p, out), PC_ENONFINITE);
    p[0] = 1;   /* 1e308 * 1 is finite */
    assert_int_equal(pc_map_image_rule(&f, p, out), PC_OK);
    assert_true(out[0] == 1e308 && out[1] == 20 && out[2] == 1);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_text),
        cmocka_unit_test(test_weight_rule),
        cmocka_unit_test(test_image_overflow),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
