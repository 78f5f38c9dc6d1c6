/* Scalar numerics of the curvilinear-coordinates toolkit: Oresme's lambda-functions
 * (example 31) and root finding by bisection (example 30). */
#ifndef PC_NUMERIC_H
#define PC_NUMERIC_H

#include <stddef.h>
#include "status.h"

#define PC_ORESME_MAXLEVEL 24

/* Oresme lambda-function on 2^m cells (example 31): y[0] = y0, y[2^m] = y1 and, level by level
 * (s = 2^m / 2^i for i = 0..m-1, j = 0, s, 2s, ..., 2^m - s),
 *   y[j + s/2] = lambda y[j] + (1 - lambda) y[j + s].
 * For 0 < lambda < 1 it is increasing and, unless lambda = 1/2, nowhere differentiable.
 * y must hold 2^m + 1 doubles.  PC_EDOMAIN unless 0 <= m <= PC_ORESME_MAXLEVEL. */
int pc_oresme_fill(double lambda, int m, double y0, double y1, double *y);
/* The listing's lookup: y[INT(t 2^m)], the index clamped to 0..2^m. */
double pc_oresme_at(const double *y, int m, double t);

/* Bisection as example 30 writes it: x0 = a, x1 = b; repeat x = (x0 + x1)/2; if
 * f(x) f(x0) < 0 then x1 = x else x0 = x; until |x1 - x0| <= tol.  The result is the last
 * midpoint x.  If f(a) = 0 the result is a, if f(b) = 0 it is b (a = b is allowed).
 * PC_ENOBRACKET if f(a) and f(b) are nonzero with the same sign, PC_ENONFINITE if a or
 * b is not finite or f returns NaN or an infinity.  An exact zero f(x) = 0 ends the search at x (the listing would
 * go on bisecting the wrong half).  tol <= 0 bisects until the interval stops shrinking.
 * *iters (if not NULL) gets the number of midpoints evaluated. */
typedef double (*pc_scalar_fn)(double x, void *ud);
int pc_bisect(pc_scalar_fn f, void *ud, double a, double b, double tol, double *x, int *iters);
/* pc_bisect with its failures worded into why (size n; "" on success), as the binding shows
 * them: "f(a) and f(b) have the same sign (f(0) = 1, f(1) = 2): the interval brackets no root",
 * "f(1) must return a finite number, got inf" (the x where f failed), or non-finite ends. */
int pc_bisect_why(pc_scalar_fn f, void *ud, double a, double b, double tol, double *x, int *iters,
                  char *why, size_t n);

/* --- small nonlinear systems and minimisation (Korotky's Ferguson splines, eq. (23), and the
 * elastic reference curve) ---------------------------------------------------------------- */

/* n equations f(x) = 0 in n unknowns: write the n residuals into f; return PC_OK or a status
 * (which ends the solve with it). */
typedef int (*pc_system_fn)(void *ud, const double *x, double *f);

/* Newton's method with a forward-difference Jacobian and step halving on max |f| (the full
 * step is tried first, so near a root it is plain Newton).  x holds the start and gets the
 * root.  Converged when the step is below tol (1 + |x|) in every unknown and max |f| has not
 * grown.  n <= PC_NEWTON_MAXN.  Failures say where: *worst (if not NULL) gets the unknown
 * whose pivot vanished (PC_ESINGULAR), or the equation with the largest residual
 * (PC_ENOCONVERGE after maxit steps), or the first non-finite residual (PC_ENONFINITE).
 * *iters (if not NULL) gets the number of Newton steps. */
#define PC_NEWTON_MAXN 64
int pc_newton(int n, pc_system_fn f, void *ud, double *x, double tol, int maxit, int *iters,
              int *worst);

#endif
