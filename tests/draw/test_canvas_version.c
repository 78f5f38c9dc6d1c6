/* The canvas change counter used by the REPL's --watch: every change of the picture bumps it,
 * saving does not, and it never goes back (not even on SCREEN). */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include "canvas.h"

static void test_version_counts_changes(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(16, 16, 16);
    assert_non_null(c);
    uint64_t v = pc_canvas_version(c);
#define CHANGED(call) \
    do { call; assert_true(pc_canvas_version(c) > v); v = pc_canvas_version(c); } while (0)
#define SAME(call) do { call; assert_true(pc_canvas_version(c) == v); } while (0)
    CHANGED(pc_pset(c, 1, 1, 14));
    CHANGED(pc_line(c, 0, 0, 5, 5, 2));
    CHANGED(pc_box(c, 0, 0, 5, 5, 2, 1));
    CHANGED(pc_circle(c, 8, 8, 3, 4, NAN, NAN, NAN));
    CHANGED(pc_paint(c, 8, 8, 1, 4));
    CHANGED(pc_cls(c));                       /* full screen, black: no operation recorded */
    CHANGED(pc_palette(c, 3, (pc_rgb){1, 2, 3}));
    CHANGED(pc_palette_reset(c));
    CHANGED(pc_canvas_reset(c, 16, 16, 16));  /* SCREEN: a new picture, the count goes on */
    SAME(pc_color(c, 4, -1));
    SAME(pc_window(c, -1, -1, 1, 1, 0));
    SAME(pc_window_reset(c));
    SAME(pc_point(c, 1, 1));
    SAME(pc_canvas_mark_saved(c));            /* what save() does */
    CHANGED(pc_canvas_clear(c));              /* the REPL's clear */
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_version_counts_changes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
