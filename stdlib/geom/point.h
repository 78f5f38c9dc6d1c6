/* Point calculus core (Konopatsky, "Modelling geometric objects in point calculus", ch. 1).
 *
 * Values.  A value of dimension n is an array of n+1 doubles in homogeneous form:
 * h[0..n-1] are the weighted coordinates and h[n] is the weight w.  A point (x, y) is
 * (x, y | 1), a vector (dx, dy | 0), k*A is (k x, k y | k), and sums add componentwise.
 * So a point equation whose coefficients sum to 1 (the book's membership condition,
 * "условие принадлежности") yields a point, a difference of points yields a vector, and a
 * meet of parallel lines yields a direction (weight 0, the improper point).
 *
 * Locations.  Metric functions (distances, angles, areas, meets) take plain Cartesian
 * coordinates: arrays of n doubles.  pc_loc() turns a value into a location, refusing any
 * value whose weight is not 1.
 *
 * Status codes: functions that can meet degenerate geometry return PC_OK or an error code
 * and never produce NaN silently.  No function here allocates. */
#ifndef PC_POINT_H
#define PC_POINT_H

#define PC_MAXDIM 16          /* largest dimension of a value, simplex or map */
#define PC_WEIGHT_TOL 1e-9    /* |w - 1| or |w| below this counts as a point or a vector */
#define PC_DEGEN_TOL 1e-10    /* relative size (a sine) below which directions are dependent */
#define PC_ON_TOL 1e-9        /* relative residual below which a point lies on a line */

#include <stddef.h>
#include "status.h"

/* --- weights ------------------------------------------------------------------------------ */
typedef enum { PC_KIND_POINT, PC_KIND_VECTOR, PC_KIND_WEIGHTED } pc_kind;
pc_kind pc_kind_of(double w);                 /* classify a weight with PC_WEIGHT_TOL */
/* weight_rule.c: classify the weight h[n] of a computed value and snap it to exactly 1 (the
 * coordinates divided by it) or 0 within PC_WEIGHT_TOL; returns its pc_kind. */
int pc_snap_weight(int n, double *h);
/* point_text.c: the value h (n + 1 doubles) as text, P(1, 2), V(0, 1) or 2*P(1, 2) (valid Lua
 * that rebuilds it) into buf; returns the length the text needs (as snprintf). */
size_t pc_value_text(int n, const double *h, char *buf, size_t size);

/* Location of a value h (n+1 doubles) into out (n doubles).  PC_OK if the weight is 1
 * (within tolerance; the coordinates are divided by w), else PC_IMPROPER for a vector
 * and PC_EWEIGHT for a weighted value (out is untouched). */
int pc_loc(int n, const double *h, double *out);
/* Divide by the weight (projective normalisation): out = h / w.  PC_IMPROPER if w is 0. */
int pc_normalize(int n, const double *h, double *out);

/* --- arithmetic on values (n+1 doubles, weights included) ---------------------------------- */
void pc_add(int n, const double *a, const double *b, double *out);
void pc_sub(int n, const double *a, const double *b, double *out);
void pc_scale(int n, const double *a, double k, double *out);
/* The values a (n + 1 doubles) and b (m + 1) are the same: one dimension and every double
 * equal (==: -0 is 0, NaN never equal), as P(1, 2) == P(1, 2) is true: 1 or 0. */
int pc_value_same(int n, const double *a, int m, const double *b);
/* (B - A) t + A, eq. of the segment (Fig. 1.1), computed as A(1 - t) + B t so that t = 0
 * and t = 1 give A and B exactly.  Works on values of any weight; two values of one weight give
 * that weight exactly at every t (two points a point, never a vector by rounding).  Large t
 * may overflow the coordinates: PC_ENONFINITE when a number of out is not finite (t not
 * finite, or an overflow), else PC_OK.  n = 1 with weights 1 lerps two numbers a[0], b[0]. */
int pc_lerp(int n, const double *a, const double *b, double t, double *out);

/* --- metric (locations or vector coordinates, n doubles) ------------------------------------ */
double pc_dot(int n, const double *u, const double *v);
double pc_norm(int n, const double *u);
double pc_dist(int n, const double *a, const double *b);
/* Metric operator of three points (§1.4, Fig. 1.11): Σ^A_BC = AH·AB = (B - A)·(C - A), H the
 * foot of the perpendicular from C to AB (the printed "AN·AB" is a misprint, digest §9). */
double pc_sigma(int n, const double *a, const double *b, const double *c);
int pc_unit(int n, const double *u, double *out);               /* PC_EZERO for 0 */
void pc_perp2(const double *u, double *out);                    /* (-y, x): +90° */
double pc_cross2(const double *u, const double *v);             /* z of the 3-D cross */
void pc_cross3(const double *u, const double *v, double *out);
/* Unsigned angle between two vectors, in [0, pi], via atan2(|u^v|, u.v). */
int pc_angle(int n, const double *u, const double *v, double *out);
/* Foot of the perpendicular from C to line AB: H = A + (B - A) Σ^A_BC / Σ^A_BB (§4.10). */
int pc_foot(int n, const double *c, const double *a, const double *b, double *out);

/* --- simple ratio and its relatives (ratio.c) --------------------------------------------- */
/* Simple ratio (XYZ) = XZ/ZY = (X - Z)/(Z - Y) of three collinear points (§2 item 3).
 * X and Y are locations; z is a value (n+1) that may be a point or an improper point
 * (a direction, weight 0: the ratio is then -1).  Z = Y gives +inf. */
int pc_sr(int n, const double *x, const double *y, const double *z, double *lambda);
/* The ratio r = u/v of parallel vectors (u = r v), as in (T - A)/(T_C - A) of (2.62).  n doubles
 * each.  PC_EZERO for v = 0; PC_ENOTCOLLINEAR when the sine of the angle between them exceeds
 * 1e-9, with *angle (may be NULL) that angle in radians, in [0, pi/2]; u = 0 gives 0. */
int pc_vec_ratio(int n, const double *u, const double *v, double *r, double *angle);
/* Z with (XYZ) = lambda: Z = (X + lambda Y)/(1 + lambda), homogeneous.  x, y are values
 * (n+1).  lambda = -1 gives the improper point X - Y (weight 0); lambda = ±inf gives Y.
 * |lambda| > 1 is computed as (X/lambda + Y)/(1/lambda + 1), so a huge lambda gives a point
 * next to Y, not an overflow; PC_ENONFINITE if the result still is not finite. */
int pc_divide(int n, const double *x, const double *y, double lambda, double *out);
/* Harmonic conjugate N of T with respect to A, B: (ABN) = -(ABT).  T may be improper
 * (then N is the midpoint); the midpoint gives the improper point of AB. */
int pc_harmonic(int n, const double *a, const double *b, const double *t, double *out);
/* Cross ratio (ABCD) = (ABC)/(ABD) (eq. 2.98).  A, B locations; C, D values (n+1) that may
 * be improper.  +inf when D = A or C = B. */
int pc_cross_ratio(int n, const double *a, const double *b, const double *c, const double *d,
                   double *out);

/* --- incidence (meet.c) --------------------------------------------------------------------- */
/* Intersection of lines A1A2 and B1B2 in any dimension n >= 2 (§1.3.5, eq. 1.5).
 * PC_OK: out (n+1) is the finite point K = A1 + (A2 - A1) lambda = B1 + (B2 - B1) mu,
 *   weight 1.
 * PC_IMPROPER: the lines are parallel; out is their direction A2 - A1 (weight 0), lambda and
 *   mu are +inf.
 * PC_ESKEW (n >= 3): the lines do not meet; *residual is their distance.
 * PC_ESAME_LINE, PC_ECOINCIDENT (A1 = A2 or B1 = B2), PC_EDIM (n < 2).
 * lambda, mu, residual may be NULL. */
int pc_meet(int n, const double *a1, const double *a2, const double *b1, const double *b2,
            double *out, double *lambda, double *mu, double *residual);
/* The same meet with homogeneous ends (n+1 doubles each), so that a point at infinity (weight
 * 0, a direction) may stand for either end of either line (§1.3.5 with improper points).
 * A value of weight neither 0 nor 1 is normalised first (divided by its weight).
 * - A finite point P and an improper point D (either order): the line through P with
 *   direction D; its parameter is K = P + D lambda.  Two finite points: as pc_meet.
 * - Two improper points: the line at infinity of the plane of their directions.  Its meet with
 *   a finite line is that line's improper point (its direction, as given or B2 - B1) when the
 *   direction lies in the plane (always in 2-D), else PC_ESKEW with *residual = +inf.  Two
 *   lines at infinity: PC_ESAME_LINE in 2-D (there is one); in n-D the direction common to
 *   the two planes (a unit vector, weight 0, PC_IMPROPER), PC_ESAME_LINE for one plane, or
 *   PC_ESKEW (*residual = +inf) for planes with no common direction.
 * - Results as pc_meet: PC_OK and a finite point; PC_IMPROPER and a direction (weight 0) with
 *   lambda = mu = +inf (parallel lines: the common improper point, the direction of line A).
 * Errors: PC_EZERO for an improper point with zero coordinates (no direction), PC_ECOINCIDENT
 * when a line's two ends are the same point (finite, or two parallel directions; line A is
 * checked before line B), PC_ENONFINITE, PC_EDIM (n < 2 or n > PC_MAXDIM). */
int pc_meet_h(int n, const double *a1, const double *a2, const double *b1, const double *b2,
              double *out, double *lambda, double *mu, double *residual);

/* --- measure (measure.c) ------------------------------------------------------------------- */
double pc_area2(const double *a, const double *b, const double *c);   /* signed, 2-D */
/* Signed area of a 2-D polygon of m vertices (pts: m pairs), shoelace formula. */
double pc_polygon_area2(int m, const double *pts);
/* Unsigned area in any dimension: 2S = sqrt(Σ^A_BB Σ^A_CC - (Σ^A_BC)^2) (§4.10, ours). */
double pc_area(int n, const double *a, const double *b, const double *c);
double pc_volume3(const double *a, const double *b, const double *c, const double *d); /* signed */
/* Unsigned measure of the k-simplex with vertices v (k+1 rows of n), from the Gram
 * determinant of its edges: sqrt(det G)/k!. */
double pc_measure(int n, int k, const double *v);

#endif
