/* Dense runs of dots (dotrun.h): a dotted curve is one run, a gap splits it, a short or a
 * standing run is not a curve; thinning keeps the ends and a vertex every step pixels. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include "dotrun.h"

static void test_runs(void **state) {
    (void)state;
    pc_xy d[40];
    for (int i = 0; i < 20; i++) d[i] = (pc_xy){10 + 0.5 * i, 20};          /* a dotted line */
    for (int i = 20; i < 30; i++) d[i] = (pc_xy){100 + 1.5 * (i - 20), 50};  /* a gap, another */
    for (int i = 30; i < 33; i++) d[i] = (pc_xy){200 + i - 30, 0};           /* 3 dots: too few */
    for (int i = 33; i < 40; i++) d[i] = (pc_xy){300, 300 + 0.1 * (i - 33)}; /* 7 on one spot */
    size_t runs[40];
    size_t m = pc_dot_runs(d, 40, runs);
    assert_int_equal(m, 2);
    assert_int_equal(runs[0], 0);
    assert_int_equal(runs[1], 20);
    assert_int_equal(runs[2], 20);
    assert_int_equal(runs[3], 30);
    /* 1.6 px apart: not dense, no run */
    pc_xy e[10];
    for (int i = 0; i < 10; i++) e[i] = (pc_xy){1.6 * i, 0};
    assert_int_equal(pc_dot_runs(e, 10, runs), 0);
}

static void test_thin(void **state) {
    (void)state;
    pc_xy d[21], out[21];
    for (int i = 0; i <= 20; i++) d[i] = (pc_xy){0.25 * i, 0};   /* 0 .. 5 px */
    size_t n = pc_dot_run_thin(d, 21, 1.0, out);
    /* kept: 0, 1 (4 dots on), 2, 3, 4, then the last dot 5 */
    assert_int_equal(n, 6);
    for (size_t i = 0; i < n; i++) assert_true(fabs(out[i].x - (double)i) < 1e-12);
    assert_int_equal(pc_dot_run_thin(d, 1, 0.75, out), 1);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_runs),
        cmocka_unit_test(test_thin),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
