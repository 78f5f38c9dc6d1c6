/* The point functions of the script API behind one entry, the operators on values, and the
 * wording of their failures (point_fn.h). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "point_fn.h"

#define PI 3.14159265358979323846

static const char MEMBERSHIP[] =
    "the coefficients of a point equation must sum to 1 for a point and to 0 for a vector "
    "(the membership condition)";

/* snprintf into buf (NULL-safe for size 0); returns the length the text needs */
static size_t put(char *buf, size_t size, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    int len = vsnprintf(buf, size, fmt, ap);
    va_end(ap);
    return len < 0 ? 0 : (size_t)len;
}

/* x as the messages show numbers: %.14g, no "-0" */
static const char *num(double x, char *s) {
    snprintf(s, 32, "%.14g", x == 0 ? 0.0 : x);
    return s;
}

static int vector_result(int n, const double *x, double *out) {
    memcpy(out, x, sizeof(double) * (size_t)n);
    out[n] = 0;
    return PC_OK;
}

int pc_point_fn(int op, int n, const double *const v[4], double x, double *out, int *value) {
    double w[PC_MAXDIM], e[4 * PC_MAXDIM];
    int st = PC_OK, isvalue = 1;
    switch (op) {
    case PC_FN_CROSS:
        if (n != 2 && n != 3) return PC_EDIM;
        isvalue = n == 3;
        if (n == 2) out[0] = pc_cross2(v[0], v[1]);
        else pc_cross3(v[0], v[1], out);
        out[n] = 0;
        break;
    case PC_FN_UNIT:
        if (pc_unit(n, v[0], w) != PC_OK) return PC_EZERO;
        vector_result(n, w, out);
        break;
    case PC_FN_PERP:
        if (n != 2) return PC_EDIM;
        pc_perp2(v[0], w);
        vector_result(n, w, out);
        break;
    case PC_FN_FOOT:
        if (pc_foot(n, v[0], v[1], v[2], out) != PC_OK) return PC_ECOINCIDENT;
        out[n] = 1;
        break;
    case PC_FN_DIVIDE:
        st = pc_divide(n, v[0], v[1], x, out);
        break;
    case PC_FN_HARMONIC:
        st = pc_harmonic(n, v[0], v[1], v[2], out);
        break;
    case PC_FN_NORMALIZE:
        st = pc_normalize(n, v[0], out);
        if (st == PC_IMPROPER) return PC_EWEIGHT;
        break;
    case PC_FN_MEET:
        for (int k = 0; k < 4; k++)
            if (v[k][n] == 0 && pc_norm(n, v[k]) == 0) return PC_EZERO;
        st = pc_meet_h(n, v[0], v[1], v[2], v[3], out, out + n + 1, out + n + 2, e);
        if (st == PC_ESKEW) out[0] = e[0];
        break;
    default:
        isvalue = 0;
        switch (op) {
        case PC_FN_DIST:
            out[0] = pc_dist(n, v[0], v[1]);
            break;
        case PC_FN_NORM:
            out[0] = pc_norm(n, v[0]);
            break;
        case PC_FN_DOT:
            out[0] = pc_dot(n, v[0], v[1]);
            break;
        case PC_FN_SIGMA:
            out[0] = pc_sigma(n, v[0], v[1], v[2]);
            break;
        case PC_FN_SR:
            st = pc_sr(n, v[0], v[1], v[2], out);
            break;
        case PC_FN_CROSS_RATIO:
            st = pc_cross_ratio(n, v[0], v[1], v[2], v[3], out);
            break;
        case PC_FN_WEIGHT:
            out[0] = v[0][n];
            break;
        case PC_FN_VOLUME:
            if (n < 3) return PC_EDIM;
            for (int j = 0; j < 4; j++) memcpy(e + j * n, v[j], sizeof(double) * (size_t)n);
            out[0] = n == 3 ? pc_volume3(e, e + 3, e + 6, e + 9) : pc_measure(n, 3, e);
            break;
        case PC_FN_ANGLE:
        case PC_FN_ANGLE_UV:
            for (int i = 0; i < n && op == PC_FN_ANGLE; i++) {
                e[i] = v[1][i] - v[0][i];
                e[PC_MAXDIM + i] = v[2][i] - v[0][i];
            }
            if (op == PC_FN_ANGLE_UV) {
                memcpy(e, v[0], sizeof(double) * (size_t)n);
                memcpy(e + PC_MAXDIM, v[1], sizeof(double) * (size_t)n);
            }
            if (pc_angle(n, e, e + PC_MAXDIM, out) != PC_OK) return PC_EZERO;
            break;
        default: return PC_EARG;
        }
    }
    if (value) *value = isvalue;
    return st;
}

static int ratio_text(int st, char *buf, size_t size) {
    switch (st) {
    case PC_ECOINCIDENT:
        put(buf, size, "the points coincide, so the ratio is undefined");
        break;
    case PC_ENOTCOLLINEAR:
        put(buf, size, "the points are not collinear");
        break;
    case PC_EZERO:
        put(buf, size, "a point at infinity with a zero direction");
        break;
    default: put(buf, size, "%s", pc_strerror(st));
    }
    return 0;
}

static int meet_text(int st, int n, const double *const v[4], char *buf, size_t size) {
    char s[PC_MAXDIM * 24 + 32];
    double out[PC_MAXDIM + 1];
    switch (st) {
    case PC_EZERO:
        for (int k = 0; k < 4; k++)
            if (v[k][n] == 0 && pc_norm(n, v[k]) == 0) {
                pc_value_text(n, v[k], s, sizeof s);
                put(buf, size, "is the zero vector %s, which has no direction, so it is no point at infinity", s);
                return k + 1;
            }
        break;
    case PC_ESAME_LINE:
        put(buf, size, "the two lines coincide, so they have no single meet");
        return 0;
    case PC_ECOINCIDENT: {
        /* which line: the meet of line A with itself fails the same way only if A is bad */
        int bad_a = pc_meet_h(n, v[0], v[1], v[0], v[1], out, NULL, NULL, NULL) == st;
        const char *names = bad_a ? "A1 and A2" : "B1 and B2";
        if (v[bad_a ? 0 : 2][n] == 0)
            put(buf, size, "%s are the same point at infinity (parallel directions), so they do not define a line",
                names);
        else
            put(buf, size, "%s coincide, so they do not define a line", names);
        return 0;
    }
    case PC_EDIM:
        put(buf, size, "lines in 1-D all coincide; meet needs 2-D or more");
        return 0;
    }
    put(buf, size, "%s", pc_strerror(st));
    return 0;
}

int pc_point_fn_text(int op, int st, int n, const double *const v[4], double x, char *buf, size_t size) {
    char s[PC_MAXDIM * 24 + 32];
    switch (op) {
    case PC_FN_CROSS:
        put(buf, size, "vectors must be 2-D or 3-D, got %d-D", n);
        return 0;
    case PC_FN_UNIT:
        put(buf, size, "the zero vector has no direction");
        return 0;
    case PC_FN_PERP:
        put(buf, size, "must be a 2-D vector, got %d-D (in space a perpendicular is not unique: use cross(u, v))", n);
        return 1;
    case PC_FN_ANGLE:
    case PC_FN_ANGLE_UV:
        put(buf, size, "a side has zero length, so the angle is undefined");
        return 0;
    case PC_FN_FOOT:
        put(buf, size, "A and B coincide, so they do not define a line");
        return 0;
    case PC_FN_SR:
    case PC_FN_HARMONIC:
    case PC_FN_CROSS_RATIO:
        return ratio_text(st, buf, size);
    case PC_FN_DIVIDE:
        put(buf, size, "the point is out of range (not finite) for lambda = %s", num(x, s));
        return 0;
    case PC_FN_VOLUME:
        put(buf, size, "points must be 3-D or more, got %d-D", n);
        return 0;
    case PC_FN_NORMALIZE:
        pc_value_text(n, v[0], s, sizeof s);
        put(buf, size, "%s has weight 0 (a vector, or a point at infinity), so it has no finite location", s);
        return 0;
    case PC_FN_MEET:
        return meet_text(st, n, v, buf, size);
    }
    put(buf, size, "%s", pc_strerror(st));
    return 0;
}

int pc_near(int n, const double *a, const double *b, double eps) {
    double scale = 1, d = 0;
    for (int i = 0; i <= n; i++) {
        scale = fmax(scale, fmax(fabs(a[i]), fabs(b[i])));
        d = fmax(d, fabs(a[i] - b[i]));
    }
    return d <= eps * scale;
}

/* ---- the operators -------------------------------------------------------------------------- */

int pc_value_ratio(int n, const double *u, const double *v, double *r) {
    if (fabs(u[n]) > PC_WEIGHT_TOL || fabs(v[n]) > PC_WEIGHT_TOL) return PC_EWEIGHT;
    return pc_vec_ratio(n, u, v, r, NULL);
}

static size_t ratio_arith_text(const pc_operand *l, const pc_operand *r, char *buf, size_t size) {
    double q, ang = 0;
    char s[32];
    if (l->n != r->n) return put(buf, size, "cannot divide a %d-D vector by a %d-D one (mixed dimensions)", l->n, r->n);
    int st = pc_value_ratio(l->n, l->h, r->h, &q);
    if (st == PC_EWEIGHT)
        return put(buf, size, "cannot divide %s by %s: only a vector divides a parallel vector (u/v = r with u = r v; "
                   "the difference of two points is a vector)", l->what, r->what);
    if (st == PC_EZERO) return put(buf, size, "division of a vector by the zero vector");
    if (st == PC_ENOTCOLLINEAR) {
        pc_vec_ratio(l->n, l->h, r->h, &q, &ang);
        return put(buf, size, "cannot divide vectors that are not parallel: they are %s degrees apart "
                   "(the ratio u/v needs u = r v, within 1e-9)", num(ang * 180 / PI, s));
    }
    return put(buf, size, "/: %s", pc_strerror(st));
}

size_t pc_arith_text(int op, const pc_operand *l, const pc_operand *r, char *buf, size_t size) {
    static const char OVERFLOW[] = "%s: the result is out of range (not finite: a coordinate overflowed)";
    int lp = l->n > 0, rp = r->n > 0;
    const pc_operand *k = lp ? r : l;                 /* the number of k*A, A*k, A/k */
    switch (op) {
    case '+':
    case '-':
        if (!lp || !rp) {
            if (op == '+')
                return put(buf, size, "cannot add %s and %s: points and vectors add only to points and "
                           "vectors; to shift a point write A + V(dx, dy)", l->what, r->what);
            return put(buf, size, "cannot subtract %s from %s: points and vectors subtract only "
                       "points and vectors; to shift a point write A - V(dx, dy)", r->what, l->what);
        }
        if (l->n != r->n)
            return put(buf, size, "cannot %s a %d-D value and a %d-D value: dimensions cannot be mixed",
                       op == '+' ? "add" : "subtract", l->n, r->n);
        return put(buf, size, OVERFLOW, op == '+' ? "A + B" : "A - B");
    case '*':
        if (!lp && !rp) return put(buf, size, "cannot multiply %s by %s", l->what, r->what);
        if (lp && rp)
            return put(buf, size, "cannot multiply a point by a point: use dot(u, v) or cross(u, v) for products "
                       "of vectors");
        if (!k->isnum) return put(buf, size, "cannot multiply a point by %s", k->what);
        if (!isfinite(k->k)) return put(buf, size, "cannot multiply a point by %.14g", k->k);
        return put(buf, size, OVERFLOW, "k * A");
    case '/':
        if (lp && rp) return ratio_arith_text(l, r, buf, size);
        if (!lp) return put(buf, size, "cannot divide %s by a point", l->what);
        if (!r->isnum) return put(buf, size, "cannot divide a point by %s", r->what);
        if (r->k == 0) return put(buf, size, "division of a point by zero");
        if (!isfinite(r->k)) return put(buf, size, "cannot divide a point by %.14g", r->k);
        return put(buf, size, OVERFLOW, "A / k");
    }
    return put(buf, size, "cannot negate %s", l->what);
}

/* ---- locations ------------------------------------------------------------------------------ */

size_t pc_location_text(const char *ctx, int n, const double *h, char *buf, size_t size) {
    char s[PC_MAXDIM * 24 + 32], w[32];
    pc_value_text(n, h, s, sizeof s);
    if (pc_kind_of(h[n]) == PC_KIND_VECTOR)
        return put(buf, size, "%s is a vector %s (weight 0), not a point: %s; to place a vector, "
                   "add it to a point, e.g. P(0, 0) + v", ctx, s, MEMBERSHIP);
    return put(buf, size, "%s has weight %s, so it is neither a point (weight 1) nor a vector "
               "(weight 0): %s; write offsets with V(), e.g. V(x, y)*100 + P(320, 240), "
               "or use normalize(p) for a projective point", ctx, num(h[n], w), MEMBERSHIP);
}

int pc_drawn(int n, const double *h, int st, double *xy) {
    if (n != 2) return st == PC_OK || st == PC_IMPROPER ? st : PC_EDIM;
    if (pc_loc(2, h, xy) != PC_OK) return PC_EWEIGHT;
    return isfinite(xy[0]) && isfinite(xy[1]) ? PC_OK : PC_ENONFINITE;
}

size_t pc_drawn_text(const char *ctx, int st, int n, const double *h, char *buf, size_t size) {
    char s[PC_MAXDIM * 24 + 32];
    pc_value_text(n, h, s, sizeof s);
    if (st == PC_IMPROPER)
        return put(buf, size, "%s (%s) projects to infinity (it lies in the camera's vanishing plane)", ctx, s);
    if (st == PC_EDIM) return put(buf, size, "%s must be a 2-D point, got the %d-D %s", ctx, n, s);
    if (st == PC_EWEIGHT) return pc_location_text(ctx, n, h, buf, size);
    return put(buf, size, "%s has infinite or NaN coordinates", ctx);
}

size_t pc_coord_text(int n, const double *h, int i, const char *key, char *buf, size_t size) {
    char s[PC_MAXDIM * 24 + 32], ctx[sizeof s + 64];
    pc_value_text(n, h, s, sizeof s);
    if (i >= n) return put(buf, size, "%s is %d-D: it has no coordinate .%s", s, n, key);
    if (key) snprintf(ctx, sizeof ctx, "reading .%.8s: the value %s", key, s);
    else snprintf(ctx, sizeof ctx, "reading p[%d]: the value %s", i + 1, s);
    return pc_location_text(ctx, n, h, buf, size);
}
