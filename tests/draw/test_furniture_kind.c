/* The furniture through points as one family (furniture.h: pc_furniture_kind_of,
 * pc_furniture): the kinds by name, each drawn as its own function draws it, the measures. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include "canvas.h"
#include "furniture.h"

static int at(const pc_canvas *c, int x, int y) { return c->pixels[y * c->width + x]; }

static void test_kinds_by_name(void **state) {
    (void)state;
    assert_int_equal(pc_furniture_kind_of("arrow"), PC_FURN_ARROW);
    assert_int_equal(pc_furniture_kind_of("dimension"), PC_FURN_DIMENSION);
    assert_int_equal(pc_furniture_kind_of("angle_mark"), PC_FURN_ANGLE);
    assert_int_equal(pc_furniture_kind_of("ticks"), PC_FURN_TICKS);
    assert_int_equal(pc_furniture_kind_of("centre_line"), PC_FURN_CENTRE);
    assert_int_equal(pc_furniture_kind_of("hatch"), -1);
    assert_int_equal(pc_furniture_kind_of(""), -1);
}

/* Each kind draws the pixels of its own function, with the binding's fixed sizes (a head of
 * 9 px, ticks 8 px long). */
static void test_same_pixels(void **state) {
    (void)state;
    pc_canvas *a = pc_canvas_new(320, 240, 16), *b = pc_canvas_new(320, 240, 16);
    double m = -1, xy[6] = {20, 200, 300, 40, 300, 200};
    assert_int_equal(pc_furniture(a, PC_FURN_ARROW, xy, PC_ARROW_BOTH, NULL, 12, &m), PC_OK);
    assert_true(m == 0);
    assert_int_equal(pc_arrow(b, 20, 200, 300, 40, PC_ARROW_BOTH, 9, 12), PC_OK);
    assert_int_equal(pc_furniture(a, PC_FURN_TICKS, xy, 3, NULL, 10, &m), PC_OK);
    assert_int_equal(pc_ticks(b, 20, 200, 300, 40, 3, 8, 10), PC_OK);
    assert_int_equal(pc_furniture(a, PC_FURN_CENTRE, xy + 2, 10, NULL, 9, &m), PC_OK);
    assert_int_equal(pc_centre_line(b, 300, 40, 300, 200, 10, 9), PC_OK);
    int drawn = 0;
    for (int y = 0; y < 240; y++)
        for (int x = 0; x < 320; x++) {
            assert_int_equal(at(a, x, y), at(b, x, y));
            drawn += at(a, x, y) != 0;
        }
    assert_true(drawn > 300);
    assert_int_equal(at(a, 300, 120), 9);   /* the centre line's first long dash, x = 300 */
    pc_canvas_free(a);
    pc_canvas_free(b);
}

static void test_measures(void **state) {
    (void)state;
    pc_canvas *c = pc_canvas_new(640, 480, 16);
    double m = 0, ab[4] = {100, 300, 300, 300}, aob[6] = {200, 100, 100, 100, 200, 0};
    assert_int_equal(pc_furniture(c, PC_FURN_DIMENSION, ab, 20, NULL, 15, &m), PC_OK);
    assert_true(m == 200);
    assert_int_equal(at(c, 200, 280), 15);   /* the dimension line, 20 px to the left of A->B */
    assert_int_equal(pc_furniture(c, PC_FURN_ANGLE, aob, 30, "t", 15, &m), PC_OK);
    assert_true(fabs(m - M_PI / 4) < 1e-15);
    assert_int_equal(at(c, 130, 100), 15);   /* the arc on OA at radius 30 */
    double same[4] = {5, 5, 5, 5};
    assert_int_equal(pc_furniture(c, PC_FURN_ARROW, same, PC_ARROW_END, NULL, 15, &m), PC_EARG);
    assert_string_equal(c->error, "arrow: the two points coincide: no direction for the head");
    assert_int_equal(pc_furniture(c, PC_FURN_TICKS, ab, 6, NULL, 15, &m), PC_EARG);   /* 1..5 ticks */
    pc_canvas_free(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kinds_by_name),
        cmocka_unit_test(test_same_pixels),
        cmocka_unit_test(test_measures),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
