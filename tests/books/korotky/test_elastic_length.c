/* The fixed-length elastic line (Korotky & Vitovtov 2021, the clamped experiment: a clamped
 * ruler keeps its length between the clamps; korotky_curves_surfaces.md A.3, A.11). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "elastic.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

/* Table A1: the support points A, B, C, D, E */
static const double PTS[10] = {1.2, 0.9, 2.1, 2.3, 2.8, 4, 5, 3.2, 5.5, 2.1};

static double length_of(const pc_curve *c) {
    double len = 0;
    assert_int_equal(pc_curve_length(c, c->t0, c->t1, 1e-10, &len), PC_OK);
    return len;
}

/* the curve passes the pins at its integer parameters, with continuous curvature */
static void through_pins(const pc_curve *c) {
    double d[6], dk, da;
    for (int i = 0; i < 5; i++) {
        assert_int_equal(pc_curve_derivs(c, i, 0, d), PC_OK);
        NEAR(d[0], PTS[2 * i], 1e-12);
        NEAR(d[1], PTS[2 * i + 1], 1e-12);
    }
    assert_int_equal(pc_curve_joint_jumps(c, &dk, &da, NULL), PC_OK);
    assert_true(dk < 1e-9 && da < 1e-9);
}

/* Free ends, the length of the free minimum (the digest's proxy: 7.4735, energy 1.8188): the
 * constraint is inactive, so the fixed-length curve is the free one. */
static void test_free_length_is_free_minimum(void **state) {
    (void)state;
    int st;
    double E0, E;
    pc_curve *c0 = pc_elastic(5, PTS, 0, NULL, &E0, &st);
    assert_non_null(c0);
    double L0 = length_of(c0);
    NEAR(L0, 7.4735, 5e-3);
    NEAR(E0, 1.8188, 2e-3);
    pc_curve *c = pc_elastic_length(5, PTS, 0, NULL, L0, &E, &st);
    assert_non_null(c);
    NEAR(length_of(c), L0, 1e-6);
    NEAR(E, E0, 1e-5);
    through_pins(c);
    pc_curve_release(c);
    pc_curve_release(c0);
}

/* Clamped at the slopes 0.2 and -0.3 (Table A4): a given length is met, the clamps hold, and
 * any length other than the free-length minimum's costs energy. */
static void test_clamped_fixed_length(void **state) {
    (void)state;
    int st;
    double ends[2] = {atan(0.2), atan(-0.3)}, E0, d[4];
    pc_curve *c0 = pc_elastic(5, PTS, 0, ends, &E0, &st);
    assert_non_null(c0);
    double L0 = length_of(c0);
    for (int k = -1; k <= 1; k += 2) {
        double L = L0 + 0.25 * k, E;
        pc_curve *c = pc_elastic_length(5, PTS, 0, ends, L, &E, &st);
        assert_non_null(c);
        NEAR(length_of(c), L, 1e-6);
        assert_true(E > E0 + 1e-4);
        through_pins(c);
        pc_curve_derivs(c, 0, 1, d);
        NEAR(d[3] / d[2], 0.2, 1e-12);
        pc_curve_derivs(c, 4, 1, d);
        NEAR(d[3] / d[2], -0.3, 1e-12);
        /* the energy reported is the curve's own */
        double Ec;
        assert_int_equal(pc_curve_bending_energy(c, &Ec), PC_OK);
        NEAR(Ec, E, 1e-3 * E);
        pc_curve_release(c);
    }
    pc_curve_release(c0);
}

static void test_length_errors(void **state) {
    (void)state;
    int st;
    double E;
    /* the polyline A B C D E is 7.0521 long: no curve through the pins is shorter */
    assert_null(pc_elastic_length(5, PTS, 0, NULL, 7.05, &E, &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_null(pc_elastic_length(5, PTS, 0, NULL, -1, &E, &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_null(pc_elastic_length(5, PTS, 0, NULL, NAN, &E, &st));
    assert_int_equal(st, PC_ENONFINITE);
    /* two points and one piece: a segment, nothing to bend */
    assert_null(pc_elastic_length(2, PTS, 1, NULL, 5, &E, &st));
    assert_int_equal(st, PC_EDIM);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_free_length_is_free_minimum),
        cmocka_unit_test(test_clamped_fixed_length),
        cmocka_unit_test(test_length_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
