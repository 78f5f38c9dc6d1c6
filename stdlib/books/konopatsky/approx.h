/* The approximation curves of Konopatsky's chapter 5 (digest konopatsky_ch3_5.md §3): the
 * curve of order N-1 through N nodes (x_j, f(x_j)) at uniform t_j = j/(N-1), its mean-square
 * error as the book measures it, and the search for the node abscissae that minimise it
 * ("optimal nodes"), built on the kernel's Nelder-Mead (optimize.h). */
#ifndef PC_APPROX_H
#define PC_APPROX_H

#include "optimize.h"
#include "curve.h"

/* §5.1 The approximation curve through (x_j, f(x_j)), j = 1..N (2 <= N <= 64), at uniform t:
 * the interpolation curve of the nodes.  PC_ENONFINITE, *bad the node j, where f(x_j) is not a
 * finite number. */
pc_curve *pc_approx_curve(pc_scalar_fn f, void *ud, int N, const double *x, int *bad, int *status);

/* The book's mean-square error of the curve through (x_j, f(x_j)), j = 1..N (N >= 2): samples
 * t_i = i/m, i = 0..m, residual f(x(t_i)) - y(t_i), SSE/(m + 1) (the convention that gives the
 * printed 0.0000284 for Runge; digest §3.2).  PC_ENONFINITE if f gives NaN. */
int pc_approx_mse(pc_scalar_fn f, void *ud, int N, const double *x, int m, double *mse);

/* The divisor of the SSE over the m + 1 samples: the book's m + 1 (a mean, the default), or m,
 * or m - 1 (for comparison with other reports; digest §3.2: SSE/m gives "0.0000287").  The
 * optimal nodes do not depend on it. */
typedef enum { PC_MSE_DIV_M1, PC_MSE_DIV_M, PC_MSE_DIV_MMINUS1 } pc_mse_divisor;
/* mse (divided by m + 1) re-divided by d; PC_EDOMAIN for m - 1 = 0. */
int pc_approx_rescale(double mse, int m, pc_mse_divisor d, double *out);

/* The optimal nodes: x_1 = a and x_N = b fixed, the N-2 inner nodes ordered in (a, b) through
 * x = a + (b - a) cumsum(softmax(0, z)) and the MSE minimised over z by Nelder-Mead from three
 * starts (uniform, Chebyshev-like, clustered to the middle), each restarted from its best
 * point with a smaller step until a restart no longer improves it by 1e-9 relative or the start
 * has used 40000 objective calls; the best of the three wins.  3 <= N <= 16, m >= N.  nodes: N values out; *evals: objective calls. */
int pc_approx_optimal_nodes(pc_scalar_fn f, void *ud, double a, double b, int N, int m,
                            double *nodes, double *mse, int *evals);

/* Chebyshev nodes: the roots cos((2k + 1)pi/(2N)) mapped to [a, b], increasing.  PC_EDOMAIN
 * unless a < b and N >= 1. */
int pc_chebyshev_nodes(int N, double a, double b, double *x);
/* The MSE of Lagrange's polynomial through (x_j, f(x_j)) against f over M uniform x in [a, b]
 * (the measure of the book's Chebyshev comparison, §5.2). */
int pc_lagrange_mse_x(pc_scalar_fn f, void *ud, int N, const double *x, double a, double b,
                      int M, double *mse);

#endif
