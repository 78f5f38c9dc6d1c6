/* The deterministic optimisers (BFGS for smooth objectives, Nelder-Mead without derivatives)
 * and the approximation curves of Konopatsky's chapter 5 (digest
 * konopatsky_ch3_5.md §3): the curve of order N-1 through N nodes (x_j, f(x_j)) at uniform
 * t_j = j/(N-1), its mean-square error as the book measures it, and the search for the node
 * abscissae that minimise it ("optimal nodes"). */
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

/* The book's mean-square error of the curve through (x_j, f(x_j)), j = 1..N (N >= 2): samples
 * t_i = i/m, i = 0..m, residual f(x(t_i)) - y(t_i), SSE/(m + 1) (the convention that gives the
 * printed 0.0000284 for Runge; digest §3.2).  PC_ENONFINITE if f gives NaN. */
int pc_approx_mse(pc_scalar_fn f, void *ud, int N, const double *x, int m, double *mse);

/* The optimal nodes: x_1 = a and x_N = b fixed, the N-2 inner nodes ordered in (a, b) through
 * x = a + (b - a) cumsum(softmax(0, z)) and the MSE minimised over z by Nelder-Mead from three
 * starts (uniform, Chebyshev-like, clustered to the middle), each restarted from its best
 * point with a smaller step until a restart no longer improves it by 1e-9 relative or the start
 * has used 40000 objective calls; the best of the three wins.  3 <= N <= 16, m >= N.  nodes: N values out; *evals: objective calls. */
int pc_approx_optimal_nodes(pc_scalar_fn f, void *ud, double a, double b, int N, int m,
                            double *nodes, double *mse, int *evals);

/* Chebyshev nodes: the roots cos((2k + 1)pi/(2N)) mapped to [a, b], increasing. */
void pc_chebyshev_nodes(int N, double a, double b, double *x);
/* The MSE of Lagrange's polynomial through (x_j, f(x_j)) against f over M uniform x in [a, b]
 * (the measure of the book's Chebyshev comparison, §5.2). */
int pc_lagrange_mse_x(pc_scalar_fn f, void *ud, int N, const double *x, double a, double b,
                      int M, double *mse);

#endif
