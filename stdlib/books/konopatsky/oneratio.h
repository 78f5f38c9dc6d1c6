/* Curves of one ratio, Konopatsky's chapter 3 (digest konopatsky_ch3_5.md §1): constructions
 * in which one simple ratio t runs through every link of a scheme.  All are curves of the one
 * curve type (curve.h): the polynomial and rational ones Bezier curves, the blends of two
 * conics FUNC curves whose homogeneous value has weight 0 at the conics' poles.
 * Points are Cartesian rows of dim; the result is a new curve or NULL with *status set. */
#ifndef PC_ONERATIO_H
#define PC_ONERATIO_H

#include "curve.h"

/* (3.1) The moving simplex: N = A t' + C t, M = N t' + B t, i.e. M = A t'^2 + B t + C t t'
 * (the print has C t'; digest §1.1): the quadratic Bezier A, (B + C)/2, B. */
pc_curve *pc_oneratio_simplex(int dim, const double *a, const double *b, const double *c,
                              int *status);
/* (3.2)-(3.3) In the simplex DABC: M = A t'^2 + (C + D) t' t + B t^2, the quadratic Bezier
 * A, (C + D)/2, B; M(1/2) is the centroid of the tetrahedron. */
pc_curve *pc_oneratio_tetra(int dim, const double *a, const double *b, const double *c,
                            const double *d, int *status);
/* §3.6 The contour arc of smoothness order n >= 1 (zero curvature at the ends for n >= 2):
 * M_n = (A - C) t'^(n+1)/D_n + (B - C) t^(n+1)/D_n + C, D_n = sum t'^k t^(n-k): the rational
 * Bezier of degree n+1 on A, C, ..., C, B with weights 1, 2/binom(n+1, i), 1.  n <= 40. */
pc_curve *pc_oneratio_smooth(int dim, const double *a, const double *b, const double *c, int n,
                             int *status);
/* (3.6) The Desargues arc: M = (A t'^3 + B t^2 t' + C t'^2 t + D t^3)/(2t^2 - 2t + 1), the
 * rational cubic Bezier A, C, B, D with weights 1, 1/3, 1/3, 1; tangents AC at A, BD at D. */
pc_curve *pc_oneratio_desargues(int dim, const double *a, const double *b, const double *c,
                                const double *d, int *status);

/* The blending function of a curve of double contact: f(ud, v) (NaN fails the evaluation). */
typedef double (*pc_blend_fn)(void *ud, double v);
/* §3.4 Double contact: P and Q the arcs (2.97) of A, B, C with discriminants kp != kq, and
 * M = P (1 - f(v)) + Q f(v), v in [0, 1].  f NULL: f(v) = v (the linear case of [14]).
 * Tangent to CA at A and to CB at B for any bounded f.  A pole of P or Q (k < 0) is a point
 * at infinity of M (weight 0).  PC_EDOMAIN for kp = 0, PC_EDOMAIN2 for kq = 0, PC_EDOMAIN3 for
 * kp = kq. */
pc_curve *pc_oneratio_double_contact(int dim, const double *a, const double *b,
                                     const double *c, double kp, double kq, pc_blend_fn f,
                                     void (*fn_free)(void *ud), void *ud, int *status);
/* The same with the constant f(v) = f. */
pc_curve *pc_oneratio_double_contact_const(int dim, const double *a, const double *b,
                                           const double *c, double kp, double kq, double f,
                                           int *status);
/* (3.4) The cubic Bezier curve of the de Casteljau scheme on A, C1, C2, B (corrected powers). */
pc_curve *pc_oneratio_bezier3(int dim, const double *a, const double *c1, const double *c2,
                              const double *b, int *status);
/* §3.5 Closed curves: M = P u' + Q u with P the arc (2.97) kP run from B to A and Q run
 * A -> B (scheme 1) or Q = (C - A)kQ u'^2/d + (B - A)kQ u^2/d + A run C -> B (scheme 2, the
 * printed Q with u^2 and u'^2 exchanged as the printed final M demands; digest §1.5).
 * M(0) = M(1) = B.  PC_EDOMAIN for kP = 0, PC_EDOMAIN2 for kQ = 0, PC_EARG for another scheme. */
pc_curve *pc_oneratio_closed(int dim, const double *a, const double *b, const double *c,
                             double kp, double kq, int scheme, int *status);

/* ---- the schemes' intermediate points, for figures that draw and label them ---------------- */

/* §3.1 (Fig. 3.1) The moving simplex at t: N = A t' + C t on AC and M = N t' + B t on NB. */
int pc_oneratio_simplex_scheme(int dim, const double *a, const double *b, const double *c,
                               double t, double *n, double *m);
/* §3.3 (Fig. 3.4) The de Casteljau scheme of the Bezier curve on n >= 2 control points (rows of
 * dim) at the one ratio t: the levels 1..n-1, row after row (n - 1 points, n - 2, ..., M last),
 * n(n - 1)/2 rows into out.  For A, C1, C2, B they are P1, P2, P3, Q1, Q2, M (the print's
 * P3 = (C2 - B)t + C2 has the wrong sign; digest konopatsky_ch3_5.md §1.3).  n <= 16. */
int pc_decasteljau_levels(int dim, int n, const double *pts, double t, double *out);
/* §3.7 (Fig. 3.12) The Desargues arc's scheme at t, as homogeneous points (dim weighted
 * coordinates, then the weight) in the order T, S, R, N, J, Q, M:
 *   T = (A t'^2 - B t^2)/(1 - 2t) (Menelaus in ACB), S = (C t'^2 - D t^2)/(1 - 2t) (in CBD),
 *   R = T t' + S t, N = A t'^2 + 2C t' t + B t^2, J = C t'^2 + 2B t' t + D t^2,
 *   Q = (B - C)t + C, M = SN x TJ = (3.6);
 * T, S and R have weight 1 - 2t: points at infinity at t = 1/2.  pq (may be NULL) gets the
 * parameters of J in the simplex S N T: p_J = 2t - 1, q_J = t'/t (infinite at t = 0). */
int pc_desargues_scheme(int dim, const double *a, const double *b, const double *c,
                        const double *d, double t, double *h, double pq[2]);

#endif
