/* Two more shells of Korotky (2015) built from the conic arcs of conic_surface.h (digest
 * korotky_curves_surfaces.md B.6): the rotational conic sweep of Fig. 3b and the composite
 * shell of Fig. 3d, whose profiles are two conic arcs with a common tangent on a ridge.
 * Both are 3-D FUNC surfaces of the one surface type. */
#ifndef PC_CONIC_SHELLS_H
#define PC_CONIC_SHELLS_H

#include "conic_surface.h"

/* Fig. 3b: a conic turned about the axis AB.  For u in [0, 1] (the ridge curve l over its
 * domain) the plane Pi(u) through A, B and T = l(u) holds the generator: the arc from A to B
 * through T whose tangents at A and B are the lines Pi ^ pi_A and Pi ^ pi_B, pi_A and pi_B
 * the fixed tangent planes of the dome at A and B (normals nA, nB: the contact surfaces of
 * B-2 degenerate to planes).  Each tangent is taken pointing to T's side of AB.  v in [0, 1]
 * runs along the arc from A to B.  The ridge is checked at u = 0, 1/64, ..., 1 (*bad_u gets
 * the first u without a generator): PC_ECOLLINEAR where T is on the line AB, PC_EDOMAIN
 * where a tangent plane holds AB's direction in Pi or T is not between the tangents.
 * PC_EDIM unless l is 3-D, PC_ECOINCIDENT for A = B, PC_EZERO for a zero normal. */
pc_surface *pc_surface_conic_revolve(const double A[3], const double B[3], const double nA[3],
                                     const double nB[3], pc_curve *l, double *bad_u,
                                     int *status);

/* Fig. 3d: a profile of two conic arcs with a common tangent on a ridge, as one surface.
 * For u in [0, 1] (each curve over its own domain): the first arc from U(u) to the ridge
 * point R(u) through T1(u), tangent at U to the line towards P(u) (a point, or a direction
 * when its weight is 0) and at R to the direction H(u); the second from R(u) to V(u) through
 * T2(u), tangent to H(u) at R and to the line towards Q(u) at V.  v in [0, 1] is the first
 * arc, [1, 2] the second, so the shell is G1 across the ridge v = 1 by construction (both
 * arcs touch H there); a T on its chord makes that arc a straight segment (weight 0: the
 * crease SL).  H is a direction (weight 0) or a point (then H - R).  Checked like the conic
 * sweep (*bad_u).  PC_EDIM unless every curve is 3-D. */
typedef struct { pc_curve *U, *R, *V, *T1, *T2, *P, *H, *Q; } pc_ridge_shell;
pc_surface *pc_surface_ridge_shell(const pc_ridge_shell *g, double *bad_u, int *status);

#endif
