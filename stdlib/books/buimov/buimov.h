/* The textbook's own constructions of space curves and surfaces (Buimov ch. 4 and 5) where
 * they differ from the general constructors of curve.h and surface.h: the B-spline knot
 * vector with multiple vertices and the Cox-de Boor basis as the book writes them, the
 * Bernstein basis, Hermite segments in the book's parameterisation t in [0, t_k], cubic
 * splines by the book's tridiagonal system with four kinds of ends, the helix, and the sphere
 * patch with its corner vectors.  Every curve and surface is of the one type (a Hermite or
 * B-spline curve, a FUNC curve or surface with a C callback).  The digest's errata are
 * followed and named where they matter. */
#ifndef PC_BUIMOV_H
#define PC_BUIMOV_H
#include "surface.h"

/* --- B-splines (§4.4) ---------------------------------------------------------------------- */
/* The book's integer knot vector for the ncp = n + 1 vertices p (rows of dim, Cartesian; a
 * multiple vertex repeated as it is) and order k (degree k - 1), into q (n + k + 1 = ncp + k
 * values; the book says n + 2(k - 1), a misprint):
 *   q_j = 0 for j < k;  q_j = q_{j-1} + [P_{j-k} != P_{j-k+1}] for k <= j <= n + 1;
 *   q_j = q_{j-1} for n + 2 <= j <= n + k.
 * PC_EDOMAIN unless 2 <= k <= ncp. */
int pc_book_knots(int dim, int ncp, const double *p, int k, double *q);
/* The basis function N_{i,k}(t) on the knots q[0..nq-1] by the Cox-de Boor recursion with
 * 0/0 = 0 (second denominator q_{i+k} - q_{i+1}; the book prints q_{i-k} - q_{i+1}); the
 * last non-empty interval is closed at t_max so that P(t_max) is the last vertex.
 * PC_EDOMAIN unless i >= 0, 1 <= k <= PC_CURVE_MAXDEG + 1 and i + k < nq. */
int pc_book_basis(const double *q, int nq, int i, int k, double t, double *out);
/* The B-spline of order k on the vertices p (rows of dim) with the book's knots: a B-spline
 * curve of degree k - 1 over [0, t_max].  PC_EDOMAIN as pc_book_knots, or when a vertex is
 * repeated so often that the knots leave no span. */
pc_curve *pc_curve_book_bspline(int dim, int ncp, const double *p, int k, int *status);

/* --- Bezier (§4.3) and Hermite (§4.2, §5.5) ------------------------------------------------ */
/* J_{n,i}(t) = C(n, i) t^i (1 - t)^(n - i) (0^0 = 1); 0 outside 0 <= i <= n.  n <= 1000. */
double pc_bernstein(int n, int i, double t);
/* The blending functions of a normalised Hermite segment (§5.5):
 * F1 = 2t^3 - 3t^2 + 1, F2 = -2t^3 + 3t^2, F3 = t^3 - 2t^2 + t, F4 = t^3 - t^2. */
void pc_hermite_blend(double t, double F[4]);
/* The coefficients B1..B4 (4 rows of dim) of P(t) = B1 + B2 t + B3 t^2 + B4 t^3 on
 * [0, tl] with P(0) = p1, P(tl) = p2, P'(0) = d1, P'(tl) = d2 (§4.2):
 * B3 = 3(p2 - p1)/tl^2 - 2 d1/tl - d2/tl, B4 = 2(p1 - p2)/tl^3 + d1/tl^2 + d2/tl^2 (the book
 * prints - d1/tl^2 - d2/tl^2 once and + d1, - d2 once).  PC_EDOMAIN unless tl > 0. */
int pc_hermite_coeffs(int dim, const double *p1, const double *p2, const double *d1,
                      const double *d2, double tl, double *B);

/* --- cubic splines (§4.2) ------------------------------------------------------------------ */
typedef enum {
    PC_BOOK_CLAMPED,      /* the end tangents given (the only ends of the book) */
    PC_BOOK_NATURAL,      /* P'' = 0 at both ends (relaxed; Rogers & Adams) */
    PC_BOOK_CYCLIC,       /* P'_n = P'_1 and P''_n = P''_1 (Rogers & Adams) */
    PC_BOOK_ANTICYCLIC    /* P'_n = -P'_1 and P''_n = -P''_1 (Rogers & Adams) */
} pc_book_ends;
/* The parameter lengths of the n - 1 segments of the n points p: 1 each (uniform, the book's
 * "normalised") or the chords |P_k - P_(k-1)| (§4.2).  PC_ECOINCIDENT for a zero chord. */
int pc_book_spline_params(int dim, int n, const double *p, int chord, double *tl);
/* The tangents P'_k (n rows of dim) of the C2 cubic spline through the n points p with the
 * segment lengths tl (n - 1), from the book's system of the joints
 *   t_(k+2) P'_k + 2(t_(k+1) + t_(k+2)) P'_(k+1) + t_(k+1) P'_(k+2)
 *       = 3/(t_(k+1) t_(k+2)) [t_(k+1)^2 (P_(k+2) - P_(k+1)) + t_(k+2)^2 (P_(k+1) - P_k)]
 * and two rows for the ends (d0, d1: the clamped tangents, rows of dim, else unused).
 * n >= 2 (clamped, natural) or n >= 4 (cyclic, anticyclic: a cyclic tridiagonal system in
 * P'_1 .. P'_(n-1) with the corners signed).  PC_EDOMAIN for bad n or tl <= 0,
 * PC_ESINGULAR, PC_ENONFINITE, PC_ENOMEM. */
int pc_book_spline_tangents(int dim, int n, const double *p, const double *tl, pc_book_ends ends,
                            const double *d0, const double *d1, double *tangents);
/* The spline as a curve (Hermite segments over the accumulated parameters 0, t_2, t_2 + t_3,
 * ...): chord 0 uniform, 1 chord length.  tangents (n rows of dim, may be NULL) receives the
 * tangents. */
pc_curve *pc_curve_book_spline(int dim, int n, const double *p, int chord, pc_book_ends ends,
                               const double *d0, const double *d1, double *tangents,
                               int *status);
/* The same with the user's segment lengths tl (n - 1 positive values: the parameter runs 0,
 * t_2, t_2 + t_3, ...; the book's two choices are pc_book_spline_params').  PC_EDOMAIN for a
 * length <= 0. */
pc_curve *pc_curve_book_spline_tl(int dim, int n, const double *p, const double *tl,
                                  pc_book_ends ends, const double *d0, const double *d1,
                                  double *tangents, int *status);

/* --- the helix (§4.1) and the sphere (§5.1) ------------------------------------------------ */
/* (a cos t, a sin t, b t), t in [t0, t1]: a FUNC curve with exact derivatives. */
pc_curve *pc_curve_helix(double a, double b, double t0, double t1, int *status);
/* The unit sphere's point and vectors at (theta, phi) (§5.1, corrected: y = sin th sin ph,
 * S_th = -sin th sin ph e1 + cos th sin ph e2, S_ph = cos th cos ph e1 + sin th cos ph e2
 * - sin ph e3): out = S, S_th, S_ph, the twist S_th,ph and N = S_th x S_ph (5 rows of 3;
 * N points inwards, |N| = |sin ph|). */
void pc_sphere_frame(double th, double ph, double out[15]);
/* The same on the sphere of centre c and radius r: S = c + r (...), S_th, S_ph and the twist
 * times r, N times r^2 (issue 24: the twist at a general centre).  PC_EDOMAIN unless r > 0. */
int pc_sphere_frame_at(const double c[3], double r, double th, double ph, double out[15]);
/* The patch c + r (cos th sin ph, sin th sin ph, cos ph), th in [th0, th1] (u), ph in
 * [ph0, ph1] (v): a FUNC surface with exact partial derivatives (Fig 5.2 is th in [0, pi/2],
 * ph in [pi/4, pi/2]).  PC_EDOMAIN unless r > 0, th0 < th1, ph0 < ph1. */
pc_surface *pc_surface_sphere(const double c[3], double r, double th0, double th1, double ph0,
                              double ph1, int *status);

/* §4.3 the G1 joint of Bezier curves: P of degree n and Q of degree m join with
 * P_n = Q_0 and n (P_n - P_(n-1)) = g m (Q_1 - Q_0) (the print's "gm(g - Q0)" is g m (Q1 - Q0)).
 * pc_bezier_g1_next: Q_0 and Q_1 of the next curve of degree m for the scalar g > 0 (g = 1: a
 * C1 joint) from P's control points p (n + 1 rows of dim, Cartesian).  pc_bezier_joint: the
 * kind of joint of P and Q (rows of dim): 0 none (P_n != Q_0), 1 C0 (a corner), 2 G1 (the
 * three points collinear, same direction), 3 C1 (g = 1), with g.  Within 1e-9 of the size. */
int pc_bezier_g1_next(int dim, int n, const double *p, int m, double g, double *q0, double *q1);
int pc_bezier_joint(int dim, int n, const double *p, int m, const double *q, int *kind, double *g);

#endif
