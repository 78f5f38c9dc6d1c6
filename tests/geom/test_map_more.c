/* The textbook's perspective by (p, q, r), foreshortening factors and the axial affinity
 * (map.h, map_more.c), with the digest's numbers (buimov_textbook.md §2.8.3-§2.8.5 and its
 * check list 15-17). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "map.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void img(const pc_map *f, double x, double y, double z, double w, double *out) {
    double in[4] = {x, y, z, w};
    pc_map_image(f, in, out);
}

static void test_pqr(void **state) {
    (void)state;
    pc_map f;
    double o[4];
    assert_int_equal(pc_map_perspective_pqr(&f, 0, 0, 0.5), PC_OK);
    img(&f, 0, 0, 1, 0, o);                      /* the z direction's vanishing point (0, 0, 2) */
    NEAR(o[3], 1, 0); NEAR(o[2], 2, 1e-15); NEAR(o[0], 0, 0);
    pc_map_perspective_pqr(&f, 0.5, 0.5, 0);     /* two-point: (1, 0, 1) -> (2/3, 0, 2/3) */
    img(&f, 1, 0, 1, 1, o);
    NEAR(o[0] / o[3], 2.0 / 3, 1e-15); NEAR(o[2] / o[3], 2.0 / 3, 1e-15);
    pc_map_perspective_pqr(&f, 0.5, 0.5, 0.5);   /* three-point: (1, 1, 1) -> (0.4, 0.4, 0.4) */
    img(&f, 1, 1, 1, 1, o);
    for (int i = 0; i < 3; i++) NEAR(o[i] / o[3], 0.4, 1e-15);
    img(&f, 1, 0, 0, 0, o);                      /* (1/p, 0, 0) */
    NEAR(o[0] / o[3], 2, 1e-15);
    assert_int_equal(pc_map_perspective_pqr(&f, NAN, 0, 0), PC_ENONFINITE);
}

static void test_foreshortening(void **state) {
    (void)state;
    pc_map f;
    double k[3];
    assert_int_equal(pc_map_dimetric(&f, 0.5), PC_OK);
    assert_int_equal(pc_map_foreshortening(&f, k), PC_OK);
    NEAR(k[0], 0.935414, 1e-6); NEAR(k[1], 0.935414, 1e-6); NEAR(k[2], 0.5, 1e-12);
    /* isometric: sqrt(2/3) on every axis */
    const double iso[12] = {0.707107, 0.408248, 0, 0, 0.816497, 0, 0.707107, -0.408248, 0, 0, 0, 1};
    /* the book's 4 x 3 row-vector matrix (z column dropped): [x y z 1] T = [x* y* 1] */
    assert_int_equal(pc_map_from_matrix(&f, 3, 2, iso, 1), PC_OK);
    assert_int_equal(pc_map_foreshortening(&f, k), PC_OK);
    for (int i = 0; i < 3; i++) NEAR(k[i], sqrt(2.0 / 3), 1e-6);
    pc_map_perspective_pqr(&f, 0, 0, 0.5);
    assert_int_equal(pc_map_foreshortening(&f, k), PC_EDOMAIN);
}

static void test_axial_affinity(void **state) {
    (void)state;
    pc_map f;
    const double a[2] = {0, 0}, d[2] = {1, 0}, s[2] = {0, 1}, s2[2] = {1, 1};
    double o[3], in[3] = {3, 4, 1};
    assert_int_equal(pc_map_axial_affinity(&f, a, d, s, 2), PC_OK);
    pc_map_image(&f, in, o);
    NEAR(o[0], 3, 1e-15); NEAR(o[1], 8, 1e-15);
    /* oblique reflection: (0, 1) = -d + s goes to -d - s = (-2, -1) */
    assert_int_equal(pc_map_axial_affinity(&f, a, d, s2, -1), PC_OK);
    double m[3] = {0, 1, 1};
    pc_map_image(&f, m, o);
    NEAR(o[0], -2, 1e-15); NEAR(o[1], -1, 1e-15);
    /* an axis off the origin keeps its points, and a point's image lies on its line along s */
    const double a2[2] = {1, 2}, d2[2] = {2, 1}, s3[2] = {-1, 3};
    assert_int_equal(pc_map_axial_affinity(&f, a2, d2, s3, 0.4), PC_OK);
    double ax[3] = {1 + 2 * 1.7, 2 + 1.7, 1}, p[3] = {4, -1, 1};
    pc_map_image(&f, ax, o);
    NEAR(o[0], ax[0], 1e-14); NEAR(o[1], ax[1], 1e-14);
    pc_map_image(&f, p, o);
    NEAR((o[0] - p[0]) * s3[1] - (o[1] - p[1]) * s3[0], 0, 1e-13);
    assert_int_equal(pc_map_axial_affinity(&f, a, d, d, 2), PC_ECOLLINEAR);
    const double z[2] = {0, 0};
    assert_int_equal(pc_map_axial_affinity(&f, a, z, s, 2), PC_EZERO);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pqr), cmocka_unit_test(test_foreshortening),
        cmocka_unit_test(test_axial_affinity),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
