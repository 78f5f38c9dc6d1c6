/* Point equations compiled (expr.h): every operation's value and first and second derivatives
 * against central differences, closed forms (a circle's curvature 1/r, a parabola's at its
 * vertex), the monograph's test vectors (Konopatsky (2.11), (2.24), (2.138), (2.142), (4.28)),
 * common subexpressions computed once, register reuse, batches, non-finite results with their
 * parameter, weights (the membership condition), substitution, printing, and every error. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "expr.h"

#define NEAR(a, b, tol) do { double a_ = (a), b_ = (b); \
    if (!(fabs(a_ - b_) <= (tol))) fail_msg("%s = %.17g, want %.17g +- %g (line %d)", #a, a_, b_, (double)(tol), __LINE__); } while (0)

static pc_expr_pool *P;
static int st;

static int K(double c) { int e = pc_expr_const(P, c, &st); assert_true(e >= 0); return e; }
static int PT(double x, double y) { double h[3] = {x, y, 1}; int e = pc_expr_vconst(P, 2, h, &st); assert_true(e >= 0); return e; }
static int VC(double x, double y) { double h[3] = {x, y, 0}; int e = pc_expr_vconst(P, 2, h, &st); assert_true(e >= 0); return e; }
static int add(int a, int b) { int e = pc_expr_add(P, a, b, &st); assert_true(e >= 0); return e; }
static int sub(int a, int b) { int e = pc_expr_sub(P, a, b, &st); assert_true(e >= 0); return e; }
static int mul(int a, int b) { int e = pc_expr_mul(P, a, b, &st); assert_true(e >= 0); return e; }
static int dv(int a, int b) { int e = pc_expr_div(P, a, b, &st); assert_true(e >= 0); return e; }
static int pw(int a, double k) { int e = pc_expr_pow(P, a, K(k), &st); assert_true(e >= 0); return e; }
static int fn(pc_expr_op op, int a) { int e = pc_expr_fn(P, op, a, &st); assert_true(e >= 0); return e; }
static int bar(int t) { int e = pc_expr_bar(P, t, &st); assert_true(e >= 0); return e; }

static int setup(void **s) { (void)s; P = pc_expr_pool_new(); return P ? 0 : -1; }
static int teardown(void **s) { (void)s; pc_expr_pool_free(P); return 0; }

static pc_expr_prog *compile1(int e) {
    int t = pc_expr_param(P, "t", &st), k = pc_expr_param_index(P, t);
    pc_expr_prog *p = pc_expr_compile(P, e, 1, &k, &st);
    assert_non_null(p);
    return p;
}

/* value, d/dt, d2/dt2 of a scalar program at t */
static void jet(pc_expr_prog *p, double t, double *v) {
    assert_int_equal(pc_expr_eval(p, 1, &t, 2, v, NULL), PC_OK);
}

static double value_at(pc_expr_prog *p, double t) {
    double v;
    assert_int_equal(pc_expr_eval(p, 1, &t, 0, &v, NULL), PC_OK);
    return v;
}

/* --- every operation against central differences -------------------------------------------- */
static void check_fd(int e, double t0, double t1) {
    pc_expr_prog *p = compile1(e);
    for (int i = 0; i <= 10; i++) {
        double t = t0 + (t1 - t0) * i / 10, h = 1e-4, v[3];
        jet(p, t, v);
        double fp = value_at(p, t + h), fm = value_at(p, t - h), f0 = value_at(p, t);
        NEAR(v[0], f0, 0);
        double scale = 1 + fabs(v[1]) + fabs(v[2]);
        NEAR(v[1], (fp - fm) / (2 * h), 1e-6 * scale);
        NEAR(v[2], (fp - 2 * f0 + fm) / (h * h), 1e-4 * scale);
    }
    pc_expr_prog_free(p);
}

static void test_ops_fd(void **s) {
    (void)s;
    int t = pc_expr_param(P, "t", &st);
    int x = add(add(K(0.3), mul(K(0.5), t)), mul(K(0.2), pw(t, 2)));   /* 0.3 + 0.5t + 0.2t^2 */
    int y = sub(K(1.7), mul(t, fn(PC_EX_SIN, t)));                       /* 1.7 - t sin t */
    check_fd(add(x, y), 0.1, 1.2);
    check_fd(sub(x, y), 0.1, 1.2);
    check_fd(pc_expr_neg(P, x, &st), 0.1, 1.2);
    check_fd(mul(x, y), 0.1, 1.2);
    check_fd(dv(x, y), 0.1, 1.2);
    check_fd(pw(x, 3), 0.1, 1.2);
    check_fd(pw(x, -2), 0.1, 1.2);
    check_fd(pw(x, 2.5), 0.1, 1.2);
    check_fd(pc_expr_pow(P, x, y, &st), 0.1, 1.2);
    static const pc_expr_op fns[] = {PC_EX_SIN, PC_EX_COS, PC_EX_TAN, PC_EX_EXP, PC_EX_LOG,
                                     PC_EX_SQRT, PC_EX_ABS, PC_EX_RECIP};
    for (size_t i = 0; i < sizeof fns / sizeof *fns; i++) check_fd(fn(fns[i], x), 0.1, 1.2);
    check_fd(fn(PC_EX_ABS, sub(x, K(1))), 0.1, 0.6);          /* the negative side */
    pc_gfun g = {PC_G_SINE, {0, 0, 0, 0, 0}};
    check_fd(pc_expr_smooth(P, &g, x, &st), 0.1, 1.2);
    g.kind = PC_G_CUBIC;
    check_fd(pc_expr_smooth(P, &g, x, &st), 0.1, 1.2);
    g.kind = PC_G_HALF;
    assert_int_equal(pc_hspline_init(&g.h, 3, 2.5, 0.4), PC_OK);
    check_fd(pc_expr_smooth(P, &g, t, &st), 0.05, 0.35);      /* both sides of t0 = 0.4 */
    check_fd(pc_expr_smooth(P, &g, t, &st), 0.45, 0.95);
    /* value operations: each coordinate of the result */
    int A = PT(1, 2), B = PT(4, -1), u = VC(0.5, 2);
    int M = pc_expr_lerp(P, A, B, y, &st);
    int W = add(mul(u, x), mul(sub(B, A), y));                 /* a moving vector */
    int vals[] = {M, W, dv(W, x), pc_expr_unit(P, W, &st)};
    for (size_t i = 0; i < 4; i++)
        for (int k = 0; k <= 2; k++) check_fd(pc_expr_comp(P, vals[i], k, &st), 0.1, 1.2);
    check_fd(pc_expr_dot(P, W, dv(W, x), &st), 0.1, 1.2);
    check_fd(pc_expr_cross(P, W, u, &st), 0.1, 1.2);
}

/* closed forms: d/dt sin = cos, d2/dt2 exp(2t) = 4 exp(2t), (t^6)'' = 30 t^4 */
static void test_closed_forms(void **s) {
    (void)s;
    int t = pc_expr_param(P, "t", &st);
    pc_expr_prog *a = compile1(fn(PC_EX_SIN, t)), *b = compile1(fn(PC_EX_EXP, mul(K(2), t)));
    pc_expr_prog *c = compile1(pw(t, 6));
    for (double x = -2; x <= 2; x += 0.25) {
        double v[3];
        jet(a, x, v);
        NEAR(v[0], sin(x), 0); NEAR(v[1], cos(x), 1e-15); NEAR(v[2], -sin(x), 1e-15);
        jet(b, x, v);
        NEAR(v[2], 4 * exp(2 * x), 1e-13 * exp(2 * x));
        jet(c, x, v);
        NEAR(v[0], pow(x, 6), 1e-14 * (1 + pow(x, 6)));
        NEAR(v[1], 6 * pow(x, 5), 1e-13 * (1 + fabs(pow(x, 5))));
        NEAR(v[2], 30 * pow(x, 4), 1e-13 * (1 + pow(x, 4)));
    }
    pc_expr_prog_free(a); pc_expr_prog_free(b); pc_expr_prog_free(c);
}

/* --- curves ----------------------------------------------------------------------------------- */
/* (2.24) M = (A - C) cos f + (B - C) sin f + C with |CA| = |CB| = r at a right angle: a circle,
 * curvature 1/r everywhere (positive: counter-clockwise); tangent |M'| = r */
static void test_circle_curvature(void **s) {
    (void)s;
    int f = pc_expr_param(P, "t", &st);
    double r = 2.5;
    int C = PT(1, -1), A = PT(1 + r, -1), B = PT(1, -1 + r);
    int M = add(add(mul(sub(A, C), fn(PC_EX_COS, f)), mul(sub(B, C), fn(PC_EX_SIN, f))), C);
    pc_curve *c = pc_expr_curve(compile1(M), 0, 2 * M_PI, &st);
    assert_non_null(c);
    assert_true(c->closed);
    for (double t = 0; t < 6.3; t += 0.3) {
        double k, d[6];
        assert_int_equal(pc_curve_curvature(c, t, &k), PC_OK);
        NEAR(k, 1 / r, 1e-13);
        assert_int_equal(pc_curve_derivs(c, t, 2, d), PC_OK);
        NEAR(d[0], 1 + r * cos(t), 1e-14);
        NEAR(hypot(d[2], d[3]), r, 1e-13);
        NEAR(d[4], -r * cos(t), 1e-13);                    /* M'' = -(M - C) */
    }
    double len;
    assert_int_equal(pc_curve_length(c, 0, 2 * M_PI, 1e-12, &len), PC_OK);
    NEAR(len, 2 * M_PI * r, 1e-9);
    pc_curve_release(c);
}

/* The parabola y = x^2 as the point equation A t̄² + 2B t t̄ + C t² (§5.3), A(-1, 1), B(0, -1),
 * C(1, 1): at the vertex t = 1/2 the curvature is 2; elsewhere 2/(1 + 4x^2)^(3/2). */
static void test_parabola_vertex(void **s) {
    (void)s;
    int t = pc_expr_param(P, "t", &st), tb = bar(t);
    int A = PT(-1, 1), B = PT(0, -1), C = PT(1, 1);
    int M = add(add(mul(A, pw(tb, 2)), mul(mul(mul(K(2), B), t), tb)), mul(C, pw(t, 2)));
    pc_expr_prog *p = compile1(M);
    double lo = 0, hi = 1;
    assert_int_equal(pc_expr_prog_weight(p, &lo, &hi, NULL, NULL), PC_KIND_POINT);
    pc_curve *c = pc_expr_curve(p, 0, 1, &st);
    assert_non_null(c);
    double k;
    assert_int_equal(pc_curve_curvature(c, 0.5, &k), PC_OK);
    NEAR(k, 2, 1e-13);
    for (double u = 0; u <= 1; u += 0.125) {
        double x = 2 * u - 1, pt[2];
        assert_int_equal(pc_curve_curvature(c, u, &k), PC_OK);
        NEAR(k, 2 / pow(1 + 4 * x * x, 1.5), 1e-13);
        assert_int_equal(pc_curve_eval(c, u, pt), PC_OK);
        NEAR(pt[1], x * x, 1e-15);
    }
    pc_curve_release(c);
}

/* --- the monograph's vectors -------------------------------------------------------------------- */
static void eval2(int e, double t, double *xy) {
    pc_expr_prog *p = compile1(e);
    double h[3];
    assert_int_equal(pc_expr_eval(p, 1, &t, 0, h, NULL), PC_OK);
    NEAR(h[2], 1, 1e-12);
    xy[0] = h[0] / h[2];
    xy[1] = h[1] / h[2];
    pc_expr_prog_free(p);
}

/* (2.11) central angle, set E: C(0,0), A(4,0), B(0,2), a = 4, b = 2 */
static void test_ellipse_2_11(void **s) {
    (void)s;
    int f = pc_expr_param(P, "t", &st);
    int C = PT(0, 0), A = PT(4, 0), B = PT(0, 2);
    double a = 4, b = 2;
    int sf = fn(PC_EX_SIN, f), cf = fn(PC_EX_COS, f);
    int den = fn(PC_EX_SQRT, add(mul(K(a * a), pw(sf, 2)), mul(K(b * b), pw(cf, 2))));
    int M = add(add(mul(sub(A, C), dv(mul(K(b), cf), den)), mul(sub(B, C), dv(mul(K(a), sf), den))), C);
    static const double tv[][3] = {{0, 4, 0}, {M_PI / 6, 2.618615, 1.511858},
                                   {M_PI / 4, 1.788854, 1.788854}, {M_PI / 2, 0, 2},
                                   {2.0, -0.892253, 1.949608}};
    for (int i = 0; i < 5; i++) {
        double xy[2];
        eval2(M, tv[i][0], xy);
        NEAR(xy[0], tv[i][1], 1e-6);
        NEAR(xy[1], tv[i][2], 1e-6);
    }
}

/* (2.138) rotation of A about C by f toward B, C(0,0), A(4,0), B(1,3); and (2.142), the sinusoid
 * on a circle, C(0,0), A(1,0), B(0,1), m = 6 */
static void test_rotation_and_sinusoid(void **s) {
    (void)s;
    int f = pc_expr_param(P, "t", &st);
    int C = PT(0, 0), A = PT(4, 0), B = PT(1, 3);
    double a = sqrt(10), b = 4, g = acos(4 / (4 * sqrt(10)));        /* cos γ = CA.CB/(ab) */
    int Q = add(add(mul(sub(A, C), dv(fn(PC_EX_SIN, sub(K(g), f)), K(sin(g)))),
                    mul(sub(B, C), dv(mul(K(b), fn(PC_EX_SIN, f)), K(a * sin(g))))), C);
    static const double tq[][3] = {{M_PI / 6, 3.464102, 2}, {M_PI / 2, 0, 4}, {M_PI, -4, 0}};
    for (int i = 0; i < 3; i++) {
        double xy[2];
        eval2(Q, tq[i][0], xy);
        NEAR(xy[0], tq[i][1], 1e-6);
        NEAR(xy[1], tq[i][2], 1e-6);
    }
    int A1 = PT(1, 0), B1 = PT(0, 1);
    double m = 6;
    int root = fn(PC_EX_SQRT, add(K(1 + m * m), mul(K(2 * m), fn(PC_EX_COS, mul(K(m), f)))));
    int M = add(add(mul(sub(A1, C), dv(mul(fn(PC_EX_SIN, sub(K(M_PI / 2), f)), root), K(m))),
                    mul(sub(B1, C), dv(mul(fn(PC_EX_SIN, f), root), K(m)))), C);
    static const double tm[][3] = {{0, 1.166667, 0}, {M_PI / 12, 0.979250, 0.262389},
                                   {M_PI / 6, 0.721688, 0.416667}, {M_PI / 2, 0, 0.833333}};
    for (int i = 0; i < 4; i++) {
        double xy[2];
        eval2(M, tm[i][0], xy);
        NEAR(xy[0], tm[i][1], 1e-6);
        NEAR(xy[1], tm[i][2], 1e-6);
    }
}

/* (4.28), the order-6 interpolation curve through M_j = (j, y_j), y = 0 3 1 4 1 5 9 (the
 * digest's corrected rows: t̄t⁵ and a final t⁶), at t = 3/10: (9/5, 33729/78125) */
static const double ROWS6[7][7] = {   /* coefficients of t̄^(6-i) t^i, i = 0..6 */
    {1, -8.7, 22.7, -22.7, 8.7, -1, 0},
    {0, 36, -133.2, 151.2, -61.2, 7.2, 0},
    {0, -45, 301.5, -418.5, 184.5, -22.5, 0},
    {0, 40, -308, 600, -308, 40, 0},
    {0, -22.5, 184.5, -418.5, 301.5, -45, 0},
    {0, 7.2, -61.2, 151.2, -133.2, 36, 0},
    {0, -1, 8.7, -22.7, 22.7, -8.7, 1}};

static int order6(void) {
    int t = pc_expr_param(P, "t", &st), tb = bar(t);
    static const double y[7] = {0, 3, 1, 4, 1, 5, 9};
    int M = -1;
    for (int j = 0; j < 7; j++) {
        int phi = -1;
        for (int i = 0; i <= 6; i++) {
            if (ROWS6[j][i] == 0) continue;
            int mono = mul(pw(tb, 6 - i), pw(t, i));
            int term = mul(K(ROWS6[j][i]), mono);
            phi = phi < 0 ? term : add(phi, term);
        }
        int term = mul(PT(j, y[j]), phi);
        M = M < 0 ? term : add(M, term);
    }
    return M;
}

static void test_order6_interpolation(void **s) {
    (void)s;
    int M = order6();
    double xy[2];
    eval2(M, 0.3, xy);
    NEAR(xy[0], 9.0 / 5, 1e-12);
    NEAR(xy[1], 33729.0 / 78125, 1e-12);
    for (int j = 0; j <= 6; j++) {            /* through its nodes */
        static const double y[7] = {0, 3, 1, 4, 1, 5, 9};
        eval2(M, j / 6.0, xy);
        NEAR(xy[0], j, 1e-11);
        NEAR(xy[1], y[j], 1e-11);
    }
    /* shared subexpressions: the powers of t and t̄ and their 7 products are computed once
     * for all seven rows: t̄^2..t̄^6 and t^2..t^6 (10 powers), 1 - t once */
    pc_expr_prog *p = compile1(M);
    assert_int_equal(pc_expr_prog_count(p, PC_EX_POWI), 10);
    assert_int_equal(pc_expr_prog_count(p, PC_EX_SUB), 1);
    assert_true(pc_expr_prog_registers(p) < pc_expr_prog_size(p));     /* registers reused */
    pc_expr_prog_free(p);
}

/* --- sharing, batches, errors ----------------------------------------------------------------- */
static void test_hash_consing(void **s) {
    (void)s;
    int t = pc_expr_param(P, "t", &st);
    int a = add(fn(PC_EX_SIN, t), K(1)), b = add(fn(PC_EX_SIN, t), K(1));
    assert_int_equal(a, b);                           /* built twice, one node */
    assert_int_equal(mul(t, a), mul(a, t));           /* products commute */
    int n = pc_expr_pool_size(P);
    int c = mul(a, b);
    assert_int_equal(pc_expr_pool_size(P), n + 1);
    pc_expr_prog *p = compile1(c);
    assert_int_equal(pc_expr_prog_count(p, PC_EX_SIN), 1);
    assert_int_equal(pc_expr_prog_size(p), 3);         /* sin, +, * */
    double v[3];
    jet(p, 0.7, v);
    NEAR(v[0], (sin(0.7) + 1) * (sin(0.7) + 1), 1e-15);
    NEAR(v[1], 2 * (sin(0.7) + 1) * cos(0.7), 1e-15);
    pc_expr_prog_free(p);
    /* folding */
    assert_int_equal(mul(t, K(1)), t);
    assert_int_equal(add(t, K(0)), t);
    assert_int_equal(sub(t, t), K(0));
    assert_int_equal(pc_expr_param(P, "t", &st), t);
    assert_int_equal(pc_expr_opof(P, add(K(2), K(3))), PC_EX_CONST);
}

/* 1000 samples in batches equal 1000 single evaluations; sample() spaces them evenly */
static void test_batches(void **s) {
    (void)s;
    int M = order6();
    pc_expr_prog *p = compile1(M);
    enum { N = 1000 };
    double *x = malloc(N * sizeof *x), *out = malloc(N * 3 * 3 * sizeof *out);
    assert_non_null(x);
    double *smp = malloc(N * 2 * sizeof *smp);
    for (int i = 0; i < N; i++) x[i] = -0.2 + 1.4 * i / (N - 1);
    assert_int_equal(pc_expr_eval(p, N, x, 2, out, NULL), PC_OK);
    for (int i = 0; i < N; i += 37) {
        double one[9];
        assert_int_equal(pc_expr_eval(p, 1, &x[i], 2, one, NULL), PC_OK);
        for (int k = 0; k < 9; k++) NEAR(out[i * 9 + k], one[k], 0);
    }
    assert_int_equal(pc_expr_sample(p, -0.2, 1.2, N, smp, NULL), PC_OK);
    for (int i = 0; i < N; i++) {
        NEAR(smp[2 * i], out[i * 9] / out[i * 9 + 2], 1e-12 * (1 + fabs(smp[2 * i])));
        NEAR(smp[2 * i + 1], out[i * 9 + 1] / out[i * 9 + 2], 1e-12 * (1 + fabs(smp[2 * i + 1])));
    }
    pc_expr_prog_free(p);
    free(x); free(out); free(smp);
}

/* non-finite results name their sample: log(t) at t = 1, 0.5, -1 fails at index 2 */
static void test_nonfinite(void **s) {
    (void)s;
    int t = pc_expr_param(P, "t", &st);
    pc_expr_prog *p = compile1(fn(PC_EX_LOG, t));
    double x[4] = {1, 0.5, -1, 2}, out[4];
    int bad = -1;
    assert_int_equal(pc_expr_eval(p, 4, x, 0, out, &bad), PC_ENONFINITE);
    assert_int_equal(bad, 2);
    NEAR(x[bad], -1, 0);
    pc_expr_prog_free(p);
    p = compile1(fn(PC_EX_SQRT, t));                   /* sqrt at 0: value fine, slope infinite */
    double z = 0, v[3];
    assert_int_equal(pc_expr_eval(p, 1, &z, 0, v, NULL), PC_OK);
    assert_int_equal(pc_expr_eval(p, 1, &z, 1, v, &bad), PC_ENONFINITE);
    assert_int_equal(bad, 0);
    long lbad = -1;
    double smp[11];
    assert_int_equal(pc_expr_sample(p, 1, -1, 11, smp, &lbad), PC_ENONFINITE);
    assert_int_equal(lbad, 6);                          /* t = -0.2 */
    pc_expr_prog_free(p);
}

/* the membership condition: A t + B t has weight 2t; B - A is a vector */
static void test_weights(void **s) {
    (void)s;
    int t = pc_expr_param(P, "t", &st);
    int A = PT(1, 2), B = PT(3, 5);
    double lo = 0, hi = 1, xb, wb;
    pc_expr_prog *p = compile1(add(mul(A, t), mul(B, t)));
    assert_int_equal(pc_expr_prog_weight(p, &lo, &hi, &xb, &wb), PC_KIND_WEIGHTED);
    NEAR(wb, 2 * xb, 1e-15);
    pc_expr_prog_free(p);
    p = compile1(mul(sub(B, A), t));
    assert_int_equal(pc_expr_prog_weight(p, &lo, &hi, NULL, NULL), PC_KIND_VECTOR);
    pc_expr_prog_free(p);
    /* a rational curve written as a weighted sum over its total weight is a point */
    int tb = bar(t), w = add(add(pw(tb, 2), mul(K(2 * 0.5), mul(t, tb))), pw(t, 2));
    int num = add(add(mul(A, pw(tb, 2)), mul(mul(PT(2, 9), K(2 * 0.5)), mul(t, tb))), mul(B, pw(t, 2)));
    p = compile1(dv(num, w));
    assert_int_equal(pc_expr_prog_weight(p, &lo, &hi, NULL, NULL), PC_KIND_POINT);
    assert_int_equal(pc_expr_prog_weight(p, &lo, &hi, NULL, NULL), PC_KIND_POINT);
    pc_expr_prog_free(p);
}

static void test_errors(void **s) {
    (void)s;
    int t = pc_expr_param(P, "t", &st), A = PT(1, 2);
    double h3[4] = {1, 2, 3, 1};
    int A3 = pc_expr_vconst(P, 3, h3, &st);
    assert_int_equal(pc_expr_add(P, A, A3, &st), -1);
    assert_int_equal(st, PC_EDIM);                      /* mixed dimensions */
    assert_int_equal(pc_expr_add(P, A, t, &st), -1);
    assert_int_equal(st, PC_EDIM);                      /* a point and a number */
    assert_int_equal(pc_expr_mul(P, A, A, &st), -1);
    assert_int_equal(st, PC_EDIM);
    assert_int_equal(pc_expr_div(P, t, A, &st), -1);
    assert_int_equal(st, PC_EDIM);
    assert_int_equal(pc_expr_fn(P, PC_EX_SIN, A, &st), -1);
    assert_int_equal(st, PC_EDIM);
    assert_int_equal(pc_expr_fn(P, PC_EX_LOG, K(-1), &st), -1);
    assert_int_equal(st, PC_EDOMAIN);
    assert_int_equal(pc_expr_div(P, t, K(0), &st), -1);
    assert_int_equal(st, PC_EDOMAIN);
    assert_int_equal(pc_expr_const(P, NAN, &st), -1);
    assert_int_equal(st, PC_ENONFINITE);
    assert_int_equal(pc_expr_unit(P, VC(0, 0), &st), -1);
    assert_int_equal(st, PC_EZERO);
    assert_int_equal(pc_expr_cross(P, A3, A, &st), -1);
    assert_int_equal(st, PC_EDIM);
    assert_int_equal(pc_expr_param(P, "", &st), -1);
    assert_int_equal(st, PC_EDOMAIN);
    char name[8];
    for (int i = 0; i < PC_EXPR_MAXPARAM; i++) {
        snprintf(name, sizeof name, "p%d", i);
        pc_expr_param(P, name, &st);
    }
    assert_int_equal(pc_expr_nparams(P), PC_EXPR_MAXPARAM);
    assert_int_equal(pc_expr_param(P, "one_too_many", &st), -1);
    assert_int_equal(st, PC_EDOMAIN);
    /* a program must have every parameter of its equation among its inputs */
    int s2 = pc_expr_param(P, "p1", &st);
    int k = pc_expr_param_index(P, t);
    assert_null(pc_expr_compile(P, add(t, s2), 1, &k, &st));
    assert_int_equal(st, PC_EDOMAIN);
    /* a scalar is no curve */
    pc_expr_prog *p = compile1(t);
    assert_null(pc_expr_curve(p, 0, 1, &st));
    assert_int_equal(st, PC_EDIM);
    p = compile1(mul(A, t));
    assert_null(pc_expr_curve(p, 1, 0, &st));
    assert_int_equal(st, PC_EDOMAIN);
    p = compile1(mul(A, t));
    double x = 0.5, out[3];
    assert_int_equal(pc_expr_eval(p, 1, &x, 3, out, NULL), PC_EDOMAIN);
    x = NAN;
    assert_int_equal(pc_expr_eval(p, 1, &x, 0, out, NULL), PC_ENONFINITE);
    pc_expr_prog_free(p);
}

/* a one-parameter family M(t; s) instantiated at s = 0.25 equals the equation written with 0.25 */
static void test_subst_family(void **s) {
    (void)s;
    int t = pc_expr_param(P, "t", &st), sp = pc_expr_param(P, "s", &st);
    int A = PT(0, 0), B = PT(4, 0), C = PT(2, 3);
    int M = pc_expr_lerp(P, pc_expr_lerp(P, A, C, sp, &st), pc_expr_lerp(P, C, B, sp, &st), t, &st);
    int Ms = pc_expr_subst(P, M, pc_expr_param_index(P, sp), K(0.25), &st);
    assert_true(Ms >= 0);
    assert_int_equal(pc_expr_params(P, Ms), 1u << pc_expr_param_index(P, t));
    int direct = pc_expr_lerp(P, pc_expr_lerp(P, A, C, K(0.25), &st),
                              pc_expr_lerp(P, C, B, K(0.25), &st), t, &st);
    assert_int_equal(Ms, direct);                       /* one node: hash-consed */
    /* substituting t = s^2 changes the speed, not the points */
    int Mt = pc_expr_subst(P, Ms, pc_expr_param_index(P, t), pw(sp, 2), &st);
    int k = pc_expr_param_index(P, sp);
    pc_expr_prog *p = pc_expr_compile(P, Mt, 1, &k, &st), *q = compile1(Ms);
    for (double u = 0; u <= 1; u += 0.1) {
        double a[3], b[3], uu = u * u;
        assert_int_equal(pc_expr_eval(p, 1, &u, 0, a, NULL), PC_OK);
        assert_int_equal(pc_expr_eval(q, 1, &uu, 0, b, NULL), PC_OK);
        for (int i = 0; i < 3; i++) NEAR(a[i], b[i], 1e-15);
    }
    pc_expr_prog_free(p); pc_expr_prog_free(q);
}

/* the surface S(u, v) = lerp(lerp(P00, P10, u), lerp(P01, P11, u), v) (bilinear) in 3-D: partials
 * exact, and the normal of the hyperbolic paraboloid z = uv over the unit square */
static void test_surface(void **s) {
    (void)s;
    int u = pc_expr_param(P, "u", &st), v = pc_expr_param(P, "v", &st);
    double h00[4] = {0, 0, 0, 1}, h10[4] = {1, 0, 0, 1}, h01[4] = {0, 1, 0, 1}, h11[4] = {1, 1, 1, 1};
    int P00 = pc_expr_vconst(P, 3, h00, &st), P10 = pc_expr_vconst(P, 3, h10, &st);
    int P01 = pc_expr_vconst(P, 3, h01, &st), P11 = pc_expr_vconst(P, 3, h11, &st);
    int S = pc_expr_lerp(P, pc_expr_lerp(P, P00, P10, u, &st), pc_expr_lerp(P, P01, P11, u, &st), v, &st);
    int in[2] = {pc_expr_param_index(P, u), pc_expr_param_index(P, v)};
    pc_expr_prog *p = pc_expr_compile(P, S, 2, in, &st);
    assert_non_null(p);
    double x[2] = {0.3, 0.8}, o[6 * 4];
    assert_int_equal(pc_expr_eval(p, 1, x, 2, o, NULL), PC_OK);
    NEAR(o[2], 0.24, 1e-15);                 /* z = uv */
    NEAR(o[4 + 2], 0.8, 1e-15);              /* dz/du = v */
    NEAR(o[8 + 2], 0.3, 1e-15);              /* dz/dv = u */
    NEAR(o[12 + 2], 0, 0);                   /* d2z/du2 */
    NEAR(o[16 + 2], 1, 1e-15);               /* d2z/dudv */
    NEAR(o[20 + 2], 0, 0);
    pc_surface *sf = pc_expr_surface(p, 0, 1, 0, 1, &st);
    assert_non_null(sf);
    double n[3];
    assert_int_equal(pc_surface_normal(sf, 0.3, 0.8, n), PC_OK);
    double len = sqrt(0.64 + 0.09 + 1);
    NEAR(n[0], -0.8 / len, 1e-14);
    NEAR(n[1], -0.3 / len, 1e-14);
    NEAR(n[2], 1 / len, 1e-14);
    pc_surface_release(sf);
}

/* the book's notation, with names for the points */
static const char *namer(void *ud, int dim, const double *h) {
    (void)ud;
    if (dim == 2 && h[2] == 1 && h[0] == 0 && h[1] == 0) return "A";
    if (dim == 2 && h[2] == 1 && h[0] == 1 && h[1] == 2) return "B";
    if (dim == 2 && h[2] == 1 && h[0] == 4 && h[1] == 0) return "C";
    return NULL;
}

static void test_print(void **s) {
    (void)s;
    int t = pc_expr_param(P, "t", &st), tb = bar(t);
    int A = PT(0, 0), B = PT(1, 2), C = PT(4, 0);
    int a = mul(A, pw(tb, 2)), b = mul(mul(mul(B, K(2)), t), tb);   /* in Lua's order */
    int M = add(add(a, b), mul(C, pw(t, 2)));
    char buf[256];
    pc_expr_print(P, M, namer, NULL, buf, sizeof buf);
    assert_string_equal(buf, "A*bar(t)^2 + 2*B*t*bar(t) + C*t^2");
    pc_expr_print(P, M, NULL, NULL, buf, sizeof buf);
    assert_string_equal(buf, "P(0, 0)*bar(t)^2 + 2*P(1, 2)*t*bar(t) + P(4, 0)*t^2");
    int f = pc_expr_param(P, "f", &st);
    int E = add(add(mul(sub(B, C), fn(PC_EX_COS, f)), mul(sub(A, C), fn(PC_EX_SIN, f))), C);
    pc_expr_print(P, E, namer, NULL, buf, sizeof buf);
    assert_string_equal(buf, "V(-3, 2)*cos(f) + V(-4, 0)*sin(f) + C");
    int q = dv(sub(K(1), pw(t, 2)), add(K(1), pw(t, 2)));
    pc_expr_print(P, q, NULL, NULL, buf, sizeof buf);
    assert_string_equal(buf, "(1 - t^2)/(1 + t^2)");
    int n = pc_expr_print(P, M, NULL, NULL, buf, 8);          /* truncated, length reported */
    assert_int_equal(n, (int)strlen("P(0, 0)*bar(t)^2 + 2*P(1, 2)*t*bar(t) + P(4, 0)*t^2"));
    assert_string_equal(buf, "P(0, 0)");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_ops_fd, setup, teardown),
        cmocka_unit_test_setup_teardown(test_closed_forms, setup, teardown),
        cmocka_unit_test_setup_teardown(test_circle_curvature, setup, teardown),
        cmocka_unit_test_setup_teardown(test_parabola_vertex, setup, teardown),
        cmocka_unit_test_setup_teardown(test_ellipse_2_11, setup, teardown),
        cmocka_unit_test_setup_teardown(test_rotation_and_sinusoid, setup, teardown),
        cmocka_unit_test_setup_teardown(test_order6_interpolation, setup, teardown),
        cmocka_unit_test_setup_teardown(test_hash_consing, setup, teardown),
        cmocka_unit_test_setup_teardown(test_batches, setup, teardown),
        cmocka_unit_test_setup_teardown(test_nonfinite, setup, teardown),
        cmocka_unit_test_setup_teardown(test_weights, setup, teardown),
        cmocka_unit_test_setup_teardown(test_errors, setup, teardown),
        cmocka_unit_test_setup_teardown(test_subst_family, setup, teardown),
        cmocka_unit_test_setup_teardown(test_surface, setup, teardown),
        cmocka_unit_test_setup_teardown(test_print, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
