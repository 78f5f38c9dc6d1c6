/* Oresme lambda-functions (example 31) and bisection (example 30). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "numeric.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_oresme(void **state) {
    (void)state;
    int m = 12, n = 1 << m;
    double *y1 = malloc((n + 1) * sizeof *y1), *y2 = malloc((n + 1) * sizeof *y2);
    assert_int_equal(pc_oresme_fill(.3, m, 1, 2, y1), PC_OK);
    assert_int_equal(pc_oresme_fill(.2, m, 1, 2, y2), PC_OK);
    /* example 31: y1(1/2) = 1.7, y2(1/2) = 1.8 */
    NEAR(y1[0], 1, 0);
    NEAR(y1[n], 2, 0);
    NEAR(y1[n / 2], 1.7, 1e-15);
    NEAR(y2[n / 2], 1.8, 1e-15);
    NEAR(y1[n / 4], .3 * 1 + .7 * 1.7, 1e-15);
    NEAR(y1[3 * n / 4], .3 * 1.7 + .7 * 2, 1e-15);
    for (int j = 0; j < n; j++) assert_true(y1[j] < y1[j + 1]);   /* increasing */
    /* lookup by INT(t n), clamped */
    NEAR(pc_oresme_at(y1, m, .5), 1.7, 1e-15);
    NEAR(pc_oresme_at(y1, m, .5 + .1 / n), 1.7, 1e-15);
    NEAR(pc_oresme_at(y1, m, .5 - .1 / n), y1[n / 2 - 1], 0);
    NEAR(pc_oresme_at(y1, m, -3), 1, 0);
    NEAR(pc_oresme_at(y1, m, 1), 2, 0);
    NEAR(pc_oresme_at(y1, m, 7), 2, 0);
    NEAR(pc_oresme_at(y1, m, NAN), 1, 0);
    /* lambda = 1/2 is the straight line */
    assert_int_equal(pc_oresme_fill(.5, 4, 0, 1, y1), PC_OK);
    for (int j = 0; j <= 16; j++) NEAR(y1[j], j / 16.0, 1e-15);
    assert_int_equal(pc_oresme_fill(.5, -1, 0, 1, y1), PC_EDOMAIN);
    assert_int_equal(pc_oresme_fill(.5, PC_ORESME_MAXLEVEL + 1, 0, 1, y1), PC_EDOMAIN);
    assert_int_equal(pc_oresme_fill(NAN, 3, 0, 1, y1), PC_ENONFINITE);
    free(y1);
    free(y2);
}

/* example 30: u(x) = x^3 + x + c on [-c, 0] */
static double cubic(double x, void *ud) {
    double c = *(double *)ud;
    return x * x * x + x + c;
}
static double bad(double x, void *ud) {
    (void)ud;
    return x > 0.3 ? NAN : x - 1;
}

/* a step that is finite everywhere, NaN included (NaN < .5 is false) */
static double step(double x, void *ud) {
    (void)ud;
    return x < .5 ? -1 : 1;
}

static void test_bisect(void **state) {
    (void)state;
    double c = 1, x;
    int it;
    assert_int_equal(pc_bisect(cubic, &c, -c, 0, .001, &x, &it), PC_OK);
    NEAR(x, -0.6823278038280193, .001);
    assert_true(it >= 9 && it <= 11);   /* 1/2^10 < .001 */
    assert_int_equal(pc_bisect(cubic, &c, -c, 0, 0, &x, &it), PC_OK);
    NEAR(x, -0.6823278038280193, 1e-15);
    c = -2.5;   /* the bracket may be given either way round */
    assert_int_equal(pc_bisect(cubic, &c, -c, 0, 1e-12, &x, NULL), PC_OK);
    NEAR(x * x * x + x + c, 0, 1e-10);
    c = 0;      /* the listing's degenerate bracket [-0, 0] */
    assert_int_equal(pc_bisect(cubic, &c, -c, 0, .001, &x, NULL), PC_OK);
    NEAR(x, 0, 0);
    c = 2;      /* an exact zero at the first midpoint, x = -1 */
    assert_int_equal(pc_bisect(cubic, &c, -c, 0, .001, &x, &it), PC_OK);
    NEAR(x, -1, 0);
    assert_int_equal(it, 1);
    c = 1;
    assert_int_equal(pc_bisect(cubic, &c, 0, 1, .001, &x, NULL), PC_ENOBRACKET);
    assert_int_equal(pc_bisect(bad, NULL, 0, 2, .001, &x, NULL), PC_ENONFINITE);
    assert_int_equal(pc_bisect(bad, NULL, 0, .25, .001, &x, NULL), PC_ENOBRACKET);
    /* non-finite ends: NaN made the loop endless, inf came back as the "root" */
    assert_int_equal(pc_bisect(step, NULL, 0, 1, 1e-9, &x, NULL), PC_OK);
    NEAR(x, .5, 1e-9);
    assert_int_equal(pc_bisect(step, NULL, NAN, 0, .001, &x, NULL), PC_ENONFINITE);
    assert_int_equal(pc_bisect(step, NULL, 0, INFINITY, .001, &x, NULL), PC_ENONFINITE);
}

static double inf_past(double x, void *ud) {
    (void)ud;
    return x > .3 ? INFINITY : -1;
}

static void test_bisect_why(void **state) {
    (void)state;
    double c = 1, x;
    int it;
    char why[200];
    assert_int_equal(pc_bisect_why(cubic, &c, -c, 0, .001, &x, &it, why, sizeof why), PC_OK);
    NEAR(x, -0.6823278038280193, .001);
    assert_string_equal(why, "");
    assert_int_equal(pc_bisect_why(cubic, &c, 0, 1.5, .001, &x, NULL, why, sizeof why), PC_ENOBRACKET);
    assert_string_equal(why, "f(a) and f(b) have the same sign (f(0) = 1, f(1.5) = 5.875): "
                             "the interval brackets no root");
    assert_int_equal(pc_bisect_why(inf_past, NULL, 0, 1, .001, &x, NULL, why, sizeof why), PC_ENONFINITE);
    assert_string_equal(why, "f(1) must return a finite number, got inf");
    assert_int_equal(pc_bisect_why(step, NULL, -.5, 1, .001, &x, NULL, why, sizeof why), PC_OK);
    NEAR(x, .5, .001);
    assert_int_equal(pc_bisect_why(step, NULL, NAN, 1, .001, &x, NULL, why, sizeof why), PC_ENONFINITE);
    assert_string_equal(why, "the ends a and b must be finite numbers");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_oresme),
        cmocka_unit_test(test_bisect),
        cmocka_unit_test(test_bisect_why),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
