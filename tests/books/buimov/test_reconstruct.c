/* Least squares (linalg.h: pc_lsq_solve) and the reconstruction of Buimov §2.8.6
 * (reconstruct.h): an exact overdetermined system, a fit against the normal equations, rank
 * deficiency; a point of space from two and from three views (the book's top view and an
 * isometric view, a perspective), noise; a camera recovered from six and more points
 * (perspective and parallel), and the degenerate cases. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "reconstruct.h"
#include "linalg.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))
static const double PI = 3.14159265358979323846;

static void lsq(void **st) {
    (void)st;
    /* consistent: 4 equations, 2 unknowns x = (2, -1) */
    double a[8] = {1, 1, 1, -1, 2, 1, 0, 3}, b[4] = {1, 3, 3, -3};
    assert_int_equal(pc_lsq_solve(4, 2, a, b), PC_OK);
    NEAR(b[0], 2, 1e-14); NEAR(b[1], -1, 1e-14); NEAR(hypot(b[2], b[3]), 0, 1e-14);
    /* a line fit y = c0 + c1 x through (0, 1), (1, 2), (2, 2), (3, 4): the normal equations
     * [4 6; 6 14] c = [9 18] give c = (0.9, 0.9); the residual is sqrt 0.7 */
    double A[8] = {1, 0, 1, 1, 1, 2, 1, 3}, y[4] = {1, 2, 2, 4};
    assert_int_equal(pc_lsq_solve(4, 2, A, y), PC_OK);
    NEAR(y[0], 0.9, 1e-14); NEAR(y[1], 0.9, 1e-14); NEAR(hypot(y[2], y[3]), sqrt(0.7), 1e-14);
    double S[6] = {1, 2, 2, 4, 3, 6}, z[3] = {1, 2, 3};
    assert_int_equal(pc_lsq_solve(3, 2, S, z), PC_ESINGULAR);
    double T[4] = {1, 2, 3, 4}, w[2] = {1, 1};
    assert_int_equal(pc_lsq_solve(1, 2, T, w), PC_EDIM);
    T[1] = NAN;
    assert_int_equal(pc_lsq_solve(2, 2, T, w), PC_ENONFINITE);
}

static void apply2(const pc_map *f, const double *x, double *xy) {
    double h[4] = {x[0], x[1], x[2], 1}, o[3];
    pc_map_apply(f, h, o);
    xy[0] = o[0] / o[2];
    xy[1] = o[1] / o[2];
}

static void reconstruct(void **st) {
    (void)st;
    pc_map v[3], top, rx, pz;
    /* the book's top view T = Rx(90) Pz: (x, y, z) -> (x, -z), and the isometric view */
    double o[3] = {0, 0, 0}, ex[3] = {1, 0, 0};
    pc_map_rotate3(&rx, o, ex, PI / 2);
    pc_map_orthographic(&pz, 'z');
    pc_map_compose(&pz, &rx, &top);
    v[0] = top;
    pc_map_isometric(&v[1]);
    double eye[3] = {6, -5, 4}, p0[3] = {0, 0, 0};
    pc_map_perspective(&v[2], eye, p0, NULL);
    double X[3] = {0.7, -1.2, 2.5}, xy[6], got[3], res;
    for (int i = 0; i < 3; i++) apply2(&v[i], X, xy + 2 * i);
    NEAR(xy[0], 0.7, 1e-15); NEAR(xy[1], -2.5, 1e-15);
    assert_int_equal(pc_reconstruct_point(2, v, xy, got, &res), PC_OK);
    for (int j = 0; j < 3; j++) NEAR(got[j], X[j], 1e-13);
    NEAR(res, 0, 1e-13);
    assert_int_equal(pc_reconstruct_point(3, v, xy, got, &res), PC_OK);   /* with a perspective */
    for (int j = 0; j < 3; j++) NEAR(got[j], X[j], 1e-12);
    assert_int_equal(pc_reconstruct_point(2, v + 1, xy + 2, got, NULL), PC_OK);
    for (int j = 0; j < 3; j++) NEAR(got[j], X[j], 1e-12);
    /* inconsistent images: a least squares compromise near X and a nonzero residual */
    double noisy[4] = {xy[0] + 1e-3, xy[1], xy[2], xy[3] - 1e-3};
    assert_int_equal(pc_reconstruct_point(2, v, noisy, got, &res), PC_OK);
    for (int j = 0; j < 3; j++) NEAR(got[j], X[j], 5e-3);
    assert_true(res > 1e-5);
    pc_map same[2] = {top, top};
    assert_int_equal(pc_reconstruct_point(2, same, xy, got, NULL), PC_ESINGULAR);
    assert_int_equal(pc_reconstruct_point(1, v, xy, got, NULL), PC_EDOMAIN);
    pc_map wrong[2];
    pc_map_identity(&wrong[0], 3);
    wrong[1] = top;
    assert_int_equal(pc_reconstruct_point(2, wrong, xy, got, NULL), PC_EDIM);
}

static void calibrate(void **st) {
    (void)st;
    /* a perspective camera, scaled and moved on the screen; eight points of a box */
    pc_map persp, scr, cam, got;
    double eye[3] = {5, -7, 4}, p0[3] = {0.5, 0.5, 0.5};
    pc_map_perspective(&persp, eye, p0, NULL);
    double k[2] = {200, -200}, t[2] = {320, 240};
    pc_map_scale(&scr, 2, k, NULL);
    pc_map tr;
    pc_map_translate(&tr, 2, t);
    pc_map s2;
    pc_map_compose(&tr, &scr, &s2);
    pc_map_compose(&s2, &persp, &cam);
    double xyz[24] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1.5};
    double xy[16], rms;
    for (int i = 0; i < 8; i++) apply2(&cam, xyz + 3 * i, xy + 2 * i);
    for (int n = 6; n <= 8; n++) {
        assert_int_equal(pc_calibrate_camera(n, xyz, xy, &got, &rms), PC_OK);
        NEAR(rms, 0, 1e-9);
        NEAR(PC_MAP_AT(&got, 2, 3), 1, 0);                 /* T44 = 1 */
        for (int i = 0; i < 12; i++)                        /* the camera up to its scale */
            NEAR(got.m[i], cam.m[i] / PC_MAP_AT(&cam, 2, 3), 1e-9 * (1 + fabs(got.m[i])));
        double q[3] = {0.3, 2, -1}, a[2], b[2];            /* and any other point */
        apply2(&got, q, a); apply2(&cam, q, b);
        NEAR(a[0], b[0], 1e-9); NEAR(a[1], b[1], 1e-9);
    }
    /* a parallel (affine) camera: the isometric view */
    pc_map iso;
    pc_map_isometric(&iso);
    for (int i = 0; i < 8; i++) apply2(&iso, xyz + 3 * i, xy + 2 * i);
    assert_int_equal(pc_calibrate_camera(8, xyz, xy, &got, &rms), PC_OK);
    for (int i = 0; i < 12; i++) NEAR(got.m[i], iso.m[i], 1e-12);
    /* noise: a fit with a small rms */
    xy[3] += 1e-3;
    assert_int_equal(pc_calibrate_camera(8, xyz, xy, &got, &rms), PC_OK);
    assert_true(rms > 1e-6 && rms < 1e-3);
    /* six coplanar points do not fix a camera */
    double flat[18] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0, 1, 3, 0};
    assert_int_equal(pc_calibrate_camera(6, flat, xy, &got, &rms), PC_ESINGULAR);
    assert_int_equal(pc_calibrate_camera(5, xyz, xy, &got, &rms), PC_EDOMAIN);
    xy[0] = INFINITY;
    assert_int_equal(pc_calibrate_camera(6, xyz, xy, &got, &rms), PC_ENONFINITE);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lsq), cmocka_unit_test(reconstruct), cmocka_unit_test(calibrate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
