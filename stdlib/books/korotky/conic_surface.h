/* Surfaces from families of conics (Korotky, "Second-order curves in surface modelling",
 * 2015; digest korotky_curves_surfaces.md, part B).  A generator conic is fixed by two points
 * U, V with their tangent lines and a third point T (construction C-1), written as a rational
 * quadratic Bezier arc U, w W, V of the one curve type; the surfaces are surfaces of the one
 * surface type: the conic sweep over a contour (B-2, B-3) as a FUNC surface, the rectangular
 * elliptic dome as an exact rational biquadratic patch, the triangular dome as a FUNC
 * surface (B-4; the article's formulas are lost, the digest's reconstruction is used). */
#ifndef PC_CONIC_SURFACE_H
#define PC_CONIC_SURFACE_H

#include "surface.h"

/* The arc from U to V through T tangent to the lines (U, tU) and (V, tV) (dim >= 2; U, V, T
 * Cartesian, tU, tV direction vectors): W is the meet of the tangent lines (at infinity when
 * they are parallel, then W is the direction), T = alpha U + beta W + gamma V, and the weight
 * is w = beta / (2 sqrt(alpha gamma)).  cp gets the three homogeneous control rows (dim + 1
 * each: U, w W, V), *w the weight (|w| < 1 ellipse, 1 parabola, > 1 hyperbola, 0 the chord).
 * T = W (the degenerate section AOD of Fig. 3c): *w = +inf, the limit of the arcs, and cp holds
 * U, W, V as points (weight 1): the line pair U W V, which pc_conic_arc_value walks.
 * PC_ECOINCIDENT for U = V, PC_EZERO for a zero tangent, PC_ESKEW when a tangent leaves the
 * plane of U, V, T, PC_EDOMAIN when T is not between the tangent lines (alpha gamma <= 0) or
 * the arc would pass through infinity (w <= -1). */
int pc_conic_arc_cp(int dim, const double *U, const double *tU, const double *V,
                    const double *tV, const double *T, double *cp, double *w);
/* The homogeneous value (dim + 1) at v in [0, 1] of the arc cp, w of pc_conic_arc_cp: the
 * rational quadratic, or for w = inf the line pair (U -> W over [0, 1/2], W -> V after). */
void pc_conic_arc_value(int dim, const double *cp, double w, double v, double *out);
/* The same arc as a curve over [0, 1]; for T = W the two straight pieces U W, W V (quadratic
 * Bezier pieces over 0, 1/2, 1) with *w = inf. */
pc_curve *pc_conic_arc(int dim, const double *U, const double *tU, const double *V,
                       const double *tV, const double *T, double *w, int *status);
/* "ellipse", "parabola", "hyperbola", "segment" or "line pair" (w = inf) for a weight
 * (within 1e-12). */
const char *pc_conic_kind(double w);

/* The conic sweep (B-2): for each u in [0, 1] the arc through U(u), V(u), T(u) tangent to the
 * lines U(u) P(u) and V(u) Q(u) (P and Q run on the rulings of the contact surfaces: a
 * conoid, a cylindroid, a hyperbolic paraboloid or a plane; a P or Q of weight 0 is a tangent
 * direction).  Each curve is 3-D and runs over its own domain, mapped to u in [0, 1]; v in
 * [0, 1] runs along the arc from U to V.  The surface keeps references to the five curves.
 * The data are checked at u = 0, 1/64, ..., 1: where no arc exists the constructor fails
 * with the arc's status and *bad_u (if not NULL) gets that u; between those values an
 * evaluation may still fail with it. */
pc_surface *pc_surface_conic_sweep(pc_curve *U, pc_curve *V, pc_curve *T, pc_curve *P,
                                   pc_curve *Q, double *bad_u, int *status);

/* The elliptic dome over the rectangle [0, 2 a0] x [0, 2 b0] (+ origin, 3 doubles or NULL):
 * z^2/c0^2 = x (2 a0 - x) y (2 b0 - y) / (a0^2 b0^2) (B-4a, reconstructed), whose sections
 * x = const and y = const are semi-ellipses with vertical tangents at the sides, as the exact
 * rational biquadratic patch of weights (1, 0, 1) x (1, 0, 1) (the middle control points at
 * infinity): u-isolines are the sections x = const.  PC_EDOMAIN unless a0, b0, c0 > 0. */
pc_surface *pc_surface_dome_rect(double a0, double b0, double c0, const double *origin,
                                 int *status);
/* z of that dome over (x, y) relative to its corner (0 outside the rectangle). */
double pc_dome_rect_height(double a0, double b0, double c0, double x, double y);

/* The triangular elliptic dome on the triangle ABC (3-D points of one horizontal plane z =
 * A.z, or give z = 0): M = l1 A + l2 B + l3 C + e_z h sqrt(27 l1 l2 l3) in barycentric
 * coordinates (B-4b: on the right triangle with legs 1, z^2 = 27 h^2 x y (1 - x - y); h is
 * the height over the centroid).  Parameters: l1 = 1 - u, l2 = u (1 - v), l3 = u v, so the
 * u-isolines are the sections parallel to BC (semi-ellipses) and v = 0, v = 1 the sides AB,
 * AC.  PC_EDOMAIN for h <= 0, PC_ECOLLINEAR for a flat triangle, PC_EDIM unless 3-D. */
pc_surface *pc_surface_dome_tri(const double *A, const double *B, const double *C, double h,
                                int *status);
/* The h of the triangular dome through the apex D (3-D, its plan inside the triangle):
 * h = (D.z - A.z) / sqrt(27 l1 l2 l3).  PC_EDOMAIN if D's plan is not inside. */
int pc_dome_tri_height_through(const double *A, const double *B, const double *C,
                               const double *D, double *h);

#endif
