/* Chapter 1 theorems: triangle areas (1.2) and Menelaus (1.3), the O-theorem (1.4), the
 * intersection of two lines (1.5) in 2-D and n-D, also with points at infinity as ends (the
 * homogeneous meet), and areas/volumes. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "point.h"

#define NEARE(a, b, e) assert_true(fabs((double)(a) - (double)(b)) <= (e) * (1 + fabs((double)(b))))
#define NEAR(a, b) NEARE(a, b, 1e-12)

static void lin(int n, const double *p, const double *q, double s, double *out) {
    for (int i = 0; i < n; i++) out[i] = p[i] + (q[i] - p[i]) * s;
}

static double sr2(const double *x, const double *y, const double *z) {
    double zh[3] = {z[0], z[1], 1}, lam;
    assert_int_equal(pc_sr(2, x, y, zh, &lam), PC_OK);
    return lam;
}

/* Theorem on triangle areas (§1.3.1, eq. 1.2), signed:
 * S_B1B2B3 / S_A1A2A3 = (1 + λ1λ2λ3)/((1 + λ1)(1 + λ2)(1 + λ3)).
 * Inputs (ours): A1(0,0) A2(4,1) A3(1,3), B1 = A1 + (A2-A1)/4, B2 = A2 + 1.5(A3-A2),
 * B3 = A3 - 0.5(A1-A3): λ = 1/3, -3, -1/3, k = -3/4, S_A = 5.5, S_B = -4.125. */
static void test_triangle_areas(void **state) {
    (void)state;
    double A1[2] = {0, 0}, A2[2] = {4, 1}, A3[2] = {1, 3}, B1[2], B2[2], B3[2];
    lin(2, A1, A2, 0.25, B1);
    lin(2, A2, A3, 1.5, B2);
    lin(2, A3, A1, -0.5, B3);
    NEAR(B2[0], -0.5); NEAR(B2[1], 4); NEAR(B3[0], 1.5); NEAR(B3[1], 4.5);
    double l1 = sr2(A1, A2, B1), l2 = sr2(A2, A3, B2), l3 = sr2(A3, A1, B3);
    NEAR(l1, 1.0 / 3); NEAR(l2, -3); NEAR(l3, -1.0 / 3);
    double k = (1 + l1 * l2 * l3) / ((1 + l1) * (1 + l2) * (1 + l3));
    NEAR(k, -0.75);
    NEAR(pc_area2(A1, A2, A3), 5.5);
    NEAR(pc_area2(B1, B2, B3), -4.125);
    NEAR(pc_area2(B1, B2, B3) / pc_area2(A1, A2, A3), k);
    /* the proof's form: a = (B1A1A2) = -1/(1 + λ1), k = 1 + a + b + c + ab + ac + bc */
    double a = sr2(B1, A1, A2), b = sr2(B2, A2, A3), c = sr2(B3, A3, A1);
    NEAR(a, -1 / (1 + l1)); NEAR(b, -1 / (1 + l2)); NEAR(c, -1 / (1 + l3));
    NEAR(1 + a + b + c + a * b + a * c + b * c, k);
    /* Corollary 2: B3 = A3 gives S_B1B2A3 / S = ab */
    NEAR(pc_area2(B1, B2, A3) / pc_area2(A1, A2, A3), a * b);
    /* Corollary 3: B1 = A1, B3 = A3 gives -b */
    NEAR(pc_area2(A1, B2, A3) / pc_area2(A1, A2, A3), -b);
}

/* Corollary 1 (1.3), Menelaus: B1, B2, B3 collinear iff λ1λ2λ3 = -1; and the O-theorem
 * (1.4) with the closing factor restored (ERRATUM, §9): the product of (A_i A_i+1 B_i) over
 * a closed m-gon cut by a line is (-1)^m.  Polygon and line are ours. */
static void test_o_theorem(void **state) {
    (void)state;
    double P[7][2], L1[2] = {-3, 0.5}, L2[2] = {4, 1.7}, K[3];
    for (int i = 0; i < 7; i++) {
        P[i][0] = 2 * cos(2 * M_PI * i / 7) + 0.3 * sin(i * i);
        P[i][1] = 2 * sin(2 * M_PI * i / 7) + 0.2 * cos(3 * i);
    }
    for (int m = 3; m <= 7; m++) {
        double prod = 1;
        for (int i = 0; i < m; i++) {
            const double *a = P[i], *b = P[(i + 1) % m];
            assert_int_equal(pc_meet(2, a, b, L1, L2, K, NULL, NULL, NULL), PC_OK);
            double lam;
            assert_int_equal(pc_sr(2, a, b, K, &lam), PC_OK);
            prod *= lam;
        }
        NEARE(prod, (m % 2) ? -1.0 : 1.0, 1e-9);
    }
    /* a side parallel to the line: its B is improper and contributes -1 */
    double Q[3][2] = {{0, 0}, {4, 0}, {1, 3}}, M1[2] = {-1, 1}, M2[2] = {5, 1};
    double prod = 1;
    for (int i = 0; i < 3; i++) {
        double lam;
        int st = pc_meet(2, Q[i], Q[(i + 1) % 3], M1, M2, K, NULL, NULL, NULL);
        assert_true(st == PC_OK || st == PC_IMPROPER);
        assert_int_equal(pc_sr(2, Q[i], Q[(i + 1) % 3], K, &lam), PC_OK);
        prod *= lam;
    }
    NEAR(prod, -1);
}

/* (1.5): λ = (q3p4 - p3q4 - p1q34 + q1p34)/(p21q34 - q21p34), K = (A-C)(p21λ+p1) + (B-C)(q21λ+q1) + C
 * in the natural parameters of simplex CAB; pc_meet must agree and K lie on both lines. */
static void test_meet_formula(void **state) {
    (void)state;
    double C[2] = {1, 1}, A[2] = {5, 2}, B[2] = {2, 4};
    double p[5] = {0, 0.2, 1.3, -0.4, 0.9}, q[5] = {0, 0.1, 0.7, 0.8, -0.3}, X[5][2];
    for (int i = 1; i <= 4; i++)
        for (int d = 0; d < 2; d++) X[i][d] = (A[d] - C[d]) * p[i] + (B[d] - C[d]) * q[i] + C[d];
    double p21 = p[2] - p[1], q21 = q[2] - q[1], p34 = p[3] - p[4], q34 = q[3] - q[4];
    double lam = (q[3] * p[4] - p[3] * q[4] - p[1] * q34 + q[1] * p34) / (p21 * q34 - q21 * p34);
    double Kb[2];
    for (int d = 0; d < 2; d++)
        Kb[d] = (A[d] - C[d]) * (p21 * lam + p[1]) + (B[d] - C[d]) * (q21 * lam + q[1]) + C[d];
    double K[3], l, m;
    assert_int_equal(pc_meet(2, X[1], X[2], X[3], X[4], K, &l, &m, NULL), PC_OK);
    NEAR(K[0], Kb[0]); NEAR(K[1], Kb[1]); NEAR(K[2], 1);
    NEAR(l, lam);
    /* on both lines: K = X1 + (X2 - X1)λ = X3 + (X4 - X3)μ */
    for (int d = 0; d < 2; d++) {
        NEAR(K[d], X[1][d] + (X[2][d] - X[1][d]) * l);
        NEAR(K[d], X[3][d] + (X[4][d] - X[3][d]) * m);
    }
    NEAR(pc_area2(K, X[1], X[2]), 0);
    NEAR(pc_area2(K, X[3], X[4]), 0);
}

static void test_meet_cases(void **state) {
    (void)state;
    double K[4], l, m, res;
    /* the diagonals of the square meet at its centre */
    double a[2] = {0, 0}, b[2] = {2, 2}, c[2] = {0, 2}, d[2] = {2, 0};
    assert_int_equal(pc_meet(2, a, b, c, d, K, &l, &m, NULL), PC_OK);
    NEAR(K[0], 1); NEAR(K[1], 1); NEAR(l, 0.5); NEAR(m, 0.5);
    /* parallel lines: the improper point, direction A2 - A1 */
    double e[2] = {0, 1}, f[2] = {2, 3};
    assert_int_equal(pc_meet(2, a, b, e, f, K, &l, &m, NULL), PC_IMPROPER);
    NEAR(K[0], 2); NEAR(K[1], 2); NEAR(K[2], 0);
    assert_true(isinf(l) && isinf(m));
    /* the same line twice, and a line given by one point twice */
    double g[2] = {5, 5};
    assert_int_equal(pc_meet(2, a, b, b, g, K, NULL, NULL, NULL), PC_ESAME_LINE);
    assert_int_equal(pc_meet(2, a, a, c, d, K, NULL, NULL, NULL), PC_ECOINCIDENT);
    assert_int_equal(pc_meet(1, a, b, c, d, K, NULL, NULL, NULL), PC_EDIM);
    /* far from the origin, nearly parallel but not quite */
    double h1[2] = {1e6, 1e6}, h2[2] = {1e6 + 1, 1e6}, h3[2] = {1e6, 1e6 + 1}, h4[2] = {1e6 + 1, 1e6 + 1.001};
    assert_int_equal(pc_meet(2, h1, h2, h3, h4, K, &l, NULL, NULL), PC_OK);
    NEARE(K[0], 1e6 - 1000, 1e-9); NEARE(K[1], 1e6, 1e-12);
    /* the diagonals of a square of side 2k meet at (k, k) whatever the scale: products of
     * two coordinates overflow at 1e200 and underflow at 1e-200, the meet must not */
    for (double k = 1e-200; k < 1e201; k *= 1e200) {
        double a2[2] = {0, 0}, b2[2] = {2 * k, 2 * k}, c2[2] = {0, 2 * k}, d2[2] = {2 * k, 0};
        assert_int_equal(pc_meet(2, a2, b2, c2, d2, K, &l, &m, NULL), PC_OK);
        NEAR(K[0] / k, 1); NEAR(K[1] / k, 1); NEAR(l, 0.5); NEAR(m, 0.5);
        double a3[3] = {0, 0, k}, b3[3] = {2 * k, 2 * k, k}, c3[3] = {0, 2 * k, k},
               d3[3] = {2 * k, 0, k};
        assert_int_equal(pc_meet(3, a3, b3, c3, d3, K, &l, &m, NULL), PC_OK);
        NEAR(K[0] / k, 1); NEAR(K[1] / k, 1); NEAR(K[2] / k, 1); NEAR(l, 0.5); NEAR(m, 0.5);
        double e2[2] = {0, k}, f2[2] = {2 * k, 3 * k};           /* parallel to a2b2 */
        assert_int_equal(pc_meet(2, a2, b2, e2, f2, K, NULL, NULL, NULL), PC_IMPROPER);
    }
    /* 3-D: two lines in the plane z = x meet; skew lines report their distance */
    double p1[3] = {0, 0, 0}, p2[3] = {2, 2, 2}, p3[3] = {0, 2, 0}, p4[3] = {2, 0, 2};
    assert_int_equal(pc_meet(3, p1, p2, p3, p4, K, &l, &m, &res), PC_OK);
    NEAR(K[0], 1); NEAR(K[1], 1); NEAR(K[2], 1); NEAR(K[3], 1); NEAR(res, 0);
    double s3[3] = {0, 2, 1}, s4[3] = {2, 0, 3};            /* the same, lifted by 1 in z */
    assert_int_equal(pc_meet(3, p1, p2, s3, s4, K, &l, &m, &res), PC_ESKEW);
    NEAR(res, sqrt(0.5));                                    /* distance between the lines */
    double t3[3] = {0, 0, 1}, t4[3] = {1, 1, 2};             /* parallel in 3-D */
    assert_int_equal(pc_meet(3, p1, p2, t3, t4, K, NULL, NULL, NULL), PC_IMPROPER);
    NEAR(K[3], 0);
    /* 4-D, lines in a plane off the origin */
    double q1[4] = {1, 0, 0, 1}, q2[4] = {3, 2, 0, 1}, q3[4] = {1, 2, 0, 1}, q4[4] = {3, 0, 0, 1};
    double K4[5];
    assert_int_equal(pc_meet(4, q1, q2, q3, q4, K4, NULL, NULL, NULL), PC_OK);
    NEAR(K4[0], 2); NEAR(K4[1], 1); NEAR(K4[2], 0); NEAR(K4[3], 1);
}

/* ---- the homogeneous meet: points at infinity as ends ------------------------------------- */

#define H2(name, x, y, w) const double name[3] = {x, y, w}
#define H3(name, x, y, z, w) const double name[4] = {x, y, z, w}

/* A line through a point with a direction (weight 0), the direction given as either end:
 * K = P + D lambda.  The diagonals of the square (0,0)-(2,2) meet at (1, 1). */
static void test_meet_h_direction(void **state) {
    (void)state;
    double K[3], l, m;
    H2(O, 0, 0, 1); H2(D, 1, 1, 0); H2(D2, 2, 2, 0);
    H2(B1, 0, 2, 1); H2(B2, 2, 0, 1); H2(E, 1, -1, 0);
    assert_int_equal(pc_meet_h(2, O, D, B1, B2, K, &l, &m, NULL), PC_OK);
    NEAR(K[0], 1); NEAR(K[1], 1); NEAR(K[2], 1); NEAR(l, 1); NEAR(m, 0.5);
    assert_int_equal(pc_meet_h(2, D, O, B1, B2, K, &l, &m, NULL), PC_OK);   /* other order */
    NEAR(K[0], 1); NEAR(K[1], 1); NEAR(K[2], 1); NEAR(l, 1); NEAR(m, 0.5);
    assert_int_equal(pc_meet_h(2, O, D2, B1, B2, K, &l, &m, NULL), PC_OK);  /* lambda along D */
    NEAR(K[0], 1); NEAR(K[1], 1); NEAR(l, 0.5);
    assert_int_equal(pc_meet_h(2, O, D, B1, E, K, &l, &m, NULL), PC_OK);    /* both by directions */
    NEAR(K[0], 1); NEAR(K[1], 1); NEAR(l, 1); NEAR(m, 1);
    assert_int_equal(pc_meet_h(2, O, D, E, B1, K, &l, &m, NULL), PC_OK);
    NEAR(K[0], 1); NEAR(K[1], 1); NEAR(l, 1); NEAR(m, 1);
    /* (1.5)'s lines with A2 replaced by the direction A2 - A1 give the same K */
    double C[2] = {1, 1}, A[2] = {5, 2}, B[2] = {2, 4};
    double p[5] = {0, 0.2, 1.3, -0.4, 0.9}, q[5] = {0, 0.1, 0.7, 0.8, -0.3}, X[5][3];
    for (int i = 1; i <= 4; i++) {
        for (int d = 0; d < 2; d++) X[i][d] = (A[d] - C[d]) * p[i] + (B[d] - C[d]) * q[i] + C[d];
        X[i][2] = 1;
    }
    double Kp[3], lp, mp, U[3] = {X[2][0] - X[1][0], X[2][1] - X[1][1], 0};
    assert_int_equal(pc_meet(2, X[1], X[2], X[3], X[4], Kp, &lp, &mp, NULL), PC_OK);
    assert_int_equal(pc_meet_h(2, U, X[1], X[3], X[4], K, &l, &m, NULL), PC_OK);
    NEAR(K[0], Kp[0]); NEAR(K[1], Kp[1]); NEAR(K[2], 1); NEAR(l, lp); NEAR(m, mp);
    /* weight 1 everywhere: exactly pc_meet */
    assert_int_equal(pc_meet_h(2, X[1], X[2], X[3], X[4], K, &l, &m, NULL), PC_OK);
    assert_true(K[0] == Kp[0] && K[1] == Kp[1] && l == lp && m == mp);
}

/* Weighted values stand for their normalised points: 2*P(0,0), 4*P(2,2), 0.5*P(0,2) and
 * -1*P(2,0) are the square's corners. */
static void test_meet_h_weighted(void **state) {
    (void)state;
    double K[3], l, m;
    H2(A1, 0, 0, 2); H2(A2, 8, 8, 4); H2(B1, 0, 1, 0.5); H2(B2, -2, 0, -1);
    assert_int_equal(pc_meet_h(2, A1, A2, B1, B2, K, &l, &m, NULL), PC_OK);
    NEAR(K[0], 1); NEAR(K[1], 1); NEAR(K[2], 1); NEAR(l, 0.5); NEAR(m, 0.5);
    H2(D, 3, 3, 0);                                           /* with a direction: K = P + D l */
    assert_int_equal(pc_meet_h(2, A1, D, B1, B2, K, &l, &m, NULL), PC_OK);
    NEAR(K[0], 1); NEAR(K[1], 1); NEAR(l, 1.0 / 3);
    /* a weight so small that the point leaves the doubles */
    H2(T, 1e301, 0, 1e-8);
    assert_int_equal(pc_meet_h(2, T, A2, B1, B2, K, NULL, NULL, NULL), PC_ENONFINITE);
}

/* Parallel lines given by directions meet in their common improper point. */
static void test_meet_h_parallel(void **state) {
    (void)state;
    double K[3], l, m;
    H2(O, 0, 0, 1); H2(D, 1, 2, 0); H2(Q, 3, 0, 1); H2(E, -2, -4, 0); H2(Q2, 4, 2, 1);
    assert_int_equal(pc_meet_h(2, O, D, Q, E, K, &l, &m, NULL), PC_IMPROPER);
    NEAR(K[0], 1); NEAR(K[1], 2); NEAR(K[2], 0);              /* the direction of line A */
    assert_true(isinf(l) && l > 0 && isinf(m) && m > 0);
    assert_int_equal(pc_meet_h(2, Q, E, O, D, K, &l, &m, NULL), PC_IMPROPER);
    NEAR(K[0], -2); NEAR(K[1], -4); NEAR(K[2], 0);
    /* line A by two points */
    assert_int_equal(pc_meet_h(2, Q, Q2, O, D, K, NULL, NULL, NULL), PC_IMPROPER);
    NEAR(K[0], 1); NEAR(K[1], 2); NEAR(K[2], 0);
    /* the same line, once by two points and once by a point and its direction */
    H2(P1, 1, 2, 1); H2(P3, 3, 6, 1);
    assert_int_equal(pc_meet_h(2, O, D, P1, P3, K, NULL, NULL, NULL), PC_ESAME_LINE);
    assert_int_equal(pc_meet_h(2, P3, E, O, P1, K, NULL, NULL, NULL), PC_ESAME_LINE);
    /* the construction the book uses: the line through C parallel to AB is C and AB's
     * improper point.  AB || DE; their meet, joined to C(0, 5), meets the y axis at C. */
    H2(A, 0, 0, 1); H2(B, 2, 1, 1); H2(Dp, 1, 3, 1); H2(Ep, 5, 5, 1); H2(C, 0, 5, 1);
    H2(Y1, 7, -1, 1); H2(Y2, 7, 1, 1);
    double Kinf[3];
    assert_int_equal(pc_meet_h(2, A, B, Dp, Ep, Kinf, NULL, NULL, NULL), PC_IMPROPER);
    assert_int_equal(pc_meet_h(2, C, Kinf, Y1, Y2, K, &l, &m, NULL), PC_OK);
    NEAR(K[0], 7); NEAR(K[1], 8.5); NEAR(K[2], 1); NEAR(l, 3.5); NEAR(m, 4.75);
}

/* Two improper points make the line at infinity. */
static void test_meet_h_line_at_infinity(void **state) {
    (void)state;
    double K[4], l, m, res;
    H2(Ex, 1, 0, 0); H2(Ey, 0, 1, 0); H2(Ex2, -3, 0, 0);
    H2(O, 0, 0, 1); H2(P, 3, 1, 1); H2(D, 1, -2, 0);
    assert_int_equal(pc_meet_h(2, Ex, Ey, O, P, K, &l, &m, NULL), PC_IMPROPER);
    NEAR(K[0], 3); NEAR(K[1], 1); NEAR(K[2], 0);              /* the finite line's direction */
    assert_true(isinf(l) && isinf(m));
    assert_int_equal(pc_meet_h(2, O, D, Ey, Ex, K, &l, &m, NULL), PC_IMPROPER);
    NEAR(K[0], 1); NEAR(K[1], -2); NEAR(K[2], 0);
    assert_int_equal(pc_meet_h(2, D, O, Ex, Ey, K, NULL, NULL, NULL), PC_IMPROPER);
    NEAR(K[0], 1); NEAR(K[1], -2); NEAR(K[2], 0);
    /* the plane has one line at infinity; two parallel directions are one improper point */
    assert_int_equal(pc_meet_h(2, Ex, Ey, D, Ex, K, NULL, NULL, NULL), PC_ESAME_LINE);
    assert_int_equal(pc_meet_h(2, Ex, Ex2, O, P, K, NULL, NULL, NULL), PC_ECOINCIDENT);
    assert_int_equal(pc_meet_h(2, O, P, Ex2, Ex, K, NULL, NULL, NULL), PC_ECOINCIDENT);
    /* 3-D: the line at infinity of the planes z = const */
    H3(X, 1, 0, 0, 0); H3(XY, 1, 1, 0, 0); H3(Q, 0, 0, 5, 1); H3(V, 2, 1, 0, 0);
    H3(Z, 0, 0, 1, 0); H3(Q2, 1, 1, 6, 1);
    assert_int_equal(pc_meet_h(3, X, XY, Q, V, K, &l, &m, &res), PC_IMPROPER);
    NEAR(K[0], 2); NEAR(K[1], 1); NEAR(K[2], 0); NEAR(K[3], 0); NEAR(res, 0);
    /* a line that leaves the plane's directions does not reach its line at infinity */
    assert_int_equal(pc_meet_h(3, Q, Q2, X, XY, K, NULL, NULL, &res), PC_ESKEW);
    assert_true(isinf(res) && res > 0);
    assert_int_equal(pc_meet_h(3, Z, Q, X, XY, K, NULL, NULL, &res), PC_ESKEW);
    /* two planes' lines at infinity meet in the direction of the planes' common line:
     * z = 0 and x = 0 share the y axis */
    H3(Y, 0, 1, 0, 0); H3(YZ, 0, 1, 1, 0); H3(YmZ, 0, 1, -1, 0);
    assert_int_equal(pc_meet_h(3, X, Y, YZ, YmZ, K, &l, &m, NULL), PC_IMPROPER);
    NEAR(fabs(K[1]), 1); NEAR(K[0], 0); NEAR(K[2], 0); NEAR(K[3], 0);
    assert_true(isinf(l) && isinf(m));
    /* z = 0 and x + y + z = 0 share (1, -1, 0)/sqrt(2) */
    H3(U1, 1, 0, -1, 0); H3(U2, 0, 1, -1, 0);
    assert_int_equal(pc_meet_h(3, U1, U2, X, XY, K, NULL, NULL, NULL), PC_IMPROPER);
    NEAR(fabs(K[0]), sqrt(0.5)); NEAR(K[0], -K[1]); NEAR(K[2], 0); NEAR(K[3], 0);
    /* the same plane twice, given by other directions */
    H3(XmY, 1, -1, 0, 0);
    assert_int_equal(pc_meet_h(3, XY, XmY, X, Y, K, NULL, NULL, NULL), PC_ESAME_LINE);
    /* 4-D: the planes (x, y) and (z, w) share no direction */
    const double e1[5] = {1, 0, 0, 0, 0}, e2[5] = {0, 1, 0, 0, 0}, e3[5] = {0, 0, 1, 0, 0},
                 e4[5] = {0, 0, 0, 1, 0};
    double K4[5];
    assert_int_equal(pc_meet_h(4, e1, e2, e3, e4, K4, NULL, NULL, &res), PC_ESKEW);
    assert_true(isinf(res));
}

/* 3-D with a direction: skew lines report their distance, meeting lines their point. */
static void test_meet_h_3d(void **state) {
    (void)state;
    double K[4], l, m, res;
    H3(O, 0, 0, 0, 1); H3(D, 1, 1, 1, 0);
    H3(S3, 0, 2, 1, 1); H3(S4, 2, 0, 3, 1);                   /* pc_meet's skew pair */
    assert_int_equal(pc_meet_h(3, O, D, S3, S4, K, &l, &m, &res), PC_ESKEW);
    NEAR(res, sqrt(0.5));
    assert_int_equal(pc_meet_h(3, D, O, S3, S4, K, &l, &m, &res), PC_ESKEW);
    NEAR(res, sqrt(0.5));
    H3(P3, 0, 2, 0, 1); H3(E, 1, -1, 1, 0);
    assert_int_equal(pc_meet_h(3, O, D, P3, E, K, &l, &m, &res), PC_OK);
    NEAR(K[0], 1); NEAR(K[1], 1); NEAR(K[2], 1); NEAR(K[3], 1); NEAR(l, 1); NEAR(m, 1);
    NEAR(res, 0);
    H3(F, 2, 2, 2, 0); H3(T, 0, 0, 1, 1);                     /* parallel in 3-D */
    assert_int_equal(pc_meet_h(3, O, D, T, F, K, &l, &m, NULL), PC_IMPROPER);
    NEAR(K[0], 1); NEAR(K[1], 1); NEAR(K[2], 1); NEAR(K[3], 0);
}

static void test_meet_h_errors(void **state) {
    (void)state;
    double K[3];
    H2(O, 0, 0, 1); H2(P, 1, 0, 1); H2(Q, 0, 1, 1); H2(Z, 0, 0, 0); H2(N, NAN, 0, 1);
    H2(I, 0, 0, INFINITY);
    assert_int_equal(pc_meet_h(2, O, Z, P, Q, K, NULL, NULL, NULL), PC_EZERO);  /* no direction */
    assert_int_equal(pc_meet_h(2, O, P, Q, Z, K, NULL, NULL, NULL), PC_EZERO);
    assert_int_equal(pc_meet_h(2, O, P, N, Q, K, NULL, NULL, NULL), PC_ENONFINITE);
    assert_int_equal(pc_meet_h(2, O, P, I, Q, K, NULL, NULL, NULL), PC_ENONFINITE);
    assert_int_equal(pc_meet_h(2, O, O, P, Q, K, NULL, NULL, NULL), PC_ECOINCIDENT);
    assert_int_equal(pc_meet_h(2, P, Q, Q, Q, K, NULL, NULL, NULL), PC_ECOINCIDENT);
    assert_int_equal(pc_meet_h(1, O, P, Q, Q, K, NULL, NULL, NULL), PC_EDIM);
    assert_int_equal(pc_meet_h(PC_MAXDIM + 1, O, P, Q, Q, K, NULL, NULL, NULL), PC_EDIM);
}

static void test_measure(void **state) {
    (void)state;
    double A[2] = {0, 0}, B[2] = {4, 0}, C[2] = {1, 3};
    NEAR(pc_area2(A, B, C), 6);
    NEAR(pc_area2(A, C, B), -6);
    double sq[8] = {0, 0, 2, 0, 2, 2, 0, 2};
    NEAR(pc_polygon_area2(4, sq), 4);
    double A3[3] = {0, 0, 0}, B3[3] = {4, 0, 0}, C3[3] = {1, 3, 0}, D3[3] = {0, 0, 2};
    NEAR(pc_area(3, A3, B3, C3), 6);
    NEAR(pc_volume3(A3, B3, C3, D3), 4);                     /* 6·2/3 */
    NEAR(pc_volume3(A3, C3, B3, D3), -4);
    double v[12] = {0, 0, 0, 4, 0, 0, 1, 3, 0, 0, 0, 2};
    NEAR(pc_measure(3, 3, v), 4);
    NEAR(pc_measure(3, 1, v), 4);
    double flat[9] = {0, 0, 0, 1, 1, 1, 2, 2, 2};
    NEAR(pc_measure(3, 2, flat), 0);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_triangle_areas),
        cmocka_unit_test(test_o_theorem),
        cmocka_unit_test(test_meet_formula),
        cmocka_unit_test(test_meet_cases),
        cmocka_unit_test(test_meet_h_direction),
        cmocka_unit_test(test_meet_h_weighted),
        cmocka_unit_test(test_meet_h_parallel),
        cmocka_unit_test(test_meet_h_line_at_infinity),
        cmocka_unit_test(test_meet_h_3d),
        cmocka_unit_test(test_meet_h_errors),
        cmocka_unit_test(test_measure),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
