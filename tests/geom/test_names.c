/* names.c: the edit distance behind "did you mean", the choice of the suggestion, and numbers
 * as messages show them. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "names.h"

static void test_distance(void **state) {
    (void)state;
    assert_int_equal(pc_edit_distance("lerp", "lerp"), 0);
    assert_int_equal(pc_edit_distance("lrep", "lerp"), 1);      /* a swap of neighbours: one edit */
    assert_int_equal(pc_edit_distance("colr", "color"), 1);     /* an insertion */
    assert_int_equal(pc_edit_distance("Color", "color"), 0);    /* case-insensitive */
    assert_int_equal(pc_edit_distance("kitten", "sitting"), 3);
    assert_int_equal(pc_edit_distance("", "abc"), 3);
    char long_name[50];
    memset(long_name, 'a', 41);
    long_name[41] = 0;
    assert_int_equal(pc_edit_distance(long_name, "a"), 99);     /* too long to compare */
}

static void test_nearest(void **state) {
    (void)state;
    const char *const keys[] = {"width", "color", "dash", "label", NULL};
    assert_string_equal(pc_nearest_name("colr", keys), "color");
    assert_string_equal(pc_nearest_name("widht", keys), "width");
    assert_null(pc_nearest_name("color", keys));                /* itself is no suggestion */
    assert_null(pc_nearest_name("size", keys));                 /* nothing near */
    const char *const short_keys[] = {"ab", "xyz", NULL};
    assert_null(pc_nearest_name("ba", (const char *const[]){"abc", NULL}));   /* 3 letters: 1 edit */
    assert_string_equal(pc_nearest_name("xy", short_keys), "xyz");
    const char *const ties[] = {"lerp", "lera", NULL};          /* both 1 edit: the first alphabetically */
    assert_string_equal(pc_nearest_name("lerb", ties), "lera");
    const char *best = NULL;
    int bestd = 99;
    pc_nearer_name("mdi", "mid", &best, &bestd);
    assert_string_equal(best, "mid");
    assert_int_equal(bestd, 1);
    pc_nearer_name("mdi", "dist", &best, &bestd);               /* farther: kept */
    assert_string_equal(best, "mid");
}

static void test_num_text(void **state) {
    (void)state;
    char buf[32];
    assert_string_equal(pc_num_text(2.5, buf, sizeof buf), "2.5");
    assert_string_equal(pc_num_text(-0.0, buf, sizeof buf), "0");
    assert_string_equal(pc_num_text(1.0 / 3, buf, sizeof buf), "0.33333333333333");
    assert_string_equal(pc_num_text(1e20, buf, sizeof buf), "1e+20");
    assert_string_equal(pc_num_text(-7, buf, sizeof buf), "-7");
    assert_string_equal(pc_num_text(INFINITY, buf, sizeof buf), "inf");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_distance),
        cmocka_unit_test(test_nearest),
        cmocka_unit_test(test_num_text),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
