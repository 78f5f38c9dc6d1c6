/* A Bezier curve applied to a scalar equation (expr.h pc_expr_bezier): the composed point
 * equation, so C(u^2) or conic.ed(...)(t) with t a param is written as the book writes it
 * ((2.97) retyped no more), with exact derivatives; and the same for any curve, with the reason
 * it cannot be applied worded (pc_expr_curve_at). */
#include <stdio.h>
#include "expr.h"
#include "status.h"

int pc_expr_bezier(pc_expr_pool *pool, int dim, int degree, const double *cp, double t0,
                   double t1, int t, int *status) {
    if (degree < 1 || degree > 64 || !(t1 > t0)) {
        *status = PC_EDOMAIN;
        return -1;
    }
    int w = dim + 1, one, h, c, s, sb, num = -1, wsum = -1, rational = 0;
    for (int i = 0; i <= degree; i++)
        if (cp[i * w + dim] != 1) rational = 1;
    /* s = (t - t0)/(t1 - t0) and s' = 1 - s */
    if ((one = pc_expr_const(pool, t0, status)) < 0) return -1;
    if ((s = pc_expr_sub(pool, t, one, status)) < 0) return -1;
    if ((h = pc_expr_const(pool, 1 / (t1 - t0), status)) < 0) return -1;
    if ((s = pc_expr_mul(pool, s, h, status)) < 0) return -1;
    if ((sb = pc_expr_bar(pool, s, status)) < 0) return -1;
    double binom = 1;
    for (int i = 0; i <= degree; i++) {
        /* B_i = binom(n, i) s'^(n-i) s^i, the powers as the pool's integer powers */
        int b, e;
        if ((b = pc_expr_const(pool, binom, status)) < 0) return -1;
        if (degree - i > 0) {
            if ((e = pc_expr_const(pool, degree - i, status)) < 0) return -1;
            if ((e = pc_expr_pow(pool, sb, e, status)) < 0) return -1;
            if ((b = pc_expr_mul(pool, b, e, status)) < 0) return -1;
        }
        if (i > 0) {
            if ((e = pc_expr_const(pool, i, status)) < 0) return -1;
            if ((e = pc_expr_pow(pool, s, e, status)) < 0) return -1;
            if ((b = pc_expr_mul(pool, b, e, status)) < 0) return -1;
        }
        /* the homogeneous control point (weight w_i) times B_i */
        if ((c = pc_expr_vconst(pool, dim, cp + i * w, status)) < 0) return -1;
        if ((c = pc_expr_mul(pool, c, b, status)) < 0) return -1;
        num = num < 0 ? c : pc_expr_add(pool, num, c, status);
        if (num < 0) return -1;
        if (rational) {
            int wi = pc_expr_const(pool, cp[i * w + dim], status);
            if (wi < 0 || (wi = pc_expr_mul(pool, wi, b, status)) < 0) return -1;
            wsum = wsum < 0 ? wi : pc_expr_add(pool, wsum, wi, status);
            if (wsum < 0) return -1;
        }
        binom = binom * (degree - i) / (i + 1);
    }
    /* a rational curve: the weighted sum over its weight, a point again (weight 1) */
    return rational ? pc_expr_div(pool, num, wsum, status) : num;
}

int pc_expr_curve_at(pc_expr_pool *pool, const pc_curve *c, int t, char *why, size_t size) {
    int d = pc_expr_dim(pool, t), st;
    if (d) {
        snprintf(why, size, "the parameter must be a number or a scalar equation, got a %d-D point equation", d);
        return -1;
    }
    if (c->kind != PC_CURVE_BEZIER || c->nknots != 2) {
        snprintf(why, size, "only a single-piece Bezier curve (a conic arc, a Bezier of any degree) can be applied "
                 "to an equation; this one has %s", c->kind == PC_CURVE_FUNC ? "a function" : "several pieces");
        return -1;
    }
    int r = pc_expr_bezier(pool, c->dim, c->degree, c->cp, c->t0, c->t1, t, &st);
    if (r < 0) snprintf(why, size, "%s", pc_expr_why(st));
    return r;
}
