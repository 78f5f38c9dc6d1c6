/* Coordinate maps: the bilinear map (example 2), graphs on segments and the four-sided patch
 * (examples 23-25, 28 -- compared with example 28's own arithmetic), the plane -> square map
 * (examples 26-28), the oblique projection (examples 33, 34) and the Moebius map (15, 16). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "curvilinear.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_bilinear(void **state) {
    (void)state;
    /* example 2's quadrilateral */
    double p0[2] = {100, 100}, p1[2] = {300, 150}, p2[2] = {280, 200}, p3[2] = {150, 300}, X[2];
    pc_bilinear(2, p0, p1, p2, p3, 0, 0, X);
    NEAR(X[0], 100, 0);
    pc_bilinear(2, p0, p1, p2, p3, 1, 1, X);
    NEAR(X[0], 280, 1e-12);
    NEAR(X[1], 200, 1e-12);
    pc_bilinear(2, p0, p1, p2, p3, 0, 1, X);
    NEAR(X[0], 150, 1e-12);
    pc_bilinear(2, p0, p1, p2, p3, .5, .5, X);   /* centre = mean of the corners */
    NEAR(X[0], (100 + 300 + 280 + 150) / 4.0, 1e-12);
    NEAR(X[1], (100 + 150 + 200 + 300) / 4.0, 1e-12);
    /* the construction of example 2: A on P0P1, B on P3P2, X on AB */
    double s1 = .3, s2 = .8;
    double ax = 100 + s1 * 200, ay = 100 + s1 * 50, bx = 150 + s1 * 130, by = 300 + s1 * -100;
    pc_bilinear(2, p0, p1, p2, p3, s1, s2, X);
    NEAR(X[0], ax + s2 * (bx - ax), 1e-12);
    NEAR(X[1], ay + s2 * (by - ay), 1e-12);
    /* 3-D works the same */
    double q0[3] = {0, 0, 0}, q1[3] = {1, 0, 0}, q2[3] = {1, 1, 1}, q3[3] = {0, 1, 0}, Y[3];
    pc_bilinear(3, q0, q1, q2, q3, .5, .5, Y);
    NEAR(Y[2], .25, 1e-15);
}

static void test_frame(void **state) {
    (void)state;
    /* example 23: segment (320,240)-(480,200); the adjacent corner x3 = x0 + (y1 - y0),
     * y3 = y0 - (x1 - x0) is O + perp(e) */
    double o[2] = {320, 240}, e[2] = {160, -40}, X[2], xi, eta;
    pc_frame_point(o, e, 0, 1, X);
    NEAR(X[0], 320 + (200 - 240), 0);
    NEAR(X[1], 240 - (480 - 320), 0);
    pc_frame_point(o, e, .3, -.7, X);
    assert_int_equal(pc_frame_coords(o, e, X, &xi, &eta), PC_OK);
    NEAR(xi, .3, 1e-14);
    NEAR(eta, -.7, 1e-14);
    double z[2] = {0, 0};
    assert_int_equal(pc_frame_coords(o, z, X, &xi, &eta), PC_EZERO);
}

/* the quadrilateral of examples 24, 25, 28 and its side graphs */
static const double QX[5] = {100, 300, 250, 150, 100}, QY[5] = {100, 70, 400, 350, 100};
static double side_f(int i, double t1) {
    double t;
    switch (i) {
    case 0: t = -1 + 2 * t1; return (t - 1) * t * (t + 1) / 3;
    case 1: t = -1 + 3 * t1; return -(t + 1) * t * (t - 1) * (t - 2) / 10;
    case 2: t = t1; return t * (t - 1) / 4;
    default: t = -1 + 2 * t1; return (t * t - 1) / 10;
    }
}
static void side(int i, double t1, double out[2]) {
    double o[2] = {QX[i], QY[i]}, e[2] = {QX[i + 1] - QX[i], QY[i + 1] - QY[i]};
    pc_frame_point(o, e, t1, side_f(i, t1), out);
}
static void patch(double t1, double t2, double out[2]) {
    double u0[2], u2[2], s1[2], s3[2], xi1, eta1, xi3, eta3;
    side(0, t1, u0);
    side(2, 1 - t1, u2);
    side(1, t2, s1);
    side(3, 1 - t2, s3);
    double o1[2] = {QX[1], QY[1]}, e1[2] = {QX[2] - QX[1], QY[2] - QY[1]};
    double o3[2] = {QX[0], QY[0]}, e3[2] = {QX[3] - QX[0], QY[3] - QY[0]};
    assert_int_equal(pc_frame_coords(o1, e1, s1, &xi1, &eta1), PC_OK);
    assert_int_equal(pc_frame_coords(o3, e3, s3, &xi3, &eta3), PC_OK);
    pc_patch_blend(u0, u2, xi1, eta1, xi3, eta3, t1, out);
}
/* example 28's listing, verbatim arithmetic */
static void listing28(double t1, double t2, double out[2]) {
    const double *x = QX, *y = QY;
    double x3 = x[0] + (y[1] - y[0]), y3 = y[0] - (x[1] - x[0]);
    double t = -1 + 2 * t1, g = (t - 1) * t * (t + 1) / 3;
    double u0 = x[0] + t1 * (x[1] - x[0]) + g * (x3 - x[0]);
    double v0 = y[0] + t1 * (y[1] - y[0]) + g * (y3 - y[0]);
    x3 = x[2] + (y[3] - y[2]);
    y3 = y[2] - (x[3] - x[2]);
    t = 1 - t1;
    g = t * (t - 1) / 4;
    double u2 = x[2] + (1 - t1) * (x[3] - x[2]) + g * (x3 - x[2]);
    double v2 = y[2] + (1 - t1) * (y[3] - y[2]) + g * (y3 - y[2]);
    double u = u0 + (v2 - v0), v = v0 - (u2 - u0);
    t = -1 + 2 * (1 - t2);
    double g1 = -(t * t - 1) / 10;
    t = -1 + 3 * t2;
    double g3 = -(t + 1) * t * (t - 1) * (t - 2) / 10;
    g = g1 + t1 * (g3 - g1);
    out[0] = u0 + t2 * (u2 - u0) + g * (u - u0);
    out[1] = v0 + t2 * (v2 - v0) + g * (v - v0);
}

static void test_patch(void **state) {
    (void)state;
    for (double t1 = 0; t1 <= 1.0001; t1 += 0.1)
        for (double t2 = 0; t2 <= 1.0001; t2 += 0.125) {
            double X[2], L[2];
            patch(t1, t2, X);
            listing28(t1, t2, L);
            NEAR(X[0], L[0], 1e-9);
            NEAR(X[1], L[1], 1e-9);
        }
    /* the four sides */
    for (double t = 0; t <= 1.0001; t += 0.05) {
        double X[2], S[2];
        patch(t, 0, X);
        side(0, t, S);
        NEAR(X[0], S[0], 1e-9);
        NEAR(X[1], S[1], 1e-9);
        patch(1, t, X);
        side(1, t, S);
        NEAR(X[0], S[0], 1e-9);
        NEAR(X[1], S[1], 1e-9);
        patch(t, 1, X);
        side(2, 1 - t, S);
        NEAR(X[0], S[0], 1e-9);
        NEAR(X[1], S[1], 1e-9);
        patch(0, t, X);
        side(3, 1 - t, S);
        NEAR(X[0], S[0], 1e-9);
        NEAR(X[1], S[1], 1e-9);
    }
}

static void test_squash(void **state) {
    (void)state;
    NEAR(pc_squash(0), 0, 0);
    NEAR(pc_squash(1), 1 / sqrt(2), 1e-15);
    NEAR(pc_squash(-1), -1 / sqrt(2), 1e-15);
    NEAR(pc_squash(INFINITY), 1, 0);
    NEAR(pc_squash(-INFINITY), -1, 0);
    NEAR(pc_squash01(0), .5, 0);
    /* example 26: the outermost grid lines p = +-5 at screen x = 124 and 516 */
    NEAR(320 + 200 * pc_squash(5), 516.1, 0.05);
    NEAR(320 + 200 * pc_squash(-5), 123.9, 0.05);
    /* example 28: a circle of radius 10 stays in [.0025, .9975] */
    NEAR(pc_squash01(-10), .0025, 0.00002);
    NEAR(pc_squash01(10), .9975, 0.00002);
    double prev = -1;
    for (double p = -50; p <= 50; p += 0.5) {
        double s = pc_squash(p);
        assert_true(s > prev && s > -1 && s < 1);
        prev = s;
    }
}

static void test_oblique(void **state) {
    (void)state;
    /* example 34: C0 = (320, 400), r = 60, k = .3, u = pi/5: the unit axes in pixels */
    double c0[2] = {320, 400}, c[8], X[2];
    pc_oblique_axes(c0, 60, .3, M_PI / 5, c);
    NEAR(c[2] - c[0], 48.5, 0.05);
    NEAR(c[3] - c[1], -10.6, 0.05);
    NEAR(c[4] - c[0], -35.3, 0.05);
    NEAR(c[5] - c[1], -14.6, 0.05);
    NEAR(c[6], 320, 0);
    NEAR(c[7], 340, 0);
    /* example 33: node (1, 0, 1) at (395, 129), node (1, 0, -1) at (395, 429) */
    double d0[2] = {320, 240};
    pc_oblique_axes(d0, 150, .3, -M_PI / 3, c);
    pc_project4(c, 1, 0, 1, X);
    NEAR(X[0], 395, 1e-12);
    NEAR(X[1], 128.97, 0.005);
    pc_project4(c, 1, 0, -1, X);
    NEAR(X[1], 428.97, 0.005);
    pc_project4(c, 0, 0, 0, X);
    NEAR(X[0], 320, 0);
    NEAR(X[1], 240, 0);
    /* example 32's rotating radial axis is the projection of (cos a, sin a, 0) */
    double a = 0.7;
    pc_oblique_axes(c0, 150, .3, M_PI / 6, c);
    pc_project4(c, cos(a), sin(a), 0, X);
    NEAR(X[0], 320 + 150 * cos(M_PI / 6 + a), 1e-12);
    NEAR(X[1], 400 - 150 * .3 * sin(M_PI / 6 + a), 1e-12);
    /* the same projection as a map: the images of pc_project4 */
    pc_map f;
    assert_int_equal(pc_map_project4(&f, c), PC_OK);
    double h[4] = {cos(a), sin(a), 2, 1}, o[3];
    pc_map_apply(&f, h, o);
    pc_project4(c, cos(a), sin(a), 2, X);
    NEAR(o[0] / o[2], X[0], 1e-12);
    NEAR(o[1] / o[2], X[1], 1e-12);
    NEAR(o[1] / o[2], 400 - 150 * .3 * sin(M_PI / 6 + a) - 300, 1e-12);   /* z = 2 goes up 2r */
}

static void test_mobius(void **state) {
    (void)state;
    double z0r = .5 * cos(M_PI / 4), z0i = .5 * sin(M_PI / 4), wr, wi;
    /* z0 goes to 0 */
    assert_int_equal(pc_mobius(z0r, z0i, 0.4, z0r, z0i, &wr, &wi), PC_OK);
    NEAR(wr, 0, 1e-15);
    NEAR(wi, 0, 1e-15);
    /* example 15: 0 goes to -z0, screen (249, 311) */
    assert_int_equal(pc_mobius(z0r, z0i, 0, 0, 0, &wr, &wi), PC_OK);
    NEAR(320 + 200 * wr, 249.3, 0.05);
    NEAR(240 - 200 * wi, 310.7, 0.05);
    /* the circle to the circle, the disc into the disc, and the inverse map */
    double izr, izi, iphi;
    pc_mobius_inverse(z0r, z0i, 1.1, &izr, &izi, &iphi);
    for (double r = 0; r <= 1.0001; r += 0.25)
        for (double u = 0; u < 2 * M_PI; u += 0.3) {
            double zr = r * cos(u), zi = r * sin(u), br, bi;
            assert_int_equal(pc_mobius(z0r, z0i, 1.1, zr, zi, &wr, &wi), PC_OK);
            double m = hypot(wr, wi);
            if (r >= 1) NEAR(m, 1, 1e-12);
            else assert_true(m < 1);
            assert_int_equal(pc_mobius(izr, izi, iphi, wr, wi, &br, &bi), PC_OK);
            NEAR(br, zr, 1e-12);
            NEAR(bi, zi, 1e-12);
        }
    /* the pole z = 1/conj(z0) */
    double pr = z0r / (z0r * z0r + z0i * z0i), pi = z0i / (z0r * z0r + z0i * z0i);
    assert_int_equal(pc_mobius(0.5, 0, 0, 2, 0, &wr, &wi), PC_EPOLE);
    int st = pc_mobius(z0r, z0i, 0, pr, pi, &wr, &wi);
    assert_true(st == PC_EPOLE || st == PC_ENONFINITE || fabs(wr) > 1e12);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bilinear), cmocka_unit_test(test_frame),
        cmocka_unit_test(test_patch),    cmocka_unit_test(test_squash),
        cmocka_unit_test(test_oblique),  cmocka_unit_test(test_mobius),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
