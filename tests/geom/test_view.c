/* Views with z up (view.h): map.view orthographic and perspective, azimuth and elevation; and
 * silhouettes: a sphere's is its outline circle, seen from afar and from near. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdlib.h>
#include <cmocka.h>
#include <math.h>
#include "view.h"

static int sphere_fn(void *ud, double u, double v, int order, double *out) {
    double R = *(const double *)ud;
    out[0] = R * cos(u) * cos(v); out[1] = R * sin(u) * cos(v); out[2] = R * sin(v); out[3] = 1;
    if (order > 0) {   /* d/du, d/dv */
        out[4] = -R * sin(u) * cos(v); out[5] = R * cos(u) * cos(v); out[6] = 0; out[7] = 0;
        out[8] = -R * cos(u) * sin(v); out[9] = -R * sin(u) * sin(v); out[10] = R * cos(v); out[11] = 0;
    }
    return PC_OK;
}

static void apply2(const pc_map *f, double x, double y, double z, double out[2]) {
    double h[4] = {x, y, z, 1}, o[3];
    pc_map_apply(f, h, o);
    out[0] = o[0] / o[2];
    out[1] = o[1] / o[2];
}

static void test_view_z_up(void **state) {
    (void)state;
    pc_map f;
    double p[2];
    /* from the -y side looking at the origin: x to the right, z up */
    double from[3] = {0, -10, 0}, to[3] = {0, 0, 0};
    assert_int_equal(pc_map_view(&f, from, to, NULL, 0), PC_OK);
    apply2(&f, 1, 0, 0, p);
    assert_true(fabs(p[0] - 1) < 1e-15 && fabs(p[1]) < 1e-15);
    apply2(&f, 0, 0, 1, p);
    assert_true(fabs(p[0]) < 1e-15 && fabs(p[1] - 1) < 1e-15);
    apply2(&f, 0, 5, 0, p);   /* depth does not show in a parallel view */
    assert_true(fabs(p[0]) < 1e-15 && fabs(p[1]) < 1e-15);
    /* the same view in perspective: the target plane keeps lengths, farther is smaller */
    assert_int_equal(pc_map_view(&f, from, to, NULL, 1), PC_OK);
    apply2(&f, 1, 0, 1, p);
    assert_true(fabs(p[0] - 1) < 1e-14 && fabs(p[1] - 1) < 1e-14);
    apply2(&f, 1, 10, 1, p);   /* twice as far from the eye */
    assert_true(fabs(p[0] - 0.5) < 1e-14 && fabs(p[1] - 0.5) < 1e-14);
    /* azimuth -90, elevation 0 is the same place as from = (0, -10, 0) */
    pc_map g;
    assert_int_equal(pc_map_view_azel(&g, to, -90, 0, 10, 0), PC_OK);
    apply2(&g, 1, 0, 1, p);
    assert_true(fabs(p[0] - 1) < 1e-12 && fabs(p[1] - 1) < 1e-12);
    /* from straight above: x right, y up in the picture at azimuth -90 */
    assert_int_equal(pc_map_view_azel(&g, to, -90, 90, 10, 0), PC_OK);
    apply2(&g, 1, 0, 0, p);
    assert_true(fabs(p[0] - 1) < 1e-12 && fabs(p[1]) < 1e-12);
    apply2(&g, 0, 1, 0, p);
    assert_true(fabs(p[0]) < 1e-12 && fabs(p[1] - 1) < 1e-12);
    assert_int_equal(pc_map_view(&f, to, to, NULL, 0), PC_ECOINCIDENT);
    double up[3] = {0, 1, 0};
    assert_int_equal(pc_map_view(&f, from, to, up, 0), PC_ECOLLINEAR);
}

/* The silhouette of a sphere of radius 2 seen along the x axis is the circle y^2 + z^2 = 4
 * in the plane x = 0; from an eye at distance 8 it is the circle of the tangent cone: in the
 * plane x = R^2/8 = 0.5, radius R sqrt(1 - R^2/64) = sqrt(3.75). */
static void check_circle(double *xyz, size_t n, double x0, double r) {
    assert_true(n > 40);
    double len = 0;
    for (size_t i = 0; i < n; i++)
        for (int e = 0; e < 2; e++) {
            const double *p = xyz + 6 * i + 3 * e;
            assert_true(fabs(p[0] - x0) < 1e-6);
            assert_true(fabs(hypot(p[1], p[2]) - r) < 1e-6);
        }
    for (size_t i = 0; i < n; i++) {
        const double *p = xyz + 6 * i;
        len += sqrt((p[3] - p[0]) * (p[3] - p[0]) + (p[4] - p[1]) * (p[4] - p[1]) + (p[5] - p[2]) * (p[5] - p[2]));
    }
    assert_true(fabs(len - 2 * M_PI * r) < 2e-3 * 2 * M_PI * r);   /* closed all round */
}

static void test_sphere_silhouette(void **state) {
    (void)state;
    double R = 2;
    int st;
    pc_surface *s = pc_surface_func(3, 0, 2 * M_PI, -M_PI / 2, M_PI / 2, sphere_fn, NULL, &R, &st);
    assert_non_null(s);
    pc_map f;
    double from[3] = {8, 0, 0}, to[3] = {0, 0, 0};
    double *xyz;
    size_t n;
    assert_int_equal(pc_map_view(&f, from, to, NULL, 0), PC_OK);
    assert_int_equal(pc_surface_silhouette(s, &f, 64, 32, &xyz, &n), PC_OK);
    check_circle(xyz, n, 0, 2);
    free(xyz);
    assert_int_equal(pc_map_view(&f, from, to, NULL, 1), PC_OK);
    assert_int_equal(pc_surface_silhouette(s, &f, 64, 32, &xyz, &n), PC_OK);
    check_circle(xyz, n, 0.5, sqrt(3.75));
    free(xyz);
    assert_int_equal(pc_surface_silhouette(s, &f, 1, 32, &xyz, &n), PC_EDOMAIN);
    pc_surface_release(s);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_view_z_up),
        cmocka_unit_test(test_sphere_silhouette),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
