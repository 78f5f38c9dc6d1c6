/* Plane curves of the textbook (plane_curves.h): the circles of Buimov §3.2 (examples 1-3 with
 * the digest's corrected values), the conic classification and rotation of §3.1/§3.3, the
 * point generators of §3.2-§3.5 (the digest's test vectors 22 and 23, the corrected
 * recurrences against their closed forms), and the conics as rational Bezier curves: every
 * point on the conic, exact at the breakpoints, the book's parameter for the parabola. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "plane_curves.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))
static const double PI = 3.14159265358979323846;

/* Example 1: (1,1), (2,2), (3,2): d = -5, e = -1, f = 4 (the book prints x^2 + y^2 - 5x + y + 4,
 * which fails at (1,1)), centre (2.5, 0.5), r = sqrt 2.5 */
static void circle_three_points(void **st) {
    (void)st;
    pc_circle_eq c;
    double a[2] = {1, 1}, b[2] = {2, 2}, d[2] = {3, 2};
    assert_int_equal(pc_circle3(a, b, d, &c), PC_OK);
    NEAR(c.d, -5, 1e-12); NEAR(c.e, -1, 1e-12); NEAR(c.f, 4, 1e-12);
    NEAR(c.c[0], 2.5, 1e-12); NEAR(c.c[1], 0.5, 1e-12); NEAR(c.r, sqrt(2.5), 1e-12);
    double k[6] = {1, 0, 1, c.d, c.e, c.f};
    NEAR(pc_conic_value(k, 1, 1), 0, 1e-12); NEAR(pc_conic_value(k, 3, 2), 0, 1e-12);
    /* far from the origin the answer is as good */
    double A[2] = {1e6 + 1, 1e6 + 1}, B[2] = {1e6 + 2, 1e6 + 2}, C[2] = {1e6 + 3, 1e6 + 2};
    assert_int_equal(pc_circle3(A, B, C, &c), PC_OK);
    NEAR(c.c[0], 1e6 + 2.5, 1e-8); NEAR(c.c[1], 1e6 + 0.5, 1e-8); NEAR(c.r, sqrt(2.5), 1e-9);
    double L[2] = {4, 4};
    assert_int_equal(pc_circle3(a, b, L, &c), PC_ECOLLINEAR);
    assert_int_equal(pc_circle3(a, a, d, &c), PC_ECOINCIDENT);
    assert_int_equal(pc_circle3(a, b, b, &c), PC_ECOINCIDENT);
}

/* Example 2: radius 5 through (1,1) and (3,2): the exact centres (2 + sqrt 4.75, 1.5 -
 * 2 sqrt 4.75) (the book's, printed rounded as (4.2, -2.85)) and (-0.179449, 5.858899) */
static void circle_two_points_radius(void **st) {
    (void)st;
    pc_circle_eq c[2];
    double a[2] = {1, 1}, b[2] = {3, 2};
    assert_int_equal(pc_circle2r(a, b, 5, c), PC_OK);
    double s = sqrt(4.75);
    NEAR(c[0].c[0], 2 + s, 1e-12); NEAR(c[0].c[1], 1.5 - 2 * s, 1e-12);
    NEAR(c[0].d, -8.358899, 5e-7); NEAR(c[0].e, 5.717798, 5e-7); NEAR(c[0].f, 0.641101, 5e-7);
    NEAR(c[1].c[0], -0.179449, 5e-7); NEAR(c[1].c[1], 5.858899, 5e-7);
    NEAR(c[1].d, 0.358899, 5e-7); NEAR(c[1].e, -11.717798, 5e-7); NEAR(c[1].f, 9.358899, 5e-7);
    for (int i = 0; i < 2; i++) {   /* the book's three equations hold */
        NEAR(2 + c[i].d + c[i].e + c[i].f, 0, 1e-12);
        NEAR(13 + 3 * c[i].d + 2 * c[i].e + c[i].f, 0, 1e-12);
        NEAR(c[i].d * c[i].d / 4 + c[i].e * c[i].e / 4 - c[i].f, 25, 1e-11);
    }
    double h[2] = {2, 1.5};       /* r = half the chord: one circle, twice */
    assert_int_equal(pc_circle2r(a, b, hypot(2, 1) / 2, c), PC_OK);
    NEAR(c[0].c[0], h[0], 1e-12); NEAR(c[1].c[1], h[1], 1e-12);
    assert_int_equal(pc_circle2r(a, b, 1, c), PC_EDOMAIN);
    assert_int_equal(pc_circle2r(a, a, 1, c), PC_ECOINCIDENT);
    assert_int_equal(pc_circle2r(a, b, -5, c), PC_EDOMAIN);
}

/* Example 3: from (1,1) with slope 1, slope 0 at x = 3: d = -6, e = 2, f = 2, centre (3, -1),
 * r = sqrt 8, end points (3, -1 +- 2 sqrt 2) */
static void circle_point_slopes(void **st) {
    (void)st;
    pc_circle_eq c[2];
    double ends[4], p[2] = {1, 1};
    int n;
    assert_int_equal(pc_circle_slopes(p, 1, 3, 0, c, ends, &n), PC_OK);
    assert_int_equal(n, 2);
    for (int i = 0; i < 2; i++) {
        NEAR(c[i].d, -6, 1e-12); NEAR(c[i].e, 2, 1e-12); NEAR(c[i].f, 2, 1e-12);
        NEAR(c[i].r, sqrt(8), 1e-12);
    }
    NEAR(ends[0], 3, 0); NEAR(ends[1], -1 + 2 * sqrt(2), 1e-12);
    NEAR(ends[2], 3, 0); NEAR(ends[3], -1 - 2 * sqrt(2), 1e-12);
    /* a general end slope: the slope -(2x + d)/(2y + e) is m1 at p and m2 at the end point */
    assert_int_equal(pc_circle_slopes(p, 0.5, 4, -2, c, ends, &n), PC_OK);
    assert_true(n >= 1);
    for (int i = 0; i < n; i++) {
        NEAR(-(2 * p[0] + c[i].d) / (2 * p[1] + c[i].e), 0.5, 1e-12);
        NEAR(ends[2 * i], 4, 1e-12);
        NEAR(-(2 * ends[2 * i] + c[i].d) / (2 * ends[2 * i + 1] + c[i].e), -2, 1e-12);
        double k[6] = {1, 0, 1, c[i].d, c[i].e, c[i].f};
        NEAR(pc_conic_value(k, p[0], p[1]), 0, 1e-12);
        NEAR(pc_conic_value(k, ends[2 * i], ends[2 * i + 1]), 0, 1e-11);
    }
    assert_int_equal(pc_circle_slopes(p, 1, 1, 0, c, ends, &n), PC_EDOMAIN);
    assert_int_equal(pc_circle_slopes(p, 0, 3, 0, c, ends, &n), PC_EDOMAIN);  /* no circle */
}

static void conic_classify_rotate(void **st) {
    (void)st;
    pc_conic_class k;
    assert_int_equal(pc_conic_classify(1, 0, 1, &k), PC_OK); assert_int_equal(k, PC_CONIC_ELLIPSE);
    assert_int_equal(pc_conic_classify(1, 2, 1, &k), PC_OK); assert_int_equal(k, PC_CONIC_PARABOLA);
    assert_int_equal(pc_conic_classify(1, 0, -1, &k), PC_OK); assert_int_equal(k, PC_CONIC_HYPERBOLA);
    assert_int_equal(pc_conic_classify(0, 0, 3, &k), PC_OK); assert_int_equal(k, PC_CONIC_PARABOLA);
    assert_int_equal(pc_conic_classify(0, 0, 0, &k), PC_EDOMAIN);
    assert_int_equal(pc_conic_classify(NAN, 0, 1, &k), PC_ENONFINITE);
    /* digest 9.2 #24: a' = 4, c' = 9, d' = -3, e' = 2, f' = -7, alpha = 0.3: both forms give
     * -3.676332 at (1.3, -0.4) */
    double in[6] = {4, 0, 9, -3, 2, -7}, out[6];
    pc_conic_rotate(in, 0.3, out);
    double x = 1.3, y = -0.4, c = cos(0.3), s = sin(0.3);
    NEAR(pc_conic_value(out, x, y), -3.676332, 5e-7);
    NEAR(pc_conic_value(in, x * c - y * s, x * s + y * c), -3.676332, 5e-7);
    NEAR(out[1], 2 * (9 - 4) * c * s, 1e-14);       /* b = 2(c' - a') cos sin, corrected */
    /* rotation keeps the discriminant and composes */
    double in2[6] = {2, 1.5, -1, 0.3, -2, 5}, r1[6], r2[6], r12[6];
    pc_conic_rotate(in2, 0.4, r1);
    pc_conic_rotate(r1, -0.9, r2);
    pc_conic_rotate(in2, -0.5, r12);
    for (int i = 0; i < 6; i++) NEAR(r2[i], r12[i], 1e-13);
    NEAR(r1[1] * r1[1] - 4 * r1[0] * r1[2], in2[1] * in2[1] - 4 * in2[0] * in2[2], 1e-13);
    /* the axis-aligned conics' coefficients vanish on them */
    double e[6], h[6], p[6];
    pc_conic_ellipse_coef(1, 2, 3, 2, e);
    NEAR(pc_conic_value(e, 1 + 3 * cos(0.7), 2 + 2 * sin(0.7)), 0, 1e-12);
    pc_conic_hyperbola_coef(-1, 1, 2, 1.5, h);
    NEAR(pc_conic_value(h, -1 + 2 * cosh(0.7), 1 + 1.5 * sinh(0.7)), 0, 1e-12);
    pc_conic_parabola_coef(2, -1, 0.5, p);    /* (x - 2)^2 = 2(y + 1): f = m^2 + 4pn = 2 */
    NEAR(p[5], 2, 0);
    NEAR(pc_conic_value(p, 4, 1), 0, 1e-12);
}

/* digest 9.2 #22, #23: the generators after n steps */
static void generators(void **st) {
    (void)st;
    double xy[2 * 41];
    assert_int_equal(pc_conic_points(PC_GEN_CIRCLE, PC_GEN_RATIONAL, 1, 0, 0.5, 1, xy), PC_OK);
    NEAR(xy[2], 0.6, 1e-15); NEAR(xy[3], 0.8, 1e-15);
    assert_int_equal(pc_conic_points(PC_GEN_CIRCLE, PC_GEN_RECURRENCE, 1, 0, PI / 2, 2, xy), PC_OK);
    NEAR(xy[0], 1, 0); NEAR(xy[2], 0, 1e-15); NEAR(xy[3], 1, 1e-15); NEAR(xy[4], -1, 1e-15); NEAR(xy[5], 0, 1e-15);
    assert_int_equal(pc_conic_points(PC_GEN_ELLIPSE, PC_GEN_RECURRENCE, 3, 2, 0.1, 10, xy), PC_OK);
    NEAR(xy[20], 1.620907, 5e-7); NEAR(xy[21], 1.682942, 5e-7);
    NEAR(xy[20], 3 * cos(1.0), 1e-13); NEAR(xy[21], 2 * sin(1.0), 1e-13);
    assert_int_equal(pc_conic_points(PC_GEN_PARABOLA, PC_GEN_RECURRENCE, 0.5, 0, 0.1, 10, xy), PC_OK);
    NEAR(xy[20], 0.5, 1e-13); NEAR(xy[21], 1.0, 1e-13);   /* the printed sign gives (-0.4, 1.0) */
    assert_int_equal(pc_conic_points(PC_GEN_HYPERBOLA_SEC, PC_GEN_RECURRENCE, 2, 1.5, 0.05, 10, xy), PC_OK);
    NEAR(xy[20], 2.278988, 5e-7); NEAR(xy[21], 0.819454, 5e-7);
    NEAR(xy[20], 2 / cos(0.5), 1e-12); NEAR(xy[21], 1.5 * tan(0.5), 1e-12);
    assert_int_equal(pc_conic_points(PC_GEN_HYPERBOLA_COSH, PC_GEN_RECURRENCE, 2, 1.5, 0.05, 10, xy), PC_OK);
    NEAR(xy[20], 2.255252, 5e-7); NEAR(xy[21], 0.781643, 5e-7);
    /* every recurrence follows its parametric form step by step */
    pc_gen_kind kinds[5] = {PC_GEN_CIRCLE, PC_GEN_ELLIPSE, PC_GEN_PARABOLA, PC_GEN_HYPERBOLA_SEC, PC_GEN_HYPERBOLA_COSH};
    for (int k = 0; k < 5; k++) {
        double r[2 * 41];
        assert_int_equal(pc_conic_points(kinds[k], PC_GEN_RECURRENCE, 2, 1.5, 0.035, 40, r), PC_OK);
        assert_int_equal(pc_conic_points(kinds[k], PC_GEN_PARAM, 2, 1.5, 0.035, 40, xy), PC_OK);
        for (int i = 0; i < 82; i++) NEAR(r[i], xy[i], 1e-12 * (1 + fabs(xy[i])));
    }
    /* the explicit circle: uniform x, y = sqrt(r^2 - x^2) */
    assert_int_equal(pc_conic_points(PC_GEN_CIRCLE, PC_GEN_EXPLICIT, 2, 0, 0.5, 8, xy), PC_OK);
    NEAR(xy[2], 1.5, 0); NEAR(xy[3], sqrt(4 - 2.25), 1e-15); NEAR(xy[16], -2, 0); NEAR(xy[17], 0, 0);
    assert_int_equal(pc_conic_points(PC_GEN_CIRCLE, PC_GEN_EXPLICIT, 2, 0, 0.5, 9, xy), PC_EDOMAIN);
    assert_int_equal(pc_conic_points(PC_GEN_ELLIPSE, PC_GEN_RATIONAL, 2, 1, 0.5, 9, xy), PC_EDOMAIN);
    assert_int_equal(pc_conic_points(PC_GEN_HYPERBOLA_SEC, PC_GEN_PARAM, 2, 1, 0.2, 8, xy), PC_EDOMAIN);
    assert_int_equal(pc_conic_points(PC_GEN_ELLIPSE, PC_GEN_PARAM, 2, 0, 0.2, 8, xy), PC_EDOMAIN);
    assert_int_equal(pc_conic_points(PC_GEN_ELLIPSE, PC_GEN_PARAM, 2, 1, NAN, 8, xy), PC_ENONFINITE);
}

/* the conics as curves: on the conic everywhere, the book's point at every breakpoint */
static void conic_curves(void **st) {
    (void)st;
    int s;
    double c[2] = {1, -2}, x[2];
    pc_curve *e = pc_curve_ellipse(c, 3, 2, -0.3, 5.1, &s);
    assert_non_null(e);
    assert_int_equal(e->nknots, 5);                      /* 4 pieces of at most 90 degrees */
    NEAR(e->t0, -0.3, 0); NEAR(e->t1, 5.1, 0);
    for (int i = 0; i <= 100; i++) {
        double t = -0.3 + 5.4 * i / 100;
        assert_int_equal(pc_curve_eval(e, t, x), PC_OK);
        NEAR(pow((x[0] - 1) / 3, 2) + pow((x[1] + 2) / 2, 2), 1, 1e-13);
    }
    for (int i = 0; i < e->nknots; i++) {
        double t = e->knots[i];
        assert_int_equal(pc_curve_eval(e, t, x), PC_OK);
        NEAR(x[0], 1 + 3 * cos(t), 1e-14); NEAR(x[1], -2 + 2 * sin(t), 1e-14);
    }
    double len;
    pc_curve *circ = pc_curve_ellipse(c, 2, 2, 0, 2 * PI, &s);
    assert_int_equal(pc_curve_length(circ, 0, 2 * PI, 1e-12, &len), PC_OK);
    NEAR(len, 4 * PI, 1e-9);
    double k;
    assert_int_equal(pc_curve_curvature(circ, 1.1, &k), PC_OK);
    NEAR(k, 0.5, 1e-12);
    pc_curve_release(circ);
    pc_curve_release(e);
    /* the parabola in the book's parameter, exactly */
    pc_curve *p = pc_curve_parabola(0.5, -2, 3, &s);
    assert_non_null(p);
    for (double t = -2; t <= 3; t += 0.25) {
        assert_int_equal(pc_curve_eval(p, t, x), PC_OK);
        NEAR(x[0], 0.5 * t * t, 1e-13); NEAR(x[1], t, 1e-13);
    }
    pc_curve_release(p);
    pc_curve *h = pc_curve_hyperbola(2, 1.5, -1.7, 2.2, &s);
    assert_non_null(h);
    for (int i = 0; i <= 50; i++) {
        double t = -1.7 + 3.9 * i / 50;
        assert_int_equal(pc_curve_eval(h, t, x), PC_OK);
        NEAR(x[0] * x[0] / 4 - x[1] * x[1] / 2.25, 1, 1e-12);
        assert_true(x[0] > 0);
    }
    for (int i = 0; i < h->nknots; i++) {
        assert_int_equal(pc_curve_eval(h, h->knots[i], x), PC_OK);
        NEAR(x[0], 2 * cosh(h->knots[i]), 1e-13); NEAR(x[1], 1.5 * sinh(h->knots[i]), 1e-13);
    }
    pc_curve_release(h);
    /* the arc through three points starts at one end, passes the middle one, ends at the other */
    double a[2] = {1, 1}, b[2] = {2, 2}, d[2] = {3, 2};
    pc_curve *arc = pc_curve_arc3(a, b, d, &s);
    assert_non_null(arc);
    double p0[2], p1[2];
    pc_curve_eval(arc, arc->t0, p0);
    pc_curve_eval(arc, arc->t1, p1);
    NEAR(p0[0] + p1[0], 4, 1e-13);                     /* the ends are (1,1) and (3,2) */
    int through = 0;
    for (int i = 0; i <= 1000; i++) {
        pc_curve_eval(arc, arc->t0 + (arc->t1 - arc->t0) * i / 1000, x);
        if (hypot(x[0] - 2, x[1] - 2) < 5e-3) through = 1;
    }
    assert_true(through);
    pc_curve_release(arc);
    /* Fig 3.1: from (1, 1) along slope 1 towards x = 3, on the circle (3, -1), r = sqrt 8: the
     * arc turns clockwise to (3, 1.828427) through the top (3 - 2, ...), a quarter turn less */
    double cc[2] = {3, -1}, s1[2] = {1, 1}, dir[2] = {1, 1}, e1[2] = {3, -1 + sqrt(8)};
    arc = pc_curve_arc_dir(cc, sqrt(8), s1, dir, e1, &s);
    assert_non_null(arc);
    NEAR(arc->t1 - arc->t0, PI / 4, 1e-12);          /* 135 degrees -> 90 degrees */
    pc_curve_eval(arc, arc->t0, x); NEAR(x[0], 3, 1e-12); NEAR(x[1], -1 + sqrt(8), 1e-12);
    pc_curve_eval(arc, arc->t1, x); NEAR(x[0], 1, 1e-12); NEAR(x[1], 1, 1e-12);
    pc_curve_release(arc);
    double back[2] = {-1, -1};                        /* the other way round: 7/4 of the turn */
    arc = pc_curve_arc_dir(cc, sqrt(8), s1, back, e1, &s);
    NEAR(arc->t1 - arc->t0, 7 * PI / 4, 1e-12);
    pc_curve_release(arc);
    double radial[2] = {-1, 1};
    assert_null(pc_curve_arc_dir(cc, sqrt(8), s1, radial, e1, &s)); assert_int_equal(s, PC_EDOMAIN);
    assert_null(pc_curve_ellipse(c, 0, 1, 0, 1, &s)); assert_int_equal(s, PC_EDOMAIN);
    assert_null(pc_curve_ellipse(c, 1, 1, 1, 1, &s)); assert_int_equal(s, PC_EDOMAIN);
    assert_null(pc_curve_parabola(1, 0, NAN, &s)); assert_int_equal(s, PC_ENONFINITE);
    double L[2] = {4, 4};
    assert_null(pc_curve_arc3(a, b, L, &s)); assert_int_equal(s, PC_ECOLLINEAR);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(circle_three_points), cmocka_unit_test(circle_two_points_radius),
        cmocka_unit_test(circle_point_slopes), cmocka_unit_test(conic_classify_rotate),
        cmocka_unit_test(generators), cmocka_unit_test(conic_curves),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
