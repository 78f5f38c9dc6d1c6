/* Complex arithmetic of complex(...) (examples 15, 16): the operations, exact integer powers,
 * and the status codes that replace inf and NaN (division by zero, 0 to a negative power,
 * overflow). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "cnum.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static pc_cnum C(double re, double im) { return (pc_cnum){re, im}; }

static void test_ops(void **state) {
    (void)state;
    pc_cnum z = C(1, 2), w = C(3, -1), r;
    assert_int_equal(pc_cnum_arith('+', z, w, &r), PC_OK);
    NEAR(r.re, 4, 0); NEAR(r.im, 1, 0);
    assert_int_equal(pc_cnum_arith('-', z, w, &r), PC_OK);
    NEAR(r.re, -2, 0); NEAR(r.im, 3, 0);
    assert_int_equal(pc_cnum_arith('*', z, w, &r), PC_OK);   /* (1 + 2i)(3 - i) = 5 + 5i */
    NEAR(r.re, 5, 0); NEAR(r.im, 5, 0);
    assert_int_equal(pc_cnum_arith('/', z, C(0, 1), &r), PC_OK);   /* (1 + 2i)/i = 2 - i */
    NEAR(r.re, 2, 1e-15); NEAR(r.im, -1, 1e-15);
    assert_int_equal(pc_cnum_arith('u', z, z, &r), PC_OK);   /* -(1 + 2i) */
    NEAR(r.re, -1, 0); NEAR(r.im, -2, 0);
    assert_int_equal(pc_cnum_arith('u', C(0, 0), C(0, 0), &r), PC_OK);   /* -0: the signs flip */
    assert_true(signbit(r.re) && signbit(r.im));
    assert_int_equal(pc_cnum_arith('?', z, w, &r), PC_EDOMAIN);
}

static void test_powers(void **state) {
    (void)state;
    pc_cnum r;
    assert_int_equal(pc_cnum_arith('^', C(0, 1), C(2, 0), &r), PC_OK);   /* i^2 = -1 exactly */
    assert_true(r.re == -1 && r.im == 0);
    assert_int_equal(pc_cnum_arith('^', C(1, 2), C(2, 0), &r), PC_OK);   /* (1 + 2i)^2 = -3 + 4i */
    assert_true(r.re == -3 && r.im == 4);
    assert_int_equal(pc_cnum_arith('^', C(0, 2), C(-1, 0), &r), PC_OK);  /* 1/(2i) = -i/2 */
    NEAR(r.re, 0, 0); NEAR(r.im, -.5, 1e-16);
    assert_int_equal(pc_cnum_arith('^', C(-1, 0), C(.5, 0), &r), PC_OK); /* principal sqrt(-1) = i */
    NEAR(r.re, 0, 1e-15); NEAR(r.im, 1, 1e-15);
    assert_int_equal(pc_cnum_arith('^', C(0, 0), C(0, 0), &r), PC_OK);
    assert_true(r.re == 1 && r.im == 0);
    assert_int_equal(pc_cnum_arith('^', C(0, 0), C(.5, 3), &r), PC_OK);  /* |0^b| = 0 for Re b > 0 */
    assert_true(r.re == 0 && r.im == 0);
    /* e^(i pi) = -1 */
    assert_int_equal(pc_cnum_exp(C(0, M_PI), &r), PC_OK);
    NEAR(r.re, -1, 1e-15); NEAR(r.im, 0, 1e-15);
}

static void test_errors(void **state) {
    (void)state;
    pc_cnum r = C(7, 7);
    assert_int_equal(pc_cnum_arith('/', C(1, 2), C(0, 0), &r), PC_EPOLE);
    assert_int_equal(pc_cnum_arith('^', C(0, 0), C(-1, 0), &r), PC_EPOLE);
    assert_int_equal(pc_cnum_arith('^', C(0, 0), C(-.5, 0), &r), PC_EPOLE);  /* cpow: inf, NaN */
    assert_int_equal(pc_cnum_arith('^', C(0, 0), C(0, 1), &r), PC_EPOLE);
    assert_int_equal(pc_cnum_arith('*', C(1e300, 0), C(1e300, 0), &r), PC_ENONFINITE);
    assert_int_equal(pc_cnum_arith('^', C(1e200, 0), C(2, 0), &r), PC_ENONFINITE);
    assert_int_equal(pc_cnum_arith('+', C(NAN, 0), C(1, 0), &r), PC_ENONFINITE);
    assert_int_equal(pc_cnum_arith('+', C(1, 0), C(0, INFINITY), &r), PC_ENONFINITE);
    assert_int_equal(pc_cnum_exp(C(1000, 0), &r), PC_ENONFINITE);
    assert_true(r.re == 7 && r.im == 7);   /* untouched on error */
}

/* conj(3 + 4i) = 3 - 4i, |3 + 4i| = 5, arg(-1) = pi, e^(i pi) = -1 */
static void test_functions(void **state) {
    (void)state;
    pc_cnum z = {3, 4}, r;
    assert_int_equal(pc_cnum_fn('c', z, &r), PC_OK);
    assert_true(r.re == 3 && r.im == -4);
    assert_int_equal(pc_cnum_fn('a', z, &r), PC_OK);
    assert_true(r.re == 5 && r.im == 0);
    pc_cnum_fn('g', (pc_cnum){-1, 0}, &r);
    assert_float_equal(r.re, 3.14159265358979323846, 1e-15);
    pc_cnum_fn('e', (pc_cnum){0, 3.14159265358979323846}, &r);
    assert_float_equal(r.re, -1, 1e-15);
    assert_float_equal(r.im, 0, 1e-15);
    assert_int_equal(pc_cnum_fn('e', (pc_cnum){1000, 0}, &r), PC_ENONFINITE);
    assert_int_equal(pc_cnum_fn('?', z, &r), PC_EDOMAIN);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ops),
        cmocka_unit_test(test_powers),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_functions),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
