/* Interpolation curves of Konopatsky's chapter 4 (digest konopatsky_ch3_5.md §2) beyond
 * pc_curve_interpolate (curve.h), which is the book's "interpolation curve from a Bezier curve"
 * through n+1 points: the book's method equals Lagrange interpolation in t, so its weights are
 * the Lagrange cardinal polynomials and its control points those of that Bezier curve.
 * Points are Cartesian rows of dim; curves are new curves or NULL with *status set. */
#ifndef PC_KONOP_INTERP_H
#define PC_KONOP_INTERP_H

#include <stddef.h>

#include "curve.h"
#include "why_call.h"

/* The weights phi_j(t) of the interpolation curve through n nodes at the distinct params
 * (NULL: uniform j/(n-1)), i.e. M(t) = sum M_j phi_j(t); they sum to 1 (§4.2-4.7: the book's
 * (4.10), (4.16), (4.21), (4.25), (4.28) are these for n = 3..7).  PC_ECOINCIDENT for
 * repeated params, PC_ENONFINITE for a t so far outside the nodes that a weight overflows. */
int pc_lagrange_weights(int n, const double *params, double t, double *w);
/* The same weights as polynomials in t, as the Maple program of §4.8 prints them (collect(e,
 * SM)): coef row j (n numbers) holds phi_j = sum_i coef[j n + i] t^i.  Errors as above. */
int pc_lagrange_weight_coefs(int n, const double *params, double *coef);

/* §4.9 Interpolation contour arc: the Bezier curve through the p >= 2 points (at uniform
 * u = (j - 1)/(p - 1)) with the tangent handles c2 (M'(0) = N (c2 - M1)) and cn (M'(1) =
 * N (Mp - cn)); cn NULL keeps the start tangent only.  Degree N = p + 1 (two tangents) or p. */
pc_curve *pc_interp_arc(int dim, int p, const double *pts, const double *c2, const double *cn,
                        int *status);
/* The same at the node parameters params (p increasing values; NULL: uniform): the curve runs
 * over [params[0], params[p-1]] and passes M_j at params[j].  PC_EDOMAIN when they do not
 * increase. */
pc_curve *pc_interp_arc_u(int dim, int p, const double *pts, const double *params,
                          const double *c2, const double *cn, int *status);

/* §4.10 Adaptive parameters v_j = (x_1 - x_j)/(x_1 - x_n) from coordinate `axis` (0-based) of
 * the nodes.  PC_ECOINCIDENT if x_1 = x_n, PC_EDOMAIN if v does not increase (the book's
 * limitation: the order of the nodes must be the order of the parameters). */
int pc_interp_adaptive_params(int dim, int n, const double *pts, int axis, double *v);
/* What failed in pc_interp_adaptive_params with status st on that axis, as text into buf (n
 * bytes); 0 (nothing written) for a status it does not explain. */
int pc_interp_adaptive_why(int st, int axis, char *buf, size_t n);
/* interp.adaptive: pc_interp_adaptive_params on axis 1..dim (counted from 1), each failure
 * explained by w: an axis outside 1..dim (argument 2), then pc_interp_adaptive_why's. */
int pc_interp_adaptive(int dim, int n, const double *pts, int axis, double *v, pc_why_call *w);

/* §4.11 The simplex-replacement engine on any prototype: basis functions g_1..g_n (g(ud, t, n,
 * out) fills n values, non-zero status fails), nodes M_j at params t_j; the collocation matrix
 * G_ji = g_i(t_j) is inverted once and M(t) = sum_j M_j phi_j(t), phi_j = sum_i g_i (G^-1)_ij.
 * The curve is evaluated coordinatewise as the book does, so a basis whose phi do not sum to 1
 * (the exponential (4.39)) depends on the origin.  Domain [t0, t1] (both NaN: from the least
 * to the greatest param).  PC_ESINGULAR if the collocation matrix is singular, PC_EDOMAIN2
 * unless t0 < t1. */
typedef int (*pc_basis_fn)(void *ud, double t, int n, double *g);
pc_curve *pc_interp_basis(int dim, int n, const double *pts, const double *params,
                          pc_basis_fn g, void (*fn_free)(void *ud), void *ud, double t0,
                          double t1, int *status);

/* The membership condition of that engine's curve (ch. 1: the weights of a point equation sum
 * to 1, so the curve does not depend on the origin): *dev gets the largest |sum_j phi_j(t) - 1|
 * over the params and `samples` >= 2 uniform t in [t0, t1].  The Bezier, Desargues (4.35),
 * fractional-rational (4.37) and trigonometric (4.40) prototypes give round-off; the
 * exponential (4.39) does not (its weights are cardinal but do not sum to 1). */
int pc_interp_basis_membership(int n, const double *params, pc_basis_fn g, void *ud, double t0,
                               double t1, int samples, double *dev);

typedef enum {
    PC_PROTO_DESARGUES,   /* (3.6) -> (4.35), 4 nodes at 0, 1/3, 2/3, 1 */
    PC_PROTO_RATIONAL,    /* (4.36) (A t^3 + B t^2 + C t + D)/(t^3 + t^2 + t + 1) -> (4.37) */
    PC_PROTO_EXP,         /* (4.39) A1 e^(k1 t) + A2 e^(k2 t) + A3 e^(k3 t), 3 nodes at 0, 1/2, 1 */
    PC_PROTO_EXP_AFFINE,  /* the constrained variant: e^(k1 t), e^(k2 t), 1 - both */
    PC_PROTO_TRIG         /* (4.40) (A1 - A2)cos t + (A3 - A2)sin t + A2, nodes 0, pi/2, pi */
} pc_proto_kind;
/* How many nodes (points) the prototype takes, and how many exponents k (0 for most). */
void pc_interp_prototype_shape(pc_proto_kind kind, int *n, int *nk);
/* The prototype's interpolation curve through its nodes (4 or 3 points, as above) at the
 * book's params, over [t0, t1] (NaN: the params' range); k: the exponents (2 or 3). */
pc_curve *pc_interp_prototype(pc_proto_kind kind, int dim, int n, const double *pts,
                              const double *k, double t0, double t1, int *status);
/* The weights of a prototype's curve at t (n of them). */
int pc_interp_prototype_weights(pc_proto_kind kind, int n, const double *k, double t, double *w);

/* (4.38) The rational (2,2) curve through 5 points at t = 0, 1/4, 1/2, 3/4, 1, each
 * coordinate its own (a1 t^2 + a2 t + a3)/(a4 t^2 + a5 t + 1) (not a point equation);
 * coef (may be NULL) gets dim rows of a1..a5.  PC_ESINGULAR if a coordinate has no such fit. */
pc_curve *pc_interp_rational22(int dim, const double *pts, double *coef, int *status);

#endif
