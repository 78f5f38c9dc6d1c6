/* What failed in the curve methods and the B-spline's conditions (curve_why.h). */
#include <stdio.h>
#include "curve_why.h"
#include "names.h"

#define AT_INF "the curve is at infinity at t = %s"
#define CUSP "the derivative is zero at t = %s (a cusp or a stop)"
#define THROUGH_INF "the curve passes through infinity: "

const pc_why pc_curve_why[] = {
    {"c:xy", PC_IMPROPER, -2, NULL, AT_INF},
    {"c:deriv", PC_IMPROPER, -2, NULL, AT_INF},
    {"c:tangent", PC_IMPROPER, -2, NULL, AT_INF},
    {"c:tangent", PC_EZERO, -2, NULL, CUSP},
    {"c:normal", PC_IMPROPER, -2, NULL, AT_INF},
    {"c:normal", PC_EZERO, -2, NULL, "the derivative is zero at t = %s"},
    {"c:normal", PC_ECOLLINEAR, -2, NULL, "the curve is straight at t = %s (no principal normal)"},
    {"c:curvature", PC_IMPROPER, -2, NULL, AT_INF},
    {"c:curvature", PC_EZERO, -2, NULL, CUSP},
    {"c:length", PC_IMPROPER, 0, NULL, THROUGH_INF "its length is infinite"},
    {"c:bbox", PC_IMPROPER, 0, NULL, THROUGH_INF "it has no bounding box"},
    {NULL, 0, 0, NULL, NULL}};

int pc_bspline_degree_why(int ncp, double degree, int periodic, char *why, size_t size) {
    int hi = periodic ? ncp : ncp - 1;
    if (degree >= 1 && degree <= hi && degree <= PC_CURVE_MAXDEG) return PC_OK;
    char got[40];
    pc_num_text(degree, got, sizeof got);
    if (periodic)
        snprintf(why, size, "must be an integer from 1 to %d (the number of points), got %s", ncp, got);
    else
        snprintf(why, size, "must be an integer from 1 to %d (fewer than the %d points), got %s",
                 hi > PC_CURVE_MAXDEG ? PC_CURVE_MAXDEG : hi, ncp, got);
    return PC_EDOMAIN;
}

int pc_knots_why(int ncp, int degree, int n, const double *knots, char *why, size_t size) {
    char a[40], b[40];
    int want = ncp + degree + 1;
    if (n != want) {
        snprintf(why, size, "must hold points + degree + 1 = %d knots, got %d", want, n);
        return PC_EDOMAIN;
    }
    for (int i = 1; i < n; i++)
        if (knots[i] < knots[i - 1]) {
            snprintf(why, size, "must be non-decreasing, but knot [%d] = %s is less than knot [%d] = %s", i + 1,
                     pc_num_text(knots[i], a, sizeof a), i, pc_num_text(knots[i - 1], b, sizeof b));
            return PC_EDOMAIN;
        }
    if (knots[degree] < knots[ncp]) return PC_OK;
    snprintf(why, size, "leaves no domain: knot [%d] = %s (the start) must be less than knot [%d] = %s (the end)",
             degree + 1, pc_num_text(knots[degree], a, sizeof a), ncp + 1, pc_num_text(knots[ncp], b, sizeof b));
    return PC_EDOMAIN;
}

int pc_params_why(int n, int got, const double *u, int any, char *why, size_t size) {
    char a[40], b[40];
    if (got != n) {
        snprintf(why, size, "must hold %d numbers (one per point), got %d", n, got);
        return PC_EDOMAIN;
    }
    for (int i = 1; !any && i < n; i++)
        if (!(u[i] > u[i - 1])) {
            snprintf(why, size, "must increase, but [%d] = %s follows [%d] = %s", i + 1, pc_num_text(u[i], a, sizeof a), i,
                     pc_num_text(u[i - 1], b, sizeof b));
            return PC_EDOMAIN;
        }
    return PC_OK;
}

int pc_number_why(const char *what, double v, int n, char *why, size_t size) {
    char got[40];
    if (v >= 1 && v <= n) return PC_OK;
    snprintf(why, size, "must be a %s number 1..%d, got %s", what, n, pc_num_text(v, got, sizeof got));
    return PC_EDOMAIN;
}

int pc_curve_inside_why(const pc_curve *c, double t, char *why, size_t size) {
    char lo[40], hi[40], got[40];
    if (t > c->t0 && t < c->t1) return PC_OK;
    snprintf(why, size, "must be inside the domain (%s, %s), got %s", pc_num_text(c->t0, lo, sizeof lo),
             pc_num_text(c->t1, hi, sizeof hi), pc_num_text(t, got, sizeof got));
    return PC_EDOMAIN;
}

int pc_curve_part_why(const pc_curve *c, double a, double b, char *why, size_t size) {
    char lo[40], hi[40], ta[40], tb[40];
    if (a >= c->t0 && b <= c->t1 && a < b) return PC_OK;
    snprintf(why, size, "need t0 <= a < b <= t1 in the domain [%s, %s], got a = %s, b = %s",
             pc_num_text(c->t0, lo, sizeof lo), pc_num_text(c->t1, hi, sizeof hi), pc_num_text(a, ta, sizeof ta),
             pc_num_text(b, tb, sizeof tb));
    return PC_EDOMAIN;
}

int pc_curve_monomial_checked(const char *op, const pc_curve *c, double piece, double *rows, int *degree, int *rational,
                              pc_why_call *why) {
    char got[40];
    int np = pc_curve_npieces(c);
    if (c->kind == PC_CURVE_FUNC)
        return pc_why_call_set(why, op, PC_EDOMAIN, 0, NULL,
                               "a function curve has no power-basis coefficients (only Bezier and B-spline curves)");
    if (piece < 1 || piece > np)
        return pc_why_call_set(why, op, PC_EDOMAIN, 1, NULL, "must be from 1 to %d (the curve's pieces), got %s", np,
                               pc_num_text(piece, got, sizeof got));
    return pc_why_call_set(why, NULL, pc_curve_monomial_rows(c, (int)piece - 1, rows, degree, rational), 0, NULL, "");
}

int pc_curve_derivs_checked(const char *op, const pc_curve *c, double t, int order, int side,
                            double *out, pc_why_call *why) {
    int st = pc_curve_derivs_n(c, t, order, side, out);
    if (st == PC_EDOMAIN && c->kind == PC_CURVE_FUNC)
        return pc_why_call_set(why, op, st, 0, NULL,
                               "a function curve gives derivatives up to order 2, not %d", order);
    const pc_why *w = pc_why_find(pc_curve_why, op, st);
    return pc_why_call_set(why, w ? op : NULL, st, w ? w->arg : 0, NULL, "%s", w ? w->text : "");
}
