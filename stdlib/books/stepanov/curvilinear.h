/* Maps that make curvilinear coordinate systems (stepanov_examples.md §H rows 3, 14, 17-19, 23):
 * the bilinear quadrilateral map, the graph of a function erected on a segment, the blend of
 * four side curves into a patch, the plane -> open square compactification, the oblique
 * projection by screen points and the Moebius automorphism of the unit disc. */
#ifndef PC_CURVILINEAR_H
#define PC_CURVILINEAR_H

#include "status.h"
#include "map.h"

/* X(t1, t2) = P0 + t1 (P1 - P0) + t2 (P3 - P0) + t1 t2 (P2 - P3 - P1 + P0) (example 2, §4):
 * P0, P1, P2, P3 at the corners (0,0), (1,0), (1,1), (0,1).  d doubles per point. */
void pc_bilinear(int d, const double *p0, const double *p1, const double *p2, const double *p3,
                 double t1, double t2, double *out);

/* The frame of a segment in the plane (example 23): origin O, first axis e, second axis
 * perp(e) = (e_y, -e_x).  pc_frame_point gives O + xi e + eta perp(e); pc_frame_coords
 * inverts it (PC_EZERO if e = 0). */
void pc_frame_point(const double o[2], const double e[2], double xi, double eta, double out[2]);
int pc_frame_coords(const double o[2], const double e[2], const double x[2], double *xi,
                    double *eta);

/* The patch from four side curves (example 25's six steps, the formulas of example 28;
 * generalised to any side curves as in the proposal for example 29).  The sides run
 * S0: A0 -> A1, S1: A1 -> A2, S2: A2 -> A3, S3: A3 -> A0, each over [0, 1].  For (t1, t2):
 *   U0 = S0(t1), U2 = S2(1 - t1);
 *   (xi1, eta1) = frame coordinates of S1(t2) in the frame (A1, A2 - A1);
 *   (xi3, eta3) = frame coordinates of S3(1 - t2) in the frame (A0, A3 - A0) (side 3 reversed);
 *   xi = xi3 + t1 (xi1 - xi3), eta = eta3 + t1 (eta1 - eta3);
 *   X = U0 + xi (U2 - U0) + eta perp(U2 - U0).
 * So X(t1, 0) = S0(t1), X(1, t2) = S1(t2), X(t1, 1) = S2(1 - t1), X(0, t2) = S3(1 - t2).
 * This function does the last two lines. */
void pc_patch_blend(const double u0[2], const double u2[2], double xi1, double eta1, double xi3,
                    double eta3, double t1, double out[2]);

/* The plane onto the open square (examples 26-28): p / sqrt(p^2 + 1) in (-1, 1), and
 * .5 p / sqrt(p^2 + 1) + .5 in (0, 1).  +-inf go to +-1 (0 and 1). */
double pc_squash(double p);
double pc_squash01(double p);

/* The oblique projection by four screen points (examples 32-34):
 *   C1 = C0 + r (cos u, -k sin u),  C2 = C0 + r (cos(u + pi/2), -k sin(u + pi/2)),
 *   C3 = C0 + (0, -r)
 * into c[8] = C0, C1, C2, C3 (x, y pairs); and the image of a 3-D point:
 *   C0 + x (C1 - C0) + y (C2 - C0) + z (C3 - C0). */
void pc_oblique_axes(const double c0[2], double r, double k, double u, double c[8]);
void pc_project4(const double c[8], double x, double y, double z, double out[2]);
/* The same projection as a 3-D -> 2-D map of the one map type (the affine map of the frame C0,
 * C1 - C0, C2 - C0, C3 - C0): pc_map_frame's status. */
int pc_map_project4(pc_map *f, const double c[8]);

/* The Moebius automorphism of the unit disc (examples 15, 16):
 *   w = e^(i phi) (z - z0) / (1 - conj(z0) z)
 * on complex numbers given as (re, im) pairs.  It maps the disc onto itself, the circle to
 * itself and z0 to 0.  PC_EPOLE when 1 - conj(z0) z = 0 (z = 1/conj(z0), outside the disc
 * when |z0| < 1). */
int pc_mobius(double z0re, double z0im, double phi, double re, double im, double *wre,
              double *wim);
/* The parameters of the inverse map: z0' = -z0 e^(i phi), phi' = -phi. */
void pc_mobius_inverse(double z0re, double z0im, double phi, double *z0re_inv,
                       double *z0im_inv, double *phi_inv);

#endif
