/* The one curve type of the core (in the spirit of TinySpline's single struct).
 *
 * Control points are homogeneous values of dimension dim (dim+1 doubles: w x1, ..., w xn | w,
 * see point.h), so weights give rational curves and conics from the same code, and a curve
 * may pass through points at infinity (weight 0).  Three representations:
 *
 *   PC_CURVE_BEZIER   piecewise Bezier: nseg segments of one degree p over the breakpoints
 *                     knots[0] < ... < knots[nseg]; ncp = nseg p + 1 control points, a
 *                     segment's last one being the next one's first.  A single Bezier curve
 *                     of any degree is nseg = 1.  Piecewise cubic Hermite data (cubic,
 *                     Ferguson and Hermite splines) and interpolation through nodes are
 *                     constructors of this kind.
 *   PC_CURVE_BSPLINE  B-spline / NURBS of degree p with ncp control points and a
 *                     non-decreasing knot vector of ncp + p + 1 knots (open, uniform,
 *                     periodic and repeated knots); the domain is [knots[p], knots[ncp]].
 *   PC_CURVE_FUNC     a function of t given by a callback (Stepanov's strokes and Fourier
 *                     curves, point equations, a Lua function): derivatives come from the
 *                     callback when it offers them, else from central differences.
 *
 * Curves are immutable once built and reference counted (pc_curve_retain/release), so a
 * split, a mapped copy or a surface can share them.  Every operation works on every kind:
 * evaluate, derivatives, split, arc length, curvature, bounding box, map, flatten. */
#ifndef PC_CURVE_H
#define PC_CURVE_H
#include <stddef.h>
#include <stdint.h>
#include "point.h"
#include "map.h"

#define PC_CURVE_MAXDEG 64        /* largest Bezier / B-spline degree */

typedef enum { PC_CURVE_BEZIER, PC_CURVE_BSPLINE, PC_CURVE_FUNC } pc_curve_kind;

/* The callback of a FUNC curve: the homogeneous value at t and its derivatives up to `order`
 * (0, 1 or 2) into out ((order+1) rows of dim+1).  Return PC_OK, PC_EDOMAIN when it cannot
 * give derivatives of that order (the core then differences order-0 values), or another
 * status (the evaluation fails with it; a binding may keep its own error object). */
typedef int (*pc_curve_fn)(void *ud, double t, int order, double *out);

/* The callback object, shared by a FUNC curve and its splits and maps.  (The typedef is not
 * named pc_curve_func: in C that would clash with the constructor pc_curve_func below.) */
typedef struct pc_curve_func {
    int refs;
    pc_curve_fn eval;
    void (*free)(void *ud);      /* called with ud when the last curve using it goes; may be NULL */
    void *ud;
} pc_curve_callback;

typedef struct pc_curve {
    int refs;
    pc_curve_kind kind;
    int dim;              /* dimension of the points, 1..PC_MAXDIM */
    int degree;           /* BEZIER, BSPLINE */
    int ncp;              /* control points: ncp rows of dim+1 in cp */
    int nknots;           /* BEZIER: nseg + 1 breakpoints; BSPLINE: ncp + degree + 1;
                             FUNC: 0, or its breakpoints (pc_curve_func_breaks) */
    int closed;           /* the curve ends where it starts (periodic, closed strokes, ...) */
    double t0, t1;        /* the parameter domain */
    double *cp, *knots;
    pc_curve_callback *func;  /* FUNC */
} pc_curve;

/* --- life ---------------------------------------------------------------------------------- */
pc_curve *pc_curve_retain(pc_curve *c);
void pc_curve_release(pc_curve *c);            /* frees at the last reference; NULL is fine */

/* --- constructors: each returns a new curve (one reference) or NULL with *status set -------
 * Homogeneous rows are dim+1 doubles (weighted coordinates, then the weight); a weight of 0
 * is a control point at infinity.  Sizes beyond the limits give PC_EDIM, NaN/inf PC_ENONFINITE,
 * malloc failure PC_ENOMEM. */

/* A Bezier curve of degree ncp-1 over [0, 1]. */
pc_curve *pc_curve_bezier(int dim, int ncp, const double *cp, int *status);
/* Piecewise Bezier: nseg segments of `degree` (nseg*degree + 1 rows) over the breakpoints
 * brk (nseg+1, increasing; NULL: 0, 1, ..., nseg).  PC_EDOMAIN if brk does not increase. */
pc_curve *pc_curve_bezier_pieces(int dim, int degree, int nseg, const double *cp,
                                 const double *brk, int *status);

typedef enum {
    PC_KNOTS_GIVEN,       /* knots[] as passed: ncp + degree + 1 non-decreasing values */
    PC_KNOTS_OPEN,        /* clamped uniform: degree+1 equal knots at each end, the curve
                             starts at the first control point and ends at the last */
    PC_KNOTS_UNIFORM,     /* 0, 1, 2, ... (the curve starts near the second control point) */
    PC_KNOTS_PERIODIC     /* closed: the first `degree` control points are repeated at the
                             end and the knots are uniform, giving a closed C^(p-1) curve */
} pc_knot_kind;
/* B-spline / NURBS of `degree` (1 <= degree < ncp, or degree <= ncp for PERIODIC).  PC_EDOMAIN
 * if the given knots decrease or a span of the domain is empty throughout. */
pc_curve *pc_curve_bspline(int dim, int degree, int ncp, const double *cp, pc_knot_kind kk,
                           const double *knots, int *status);

/* Piecewise cubic Hermite through n nodes p (n rows of dim, Cartesian) at the parameters u
 * (n, increasing; NULL: 0..n-1) with the derivative d/du leaving each node dout and arriving
 * din (n rows of dim each; din NULL means din = dout: a C1 curve).  closed: one more segment
 * from node n-1 back to node 0, over [u[n-1], u[n-1] + (u[1] - u[0])] when u is given. */
pc_curve *pc_curve_hermite(int dim, int n, const double *p, const double *dout,
                           const double *din, const double *u, int closed, int *status);

typedef enum { PC_END_NATURAL, PC_END_CLAMPED, PC_END_PERIODIC } pc_end_kind;
/* The C2 cubic spline through n >= 2 nodes p (n rows of dim) at the parameters u (NULL: the
 * chord lengths, accumulated; as in Buimov §4.2): natural ends (second derivative 0),
 * clamped (first derivatives d0 and d1 given, rows of dim) or periodic (the last node must
 * equal the first).  Solves the tridiagonal system (linalg.h) and returns a Hermite curve. */
pc_curve *pc_curve_cubic_spline(int dim, int n, const double *p, const double *u,
                                pc_end_kind ends, const double *d0, const double *d1,
                                int *status);

/* The polynomial curve of degree n-1 through n nodes p (n rows of dim) at the distinct
 * parameters u (NULL: 0, 1/(n-1), ..., 1), as a Bezier curve over [min u, max u]
 * (Konopatsky's interpolation curves).  PC_ECOINCIDENT for repeated parameters. */
pc_curve *pc_curve_interpolate(int dim, int n, const double *p, const double *u, int *status);

/* A curve given by a callback over [t0, t1] (fn_free may be NULL).  On failure fn_free is
 * not called: the caller keeps ud. */
pc_curve *pc_curve_func(int dim, double t0, double t1, int closed, pc_curve_fn eval,
                        void (*fn_free)(void *ud), void *ud, int *status);
/* The same with breakpoints t0 < brk[0] < ... < brk[nbrk-1] < t1 where the function may be
 * less smooth (the joints of a stroke's pieces): flattening, arc length and the bounding box
 * start from them as from a Bezier curve's breakpoints.  They are kept in knots (t0, brk...,
 * t1: nknots = nbrk + 2; a FUNC curve without breaks has nknots = 0).  PC_EDOMAIN if brk does
 * not increase inside (t0, t1). */
pc_curve *pc_curve_func_breaks(int dim, double t0, double t1, int closed, int nbrk,
                               const double *brk, pc_curve_fn eval, void (*fn_free)(void *ud),
                               void *ud, int *status);

/* --- evaluation --------------------------------------------------------------------------- */
/* The homogeneous value at t and its derivatives up to order 0..2 (out: (order+1) rows of
 * dim+1).  t outside the domain extrapolates the end piece (a Bezier's polynomial, the
 * B-spline's end span).  Status from a FUNC callback, or PC_ENONFINITE. */
int pc_curve_eval_h(const pc_curve *c, double t, int order, double *out);
/* The value at t as c(t) shows it (dim + 1 doubles): a point of weight 1 (divided by the
 * weight), or a vector (weight exactly 0, the coordinates as they are).  pc_curve_eval_h's status. */
int pc_curve_value(const pc_curve *c, double t, double *out);
/* The Cartesian point at t (dim doubles).  PC_IMPROPER if the weight is 0 (out is then the
 * direction, the homogeneous coordinates as they are). */
int pc_curve_eval(const pc_curve *c, double t, double *out);
/* The Cartesian point and its derivatives up to order (quotient rule for rational curves):
 * out holds (order+1) rows of dim.  PC_IMPROPER at a point at infinity. */
int pc_curve_derivs(const pc_curve *c, double t, int order, double *out);
/* Derivatives of any order 0..PC_CURVE_MAXDEG at t, taken on one side of a joint: side -1 the
 * piece ending at t, +1 the piece starting there, 0 the default (the piece starting at t, the
 * last piece at the end of the domain), the same pieces as pc_curve_eval_h uses.  Bezier and
 * B-spline curves differentiate their piece's control points exactly (orders beyond the
 * degree are 0 for the homogeneous values, not for a rational curve's points); FUNC curves
 * give orders up to 2 (PC_EDOMAIN beyond) and have no sides.  eval_hn: (order+1) rows of
 * dim+1; derivs_n: (order+1) rows of dim, Leibniz's rule for the weight (PC_IMPROPER at a
 * point at infinity). */
int pc_curve_eval_hn(const pc_curve *c, double t, int order, int side, double *out);
int pc_curve_derivs_n(const pc_curve *c, double t, int order, int side, double *out);
/* The power-basis coefficients of piece `piece` (0-based: Bezier segment, or non-empty
 * B-spline span) in the curve's own parameter t: H(t) = sum_j coef_j t^j, coef (degree + 1
 * rows of dim + 1: the weighted coordinates and the weight polynomial; a polynomial curve has
 * weight coefficients 1, 0, ...), *degree gets the degree.  PC_EDOMAIN for a FUNC curve or a
 * piece out of range. */
int pc_curve_monomial(const pc_curve *c, int piece, double *coef, int *degree);
/* The pieces pc_curve_monomial counts: Bezier segments, non-empty B-spline spans (FUNC: 0). */
int pc_curve_npieces(const pc_curve *c);
/* pc_curve_monomial by coordinate: rows[x (degree + 1) + j] the coefficient of t^j of the
 * weighted coordinate x, the weight's last (dim + 1 rows; no -0); *rational is 1 when the
 * weight polynomial is not 1 (within 1e-12). */
int pc_curve_monomial_rows(const pc_curve *c, int piece, double *rows, int *degree, int *rational);
/* Curvature at t: signed in the plane (positive turning counter-clockwise for y up),
 * |C' x C''| / |C'|^3 otherwise.  PC_EZERO where C' = 0. */
int pc_curve_curvature(const pc_curve *c, double t, double *k);
/* The unit tangent e at t and, when nrm is not NULL, the unit principal normal: in the plane
 * the tangent turned by +90 degrees, otherwise the part of C'' across the tangent, normalised.
 * PC_IMPROPER where the curve is at infinity, PC_EZERO where C' = 0 (a cusp or a stop),
 * PC_ECOLLINEAR where C'' is along C' in space (a straight stretch: no principal normal). */
int pc_curve_frame(const pc_curve *c, double t, double *e, double *nrm);

/* --- operations --------------------------------------------------------------------------- */
/* The two parts of c at t (t0 < t < t1): left over [t0, t], right over [t, t1], each the same
 * kind (de Casteljau for Bezier pieces, knot insertion for B-splines, a narrower domain for
 * FUNC).  PC_EDOMAIN if t is not inside the domain. */
int pc_curve_split(const pc_curve *c, double t, pc_curve **left, pc_curve **right);
/* A B-spline with the knot u inserted once (Boehm): the same curve, one more control point.
 * PC_EDOMAIN for other kinds or u outside the domain, or a knot already of full multiplicity. */
pc_curve *pc_curve_insert_knot(const pc_curve *c, double u, int *status);
/* The part of c over [a, b] (a < b inside the domain), same kind. */
pc_curve *pc_curve_sub(const pc_curve *c, double a, double b, int *status);
/* Arc length over [a, b] (adaptive Gauss-Legendre on |C'| to relative tolerance tol, piece
 * by piece).  PC_IMPROPER if the curve passes through infinity there. */
int pc_curve_length(const pc_curve *c, double a, double b, double tol, double *len);
/* Axis-aligned bounding box of the part over the domain: lo, hi (dim each), within tol. */
int pc_curve_bbox(const pc_curve *c, double tol, double *lo, double *hi);
/* The image of c under f (f->nin == c->dim): control points mapped exactly (a projective map
 * keeps a rational curve rational), FUNC curves wrapped.  PC_EDIM on a dimension mismatch. */
pc_curve *pc_curve_map(const pc_curve *c, const pc_map *f, int *status);

/* --- flattening ---------------------------------------------------------------------------- */
/* A polyline in the plane, possibly broken into pieces: vertex i is (xy[2i], xy[2i+1]) and
 * starts a new piece when move[i] is 1.  clip, when set, is the part of the plane that will be
 * seen (xmin, ymin, xmax, ymax, with a margin): flattening does not subdivide a piece whose
 * control polygon lies outside it (the polyline just moves past it), so the cost of a drawing
 * follows what is visible.  No polyline has more than PC_POLYLINE_MAX vertices (pushing more
 * is PC_ENOMEM). */
#define PC_POLYLINE_MAX ((size_t)1 << 22)
typedef struct {
    double *xy;
    uint8_t *move;
    size_t n, cap;
    const double *clip;
} pc_polyline;
void pc_polyline_free(pc_polyline *pl);     /* frees the arrays, leaves an empty polyline */
int pc_polyline_push(pc_polyline *pl, double x, double y, int move);

/* How a homogeneous value (dim+1) becomes a point of the plane in which the tolerance is
 * measured (the current projection, then WINDOW and VIEW, down to screen pixels).  Return
 * PC_OK, or PC_IMPROPER / PC_ENONFINITE where there is no finite image. */
typedef int (*pc_project_fn)(void *ud, const double *h, double xy[2]);

/* Append to out an adaptive polyline of c over [a, b] whose distance from the projected
 * curve is at most tol (in the projected plane; e.g. 0.25 px).  proj NULL: the curve must be
 * 2-D and its Cartesian coordinates are used.  Where the curve passes through a point at
 * infinity, or its image is not finite, the polyline is broken (the next vertex has move = 1)
 * instead of drawn across.  Subdivision starts at the breakpoints/knots and at least 8 pieces
 * per piece of the curve, and stops at a depth limit (then the chord is accepted).  Returns
 * PC_OK or PC_ENOMEM (a callback's error status is returned as is). */
int pc_curve_flatten(const pc_curve *c, double a, double b, pc_project_fn proj, void *ud,
                     double tol, pc_polyline *out);
/* The same through a projective map m to the plane (m->nin == dim, m->nout == 2; NULL for a
 * 2-D curve as it is).  Bezier and B-spline pieces are flattened by halving their mapped
 * control polygons until it is within tol of its chord (a piece lies in the hull of its
 * control points while its weights keep one sign), which evaluates no points; pieces through
 * infinity and FUNC curves are sampled as pc_curve_flatten does. */
int pc_curve_flatten_map(const pc_curve *c, double a, double b, const pc_map *m, double tol,
                         pc_polyline *out);

#endif
