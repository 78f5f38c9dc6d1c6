/* The one map type of the core: a projective map of homogeneous coordinates.
 *
 * A map from nin-space to nout-space is an (nout+1) x (nin+1) matrix M acting on a value
 * h = (x1 w, ..., xn w | w) as a column vector: h' = M h.  The last row makes the new weight,
 * so a map whose last row is (0 ... 0 | 1) is affine (it keeps points points and vectors
 * vectors), and any other is projective: a point at infinity (a vector) may go to a finite
 * point, which is how a perspective sends a direction to its vanishing point.
 *
 * Affine maps by point correspondences (Konopatsky's change of simplex, §1.2.2), the
 * textbook's matrices (Buimov: row vectors, p' = p T, composed left to right) and every
 * 3-D -> 2-D projection are constructors of this one type, so any two maps of fitting
 * dimensions compose.  No function here allocates.
 *
 * A scale of the whole matrix does not change a projective map; the results of
 * pc_map_from_matrix (for a last row (0 ... 0 | s), the textbook's overall scale), of
 * pc_map_compose and of pc_map_inverse are divided by their corner entry when it is neither 0
 * nor 1, so an affine map always has the last row (0 ... 0 | 1) exactly and keeps weights. */
#ifndef PC_MAP_H
#define PC_MAP_H
#include <stddef.h>
#include "point.h"

typedef struct {
    int nin, nout;                                   /* dimensions of the points in and out */
    double m[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)];     /* (nout+1) rows of nin+1, row-major */
} pc_map;
#define PC_MAP_AT(f, i, j) ((f)->m[(i) * ((f)->nin + 1) + (j)])

/* --- general ------------------------------------------------------------------------------ */
void pc_map_identity(pc_map *f, int n);
/* From a matrix of (nout+1) x (nin+1) numbers, row-major, in the column-vector convention
 * above (rowvec = 0), or from the textbook's (nin+1) x (nout+1) matrix T of p' = p T
 * (rowvec = 1; T is the transpose of M).  PC_EDIM on bad sizes, PC_ENONFINITE for NaN/inf,
 * PC_ESINGULAR for the zero matrix (it sends everything to weight 0 and zero coordinates).
 * A last row (0 ... 0 | s), s != 0, is divided out (the textbook's overall scale: x* = x/s),
 * which gives an affine map. */
int pc_map_from_matrix(pc_map *f, int nin, int nout, const double *a, int rowvec);
/* The matrix in either convention, into a ((nin+1) * (nout+1) doubles; no -0). */
void pc_map_to_matrix(const pc_map *f, int rowvec, double *a);
/* Is the last row (0 ... 0 | 1) (exactly)? */
int pc_map_is_affine(const pc_map *f);

/* Apply to a value: in has nin+1 doubles (weight last), out nout+1: out = M in, raw (a
 * projective map gives any weight). */
void pc_map_apply(const pc_map *f, const double *in, double *out);
/* The image of a value as the point calculus reads it (in place is fine).  An affine map:
 * pc_map_apply (weights kept, vectors stay vectors).  A projective map: M in scaled so that
 * the weight is that of `in` (a point stays a point, k A goes to k f(A)), and a direction
 * whose image is finite gives its point, weight 1 (a vanishing point).  An image whose
 * weight cancels to rounding (relative 1e-13) is a direction, weight exactly 0: PC_IMPROPER
 * when `in` had a weight (a point sent to infinity), PC_OK for a direction.  PC_EPOLE if a
 * nonzero value goes to the zero value (the centre of a central projection). */
int pc_map_image(const pc_map *f, const double *in, double *out);
/* map_text.c: the image by the one weight rule (point.h): pc_map_image, its weight snapped
 * to 1 or 0 within PC_WEIGHT_TOL; a raw weight within it of 0 is a direction
 * (map.matrix({{1, 0, 0}, {0, 1, 0}, {0, 1e-17, 1}}) sends V(0, 1) to V(0, 1), not to
 * P(0, 1e17)): PC_IMPROPER for a point sent there, PC_EPOLE for the zero image,
 * PC_ENONFINITE for an image that overflowed (map.scale(1e308, 2)(P(10, 10))).  And the map
 * as text: "affine map 2-D -> 2-D [1 0 | 0; 0 1 | 0]", and its matrix aligned under a header
 * naming the convention (rowvec: p' = p T); both return the length the text needs. */
int pc_map_image_rule(const pc_map *f, const double *in, double *out);
size_t pc_map_text(const pc_map *f, char *buf, size_t size);
size_t pc_map_show(const pc_map *f, int rowvec, char *buf, size_t size);
/* h = f o g (g first).  PC_EDIM unless g->nout == f->nin. */
int pc_map_compose(const pc_map *f, const pc_map *g, pc_map *h);
/* PC_EDIM unless nin == nout; PC_ESINGULAR for a singular matrix. */
int pc_map_inverse(const pc_map *f, pc_map *inv);

/* --- affine maps -------------------------------------------------------------------------- */
/* The affine map sending src[i] to dst[i] for i = 0..nin (src: nin+1 rows of nin, dst: nin+1
 * rows of nout): 3 pairs in the plane, 4 in space; nout may differ from nin (4 image points
 * of a 3-D frame in the plane give an oblique projection).  PC_ECOINCIDENT/PC_ECOLLINEAR if
 * the source points are dependent, PC_EDIM on bad sizes. */
int pc_map_affine_points(pc_map *f, int nin, int nout, const double *src, const double *dst);
/* The map of a frame: (x1, ..., xk) -> O + x1 a1 + ... + xk ak, with naxes vectors a_i (rows
 * of nout).  No independence is required (a projection is a valid frame map). */
int pc_map_frame(pc_map *f, int nout, int naxes, const double *o, const double *axes);
/* x -> x + v in n-space. */
void pc_map_translate(pc_map *f, int n, const double *v);
/* x -> c + diag(k) (x - c); c NULL for the origin. */
void pc_map_scale(pc_map *f, int n, const double *k, const double *c);
/* The plane turned by angle (radians, counter-clockwise for y up) about c (NULL: origin). */
void pc_map_rotate2(pc_map *f, double angle, const double *c);
/* Space turned by angle about the axis through point a with direction d (right-hand rule).
 * PC_EZERO for d = 0. */
int pc_map_rotate3(pc_map *f, const double *a, const double *d, double angle);
/* Reflection in the hyperplane through a with normal nrm (a line in the plane, a plane in
 * space).  PC_EZERO for nrm = 0. */
int pc_map_reflect(pc_map *f, int n, const double *a, const double *nrm);
/* Shear: x_i += k x_j (0-based axes i != j).  PC_EDOMAIN for bad axes. */
int pc_map_shear(pc_map *f, int n, int i, int j, double k);

/* --- 3-D -> 2-D projections (Buimov ch. 2; the picture's x to the right, y up) ------------- */
/* Orthographic projection along a coordinate axis, onto the plane where it is 0: 'z' keeps
 * (x, y) (the textbook's Pz), 'y' keeps (x, z), 'x' keeps (y, z).  PC_EDOMAIN else. */
int pc_map_orthographic(pc_map *f, char axis);
/* Axonometric: turn about the y axis by phi, then about the x axis by theta, then drop z
 * (the textbook's general axonometry). */
void pc_map_axonometric(pc_map *f, double phi, double theta);
/* Isometric: phi = 45 deg, theta = asin(tan 30 deg) = 35.26 deg; equal foreshortening
 * sqrt(2/3) on all three axes. */
void pc_map_isometric(pc_map *f);
/* Dimetric with foreshortening fz of the z axis, the x and y axes equal (Buimov §2.8.3:
 * sin^2 theta = fz^2/2, sin^2 phi = fz^2/(2 - fz^2)).  PC_EDOMAIN unless 0 < fz < 1. */
int pc_map_dimetric(pc_map *f, double fz);
/* Oblique: x' = x + k z cos(alpha), y' = y + k z sin(alpha); cavalier k = 1, cabinet k = 1/2. */
void pc_map_oblique(pc_map *f, double k, double alpha);
/* Central projection with the centre (eye) at e onto the picture plane through the point p0
 * perpendicular to the line from e towards p0 (the principal ray); picture coordinates have
 * their origin at p0, x to the right as the eye sees it and y along the projection of `up`
 * (NULL: the z axis) onto the plane; lengths in the picture plane are kept.  The eye goes to
 * the zero value (pc_map_image: PC_EPOLE), points of the plane through the eye parallel to
 * the picture to infinity, a direction to its vanishing point.  (The textbook's one-point
 * perspective with its centre at (0, 0, -k) plots x* = x k/(z + k) unmirrored, which is this
 * picture reflected in its y axis: Buimov convention 8.)  PC_ECOINCIDENT if e = p0, PC_EZERO
 * for up = 0, PC_ECOLLINEAR if up is along the ray, PC_ENONFINITE for NaN or inf. */
int pc_map_perspective(pc_map *f, const double *e, const double *p0, const double *up);

/* --- map_more.c ------------------------------------------------------------------------------ */
/* The textbook's perspective transform by (p, q, r) (Buimov §2.8.5): the 3-D map of row-vector
 * matrix [[1,0,0,p],[0,1,0,q],[0,0,1,r],[0,0,0,1]], h = px + qy + rz + 1, vanishing points
 * (1/p, 0, 0), (0, 1/q, 0), (0, 0, 1/r); one, two or three of them nonzero give the one-, two-
 * and three-point perspectives.  Follow it with a parallel projection. */
int pc_map_perspective_pqr(pc_map *f, double p, double q, double r);
/* The foreshortening factors of an affine map (an axonometry: nin = 3, nout = 2 or 3): the
 * lengths of the images of the unit axis vectors, factors[0 .. nin-1] (Buimov §2.8.3:
 * f_x = sqrt(cos^2 phi + sin^2 phi sin^2 theta), ...).  PC_EDOMAIN for a projective map. */
int pc_map_foreshortening(const pc_map *f, double *factors);
/* The axial affinity of the plane with the axis through a along d, the direction s (not along
 * the axis) and the ratio k: M = A + alpha d + beta s goes to A + alpha d + k beta s.  k = -1
 * is the oblique reflection in the axis, k = 0 the parallel projection onto it.  PC_EZERO for a
 * zero d or s, PC_ECOLLINEAR for s along the axis. */
int pc_map_axial_affinity(pc_map *f, const double a[2], const double d[2], const double s[2],
                          double k);

/* --- map_parts.c ----------------------------------------------------------------------------- */
/* The image (pc_map_image) of the origin (i = 0) or of the unit point of axis i (1..nin): a
 * projection's screen points C0, C1, ...  PC_EDOMAIN for i out of range. */
int pc_map_unit_image(const pc_map *f, int i, double *out);
/* The vanishing points of a map from 3-D to 2-D or 3-D: the images of the x, y and z
 * directions, rows of nout + 1 in out; finite[i] 0 for a direction that stays at infinity.
 * PC_EDIM for other dimensions. */
int pc_map_vanishing_points(const pc_map *f, double out[3][PC_MAXDIM + 1], int finite[3]);
/* What a failure of pc_map_affine_points from nin-D means ("the source points are collinear,
 * so they do not fix an affine map"), and of pc_map_perspective (up_given: whether up was
 * given, else the default z axis); other statuses: pc_strerror. */
const char *pc_map_points_why(int st, int nin);
const char *pc_map_perspective_why(int st, int up_given);

#endif
