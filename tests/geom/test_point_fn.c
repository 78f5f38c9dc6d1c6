/* The point functions behind one entry, the operators on values and their messages
 * (point_fn.h): values from the definitions, and the wording the script API shows. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "point_fn.h"

static int fn(int op, int n, const double *a, const double *b, const double *c, const double *d, double x,
              double *out, int *value) {
    const double *v[4] = {a, b, c ? c : b, d ? d : (c ? c : b)};
    return pc_point_fn(op, n, v, x, out, value);
}

static void test_numbers(void **state) {
    (void)state;
    double out[PC_MAXDIM + 3];
    int value = -1;
    assert_int_equal(fn(PC_FN_DIST, 2, (double[]){0, 0, 1}, (double[]){3, 4, 1}, NULL, NULL, 0, out, &value), PC_OK);
    assert_float_equal(out[0], 5, 1e-15);
    assert_int_equal(value, 0);
    /* Sigma(A, B, C) = (B - A).(C - A); Sigma(A, B) = AB^2 */
    fn(PC_FN_SIGMA, 2, (double[]){1, 1, 1}, (double[]){4, 5, 1}, (double[]){2, 1, 1}, NULL, 0, out, NULL);
    assert_float_equal(out[0], 3, 1e-15);
    fn(PC_FN_SIGMA, 2, (double[]){1, 1, 1}, (double[]){4, 5, 1}, NULL, NULL, 0, out, NULL);
    assert_float_equal(out[0], 25, 1e-15);
    fn(PC_FN_CROSS, 2, (double[]){1, 0, 0}, (double[]){0, 2, 0}, NULL, NULL, 0, out, &value);
    assert_float_equal(out[0], 2, 1e-15);
    assert_int_equal(value, 0);
    /* the angle at A of the right isosceles triangle, and between two vectors */
    fn(PC_FN_ANGLE, 2, (double[]){0, 0, 1}, (double[]){1, 0, 1}, (double[]){1, 1, 1}, NULL, 0, out, NULL);
    assert_float_equal(out[0], M_PI / 4, 1e-15);
    fn(PC_FN_ANGLE_UV, 2, (double[]){1, 0, 0}, (double[]){0, -3, 0}, NULL, NULL, 0, out, NULL);
    assert_float_equal(out[0], M_PI / 2, 1e-15);
    /* the unit tetrahedron has volume 1/6, positive when right-handed */
    fn(PC_FN_VOLUME, 3, (double[]){0, 0, 0, 1}, (double[]){1, 0, 0, 1}, (double[]){0, 1, 0, 1}, (double[]){0, 0, 1, 1},
       0, out, NULL);
    assert_float_equal(out[0], 1.0 / 6, 1e-15);
    fn(PC_FN_WEIGHT, 2, (double[]){2, 4, 2}, NULL, NULL, NULL, 0, out, NULL);
    assert_float_equal(out[0], 2, 0);
}

static void test_values(void **state) {
    (void)state;
    double out[PC_MAXDIM + 3];
    int value = -1;
    /* the foot of the perpendicular from C = (1, 3) to the x axis */
    assert_int_equal(fn(PC_FN_FOOT, 2, (double[]){1, 3, 1}, (double[]){0, 0, 1}, (double[]){5, 0, 1}, NULL, 0, out,
                        &value), PC_OK);
    assert_int_equal(value, 1);
    assert_float_equal(out[0], 1, 1e-15);
    assert_float_equal(out[1], 0, 1e-15);
    assert_float_equal(out[2], 1, 0);
    fn(PC_FN_PERP, 2, (double[]){2, 1, 0}, NULL, NULL, NULL, 0, out, NULL);
    assert_true(out[0] == -1 && out[1] == 2 && out[2] == 0);
    fn(PC_FN_CROSS, 3, (double[]){1, 0, 0, 0}, (double[]){0, 1, 0, 0}, NULL, NULL, 0, out, &value);
    assert_true(value == 1 && out[0] == 0 && out[1] == 0 && out[2] == 1 && out[3] == 0);
    /* divide(X, Y, 1) is the midpoint; normalize(2*P(1, 2)) is P(1, 2) */
    fn(PC_FN_DIVIDE, 1, (double[]){0, 1}, (double[]){4, 1}, NULL, NULL, 1, out, NULL);
    assert_float_equal(out[0] / out[1], 2, 1e-15);
    fn(PC_FN_NORMALIZE, 2, (double[]){2, 4, 2}, NULL, NULL, NULL, 0, out, NULL);
    assert_true(out[0] == 1 && out[1] == 2 && out[2] == 1);
    /* the diagonals of the square (0, 0) (2, 2) / (0, 2) (2, 0) meet at (1, 1), lambda = mu = 1/2 */
    assert_int_equal(fn(PC_FN_MEET, 2, (double[]){0, 0, 1}, (double[]){2, 2, 1}, (double[]){0, 2, 1},
                        (double[]){2, 0, 1}, 0, out, NULL), PC_OK);
    assert_true(out[0] == 1 && out[1] == 1 && out[2] == 1 && out[3] == 0.5 && out[4] == 0.5);
    /* skew lines of 3-D at distance 1 */
    assert_int_equal(fn(PC_FN_MEET, 3, (double[]){0, 0, 0, 1}, (double[]){1, 0, 0, 1}, (double[]){0, 1, 1, 1},
                        (double[]){0, 2, 1, 1}, 0, out, NULL), PC_ESKEW);
    assert_float_equal(out[0], 1, 1e-15);
}

static void test_failures(void **state) {
    (void)state;
    double out[PC_MAXDIM + 3];
    char msg[400];
    const double z[] = {0, 0, 0}, p[] = {1, 1, 1}, q[] = {2, 3, 1};
    const double *v[4] = {p, z, q, q};
    assert_int_equal(pc_point_fn(PC_FN_MEET, 2, v, 0, out, NULL), PC_EZERO);
    assert_int_equal(pc_point_fn_text(PC_FN_MEET, PC_EZERO, 2, v, 0, msg, sizeof msg), 2);
    assert_string_equal(msg, "is the zero vector V(0, 0), which has no direction, so it is no point at infinity");
    const double *w[4] = {p, p, q, z};
    assert_int_equal(pc_point_fn(PC_FN_FOOT, 2, (const double *const[]){q, p, p, p}, 0, out, NULL), PC_ECOINCIDENT);
    assert_int_equal(pc_point_fn_text(PC_FN_FOOT, PC_ECOINCIDENT, 2, w, 0, msg, sizeof msg), 0);
    assert_string_equal(msg, "A and B coincide, so they do not define a line");
    assert_int_equal(pc_point_fn(PC_FN_PERP, 3, w, 0, out, NULL), PC_EDIM);
    assert_int_equal(pc_point_fn_text(PC_FN_PERP, PC_EDIM, 3, w, 0, msg, sizeof msg), 1);
    assert_string_equal(msg, "must be a 2-D vector, got 3-D (in space a perpendicular is not unique: use cross(u, v))");
    pc_point_fn_text(PC_FN_DIVIDE, PC_ENONFINITE, 2, w, -0.0, msg, sizeof msg);
    assert_string_equal(msg, "the point is out of range (not finite) for lambda = 0");
    const double *vec[4] = {(double[]){1, 2, 0}, NULL, NULL, NULL};
    assert_int_equal(pc_point_fn(PC_FN_NORMALIZE, 2, vec, 0, out, NULL), PC_EWEIGHT);
    pc_point_fn_text(PC_FN_NORMALIZE, PC_EWEIGHT, 2, vec, 0, msg, sizeof msg);
    assert_string_equal(msg, "V(1, 2) has weight 0 (a vector, or a point at infinity), so it has no finite location");
}

static void test_near(void **state) {
    (void)state;
    assert_true(pc_near(0, (double[]){1}, (double[]){1 + 5e-10}, 1e-9));
    assert_false(pc_near(0, (double[]){1}, (double[]){1 + 2e-9}, 1e-9));
    assert_true(pc_near(0, (double[]){1e6}, (double[]){1e6 + 5e-4}, 1e-9));       /* relative to the size */
    assert_true(pc_near(2, (double[]){1, 2, 1}, (double[]){1, 2 + 1e-10, 1}, 1e-9));
    assert_false(pc_near(2, (double[]){1, 2, 1}, (double[]){1, 2, 0}, 1e-9));     /* P(1, 2) and V(1, 2) */
}

static void test_arith(void **state) {
    (void)state;
    double a[] = {1, 2, 1}, b[] = {3, -1, 0}, out[3], r = 0;
    assert_int_equal(pc_value_arith('+', 2, a, b, 0, out), PC_OK);
    assert_true(out[0] == 4 && out[1] == 1 && out[2] == 1);          /* a point plus a vector */
    assert_int_equal(pc_value_arith('/', 2, a, NULL, 2, out), PC_OK);
    assert_true(out[0] == 0.5 && out[1] == 1 && out[2] == 0.5);      /* the weight divided too */
    assert_int_equal(pc_value_arith('/', 2, a, NULL, 0, out), PC_EZERO);
    assert_int_equal(pc_value_arith('*', 2, (double[]){1e308, 0, 1}, NULL, 10, out), PC_ENONFINITE);
    assert_int_equal(pc_value_ratio(2, (double[]){-4, 2, 0}, b + 0, &r), PC_ENOTCOLLINEAR);
    assert_int_equal(pc_value_ratio(2, (double[]){-6, 2, 0}, b, &r), PC_OK);
    assert_float_equal(r, -2, 1e-15);
    assert_int_equal(pc_value_ratio(2, a, b, &r), PC_EWEIGHT);
}

static void test_arith_text(void **state) {
    (void)state;
    char msg[400];
    double a[] = {1, 2, 1}, u[] = {1, 0, 0}, v[] = {0, 1, 0};
    pc_operand pt = {2, a, 0, 0, "a point"}, num = {0, NULL, 1, INFINITY, "a number"};
    pc_operand tab = {0, NULL, 0, 0, "a table"}, p3 = {3, (double[]){1, 2, 3, 1}, 0, 0, "a point"};
    pc_arith_text('+', &pt, &tab, msg, sizeof msg);
    assert_string_equal(msg, "cannot add a point and a table: points and vectors add only to points and vectors; "
                             "to shift a point write A + V(dx, dy)");
    pc_arith_text('-', &pt, &p3, msg, sizeof msg);
    assert_string_equal(msg, "cannot subtract a 2-D value and a 3-D value: dimensions cannot be mixed");
    pc_arith_text('*', &num, &pt, msg, sizeof msg);
    assert_string_equal(msg, "cannot multiply a point by inf");
    pc_arith_text('/', &tab, &pt, msg, sizeof msg);
    assert_string_equal(msg, "cannot divide a table by a point");
    pc_operand pu = {2, u, 0, 0, "a point"}, pv = {2, v, 0, 0, "a point"};
    pc_arith_text('/', &pu, &pv, msg, sizeof msg);
    assert_string_equal(msg, "cannot divide vectors that are not parallel: they are 90 degrees apart "
                             "(the ratio u/v needs u = r v, within 1e-9)");
    pc_arith_text('u', &tab, &tab, msg, sizeof msg);
    assert_string_equal(msg, "cannot negate a table");
}

static void test_locations(void **state) {
    (void)state;
    char msg[600];
    pc_location_text("pset: argument #1", 2, (double[]){1, 0, 0}, msg, sizeof msg);
    assert_string_equal(msg, "pset: argument #1 is a vector V(1, 0) (weight 0), not a point: the coefficients of a "
                             "point equation must sum to 1 for a point and to 0 for a vector (the membership "
                             "condition); to place a vector, add it to a point, e.g. P(0, 0) + v");
    double xy[2] = {0, 0};
    assert_int_equal(pc_drawn(2, (double[]){2, 4, 2}, PC_OK, xy), PC_EWEIGHT);
    pc_drawn_text("pset: argument #1", PC_EWEIGHT, 2, (double[]){2, 4, 2}, msg, sizeof msg);
    assert_true(strncmp(msg, "pset: argument #1 has weight 2, so it is neither", 48) == 0);
    assert_int_equal(pc_drawn(2, (double[]){INFINITY, 4, 1}, PC_OK, xy), PC_ENONFINITE);   /* an overflow */
    pc_drawn_text("pset: self", PC_ENONFINITE, 2, (double[]){INFINITY, 4, 1}, msg, sizeof msg);
    assert_string_equal(msg, "pset: self has infinite or NaN coordinates");
    assert_int_equal(pc_drawn(2, (double[]){3, 4, 1}, PC_OK, xy), PC_OK);
    assert_true(xy[0] == 3 && xy[1] == 4);
    assert_int_equal(pc_drawn(3, (double[]){1, 2, 3, 1}, PC_EARG, xy), PC_EDIM);   /* no camera */
    pc_drawn_text("line: argument #3", PC_EDIM, 3, (double[]){1, 2, 3, 1}, msg, sizeof msg);
    assert_string_equal(msg, "line: argument #3 must be a 2-D point, got the 3-D P(1, 2, 3)");
    assert_int_equal(pc_drawn(3, (double[]){1, 2, 3, 1}, PC_IMPROPER, xy), PC_IMPROPER);
    pc_drawn_text("line: argument #1", PC_IMPROPER, 3, (double[]){1, 2, 3, 1}, msg, sizeof msg);
    assert_string_equal(msg, "line: argument #1 (P(1, 2, 3)) projects to infinity (it lies in the camera's vanishing plane)");
    xy[0] = 7;
    assert_int_equal(pc_drawn(3, (double[]){1, 2, 3, 1}, PC_OK, xy), PC_OK);   /* projected: xy kept */
    assert_true(xy[0] == 7);
    double x = 0;
    assert_int_equal(pc_coord(2, (double[]){1, 2, 1}, 1, &x), PC_OK);
    assert_true(x == 2);
    assert_int_equal(pc_coord(2, (double[]){1, 2, 0}, 0, &x), PC_OK);            /* a component */
    assert_true(x == 1);
    assert_int_equal(pc_coord(2, (double[]){3, 6, 1 + 1e-12}, 1, &x), PC_OK);    /* a location */
    assert_float_equal(x, 6 / (1 + 1e-12), 1e-15);
    assert_int_equal(pc_coord(2, (double[]){2, 4, 2}, 0, &x), PC_EWEIGHT);
    assert_int_equal(pc_coord(2, (double[]){1, 2, 1}, 2, &x), PC_EDIM);
    pc_coord_text(2, (double[]){1, 2, 1}, 2, "z", msg, sizeof msg);
    assert_string_equal(msg, "P(1, 2) is 2-D: it has no coordinate .z");
    pc_coord_text(2, (double[]){2, 4, 2}, 0, NULL, msg, sizeof msg);
    assert_true(strncmp(msg, "reading p[1]: the value 2*P(1, 2) has weight 2, so it is neither", 64) == 0);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_numbers), cmocka_unit_test(test_values),
                                       cmocka_unit_test(test_failures), cmocka_unit_test(test_near),
                                       cmocka_unit_test(test_arith),
                                       cmocka_unit_test(test_arith_text), cmocka_unit_test(test_locations)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
