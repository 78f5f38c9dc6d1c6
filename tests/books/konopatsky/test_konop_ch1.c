/* Konopatsky's chapter 1 (konop_ch1.h), digest konopatsky_ch1_2.md §4 and §5.0: the theorem on
 * triangle areas (1.2) against measured signed areas, its corollaries 1-3, the O-theorem (1.4)
 * with the closing factor for m = 3..7, the S- and V-theorems, the line-plane meet in 3-D
 * against the V-theorem's volumes and in 5-D, the rotation (2.138) and polar (2.118) test
 * vectors, and the moving-simplex surface of Fig. 1.2. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "konop_ch1.h"
#include "point.h"
#include <string.h>

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static void lerp2(const double *a, const double *b, double t, double *o) {
    o[0] = a[0] + (b[0] - a[0]) * t;
    o[1] = a[1] + (b[1] - a[1]) * t;
}

static void test_area_theorem(void **state) {
    (void)state;
    double A[6] = {0.5, -1, 4, 1.5, -1, 3}, B[6];
    const double cases[3][3] = {{0.25, 1.5, -0.5}, {2, -0.7, 0.4}, {-1.5, 3, 1.2}};
    for (int c = 0; c < 3; c++) {
        for (int i = 0; i < 3; i++) lerp2(A + 2 * i, A + 2 * ((i + 1) % 3), cases[c][i], B + 2 * i);
        pc_k_areas o;
        assert_int_equal(pc_k_area_theorem(2, A, B, &o), PC_OK);
        double measured = pc_area2(B, B + 2, B + 4) / pc_area2(A, A + 2, A + 4), k;
        NEAR(o.k, measured, 1e-12);                          /* (1.2), signed */
        assert_int_equal(pc_k_area_k(o.lambda[0], o.lambda[1], o.lambda[2], &k), PC_OK);
        NEAR(k, measured, 1e-12);
        for (int i = 0; i < 3; i++) {
            /* B on A1A2 at t: lambda = (A1A2B) = t/(1 - t), a = -1/(1 + lambda) = t - 1 */
            double t = cases[c][i];
            NEAR(o.lambda[i], t / (1 - t), 1e-12);
            NEAR(o.abc[i], t - 1, 1e-12);
        }
        assert_false(o.collinear);
    }
    /* corollary 1 (1.3), Menelaus: a transversal's points give k = 0, l1 l2 l3 = -1 */
    const double L1[2] = {-3, 0.2}, L2[2] = {5, 2.6};
    for (int i = 0; i < 3; i++) {
        double k[3];
        assert_int_equal(pc_meet(2, A + 2 * i, A + 2 * ((i + 1) % 3), L1, L2, k, NULL, NULL, NULL), PC_OK);
        B[2 * i] = k[0], B[2 * i + 1] = k[1];
    }
    pc_k_areas o;
    assert_int_equal(pc_k_area_theorem(2, A, B, &o), PC_OK);
    assert_true(o.collinear);
    NEAR(o.lambda[0] * o.lambda[1] * o.lambda[2], -1, 1e-12);
    /* corollary 2: B3 = A3 gives k = ab; corollary 3: B1 = A1, B3 = A3 gives -b */
    lerp2(A, A + 2, 0.3, B);
    lerp2(A + 2, A + 4, 0.8, B + 2);
    B[4] = A[4], B[5] = A[5];
    assert_int_equal(pc_k_area_theorem(2, A, B, &o), PC_OK);
    NEAR(o.k, o.abc[0] * o.abc[1], 1e-12);
    NEAR(o.k, pc_area2(B, B + 2, B + 4) / pc_area2(A, A + 2, A + 4), 1e-12);
    B[0] = A[0], B[1] = A[1];
    assert_int_equal(pc_k_area_theorem(2, A, B, &o), PC_OK);
    NEAR(o.k, -o.abc[1], 1e-12);
    NEAR(o.k, pc_area2(B, B + 2, B + 4) / pc_area2(A, A + 2, A + 4), 1e-12);
    /* B1 = A2: lambda1 infinite, k still finite */
    B[0] = A[2], B[1] = A[3];
    assert_int_equal(pc_k_area_theorem(2, A, B, &o), PC_OK);
    assert_true(isinf(o.lambda[0]));
    NEAR(o.k, pc_area2(B, B + 2, B + 4) / pc_area2(A, A + 2, A + 4), 1e-12);
    /* the same in 3-D, the triangle tilted: the ratio is affine */
    double A3[9] = {0.5, -1, 0.2, 4, 1.5, 1, -1, 3, -2}, B3[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) B3[3 * i + j] = A3[3 * i + j] + (A3[3 * ((i + 1) % 3) + j] - A3[3 * i + j]) * cases[0][i];
    assert_int_equal(pc_k_area_theorem(3, A3, B3, &o), PC_OK);
    double k;
    pc_k_area_k(0.25 / 0.75, 1.5 / -0.5, -0.5 / 1.5, &k);
    NEAR(o.k, k, 1e-12);
    /* errors */
    B3[1] += 0.1;
    assert_int_equal(pc_k_area_theorem(3, A3, B3, &o), PC_ENOTCOLLINEAR);
    const double flat[6] = {0, 0, 1, 1, 2, 2};
    assert_int_equal(pc_k_area_theorem(2, flat, B, &o), PC_ECOLLINEAR);
    assert_int_equal(pc_k_area_k(-1, 2, 3, &k), PC_EPOLE);
}

static void test_o_theorem(void **state) {
    (void)state;
    const double d1[2] = {-6, -1.3}, d2[2] = {6, 0.9};
    for (int m = 3; m <= 7; m++) {
        double poly[14], ratios[7], b[21], prod;
        for (int i = 0; i < m; i++) {
            double ang = 2 * M_PI * i / m;
            poly[2 * i] = 3 * cos(ang) + 0.4 * sin(3 * (i + 1));
            poly[2 * i + 1] = 2 * sin(ang) + 0.3 * cos(i + 1);
        }
        assert_int_equal(pc_k_o_theorem(2, m, poly, d1, d2, ratios, b, &prod), PC_OK);
        NEAR(prod, m % 2 ? -1 : 1, 1e-10);                   /* (-1)^m with the closing factor */
        double printed = 1;
        for (int i = 0; i < m - 1; i++) printed *= ratios[i];
        assert_true(fabs(printed - (m % 2 ? -1 : 1)) > 1e-6);   /* the print's m - 1 factors */
        for (int i = 0; i < m; i++) {                        /* each Bi on d */
            double cr = (d2[0] - d1[0]) * (b[3 * i + 1] - d1[1]) - (d2[1] - d1[1]) * (b[3 * i] - d1[0]);
            NEAR(cr, 0, 1e-9);
        }
    }
    /* a side parallel to d: B at infinity, ratio -1, still (-1)^m */
    const double sq[8] = {0, 0, 2, 0, 2, 2, 0, 2}, e1[2] = {-1, 1}, e2[2] = {3, 1.5};
    double r[4], prod;
    assert_int_equal(pc_k_o_theorem(2, 4, sq, e1, e2, r, NULL, &prod), PC_OK);
    NEAR(prod, 1, 1e-12);
    const double h1[2] = {-1, 1}, h2[2] = {3, 1};
    assert_int_equal(pc_k_o_theorem(2, 4, sq, h1, h2, r, NULL, &prod), PC_OK);
    NEAR(r[0], -1, 0);
    NEAR(prod, 1, 1e-12);
    const double v1[2] = {0, 0}, v2[2] = {3, 1};    /* through a vertex */
    assert_int_equal(pc_k_o_theorem(2, 4, sq, v1, v2, r, NULL, &prod), PC_EDOMAIN);
}

static void test_simplex_ratio(void **state) {
    (void)state;
    /* S-theorem on the triangle A(0,0), B(4,0), C(0,3): A1 = A p + B q + C r ... */
    const double rows[9] = {0.2, 0.3, 0.5, 0.6, 0.1, 0.3, 0.1, 0.7, 0.2};
    double r;
    assert_int_equal(pc_k_simplex_ratio(2, rows, &r), PC_OK);
    double P[6];
    const double A[2] = {0, 0}, B[2] = {4, 0}, C[2] = {0, 3};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 2; j++) P[2 * i + j] = A[j] * rows[3 * i] + B[j] * rows[3 * i + 1] + C[j] * rows[3 * i + 2];
    NEAR(r, pc_area2(P, P + 2, P + 4) / pc_area2(A, B, C), 1e-12);
    /* V-theorem: the corrected ratio is the determinant, not det/det = 1 */
    const double T[12] = {0, 0, 0, 2, 0, 0, 0, 3, 0, 0, 0, 1};
    const double v[16] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.1, 0.2, 0.2, 0.25, 0.25, 0.25, 0.25, 0, 0.1, 0.1, 0.8};
    assert_int_equal(pc_k_simplex_ratio(3, v, &r), PC_OK);
    double Q[12];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 3; j++) {
            Q[3 * i + j] = 0;
            for (int k = 0; k < 4; k++) Q[3 * i + j] += T[3 * k + j] * v[4 * i + k];
        }
    NEAR(r, pc_volume3(Q, Q + 3, Q + 6, Q + 9) / pc_volume3(T, T + 3, T + 6, T + 9), 1e-12);
    assert_true(fabs(r - 1) > 0.1);
    const double bad[9] = {0.2, 0.3, 0.4, 0.6, 0.1, 0.3, 0.1, 0.7, 0.2};
    assert_int_equal(pc_k_simplex_ratio(2, bad, &r), PC_EDOMAIN);
    /* konopatsky.simplex_ratio's entry: a square matrix, the failures as rows */
    pc_why_call why;
    double ident[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    assert_int_equal(pc_k_simplex_ratio_rows(3, 3, ident, &r, &why), PC_OK);
    assert_true(fabs(r - 1) <= 1e-15);
    assert_null(why.row[0].op);
    assert_int_equal(pc_k_simplex_ratio_rows(2, 3, ident, &r, &why), PC_EDIM);
    assert_int_equal(why.row[0].arg, 1);
    assert_string_equal(why.row[0].text, "must hold 2 to 9 rows of as many numbers (a square matrix), got 2 rows of 3");
    double off[4] = {1, 1, 0, 1};
    assert_int_equal(pc_k_simplex_ratio_rows(2, 2, off, &r, &why), PC_EDOMAIN);
    assert_string_equal(why.row[0].text, "each row's parameters must sum to 1 (the membership condition)");
}

static void test_meet_line_plane(void **state) {
    (void)state;
    /* 3-D: the line (0,0,-1) -> (1,1,1) and the plane z = 0 */
    const double a1[3] = {0, 0, -1}, a2[3] = {1, 1, 1}, p1[3] = {1, 0, 0}, p2[3] = {0, 1, 0}, p3[3] = {0, 0, 0};
    double k[4], lam, pq[2];
    assert_int_equal(pc_k_meet_line_plane(3, a1, a2, p1, p2, p3, k, &lam, pq), PC_OK);
    NEAR(k[0], 0.5, 1e-15); NEAR(k[1], 0.5, 1e-15); NEAR(k[2], 0, 1e-15); NEAR(k[3], 1, 0);
    NEAR(lam, 0.5, 1e-15);
    NEAR(pq[0], 0.5, 1e-15); NEAR(pq[1], 0.5, 1e-15);
    /* a general case against the V-theorem: V(M P1 P2 P3) = 0 with M linear in lambda gives
     * lambda = V1/(V1 - V2), V_i the volumes of A_i P1 P2 P3 */
    const double b1[3] = {0.3, -1.2, 2.5}, b2[3] = {1.7, 2.2, -0.4};
    const double q1[3] = {2, 0.5, 0.3}, q2[3] = {-0.5, 1.5, 1.1}, q3[3] = {0.2, -0.8, -0.6};
    assert_int_equal(pc_k_meet_line_plane(3, b1, b2, q1, q2, q3, k, &lam, pq), PC_OK);
    double V1 = pc_volume3(b1, q1, q2, q3), V2 = pc_volume3(b2, q1, q2, q3);
    NEAR(lam, V1 / (V1 - V2), 1e-12);
    NEAR(pc_volume3(k, q1, q2, q3), 0, 1e-12);
    for (int i = 0; i < 3; i++) NEAR(k[i], (q1[i] - q3[i]) * pq[0] + (q2[i] - q3[i]) * pq[1] + q3[i], 1e-12);
    /* the same configuration in 5-D, shifted and sheared into the other axes */
    double B1[5], B2[5], Q1[5], Q2[5], Q3[5], K5[6];
    const double *src[5] = {b1, b2, q1, q2, q3};
    double *dst[5] = {B1, B2, Q1, Q2, Q3};
    for (int i = 0; i < 5; i++) {
        const double *s = src[i];
        double x[5] = {s[0] + 0.5 * s[2], s[1] - s[0], s[2] + 1, 0.3 * s[1] + 2, -s[2] + 0.1 * s[0]};
        for (int j = 0; j < 5; j++) dst[i][j] = x[j];
    }
    double lam5;
    assert_int_equal(pc_k_meet_line_plane(5, B1, B2, Q1, Q2, Q3, K5, &lam5, NULL), PC_OK);
    NEAR(lam5, lam, 1e-12);
    /* parallel, in the plane, skew (4-D), coincident ends */
    const double c1[3] = {0, 0, 1}, c2[3] = {1, 2, 1};
    assert_int_equal(pc_k_meet_line_plane(3, c1, c2, p1, p2, p3, k, &lam, NULL), PC_IMPROPER);
    NEAR(k[0], 1, 0); NEAR(k[1], 2, 0); NEAR(k[3], 0, 0);
    assert_true(isinf(lam));
    const double i1[3] = {0, 0, 0}, i2[3] = {1, 2, 0};
    assert_int_equal(pc_k_meet_line_plane(3, i1, i2, p1, p2, p3, k, &lam, NULL), PC_ESAME_LINE);
    const double s1[4] = {0.2, 0.2, -1, 1}, s2[4] = {0.2, 0.2, 1, 1};
    const double r1[4] = {1, 0, 0, 0}, r2[4] = {0, 1, 0, 0}, r3[4] = {0, 0, 0, 0};
    assert_int_equal(pc_k_meet_line_plane(4, s1, s2, r1, r2, r3, k, &lam, NULL), PC_ESKEW);
    assert_int_equal(pc_k_meet_line_plane(3, a1, a1, p1, p2, p3, k, &lam, NULL), PC_ECOINCIDENT);
    assert_int_equal(pc_k_meet_line_plane(3, a1, a2, p1, p1, p3, k, &lam, NULL), PC_ECOLLINEAR);
}

static void test_polar_rotation(void **state) {
    (void)state;
    /* (2.138) digest §5.0: C(0,0), A(4,0), B(1,3) */
    const double C[2] = {0, 0}, A[2] = {4, 0}, B[2] = {1, 3};
    double m[2];
    assert_int_equal(pc_k_polar(2, C, A, B, 4, M_PI / 6, m), PC_OK);
    NEAR(m[0], 3.464102, 1e-6); NEAR(m[1], 2, 1e-12);
    pc_k_polar(2, C, A, B, 4, M_PI / 2, m);
    NEAR(m[0], 0, 1e-12); NEAR(m[1], 4, 1e-12);
    pc_k_polar(2, C, A, B, 4, M_PI, m);
    NEAR(m[0], -4, 1e-12); NEAR(m[1], 0, 1e-12);
    /* (2.118) §5.8.3: the Fig. 2.25 points A(0,0), B(0.5,1), C(1,0), R = 0.5 about C */
    const double a[2] = {0, 0}, b[2] = {0.5, 1}, c[2] = {1, 0};
    /* gamma = angle ACB = 1.107149 */
    pc_k_polar(2, c, a, b, 0.5, 0, m);
    NEAR(m[0], 0.5, 1e-12); NEAR(m[1], 0, 1e-12);
    pc_k_polar(2, c, a, b, 0.5, 1.1071487177940904 / 2, m);
    NEAR(m[0], 0.574675, 1e-6); NEAR(m[1], 0.262866, 1e-6);
    pc_k_polar(2, c, a, b, 0.5, 1.1071487177940904, m);
    NEAR(m[0], 0.776393, 1e-6); NEAR(m[1], 0.447214, 1e-6);
    pc_k_polar(2, c, a, b, 0.5, M_PI, m);
    NEAR(m[0], 1.5, 1e-12); NEAR(m[1], 0, 1e-12);
    /* in 3-D, the plane of CAB tilted: the distance and the angle are kept */
    const double C3[3] = {1, 1, 1}, A3[3] = {3, 1, 2}, B3[3] = {1, 4, 0};
    double m3[3];
    pc_k_polar(3, C3, A3, B3, 2.5, 0.4, m3);
    NEAR(pc_dist(3, m3, C3), 2.5, 1e-12);
    double u[3] = {A3[0] - C3[0], A3[1] - C3[1], A3[2] - C3[2]}, w[3] = {m3[0] - C3[0], m3[1] - C3[1], m3[2] - C3[2]};
    NEAR(acos(pc_dot(3, u, w) / (pc_norm(3, u) * pc_norm(3, w))), 0.4, 1e-12);
    const double flat[2] = {8, 0};
    assert_int_equal(pc_k_polar(2, C, A, flat, 1, 0.3, m), PC_ECOLLINEAR);
}

static void test_moving_simplex(void **state) {
    (void)state;
    /* Fig. 1.2: simplex DABC, guides NA on A -> A', NB on D -> B, NC on C -> C' (straight,
     * linear in u), the generator a quadratic (p, q) through (1, 0), (0.3, 0.3), (0, 1) */
    const double A[4] = {0, 0, 0, 1}, A2[4] = {0, 0, 2, 1}, D[4] = {3, 0, 0, 1}, B[4] = {3, 0, 3, 1};
    const double C[4] = {0, 3, 0, 1}, C2[4] = {0.5, 3, 2.5, 1};
    double ga[8], gb[8], gc[8];
    for (int j = 0; j < 4; j++) ga[j] = A[j], ga[4 + j] = A2[j], gb[j] = D[j], gb[4 + j] = B[j],
                               gc[j] = C[j], gc[4 + j] = C2[j];
    int st;
    pc_curve *na = pc_curve_bezier(3, 2, ga, &st), *nb = pc_curve_bezier(3, 2, gb, &st),
             *nc = pc_curve_bezier(3, 2, gc, &st);
    const double g[9] = {1, 0, 1, 0.3, 0.3, 1, 0, 1, 1};
    pc_curve *gen = pc_curve_bezier(2, 3, g, &st);
    pc_surface *s = pc_k_moving_simplex(na, nb, nc, gen, &st);
    assert_non_null(s);
    double m[3], h[12];
    for (double u = 0; u <= 1; u += 0.25) {
        pc_surface_eval(s, u, 0, m);          /* p = 1, q = 0: on guide NA */
        NEAR(m[0], 0, 1e-15); NEAR(m[2], 2 * u, 1e-15);
        pc_surface_eval(s, u, 1, m);          /* on guide NB */
        NEAR(m[0], 3, 1e-15); NEAR(m[2], 3 * u, 1e-15);
        /* a point inside: (NA - NC) p + (NB - NC) q + NC at v = 0.5, (p, q) = (0.4, 0.4) */
        pc_surface_eval(s, u, 0.5, m);
        double NA[3] = {0, 0, 2 * u}, NB[3] = {3, 0, 3 * u}, NC[3] = {0.5 * u, 3, 2.5 * u};
        for (int j = 0; j < 3; j++) NEAR(m[j], (NA[j] - NC[j]) * 0.4 + (NB[j] - NC[j]) * 0.4 + NC[j], 1e-14);
        /* exact partials against differences */
        assert_int_equal(pc_surface_eval_h(s, u, 0.37, 1, h), PC_OK);
        double e0[3], e1[3], f0[3], f1[3], d = 1e-6;
        pc_surface_eval(s, u - d, 0.37, e0); pc_surface_eval(s, u + d, 0.37, e1);
        pc_surface_eval(s, u, 0.37 - d, f0); pc_surface_eval(s, u, 0.37 + d, f1);
        for (int j = 0; j < 3; j++) {
            NEAR(h[4 + j], (e1[j] - e0[j]) / (2 * d), 1e-8);
            NEAR(h[8 + j], (f1[j] - f0[j]) / (2 * d), 1e-8);
        }
    }
    pc_surface_release(s);
    assert_null(pc_k_moving_simplex(na, nb, nc, na, &st));
    assert_int_equal(st, PC_EDIM);
    char why[200];
    assert_true(pc_k_moving_simplex_why(st, na, nb, nc, na, why, sizeof why));
    assert_non_null(strstr(why, "one dimension (3-D, 3-D, 3-D) and the generator gen must be 2-D"));
    assert_non_null(strstr(why, "got 3-D"));
    pc_curve *half = pc_curve_sub(nc, 0, 0.5, &st);
    assert_null(pc_k_moving_simplex(na, half, nc, gen, &st));
    assert_int_equal(st, PC_EDOMAIN);
    assert_true(pc_k_moving_simplex_why(st, na, half, nc, gen, why, sizeof why));
    assert_string_equal(why, "the guides must run over one domain of u (NA over [0, 1])");
    assert_false(pc_k_moving_simplex_why(PC_ENOMEM, na, nb, nc, gen, why, sizeof why));
    pc_curve_release(half);
    pc_curve_release(na); pc_curve_release(nb); pc_curve_release(nc); pc_curve_release(gen);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_area_theorem), cmocka_unit_test(test_o_theorem),
        cmocka_unit_test(test_simplex_ratio), cmocka_unit_test(test_meet_line_plane),
        cmocka_unit_test(test_polar_rotation), cmocka_unit_test(test_moving_simplex),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
