/* The point calculus as the script API calls it (point_fn.c): the functions of one shape (up to
 * four located arguments and a number in, a number or a value out) behind one entry, the
 * operators on values, and the wording of every failure of them, formatted into a buffer so that
 * a binding only reads its arguments, calls here and pushes the result or raises the text. */
#ifndef PC_POINT_FN_H
#define PC_POINT_FN_H

#include <math.h>
#include <stddef.h>
#include "point.h"

typedef enum {
    PC_FN_DIST, PC_FN_NORM, PC_FN_DOT, PC_FN_CROSS, PC_FN_UNIT, PC_FN_PERP, PC_FN_ANGLE,
    PC_FN_ANGLE_UV, PC_FN_FOOT, PC_FN_SIGMA, PC_FN_SR, PC_FN_DIVIDE, PC_FN_HARMONIC,
    PC_FN_CROSS_RATIO, PC_FN_VOLUME, PC_FN_NORMALIZE, PC_FN_WEIGHT, PC_FN_MEET
} pc_fn_op;

/* op on the n-D arguments v[0..3] (points and vectors as n coordinates, values and ends that may
 * be at infinity as n + 1 homogeneous ones) and the number x (divide's lambda):
 *   DIST(A, B) NORM(v) DOT(u, v) SIGMA(A, B, C) SR(X, Y, Z) CROSS_RATIO(A, B, C, D)
 *   VOLUME(A, B, C, D) WEIGHT(p) ANGLE(A, B, C) ANGLE_UV(u, v): a number into out[0];
 *   CROSS(u, v): a number in 2-D, a vector in 3-D; UNIT(v) PERP(v) FOOT(C, A, B) DIVIDE(X, Y)
 *   HARMONIC(A, B, T) NORMALIZE(p): a value, n + 1 doubles (weight 0 for a direction);
 *   MEET(A1, A2, B1, B2): pc_meet_h's K (n + 1), then lambda, mu; on PC_ESKEW out[0] = the
 *   distance of the lines.
 * *value (may be NULL) is 1 when out holds a value.  Returns PC_OK, PC_IMPROPER (a point at
 * infinity: harmonic, meet), or the failure pc_point_fn_text words. */
int pc_point_fn(int op, int n, const double *const v[4], double x, double *out, int *value);
/* The failure st of pc_point_fn(op, n, v, x) as text into buf ("A and B coincide, so they do
 * not define a line"); returns the argument (1..4) the text is about, to be shown as
 * "argument #k (NAME) TEXT", or 0 when it is about the call. */
int pc_point_fn_text(int op, int st, int n, const double *const v[4], double x, char *buf, size_t size);

/* near(a, b, eps): the n + 1 doubles a and b (values; n = 0: two numbers) equal within eps
 * relative to their size (at least 1): 1 or 0. */
int pc_near(int n, const double *a, const double *b, double eps);

/* The operators on values h (n + 1 doubles): op '+' a + b, '-' a - b, '*' a k, '/' a / k, 'u' -a
 * (b is used by + and - only).  PC_ENONFINITE when k or the result is not finite (an overflow),
 * PC_EZERO for a division by 0.  Inline: the operators are the hot path of every script. */
static inline int pc_value_arith(int op, int n, const double *a, const double *b, double k, double *out) {
    if ((op == '*' || op == '/') && !isfinite(k)) return PC_ENONFINITE;
    if (op == '/' && k == 0) return PC_EZERO;
    switch (op) {
    case '+':
        for (int i = 0; i <= n; i++) out[i] = a[i] + b[i];
        break;
    case '-':
        for (int i = 0; i <= n; i++) out[i] = a[i] - b[i];
        break;
    case '*':
        for (int i = 0; i <= n; i++) out[i] = a[i] * k;
        break;
    case '/': /* the weight is divided too */
        for (int i = 0; i <= n; i++) out[i] = a[i] / k;
        break;
    case 'u':
        for (int i = 0; i <= n; i++) out[i] = -a[i];
        return PC_OK;
    default: return PC_EARG;
    }
    for (int i = 0; i <= n; i++)
        if (!isfinite(out[i])) return PC_ENONFINITE;
    return PC_OK;
}

/* u / v of two values that are vectors (weights within 1e-9 of 0): the number r with u = r v
 * ((2.62)'s (T - A)/(T_C - A)).  PC_EWEIGHT for another weight, else as pc_vec_ratio. */
int pc_value_ratio(int n, const double *u, const double *v, double *r);
/* An operand as the operators' messages show it: a value (n > 0, h), else a number (isnum, k)
 * or another thing, described by what ("a number", "a curve"). */
typedef struct {
    int n;
    const double *h;
    int isnum;
    double k;
    const char *what;
} pc_operand;
/* The message of the operator op ('+', '-', '*', '/', 'u') on l and r that it does not take,
 * or whose result pc_value_arith (pc_value_ratio for two values divided) refused. */
size_t pc_arith_text(int op, const pc_operand *l, const pc_operand *r, char *buf, size_t size);

/* The value h (its weight not 1) used as a location where ctx says ("f: argument #2"): the
 * membership condition, and V() or normalize() as the remedy. */
size_t pc_location_text(const char *ctx, int n, const double *h, char *buf, size_t size);
/* The value h drawn as a 2-D point: n = 2, its location into xy; else st, the status of its
 * projection by the camera (xy its image when PC_OK).  PC_OK; PC_EWEIGHT (2-D, not a point),
 * PC_ENONFINITE (an overflowed location), PC_IMPROPER (it projects to infinity) or PC_EDIM
 * (not 2-D and not projected: no camera), which pc_drawn_text words with ctx ("line: argument #2"). */
int pc_drawn(int n, const double *h, int st, double *xy);
size_t pc_drawn_text(const char *ctx, int st, int n, const double *h, char *buf, size_t size);
/* Reading coordinate i (0-based) of h as .KEY (key "x", "y", "z"), or as p[i + 1] (key NULL):
 * "... has no coordinate .z" past the dimension, else the location text of a weighted value. */
size_t pc_coord_text(int n, const double *h, int i, const char *key, char *buf, size_t size);
/* Coordinate i (0-based) of h as a script reads it (.x, p[1]) into *x: a point's location, a
 * vector's component; PC_EDIM past the dimension, PC_EWEIGHT for a weighted value (both
 * worded by pc_coord_text).  Inline: reading a coordinate is a hot path. */
static inline int pc_coord(int n, const double *h, int i, double *x) {
    double w = h[n];
    if (i >= n) return PC_EDIM;
    if (w == 1.0 || w == 0.0) {   /* the common case */
        *x = h[i];
        return PC_OK;
    }
    int kind = pc_kind_of(w);
    *x = kind == PC_KIND_POINT ? h[i] / w : h[i];
    return kind == PC_KIND_WEIGHTED ? PC_EWEIGHT : PC_OK;
}

#endif
