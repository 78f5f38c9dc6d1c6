/* Nature-like curves through support points (Korotky & Vitovtov, "Modelling nature-like
 * curves", 2021; digest korotky_curves_surfaces.md, part A): the polynomial cubic spline
 * y = S(x) of eqs (1)-(9) and the three Ferguson (cubic Hermite) splines of eqs (10)-(29).
 * Every result is a curve of the one curve type (Hermite pieces, pc_curve_hermite).
 *
 * Ferguson data.  Points p are n rows of 2 (A, B, C, ... in the article), tangent
 * directions T are n rows of 2 (normalised here; a zero row is PC_EZERO), and the derivative
 * moduli of the n - 1 segments are 2n - 2 numbers in "mags": segment i leaves knot i with
 * the derivative mags[2i] T_i and arrives at knot i + 1 with mags[2i + 1] T_(i+1).  So
 * mags = {w_A, z1, z2, ..., z_(2n-4), w_E} in the article's names (z1 = w_B(1), z2 = w_B(2),
 * ...).  Each segment has the parameter t in [0, 1] (eq. (10)); the curve runs over [0, n-1].
 *
 * Failures name the knot: *bad (when not NULL) gets the index of the knot (0 = A) where the
 * data are degenerate or the solve failed, or -1. */
#ifndef PC_FERGUSON_H
#define PC_FERGUSON_H

#include "curve.h"

/* Coefficients of the polynomial spline through (x[i], y[i]), i = 0..n-1 (n >= 2, x
 * increasing): S_i(x) = a + b (x - x_i) + c (x - x_i)^2 + d (x - x_i)^3 on [x_i, x_(i+1)],
 * written to coef as n - 1 rows {a, b, c, d}.  ends PC_END_NATURAL (S'' = 0 at both ends,
 * eq. (6)) or PC_END_CLAMPED (S'(x_0) = s0, S'(x_(n-1)) = s1, eq. (8)); solved through the
 * tridiagonal system of the moments S''(x_i).  PC_EDOMAIN (*bad = i) if x_i <= x_(i-1),
 * PC_EARG for PC_END_PERIODIC, PC_ENONFINITE for NaN/inf input. */
int pc_poly_spline(int n, const double *x, const double *y, pc_end_kind ends, double s0,
                   double s1, double *coef, int *bad);
/* The graph of those coefficients as a 2-D curve over [x_0, x_(n-1)] whose parameter is x
 * (Hermite pieces with derivative (1, S'(x_i)): exact). */
pc_curve *pc_poly_spline_curve(int n, const double *x, const double *coef, int *status);

/* The Ferguson spline of given moduli (eq. (19), scalar form (27)): n >= 2 points, n
 * directions, 2n - 2 moduli (any sign; zero gives a cusp). */
pc_curve *pc_ferguson_curve(int n, const double *p, const double *T, const double *mags,
                            int *status);

/* Fixed-lambda joints, eq. (22) for any n: the outgoing derivative m_i at each interior
 * knot solves, per coordinate, the tridiagonal system
 *   lambda_i^2 m_(i-1) + 2 (1 + lambda_i) m_i + m_(i+1) / lambda_(i+1)
 *       = 3 P_(i+1) + 3 P_i (lambda_i^2 - 1) - 3 P_(i-1) lambda_i^2
 * with m_0 = dA and the last m_(i+1)/lambda_(i+1) the end derivative dE; the incoming one
 * is m_i / lambda_i, so the joints satisfy r''(2)(0) = lambda^2 r''(1)(1) (eq. (14)).
 * p: n rows of dim; dA, dE: the end derivative vectors w_A T_A, w_E T_E; lambda: n - 2
 * positive ratios.  dout, din get n rows of dim each (the derivatives leaving / arriving at
 * each knot; din[0] = dout[0] = dA, din[n-1] = dout[n-1] = dE).  PC_EDOMAIN (*bad) for a
 * lambda <= 0, PC_ESINGULAR (*bad) if the system has no solution. */
int pc_ferguson_lambda(int dim, int n, const double *p, const double *dA, const double *dE,
                       const double *lambda, double *dout, double *din, int *bad);

/* Given tangents at every knot: Newton's method on the 2(n-2) equations (23), written
 * for any n at interior knot i with z- = mags[2i-1], z+ = mags[2i]:
 *   3 z-^2 (P_(i+1) - P_i) + 3 z+^2 (P_i - P_(i-1)) - z+^2 mags[2i-2] T_(i-1)
 *     - 2 (z-^2 z+ + z- z+^2) T_i - z-^2 mags[2i+1] T_(i+1) = 0.
 * mags[0] = w_A and mags[2n-3] = w_E are given; the unknowns mags[1..2n-4] start from their
 * values in mags, or from the chord lengths when start is 0.  The root must be positive: a
 * modulus <= 1e-6 times the longest chord (the degenerate roots z5 = z6 = 0 of (23)) is PC_EDOMAIN with *bad at its
 * knot; PC_ENOCONVERGE / PC_ESINGULAR name the knot of the worst equation / unknown.
 * n <= PC_FERGUSON_MAXN. */
#define PC_FERGUSON_MAXN 32
int pc_ferguson_tangents(int n, const double *p, const double *T, double *mags, int start,
                         int *bad);

/* The authors' sequential substitution (A-5, systems (24)-(26)), solved in closed form: at
 * each interior knot in turn the pair of equations is one quadratic in the outgoing modulus
 * z+ (cross product with T_(i+1)), A2 z+^2 + A1 z+ + A0 = 0 with
 *   V = 3 (P_i - P_(i-1)) - mags[2i-2] T_(i-1),  A2 = V x T_(i+1) - 2 z- (T_i x T_(i+1)),
 *   A1 = -2 z-^2 (T_i x T_(i+1)),                  A0 = 3 z-^2 ((P_(i+1) - P_i) x T_(i+1)),
 * and the next incoming modulus follows linearly.  Given mags[0] = w_A and mags[1] = z1,
 * fills mags[2..2n-3] (w_E is an output).  Of two admissible roots (positive, with a
 * positive next modulus) root_max picks the larger, else the smaller.  quad (if not NULL)
 * gets the n - 2 quadratics {A2, A1, A0}.  PC_EDOMAIN (*bad) if a knot has no admissible
 * root, PC_ESINGULAR (*bad) where the quadratic vanishes identically. */
int pc_ferguson_substitution(int n, const double *p, const double *T, double *mags,
                             int root_max, double *quad, int *bad);

#endif
