/* A value as text (point_text.c): points, vectors and weighted values as the Lua that rebuilds
 * them, a weight within 1e-9 of 1 shown as the point it counts as, no "-0", 14 digits, and a
 * buffer too small (truncated, the needed length returned). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <string.h>
#include "point.h"

static const char *text(int n, const double *h) {
    static char buf[128];
    size_t len = pc_value_text(n, h, buf, sizeof buf);
    assert_int_equal(len, strlen(buf));
    return buf;
}

static void test_kinds(void **state) {
    (void)state;
    assert_string_equal(text(2, (double[]){1, 2, 1}), "P(1, 2)");
    assert_string_equal(text(2, (double[]){0, -0.0, 0}), "V(0, 0)");
    assert_string_equal(text(2, (double[]){2, 4, 2}), "2*P(1, 2)");
    assert_string_equal(text(2, (double[]){1 + 1e-12, 2 + 2e-12, 1 + 1e-12}), "P(1, 2)");
    assert_string_equal(text(3, (double[]){1.0 / 3, 1e20, -1e-300, 1}), "P(0.33333333333333, 1e+20, -1e-300)");
    assert_string_equal(text(1, (double[]){-5, 1e-17}), "V(-5)");
}

static void test_truncated(void **state) {
    (void)state;
    char small[6];
    assert_int_equal(pc_value_text(2, (double[]){10, 20, 1}, small, sizeof small), 9);
    assert_string_equal(small, "P(10,");
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_kinds), cmocka_unit_test(test_truncated)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
