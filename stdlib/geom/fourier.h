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

/* f: 2n samples, the i-th at f[i * stride]; a, b: n + 1 coefficients each.
 * PC_EDOMAIN if n < 1, PC_ENONFINITE for a NaN or infinite sample. */
int pc_fourier_coef(int n, const double *f, int stride, double *a, double *b);
double pc_fourier_eval(int n, const double *a, const double *b, double u);

#endif
