/* The degenerate section of Korotky 2015, Fig. 3c (digest korotky_curves_surfaces.md B.3 step
 * 3 and B.6 (3c)): the arc through T = W has the infinite weight, and is the limit line pair
 * U W V; arcs with T near W lie near it, and a conic sweep may end in it. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "conic_surface.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

/* distance from p to the polyline U W V (2-D) */
static double off_pair(const double *p, const double *U, const double *W, const double *V) {
    double best = INFINITY;
    const double *a[2] = {U, W}, *b[2] = {W, V};
    for (int i = 0; i < 2; i++) {
        double dx = b[i][0] - a[i][0], dy = b[i][1] - a[i][1];
        double t = ((p[0] - a[i][0]) * dx + (p[1] - a[i][1]) * dy) / (dx * dx + dy * dy);
        t = fmax(0, fmin(1, t));
        best = fmin(best, hypot(p[0] - a[i][0] - t * dx, p[1] - a[i][1] - t * dy));
    }
    return best;
}

static void test_t_equals_w(void **state) {
    (void)state;
    const double U[2] = {0, 0}, tU[2] = {1, 1}, V[2] = {2, 0}, tV[2] = {-1, 1}, W[2] = {1, 1};
    double w, cp[9], x[2];
    assert_int_equal(pc_conic_arc_cp(2, U, tU, V, tV, W, cp, &w), PC_OK);
    assert_true(isinf(w) && w > 0);
    NEAR(cp[3], 1, 1e-15); NEAR(cp[4], 1, 1e-15); NEAR(cp[5], 1, 0);   /* W as a point */
    assert_string_equal(pc_conic_kind(w), "line pair");
    int st;
    pc_curve *c = pc_conic_arc(2, U, tU, V, tV, W, &w, &st);
    assert_non_null(c);
    assert_true(isinf(w));
    for (int i = 0; i <= 8; i++) {
        assert_int_equal(pc_curve_eval(c, i / 8.0, x), PC_OK);
        NEAR(off_pair(x, U, W, V), 0, 1e-15);
    }
    pc_curve_eval(c, 0.5, x);
    NEAR(x[0], 1, 1e-15); NEAR(x[1], 1, 1e-15);
    pc_curve_eval(c, 0.25, x);
    NEAR(x[0], 0.5, 1e-15); NEAR(x[1], 0.5, 1e-15);
    pc_curve_release(c);
    /* the limit: as T -> W along the median the weight grows as 1/(1 - h) and the arcs close
     * in on the line pair */
    double prev = INFINITY;
    for (int k = 1; k <= 4; k++) {
        double e = pow(10, -k), T[2] = {1, 1 - e};
        c = pc_conic_arc(2, U, tU, V, tV, T, &w, &st);
        assert_non_null(c);
        double worst = 0;
        for (int i = 0; i <= 32; i++) {
            pc_curve_eval(c, i / 32.0, x);
            worst = fmax(worst, off_pair(x, U, W, V));
        }
        assert_true(worst < prev);
        assert_true(worst <= 2 * e);
        prev = worst;
        pc_curve_release(c);
    }
}

static void test_sweep_to_line_pair(void **state) {
    (void)state;
    /* Fig. 3c in miniature: U, V fixed on the base, tangents along fixed directions P, Q, and T
     * rising to W = (1, 0, 1) at u = 1: the last section is the triangle U W V */
    int st;
    const double u0[8] = {0, 0, 0, 1, 0, 0, 0, 1}, v0[8] = {2, 0, 0, 1, 2, 0, 0, 1};
    const double t0[8] = {1, 0, 0.5, 1, 1, 0, 1, 1};
    const double p0[8] = {1, 0, 1, 0, 1, 0, 1, 0}, q0[8] = {-1, 0, 1, 0, -1, 0, 1, 0};
    pc_curve *U = pc_curve_bezier(3, 2, u0, &st), *V = pc_curve_bezier(3, 2, v0, &st),
             *T = pc_curve_bezier(3, 2, t0, &st), *P = pc_curve_bezier(3, 2, p0, &st),
             *Q = pc_curve_bezier(3, 2, q0, &st);
    double bad = -1;
    pc_surface *s = pc_surface_conic_sweep(U, V, T, P, Q, &bad, &st);
    if (!s) print_error("status %d at u = %g\n", st, bad);
    assert_non_null(s);
    double m[3];
    assert_int_equal(pc_surface_eval(s, 1, 0.5, m), PC_OK);
    NEAR(m[0], 1, 1e-15); NEAR(m[2], 1, 1e-15);
    assert_int_equal(pc_surface_eval(s, 1, 0.25, m), PC_OK);
    NEAR(m[0], 0.5, 1e-15); NEAR(m[2], 0.5, 1e-15);
    /* at u = 0.5 an ordinary arc through T(0.5) = (1, 0, 0.75) */
    assert_int_equal(pc_surface_eval(s, 0.5, 0.5, m), PC_OK);
    NEAR(m[0], 1, 1e-12); NEAR(m[2], 0.75, 1e-12);
    pc_surface_release(s);
    pc_curve *all[5] = {U, V, T, P, Q};
    for (int i = 0; i < 5; i++) pc_curve_release(all[i]);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_t_equals_w), cmocka_unit_test(test_sweep_to_line_pair),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
