/* The one surface type of the core: a point function S(u, v) over [u0, u1] x [v0, v1].
 *
 * Kinds (Buimov ch. 5, Korotky's conic surfaces, Stepanov's ruled surfaces):
 *   PC_SURF_BEZIER     tensor-product Bezier of degrees (p, q), rational through weights:
 *                      (p+1)(q+1) homogeneous control points, row i (along u) major;
 *                      the bilinear surface is p = q = 1, the bicubic Hermite patch a
 *                      constructor giving p = q = 3.
 *   PC_SURF_BSPLINE    tensor-product B-spline / NURBS with a knot vector in each direction.
 *   PC_SURF_RULED      (1 - v) C0(u) + v C1(u) of two curves.
 *   PC_SURF_COONS      the linear Coons patch of four boundary curves.
 *   PC_SURF_REVOLUTION a curve turned about an axis (point a, direction d) by v radians.
 *   PC_SURF_FUNC       a callback (a Lua function, a point equation).
 * Surfaces are immutable and reference counted like curves; iso-curves are pc_curves. */
#ifndef PC_SURFACE_H
#define PC_SURFACE_H
#include "curve.h"
#include "why.h"
#include "why_call.h"

typedef enum {
    PC_SURF_BEZIER, PC_SURF_BSPLINE, PC_SURF_RULED, PC_SURF_COONS, PC_SURF_REVOLUTION,
    PC_SURF_FUNC
} pc_surface_kind;

/* The callback of a FUNC surface: the homogeneous value at (u, v) into out (dim+1); with
 * order 1 also dS/du and dS/dv (3 rows).  PC_EDOMAIN if it cannot give derivatives (the core
 * then differences). */
typedef int (*pc_surface_fn)(void *ud, double u, double v, int order, double *out);

typedef struct pc_surface {
    int refs;
    pc_surface_kind kind;
    int dim;
    int pdeg, qdeg;           /* BEZIER, BSPLINE: degrees in u and v */
    int nu, nv;               /* control net: nu x nv rows of dim+1 (row-major, u index outer) */
    double u0, u1, v0, v1;    /* the domain */
    double *cp, *uknots, *vknots;
    pc_curve *curves[4];      /* RULED: C0, C1; COONS: the sides; REVOLUTION: the profile */
    double axis[2 * PC_MAXDIM];   /* REVOLUTION: a point of the axis, then its unit direction */
    pc_surface_fn fn; void (*fn_free)(void *ud); void *ud;   /* FUNC */
} pc_surface;

pc_surface *pc_surface_retain(pc_surface *s);
void pc_surface_release(pc_surface *s);

/* --- constructors (NULL with *status on failure, as for curves) --------------------------- */
/* Bilinear: P00, P10, P01, P11 (Cartesian rows of dim) at (u, v) = (0,0), (1,0), (0,1), (1,1). */
pc_surface *pc_surface_bilinear(int dim, const double *p00, const double *p10,
                                const double *p01, const double *p11, int *status);
/* Bezier patch of degrees p, q: (p+1)(q+1) homogeneous rows, index i*(q+1) + j for the
 * control point B_ij (i along u). */
pc_surface *pc_surface_bezier(int dim, int p, int q, const double *cp, int *status);
/* B-spline patch: nu x nv homogeneous rows, degrees p, q, knot kinds as for curves (uk, vk
 * used when the kind is PC_KNOTS_GIVEN: nu+p+1 and nv+q+1 values), with the curves' domains
 * (OPEN: [0, n-p], UNIFORM: [p, n], PERIODIC: [0, n], the net then wrapped by p rows so that
 * nu or nv in the struct grow by p).  PC_EDIM for degrees outside 1..PC_CURVE_MAXDEG or too
 * few points, PC_EDOMAIN for decreasing knots or an empty domain. */
pc_surface *pc_surface_bspline(int dim, int p, int q, int nu, int nv, const double *cp,
                               pc_knot_kind ukind, const double *uk, pc_knot_kind vkind,
                               const double *vk, int *status);
/* Bicubic Hermite (Coons) patch over [0,1]^2 (Buimov §5.5): corner points P[4], u-tangents
 * Pu[4], v-tangents Pv[4] and twists Puv[4] (rows of dim each), corners in the order
 * (0,0), (1,0), (0,1), (1,1).  Converted exactly to a bicubic Bezier patch. */
pc_surface *pc_surface_hermite(int dim, const double *p, const double *pu, const double *pv,
                               const double *puv, int *status);
/* Ruled surface between c0 and c1 (same dimension; u runs over each curve's own domain,
 * mapped to [0, 1]). */
pc_surface *pc_surface_ruled(pc_curve *c0, pc_curve *c1, int *status);
/* Linear Coons patch over [0,1]^2 from the boundary curves (each over its own domain, mapped
 * to [0, 1]): cu0 = S(u, 0), cu1 = S(u, 1), c0v = S(0, v), c1v = S(1, v).  The corners must
 * agree within 1e-9 times the largest corner coordinate (PC_EDOMAIN if they do not meet, or
 * if one is at infinity); the patch keeps the mean of the two ends at each corner in cp
 * (P00, P10, P01, P11). */
pc_surface *pc_surface_coons(pc_curve *cu0, pc_curve *cu1, pc_curve *c0v, pc_curve *c1v,
                             int *status);
/* The profile (a 3-D curve, u over its domain) turned about the axis through a with
 * direction d by v in [v0, v1] radians (0 .. 2 pi for a whole surface).  PC_EZERO for d = 0,
 * PC_EDIM unless 3-D. */
pc_surface *pc_surface_revolution(pc_curve *profile, const double *a, const double *d,
                                  double v0, double v1, int *status);
/* A FUNC surface over [u0, u1] x [v0, v1] (u0 < u1, v0 < v1).  fn_free (may be NULL) is called
 * with ud at the last release; on failure the caller keeps ud. */
pc_surface *pc_surface_func(int dim, double u0, double u1, double v0, double v1,
                            pc_surface_fn fn, void (*fn_free)(void *ud), void *ud, int *status);

/* --- evaluation --------------------------------------------------------------------------- */
/* The homogeneous value at (u, v) (dim+1) and, with order 1, its partial derivatives d/du
 * and d/dv after it (3 rows of dim+1).  Parameters outside the domain extrapolate (the
 * patch's polynomial, the end spans, the curves' own extrapolation).  The curve-based kinds
 * give weight 1 (and 0 for the derivatives); where one of their curves is at infinity the
 * status is PC_IMPROPER and out is zero.  PC_EDOMAIN from a FUNC callback that cannot give
 * derivatives. */
int pc_surface_eval_h(const pc_surface *s, double u, double v, int order, double *out);
/* Cartesian point (dim), PC_IMPROPER at a point at infinity (out: the homogeneous
 * coordinates as they are, the direction). */
int pc_surface_eval(const pc_surface *s, double u, double v, double *out);
/* Point, dS/du, dS/dv (3 rows of dim), Cartesian (quotient rule for rational patches; central
 * differences, one-sided at the edge of a callback's domain, for a FUNC surface whose
 * callback returns PC_EDOMAIN for order 1).  PC_IMPROPER at a point at infinity. */
int pc_surface_partials(const pc_surface *s, double u, double v, double *out);
/* Unit normal dS/du x dS/dv (3-D only: PC_EDIM otherwise; PC_EZERO where it vanishes). */
int pc_surface_normal(const pc_surface *s, double u, double v, double *n);
/* The iso-curve u = const (dir 0: a curve in v) or v = const (dir 1: a curve in u), over the
 * surface's own parameter.  Exact (a Bezier / B-spline curve whose control points are the
 * net's columns / rows reduced at value) for tensor-product patches, a FUNC curve holding a
 * reference to the surface otherwise (closed for a whole turn of a revolution).  PC_EDOMAIN
 * for another dir. */
pc_curve *pc_surface_iso(pc_surface *s, int dir, double value, int *status);
/* The image under a map (f->nin == dim, else PC_EDIM): the net mapped exactly for tensor
 * patches (a projective map keeps them rational), a FUNC surface holding a reference to s
 * otherwise. */
pc_surface *pc_surface_map(pc_surface *s, const pc_map *f, int *status);

/* The explanations of the statuses of the surface constructors and of s:shade, by the names
 * the bindings give them (surface_why.c). */
extern const pc_why pc_surface_why[];
/* pc_surface_eval, pc_surface_partials and pc_surface_normal for the call op, their geometric
 * failures explained in why (why_call.h): a point at infinity ("the point at (0.5, 1) is at
 * infinity"), a surface not 3-D and a singular point for the normal; another failure leaves why
 * empty. */
int pc_surface_eval_checked(const char *op, const pc_surface *s, double u, double v, double *out, pc_why_call *why);
int pc_surface_partials_checked(const char *op, const pc_surface *s, double u, double v,
                                double *out, pc_why_call *why);
int pc_surface_normal_checked(const char *op, const pc_surface *s, double u, double v, double *n, pc_why_call *why);

/* --- internal to stdlib/geom/surface*.c (not an API) ------------------------------------- */
pc_surface *pc_surf_alloc(pc_surface_kind kind, int dim, int *status);
int pc_surf_tensor_eval_h(const pc_surface *s, double u, double v, int order, double *out);
pc_curve *pc_surf_tensor_iso(const pc_surface *s, int dir, double value, int *status);
pc_surface *pc_surf_tensor_map(const pc_surface *s, const pc_map *f, int *status);
int pc_surf_curves_eval_h(const pc_surface *s, double u, double v, int order, double *out);

#endif
