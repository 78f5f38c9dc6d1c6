/* The closed curve through 2n points by a finite Fourier series (example 12, after Hamming):
 * for samples f(0..2n-1) at u_i = i pi / n,
 *   a_k = (1/n) sum_i f(i) cos(pi k i / n)   (k = 0..n)
 *   b_k = (1/n) sum_i f(i) sin(pi k i / n)   (k = 1..n-1; b_0 = b_n = 0)
 *   f(u) = a_0/2 + sum_{k=1}^{n-1} (a_k cos ku + b_k sin ku) + (a_n/2) cos nu,
 * the trigonometric polynomial of period 2 pi with f(u_i) = f(i).  Applied to each
 * coordinate separately it gives a closed curve through the points. */
#ifndef PC_FOURIER_H
#define PC_FOURIER_H

#include "status.h"
#include "curve.h"

/* f: 2n samples, the i-th at f[i * stride]; a, b: n + 1 coefficients each.
 * PC_EDOMAIN if n < 1, PC_ENONFINITE for a NaN or infinite sample. */
int pc_fourier_coef(int n, const double *f, int stride, double *a, double *b);
double pc_fourier_eval(int n, const double *a, const double *b, double u);
/* f'(u) and f''(u) of the same series. */
double pc_fourier_deriv(int n, const double *a, const double *b, double u, int order);

/* The closed curve through 2n points (samples: 2n rows of d, the i-th at u = i pi / n) as a
 * FUNC curve of the core over [0, 2 pi], closed, with exact first and second derivatives and
 * breakpoints at the samples.  PC_EDIM (d out of 1..PC_MAXDIM), PC_EDOMAIN (n < 1), PC_EARG
 * (samples NULL), PC_ENONFINITE, PC_ENOMEM. */
pc_curve *pc_curve_fourier(int d, int n, const double *samples, int *status);
/* The coefficients of such a curve over its whole domain, *n its n: per coordinate k, a[0..n]
 * from 2k(n + 1), then b[0..n]; NULL (and 0) for any other curve, a part or an image of one. */
const double *pc_curve_fourier_coefs(const pc_curve *c, int *n);

#endif
