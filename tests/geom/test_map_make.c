/* The maps made of numbers by kind (map_make.h): each the same map as its own constructor,
 * with the images the textbook gives, and the why-table's rows for the statuses they return. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "map_make.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))
static const double PI = 3.14159265358979323846;

/* the image of the 3-D point (x, y, z) under f, Cartesian */
static void xy(const pc_map *f, double x, double y, double z, double *out) {
    double in[4] = {x, y, z, 1}, h[PC_MAXDIM + 1];
    pc_map_image(f, in, h);
    for (int i = 0; i < f->nout; i++) out[i] = h[i] / h[f->nout];
}

static void same_as_constructors(void **state) {
    (void)state;
    pc_map f, g;
    double x[3] = {3}, o[3];
    assert_int_equal(pc_map_make(&f, PC_MM_IDENTITY, x), PC_OK);
    assert_int_equal(f.nin, 3);
    xy(&f, 1, 2, 3, o);
    NEAR(o[0], 1, 0); NEAR(o[1], 2, 0); NEAR(o[2], 3, 0);
    x[0] = 1;                                       /* "y": keeps (x, z) */
    assert_int_equal(pc_map_make(&f, PC_MM_ORTHOGRAPHIC, x), PC_OK);
    xy(&f, 1, 2, 3, o);
    NEAR(o[0], 1, 0); NEAR(o[1], 3, 0);
    /* cabinet: z recedes at half length, 45 deg */
    assert_int_equal(pc_map_make(&f, PC_MM_CABINET, (double[]){PI / 4}), PC_OK);
    xy(&f, 0, 0, 2, o);
    NEAR(o[0], sqrt(0.5), 1e-15); NEAR(o[1], sqrt(0.5), 1e-15);
    assert_int_equal(pc_map_make(&g, PC_MM_OBLIQUE, (double[]){0.5, PI / 4}), PC_OK);
    xy(&g, 0, 0, 2, x);
    NEAR(o[0], x[0], 0); NEAR(o[1], x[1], 0);
    assert_int_equal(pc_map_make(&f, PC_MM_CAVALIER, (double[]){0}), PC_OK);
    xy(&f, 0, 0, 2, o);
    NEAR(o[0], 2, 1e-15); NEAR(o[1], 0, 1e-15);
    assert_int_equal(pc_map_make(&f, PC_MM_ISOMETRIC, x), PC_OK);
    pc_map_axonometric(&g, PI / 4, asin(tan(PI / 6)));
    xy(&f, 1, 1, 1, o);
    xy(&g, 1, 1, 1, x);
    NEAR(o[0], x[0], 1e-12); NEAR(o[1], x[1], 1e-12);
    assert_int_equal(pc_map_make(&f, PC_MM_PERSPECTIVE_PQR, (double[]){0, 0, 0.5}), PC_OK);
    xy(&f, 1, 1, 2, o);                             /* h = 0.5 z + 1 = 2 */
    NEAR(o[0], 0.5, 1e-15); NEAR(o[2], 1, 1e-15);
}

static void statuses_explained(void **state) {
    (void)state;
    pc_map f;
    assert_int_equal(pc_map_make(&f, PC_MM_IDENTITY, (double[]){0}), PC_EDOMAIN);
    assert_int_equal(pc_map_make(&f, PC_MM_ORTHOGRAPHIC, (double[]){3}), PC_EDOMAIN);
    int st = pc_map_make(&f, PC_MM_DIMETRIC, (double[]){1.5});
    assert_int_equal(st, PC_EDOMAIN);
    const pc_why *w = pc_why_find(pc_map_why, "map.dimetric", st);
    assert_non_null(w);
    assert_int_equal(w->arg, 1);
    assert_int_equal(pc_map_make(&f, PC_MM_DIMETRIC, (double[]){0.5}), PC_OK);
    double zero[2] = {0, 0}, d[3] = {1, 0, 0}, m[9] = {0};
    st = pc_map_axial_affinity(&f, zero, d, d, 2);
    assert_non_null(strstr(pc_why_find(pc_map_why, "map.axial_affinity", st)->text, "along the axis"));
    st = pc_map_axial_affinity(&f, zero, zero, d, 2);
    assert_non_null(strstr(pc_why_find(pc_map_why, "map.axial_affinity", st)->text, "not be zero"));
    st = pc_map_from_matrix(&f, 2, 2, m, 0);
    assert_non_null(strstr(pc_why_find(pc_map_why, "map.matrix", st)->text, "zero matrix"));
    pc_map s, inv;
    pc_map_scale(&s, 2, (double[]){1, 0}, NULL);
    st = pc_map_inverse(&s, &inv);
    assert_non_null(strstr(pc_why_find(pc_map_why, "f:inverse", st)->text, "singular"));
    pc_map_perspective_pqr(&f, 0, 0, 1);
    st = pc_map_foreshortening(&f, d);
    assert_non_null(pc_why_find(pc_map_why, "map.foreshortening", st));
    st = pc_map_shear(&f, 3, 1, 1, 2.0);                    /* one axis twice */
    assert_int_equal(st, PC_EDOMAIN);
    assert_string_equal(pc_why_find(pc_map_why, "map.shear", st)->text,
                        "arguments #2 and #3 (i, j) name the same axis; a shear adds k times axis j to axis i");
}

static void translate_finite(void **state) {
    (void)state;
    pc_map f;
    double v[2] = {1, -2}, o[3];
    assert_int_equal(pc_map_translate_finite(&f, 2, v), PC_OK);
    double in[3] = {3, 4, 1};
    pc_map_image(&f, in, o);
    NEAR(o[0], 4, 0); NEAR(o[1], 2, 0); NEAR(o[2], 1, 0);
    v[1] = INFINITY;
    int st = pc_map_translate_finite(&f, 2, v);
    assert_int_equal(st, PC_ENONFINITE);
    assert_int_equal(pc_why_find(pc_map_why, "map.translate", st)->arg, 1);
}

static void unit_names(void **state) {
    (void)state;
    assert_int_equal(pc_map_unit_name("C0"), 0);
    assert_int_equal(pc_map_unit_name("C3"), 3);
    assert_int_equal(pc_map_unit_name("C12"), 12);
    assert_int_equal(pc_map_unit_name("C01"), -1);
    assert_int_equal(pc_map_unit_name("C"), -1);
    assert_int_equal(pc_map_unit_name("C3x"), -1);
    assert_int_equal(pc_map_unit_name("D1"), -1);
    assert_int_equal(pc_map_unit_name("C99999999999999999999"), -1);
}

static void rotate_about_axis(void **state) {
    (void)state;
    pc_map f;
    double a[3] = {1, 0, 0}, b[3] = {1, 0, 5}, up[3] = {0, 0, 2}, o[3];
    assert_int_equal(pc_map_rotate_axis(&f, a, b, 0, PI / 2), PC_OK);   /* about x = 1, y = 0 */
    xy(&f, 2, 0, 7, o);
    NEAR(o[0], 1, 1e-15); NEAR(o[1], 1, 1e-15); NEAR(o[2], 7, 1e-15);
    assert_int_equal(pc_map_rotate_axis(&f, a, up, 1, PI), PC_OK);      /* along the direction z */
    xy(&f, 2, 0, 0, o);
    NEAR(o[0], 0, 1e-15); NEAR(o[1], 0, 1e-15);
    assert_int_equal(pc_map_rotate_axis(&f, a, a, 0, 1), PC_ECOINCIDENT);
    double zero[3] = {0, 0, 0};
    assert_int_equal(pc_map_rotate_axis(&f, a, zero, 1, 1), PC_EZERO);
    assert_non_null(pc_why_find(pc_map_why, "map.rotate", PC_ECOINCIDENT));
    assert_non_null(pc_why_find(pc_map_why, "map.rotate", PC_EZERO));
}

static void affine_counts(void **state) {
    (void)state;
    pc_map f;
    pc_why_call w;
    double src[6] = {0, 0, 1, 0, 0, 1}, dst[6] = {1, 1, 2, 1, 1, 2}, o[2];
    assert_int_equal(pc_map_affine_checked(&f, 3, 2, 3, 2, src, dst, &w), PC_OK);
    double in[3] = {3, 3, 1}, h[3];
    pc_map_image(&f, in, h);
    o[0] = h[0] / h[2], o[1] = h[1] / h[2];
    NEAR(o[0], 4, 1e-15); NEAR(o[1], 4, 1e-15);
    assert_int_equal(pc_map_affine_checked(&f, 1, 2, 1, 2, src, dst, &w), PC_EDIM);
    assert_int_equal(w.row[0].arg, 1);
    assert_string_equal(w.row[0].text, "holds 1 points; a map of n-D needs n + 1 (3 in the plane, 4 in space)");
    assert_int_equal(pc_map_affine_checked(&f, 2, 2, 2, 2, src, dst, &w), PC_EDIM);
    assert_string_equal(w.row[0].text, "holds 2 2-D points; a map of 2-D needs 3 (dimension + 1)");
    assert_int_equal(pc_map_affine_checked(&f, 3, 2, 2, 2, src, dst, &w), PC_EDIM);
    assert_int_equal(w.row[0].arg, 2);
    double line[6] = {0, 0, 1, 0, 2, 0};
    assert_int_not_equal(pc_map_affine_checked(&f, 3, 2, 3, 2, line, dst, &w), PC_OK);
    assert_non_null(strstr(w.row[0].text, "collinear"));
}

static void kinds_named(void **state) {
    (void)state;
    assert_int_equal(pc_map_kind_named("identity"), PC_MM_IDENTITY);
    assert_int_equal(pc_map_kind_named("isometric"), PC_MM_ISOMETRIC);
    assert_int_equal(pc_map_kind_named("cabinet"), PC_MM_CABINET);
    assert_int_equal(pc_map_kind_named("perspective_pqr"), PC_MM_PERSPECTIVE_PQR);
    assert_int_equal(pc_map_kind_named("perspective"), -1);
    assert_int_equal(pc_map_kind_named(""), -1);
    pc_map f;
    double o[3];
    assert_int_equal(pc_map_make(&f, pc_map_kind_named("cavalier"), (double[]){0}), PC_OK);
    xy(&f, 1, 2, 3, o);
    NEAR(o[0], 4, 1e-12);
    NEAR(o[1], 2, 1e-12);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(same_as_constructors), cmocka_unit_test(kinds_named), cmocka_unit_test(statuses_explained),
        cmocka_unit_test(translate_finite), cmocka_unit_test(unit_names),
        cmocka_unit_test(rotate_about_axis), cmocka_unit_test(affine_counts),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
