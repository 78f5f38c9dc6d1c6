/* Core values, weights, metric operator (§1.4) and simple ratios (conventions §2 item 3). */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "point.h"

#define EPS 1e-12
#define NEAR(a, b) assert_true(fabs((double)(a) - (double)(b)) <= EPS * (1 + fabs((double)(b))))

/* A point equation with coefficients summing to 1 is a point, a difference a vector; the
 * classic slip P*100 + P gives weight 101 (the membership condition is violated). */
static void test_weights(void **state) {
    (void)state;
    double a[3] = {1, 2, 1}, b[3] = {5, 4, 1}, m[3], loc[2];
    pc_lerp(2, a, b, 0.25, m);
    assert_int_equal(pc_kind_of(m[2]), PC_KIND_POINT);
    assert_int_equal(pc_loc(2, m, loc), PC_OK);
    NEAR(loc[0], 2); NEAR(loc[1], 2.5);
    pc_sub(2, b, a, m);
    assert_int_equal(pc_kind_of(m[2]), PC_KIND_VECTOR);
    assert_int_equal(pc_loc(2, m, loc), PC_IMPROPER);
    double s[3];
    pc_scale(2, a, 100, s);
    pc_add(2, s, b, m);
    assert_int_equal(pc_kind_of(m[2]), PC_KIND_WEIGHTED);
    assert_int_equal(pc_loc(2, m, loc), PC_EWEIGHT);
    /* normalisation divides by the weight: (100 A + B)/101 */
    double nm[3];
    assert_int_equal(pc_normalize(2, m, nm), PC_OK);
    NEAR(nm[0], 105.0 / 101); NEAR(nm[1], 204.0 / 101); NEAR(nm[2], 1);
    pc_sub(2, b, a, m);
    assert_int_equal(pc_normalize(2, m, nm), PC_IMPROPER);
    /* M = A t̄ + B t: both endpoints exact */
    pc_lerp(2, a, b, 0.0, m);
    assert_true(m[0] == 1 && m[1] == 2 && m[2] == 1);
    pc_lerp(2, a, b, 1.0, m);
    assert_true(m[0] == 5 && m[1] == 4 && m[2] == 1);
    /* a weight within 1e-9 of 1 still reads as a point */
    assert_int_equal(pc_kind_of(1 + 1e-12), PC_KIND_POINT);
    assert_int_equal(pc_kind_of(1e-12), PC_KIND_VECTOR);
    assert_int_equal(pc_kind_of(1 + 1e-6), PC_KIND_WEIGHTED);
}

/* Metric operator Σ^A_BC and its five properties (§1.4, Fig. 1.11). */
static void test_sigma(void **state) {
    (void)state;
    double A[2] = {0, 0}, B[2] = {4, 0}, C[2] = {1, 3};
    double sA = pc_sigma(2, A, B, C), sB = pc_sigma(2, B, A, C), sC = pc_sigma(2, C, A, B);
    NEAR(sA, 4);                                       /* AH·AB = 1·4, H = (1, 0) */
    double c = pc_dist(2, A, B), b = pc_dist(2, C, A), a = pc_dist(2, B, C);
    NEAR(sA, (c * c + b * b - a * a) / 2);             /* (AB² + AC² - BC²)/2 */
    NEAR(sA, c * b * cos(atan2(3, 1)));                /* AB·AC·cos α */
    NEAR(pc_sigma(2, A, B, C), pc_sigma(2, A, C, B));  /* 1: symmetric in B, C */
    NEAR(pc_sigma(2, A, B, B), c * c);                 /* 2: Σ^A_BB = AB² */
    NEAR(pc_sigma(2, A, A, B), 0);                     /* 3 */
    NEAR(pc_sigma(2, B, A, B), 0);
    NEAR(sA + sB, c * c);                              /* 4: Σ^A + Σ^B = AB², and round */
    NEAR(sB + sC, a * a);                              /*    the triangle: Σ^B + Σ^C = BC² */
    NEAR(sA + sC, b * b);                              /*    Σ^A + Σ^C = CA² */
    NEAR(sB, 12); NEAR(sC, 6);                         /* BA·BH = 4·3, CA·CB = (-1,-3)·(3,-3) */
    /* 5: right angle at a vertex iff Σ there is 0 */
    double R[2] = {4, 5};
    NEAR(pc_sigma(2, B, A, R), 0);
    /* foot of the perpendicular: H = A + (B - A) Σ^A_BC / Σ^A_BB */
    double H[2];
    assert_int_equal(pc_foot(2, C, A, B, H), PC_OK);
    NEAR(H[0], 1); NEAR(H[1], 0);
    assert_int_equal(pc_foot(2, C, A, A, H), PC_ECOINCIDENT);
    /* the same triangle scaled by 1e200 and by 1e-200: the squared lengths would overflow
     * or underflow, the foot must not (it scales with the triangle) */
    for (double k = 1e-200; k < 1e201; k *= 1e200) {
        double Ak[2] = {0, 0}, Bk[2] = {4 * k, 0}, Ck[2] = {k, 3 * k};
        assert_int_equal(pc_foot(2, Ck, Ak, Bk, H), PC_OK);
        NEAR(H[0] / k, 1); NEAR(H[1] / k, 0);
    }
    /* 3-D: AB ⟂ AC */
    double A3[3] = {1, 2, 0}, B3[3] = {4, 6, 0}, C3[3] = {1, 2, 5};
    NEAR(pc_sigma(3, A3, B3, C3), 0);
    NEAR(pc_dist(3, A3, B3), 5);
    /* "(product of two segments)·sin = double area": 2S = sqrt(ΣBB ΣCC - ΣBC²) */
    double S2 = sqrt(pc_sigma(2, A, B, B) * pc_sigma(2, A, C, C) - sA * sA);
    NEAR(S2, 2 * pc_area2(A, B, C));
    NEAR(pc_area(2, A, B, C), 6);
}

static void test_vectors(void **state) {
    (void)state;
    double u[3] = {3, 4, 0}, v[3] = {0, 0, 2}, w[3], ang;
    assert_int_equal(pc_unit(3, u, w), PC_OK);
    NEAR(w[0], 0.6); NEAR(w[1], 0.8);
    double z[3] = {0, 0, 0};
    assert_int_equal(pc_unit(3, z, w), PC_EZERO);
    pc_cross3(u, v, w);
    NEAR(w[0], 8); NEAR(w[1], -6); NEAR(w[2], 0);
    NEAR(pc_cross2(u, (double[]){-4, 3}), 25);
    pc_perp2(u, w);
    NEAR(w[0], -4); NEAR(w[1], 3);
    assert_int_equal(pc_angle(3, u, v, &ang), PC_OK);
    NEAR(ang, M_PI / 2);
    assert_int_equal(pc_angle(2, (double[]){1, 0}, (double[]){-1, 1e-9}, &ang), PC_OK);
    NEAR(ang, M_PI - 1e-9);
    assert_int_equal(pc_angle(2, (double[]){1, 0}, (double[]){1, 1e-9}, &ang), PC_OK);
    assert_true(fabs(ang - 1e-9) < 1e-20);                 /* accurate for small angles */
    assert_int_equal(pc_angle(3, u, z, &ang), PC_EZERO);
    NEAR(pc_norm(2, (double[]){3e200, 4e200}), 5e200);     /* no overflow */
}

/* (XYZ) = (X - Z)/(Z - Y); Z = (X + λY)/(1 + λ); the permutation rules of §2 item 3. */
static void test_simple_ratio(void **state) {
    (void)state;
    double A[2] = {0, 0}, B[2] = {6, 3}, lam;
    double Ch[3] = {2, 1, 1};                          /* C = A + (B - A)/3 */
    assert_int_equal(pc_sr(2, A, B, Ch, &lam), PC_OK);
    NEAR(lam, 0.5);                                    /* AC/CB = 1/2 */
    double Ah[3] = {0, 0, 1}, Bh[3] = {6, 3, 1}, Z[3];
    assert_int_equal(pc_divide(2, Ah, Bh, 0.5, Z), PC_OK);
    NEAR(Z[0], 2); NEAR(Z[1], 1); NEAR(Z[2], 1);
    /* the six permutations from λ = (ABC) */
    double Cl[2] = {2, 1}, Ahh[3], r;
    pc_sr(2, B, A, Ch, &r); NEAR(r, 1 / lam);                        /* (BAC) */
    pc_sr(2, A, Cl, Bh, &r); NEAR(r, -(1 + lam));                    /* (ACB) */
    Ahh[0] = 0; Ahh[1] = 0; Ahh[2] = 1;
    pc_sr(2, Cl, A, Bh, &r); NEAR(r, -1 / (1 + lam));                /* (CAB) */
    pc_sr(2, B, Cl, Ahh, &r); NEAR(r, -(1 + lam) / lam);             /* (BCA) */
    pc_sr(2, Cl, B, Ahh, &r); NEAR(r, -lam / (1 + lam));             /* (CBA) */
    /* (XYZ)(YXZ) = 1, used in the proof of the O-theorem */
    double r1, r2;
    pc_sr(2, A, B, Ch, &r1); pc_sr(2, B, A, Ch, &r2); NEAR(r1 * r2, 1);
    /* special values: Z = X gives 0, Z = Y gives oo, midpoint gives 1 */
    assert_int_equal(pc_sr(2, A, B, Ah, &r), PC_OK); NEAR(r, 0);
    assert_int_equal(pc_sr(2, A, B, Bh, &r), PC_OK); assert_true(isinf(r) && r > 0);
    double Mh[3] = {3, 1.5, 1};
    pc_sr(2, A, B, Mh, &r); NEAR(r, 1);
    /* λ = -1: the improper point of AB, and its ratio is -1 */
    assert_int_equal(pc_divide(2, Ah, Bh, -1, Z), PC_IMPROPER);
    NEAR(Z[0], -6); NEAR(Z[1], -3); NEAR(Z[2], 0);
    assert_int_equal(pc_sr(2, A, B, Z, &r), PC_OK); NEAR(r, -1);
    assert_int_equal(pc_divide(2, Ah, Bh, INFINITY, Z), PC_OK);
    NEAR(Z[0], 6); NEAR(Z[2], 1);
    assert_int_equal(pc_divide(2, Ah, Bh, NAN, Z), PC_ENONFINITE);
    /* errors */
    double Off[3] = {2, 2, 1};
    assert_int_equal(pc_sr(2, A, B, Off, &r), PC_ENOTCOLLINEAR);
    double Vd[3] = {1, 1, 0};
    assert_int_equal(pc_sr(2, A, B, Vd, &r), PC_ENOTCOLLINEAR);
    assert_int_equal(pc_sr(2, A, A, Ah, &r), PC_ECOINCIDENT);
    double W[3] = {4, 2, 2};
    assert_int_equal(pc_sr(2, A, B, W, &r), PC_EWEIGHT);
    /* the ratio is scale-free: (XYZ) = -2 for X = 0, Y = k, Z = 2k whether k is 1e-300 or
     * 1e200 (a dot product of the differences would underflow or overflow to 0/0) */
    for (double k = 1e-300; k < 1e201; k *= 1e250) {
        double Xk[2] = {0, 0}, Yk[2] = {k, 0}, Zk[3] = {2 * k, 0, 1};
        assert_int_equal(pc_sr(2, Xk, Yk, Zk, &r), PC_OK);
        NEAR(r, -2);
        double Zoff[3] = {2 * k, k, 1};
        assert_int_equal(pc_sr(2, Xk, Yk, Zoff, &r), PC_ENOTCOLLINEAR);
    }
    /* "if AP/AC = t then (ACP) = t/t̄" (ch. 3) */
    double t = 0.3, P[3] = {6 * t, 3 * t, 1};
    pc_sr(2, A, B, P, &r); NEAR(r, t / (1 - t));
}

static void test_harmonic_cross(void **state) {
    (void)state;
    double A[1] = {0}, B[1] = {4}, T[2] = {1, 1}, N[2], cr;
    /* (ABT) = 1/3, the conjugate has (ABN) = -1/3: N = -2 */
    assert_int_equal(pc_harmonic(1, A, B, T, N), PC_OK);
    NEAR(N[0] / N[1], -2);
    double Nh[2] = {-2, 1}, Th[2] = {1, 1};
    assert_int_equal(pc_cross_ratio(1, A, B, Th, Nh, &cr), PC_OK);
    NEAR(cr, -1);                                      /* harmonic quadruple */
    /* the midpoint's conjugate is the improper point, and back */
    double Mid[2] = {2, 1};
    assert_int_equal(pc_harmonic(1, A, B, Mid, N), PC_IMPROPER);
    NEAR(N[1], 0);
    assert_int_equal(pc_harmonic(1, A, B, N, Th), PC_OK);
    NEAR(Th[0] / Th[1], 2);
    /* cross ratio is a projective invariant: x -> 1/x on points off 0 */
    double a[1] = {1}, b[1] = {2}, c[2] = {3, 1}, d[2] = {5, 1}, r1, r2;
    pc_cross_ratio(1, a, b, c, d, &r1);
    double a2[1] = {1.0}, b2[1] = {0.5}, c2[2] = {1.0 / 3, 1}, d2[2] = {0.2, 1};
    pc_cross_ratio(1, a2, b2, c2, d2, &r2);
    NEAR(r1, r2);
    NEAR(r1, (-2.0 / 1.0) / (-4.0 / 3.0));            /* (ABC) = -2/1, (ABD) = -4/3 */
    double Ah[2] = {0, 1};
    assert_int_equal(pc_cross_ratio(1, A, B, Th, Ah, &cr), PC_OK);
    assert_true(isinf(cr));
    assert_int_equal(pc_cross_ratio(1, A, B, Ah, Ah, &cr), PC_ECOINCIDENT);
    assert_int_equal(pc_cross_ratio(1, A, A, Th, Ah, &cr), PC_ECOINCIDENT);
}

/* Equality of values: one dimension, every double == (the __eq of points). */
static void test_value_same(void **state) {
    (void)state;
    assert_true(pc_value_same(2, (double[]){1, 2, 1}, 2, (double[]){1, 2, 1}));
    assert_true(pc_value_same(1, (double[]){-0.0, 0}, 1, (double[]){0, 0}));          /* -0 is 0 */
    assert_false(pc_value_same(2, (double[]){1, 2, 1}, 2, (double[]){1, 2, 0}));      /* P and V */
    assert_false(pc_value_same(1, (double[]){1, 1}, 2, (double[]){1, 1, 1}));         /* 1-D, 2-D */
    assert_false(pc_value_same(1, (double[]){NAN, 1}, 1, (double[]){NAN, 1}));
    assert_false(pc_value_same(1, (double[]){1, 1}, 1, (double[]){1 + 1e-15, 1}));    /* exact */
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_weights),
        cmocka_unit_test(test_sigma),
        cmocka_unit_test(test_vectors),
        cmocka_unit_test(test_simple_ratio),
        cmocka_unit_test(test_harmonic_cross),
        cmocka_unit_test(test_value_same),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
