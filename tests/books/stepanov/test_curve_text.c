/* A curve as tostring shows it: Bezier, function curves, strokes, spline2, Fourier curves. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "curve_text.h"
#include "fourier.h"
#include "spline.h"

static int half(void *ud, double t, int order, double *out) {
    (void)ud, (void)order;
    out[0] = t;
    out[1] = 1;
    return PC_OK;
}

static void test_kinds(void **state) {
    (void)state;
    char buf[120];
    int st;
    double cp[] = {0, 0, 1, 1, 0, 1, 1, 1, 1, 2, -.5, 1};
    pc_curve *b = pc_curve_bezier(2, 4, cp, &st);
    size_t len = pc_curve_text(b, "bezier", buf, sizeof buf);
    assert_int_equal(len, strlen(buf));
    assert_string_equal(buf, "bezier(2-D, degree 3, 4 control points, t in [0, 1])");
    pc_curve *f = pc_curve_func(1, -0.0, 2.5, 0, half, NULL, NULL, &st);
    pc_curve_text(f, "curve", buf, sizeof buf);
    assert_string_equal(buf, "curve(1-D, t in [0, 2.5])");   /* no -0 */
    double sq[8] = {0, 0, 3, 0, 3, 3, 0, 3};
    pc_stroke_spec s = {.d = 2, .nnodes = 4, .closed = 1, .nodes = sq};
    pc_piece pcs[4];
    assert_int_equal(pc_stroke_build(&s, pcs, NULL), PC_OK);
    pc_curve *closed = pc_curve_stroke(2, 4, pcs, 1, &st), *open = pc_curve_stroke(2, 3, pcs, 0, &st);
    pc_curve_text(closed, "stroke", buf, sizeof buf);
    assert_string_equal(buf, "stroke(4 nodes, 4 pieces, 2-D, closed)");
    pc_curve_text(open, "stroke", buf, sizeof buf);
    assert_string_equal(buf, "stroke(4 nodes, 3 pieces, 2-D)");
    pc_curve *one = pc_curve_stroke(2, 1, pcs, 0, &st);
    pc_curve_text(one, "spline2", buf, sizeof buf);
    assert_string_equal(buf, "spline2(2-D)");
    pc_curve *four = pc_curve_fourier(2, 2, sq, &st);
    pc_curve_text(four, "fourier", buf, sizeof buf);
    assert_string_equal(buf, "fourier(4 points, 2-D)");
    assert_int_equal(pc_curve_text(b, "bezier", buf, 8), 52);   /* cut; the length it needs */
    assert_string_equal(buf, "bezier(");
    pc_curve *all[] = {b, f, closed, open, one, four};
    for (int i = 0; i < 6; i++) pc_curve_release(all[i]);
}

/* the fields a script reads: c.dim, c.t0, c.closed, c.degree, c.pieces, c.n */
static void test_fields(void **state) {
    (void)state;
    int st;
    double v, cp[] = {0, 0, 1, 1, 0, 1, 1, 1, 1, 2, -.5, 1}, sq[8] = {0, 0, 3, 0, 3, 3, 0, 3};
    pc_curve *b = pc_curve_bezier(2, 4, cp, &st), *f = pc_curve_func(1, -1, 2.5, 0, half, NULL, NULL, &st);
    pc_curve *four = pc_curve_fourier(2, 2, sq, &st);
    assert_int_equal(pc_curve_field(b, "dim", &v), PC_FIELD_INTEGER);
    assert_float_equal(v, 2, 0);
    assert_int_equal(pc_curve_field(b, "degree", &v), PC_FIELD_INTEGER);
    assert_float_equal(v, 3, 0);
    assert_int_equal(pc_curve_field(b, "pieces", &v), PC_FIELD_INTEGER);
    assert_float_equal(v, 1, 0);
    assert_int_equal(pc_curve_field(b, "closed", &v), PC_FIELD_BOOLEAN);
    assert_float_equal(v, 0, 0);
    assert_int_equal(pc_curve_field(f, "t0", &v), PC_FIELD_NUMBER);
    assert_float_equal(v, -1, 0);
    assert_int_equal(pc_curve_field(f, "hi", &v), PC_FIELD_NUMBER);
    assert_float_equal(v, 2.5, 0);
    assert_int_equal(pc_curve_field(f, "degree", &v), PC_FIELD_NONE);
    assert_int_equal(pc_curve_field(f, "n", &v), PC_FIELD_NONE);
    assert_int_equal(pc_curve_field(four, "n", &v), PC_FIELD_INTEGER);
    assert_float_equal(v, 2, 0);
    assert_int_equal(pc_curve_field(four, "closed", &v), PC_FIELD_BOOLEAN);
    assert_float_equal(v, 1, 0);
    assert_int_equal(pc_curve_field(b, "eval", &v), PC_FIELD_NONE);
    pc_curve *all[] = {b, f, four};
    for (int i = 0; i < 3; i++) pc_curve_release(all[i]);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_kinds), cmocka_unit_test(test_fields)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
