/* Internals shared by the curve files (curve.c, curve_eval.c, curve_ops.c, curve_build.c,
 * curve_flatten.c); not part of the public API. */
#ifndef PC_CURVE_IMPL_H
#define PC_CURVE_IMPL_H
#include <stddef.h>
#include "curve.h"

#define PCC_W (PC_MAXDIM + 1)              /* widest homogeneous row */
#define PCC_ROWS (PC_CURVE_MAXDEG + 1)     /* most control points of one piece */

/* A curve of `kind` with room for ncp rows of dim+1 and nknots knots (fields filled but for
 * the arrays' contents, t0, t1, degree, closed).  NULL with *status = PC_ENOMEM. */
pc_curve *pcc_new(pc_curve_kind kind, int dim, int ncp, int nknots, int *status);
/* 1 if all n values are finite. */
int pcc_finite(size_t n, const double *v);
pc_curve_callback *pcc_func_new(pc_curve_fn eval, void (*fn_free)(void *), void *ud);
void pcc_func_release(pc_curve_callback *f);
/* A FUNC curve using f (one more reference taken on success) with the breakpoints
 * t0 < brk[0] < ... < brk[nbrk-1] < t1 (none when nbrk = 0). */
pc_curve *pcc_func_curve(int dim, double t0, double t1, int closed, pc_curve_callback *f,
                         int nbrk, const double *brk, int *status);
/* The smallest breakpoint of c (Bezier breaks, distinct B-spline knots of the domain, FUNC
 * breaks, the domain ends) greater than x, or b if there is none below b. */
double pcc_next_break(const pc_curve *c, double x, double b);
/* The Bezier segment (0..nseg-1) or B-spline span (degree..ncp-1, a non-empty one) used at t. */
int pcc_piece(const pc_curve *c, double t);
/* The homogeneous value of a polynomial piece and its derivatives (de Boor on the local knots
 * U with span k, q = degree, d: q+1 rows of w, destroyed). */
void pcc_deboor(int q, int w, double *d, const double *U, int k, double x, int order,
                double *out);
/* The Bezier control points (degree + 1 rows of dim + 1, homogeneous) of piece k: Bezier
 * segment k, or the non-empty B-spline span k (over knots[k] .. knots[k+1]). */
void pcc_bezier_piece(const pc_curve *c, int k, double *out);
/* Local knots of Bezier segment i: 2 degree + 2 values in U, the span index returned. */
int pcc_bezier_knots(const pc_curve *c, int i, double *U);

#endif
