/* The conics of Konopatsky's monograph, chapter 2 (digest konopatsky_ch1_2.md §5), as curves
 * of the one curve type (curve.h).
 *
 * Every arc whose point equation is rational of degree 2 in the book's parameter is built as a
 * rational quadratic Bezier curve over the book's parameter range (digest §6: "every conic arc
 * of ch. 2 is a rational quadratic Bezier"), so it passes through its points at infinity and the
 * flattener breaks the polyline there.  The parametrisations by angles and radii, which are not
 * rational, are FUNC curves with a C callback (pc_kcurve below).
 *
 * Points are Cartesian (dim doubles, weight 1).  The simplex is written CAB as in the book: C is
 * the initial point, M = (A - C)p + (B - C)q + C.  Constructors return a new curve (one
 * reference) or NULL with *status set: PC_ECOLLINEAR for a flat triangle, PC_EDOMAIN for a
 * parameter outside the book's range, PC_ENONFINITE for NaN/inf. */
#ifndef PC_CONIC_H
#define PC_CONIC_H

#include "curve.h"

/* The rational quadratic Bezier curve over [u0, u1] whose homogeneous point equation H(u)
 * (dim+1 doubles: weighted coordinates, weight) is quadratic in u, given by its values at u0,
 * (u0 + u1)/2 and u1.  The curve's parameter is u itself. */
pc_curve *pc_rquad_from_samples(int dim, const double *h0, const double *hm, const double *h1,
                                double u0, double u1, int *status);

/* (2.58) The parabola of one ratio A1 t'^2 + 2 A3 t' t + A2 t^2: ends A1, A2, tangents meeting
 * at A3 (the middle vertex; digest §5.3 on the prose's labels). */
pc_curve *pc_conic_parabola(int dim, const double *a1, const double *a3, const double *a2,
                            int *status);
/* (2.62) The parabola through A (t = 0), C (t = tC) and B (t = 1), 0 < tC < 1. */
pc_curve *pc_conic_parabola3(int dim, const double *a, const double *c, const double *b,
                             double tc, int *status);

/* (2.97) The engineering-discriminant arc: M(0) = A, M(1/2) = K on the median CT1 with
 * k = CK/CT1, M(1) = B, tangents CA and CB.  Weights (k, 1 - k, k) on A, C, B.  k = 0 is
 * PC_EDOMAIN (the arc collapses to C); k < 1/2 hyperbola (k < 0: through infinity inside
 * [0, 1]), 1/2 parabola, 1/2 < k ellipse. */
pc_curve *pc_conic_ed(int dim, const double *a, const double *b, const double *c, double k,
                      int *status);
/* The k of (2.97) whose arc passes through K, a point of the median from C: k = CK/CT1.
 * PC_ENOTCOLLINEAR if K is not on the median. */
int pc_conic_ed_k(int dim, const double *a, const double *b, const double *c, const double *kpt,
                  double *k);
/* (2.107) k of the circular arc AB whose tangents meet at C (|CA| = |CB| required,
 * PC_EDOMAIN otherwise): k = 1/2 + 2 h^2 / c^2, c the chord, h the height of the segment. */
int pc_conic_ed_circle_k(int dim, const double *a, const double *b, const double *c, double *k);
/* §2.1.8.1 The circular arc AB whose tangents meet at C: (2.97) with the k of (2.107); the
 * statuses of pc_conic_ed_circle_k. */
pc_curve *pc_conic_circle_arc(int dim, const double *a, const double *b, const double *c, int *status);
/* §4.1 The arc through A (u = 0), K (u = 1/2), B (u = 1) with discriminant k (k != 0, 1): the
 * apex C = K/k' - (A + B) k/(2k') (the print has K/k, digest §2.1 ch. 3-5), then (2.97). */
pc_curve *pc_conic_ed3(int dim, const double *a, const double *kpt, const double *b, double k,
                       int *status);

/* (2.104) Ceva's parametrisation: M(0) = A2, M(1) = A1, tangents A2A3 and A1A3; weights
 * (1, 1/2, k) on A2, A3, A1.  k = 1/4 parabola, k < 1/4 hyperbola, k > 1/4 ellipse. */
pc_curve *pc_conic_ceva(int dim, const double *a1, const double *a2, const double *a3, double k,
                        int *status);
/* §2.1.7's relation to §2.1.6 (digest §5.7): the arc meets the median at t = 1/(1 + sqrt k),
 * so k_ED = 2 sqrt k/(1 + 2 sqrt k) and k = (k_ED/(2(1 - k_ED)))^2; Ceva's 1/4 is ED's 1/2.
 * PC_EDOMAIN for a Ceva k <= 0 or an ED k outside (0, 1) (no arc inside the triangle). */
int pc_ceva_to_ed(double k_ceva, double *k_ed);
int pc_ed_to_ceva(double k_ed, double *k_ceva);
/* (2.100) k = v31/v23 of the conic of the pencil through a fifth point K:
 * K1 = A1K x A2A3, K2 = A2K x A3A1, v23 = (A2A3K1), v31 = (A3A1K2). */
int pc_conic_ceva_k(int dim, const double *a1, const double *a2, const double *a3,
                    const double *kpt, double *k);

/* (2.32) Conjugate semi-diameters CA, CB (any angle): the quarter A -> B, t in [0, 1],
 * (A - C)(1 - t^2)/(1 + t^2) + (B - C) 2t/(1 + t^2) + C. */
pc_curve *pc_conic_conjugate(int dim, const double *c, const double *a, const double *b,
                             int *status);
/* §2.1.1.6 A diameter KA, a third point B and lambda = KC/KA (0 < lambda < 1) fixing the
 * conjugate direction BC: the half ellipse K (t = 0), B (t = lambda), A (t = 1). */
pc_curve *pc_conic_conjugate2(int dim, const double *kpt, const double *a, const double *b,
                              double lambda, int *status);

/* §2.1.4 The conic through five coplanar points by Pascal's hexagon A D M E B C, in the
 * corrected form (the printed S (2.68) is the meet with the line through E parallel to CB, so
 * the printed (2.74) misses B; digest §5.4): S = BE x AD, U = (A - C)u + C, V = SU x CB,
 * M = UE x VD.  The curve runs over [u0, u1] in the book's u (C at u = 0, A at u = 1; NaN: the
 * end of pc_conic_five_points_span); upar
 * (may be NULL) gets u of A, B, C, D, E.  whole: a second piece over [u1, 2 u1 - u0] adds the
 * complementary arc (the middle control point negated; not the book's u), closing the conic.
 * PC_ECOLLINEAR if A, B, C are collinear, PC_EDOMAIN
 * if D or E is off their plane or four of the points are collinear, PC_EDOMAIN2 unless
 * u0 < u1. */
pc_curve *pc_conic_five_points(int dim, const double *a, const double *b, const double *c,
                               const double *d, const double *e, double u0, double u1,
                               int whole, double upar[5], int *status);
/* The parameters u of A, B, C, D, E on that conic (corrected u_B = p_E/(1 - q_E)). */
int pc_conic_five_points_params(int dim, const double *a, const double *b, const double *c,
                                const double *d, const double *e, double upar[5]);
/* The default range of pc_conic_five_points: [0, 1] (C to A) widened to every u of upar,
 * except a |u| of 1e6 or more (a point whose U is the point at infinity of CA, ED parallel to
 * CA), which is no range end: only the whole conic reaches it. */
void pc_conic_five_points_span(const double upar[5], double *u0, double *u1);

/* §2.1.5 The conic through A (t = 0) and B (t = 1) and A1 = (A - C)p1 + C,
 * A2 = (A - C)p1 p2' q2 + (B - C)p2 q2 q3 + C, A3 = (B - C)q3 + C, by the Pascal hexagon
 * A A1 A2 M A3 B, in the corrected (2.93) (digest §5.5: q2(p2 t' + p1 p2') and (t' - p1)).
 * p1 = 1 and q3 = 1 give the tangent cases (2.94)-(2.96).  PC_EDOMAIN unless p1 and q3 are in
 * (0, 1], PC_EDOMAIN2 unless p2 and q2 are in (0, 1) (A2 inside the triangle C A1 A3). */
pc_curve *pc_conic_five_points2(int dim, const double *c, const double *a, const double *b,
                                double p1, double p2, double q2, double q3, int *status);

/* (2.120) The redundant parametrisation of the plane: K = AQ x BP with P = (A - C)u' + C,
 * Q = (B - C)v + C: K = (A - C)u'v'/(1 - v u') + (B - C)uv/(1 - v u') + C (the print has
 * u'v; digest §5.10).  PC_EPOLE at u = 0, v = 1. */
int pc_redundant_point(int dim, const double *c, const double *a, const double *b, double u,
                       double v, double *out);

/* §2.2 (b) The system of triples without a Pascal line: A = A2A3 x A4A5, C = A1 t' + A5 t,
 * B = AA1 x A2C, M = BA3 x CA4.  Corrected (digest §5.9: B uses A, not A5), the locus is a
 * conic through A1 (t = 0), A3 and A4, not through A2 and A5.  A FUNC curve over [t0, t1].
 * PC_EDOMAIN if A2A3 and A4A5 do not meet, PC_EDOMAIN2 unless t0 < t1. */
pc_curve *pc_triples_conic(int dim, const double *a1, const double *a2, const double *a3,
                           const double *a4, const double *a5, double t0, double t1,
                           int *status);

#endif
