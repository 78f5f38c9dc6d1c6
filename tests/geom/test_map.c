/* The one map type (map.h): affine maps by point correspondences (change of simplex, §1.2.2)
 * and frames, composition and inverse of affine and projective maps, the textbook's matrices
 * and test vectors (Buimov §1.7, §2.1-§2.8, digest §9.2, with the corrected signs), the
 * projections, vanishing points, the matrix conventions, and the errors. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "map.h"

#define NEARE(a, b, e) assert_true(fabs((double)(a) - (double)(b)) <= (e) * (1 + fabs((double)(b))))
#define NEAR(a, b) NEARE(a, b, 1e-12)
#define NEAR6(a, b) assert_true(fabs((double)(a) - (double)(b)) <= 5e-7)

static const double PI = 3.14159265358979323846;

/* the image of a point (weight 1) that must stay finite */
static void apply_pt(const pc_map *f, const double *x, double *y) {
    double in[PC_MAXDIM + 1], out[PC_MAXDIM + 1];
    for (int i = 0; i < f->nin; i++) in[i] = x[i];
    in[f->nin] = 1;
    assert_int_equal(pc_map_image(f, in, out), PC_OK);
    assert_true(out[f->nout] == 1);
    for (int i = 0; i < f->nout; i++) y[i] = out[i];
}

/* the matrix of f in the textbook's row convention against a printed one */
static void row_matrix_is(const pc_map *f, const double *want, double tol) {
    double a[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)];
    pc_map_to_matrix(f, 1, a);
    for (int i = 0; i < (f->nin + 1) * (f->nout + 1); i++)
        assert_true(fabs(a[i] - want[i]) <= tol);
}

static void is_identity(const pc_map *h, int n, double tol) {
    assert_int_equal(h->nin, n);
    assert_int_equal(h->nout, n);
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++)
            assert_true(fabs(PC_MAP_AT(h, i, j) - (i == j ? 1.0 : 0.0)) <= tol);
}

/* deterministic pseudo-random numbers in [-1, 1) */
static uint64_t seed = 88172645463325252ull;
static double rnd(void) {
    seed ^= seed << 13; seed ^= seed >> 7; seed ^= seed << 17;
    return (double)(seed >> 11) / 4503599627370496.0 - 1.0;
}

static void test_affine_points(void **state) {
    (void)state;
    double src[6] = {0, 0, 1, 0, 0, 1}, dst[6] = {2, 1, 4, 2, 1, 3};
    pc_map f;
    assert_int_equal(pc_map_affine_points(&f, 2, 2, src, dst), PC_OK);
    assert_true(pc_map_is_affine(&f));
    double y[2];
    for (int i = 0; i < 3; i++) {                 /* the pairs map onto each other */
        apply_pt(&f, src + 2 * i, y);
        NEAR(y[0], dst[2 * i]); NEAR(y[1], dst[2 * i + 1]);
    }
    /* M = [[2, -1], [1, 2]], t = (2, 1) */
    NEAR(PC_MAP_AT(&f, 0, 0), 2); NEAR(PC_MAP_AT(&f, 0, 1), -1); NEAR(PC_MAP_AT(&f, 0, 2), 2);
    NEAR(PC_MAP_AT(&f, 1, 0), 1); NEAR(PC_MAP_AT(&f, 1, 1), 2); NEAR(PC_MAP_AT(&f, 1, 2), 1);
    /* a vector (weight 0) ignores the translation; weights are kept */
    double v[3] = {1, 1, 0}, out[3];
    assert_int_equal(pc_map_image(&f, v, out), PC_OK);
    NEAR(out[0], 1); NEAR(out[1], 3); assert_true(out[2] == 0);
    double w[3] = {2, 0, 2};                      /* 2*P(1, 0) */
    pc_map_apply(&f, w, out);
    NEAR(out[0], 8); NEAR(out[1], 4); NEAR(out[2], 2);
    /* general source triangle */
    double s2[6] = {1, 1, 5, 2, 2, 4}, d2[6] = {0, 0, 3, -1, 7, 7};
    assert_int_equal(pc_map_affine_points(&f, 2, 2, s2, d2), PC_OK);
    for (int i = 0; i < 3; i++) {
        apply_pt(&f, s2 + 2 * i, y);
        NEAR(y[0], d2[2 * i]); NEAR(y[1], d2[2 * i + 1]);
    }
    double flat[6] = {0, 0, 1, 1, 2, 2};
    assert_int_equal(pc_map_affine_points(&f, 2, 2, flat, dst), PC_ECOLLINEAR);
    double same[6] = {1, 1, 1, 1, 0, 0};
    assert_int_equal(pc_map_affine_points(&f, 2, 2, same, dst), PC_ECOINCIDENT);
    assert_int_equal(pc_map_affine_points(&f, 0, 2, same, dst), PC_EDIM);
}

/* f o f^-1 = f^-1 o f = id for random well-conditioned maps of dimensions 1..4, affine (the
 * result is exactly affine) and projective; (f o g)(x) = f(g(x)). */
static void test_compose_inverse(void **state) {
    (void)state;
    for (int n = 1; n <= 4; n++) {
        for (int trial = 0; trial < 20; trial++) {
            for (int proj = 0; proj < 2; proj++) {
                double a[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)];
                for (int i = 0; i <= n; i++)
                    for (int j = 0; j <= n; j++) {
                        double v = (i == j ? 2.0 : 0.0) + 0.5 * rnd();
                        if (i < n && j == n) v = 3 * rnd();                /* translation */
                        if (i == n) v = proj ? (j == n ? 1.0 : 0.3 * rnd()) : (j == n);
                        a[i * (n + 1) + j] = v;
                    }
                pc_map f, fi, h;
                assert_int_equal(pc_map_from_matrix(&f, n, n, a, 0), PC_OK);
                assert_int_equal(pc_map_is_affine(&f), !proj);
                assert_int_equal(pc_map_inverse(&f, &fi), PC_OK);
                assert_int_equal(pc_map_is_affine(&fi), !proj);
                assert_int_equal(pc_map_compose(&f, &fi, &h), PC_OK);
                is_identity(&h, n, 1e-12);
                if (!proj) assert_true(pc_map_is_affine(&h));
                assert_int_equal(pc_map_compose(&fi, &f, &h), PC_OK);
                is_identity(&h, n, 1e-12);
                /* (f o g)(x) = f(g(x)) with g another random map */
                pc_map g;
                for (int i = 0; i < (n + 1) * (n + 1); i++) a[i] += 0.1 * rnd();
                a[n * (n + 1) + n] = 1;
                assert_int_equal(pc_map_from_matrix(&g, n, n, a, 0), PC_OK);
                assert_int_equal(pc_map_compose(&f, &g, &h), PC_OK);
                double x[PC_MAXDIM + 1], gx[PC_MAXDIM + 1], fgx[PC_MAXDIM + 1], hx[PC_MAXDIM + 1];
                for (int i = 0; i < n; i++) x[i] = 0.2 * rnd();
                x[n] = 1;
                if (pc_map_image(&g, x, gx) != PC_OK) continue;
                if (pc_map_image(&f, gx, fgx) != PC_OK) continue;
                assert_int_equal(pc_map_image(&h, x, hx), PC_OK);
                for (int i = 0; i <= n; i++) NEARE(hx[i], fgx[i], 1e-11);
            }
        }
    }
    /* composition order with named maps: scale by 2 after a shift by (1, 0) */
    pc_map s, t, h;
    double k[2] = {2, 2}, v[2] = {1, 0}, x[2] = {1, 1}, r[2];
    pc_map_scale(&s, 2, k, NULL);
    pc_map_translate(&t, 2, v);
    assert_int_equal(pc_map_compose(&s, &t, &h), PC_OK);
    apply_pt(&h, x, r);
    NEAR(r[0], 4); NEAR(r[1], 2);
    assert_int_equal(pc_map_compose(&t, &s, &h), PC_OK);
    apply_pt(&h, x, r);
    NEAR(r[0], 3); NEAR(r[1], 2);
    /* identity */
    pc_map_identity(&h, 3);
    is_identity(&h, 3, 0);
    assert_true(pc_map_is_affine(&h));
}

/* Projections: the orthographic ones and the axonometric ones after the embedding back of
 * the picture plane: P o E = id, so P o E o P = P and E o P is idempotent. */
static void test_projections_idempotent(void **state) {
    (void)state;
    const char axes[3] = {'z', 'y', 'x'};
    for (int a = 0; a < 4; a++) {
        pc_map p, e, pe, pep, ep, epep;
        if (a < 3) assert_int_equal(pc_map_orthographic(&p, axes[a]), PC_OK);
        else pc_map_axonometric(&p, 0.4, -1.1);
        /* E: the picture plane back into space, along the rows of P (orthonormal) */
        double o[3] = {0, 0, 0}, ax[6];
        for (int j = 0; j < 3; j++) { ax[j] = PC_MAP_AT(&p, 0, j); ax[3 + j] = PC_MAP_AT(&p, 1, j); }
        assert_int_equal(pc_map_frame(&e, 3, 2, o, ax), PC_OK);
        assert_int_equal(pc_map_compose(&p, &e, &pe), PC_OK);
        is_identity(&pe, 2, 1e-15);
        assert_int_equal(pc_map_compose(&pe, &p, &pep), PC_OK);
        assert_int_equal(pc_map_compose(&e, &p, &ep), PC_OK);
        assert_int_equal(pc_map_compose(&ep, &ep, &epep), PC_OK);
        for (int i = 0; i <= 2; i++)
            for (int j = 0; j <= 3; j++) NEARE(PC_MAP_AT(&pep, i, j), PC_MAP_AT(&p, i, j), 1e-15);
        for (int i = 0; i <= 3; i++)
            for (int j = 0; j <= 3; j++) NEARE(PC_MAP_AT(&epep, i, j), PC_MAP_AT(&ep, i, j), 1e-15);
    }
    /* the textbook's Pz = diag(1, 1, 0, 1) is E o P for 'z' */
    pc_map p, e, ep;
    double o[3] = {0, 0, 0}, ax[6] = {1, 0, 0, 0, 1, 0};
    pc_map_orthographic(&p, 'z');
    pc_map_frame(&e, 3, 2, o, ax);
    pc_map_compose(&e, &p, &ep);
    const double pz[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
    row_matrix_is(&ep, pz, 0);
    /* 'y' keeps (x, z), 'x' keeps (y, z) */
    double X[3] = {1, 2, 3}, y[2];
    pc_map_orthographic(&p, 'y'); apply_pt(&p, X, y); NEAR(y[0], 1); NEAR(y[1], 3);
    pc_map_orthographic(&p, 'x'); apply_pt(&p, X, y); NEAR(y[0], 2); NEAR(y[1], 3);
}

/* Buimov §1.7: the 2-D matrices of chapter 1 in the row convention. */
static void test_textbook_plane(void **state) {
    (void)state;
    pc_map f, g, h;
    /* §1.7.1: R(90°) = [[0, 1], [-1, 0]]; (3, -1) -> (1, 3) */
    pc_map_rotate2(&f, PI / 2, NULL);
    const double r90[9] = {0, 1, 0, -1, 0, 0, 0, 0, 1};
    row_matrix_is(&f, r90, 1e-15);
    double x[2] = {3, -1}, y[2];
    apply_pt(&f, x, y); NEAR(y[0], 1); NEAR(y[1], 3);
    /* §1.7.8 and digest 9.2 item 11: rotation about (2, 3): the third row of T */
    const double angles[4] = {PI / 2, PI, 3 * PI / 2, PI / 6};
    const double row3[4][2] = {{5, 1}, {4, 6}, {-1, 5}, {1.767949, -0.598076}};
    double c[2] = {2, 3};
    for (int i = 0; i < 4; i++) {
        pc_map_rotate2(&f, angles[i], c);
        double a[9];
        pc_map_to_matrix(&f, 1, a);
        NEAR6(a[6], row3[i][0]); NEAR6(a[7], row3[i][1]); assert_true(a[8] == 1);
        /* = Tr(-m, -n) R(theta) Tr(m, n), composed left to right in the textbook */
        double mc[2] = {-2, -3};
        pc_map t1, r, t2, rt;
        pc_map_translate(&t1, 2, mc);
        pc_map_rotate2(&r, angles[i], NULL);
        pc_map_translate(&t2, 2, c);
        pc_map_compose(&r, &t1, &rt);
        pc_map_compose(&t2, &rt, &h);
        for (int k = 0; k < 9; k++) NEARE(h.m[k], f.m[k], 1e-15);
    }
    /* §1.7.3 (corrected): T1 = R(90°), T2 = reflection in x = 0; T1 T2 (T1 first) sends
     * (5, 7) to (7, 5), T2 T1 to (-7, -5) (the book prints [-x -y]: an erratum) */
    double o[2] = {0, 0}, nx[2] = {1, 0}, p57[2] = {5, 7};
    pc_map_rotate2(&f, PI / 2, NULL);
    assert_int_equal(pc_map_reflect(&g, 2, o, nx), PC_OK);
    pc_map_compose(&g, &f, &h);
    const double t1t2[9] = {0, 1, 0, 1, 0, 0, 0, 0, 1};
    row_matrix_is(&h, t1t2, 1e-15);
    apply_pt(&h, p57, y); NEAR(y[0], 7); NEAR(y[1], 5);
    pc_map_compose(&f, &g, &h);
    apply_pt(&h, p57, y); NEAR(y[0], -7); NEAR(y[1], -5);
    /* §1.7.2: reflection in y = x: (8, 1) -> (1, 8) */
    double dn[2] = {1, -1}, p81[2] = {8, 1};
    pc_map_reflect(&f, 2, o, dn);
    apply_pt(&f, p81, y); NEAR(y[0], 1); NEAR(y[1], 8);
    /* §1.7.6, Fig 1.16: [x y 1] [[1,0,1],[0,1,1],[0,0,1]]: (1, 3) -> (1/5, 3/5), (4, 1) -> (2/3, 1/6) */
    const double pq[9] = {1, 0, 1, 0, 1, 1, 0, 0, 1};
    assert_int_equal(pc_map_from_matrix(&f, 2, 2, pq, 1), PC_OK);
    assert_false(pc_map_is_affine(&f));
    double a1[2] = {1, 3}, b1[2] = {4, 1};
    apply_pt(&f, a1, y); NEAR(y[0], 0.2); NEAR(y[1], 0.6);
    apply_pt(&f, b1, y); NEAR(y[0], 2.0 / 3); NEAR(y[1], 1.0 / 6);
    /* §1.7.6: the overall scale s = 2: x* = x/2, an affine map */
    const double s2[9] = {1, 0, 0, 0, 1, 0, 0, 0, 2};
    assert_int_equal(pc_map_from_matrix(&f, 2, 2, s2, 1), PC_OK);
    assert_true(pc_map_is_affine(&f));
    double p64[2] = {6, 4};
    apply_pt(&f, p64, y); NEAR(y[0], 3); NEAR(y[1], 2);
    /* §1.4, Fig 1.7: T = [[1, 2], [3, 1]]: A(0, 1) -> (3, 1), B(2, 3) -> (11, 7) */
    const double t17[9] = {1, 2, 0, 3, 1, 0, 0, 0, 1};
    pc_map_from_matrix(&f, 2, 2, t17, 1);
    double pa[2] = {0, 1}, pb[2] = {2, 3};
    apply_pt(&f, pa, y); NEAR(y[0], 3); NEAR(y[1], 1);
    apply_pt(&f, pb, y); NEAR(y[0], 11); NEAR(y[1], 7);
}

/* Buimov §2.3-§2.7: rotations about the axes and about an arbitrary axis, shear. */
static void test_textbook_space(void **state) {
    (void)state;
    pc_map f;
    double o[3] = {0, 0, 0};
    double ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0}, ez[3] = {0, 0, 1};
    const double rx[16] = {1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1};
    const double ry[16] = {0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1};
    const double rz[16] = {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    assert_int_equal(pc_map_rotate3(&f, o, ex, PI / 2), PC_OK); row_matrix_is(&f, rx, 1e-15);
    assert_int_equal(pc_map_rotate3(&f, o, ey, PI / 2), PC_OK); row_matrix_is(&f, ry, 1e-15);
    assert_int_equal(pc_map_rotate3(&f, o, ez, PI / 2), PC_OK); row_matrix_is(&f, rz, 1e-15);
    /* n = (1, 1, 1)/sqrt 3, 120°: the cyclic permutation x -> y -> z (the direction need not
     * be unit) */
    double d111[3] = {1, 1, 1};
    const double cyc[16] = {0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 0, 0, 1};
    assert_int_equal(pc_map_rotate3(&f, o, d111, 2 * PI / 3), PC_OK);
    row_matrix_is(&f, cyc, 1e-15);
    /* the axis along z through (1, 1, 0), 90°: (2, 1, 5) -> (1, 2, 5) */
    double a[3] = {1, 1, 0}, x[3] = {2, 1, 5}, y[3];
    assert_int_equal(pc_map_rotate3(&f, a, ez, PI / 2), PC_OK);
    apply_pt(&f, x, y);
    NEAR(y[0], 1); NEAR(y[1], 2); NEAR(y[2], 5);
    /* Rz(theta) for any theta, as the book's example n = (0, 0, 1) */
    pc_map_rotate3(&f, o, ez, 0.7);
    const double rz7[16] = {cos(0.7), sin(0.7), 0, 0, -sin(0.7), cos(0.7), 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    row_matrix_is(&f, rz7, 1e-15);
    /* §2.2: shear x += d y: [x y z 1] -> [x + d y, y, z, 1] */
    assert_int_equal(pc_map_shear(&f, 3, 0, 1, 0.5), PC_OK);
    apply_pt(&f, x, y);
    NEAR(y[0], 2.5); NEAR(y[1], 1); NEAR(y[2], 5);
    /* §2.4: reflection in xOy is diag(1, 1, -1, 1) */
    const double mz[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1};
    pc_map_reflect(&f, 3, o, ez);
    row_matrix_is(&f, mz, 0);
    /* §2.1 local scaling about a centre: the centre is fixed */
    double k[3] = {2, 3, 4}, c[3] = {1, 1, 1};
    pc_map_scale(&f, 3, k, c);
    apply_pt(&f, c, y);
    NEAR(y[0], 1); NEAR(y[1], 1); NEAR(y[2], 1);
    apply_pt(&f, x, y);
    NEAR(y[0], 3); NEAR(y[1], 1); NEAR(y[2], 17);
}

/* Buimov §2.8.2-§2.8.4 and the oblique projections. */
static void test_textbook_projections(void **state) {
    (void)state;
    pc_map f, r, p;
    double o[3] = {0, 0, 0}, ex[3] = {1, 0, 0}, y[2];
    /* §2.8.2, the top view with the corrected signs: T = Rx(90°) Pz, [x y z 1] -> [x, -z] */
    pc_map_rotate3(&r, o, ex, PI / 2);
    pc_map_orthographic(&p, 'z');
    pc_map_compose(&p, &r, &f);
    const double top[12] = {1, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, 1};
    row_matrix_is(&f, top, 1e-15);
    const double cube[8][3] = {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {0, 1, 1},
                               {1, 0, 0}, {1, 0, 1}, {1, 1, 0}, {1, 1, 1}};   /* A E B F D H C G */
    const double img[8][2] = {{0, 0}, {0, -1}, {0, 0}, {0, -1}, {1, 0}, {1, -1}, {1, 0}, {1, -1}};
    for (int i = 0; i < 8; i++) {
        apply_pt(&f, cube[i], y);
        NEAR(y[0], img[i][0]); NEAR(y[1], img[i][1]);
    }
    /* §2.8.3: dimetric with f_z = 1/2 */
    assert_int_equal(pc_map_dimetric(&f, 0.5), PC_OK);
    const double dim[12] = {0.925820, 0.133631, 0, 0, 0.935414, 0, 0.377964, -0.327327, 0, 0, 0, 1};
    row_matrix_is(&f, dim, 5e-7);
    double fore[3];
    for (int j = 0; j < 3; j++) fore[j] = hypot(PC_MAP_AT(&f, 0, j), PC_MAP_AT(&f, 1, j));
    NEAR6(fore[0], 0.935414); NEAR6(fore[1], 0.935414); NEAR(fore[2], 0.5);
    /* the angles: theta = 20.704811°, phi = 22.207654° give the same map */
    pc_map_axonometric(&p, 22.207654 * PI / 180, 20.704811 * PI / 180);
    for (int i = 0; i < 12; i++) NEARE(p.m[i], f.m[i], 1e-7);
    /* §2.8.4: isometric, all foreshortenings sqrt(2/3), the x axis at 30°, z at -30° */
    pc_map_isometric(&f);
    const double iso[12] = {0.707107, 0.408248, 0, 0, 0.816497, 0, 0.707107, -0.408248, 0, 0, 0, 1};
    row_matrix_is(&f, iso, 5e-7);
    for (int j = 0; j < 3; j++) NEAR(hypot(PC_MAP_AT(&f, 0, j), PC_MAP_AT(&f, 1, j)), sqrt(2.0 / 3));
    NEAR(atan2(PC_MAP_AT(&f, 1, 0), PC_MAP_AT(&f, 0, 0)), PI / 6);
    NEAR(atan2(PC_MAP_AT(&f, 1, 2), PC_MAP_AT(&f, 0, 2)), -PI / 6);
    /* isometric = dimetric(sqrt(2/3)) */
    assert_int_equal(pc_map_dimetric(&p, sqrt(2.0 / 3)), PC_OK);
    for (int i = 0; i < 12; i++) NEARE(p.m[i], f.m[i], 1e-12);
    /* oblique (digest §10): the z unit goes to k (cos alpha, sin alpha); cavalier, cabinet */
    double ez[3] = {0, 0, 1}, x[3] = {1, 2, 3};
    pc_map_oblique(&f, 1, PI / 4);
    apply_pt(&f, ez, y); NEAR(y[0], sqrt(0.5)); NEAR(y[1], sqrt(0.5));
    pc_map_oblique(&f, 0.5, PI / 6);
    apply_pt(&f, x, y); NEAR(y[0], 1 + 1.5 * cos(PI / 6)); NEAR(y[1], 2 + 1.5 * 0.5);
}

/* §2.8.5, digest 9.2 items 17-18: perspectives, points at infinity and vanishing points. */
static void test_perspective(void **state) {
    (void)state;
    /* the two-point example: Ry(60°), then the one-point transform with r = 1/k, k = 2 */
    pc_map ry, pr, f;
    double o[3] = {0, 0, 0}, ey[3] = {0, 1, 0};
    pc_map_rotate3(&ry, o, ey, PI / 3);
    const double one_point[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0.5, 0, 0, 0, 1};
    assert_int_equal(pc_map_from_matrix(&pr, 3, 3, one_point, 1), PC_OK);
    assert_false(pc_map_is_affine(&pr));
    assert_int_equal(pc_map_compose(&pr, &ry, &f), PC_OK);
    const double book[16] = {0.5, 0, -0.866025, -0.433013, 0, 1, 0, 0,
                             0.866025, 0, 0.5, 0.25, 0, 0, 0, 1};
    row_matrix_is(&f, book, 5e-7);
    /* the images of the axis directions (weight 0) */
    double vx[4] = {1, 0, 0, 0}, vy[4] = {0, 1, 0, 0}, vz[4] = {0, 0, 1, 0}, out[4];
    assert_int_equal(pc_map_image(&f, vx, out), PC_OK);
    NEAR6(out[0], -1.154701); NEAR(out[1], 0); NEAR(out[2], 2); assert_true(out[3] == 1);
    NEAR(out[0], -2 / tan(PI / 3));                       /* -k cot theta */
    assert_int_equal(pc_map_image(&f, vz, out), PC_OK);
    NEAR6(out[0], 3.464102); NEAR(out[1], 0); NEAR(out[2], 2); assert_true(out[3] == 1);
    NEAR(out[0], 2 * tan(PI / 3));                        /* k tan theta */
    assert_int_equal(pc_map_image(&f, vy, out), PC_OK);   /* y stays at infinity */
    assert_true(out[3] == 0); NEAR(out[1], 1);
    /* item 17: one-point r = 0.5 maps (1, 1, 1) to (2/3, 2/3, 2/3); three-point p = q = r = .5
     * maps it to (0.4, 0.4, 0.4) */
    double p111[3] = {1, 1, 1}, y[3];
    apply_pt(&pr, p111, y); NEAR(y[0], 2.0 / 3); NEAR(y[1], 2.0 / 3); NEAR(y[2], 2.0 / 3);
    const double three[16] = {1, 0, 0, 0.5, 0, 1, 0, 0.5, 0, 0, 1, 0.5, 0, 0, 0, 1};
    pc_map_from_matrix(&pr, 3, 3, three, 1);
    apply_pt(&pr, p111, y); NEAR(y[0], 0.4); NEAR(y[1], 0.4); NEAR(y[2], 0.4);

    /* pc_map_perspective with the textbook's centre (0, 0, -2) onto z = 0, y up: the book's
     * picture mirrored in its y axis (convention 8), so the vanishing points change sign */
    pc_map c, cr;
    double eye[3] = {0, 0, -2}, up[3] = {0, 1, 0};
    assert_int_equal(pc_map_perspective(&c, eye, o, up), PC_OK);
    assert_int_equal(pc_map_compose(&c, &ry, &cr), PC_OK);
    double v2[3];
    assert_int_equal(pc_map_image(&cr, vx, v2), PC_OK);
    NEAR6(v2[0], 1.154701); NEAR(v2[1], 0); assert_true(v2[2] == 1);
    assert_int_equal(pc_map_image(&cr, vz, v2), PC_OK);
    NEAR6(v2[0], -3.464102); NEAR(v2[1], 0);
    assert_int_equal(pc_map_image(&cr, vy, v2), PC_OK);
    assert_true(v2[2] == 0);
    /* ... and the picture of a point: x* = -x k/(z + k), y* = y k/(z + k) */
    double q[3] = {1, 2, 3};
    apply_pt(&c, q, y);
    NEAR(y[0], -1 * 2.0 / 5); NEAR(y[1], 2 * 2.0 / 5);
    /* a vanishing point is where the pictures of far points of a line go */
    double d[4] = {0.5, -0.25, 0.8, 0}, vd[3], far[3], yf[2];
    assert_int_equal(pc_map_image(&c, d, vd), PC_OK);
    for (int i = 0; i < 3; i++) far[i] = q[i] + 1e9 * d[i];
    apply_pt(&c, far, yf);
    NEARE(yf[0], vd[0], 1e-8); NEARE(yf[1], vd[1], 1e-8);
    NEAR(vd[0], -2 * 0.5 / 0.8); NEAR(vd[1], 2 * -0.25 / 0.8);
    /* seen from the other side, eye (0, 0, 2) towards the origin: x to the right is +x */
    double eye2[3] = {0, 0, 2};
    pc_map_perspective(&c, eye2, o, up);
    apply_pt(&c, q, y);
    NEAR(y[0], -2.0); NEAR(y[1], -4.0);                    /* behind the eye: k/(k - z) = -2 */
    double q2[3] = {1, 2, -2};
    apply_pt(&c, q2, y);
    NEAR(y[0], 0.5); NEAR(y[1], 1.0);
    /* the picture plane is kept 1:1 and p0 is the origin of the picture */
    double eye3[3] = {5, -4, 3}, p0[3] = {1, 1, 1}, pp[3];
    assert_int_equal(pc_map_perspective(&c, eye3, p0, NULL), PC_OK);
    apply_pt(&c, p0, y); NEAR(y[0], 0); NEAR(y[1], 0);
    /* a point of the picture plane at distance 1 straight "up" (z, made perpendicular) */
    double n[3] = {-4, 5, -2}, nn = sqrt(45.0);
    double up3[3] = {0, 0, 1}, un = (n[2] / nn);
    for (int i = 0; i < 3; i++) pp[i] = up3[i] - un * n[i] / nn;
    double pl = sqrt(pp[0] * pp[0] + pp[1] * pp[1] + pp[2] * pp[2]);
    for (int i = 0; i < 3; i++) pp[i] = p0[i] + pp[i] / pl;
    apply_pt(&c, pp, y); NEAR(y[0], 0); NEAR(y[1], 1);
    /* the eye has no image; a point of the eye's plane goes to infinity */
    double in[4] = {5, -4, 3, 1};
    assert_int_equal(pc_map_image(&c, in, out), PC_EPOLE);
    double side[4] = {5 + 5, -4 + 4, 3, 1};              /* eye + (5, 4, 0), n.(5, 4, 0) = 0 */
    assert_int_equal(pc_map_image(&c, side, out), PC_IMPROPER);
    assert_true(out[2] == 0);
    /* errors */
    assert_int_equal(pc_map_perspective(&c, p0, p0, NULL), PC_ECOINCIDENT);
    double zeye[3] = {1, 1, 5}, zero[3] = {0, 0, 0};
    assert_int_equal(pc_map_perspective(&c, zeye, p0, NULL), PC_ECOLLINEAR);
    assert_int_equal(pc_map_perspective(&c, eye3, p0, zero), PC_EZERO);
    double bad[3] = {NAN, 0, 0};
    assert_int_equal(pc_map_perspective(&c, bad, p0, NULL), PC_ENONFINITE);
}

/* from_matrix and to_matrix in both conventions; the row form is the transpose. */
static void test_matrix_round_trip(void **state) {
    (void)state;
    double a[12], b[12], t[12];
    for (int i = 0; i < 12; i++) a[i] = rnd();
    a[11] = 1;                                  /* a 3-D -> 2-D projective map, corner 1 */
    pc_map f, g;
    assert_int_equal(pc_map_from_matrix(&f, 3, 2, a, 0), PC_OK);
    assert_int_equal(f.nin, 3); assert_int_equal(f.nout, 2);
    pc_map_to_matrix(&f, 0, b);
    assert_memory_equal(a, b, sizeof a);
    pc_map_to_matrix(&f, 1, t);                 /* 4 rows of 3 */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) assert_true(t[j * 3 + i] == a[i * 4 + j]);
    assert_int_equal(pc_map_from_matrix(&g, 3, 2, t, 1), PC_OK);
    assert_memory_equal(f.m, g.m, sizeof(double) * 12);
    pc_map_to_matrix(&g, 1, b);
    assert_memory_equal(t, b, sizeof t);
    /* a projective matrix with corner 3 is kept as it is */
    a[11] = 3;
    pc_map_from_matrix(&f, 3, 2, a, 0);
    pc_map_to_matrix(&f, 0, b);
    assert_memory_equal(a, b, sizeof a);
}

/* Stepanov ex. 33: the map by four image points of the Cartesian simplex O E1 E2 E3 equals
 * the frame map; it has no inverse (3-D -> 2-D). */
static void test_oblique_frame(void **state) {
    (void)state;
    double cr = 150, ck = 0.3, cu = -PI / 3;
    double C[8] = {320, 240,
                   320 + cr * cos(cu), 240 - cr * ck * sin(cu),
                   320 + cr * cos(cu + PI / 2), 240 - cr * ck * sin(cu + PI / 2),
                   320, 240 - cr};
    double E[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    pc_map f, g, inv;
    assert_int_equal(pc_map_affine_points(&f, 3, 2, E, C), PC_OK);
    double axes[6];
    for (int i = 0; i < 3; i++)
        for (int d = 0; d < 2; d++) axes[2 * i + d] = C[2 * (i + 1) + d] - C[d];
    assert_int_equal(pc_map_frame(&g, 2, 3, C, axes), PC_OK);
    double X[3] = {1, 0, 1}, y1[2], y2[2];
    apply_pt(&f, X, y1);
    apply_pt(&g, X, y2);
    NEAR(y1[0], y2[0]); NEAR(y1[1], y2[1]);
    NEAR(y1[0], 320 + 75);
    NEAR(y1[1], 240 + 150 * 0.3 * sin(PI / 3) - 150);
    assert_true(fabs(y1[0] - 395) < 1 && fabs(y1[1] - 129) < 1);
    assert_int_equal(pc_map_inverse(&f, &inv), PC_EDIM);
}

static void test_errors(void **state) {
    (void)state;
    pc_map f, g, h;
    double a[25] = {0};
    /* bad sizes, NaN, the zero matrix */
    assert_int_equal(pc_map_from_matrix(&f, 0, 2, a, 0), PC_EDIM);
    assert_int_equal(pc_map_from_matrix(&f, 2, PC_MAXDIM + 1, a, 0), PC_EDIM);
    assert_int_equal(pc_map_from_matrix(&f, 2, 2, a, 0), PC_ESINGULAR);
    a[0] = 1; a[4] = 1; a[8] = 1; a[5] = NAN;
    assert_int_equal(pc_map_from_matrix(&f, 2, 2, a, 0), PC_ENONFINITE);
    a[5] = INFINITY;
    assert_int_equal(pc_map_from_matrix(&f, 2, 2, a, 1), PC_ENONFINITE);
    /* singular: an affine frame with dependent axes, a projective matrix of rank 2 */
    double o[2] = {0, 0}, dep[4] = {1, 2, 2, 4};
    assert_int_equal(pc_map_frame(&g, 2, 2, o, dep), PC_OK);
    assert_int_equal(pc_map_inverse(&g, &h), PC_ESINGULAR);
    const double rank2[9] = {1, 0, 0, 0, 1, 0, 1, 1, 0};
    assert_int_equal(pc_map_from_matrix(&f, 2, 2, rank2, 0), PC_OK);
    assert_int_equal(pc_map_inverse(&f, &h), PC_ESINGULAR);
    /* non-square, mismatched composition */
    pc_map_orthographic(&f, 'z');
    assert_int_equal(pc_map_inverse(&f, &h), PC_EDIM);
    assert_int_equal(pc_map_compose(&f, &f, &h), PC_EDIM);
    assert_int_equal(pc_map_frame(&f, 0, 2, o, dep), PC_EDIM);
    /* domains */
    assert_int_equal(pc_map_orthographic(&f, 'w'), PC_EDOMAIN);
    assert_int_equal(pc_map_dimetric(&f, 0), PC_EDOMAIN);
    assert_int_equal(pc_map_dimetric(&f, 1), PC_EDOMAIN);
    assert_int_equal(pc_map_dimetric(&f, NAN), PC_EDOMAIN);
    assert_int_equal(pc_map_shear(&f, 3, 1, 1, 2), PC_EDOMAIN);
    assert_int_equal(pc_map_shear(&f, 3, 0, 3, 2), PC_EDOMAIN);
    assert_int_equal(pc_map_shear(&f, 3, 0, 1, NAN), PC_ENONFINITE);
    double z3[3] = {0, 0, 0}, e1[3] = {1, 0, 0}, n3[3] = {NAN, 0, 0};
    assert_int_equal(pc_map_rotate3(&f, z3, z3, 1), PC_EZERO);
    assert_int_equal(pc_map_rotate3(&f, z3, e1, NAN), PC_ENONFINITE);
    assert_int_equal(pc_map_rotate3(&f, n3, e1, 1), PC_ENONFINITE);
    assert_int_equal(pc_map_reflect(&f, 3, z3, z3), PC_EZERO);
    assert_int_equal(pc_map_reflect(&f, 3, n3, e1), PC_ENONFINITE);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_affine_points),
        cmocka_unit_test(test_compose_inverse),
        cmocka_unit_test(test_projections_idempotent),
        cmocka_unit_test(test_textbook_plane),
        cmocka_unit_test(test_textbook_space),
        cmocka_unit_test(test_textbook_projections),
        cmocka_unit_test(test_perspective),
        cmocka_unit_test(test_matrix_round_trip),
        cmocka_unit_test(test_oblique_frame),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
