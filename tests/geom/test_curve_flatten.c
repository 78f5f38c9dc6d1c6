/* Flattening beyond the tolerance checks of test_flatten.c: a hyperbola written as a rational
 * quadratic with a negative middle weight comes out as its two branches (three pieces, the
 * branch through the end points broken at infinity twice) with no segment across the picture;
 * a projection without an image somewhere breaks the polyline there; callback errors pass
 * through; polylines start new pieces and do not repeat vertices; every error status. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "curve.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

/* x^2 - y^2 = R^2: end points at parameter -1 and 1 of (R cosh s, R sinh s), the tangents
 * meeting at (R / cosh 1, 0); weight cosh 1 gives the arc between them, -cosh 1 the rest */
#define R 100.0
static pc_curve *hyperbola(double sign) {
    double c = cosh(1.0), s = sinh(1.0), w = sign * c;
    double cp[9] = {R * c, -R * s, 1, w * R / c, 0, w, R * c, R * s, 1};
    int st;
    pc_curve *h = pc_curve_bezier(2, 3, cp, &st);
    assert_non_null(h);
    return h;
}

static int pieces_of(const pc_polyline *pl) {
    int n = 0;
    for (size_t k = 0; k < pl->n; k++) n += k == 0 || pl->move[k];
    return n;
}

static void check_hyperbola(const pc_polyline *pl) {
    assert_true(pl->n > 10);
    assert_int_equal(pl->move[0], 1);
    assert_int_equal(pieces_of(pl), 3);
    int piece = 0;
    double far[3] = {0, 0, 0};
    for (size_t k = 0; k < pl->n; k++) {
        double x = pl->xy[2 * k], y = pl->xy[2 * k + 1];
        if (pl->move[k]) piece++;
        /* on the hyperbola (relative 1e-9), the middle piece on the other branch */
        NEAR(x * x - y * y, R * R, 1e-9 * (x * x + y * y));
        assert_true(piece == 2 ? x < 0 : x > 0);
        far[piece - 1] = fmax(far[piece - 1], fabs(x));
        if (k > 0 && !pl->move[k])       /* no segment joins the branches */
            assert_true((x > 0) == (pl->xy[2 * k - 2] > 0));
    }
    for (int i = 0; i < 3; i++) assert_true(far[i] > 1e4 * R);   /* each piece runs far out */
}

static int scale_proj(void *ud, const double *h, double xy[2]) {
    double k = *(const double *)ud;
    if (h[2] == 0) return PC_IMPROPER;
    xy[0] = k * h[0] / h[2];
    xy[1] = k * h[1] / h[2];
    return PC_OK;
}

static void test_hyperbola(void **state) {
    (void)state;
    pc_curve *h = hyperbola(-1);
    double wt[3];   /* the weight vanishes twice inside: 1 - 2 (1 + cosh 1) t (1 - t) */
    assert_int_equal(pc_curve_eval_h(h, 0.5, 0, wt), PC_OK);
    assert_true(wt[2] < 0);
    pc_polyline pl = {0};
    assert_int_equal(pc_curve_flatten(h, 0, 1, NULL, NULL, 0.25, &pl), PC_OK);
    check_hyperbola(&pl);
    pc_polyline_free(&pl);
    assert_int_equal(pc_curve_flatten_map(h, 0, 1, NULL, 0.25, &pl), PC_OK);
    check_hyperbola(&pl);
    pc_polyline_free(&pl);
    double one = 1;
    assert_int_equal(pc_curve_flatten(h, 0, 1, scale_proj, &one, 0.25, &pl), PC_OK);
    check_hyperbola(&pl);
    pc_polyline_free(&pl);
    pc_curve_release(h);
    /* the positive weight: one piece, the arc between the end points */
    h = hyperbola(1);
    assert_int_equal(pc_curve_flatten(h, 0, 1, NULL, NULL, 0.25, &pl), PC_OK);
    assert_int_equal(pieces_of(&pl), 1);
    NEAR(pl.xy[0], R * cosh(1.0), 1e-12 * R);
    NEAR(pl.xy[2 * pl.n - 1], R * sinh(1.0), 1e-12 * R);
    pc_polyline_free(&pl);
    pc_curve_release(h);
}

/* a projection refusing y > 0.5: the circle's polyline breaks at the two crossings (located
 * to 1e-6) and has no vertex above */
static int cut_proj(void *ud, const double *h, double xy[2]) {
    (void)ud;
    xy[0] = h[0] / h[2];
    xy[1] = h[1] / h[2];
    return xy[1] > 0.5 ? PC_IMPROPER : PC_OK;
}

static int error_proj(void *ud, const double *h, double xy[2]) {
    (void)ud;
    xy[0] = h[0];
    xy[1] = h[1];
    return h[0] / h[2] < -0.5 ? PC_EARG : PC_OK;
}

static pc_curve *circle(void) {     /* unit circle, 9-point NURBS, starting at (1, 0) */
    double hw = sqrt(0.5), cp[27];
    const double ux[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, uy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    for (int i = 0; i < 9; i++) {
        double w = i % 2 ? hw : 1;
        cp[3 * i] = w * ux[i];
        cp[3 * i + 1] = w * uy[i];
        cp[3 * i + 2] = w;
    }
    const double kn[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    int st;
    pc_curve *c = pc_curve_bspline(2, 2, 9, cp, PC_KNOTS_GIVEN, kn, &st);
    assert_non_null(c);
    return c;
}

static void test_projection_fails(void **state) {
    (void)state;
    pc_curve *c = circle();
    pc_polyline pl = {0};
    assert_int_equal(pc_curve_flatten(c, 0, 4, cut_proj, NULL, 1e-3, &pl), PC_OK);
    assert_int_equal(pieces_of(&pl), 2);
    double top = -1;
    for (size_t k = 0; k < pl.n; k++) {
        assert_true(pl.xy[2 * k + 1] <= 0.5);
        NEAR(hypot(pl.xy[2 * k], pl.xy[2 * k + 1]), 1, 1e-12);
        top = fmax(top, pl.xy[2 * k + 1]);
    }
    NEAR(top, 0.5, 1e-6);
    /* the first piece ends and the second starts next to y = 0.5 */
    size_t brk = 1;
    while (!pl.move[brk]) brk++;
    NEAR(pl.xy[2 * brk - 1], 0.5, 1e-6);
    NEAR(pl.xy[2 * brk + 1], 0.5, 1e-6);
    pc_polyline_free(&pl);
    /* another status from the callback is returned as it is */
    assert_int_equal(pc_curve_flatten(c, 0, 4, error_proj, NULL, 0.01, &pl), PC_EARG);
    pc_polyline_free(&pl);
    pc_curve_release(c);
}

/* vertices: a new piece per call, no vertex repeated, a circle of radius 200 at 0.25 in at
 * most four times the fewest chords that can do it */
static void test_vertices(void **state) {
    (void)state;
    pc_curve *c = circle();
    pc_map f;
    pc_map_identity(&f, 2);
    PC_MAP_AT(&f, 0, 0) = PC_MAP_AT(&f, 1, 1) = 200;
    int st;
    pc_curve *big = pc_curve_map(c, &f, &st);
    pc_polyline pl = {0};
    assert_int_equal(pc_curve_flatten(big, 0, 4, NULL, NULL, 0.25, &pl), PC_OK);
    double fewest = 2 * M_PI / (2 * acos(1 - 0.25 / 200));
    assert_true(pl.n <= 4 * fewest + 1);
    assert_true(pl.n >= fewest);
    assert_int_equal(pl.move[0], 1);
    for (size_t k = 1; k < pl.n; k++) {
        assert_int_equal(pl.move[k], 0);
        assert_true(pl.xy[2 * k] != pl.xy[2 * k - 2] || pl.xy[2 * k + 1] != pl.xy[2 * k - 1]);
    }
    NEAR(pl.xy[0], 200, 1e-12);                  /* closed: ends where it starts */
    NEAR(pl.xy[2 * pl.n - 2], 200, 1e-12);
    size_t n1 = pl.n;
    assert_int_equal(pc_curve_flatten(big, 0, 1, NULL, NULL, 0.25, &pl), PC_OK);
    assert_int_equal(pl.move[n1], 1);            /* a second call starts a new piece */
    assert_int_equal(pc_curve_flatten(big, 2, 2, NULL, NULL, 0.25, &pl), PC_OK);   /* one point */
    assert_int_equal(pl.move[pl.n - 1], 1);
    NEAR(pl.xy[2 * pl.n - 2], -200, 1e-12);
    pc_polyline_free(&pl);
    assert_null(pl.xy);
    assert_int_equal(pl.n, 0);
    pc_polyline_free(&pl);                        /* twice is fine */
    pc_curve_release(big);
    pc_curve_release(c);
}

static void test_errors(void **state) {
    (void)state;
    pc_curve *c = circle();
    pc_polyline pl = {0};
    assert_int_equal(pc_curve_flatten(c, 0, 4, NULL, NULL, 0, &pl), PC_EDOMAIN);
    assert_int_equal(pc_curve_flatten(c, 0, 4, NULL, NULL, -1, &pl), PC_EDOMAIN);
    assert_int_equal(pc_curve_flatten(c, 0, 4, NULL, NULL, NAN, &pl), PC_ENONFINITE);
    assert_int_equal(pc_curve_flatten(c, 0, INFINITY, NULL, NULL, 0.1, &pl), PC_ENONFINITE);
    assert_int_equal(pc_curve_flatten(c, 3, 1, NULL, NULL, 0.1, &pl), PC_EDOMAIN);
    assert_int_equal(pc_curve_flatten(c, 0, 4, NULL, NULL, 0.1, NULL), PC_EARG);
    assert_int_equal(pc_curve_flatten(NULL, 0, 4, NULL, NULL, 0.1, &pl), PC_EARG);
    assert_int_equal(pl.n, 0);
    double cp3[8] = {0, 0, 0, 1, 1, 1, 1, 1};
    int st;
    pc_curve *c3 = pc_curve_bezier(3, 2, cp3, &st);
    assert_int_equal(pc_curve_flatten(c3, 0, 1, NULL, NULL, 0.1, &pl), PC_EDIM);
    pc_curve_release(c3);
    assert_int_equal(pc_polyline_push(NULL, 0, 0, 1), PC_EARG);
    pc_curve_release(c);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hyperbola), cmocka_unit_test(test_projection_fails),
        cmocka_unit_test(test_vertices), cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
