/* Simplices: initial-point and barycentric forms (§4.1, §4.3), parameters of a point in any
 * ambient dimension, the S-theorem and the V-theorem (§1.3.3-1.3.4). */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include "simplex.h"

#define NEARE(a, b, e) assert_true(fabs((double)(a) - (double)(b)) <= (e) * (1 + fabs((double)(b))))
#define NEAR(a, b) NEARE(a, b, 1e-12)

static pc_simplex *make(int n, int k, const double *v, int expect) {
    pc_simplex *s = malloc(pc_simplex_size(n, k));
    assert_non_null(s);
    assert_int_equal(pc_simplex_init(s, n, k, v), expect);
    return s;
}

/* simplex CAB: C(1,1) A(5,2) B(2,4); M = (A - C)p + (B - C)q + C */
static void test_eval_params(void **state) {
    (void)state;
    double v[6] = {1, 1, 5, 2, 2, 4};
    pc_simplex *s = make(2, 2, v, PC_OK);
    double pq[2] = {0.3, 0.6}, M[2], back[2], res;
    pc_simplex_eval(s, pq, M);
    NEAR(M[0], 1 + 4 * 0.3 + 1 * 0.6); NEAR(M[1], 1 + 1 * 0.3 + 3 * 0.6);
    pc_simplex_params(s, M, back, &res);
    NEAR(back[0], 0.3); NEAR(back[1], 0.6); NEAR(res, 0);
    /* vertices: A(1,0), B(0,1), C(0,0) */
    pc_simplex_params(s, v + 2, back, &res); NEAR(back[0], 1); NEAR(back[1], 0);
    pc_simplex_params(s, v, back, &res); NEAR(back[0], 0); NEAR(back[1], 0);
    /* barycentric: Ap + Bq + Cr with p + q + r = 1 is the same point */
    double c[3] = {0.3, 0.6, 0.1}, h[3];
    pc_simplex_bary(s, c, h);
    NEAR(h[0], M[0]); NEAR(h[1], M[1]); NEAR(h[2], 1);
    /* coefficients summing to 2: a weighted value (membership condition violated) */
    double c2[3] = {1, 1, 0};
    pc_simplex_bary(s, c2, h);
    NEAR(h[2], 2); NEAR(h[0], 7); NEAR(h[1], 6);
    /* measure is the signed area: C -> A -> B counter-clockwise */
    NEAR(pc_simplex_measure(s), 5.5);
    free(s);
}

/* Parameters of a point for a triangle in 3-D and 4-D (least squares, with residual), and
 * the identity S(S:params(M)) = M for points of the flat. */
static void test_params_nd(void **state) {
    (void)state;
    double v[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};            /* the triangle x + y + z = 1 */
    pc_simplex *s = make(3, 2, v, PC_OK);
    double M[3] = {0.2, 0.3, 0.5}, p[2], res, back[3];
    pc_simplex_params(s, M, p, &res);
    NEAR(p[0], 0.3); NEAR(p[1], 0.5); NEAR(res, 0);
    pc_simplex_eval(s, p, back);
    NEAR(back[0], 0.2); NEAR(back[1], 0.3); NEAR(back[2], 0.5);
    /* off the plane by (1,1,1)/√3·d: params of the projection, residual d */
    double d = 0.7, Off[3];
    for (int i = 0; i < 3; i++) Off[i] = M[i] + d / sqrt(3);
    pc_simplex_params(s, Off, p, &res);
    NEAR(p[0], 0.3); NEAR(p[1], 0.5); NEAR(res, d);
    NEAR(pc_simplex_measure(s), sqrt(3) / 2);             /* unsigned when k < n */
    free(s);
    /* 4-D: a tetrahedron in a 3-flat, round trip */
    double w[16] = {1, 2, 3, 4,  2, 2, 3, 5,  1, 4, 3, 4,  1, 2, 6, 3};
    pc_simplex *t = make(4, 3, w, PC_OK);
    double q[3] = {0.25, -0.5, 1.5}, X[4], r[3];
    pc_simplex_eval(t, q, X);
    pc_simplex_params(t, X, r, &res);
    NEAR(r[0], q[0]); NEAR(r[1], q[1]); NEAR(r[2], q[2]); NEARE(res, 0, 1e-12);
    free(t);
}

/* S-theorem: for A_i = A p_i + B q_i + C r_i, S_A1A2A3 / S_ABC = det[p_i q_i 1] (signed). */
static void test_s_theorem(void **state) {
    (void)state;
    double v[6] = {1, 3, 0, 0, 4, 1};                     /* simplex C(1,3) A(0,0) B(4,1) */
    pc_simplex *s = make(2, 2, v, PC_OK);
    double pts[6] = {0.5, 0.2, 2.5, -1.0, -1.5, 2.0}, res;
    double ratio = pc_simplex_ratio(s, pts, &res);
    double S = pc_area2(v, v + 2, v + 4);
    NEAR(ratio, pc_area2(pts, pts + 2, pts + 4) / S);
    NEAR(res, 0);
    /* with the book's full barycentric rows (p, q, r): the same determinant */
    double m[9];
    for (int i = 0; i < 3; i++) {
        double pq[2];
        pc_simplex_params(s, pts + 2 * i, pq, &res);
        m[3 * i] = pq[0]; m[3 * i + 1] = pq[1]; m[3 * i + 2] = 1 - pq[0] - pq[1];
    }
    double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6])
               + m[2] * (m[3] * m[7] - m[4] * m[6]);
    NEAR(det, ratio);
    /* the simplex's own vertices give 1, swapped ones -1 */
    NEAR(pc_simplex_ratio(s, v, &res), 1);
    double sw[6] = {0, 0, 1, 3, 4, 1};
    NEAR(pc_simplex_ratio(s, sw, &res), -1);
    /* works for a triangle in space: the ratio is affine-invariant */
    double v3[9] = {1, 3, 7, 0, 0, 7, 4, 1, 7}, pts3[9] = {0.5, 0.2, 7, 2.5, -1, 7, -1.5, 2, 7};
    pc_simplex *s3 = make(3, 2, v3, PC_OK);
    NEAR(pc_simplex_ratio(s3, pts3, &res), ratio);
    free(s3);
    free(s);
}

/* V-theorem (with the printed det/det ERRATUM corrected): V_1234/V_ABCD = det[p q r s]. */
static void test_v_theorem(void **state) {
    (void)state;
    double v[12] = {0, 0, 0,  3, 0, 0,  0, 2, 0,  0, 0, 4};   /* D A B C, volume 4 */
    pc_simplex *s = make(3, 3, v, PC_OK);
    NEAR(pc_simplex_measure(s), 4);
    double pts[12] = {1, 0.5, 0.2,  0.1, 1.5, 1,  0.3, 0.2, 2.5,  2, 1, 1}, res;
    double ratio = pc_simplex_ratio(s, pts, &res);
    NEAR(ratio, pc_volume3(pts, pts + 3, pts + 6, pts + 9) / pc_volume3(v, v + 3, v + 6, v + 9));
    /* full barycentric rows (p, q, r, s) of A_i = Ap + Bq + Cr + Ds: the book's determinant
     * is the ratio to V_ABCD, and ABCD is an odd permutation of our DABC: det = -ratio */
    double m[16];
    for (int i = 0; i < 4; i++) {
        double pqr[3];
        pc_simplex_params(s, pts + 3 * i, pqr, &res);
        m[4 * i] = pqr[0]; m[4 * i + 1] = pqr[1]; m[4 * i + 2] = pqr[2];
        m[4 * i + 3] = 1 - pqr[0] - pqr[1] - pqr[2];
    }
    /* 4x4 determinant by cofactors of the first row */
    double det = 0;
    for (int c = 0; c < 4; c++) {
        double sub[9];
        int k = 0;
        for (int i = 1; i < 4; i++)
            for (int j = 0; j < 4; j++) if (j != c) sub[k++] = m[4 * i + j];
        double d3 = sub[0] * (sub[4] * sub[8] - sub[5] * sub[7]) - sub[1] * (sub[3] * sub[8] - sub[5] * sub[6])
                  + sub[2] * (sub[3] * sub[7] - sub[4] * sub[6]);
        det += ((c % 2) ? -1 : 1) * m[c] * d3;
    }
    NEAR(det, -ratio);
    NEAR(det, pc_volume3(pts, pts + 3, pts + 6, pts + 9) / pc_volume3(v + 3, v + 6, v + 9, v));
    NEAR(pc_simplex_ratio(s, v, &res), 1);
    free(s);
}

static void test_degenerate(void **state) {
    (void)state;
    double flat[6] = {0, 0, 1, 1, 2, 2};
    free(make(2, 2, flat, PC_ECOLLINEAR));
    double same[6] = {1, 1, 1, 1, 2, 3};
    free(make(2, 2, same, PC_ECOINCIDENT));
    double nearly[6] = {0, 0, 1, 0, 2, 1e-13};
    free(make(2, 2, nearly, PC_ECOLLINEAR));
    double thin[6] = {0, 0, 1, 0, 2, 1e-6};               /* thin but a true triangle */
    free(make(2, 2, thin, PC_OK));
    double coplanar[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    free(make(3, 3, coplanar, PC_ECOLLINEAR));
    double two[4] = {0, 0, 1, 1};
    free(make(1, 3, two, PC_EDIM));                       /* 3-simplex in 1-D */
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_eval_params),
        cmocka_unit_test(test_params_nd),
        cmocka_unit_test(test_s_theorem),
        cmocka_unit_test(test_v_theorem),
        cmocka_unit_test(test_degenerate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
