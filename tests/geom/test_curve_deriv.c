/* Derivatives of any order, one side of a joint, and power-basis coefficients (curve.h:
 * pc_curve_eval_hn, pc_curve_derivs_n, pc_curve_monomial): the cubic's third derivative
 * 6(P3 - 3 P2 + 3 P1 - P0) (Konopatsky §3.7 needs it), the jumps at the joints of a kinked
 * piecewise curve and of a quadratic B-spline, a rational quadratic's derivatives against its
 * closed form, and the monomial form of the book's examples. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "curve.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_cubic(void **state) {
    (void)state;
    const double cp[12] = {0, 0, 1, 1, 3, 1, 4, 2, 1, 6, -1, 1};
    int st;
    pc_curve *c = pc_curve_bezier(2, 4, cp, &st);
    double d[10], ref[6];
    assert_int_equal(pc_curve_derivs_n(c, 0.3, 4, 0, d), PC_OK);
    assert_int_equal(pc_curve_derivs(c, 0.3, 2, ref), PC_OK);
    for (int i = 0; i < 6; i++) NEAR(d[i], ref[i], 1e-13);
    NEAR(d[6], 6 * (6 - 3 * 4 + 3 * 1 - 0), 1e-12);     /* the third derivative, constant */
    NEAR(d[7], 6 * (-1 - 3 * 2 + 3 * 3 - 0), 1e-12);
    NEAR(d[8], 0, 0); NEAR(d[9], 0, 0);                  /* the fourth vanishes */
    /* monomial: C(t) = sum a_j t^j with a_0 = P0, a_1 = 3(P1 - P0), a_2 = 3(P2 - 2P1 + P0),
     * a_3 = P3 - 3P2 + 3P1 - P0 */
    double m[12];
    int deg;
    assert_int_equal(pc_curve_monomial(c, 0, m, &deg), PC_OK);
    assert_int_equal(deg, 3);
    NEAR(m[0], 0, 1e-14); NEAR(m[3], 3, 1e-14); NEAR(m[6], 3 * (4 - 2), 1e-13); NEAR(m[9], 6 - 12 + 3, 1e-13);
    NEAR(m[4], 9, 1e-14); NEAR(m[7], 3 * (2 - 6), 1e-13); NEAR(m[10], -1 - 6 + 9, 1e-13);
    NEAR(m[2], 1, 1e-14); NEAR(m[5], 0, 1e-14); NEAR(m[8], 0, 1e-14); NEAR(m[11], 0, 1e-14);
    pc_curve_release(c);
}

static void test_joints(void **state) {
    (void)state;
    /* two quadratic pieces over [0, 1], [1, 3] with a kink at (2, 0): (0,0) (1,1) (2,0) (4,1) (5,0) */
    const double cp[15] = {0, 0, 1, 1, 1, 1, 2, 0, 1, 4, 1, 1, 5, 0, 1};
    const double brk[3] = {0, 1, 3};
    int st;
    pc_curve *c = pc_curve_bezier_pieces(2, 2, 2, cp, brk, &st);
    double l[4], r[4], d[4];
    assert_int_equal(pc_curve_derivs_n(c, 1, 1, -1, l), PC_OK);
    assert_int_equal(pc_curve_derivs_n(c, 1, 1, 1, r), PC_OK);
    assert_int_equal(pc_curve_derivs_n(c, 1, 1, 0, d), PC_OK);
    NEAR(l[0], 2, 1e-15); NEAR(r[0], 2, 1e-15);          /* one point */
    NEAR(l[2], 2 * (2 - 1) / 1.0, 1e-14); NEAR(l[3], 2 * (0 - 1), 1e-14);   /* 2(P2 - P1)/1 */
    NEAR(r[2], 2 * (4 - 2) / 2.0, 1e-14); NEAR(r[3], 2 * (1 - 0) / 2.0, 1e-14); /* 2(P1 - P0)/2 */
    NEAR(d[2], r[2], 0); NEAR(d[3], r[3], 0);            /* the default is the right side */
    /* inside a piece the sides agree; at the ends the only piece is used */
    assert_int_equal(pc_curve_derivs_n(c, 0.5, 1, -1, l), PC_OK);
    assert_int_equal(pc_curve_derivs_n(c, 0.5, 1, 1, r), PC_OK);
    NEAR(l[2], r[2], 0);
    assert_int_equal(pc_curve_derivs_n(c, 3, 1, 1, r), PC_OK);
    NEAR(r[2], 2 * (5 - 4) / 2.0, 1e-14);
    /* monomial of the second piece in the curve's own t: C(t) on [1, 3] */
    double m[9];
    int deg;
    assert_int_equal(pc_curve_monomial(c, 1, m, &deg), PC_OK);
    for (double t = 1; t <= 3; t += 0.5) {
        double x[2];
        pc_curve_eval(c, t, x);
        NEAR(m[0] + m[3] * t + m[6] * t * t, x[0], 1e-12);
        NEAR(m[1] + m[4] * t + m[7] * t * t, x[1], 1e-12);
    }
    assert_int_equal(pc_curve_monomial(c, 2, m, &deg), PC_EDOMAIN);
    pc_curve_release(c);
    /* a quadratic B-spline is C1 at its knots: the first derivatives agree, the second jump */
    const double bp[12] = {0, 0, 1, 1, 2, 1, 3, 0, 1, 4, 2, 1};
    pc_curve *b = pc_curve_bspline(2, 2, 4, bp, PC_KNOTS_OPEN, NULL, &st);
    double kl[6], kr[6];
    double knot = b->knots[3];
    assert_int_equal(pc_curve_derivs_n(b, knot, 2, -1, kl), PC_OK);
    assert_int_equal(pc_curve_derivs_n(b, knot, 2, 1, kr), PC_OK);
    NEAR(kl[2], kr[2], 1e-12); NEAR(kl[3], kr[3], 1e-12);
    assert_true(fabs(kl[5] - kr[5]) > 1);
    /* each side against the limit from that side */
    double e[6];
    pc_curve_derivs(b, knot - 1e-9, 2, e);
    NEAR(kl[5], e[5], 1e-6);
    pc_curve_derivs(b, knot + 1e-9, 2, e);
    NEAR(kr[5], e[5], 1e-6);
    pc_curve_release(b);
}

static void test_rational(void **state) {
    (void)state;
    /* the quarter circle (1,0), (1,1) w = 1/sqrt 2, (0,1): C(t) = ((1-t^2)... in t = tan(phi/2)
     * form its derivatives are those of a unit-speed circle only at t = 0; check against
     * differences of the exact lower orders */
    const double r2 = sqrt(0.5), cp[9] = {1, 0, 1, r2, r2, r2, 0, 1, 1};
    int st;
    pc_curve *c = pc_curve_bezier(2, 3, cp, &st);
    double d[10], lo[6], hi[6], h = 1e-5;
    assert_int_equal(pc_curve_derivs_n(c, 0.4, 4, 0, d), PC_OK);
    pc_curve_derivs(c, 0.4 - h, 2, lo);
    pc_curve_derivs(c, 0.4 + h, 2, hi);
    NEAR(d[6], (hi[4] - lo[4]) / (2 * h), 1e-5);
    NEAR(d[7], (hi[5] - lo[5]) / (2 * h), 1e-5);
    double d3l[8], d3h[8];
    pc_curve_derivs_n(c, 0.4 - h, 3, 0, d3l);
    pc_curve_derivs_n(c, 0.4 + h, 3, 0, d3h);
    NEAR(d[8], (d3h[6] - d3l[6]) / (2 * h), 1e-4);
    assert_true(fabs(d[8]) > 0.01);                    /* rational: beyond the degree, not 0 */
    double m[9];
    int deg;
    assert_int_equal(pc_curve_monomial(c, 0, m, &deg), PC_OK);
    NEAR(m[2], 1, 1e-15); NEAR(m[5], 2 * (r2 - 1), 1e-14); NEAR(m[8], 2 - 2 * r2, 1e-14);
    assert_int_equal(pc_curve_derivs_n(c, 0.4, PC_CURVE_MAXDEG + 1, 0, d), PC_EDOMAIN);
    pc_curve_release(c);
}

/* the coefficients by coordinate, the pieces counted, the weight polynomial told */
static void test_monomial_rows(void **state) {
    (void)state;
    const double r2 = sqrt(0.5), cp[9] = {1, 0, 1, r2, r2, r2, 0, 1, 1};
    int st, deg = -1, rational = -1;
    pc_curve *c = pc_curve_bezier(2, 3, cp, &st);
    double rows[9], m[9];
    assert_int_equal(pc_curve_npieces(c), 1);
    assert_int_equal(pc_curve_monomial_rows(c, 0, rows, &deg, &rational), PC_OK);
    assert_int_equal(pc_curve_monomial(c, 0, m, &deg), PC_OK);
    assert_int_equal(deg, 2);
    assert_int_equal(rational, 1);
    for (int x = 0; x < 3; x++)
        for (int j = 0; j <= 2; j++) NEAR(rows[x * 3 + j], m[j * 3 + x], 0);
    NEAR(rows[6], 1, 1e-15); NEAR(rows[7], 2 * (r2 - 1), 1e-14);   /* the weight's row */
    assert_int_equal(pc_curve_monomial_rows(c, 1, rows, &deg, &rational), PC_EDOMAIN);
    pc_curve_release(c);
    /* a polynomial B-spline (open knots 0 0 0 1 2 2 2: two spans), the weight 1 */
    const double bp[12] = {0, 0, 1, 1, 2, 1, 3, 0, 1, 4, 2, 1};
    pc_curve *b = pc_curve_bspline(2, 2, 4, bp, PC_KNOTS_OPEN, NULL, &st);
    assert_int_equal(pc_curve_npieces(b), 2);
    assert_int_equal(pc_curve_monomial_rows(b, 1, rows, &deg, &rational), PC_OK);
    assert_int_equal(rational, 0);
    NEAR(rows[6], 1, 1e-15); NEAR(rows[7], 0, 0); NEAR(rows[8], 0, 0);
    assert_true(!signbit(rows[8]));   /* no -0 */
    pc_curve_release(b);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cubic), cmocka_unit_test(test_joints), cmocka_unit_test(test_rational),
        cmocka_unit_test(test_monomial_rows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
