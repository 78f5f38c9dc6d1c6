/* The closed Fourier curve of example 12: it passes through its 2n points, reproduces a
 * trigonometric polynomial exactly, and its coefficients are the listing's sums. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "fourier.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

/* example 12's points: astroid + .3 * (QBasic's first RND values) -- here a fixed pseudo-noise */
static void test_interpolates(void **state) {
    (void)state;
    enum { N = 16 };
    double x[2 * N], y[2 * N], ax[N + 1], bx[N + 1], ay[N + 1], by[N + 1];
    for (int i = 0; i < 2 * N; i++) {
        double u = i * M_PI / N;
        x[i] = pow(cos(u), 3) + .3 * fmod(i * 0.7055475 + 0.123, 1.0);
        y[i] = pow(sin(u), 3) + .3 * fmod(i * 0.5334240 + 0.456, 1.0);
    }
    assert_int_equal(pc_fourier_coef(N, x, 1, ax, bx), PC_OK);
    assert_int_equal(pc_fourier_coef(N, y, 1, ay, by), PC_OK);
    for (int i = 0; i < 2 * N; i++) {
        double u = i * M_PI / N;
        NEAR(pc_fourier_eval(N, ax, bx, u), x[i], 1e-12);
        NEAR(pc_fourier_eval(N, ay, by, u), y[i], 1e-12);
    }
    /* closed: period 2 pi */
    NEAR(pc_fourier_eval(N, ax, bx, 2 * M_PI + 0.3), pc_fourier_eval(N, ax, bx, 0.3), 1e-12);
    /* the listing's sums */
    double a3 = 0, b5 = 0;
    for (int i = 0; i < 2 * N; i++) {
        a3 += x[i] * cos(3 * i * M_PI / N) / N;
        b5 += x[i] * sin(5 * i * M_PI / N) / N;
    }
    NEAR(ax[3], a3, 1e-13);
    NEAR(bx[5], b5, 1e-13);
    NEAR(bx[0], 0, 0);
    NEAR(bx[N], 0, 0);
}

static void test_exact(void **state) {
    (void)state;
    /* samples of 1 + 2 cos u - 3 sin 2u + .5 cos 4u on 2n = 8 points: coefficients exact */
    enum { N = 4 };
    double f[2 * N * 2], a[N + 1], b[N + 1];
    for (int i = 0; i < 2 * N; i++) {
        double u = i * M_PI / N;
        f[2 * i] = 1 + 2 * cos(u) - 3 * sin(2 * u) + .5 * cos(4 * u);
        f[2 * i + 1] = -99;   /* stride 2: never read */
    }
    assert_int_equal(pc_fourier_coef(N, f, 2, a, b), PC_OK);
    NEAR(a[0], 2, 1e-14);
    NEAR(a[1], 2, 1e-14);
    NEAR(b[2], -3, 1e-14);
    NEAR(a[2], 0, 1e-14);
    NEAR(a[4], 1, 1e-14);   /* the Nyquist term enters as a_n / 2 */
    for (double u = 0; u < 6.3; u += 0.1)
        NEAR(pc_fourier_eval(N, a, b, u), 1 + 2 * cos(u) - 3 * sin(2 * u) + .5 * cos(4 * u), 1e-13);
    assert_int_equal(pc_fourier_coef(0, f, 1, a, b), PC_EDOMAIN);
    f[2] = NAN;
    assert_int_equal(pc_fourier_coef(N, f, 2, a, b), PC_ENONFINITE);
}

/* a Fourier curve gives back the coefficients it was made of; its part, another curve, none */
static void test_coefs_of_curve(void **state) {
    (void)state;
    enum { N = 4 };
    double xy[2 * N * 2], a[N + 1], b[N + 1];
    for (int i = 0; i < 2 * N; i++) {
        double u = i * M_PI / N;
        xy[2 * i] = 1 + 2 * cos(u) - 3 * sin(2 * u);
        xy[2 * i + 1] = sin(u);
    }
    int st, n = -1;
    pc_curve *c = pc_curve_fourier(2, N, xy, &st);
    assert_non_null(c);
    const double *coef = pc_curve_fourier_coefs(c, &n);
    assert_non_null(coef);
    assert_int_equal(n, N);
    assert_int_equal(pc_fourier_coef(N, xy + 1, 2, a, b), PC_OK);   /* y: from 2(N + 1) on */
    for (int k = 0; k <= N; k++) {
        NEAR(coef[2 * (N + 1) + k], a[k], 1e-15);
        NEAR(coef[3 * (N + 1) + k], b[k], 1e-15);
    }
    NEAR(coef[0], 2, 1e-14);        /* x: a0 = 2, a1 = 2, b2 = -3 */
    NEAR(coef[1], 2, 1e-14);
    NEAR(coef[N + 1 + 2], -3, 1e-14);
    NEAR(coef[3 * (N + 1) + 1], 1, 1e-14);   /* y = sin u: b1 = 1 */
    pc_curve *l, *r;
    assert_int_equal(pc_curve_split(c, 1, &l, &r), PC_OK);
    assert_null(pc_curve_fourier_coefs(l, &n));
    assert_int_equal(n, 0);
    double cp[] = {0, 0, 1, 1, 1, 1};
    pc_curve *line = pc_curve_bezier(2, 2, cp, &st);
    assert_null(pc_curve_fourier_coefs(line, NULL));
    assert_null(pc_curve_fourier_coefs(NULL, NULL));
    pc_curve_release(l);
    pc_curve_release(r);
    pc_curve_release(line);
    pc_curve_release(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_interpolates),
        cmocka_unit_test(test_exact),
        cmocka_unit_test(test_coefs_of_curve),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
