/* The textbook's why-table (buimov_why.h): each row explains the status its construction
 * really returns for the failing condition, and pc_conic_coef by kind (§3.3-§3.5). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "buimov_why.h"
#include "plane_curves.h"
#include "buimov.h"
#include "buimov_parts.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

/* the row of op for status st, which must exist */
static const char *why(const char *op, int st) {
    const pc_why *w = pc_why_find(pc_buimov_why, op, st);
    assert_non_null(w);
    return w->text;
}

static void circles_explained(void **state) {
    (void)state;
    pc_circle_eq c[2];
    double a[2] = {1, 1}, b[2] = {3, 3}, m[2] = {2, 2}, ends[4];
    int n;
    assert_string_equal(why("plane.circle3", pc_circle3(a, a, b, c)), "two of the points coincide");
    assert_non_null(strstr(why("plane.circle3", pc_circle3(a, m, b, c)), "lie on one line"));
    pc_why_call w;
    assert_int_equal(pc_circle2r_checked(a, a, 1, c, &w), PC_ECOINCIDENT);
    assert_non_null(strstr(w.row[0].text, "coincide"));
    assert_int_equal(pc_circle2r_checked(a, b, 1, c, &w), PC_EDOMAIN);   /* |AB| = 2 sqrt 2 > 2r */
    assert_string_equal(w.row[0].text, "the points are 2.8284271247462 apart, farther than the diameter 2r = 2");
    assert_int_equal(pc_circle2r_checked(a, b, 2, c, &w), PC_OK);
    NEAR(hypot(c[0].c[0] - 1, c[0].c[1] - 1), 2, 1e-12);              /* both circles through A */
    NEAR(hypot(c[1].c[0] - 3, c[1].c[1] - 3), 2, 1e-12);
    assert_int_equal(pc_circle_slopes_checked(a, 0, 3, 0, c, ends, &n, &w), PC_EDOMAIN);
    assert_non_null(strstr(w.row[0].text, "no circle"));
    assert_int_equal(pc_circle_slopes_checked(a, 1, 1, 0, c, ends, &n, &w), PC_EDOMAIN);
    assert_int_equal(w.row[0].arg, 3);
    assert_string_equal(w.row[0].text, "equals the abscissa of A");
    pc_conic_class k;
    assert_non_null(strstr(why("plane.classify", pc_conic_classify(0, 0, 0, &k)), "not a conic"));
    /* no row for a status the construction does not return */
    assert_null(pc_why_find(pc_buimov_why, "plane.circle3", PC_EDOMAIN));
}

static void curves_explained(void **state) {
    (void)state;
    int st;
    double c[2] = {0, 0}, p[6] = {0, 0, 1, 1, 1, 1};
    assert_null(pc_curve_ellipse(c, 1, 2, 1, 1, &st));
    assert_non_null(strstr(why("plane.ellipse", st), "th0 < th1"));
    assert_null(pc_curve_parabola(1, 2, 1, &st));
    assert_string_equal(why("plane.parabola", st), "need th0 < th1");
    assert_null(pc_curve_hyperbola(1, 1, 1, 0, &st));
    assert_string_equal(why("plane.hyperbola", st), "need t0 < t1");
    assert_null(pc_curve_helix(1, 1, 1, 0, &st));
    assert_string_equal(why("buimov.helix", st), "need t0 < t1");
    double o[3] = {0, 0, 0};
    assert_null(pc_surface_sphere(o, 1, 0, 1, 1, 0, &st));
    assert_string_equal(why("buimov.sphere", st), "need th0 < th1 and ph0 < ph1");
    assert_null(pc_curve_book_spline(2, 3, p, 1, PC_BOOK_NATURAL, NULL, NULL, NULL, &st));
    assert_non_null(strstr(why("buimov.spline", st), "chord of length 0"));
}

static void conic_coef_by_kind(void **state) {
    (void)state;
    double c[2] = {1, 2}, k[6], e[6];
    assert_int_equal(pc_conic_coef(0, c, 3, 2, k), PC_OK);     /* the ellipse of §3.3 */
    pc_conic_ellipse_coef(1, 2, 3, 2, e);
    for (int i = 0; i < 6; i++) NEAR(k[i], e[i], 0);
    NEAR(pc_conic_value(k, 4, 2), 0, 1e-12);                    /* the end of the major axis */
    assert_int_equal(pc_conic_coef(1, c, 2, 1.5, k), PC_OK);   /* the hyperbola: vertex (3, 2) */
    NEAR(pc_conic_value(k, 3, 2), 0, 1e-12);
    NEAR(k[2], -4, 0);
    assert_int_equal(pc_conic_coef(2, c, 0.5, NAN, k), PC_OK); /* the parabola: B unused */
    NEAR(k[4], -2, 0);
    NEAR(k[5], 1 + 4 * 0.5 * 2, 1e-12);                         /* f = m^2 + 4pn */
    assert_int_equal(pc_conic_coef(0, c, 3, 0, k), PC_EDOMAIN);
    assert_int_equal(pc_conic_coef(1, c, -1, 2, k), PC_EDOMAIN);
    pc_why_call w;
    assert_int_equal(pc_conic_coef_checked(0, c, 3, 1, 0, k, &w), PC_EDOMAIN);
    assert_non_null(strstr(w.row[0].text, "semi-axes"));
    assert_int_equal(pc_conic_coef_checked(1, c, 3, 0, 0, k, &w), PC_EDOMAIN);
    assert_int_equal(w.row[0].arg, 4);
    assert_non_null(strstr(w.row[0].text, "the hyperbola's second semi-axis"));
    assert_int_equal(pc_conic_coef_checked(2, c, 0.5, 0, 0, k, &w), PC_OK);
    NEAR(k[4], -2, 0);
    /* plane.points: B where the kind needs it, the circle's own methods, the domain */
    double xy[20];
    assert_int_equal(pc_conic_points_checked(PC_GEN_ELLIPSE, PC_GEN_PARAM, 1, 0, 0, 0.1, 5, xy, &w), PC_EDOMAIN);
    assert_string_equal(w.row[0].key, "B");
    assert_string_equal(w.row[0].text, "must be a positive number (the ellipse's), got nil");
    assert_int_equal(pc_conic_points_checked(PC_GEN_ELLIPSE, PC_GEN_RATIONAL, 1, 1, 1, 0.1, 5, xy, &w), PC_EDOMAIN);
    assert_string_equal(w.row[0].text, "the rational method is the circle's only");
    assert_int_equal(pc_conic_points_checked(PC_GEN_CIRCLE, PC_GEN_EXPLICIT, 2, 0, 0, 0.5, 9, xy, &w), PC_EDOMAIN);
    assert_non_null(strstr(w.row[0].text, "the steps leave the curve's domain"));
    assert_int_equal(pc_conic_points_checked(PC_GEN_CIRCLE, PC_GEN_PARAM, 2, 0, 0, 0.5, 4, xy, &w), PC_OK);
    NEAR(xy[2], 2 * cos(0.5), 1e-15); NEAR(xy[3], 2 * sin(0.5), 1e-15);
    assert_string_equal(pc_gen_kind_names[PC_GEN_HYPERBOLA_COSH], "hyperbola_ch");
    pc_map cam;   /* buimov.calibrate: points and images pair up; six coplanar points fix no camera */
    double rms, flat[18] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0, 1, 3, 0}, img[14] = {0};
    assert_int_equal(pc_calibrate_checked(6, flat, 7, img, &cam, &rms, &w), PC_EDIM);
    assert_string_equal(w.row[0].text, "6 points but 7 images");
    assert_int_equal(pc_calibrate_checked(6, flat, 6, img, &cam, &rms, &w), PC_ESINGULAR);
    assert_string_equal(w.row[0].op, "buimov.calibrate");
    assert_string_equal(w.row[0].text, pc_why_find(pc_buimov_why, "buimov.calibrate", PC_ESINGULAR)->text);
    assert_string_equal(pc_conic_names[PC_CONIC_PARABOLA], "parabola");
    assert_string_equal(pc_conic_names[PC_CONIC_HYPERBOLA], "hyperbola");
    assert_null(pc_conic_names[3]);
    assert_string_equal(pc_book_ends_names[PC_BOOK_NATURAL], "natural");
    assert_string_equal(pc_book_ends_names[PC_BOOK_ANTICYCLIC], "anticyclic");
    assert_null(pc_book_ends_names[4]);
    assert_string_equal(pc_book_param_names[1], "chord");   /* pc_book_spline_params' chord */
    assert_null(pc_book_param_names[2]);
}

/* the conditions of buimov.spline's options, in the order the messages come */
static void spline_options(void **state) {
    (void)state;
    pc_why_call w;
    pc_book_ends e = PC_BOOK_NATURAL;
    double len[3] = {1, 2, 3}, bad[3] = {1, 0, 2};
    assert_int_equal(pc_book_spline_check(4, &e, 0, 2, 0, -1, NULL, &w), PC_OK);
    assert_int_equal(e, PC_BOOK_CLAMPED);                        /* tangents without ends */
    e = PC_BOOK_CLAMPED;
    assert_int_equal(pc_book_spline_check(4, &e, 1, 1, 0, -1, NULL, &w), PC_EDOMAIN);
    assert_string_equal(w.row[0].text, "clamped ends need both end tangents d0 and d1");
    e = PC_BOOK_CYCLIC;
    assert_int_equal(pc_book_spline_check(3, &e, 1, 0, 0, -1, NULL, &w), PC_EDOMAIN);
    assert_string_equal(w.row[0].text, "cyclic and anticyclic ends need at least 4 points, got 3");
    e = PC_BOOK_NATURAL;
    assert_int_equal(pc_book_spline_check(4, &e, 0, 0, 1, 3, len, &w), PC_EDOMAIN);
    assert_non_null(strstr(w.row[0].text, "not both"));
    assert_int_equal(pc_book_spline_check(4, &e, 0, 0, 0, 2, len, &w), PC_EDOMAIN);
    assert_string_equal(w.row[0].key, "lengths");
    assert_string_equal(w.row[0].text, "must hold 3 segment lengths (one per segment), got 2");
    assert_int_equal(pc_book_spline_check(4, &e, 0, 0, 0, 3, bad, &w), PC_EDOMAIN);
    assert_string_equal(w.row[0].text, "[2] must be a positive length, got 0");
    assert_int_equal(pc_book_spline_check(4, &e, 0, 0, 0, 3, len, &w), PC_OK);
    assert_int_equal(e, PC_BOOK_NATURAL);
}

static void basis_checked(void **state) {
    (void)state;
    pc_why_call w;
    double q[6] = {0, 0, 1, 2, 3, 3}, N;
    assert_int_equal(pc_book_basis_checked(q, 6, 0, 2, 0.5, &N, &w), PC_OK);
    NEAR(N, 0.5, 1e-15);                                          /* the hat on [0, 1]: 1 - t */
    assert_int_equal(pc_book_basis_checked(q, 6, 4, 2, 0.5, &N, &w), PC_EDOMAIN);
    assert_string_equal(w.row[0].text, "N(i = 4, k = 2) needs the knots q[i] .. q[i + k]: 6 knots given");
    double down[3] = {0, 1, 0};
    assert_int_equal(pc_book_basis_checked(down, 3, 0, 2, 0.5, &N, &w), PC_EDOMAIN);
    assert_int_equal(w.row[0].arg, 4);
    assert_string_equal(w.row[0].text, "must not decrease ([3])");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(circles_explained), cmocka_unit_test(curves_explained),
        cmocka_unit_test(conic_coef_by_kind), cmocka_unit_test(spline_options), cmocka_unit_test(basis_checked),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
