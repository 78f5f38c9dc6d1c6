/* The "key" construction of Korotky (2015), Example 1 (Fig. 1b, the sail; Fig. 1c, the
 * planking): the contour is lifted into four dimensions by giving its nodes a fourth
 * coordinate t, and the surface is the set of meets of two pencils of 2-planes; its xyz
 * projection is the shell, its xyt projection a simple auxiliary surface (a cone, a conoid).
 * Digest korotky_curves_surfaces.md B.4 (the reading with the basis point Z at infinity on
 * the z axis, B.9 item 4).  Points are homogeneous 5-vectors (x, y, z, t | w), w = 0 at
 * infinity. */
#ifndef PC_PENCILS4_H
#define PC_PENCILS4_H

#include "surface.h"

/* The meet of the 2-planes spanned by p[0..2] and q[0..2] (homogeneous 5-vectors; a
 * repeated or dependent spanning point makes that flat a line): two 2-planes of projective
 * 4-space meet in one point in general.  out gets it (homogeneous, weight 1 when finite).
 * PC_ESAME_LINE when the flats share a line (more than one point in common: a plane of one
 * pencil through the basis point of the other, B.4 step 5), PC_ESKEW when they do not meet
 * (a line and a plane in general position), PC_ENONFINITE for NaN/inf. */
int pc_meet_planes4(const double p[3][5], const double q[3][5], double out[5]);

/* A spanning point of a pencil: a 4-D curve (over its own domain, mapped to [0, 1]) or,
 * when c is NULL, the fixed homogeneous point h (a basis point; w = 0 for Z at infinity). */
typedef struct {
    pc_curve *c;
    double h[5];
} pc_pencil_point;

/* The surface of the meets S(u, v) = omega(u) ^ delta(v), omega(u) the 2-plane through
 * om[0..2] at u and delta(v) the one through de[0..2] at v (u, v in [0, 1]; points of
 * different curves of one pencil are paired by equal parameters, so give the article's level
 * pairing by curves whose parameter runs with the level).  A 4-D FUNC surface holding
 * references to the curves; an evaluation where the planes do not meet in one point fails
 * with pc_meet_planes4's status.  PC_EDIM unless every curve is 4-D. */
pc_surface *pc_surface_two_pencils(const pc_pencil_point om[3], const pc_pencil_point de[3],
                                   int *status);
/* The same, refused when the planes do not meet in one point at u = v = 0.5 (a surface whose
 * every meet fails is a mistake in the data): then NULL with *meet (and *status) the status
 * of pc_meet_planes4 there; *meet is PC_OK otherwise. */
pc_surface *pc_surface_two_pencils_checked(const pc_pencil_point om[3], const pc_pencil_point de[3],
                                           int *status, int *meet);

#endif
