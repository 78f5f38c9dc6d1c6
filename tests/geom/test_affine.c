/* Affine maps: by point correspondences (change of simplex, §1.2.2), frames, the oblique
 * projection of Stepanov's examples 32-34, composition and inverse. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include "affine.h"

#define NEARE(a, b, e) assert_true(fabs((double)(a) - (double)(b)) <= (e) * (1 + fabs((double)(b))))
#define NEAR(a, b) NEARE(a, b, 1e-12)

static void apply_pt(const pc_affine *f, const double *x, double *y) {
    double in[PC_MAXDIM + 1], out[PC_MAXDIM + 1];
    for (int i = 0; i < f->nin; i++) in[i] = x[i];
    in[f->nin] = 1;
    pc_affine_apply(f, in, out);
    assert_true(out[f->nout] == 1);
    for (int i = 0; i < f->nout; i++) y[i] = out[i];
}

static void test_from_points_2d(void **state) {
    (void)state;
    double src[6] = {0, 0, 1, 0, 0, 1}, dst[6] = {2, 1, 4, 2, 1, 3};
    pc_affine f;
    assert_int_equal(pc_affine_from_points(&f, 2, 2, src, dst), PC_OK);
    double y[2];
    for (int i = 0; i < 3; i++) {                 /* the pairs map onto each other */
        apply_pt(&f, src + 2 * i, y);
        NEAR(y[0], dst[2 * i]); NEAR(y[1], dst[2 * i + 1]);
    }
    /* M = [[2, -1], [1, 2]], t = (2, 1) */
    NEAR(PC_AFFINE_AT(&f, 0, 0), 2); NEAR(PC_AFFINE_AT(&f, 0, 1), -1); NEAR(PC_AFFINE_AT(&f, 0, 2), 2);
    NEAR(PC_AFFINE_AT(&f, 1, 0), 1); NEAR(PC_AFFINE_AT(&f, 1, 1), 2); NEAR(PC_AFFINE_AT(&f, 1, 2), 1);
    /* a vector (weight 0) ignores the translation; weights are kept */
    double v[3] = {1, 1, 0}, out[3];
    pc_affine_apply(&f, v, out);
    NEAR(out[0], 1); NEAR(out[1], 3); NEAR(out[2], 0);
    double w[3] = {2, 0, 2};                      /* 2*P(1, 0) */
    pc_affine_apply(&f, w, out);
    NEAR(out[0], 8); NEAR(out[1], 4); NEAR(out[2], 2);
    /* an affine map keeps simple ratios: the midpoint goes to the midpoint */
    double m[2] = {0.5, 0.5}, fm[2];
    apply_pt(&f, m, fm);
    NEAR(fm[0], (4 + 1) / 2.0); NEAR(fm[1], (2 + 3) / 2.0);
    /* general source triangle */
    double s2[6] = {1, 1, 5, 2, 2, 4}, d2[6] = {0, 0, 3, -1, 7, 7};
    assert_int_equal(pc_affine_from_points(&f, 2, 2, s2, d2), PC_OK);
    for (int i = 0; i < 3; i++) {
        apply_pt(&f, s2 + 2 * i, y);
        NEARE(y[0], d2[2 * i], 1e-12); NEARE(y[1], d2[2 * i + 1], 1e-12);
    }
    double flat[6] = {0, 0, 1, 1, 2, 2};
    assert_int_equal(pc_affine_from_points(&f, 2, 2, flat, dst), PC_ECOLLINEAR);
}

/* f o f^-1 = id, f^-1 o f = id; composition order: (f o g)(x) = f(g(x)). */
static void test_inverse_compose(void **state) {
    (void)state;
    double src[12] = {1, 0, 0,  2, 1, 0,  1, 2, 1,  0, 0, 3};
    double dst[12] = {0, 0, 0,  1, 0, 0,  0, 1, 0,  0.5, 0.5, 1};
    pc_affine f, g, fi, h;
    assert_int_equal(pc_affine_from_points(&f, 3, 3, src, dst), PC_OK);
    assert_int_equal(pc_affine_inverse(&f, &fi), PC_OK);
    assert_int_equal(pc_affine_compose(&f, &fi, &h), PC_OK);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j <= 3; j++) NEARE(PC_AFFINE_AT(&h, i, j), (i == j) ? 1.0 : 0.0, 1e-12);
    assert_int_equal(pc_affine_compose(&fi, &f, &h), PC_OK);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j <= 3; j++) NEARE(PC_AFFINE_AT(&h, i, j), (i == j) ? 1.0 : 0.0, 1e-12);
    /* the inverse maps the images back */
    double y[3];
    apply_pt(&fi, dst + 9, y);
    NEAR(y[0], 0); NEAR(y[1], 0); NEAR(y[2], 3);
    /* composition order */
    double o[2] = {0, 0}, ax[4] = {2, 0, 0, 2};     /* scale by 2 */
    assert_int_equal(pc_affine_frame(&g, 2, 2, o, ax), PC_OK);
    double o2[2] = {1, 0}, ax2[4] = {1, 0, 0, 1};   /* shift by (1, 0) */
    pc_affine t;
    assert_int_equal(pc_affine_frame(&t, 2, 2, o2, ax2), PC_OK);
    assert_int_equal(pc_affine_compose(&g, &t, &h), PC_OK);   /* scale after shift */
    double x[2] = {1, 1}, r[2];
    apply_pt(&h, x, r);
    NEAR(r[0], 4); NEAR(r[1], 2);
    assert_int_equal(pc_affine_compose(&f, &g, &h), PC_EDIM);  /* 2-D into 3-D input */
    /* identity */
    pc_affine_identity(&h, 3);
    apply_pt(&h, src + 3, y);
    NEAR(y[0], 2); NEAR(y[1], 1); NEAR(y[2], 0);
}

/* Stepanov ex. 33: screen = C0 + x (C1 - C0) + y (C2 - C0) + z (C3 - C0), with C0 = (320,240),
 * cr0 = 150, ck0 = .3, cu0 = -π/3.  The map by four image points of the Cartesian simplex
 * O E1 E2 E3 (§2.6) equals the frame map; a 3-D -> 2-D map has no inverse. */
static void test_oblique(void **state) {
    (void)state;
    double cr = 150, ck = 0.3, cu = -M_PI / 3;
    double C[8] = {320, 240,
                   320 + cr * cos(cu), 240 - cr * ck * sin(cu),
                   320 + cr * cos(cu + M_PI / 2), 240 - cr * ck * sin(cu + M_PI / 2),
                   320, 240 - cr};
    double E[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    pc_affine f, g, inv;
    assert_int_equal(pc_affine_from_points(&f, 3, 2, E, C), PC_OK);
    double axes[6];
    for (int i = 0; i < 3; i++)
        for (int d = 0; d < 2; d++) axes[2 * i + d] = C[2 * (i + 1) + d] - C[d];
    assert_int_equal(pc_affine_frame(&g, 2, 3, C, axes), PC_OK);
    double X[3] = {1, 0, 1}, y1[2], y2[2];          /* node 0 of ex. 33 */
    apply_pt(&f, X, y1);
    apply_pt(&g, X, y2);
    NEAR(y1[0], y2[0]); NEAR(y1[1], y2[1]);
    NEARE(y1[0], 320 + 75, 1e-12);                  /* cos(-π/3)·150 */
    NEARE(y1[1], 240 + 150 * 0.3 * sin(M_PI / 3) - 150, 1e-12);
    /* the article's picture: node (1,0,1) is near screen (395,129) */
    assert_true(fabs(y1[0] - 395) < 1 && fabs(y1[1] - 129) < 1);
    assert_int_equal(pc_affine_inverse(&f, &inv), PC_EDIM);
    /* a frame with dependent axes is a valid map but singular */
    double o[2] = {0, 0}, dep[4] = {1, 2, 2, 4};
    assert_int_equal(pc_affine_frame(&g, 2, 2, o, dep), PC_OK);
    assert_int_equal(pc_affine_inverse(&g, &inv), PC_ESINGULAR);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_from_points_2d),
        cmocka_unit_test(test_inverse_compose),
        cmocka_unit_test(test_oblique),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
