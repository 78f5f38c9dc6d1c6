/* Quadrilateral splines and one-stroke curves: the listings' own arithmetic of examples 5, 10,
 * 33, 34 (stepanov_examples.md), end points, end directions, tangent continuity at nodes. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "spline.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void test_dirs(void **state) {
    (void)state;
    double e[3];
    pc_dir2(M_PI / 2, 1, e);   /* a quarter turn counter-clockwise on a y-down screen: up */
    NEAR(e[0], 0, 1e-15);
    NEAR(e[1], -1, 1e-15);
    pc_dir2(M_PI / 2, 0, e);
    NEAR(e[1], 1, 1e-15);
    pc_dir3(0, -M_PI / 2, e);  /* example 33, node 0: straight down */
    NEAR(e[0], 0, 1e-15);
    NEAR(e[1], 0, 1e-15);
    NEAR(e[2], -1, 1e-15);
    pc_dir3(M_PI / 3, M_PI / 6, e);
    NEAR(e[0] * e[0] + e[1] * e[1] + e[2] * e[2], 1, 1e-15);
    NEAR(e[1] / e[0], tan(M_PI / 3), 1e-12);
}

/* example 5: the listing's formulas, t in [-1, 3] */
static void test_example5(void **state) {
    (void)state;
    double pi = 3.14159, r = 100, u0 = 7 * pi / 15, u1 = .9 * pi;
    double A[2] = {300, 200}, B[2] = {350, 400};
    double P[2] = {A[0] + r * cos(u0), A[1] + r * sin(u0)};
    double Q[2] = {B[0] - r * cos(u1), B[1] - r * sin(u1)};
    for (double t = -1; t <= 3; t += 0.125) {
        double xa = A[0] + t * r * cos(u0), ya = A[1] + t * r * sin(u0);
        double xb = B[0] + (t - 1) * r * cos(u1), yb = B[1] + (t - 1) * r * sin(u1);
        double g = -2 * t * t * t + 3 * t * t;
        double X[2];
        pc_qspline(2, A, P, Q, B, t, pc_smooth_cubic(t), X);
        NEAR(X[0], xa + g * (xb - xa), 1e-9);
        NEAR(X[1], ya + g * (yb - ya), 1e-9);
    }
    double X[2];
    pc_qspline(2, A, P, Q, B, 0, 0, X);
    NEAR(X[0], 300, 0);
    NEAR(X[1], 200, 0);
    pc_qspline(2, A, P, Q, B, 1, 1, X);
    NEAR(X[0], 350, 1e-12);
    NEAR(X[1], 400, 1e-12);
}

/* example 10's DATA (angles in turns) */
static const double ex10_x[4] = {100, 200, 300, 400}, ex10_y[4] = {300, 150, 50, 100};
static const double ex10_uin[4] = {0, .3, .85, 0};
static const double ex10_rin[4] = {50, 60, 40, 50}, ex10_rout[4] = {70, 30, 80, 40};
static const double ex10_n[4] = {2, 4, 6, 2}, ex10_m[4] = {7, 5, 3, 2}, ex10_t0[4] = {.3, .5, .7, .2};

static void piece_xy(const pc_piece *pc, double t, double *x, double *y) {
    double X[2];
    pc_piece_eval(2, pc, t, X);
    *x = X[0];
    *y = X[1];
}

static void test_example10(void **state) {
    (void)state;
    double nodes[8], dir[8];
    for (int i = 0; i < 4; i++) {
        nodes[2 * i] = ex10_x[i];
        nodes[2 * i + 1] = ex10_y[i];
        pc_dir2(2 * M_PI * ex10_uin[i], 1, dir + 2 * i);
    }
    pc_stroke_spec s = {.d = 2, .nnodes = 4, .closed = 0, .nodes = nodes, .ein = dir,
                        .eout = NULL, .rin = ex10_rin, .rout = ex10_rout,
                        .n = ex10_n, .m = ex10_m, .t0 = ex10_t0};
    assert_int_equal(pc_stroke_npieces(4, 0), 3);
    pc_piece pcs[3];
    int bad;
    assert_int_equal(pc_stroke_build(&s, pcs, &bad), PC_OK);
    for (int i = 0; i < 3; i++) {
        /* the listing: v1 = x + rout cos(uout), w1 = y - rout sin(uout), ... */
        double uo = 2 * M_PI * ex10_uin[i], ui = 2 * M_PI * ex10_uin[i + 1];
        double v1 = ex10_x[i] + ex10_rout[i] * cos(uo), w1 = ex10_y[i] - ex10_rout[i] * sin(uo);
        double v2 = ex10_x[i + 1] - ex10_rin[i + 1] * cos(ui);
        double w2 = ex10_y[i + 1] + ex10_rin[i + 1] * sin(ui);
        NEAR(pcs[i].p[0], v1, 1e-12);
        NEAR(pcs[i].p[1], w1, 1e-12);
        NEAR(pcs[i].q[0], v2, 1e-12);
        NEAR(pcs[i].q[1], w2, 1e-12);
        double n = ex10_n[i], m = ex10_m[i], t0 = ex10_t0[i];
        double c1 = m / ((n - n * t0 + m * t0) * pow(t0, n - 1));
        double c2 = (1 - c1 * pow(t0, n)) / pow(1 - t0, m);
        for (double t = 0; t <= 1; t += 0.0625) {
            double xa = ex10_x[i] + t * (v1 - ex10_x[i]), ya = ex10_y[i] + t * (w1 - ex10_y[i]);
            double xb = v2 + t * (ex10_x[i + 1] - v2), yb = w2 + t * (ex10_y[i + 1] - w2);
            double g = t < t0 ? c1 * pow(t, n) : 1 - c2 * pow(1 - t, m);
            double x, y;
            piece_xy(&pcs[i], t, &x, &y);
            NEAR(x, xa + g * (xb - xa), 1e-9);
            NEAR(y, ya + g * (yb - ya), 1e-9);
        }
        /* through the nodes */
        double x, y;
        piece_xy(&pcs[i], 0, &x, &y);
        NEAR(x, ex10_x[i], 1e-12);
        NEAR(y, ex10_y[i], 1e-12);
        piece_xy(&pcs[i], 1, &x, &y);
        NEAR(x, ex10_x[i + 1], 1e-12);
        NEAR(y, ex10_y[i + 1], 1e-12);
    }
    /* no kink: the curve arrives at node 1 and leaves it along e(uin[1]) */
    double xa, ya, xb, yb;
    piece_xy(&pcs[0], 1 - 1e-6, &xa, &ya);
    piece_xy(&pcs[1], 1e-6, &xb, &yb);
    double e[2];
    pc_dir2(2 * M_PI * .3, 1, e);
    double dx = xb - xa, dy = yb - ya, l = hypot(dx, dy);
    NEAR(dx / l, e[0], 1e-4);
    NEAR(dy / l, e[1], 1e-4);
}

/* chord tangents and chord/3 sides (the reconstructions of examples 13 and 29), closed */
static void test_closed_defaults(void **state) {
    (void)state;
    double sq[8] = {0, 0, 3, 0, 3, 3, 0, 3};
    pc_stroke_spec s = {.d = 2, .nnodes = 4, .closed = 1, .nodes = sq};
    assert_int_equal(pc_stroke_npieces(4, 1), 4);
    pc_piece pcs[4];
    assert_int_equal(pc_stroke_build(&s, pcs, NULL), PC_OK);
    /* node 0: tangent parallel to N1 - N3 = (3, -3); side = chord/3 = 1 */
    NEAR(pcs[0].p[0], 1 / sqrt(2), 1e-15);
    NEAR(pcs[0].p[1], -1 / sqrt(2), 1e-15);
    /* the last piece returns to node 0, arriving along the same tangent */
    NEAR(pcs[3].b[0], 0, 0);
    NEAR(pcs[3].b[1], 0, 0);
    NEAR(pcs[3].q[0], -1 / sqrt(2), 1e-15);
    NEAR(pcs[3].q[1], 1 / sqrt(2), 1e-15);
    NEAR(pcs[0].g.h.c1, 2, 0);
    /* symmetric: the curve through the square is symmetric about its centre */
    double X[2], Y[2];
    pc_piece_eval(2, &pcs[0], 0.3, X);
    pc_piece_eval(2, &pcs[2], 0.3, Y);
    NEAR(X[0] + Y[0], 3, 1e-12);
    NEAR(X[1] + Y[1], 3, 1e-12);
    /* open: one-sided tangents at the ends */
    s.closed = 0;
    assert_int_equal(pc_stroke_build(&s, pcs, NULL), PC_OK);
    NEAR(pcs[0].p[0], 1, 1e-15);
    NEAR(pcs[0].p[1], 0, 1e-15);
    NEAR(pcs[2].q[0], 1, 1e-15);   /* N3 - 1 * unit(N3 - N2) = (0, 3) - (-1, 0) */
    NEAR(pcs[2].q[1], 3, 1e-15);
}

/* example 33's first piece (3-D, spherical angles) and example 34's explicit vectors */
static void test_3d(void **state) {
    (void)state;
    double nodes[6] = {1, 0, 1, 1, 0, .1};
    double ein[6], eout[6];
    pc_dir3(0, 2 * M_PI * -.25, ein);
    pc_dir3(0, 2 * M_PI * -.25, ein + 3);
    pc_dir3(0, 2 * M_PI * -.25, eout);
    pc_dir3(0, 2 * M_PI * -.25, eout + 3);
    double r[2] = {.25, .25};
    pc_stroke_spec s = {.d = 3, .nnodes = 2, .nodes = nodes, .ein = ein, .eout = eout,
                        .rin = r, .rout = r};
    pc_piece pc;
    assert_int_equal(pc_stroke_build(&s, &pc, NULL), PC_OK);
    NEAR(pc.p[2], .75, 1e-15);
    NEAR(pc.q[2], .35, 1e-15);
    NEAR(pc.p[0], 1, 1e-15);
    double X[3];
    pc_piece_eval(3, &pc, 0.5, X);   /* a straight vertical strand: x, y stay put */
    NEAR(X[0], 1, 1e-15);
    NEAR(X[1], 0, 1e-15);
    NEAR(X[2], .55, 1e-12);
    /* example 34: P = N - (0, 0, rout), Q = N' + (0, 0, rin) with e = (0, 0, -2) (normalised) */
    double down[6] = {0, 0, -2, 0, 0, -2};
    double half[2] = {.5, .5};
    double church[6] = {.05, 0, 3.9, .05, 0, 3.8};
    pc_stroke_spec c = {.d = 3, .nnodes = 2, .nodes = church, .ein = down, .rin = half,
                        .rout = half};
    assert_int_equal(pc_stroke_build(&c, &pc, NULL), PC_OK);
    NEAR(pc.p[2], 3.4, 1e-15);
    NEAR(pc.q[2], 4.3, 1e-15);
}

static void test_errors(void **state) {
    (void)state;
    double two[4] = {0, 0, 0, 0};
    pc_piece pcs[2];
    int bad = 99;
    pc_stroke_spec s = {.d = 2, .nnodes = 2, .nodes = two};
    assert_int_equal(pc_stroke_build(&s, pcs, &bad), PC_EZERO);   /* coincident nodes */
    assert_int_equal(bad, 0);
    double ok[4] = {0, 0, 1, 0};
    s.nodes = ok;
    s.nnodes = 1;
    assert_int_equal(pc_stroke_build(&s, pcs, &bad), PC_EDIM);
    s.nnodes = 2;
    double t0[2] = {.5, 1.5};
    double t0bad[2] = {1.5, .5};
    s.t0 = t0;
    assert_int_equal(pc_stroke_build(&s, pcs, &bad), PC_OK);   /* the last t0 is unused */
    s.t0 = t0bad;
    assert_int_equal(pc_stroke_build(&s, pcs, &bad), PC_EDOMAIN);
    assert_int_equal(bad, 0);
    s.t0 = NULL;
    double zero[4] = {0, 0, 1, 0};
    s.ein = zero;
    assert_int_equal(pc_stroke_build(&s, pcs, &bad), PC_EZERO);
    assert_int_equal(bad, 0);
    double nan_row[4] = {NAN, 0, 1, 0};   /* NaN row: chord tangent */
    s.ein = nan_row;
    assert_int_equal(pc_stroke_build(&s, pcs, &bad), PC_OK);
    NEAR(pcs[0].p[0], 1.0 / 3, 1e-15);
    double inf[4] = {0, 0, INFINITY, 0};
    s.nodes = inf;
    s.ein = NULL;
    assert_int_equal(pc_stroke_build(&s, pcs, &bad), PC_ENONFINITE);
    assert_int_equal(bad, 1);
    s.nodes = ok;
    s.d = PC_CURVE_MAXDIM + 1;   /* beyond the dimensions points have */
    assert_int_equal(pc_stroke_build(&s, pcs, &bad), PC_EDIM);
}

/* example 5's quadrilateral: A, A + a, B - b, B with the smoothstep given */
static void test_spline2_piece(void **state) {
    (void)state;
    double A[2] = {1, 2}, a[2] = {3, 0}, B[2] = {5, 6}, b[2] = {0, 4}, X[2];
    pc_gfun g = {.kind = PC_G_SINE};
    pc_piece pc;
    pc_spline2_piece(2, A, a, B, b, &g, &pc);
    NEAR(pc.p[0], 4, 0); NEAR(pc.p[1], 2, 0);
    NEAR(pc.q[0], 5, 0); NEAR(pc.q[1], 2, 0);
    NEAR(pc.b[1], 6, 0);
    assert_int_equal(pc.g.kind, PC_G_SINE);
    pc_piece_eval(2, &pc, 1, X);
    NEAR(X[0], 5, 1e-15); NEAR(X[1], 6, 1e-15);
}

/* a smoothstep callback: g(t) = t^2 counting its calls; failing past t = 5 */
static int calls;
static int square_g(void *ud, double t, double *g) {
    (void)ud;
    calls++;
    *g = t * t;
    return t > 5 ? PC_EARG : PC_OK;
}
static int freed;
static void count_free(void *ud) {
    (void)ud;
    freed++;
}

/* the stroke of two pieces of the square's corners with the callback: X = M + g (N - M) of
 * each piece at its own t, the ends extrapolating; its pieces come back, those of a part not */
static void test_stroke_callback(void **state) {
    (void)state;
    double sq[8] = {0, 0, 3, 0, 3, 3, 0, 3};
    pc_stroke_spec s = {.d = 2, .nnodes = 3, .nodes = sq};
    pc_piece pcs[2];
    assert_int_equal(pc_stroke_build(&s, pcs, NULL), PC_OK);
    int st, np = -1;
    pc_curve *c = pc_curve_stroke_fn(2, 2, pcs, 0, square_g, count_free, NULL, &st);
    assert_non_null(c);
    assert_true(pc_curve_stroke_pieces(c, &np) != NULL);
    assert_int_equal(np, 2);
    NEAR(pc_curve_stroke_pieces(c, NULL)[1].b[1], 3, 0);
    double X[2], Y[2], h[3];
    pc_qspline(2, pcs[1].a, pcs[1].p, pcs[1].q, pcs[1].b, .25, .0625, Y);
    calls = 0;
    assert_int_equal(pc_curve_eval_h(c, 1.25, 0, h), PC_OK);   /* piece 2 at t = .25 */
    assert_int_equal(calls, 1);
    NEAR(h[0], Y[0], 1e-15);
    NEAR(h[1], Y[1], 1e-15);
    NEAR(h[2], 1, 0);
    assert_int_equal(pc_stroke_piece_at(c, 1, .25, X), PC_OK);
    NEAR(X[0], Y[0], 1e-15);
    NEAR(X[1], Y[1], 1e-15);
    assert_int_equal(pc_stroke_piece_at(c, 1, 6, X), PC_EARG);   /* the callback's status */
    assert_int_equal(pc_stroke_piece_at(c, 2, .5, X), PC_EARG);  /* no piece 3 */
    assert_null(pc_stroke_past(c, -1, &np, X));                   /* a callback extrapolates */
    pc_curve *l, *r;
    assert_int_equal(pc_curve_split(c, .5, &l, &r), PC_OK);
    assert_null(pc_curve_stroke_pieces(l, &np));
    assert_int_equal(np, 0);
    assert_int_equal(pc_stroke_piece_at(l, 0, .5, X), PC_EARG);
    pc_curve_release(l);
    pc_curve_release(r);
    freed = 0;
    pc_curve_release(c);
    assert_int_equal(freed, 1);   /* the callback's data goes with the last curve */
}

/* a half-spline of fractional degree n = 2.5 does not extrapolate before its piece: the stroke
 * says which piece and where, and evaluates inside */
static void test_stroke_past(void **state) {
    (void)state;
    double two[4] = {0, 0, 3, 0}, n[2] = {2.5, 2.5};
    pc_stroke_spec s = {.d = 2, .nnodes = 2, .nodes = two, .n = n};
    pc_piece pc;
    assert_int_equal(pc_stroke_build(&s, &pc, NULL), PC_OK);
    int st, i = -1;
    double t = 0, X[2], Y[2];
    pc_curve *c = pc_curve_stroke(2, 1, &pc, 0, &st);
    assert_true(pc_stroke_past(c, -.5, &i, &t) == pc_curve_stroke_pieces(c, NULL));
    assert_int_equal(i, 0);
    NEAR(t, -.5, 0);
    char why[200];
    assert_string_equal(pc_half_why(&pc, t, i, 1, why, sizeof why),
                        "must be at least 0 (piece 1's half-spline has the fractional degree n = 2.5 and does not "
                        "extrapolate)");
    assert_string_equal(pc_half_why(&pc, 3, 1, 2, why, sizeof why),
                        "must be at most 2 (piece 2's half-spline has the fractional degree m = 2 and does not "
                        "extrapolate)");
    assert_null(pc_stroke_past(c, .5, &i, &t));
    assert_int_equal(pc_stroke_piece_at(c, 0, -.5, X), PC_EDOMAIN);
    assert_int_equal(pc_stroke_piece_at(c, 0, .5, X), PC_OK);
    pc_piece_eval(2, &pc, .5, Y);
    NEAR(X[0], Y[0], 0);
    NEAR(X[1], 0, 0);                     /* a straight stroke stays on its line */
    assert_true(X[0] > 1 && X[0] < 2);    /* between P = (1, 0) and Q = (2, 0) */
    double cp[] = {0, 0, 1, 1, 1, 1};
    pc_curve *line = pc_curve_bezier(2, 2, cp, &st);
    assert_null(pc_stroke_past(line, -.5, &i, &t));
    assert_null(pc_curve_stroke_pieces(line, NULL));
    /* the same failures as the bindings raise them: a row for the call, naming the argument */
    pc_why_call w;
    double h[3];
    assert_int_equal(pc_stroke_value_checked("c", c, -.5, h, &w), PC_EDOMAIN);
    assert_string_equal(w.row[0].op, "c");
    assert_int_equal(w.row[0].status, PC_EDOMAIN);
    assert_int_equal(w.row[0].arg, 1);
    assert_string_equal(w.row[0].text, "must be at least 0 (piece 1's half-spline has the fractional degree n = 2.5 "
                                       "and does not extrapolate)");
    assert_null(w.row[1].op);
    assert_int_equal(pc_stroke_value_checked("c", c, .5, h, &w), PC_OK);
    assert_null(w.row[0].op);
    NEAR(h[0], Y[0], 1e-15);
    NEAR(h[2], 1, 0);
    assert_int_equal(pc_stroke_piece_checked("c:piece", c, 0, -.5, X, &w), PC_EDOMAIN);
    assert_string_equal(w.row[0].op, "c:piece");
    assert_int_equal(w.row[0].arg, 2);
    assert_string_equal(w.row[0].text, "must be at least 0 (piece 1's half-spline has the fractional degree n = 2.5 "
                                       "and does not extrapolate)");
    assert_int_equal(pc_stroke_piece_checked("c:piece", c, 0, .5, X, &w), PC_OK);
    assert_null(w.row[0].op);
    NEAR(X[0], Y[0], 0);
    assert_int_equal(pc_stroke_piece_checked("c:piece", line, 0, .5, X, &w), PC_EARG);   /* no stroke: no row */
    assert_null(w.row[0].op);
    assert_int_equal(pc_stroke_value_checked("c", line, 2, h, &w), PC_OK);   /* a Bezier curve extrapolates */
    assert_null(w.row[0].op);
    NEAR(h[0], 2, 1e-15);
    pc_curve_release(line);
    pc_curve_release(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_dirs),           cmocka_unit_test(test_example5),
        cmocka_unit_test(test_example10),      cmocka_unit_test(test_closed_defaults),
        cmocka_unit_test(test_3d),             cmocka_unit_test(test_errors),
        cmocka_unit_test(test_stroke_callback), cmocka_unit_test(test_stroke_past),
        cmocka_unit_test(test_spline2_piece),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
