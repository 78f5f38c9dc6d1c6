/* QBasic number semantics (stepanov_examples.md §E, §F): SINGLE rounding, FOR loops that
 * accumulate in single precision, CINT rounding, the RND generator. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "qbnum.h"

static void test_f32(void **state) {
    (void)state;
    assert_true(qb_f32(0.5) == 0.5);
    assert_true(qb_f32(0.1) == (double)0.1f);
    assert_true(qb_f32(0.1) != 0.1);
    /* 4*ATN(1) in single precision */
    assert_true(qb_f32(4 * atan(1.0)) == 3.1415927410125732);
    assert_true(qb_f32(16777217.0) == 16777216.0);
    assert_true(isinf(qb_f32(1e39)));
}

static void test_cint(void **state) {
    (void)state;
    int ok;
    assert_true(qb_cint(2.5, &ok) == 2 && ok);
    assert_true(qb_cint(3.5, &ok) == 4 && ok);
    assert_true(qb_cint(-2.5, &ok) == -2 && ok);
    assert_true(qb_cint(-2.6, &ok) == -3 && ok);
    assert_true(qb_cint(32767.4, &ok) == 32767 && ok);
    qb_cint(32767.5, &ok);
    assert_false(ok);
    qb_cint(-32768.5, &ok);   /* ties to even: -32768 */
    assert_true(ok);
    qb_cint(-32769, &ok);
    assert_false(ok);
    assert_true(qb_clng(70000.5, &ok) == 70000 && ok);
    qb_clng(2147483648.0, &ok);
    assert_false(ok);
}

/* The listings' loops, counted in single precision (§F): the counts differ from a double
 * port, which gives 1000, 10001, 8, 100001, 2000 and 20001. */
static void test_range_counts(void **state) {
    (void)state;
    double pi = qb_f32(4 * atan(1.0));
    assert_int_equal(qb_range_count(0, 1, qb_f32(.001), 1000000), 1001);
    assert_int_equal(qb_range_count(0, 1, .01, 1000000), 101);
    assert_int_equal(qb_range_count(-1, 0, .01, 1000000), 101);
    assert_int_equal(qb_range_count(0, 1, .0001, 1000000), 10000);
    assert_int_equal(qb_range_count(.2, 1.6, .2, 1000000), 7);
    assert_int_equal(qb_range_count(.2, 1.8, .2, 1000000), 8);
    assert_int_equal(qb_range_count(0, .95, .05, 1000000), 19);
    assert_int_equal(qb_range_count(-1, 1, .001, 1000000), 2001);
    assert_int_equal(qb_range_count(-5, 5, .01, 1000000), 1000);
    assert_int_equal(qb_range_count(0, qb_f32(2 * pi), qb_f32(pi / 50000), 1000000), 99884);
    assert_int_equal(qb_range_count(0, qb_f32(2 * pi), qb_f32(pi / 10000), 1000000), 19998);
    assert_int_equal(qb_range_count(0, qb_f32(2 * pi), qb_f32(pi / 200), 1000000), 400);
    /* negative steps, empty loops, a padded limit */
    assert_int_equal(qb_range_count(10, 1, -1, 1000), 10);
    assert_int_equal(qb_range_count(1, 0, 1, 1000), 0);
    assert_int_equal(qb_range_count(0, -1, -.25, 1000), 5);
    assert_int_equal(qb_range_count(0, 1.01, .1, 1000), 11);
    /* a zero step never ends: counting stops at max */
    assert_int_equal(qb_range_count(0, 1, 0, 50), 50);
}

static void test_range_values(void **state) {
    (void)state;
    qb_range r;
    double v = -1, last = -1;
    qb_range_init(&r, 0, 1, .001);
    while (qb_range_next(&r, &v)) last = v;
    /* last t = 0.9999907, and the variable is left at last + step */
    assert_true(last == (double)0.99999070167541504f);
    assert_true(r.value == qb_f32(last + qb_f32(.001)));
    assert_true(r.value > 1);
    /* .2 .. 1.6: the 8th value is 1.6000001 > 1.6 */
    qb_range_init(&r, .2, 1.6, .2);
    int n = 0;
    while (qb_range_next(&r, &v)) n++;
    assert_int_equal(n, 7);
    assert_true(r.value == (double)1.6000001430511475f);
}

static void test_rnd(void **state) {
    (void)state;
    qb_rnd_state s;
    qb_rnd_init(&s);
    /* QBasic without RANDOMIZE: 0.7055475, 0.533424, 0.5795186, 0.2895625, 0.301948 */
    const double want[5] = {11837123, 8949370, 9722709, 4858052, 5065847};
    for (int i = 0; i < 5; i++) assert_true(qb_rnd(&s, 1) == want[i] / 16777216.0);
    assert_true(fabs(want[0] / 16777216.0 - 0.7055475) < 5e-8);
    assert_true(fabs(want[4] / 16777216.0 - 0.301948) < 5e-8);
    /* RND(0) repeats, any positive argument advances */
    assert_true(qb_rnd(&s, 0) == want[4] / 16777216.0);
    qb_rnd_init(&s);
    assert_true(qb_rnd(&s, 7.5) == want[0] / 16777216.0);
    /* a negative argument reseeds from the SINGLE bits: -1 = BF800000 -> seed 8000BF */
    qb_rnd_init(&s);
    assert_true(qb_rnd(&s, -1) == 3758214 / 16777216.0);
    double a = qb_rnd(&s, 1);
    qb_rnd(&s, 1);
    assert_true(qb_rnd(&s, -1) == 3758214 / 16777216.0);
    assert_true(qb_rnd(&s, 1) == a);
    /* RANDOMIZE 1: high dword 3FF00000 folds to 3FF0, the seed's middle bytes */
    qb_rnd_init(&s);
    qb_randomize(&s, 1);
    assert_int_equal(s.seed, 0x3FF000);
    assert_true(qb_rnd(&s, 1) == 12832451 / 16777216.0);
    /* every value is in [0, 1) and a SINGLE */
    for (int i = 0; i < 1000; i++) {
        double x = qb_rnd(&s, 1);
        assert_true(x >= 0 && x < 1 && qb_f32(x) == x);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_f32),          cmocka_unit_test(test_cint),
        cmocka_unit_test(test_range_counts), cmocka_unit_test(test_range_values),
        cmocka_unit_test(test_rnd),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
