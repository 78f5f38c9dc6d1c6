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

/* The least-energy curve through n >= 2 points p (rows of 2), `pieces` cubic Hermite pieces
 * per span (1..4; interior nodes of a span are free), free ends when end_angles is NULL, or
 * clamped ends with the tangent angles end_angles[0] at the first point and end_angles[1] at
 * the last (radians from the x axis, in the direction of travel).  The unknowns (a tangent
 * angle at every node, two derivative moduli per piece as logarithms, the free nodes) are
 * found by pc_minimize starting from the chord-length natural cubic spline.  *energy (if not
 * NULL) gets the integral of kappa^2 ds.  The curve runs over [0, n-1], span i over [i, i+1].
 * PC_ECOINCIDENT for repeated consecutive points, PC_ENOCONVERGE if the minimisation does
 * not settle, PC_EDIM for n outside 2..PC_ELASTIC_MAXN or pieces outside 1..4. */
#define PC_ELASTIC_MAXN 12
pc_curve *pc_elastic(int n, const double *p, int pieces, const double *end_angles,
                     double *energy, int *status);

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
