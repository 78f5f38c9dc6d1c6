/* The deterministic optimisers: BFGS for smooth objectives, Nelder-Mead without derivatives. */
#ifndef PC_OPTIMIZE_H
#define PC_OPTIMIZE_H

#include "numeric.h"

/* An objective of n unknowns, for both methods; NaN or an infinity means "outside the domain"
 * (BFGS's line search then steps back; Nelder-Mead counts it as +inf). */
typedef double (*pc_objective_fn)(void *ud, const double *x);

/* Deterministic quasi-Newton minimisation (BFGS with an Armijo line search, central
 * difference gradients with step h (1e-6 relative when h <= 0)).  x holds the start and gets
 * the minimiser, *fx (if not NULL) the value there.  Stops when the largest gradient
 * component is below gtol, or when no step along the search direction lowers f any more
 * (the minimum to the precision of the differences).  PC_ENOCONVERGE after maxit
 * iterations, PC_ENONFINITE if f is not finite at the start, PC_EDIM for n outside
 * 1..PC_NEWTON_MAXN. */
int pc_minimize(int n, pc_objective_fn f, void *ud, double *x, double gtol, double h, int maxit,
                double *fx, int *iters);

/* Nelder-Mead on R^n (n <= 32), deterministic: the start simplex is x and x + step e_i;
 * reflection 1, expansion 2, contraction 1/2, shrink 1/2; ties keep the vertex order.
 * Stopping rule: f(worst) - f(best) <= ftol (|f(best)| + 1e-300) and the simplex's largest
 * edge from the best vertex <= xtol, or maxiter iterations (then PC_ENOCONVERGE, x and *fx
 * still hold the best point found).  x: start in, best out.  PC_ENONFINITE if f(start) is
 * not finite (non-finite values elsewhere count as +inf). */
int pc_nelder_mead(int n, pc_objective_fn f, void *ud, double *x, double step, double ftol,
                   double xtol, int maxiter, double *fx, int *iters);

#endif
