/* The parts of a map the bindings show (map_parts.c): unit images, vanishing points, what the
 * constructors' failures mean, and a matrix without -0. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "map.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_unit_image(void **state) {
    (void)state;
    pc_map f;
    pc_map_oblique(&f, 0.5, 0);                  /* x' = x + z/2, y' = y */
    double o[3];
    assert_int_equal(pc_map_unit_image(&f, 0, o), PC_OK);
    NEAR(o[0], 0, 0); NEAR(o[1], 0, 0); NEAR(o[2], 1, 0);
    assert_int_equal(pc_map_unit_image(&f, 3, o), PC_OK);   /* C3 = (0, 0, 1) -> (0.5, 0) */
    NEAR(o[0], 0.5, 1e-15); NEAR(o[1], 0, 1e-15); NEAR(o[2], 1, 0);
    assert_int_equal(pc_map_unit_image(&f, 4, o), PC_EDOMAIN);
    assert_int_equal(pc_map_unit_image(&f, -1, o), PC_EDOMAIN);
}

static void test_vanishing(void **state) {
    (void)state;
    pc_map f;
    double v[3][PC_MAXDIM + 1];
    int finite[3];
    assert_int_equal(pc_map_perspective_pqr(&f, 0, 0, 0.5), PC_OK);   /* one-point: z -> (0, 0, 2) */
    assert_int_equal(pc_map_vanishing_points(&f, v, finite), PC_OK);
    assert_int_equal(finite[0], 0); assert_int_equal(finite[1], 0); assert_int_equal(finite[2], 1);
    NEAR(v[2][0], 0, 1e-15); NEAR(v[2][1], 0, 1e-15); NEAR(v[2][2], 2, 1e-15); NEAR(v[2][3], 1, 0);
    pc_map_rotate2(&f, 1, NULL);
    assert_int_equal(pc_map_vanishing_points(&f, v, finite), PC_EDIM);
}

static void test_why(void **state) {
    (void)state;
    assert_string_equal(pc_map_points_why(PC_ECOLLINEAR, 2),
                        "the source points are collinear, so they do not fix an affine map");
    assert_string_equal(pc_map_points_why(PC_ECOLLINEAR, 3),
                        "the source points are coplanar, so they do not fix an affine map");
    assert_string_equal(pc_map_points_why(PC_ECOINCIDENT, 1),
                        "the source points coincide, so they do not fix an affine map");
    assert_string_equal(pc_map_points_why(PC_EDIM, 2), pc_strerror(PC_EDIM));
    assert_string_equal(pc_map_perspective_why(PC_ECOINCIDENT, 0),
                        "the eye and p0 coincide, so there is no direction of view");
    assert_non_null(strstr(pc_map_perspective_why(PC_ECOLLINEAR, 0), "the default up, the z axis,"));
    assert_non_null(strstr(pc_map_perspective_why(PC_ECOLLINEAR, 1), "argument #3 (up) is along"));
    assert_string_equal(pc_map_perspective_why(PC_ENONFINITE, 1), pc_strerror(PC_ENONFINITE));
    /* the failures really come from the constructors */
    pc_map f;
    const double src[6] = {0, 0, 1, 1, 2, 2}, dst[6] = {0, 0, 1, 0, 0, 1}, e[3] = {0, 0, 5}, p0[3] = {0, 0, 0};
    assert_int_equal(pc_map_affine_points(&f, 2, 2, src, dst), PC_ECOLLINEAR);
    assert_int_equal(pc_map_perspective(&f, e, p0, NULL), PC_ECOLLINEAR);
}

static void test_no_negative_zero(void **state) {
    (void)state;
    pc_map f;
    const double m[9] = {-0.0, 1, 0, 1, -0.0, 0, 0, 0, 1};
    assert_int_equal(pc_map_from_matrix(&f, 2, 2, m, 0), PC_OK);
    double a[9];
    pc_map_to_matrix(&f, 1, a);
    for (int i = 0; i < 9; i++) assert_false(signbit(a[i]));
    NEAR(a[1], 1, 0); NEAR(a[3], 1, 0);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_unit_image), cmocka_unit_test(test_vanishing), cmocka_unit_test(test_why),
        cmocka_unit_test(test_no_negative_zero),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
