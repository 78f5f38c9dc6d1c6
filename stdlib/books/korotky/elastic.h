/* The elastic reference of Korotky & Vitovtov (2021): the article measures its spline models
 * against the line of a thin steel ruler bent through pins, which takes the shape of least
 * bending energy.  The text keeps only the pins and the measured slopes, so the reference is
 * computed: the curve of least integral of kappa^2 ds through the points with free length
 * (frictionless pins, unloaded free ends give kappa = 0 there), approximated by cubic Hermite
 * pieces (digest korotky_curves_surfaces.md, A.11).  The measures below compare any model
 * with it: maximum distance, curvature jumps at the joints, bending energy. */
#ifndef PC_ELASTIC_H
#define PC_ELASTIC_H

#include "curve.h"

/* The least-energy curve through n >= 2 points p (rows of 2): a C2 cubic spline in a
 * parameter of its own through the points and `pieces` - 1 free nodes inside each span
 * (pieces 1..4, or 0 for the most that n allows: 4 up to 10 points), with free ends
 * (natural: kappa = 0 there, as at the unloaded ends of a ruler) when end_angles is NULL, or
 * clamped ends with the tangent angles end_angles[0] at the first point and end_angles[1] at
 * the last (radians from the x axis, in the direction of travel; the length stays free).
 * The unknowns (the spline's parameter steps, the free nodes' offsets across the curve, the
 * clamped end speeds) are found by pc_minimize from the chord-length cubic spline.  *energy
 * (if not NULL) gets the integral of kappa^2 ds.  The curve runs over [0, n-1], span i over
 * [i, i+1] (each span's pieces keep their parameter ratios): C2 inside a span, and at a pin
 * tangent and curvature are continuous (G2), only the speed of the parameter changes.
 * PC_ECOINCIDENT for repeated consecutive points, PC_ENOCONVERGE if the minimisation does
 * not settle, PC_EDIM for n outside 2..PC_ELASTIC_MAXN, pieces outside 0..4 or too many
 * unknowns (2 (n-1) pieces - n, + 2 when clamped, at most PC_NEWTON_MAXN). */
#define PC_ELASTIC_MAXN 12
pc_curve *pc_elastic(int n, const double *p, int pieces, const double *end_angles,
                     double *energy, int *status);
/* The same with a fixed length (length > 0; 0 leaves it free): the least-energy curve through
 * the points whose length is `length`, as a clamped ruler keeps its length between the
 * clamps (the article's second experiment; its length is not given).  Solved from the free
 * minimum by an augmented Lagrangian (length met to 1e-6 relative, usually 1e-8).  PC_EDOMAIN unless the
 * length exceeds the polyline through the points; PC_EDIM when nothing is free (two points,
 * one piece); the other statuses as pc_elastic. */
pc_curve *pc_elastic_length(int n, const double *p, int pieces, const double *end_angles,
                            double length, double *energy, int *status);

/* --- measures of a model against another (the article compares with the elastic line) --- */

/* Two-sided Hausdorff distance between two curves of one dimension: each sampled on
 * `samples` points per piece (>= 8), every sample's nearest point on the other curve found
 * by a coarse search and golden-section refinement.  PC_EDIM on mixed dimensions. */
int pc_curve_hausdorff(const pc_curve *a, const pc_curve *b, int samples, double *d);

/* The jumps at the joints of a piecewise curve (Bezier pieces: Hermite, Ferguson and cubic
 * splines): the largest |kappa_left - kappa_right| (signed curvature in the plane,
 * |C' x C''|/|C'|^3 otherwise) and the largest angle between the tangents, in radians;
 * *at (if not NULL) the index of the joint with the largest curvature jump (1 = the first
 * interior knot), 0 when the curve has one piece.  PC_EZERO at a zero derivative. */
int pc_curve_joint_jumps(const pc_curve *c, double *dk, double *dangle, int *at);

/* The bending energy: the integral of kappa^2 ds over the curve (16-point Gauss-Legendre on
 * 8 parts of each piece). */
int pc_curve_bending_energy(const pc_curve *c, double *energy);

#endif
