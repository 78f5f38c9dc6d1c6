/* The one parser of colour strings (issue 15, item 7): exactly "#rrggbb".  sscanf("%2x")
 * took "#12345g" (as 12 34 05), "#-1-1-1" and "# 1 2 3". */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"

static int parse(const char *s, pc_rgb *out) { return pc_rgb_parse(s, strlen(s), out); }

static void test_good(void **state) {
    (void)state;
    pc_rgb c;
    assert_int_equal(parse("#12a4Bf", &c), PC_OK);
    assert_int_equal(c.r, 0x12);
    assert_int_equal(c.g, 0xa4);
    assert_int_equal(c.b, 0xbf);
    assert_int_equal(parse("#000000", &c), PC_OK);
    assert_int_equal(c.r + c.g + c.b, 0);
    assert_int_equal(parse("#FFFFFF", &c), PC_OK);
    assert_int_equal(c.r & c.g & c.b, 255);
}

static void test_bad(void **state) {
    (void)state;
    static const char *bad[] = {"#12345g", "#-1-1-1", "# 1 2 3", "#fff", "#1234567", "",
                                "#", "123456", "#12 456", "#+12345", "#0x1234", "#12345G",
                                "ff0000#", "#\xff\xff\xff\xff\xff\xff"};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        pc_rgb c = {7, 8, 9};
        assert_int_equal(parse(bad[i], &c), PC_EARG);
        assert_true(c.r == 7 && c.g == 8 && c.b == 9);   /* untouched */
    }
    pc_rgb c;
    assert_int_equal(pc_rgb_parse("#12\0" "456", 7, &c), PC_EARG);   /* an embedded NUL */
    assert_int_equal(pc_rgb_parse(NULL, 7, &c), PC_EARG);
    assert_int_equal(pc_rgb_parse("#123456", 6, &c), PC_EARG);      /* the length counts */
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_good),
        cmocka_unit_test(test_bad),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
