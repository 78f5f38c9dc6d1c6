/* QBasic statements' arguments (qbstatements.c): VIEW rounds its corners and refuses ones
 * beyond any screen with their values named, PALETTE's numbers map 63 to 255, PMAP converts
 * both ways through WINDOW and VIEW. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"
#include "qbscreen.h"

static void test_view_at(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_view_at(c, 10.4, 20.6, 99.5, 200.2, -1, -1, 1), PC_OK);
    assert_int_equal(c->view.x0, 10);
    assert_int_equal(c->view.y0, 21);
    assert_int_equal(c->view.x1, 100);   /* lrint: ties to even */
    assert_int_equal(c->view.y1, 200);
    assert_int_equal(pc_view_at(c, 0, 0, 5e9, 10, -1, -1, 1), PC_EARG);
    assert_string_equal(c->error, "view (0, 0)-(5000000000, 10) is not inside the 640x480 screen");
    assert_int_equal(pc_view_at(c, -3, 0, 10, 10, -1, -1, 1), PC_EARG);
    assert_string_equal(c->error, "view (-3, 0)-(10, 10) is not inside the 640x480 screen");
    pc_canvas_free(c);
}

static void test_rgb_qbasic(void **state) {
    (void)state;
    pc_rgb rgb;
    assert_int_equal(pc_rgb_qbasic(63, &rgb), PC_OK);
    assert_int_equal(rgb.r, 255);
    assert_int_equal(rgb.g, 0);
    assert_int_equal(rgb.b, 0);
    assert_int_equal(pc_rgb_qbasic(65536 * 32 + 256 * 1, &rgb), PC_OK);
    assert_int_equal(rgb.r, 0);
    assert_int_equal(rgb.g, 4);
    assert_int_equal(rgb.b, 130);
    assert_int_equal(pc_rgb_qbasic(64, &rgb), PC_EARG);
    assert_int_equal(pc_rgb_qbasic(-1, &rgb), PC_EARG);
    assert_int_equal(pc_rgb_qbasic(0x3f3f3f + 1, &rgb), PC_EARG);
}

static void test_pmap(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_view(c, 100, 100, 299, 199, -1, -1, 0), PC_OK);
    assert_int_equal(pc_window(c, 0, 0, 10, 5, 0), PC_OK);
    assert_true(pc_pmap(c, 5, 0) == 100);   /* half of the view's 199 px, rounded */
    assert_true(pc_pmap(c, 5, 1) == 0);     /* y up: the top */
    assert_true(pc_pmap(c, 0, 1) == 99);
    assert_true(fabs(pc_pmap(c, 199, 2) - 10) < 1e-9);
    assert_true(fabs(pc_pmap(c, 99, 3)) < 1e-9);
    pc_canvas_free(c);
}

static void test_line_stmt(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    assert_int_equal(pc_line_stmt(c, 10, 10, 20, 10, 5, 0, -1), PC_OK);
    assert_int_equal(c->pixels[10 * 640 + 15], 5);
    assert_int_equal(pc_line_stmt(c, 30, 30, 40, 40, 6, 2, 0), PC_OK);   /* a filled box ignores the style */
    assert_int_equal(c->pixels[35 * 640 + 35], 6);
    assert_int_equal(pc_line_stmt(c, 50, 50, 60, 60, 7, 1, -1), PC_OK);   /* an outline */
    assert_int_equal(c->pixels[50 * 640 + 55], 7);
    assert_int_equal(c->pixels[55 * 640 + 55], 0);
    /* &HAAAA: every other pixel, bit 15 first */
    assert_int_equal(pc_line_stmt(c, 100, 100, 115, 100, 8, 0, 0xAAAA), PC_OK);
    int on = 0;
    for (int x = 100; x <= 115; x++) on += c->pixels[100 * 640 + x] == 8;
    assert_int_equal(on, 8);
    assert_int_equal(pc_line_stmt(c, 1e300, 0, 0, 0, 99, 0, -1), PC_EARG);
    assert_string_equal(pc_canvas_message(c), "colour 99 out of range 0..15");
    strcpy(c->error, "pset: coordinates out of range");
    assert_string_equal(pc_canvas_message(c), "coordinates out of range");
    strcpy(c->error, "view (1, 2) is not inside");
    assert_string_equal(pc_canvas_message(c), "view (1, 2) is not inside");
    strcpy(c->error, "line_to: no such");
    assert_string_equal(pc_canvas_message(c), "no such");
    strcpy(c->error, "Line: kept");
    assert_string_equal(pc_canvas_message(c), "Line: kept");
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_view_at), cmocka_unit_test(test_rgb_qbasic),
                                       cmocka_unit_test(test_pmap), cmocka_unit_test(test_line_stmt)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
