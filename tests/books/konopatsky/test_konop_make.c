/* The constructions by kind (konop_make.h): each kind is its construction's own function, on
 * the same points and numbers; the numbers of the book's k for known arcs. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "konop_make.h"
#include "conic.h"
#include "oneratio.h"
#include "konop_schemes.h"
#include "konop_curves.h"
#include "approx.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

/* A, B, C, D as rows of 2 */
static const double PTS[8] = {0, 0, 4, 0, 1, 3, 4, 3};

/* the two curves agree at t = 0, 0.3, 0.7, 1 */
static void same(pc_curve *c, pc_curve *ref) {
    assert_non_null(c);
    assert_non_null(ref);
    for (int i = 0; i < 4; i++) {
        double t = (double[]){0, 0.3, 0.7, 1}[i], m[2], r[2];
        assert_int_equal(pc_curve_eval(c, t, m), PC_OK);
        assert_int_equal(pc_curve_eval(ref, t, r), PC_OK);
        NEAR(m[0], r[0], 1e-14);
        NEAR(m[1], r[1], 1e-14);
    }
    pc_curve_release(c);
    pc_curve_release(ref);
}

static void test_curves(void **state) {
    (void)state;
    int st;
    const double *a = PTS, *b = PTS + 2, *c = PTS + 4, *d = PTS + 6, k[1] = {0.3}, none[1] = {NAN};
    same(pc_konop_make(PC_KM_ED, 2, PTS, k, &st), pc_conic_ed(2, a, b, c, 0.3, &st));
    same(pc_konop_make(PC_KM_CEVA, 2, PTS, k, &st), pc_conic_ceva(2, a, b, c, 0.3, &st));
    same(pc_konop_make(PC_KM_PARABOLA, 2, PTS, none, &st), pc_conic_parabola(2, a, b, c, &st));
    same(pc_konop_make(PC_KM_PARABOLA, 2, PTS, k, &st), pc_conic_parabola3(2, a, b, c, 0.3, &st));
    same(pc_konop_make(PC_KM_ED3, 2, PTS, k, &st), pc_conic_ed3(2, a, b, c, 0.3, &st));
    same(pc_konop_make(PC_KM_TETRA, 2, PTS, NULL, &st), pc_oneratio_tetra(2, a, b, c, d, &st));
    same(pc_konop_make(PC_KM_BEZIER3, 2, PTS, NULL, &st), pc_oneratio_bezier3(2, a, b, c, d, &st));
    same(pc_konop_make(PC_KM_SMOOTH, 2, PTS, (double[]){3}, &st), pc_oneratio_smooth(2, a, b, c, 3, &st));
    same(pc_konop_make(PC_KM_DESARGUES, 2, PTS, NULL, &st), pc_oneratio_desargues(2, a, b, c, d, &st));
    same(pc_konop_make(PC_KM_CLOSED, 2, PTS, (double[]){0.8, 0.5, 2}, &st),
         pc_oneratio_closed(2, a, b, c, 0.8, 0.5, 2, &st));
    const double five[10] = {3.0, 0.2, 1.2, 0.9, 2.0, 1.8, 0.2, 1.3, 0.5, 2.7}, *f = five;
    same(pc_konop_make(PC_KM_TRIPLES, 2, five, (double[]){0.1, 0.9}, &st),
         pc_triples_conic(2, f, f + 2, f + 4, f + 6, f + 8, 0.1, 0.9, &st));
    /* the cubic of two cones over the tetrahedron (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1) */
    const double tet[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, *T = tet;
    pc_curve *q = pc_konop_make(PC_KM_CONES, 3, tet, (double[]){0.3, 0.8, 2}, &st);
    pc_curve *qref = pc_cubic_cones(3, T, T + 3, T + 6, T + 9, 0.3, 0.8, 2, &st);
    double mq[3], mr[3];
    assert_int_equal(pc_curve_eval(q, 0.25, mq), PC_OK);
    assert_int_equal(pc_curve_eval(qref, 0.25, mr), PC_OK);
    for (int i = 0; i < 3; i++) NEAR(mq[i], mr[i], 0);
    NEAR(mq[0], 0.005718, 1e-6);                                  /* test_conic's value */
    pc_curve_release(q);
    pc_curve_release(qref);
    assert_int_equal(pc_konop_npoints(PC_KM_TRIPLES), 5);
    assert_int_equal(pc_konop_kind_of("conic.cones"), PC_KM_CONES);
    /* the statuses of the constructions' own checks */
    assert_null(pc_konop_make(PC_KM_ED, 2, PTS, (double[]){0}, &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_null(pc_konop_make(PC_KM_ED_K, 2, PTS, k, &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_int_equal(pc_konop_npoints(PC_KM_ED), 3);
    assert_int_equal(pc_konop_npoints(PC_KM_DESARGUES), 4);
    assert_int_equal(pc_konop_npoints(PC_KM_CEVA_K), 4);
}

static void test_numbers(void **state) {
    (void)state;
    /* K on the median from C = (1, 3) to T1 = (2, 0) at k = 1/4 of the way */
    double p[8] = {0, 0, 4, 0, 1, 3, 1.25, 2.25}, k;
    assert_int_equal(pc_konop_number(PC_KM_ED_K, 2, p, NULL, &k), PC_OK);
    NEAR(k, 0.25, 1e-14);
    /* tangents from C = (2, 2) to the circle through A = (0, 0), B = (4, 0): the quarter arc,
     * k = 1/(1 + cos 45 deg) */
    double q[6] = {0, 0, 4, 0, 2, 2};
    assert_int_equal(pc_konop_number(PC_KM_CIRCLE_K, 2, q, NULL, &k), PC_OK);
    NEAR(k, 1 / (1 + sqrt(0.5)), 1e-12);
    double ref = 0;
    k = 0;
    assert_int_equal(pc_konop_number(PC_KM_CEVA_K, 2, p, NULL, &k), pc_conic_ceva_k(2, p, p + 2, p + 4, p + 6, &ref));
    NEAR(k, ref, 0);
    p[6] = 3;   /* off the median */
    assert_int_equal(pc_konop_number(PC_KM_ED_K, 2, p, NULL, &k), PC_ENOTCOLLINEAR);
    assert_int_equal(pc_konop_number(PC_KM_ED, 2, p, NULL, &k), PC_EDOMAIN);
    /* the two readings of one arc: Ceva's 1/4 is the engineering discriminant's 1/2 */
    assert_int_equal(pc_konop_number(PC_KM_CEVA_TO_ED, 0, NULL, (double[]){0.25}, &k), PC_OK);
    NEAR(k, 0.5, 1e-15);
    assert_int_equal(pc_konop_number(PC_KM_ED_TO_CEVA, 0, NULL, (double[]){0.5}, &k), PC_OK);
    NEAR(k, 0.25, 1e-15);
    assert_int_equal(pc_konop_number(PC_KM_ED_TO_CEVA, 0, NULL, (double[]){1}, &k), PC_EDOMAIN);
    assert_int_equal(pc_konop_npoints(PC_KM_CEVA_TO_ED), 0);
    /* (1.2) with l1 = l2 = l3 = 1 (the midpoints): k = 2/8 */
    assert_int_equal(pc_konop_number(PC_KM_AREA_K, 0, NULL, (double[]){1, 1, 1}, &k), PC_OK);
    NEAR(k, 0.25, 1e-15);
    assert_int_equal(pc_konop_number(PC_KM_AREA_K, 0, NULL, (double[]){-1, 1, 1}, &k), PC_EPOLE);
    assert_int_equal(pc_konop_npoints(PC_KM_AREA_K), 0);
    /* the lists: fP = fQ = 1/4 avoids (1 +- sqrt 2)/2 of (2.151); 3 Chebyshev nodes on [-1, 1] */
    double u[64], uref[64];
    int n, nref;
    assert_int_equal(pc_konop_list(PC_KM_CONES_EXCLUDED, (double[]){0.25, 0.25}, u, &n), PC_OK);
    assert_int_equal(pc_cones_excluded(0.25, 0.25, uref, &nref), PC_OK);
    assert_int_equal(n, nref);
    for (int i = 0; i < n; i++) NEAR(u[i], uref[i], 0);
    NEAR(u[0], (1 - sqrt(2)) / 2, 1e-15);
    assert_int_equal(pc_konop_list(PC_KM_CHEBYSHEV, (double[]){3, -1, 1}, u, &n), PC_OK);
    assert_int_equal(n, 3);
    NEAR(u[0], -sqrt(3) / 2, 1e-15);
    NEAR(u[1], 0, 1e-15);
    NEAR(u[2], sqrt(3) / 2, 1e-15);
    assert_int_equal(pc_konop_list(PC_KM_CHEBYSHEV, (double[]){3, 1, 1}, u, &n), PC_EDOMAIN);
    assert_int_equal(pc_konop_list(PC_KM_AREA_K, (double[]){1, 1, 1}, u, &n), PC_EDOMAIN);
    assert_int_equal(pc_konop_kind_of("approx.chebyshev"), PC_KM_CHEBYSHEV);
}

/* the schemes by kind: their own functions' points, packed in order */
static void test_schemes(void **state) {
    (void)state;
    const double *a = PTS, *b = PTS + 2, *c = PTS + 4, *d = PTS + 6;
    double out[8 * 3], ref[8 * 3], x[2] = {0.3, 0.25};
    assert_int_equal(pc_konop_scheme(PC_KS_ED, 2, PTS, x, out), PC_OK);
    assert_int_equal(pc_conic_ed_scheme(2, a, b, c, 0.3, 0.25, ref), PC_OK);
    for (int i = 0; i < 7 * 3; i++) NEAR(out[i], ref[i], 0);
    assert_int_equal(pc_konop_scheme(PC_KS_ED, 2, PTS, (double[]){0, 0.25}, out), PC_EARG);
    double t3, r;
    assert_int_equal(pc_konop_scheme(PC_KS_CEVA, 2, PTS, x, out), PC_OK);
    assert_int_equal(pc_conic_ceva_scheme(2, a, b, c, 0.3, 0.25, ref, &t3, &r), PC_OK);
    for (int i = 0; i < 4; i++) NEAR(out[i], ref[i], 0);
    NEAR(out[4], t3, 0);
    NEAR(out[5], r, 0);
    assert_int_equal(pc_konop_scheme(PC_KS_SIMPLEX, 2, PTS, x, out), PC_OK);
    NEAR(out[0], 0.7 * a[0] + 0.3 * c[0], 1e-15);           /* N = A t' + C t */
    NEAR(out[1], 0.7 * a[1] + 0.3 * c[1], 1e-15);
    NEAR(out[2], 0.7 * out[0] + 0.3 * b[0], 1e-15);          /* M = N t' + B t */
    double pq[2];
    assert_int_equal(pc_konop_scheme(PC_KS_DESARGUES, 2, PTS, (double[]){0.5}, out), PC_OK);
    assert_int_equal(pc_desargues_scheme(2, a, b, c, d, 0.5, ref, pq), PC_OK);
    for (int i = 0; i < 7 * 3; i++) NEAR(out[i], ref[i], 0);
    NEAR(out[21], pq[0], 0);
    NEAR(out[22], pq[1], 0);
    NEAR(out[2], 0, 0);                                      /* T at infinity at t = 1/2 */
    /* the ellipse of centre (0, 0), semi-axes 5 and 3: foci (+-4, 0), e = 4/5, p = 9/5 */
    double cab[6] = {0, 0, 5, 0, 0, 3};
    assert_int_equal(pc_konop_scheme(PC_KS_FOCI, 2, cab, (double[]){0}, out), PC_OK);
    NEAR(fabs(out[0]), 4, 1e-14);
    NEAR(out[0] + out[2], 0, 1e-14);
    NEAR(out[4], 0.8, 1e-15);
    NEAR(out[5], 1.8, 1e-14);
    assert_int_equal(pc_konop_scheme(PC_KS_FOCI, 2, cab, (double[]){1}, out), PC_OK);   /* hyperbola */
    NEAR(fabs(out[0]), sqrt(34), 1e-14);
    double pab[2];
    assert_int_equal(pc_konop_scheme(PC_KS_FOCAL, 2, cab, (double[]){0.7, 0}, out), PC_OK);
    assert_int_equal(pc_conic_focal_point(2, cab, cab + 2, cab + 4, 0, 0.7, ref, pab), PC_OK);
    for (int i = 0; i < 4; i++) NEAR(out[i], ref[i], 0);      /* M, F */
    NEAR(out[4], pab[0], 0);
    NEAR(out[5], pab[1], 0);
    NEAR(out[2], -4, 1e-14);                                 /* F = F2 = C - (A - C)e */
    assert_int_equal(pc_konop_scheme_npoints(PC_KS_FIVE), 5);
    assert_int_equal(pc_konop_scheme_npoints(PC_KS_DESARGUES), 4);
    assert_int_equal(pc_konop_scheme_npoints(PC_KS_CEVA), 3);
    double five[10] = {0, 0, 4, 0, 1, 3, 4, 3, 2, 4}, o5[8 * 3], r5[8 * 3];
    assert_int_equal(pc_konop_scheme(PC_KS_FIVE, 2, five, x, o5), PC_OK);
    assert_int_equal(pc_conic_five_scheme(2, five, five + 2, five + 4, five + 6, five + 8, 0.3, r5), PC_OK);
    for (int i = 0; i < 8 * 3; i++) NEAR(o5[i], r5[i], 0);
    /* C = (0, 0), A = (5, 0), B = (0, 3): rho 2 at phi = pi/2 is (0, 2); the rotation of A by
     * pi/2 towards B is (0, 5) */
    assert_int_equal(pc_konop_scheme(PC_KS_POLAR, 2, cab, (double[]){2, M_PI / 2}, out), PC_OK);
    NEAR(out[0], 0, 1e-15);
    NEAR(out[1], 2, 1e-15);
    assert_int_equal(pc_konop_scheme(PC_KS_ROTATE, 2, cab, (double[]){M_PI / 2}, out), PC_OK);
    NEAR(out[0], 0, 1e-15);
    NEAR(out[1], 5, 1e-15);
    double flat3[6] = {0, 0, 1, 0, 2, 0};
    assert_int_equal(pc_konop_scheme(PC_KS_ROTATE, 2, flat3, (double[]){1}, out), PC_ECOLLINEAR);
    assert_int_equal(pc_konop_scheme_npoints(PC_KS_POLAR), 3);
}

/* the kinds by the names the API gives them */
static void test_names(void **state) {
    (void)state;
    assert_int_equal(pc_konop_kind_of("conic.ed"), PC_KM_ED);
    assert_int_equal(pc_konop_kind_of("conic.ceva_k"), PC_KM_CEVA_K);
    assert_int_equal(pc_konop_kind_of("interp.conic"), PC_KM_ED3);
    assert_int_equal(pc_konop_kind_of("oneratio.desargues"), PC_KM_DESARGUES);
    assert_int_equal(pc_konop_kind_of("conic.ellipse"), -1);
    const char *fields = NULL;
    assert_int_equal(pc_konop_scheme_of("conic.ceva_scheme", &fields), PC_KS_CEVA);
    assert_string_equal(fields, "M3=p M=p t3=n r=n");
    assert_int_equal(pc_konop_scheme_of("conic.foci", &fields), PC_KS_FOCI);
    assert_string_equal(fields, "p p n n");
    assert_int_equal(pc_konop_scheme_of("oneratio.desargues_scheme", &fields), PC_KS_DESARGUES);
    assert_int_equal(pc_konop_scheme_of("conic.ed", &fields), -1);
    assert_int_equal(pc_konop_kind_of("konopatsky.area_k"), PC_KM_AREA_K);
    assert_int_equal(pc_konop_scheme_of("konopatsky.rotate", &fields), PC_KS_ROTATE);
    assert_string_equal(fields, "p");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_names),
        cmocka_unit_test(test_curves),
        cmocka_unit_test(test_numbers),
        cmocka_unit_test(test_schemes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
