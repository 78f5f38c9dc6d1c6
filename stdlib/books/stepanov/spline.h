/* Stepanov's "quadrilateral spline" and the one-stroke curve through nodes
 * (stepanov_examples.md §H rows 7, 8, 25; examples 5, 6, 9, 10, 11, 13, 17, 29, 32, 33, 34).
 *
 * A piece joins node A to node B.  Its quadrilateral is A, P, Q, B with P = A + rout*eout (the
 * outgoing side) and Q = B - rin*ein (the incoming side at B).  For a parameter t:
 *   M = A + t (P - A),   N = Q + t (B - Q),   X = M + g(t) (N - M)
 * with a smoothstep g (g(0) = 0, g(1) = 1, g'(0) = g'(1) = 0), so X(0) = A with direction
 * P - A and X(1) = B with direction B - Q.  t outside [0, 1] extrapolates (example 5).
 * Points are plain arrays of d doubles, d <= PC_CURVE_MAXDIM. */
#ifndef PC_SPLINE_H
#define PC_SPLINE_H

#include "smooth.h"
#include "curve.h"
#include "why_call.h"

#define PC_CURVE_MAXDIM PC_MAXDIM   /* strokes go to every dimension points have */

/* Directions from angles in radians.  2-D: (cos u, -sin u) when ccw is nonzero, the article's
 * w = y - r sin u, counter-clockwise on a y-down screen (examples 10, 11, 17, 32); else
 * (cos u, sin u).  3-D (example 33): e(lon, lat) = (cos lon cos lat, sin lon cos lat, sin lat). */
void pc_dir2(double u, int ccw, double out[2]);
void pc_dir3(double lon, double lat, double out[3]);

/* X = M + g (N - M) as above, for a given value g = g(t). */
void pc_qspline(int d, const double *a, const double *p, const double *q, const double *b,
                double t, double g, double *out);

typedef struct {
    double a[PC_CURVE_MAXDIM], p[PC_CURVE_MAXDIM], q[PC_CURVE_MAXDIM], b[PC_CURVE_MAXDIM];
    pc_gfun g;
} pc_piece;

/* Example 5's piece from A leaving along a to B arriving along b (rows of d): the
 * quadrilateral A, A + a, B - b, B blended by g. */
void pc_spline2_piece(int d, const double *A, const double *a, const double *B, const double *b,
                      const pc_gfun *g, pc_piece *out);

/* X(t) of one piece with its own smoothstep. */
void pc_piece_eval(int d, const pc_piece *pc, double t, double *out);

/* A one-stroke curve through nnodes nodes (example 10's program, any dimension):
 *  - ein/eout: per node the incoming/outgoing direction (rows of d; normalised here).  NULL,
 *    or a row containing a NaN, means the chord tangent N[i+1] - N[i-1] (cyclic when closed,
 *    one-sided at the ends of an open curve), as in the reconstructions of examples 13, 29.
 *    eout NULL means eout = ein.
 *  - rin/rout: per node the side lengths; NULL or a NaN entry means a third of the chord of
 *    the piece that uses it (rout[i]: chord i -> i+1; rin[i]: chord i-1 -> i).
 *  - n, m, t0: per node, the half-spline of the piece leaving that node; NULL means 2, 2, 1/2.
 * An open curve has nnodes - 1 pieces, a closed one nnodes (the last joins node nnodes-1 to
 * node 0). */
typedef struct {
    int d, nnodes, closed;
    const double *nodes;
    const double *ein, *eout;
    const double *rin, *rout;
    const double *n, *m, *t0;
} pc_stroke_spec;

int pc_stroke_npieces(int nnodes, int closed);
/* Fill out[0 .. npieces-1].  PC_EDIM (d out of 1..PC_CURVE_MAXDIM, fewer than 2 nodes),
 * PC_EZERO (a zero direction, or coincident neighbours for a chord tangent),
 * PC_EDOMAIN (bad n, m, t0), PC_ENONFINITE.  On error *bad (if not NULL) is the index
 * of the offending node. */
int pc_stroke_build(const pc_stroke_spec *s, pc_piece *out, int *bad);

/* The stroke of npieces pieces as a FUNC curve of the core (pieces copied): over s in
 * [0, npieces], piece floor(s) at its own t = s - i; the first and last pieces extrapolate
 * outside (as the binding's c(t) does).  Breakpoints at the joints; exact first and second
 * derivatives from the smoothsteps' own.  Where a half-spline of fractional degree does not
 * extrapolate (pc_gfun_check) the evaluation fails with PC_EDOMAIN.  PC_EDIM (d out of
 * 1..PC_CURVE_MAXDIM, npieces < 1), PC_EARG (pieces NULL), PC_ENONFINITE, PC_ENOMEM. */
pc_curve *pc_curve_stroke(int d, int npieces, const pc_piece *pieces, int closed, int *status);

/* A smoothstep given by a callback (a script's function): g(t) into *g; PC_OK or a failure
 * status, with which the evaluation fails. */
typedef int (*pc_gcall)(void *ud, double t, double *g);
/* pc_curve_stroke with every piece blended by the callback g (NULL: by its own smoothstep);
 * gfree(gud), if set, when the last curve using it goes (on failure the caller keeps gud).  A
 * callback's stroke has no breakpoints and no derivatives of its own: the core samples and
 * differences it as any function curve. */
pc_curve *pc_curve_stroke_fn(int d, int npieces, const pc_piece *pieces, int closed, pc_gcall g,
                             void (*gfree)(void *ud), void *gud, int *status);
/* The pieces of a stroke made by pc_curve_stroke(_fn), over its whole domain [0, npieces], and
 * *npieces; NULL (and 0) for any other curve, a part or an image of a stroke. */
const pc_piece *pc_curve_stroke_pieces(const pc_curve *c, int *npieces);
/* Piece i (0-based) of the stroke c at its own parameter t, any t (the formula extrapolates
 * where the smoothstep has values): PC_EDOMAIN where its half-spline of fractional degree does
 * not (pc_gfun_check), PC_EARG for no stroke or no piece i, else the callback's status. */
int pc_stroke_piece_at(const pc_curve *c, int i, double t, double *out);
/* When the stroke c has no value at s because the half-spline of s's piece (floor(s), the
 * ends extrapolating) is of fractional degree and does not extrapolate there: that piece, *i
 * its index and *t its own parameter; else NULL. */
const pc_piece *pc_stroke_past(const pc_curve *c, double s, int *i, double *t);
/* Why the parameter s of piece pc (index i), below 0 or above hi, is past the reach of its
 * half-spline, into why (returned): "must be at least 0 (piece 1's half-spline has the
 * fractional degree n = 2.5 and does not extrapolate)". */
const char *pc_half_why(const pc_piece *pc, double s, int i, double hi, char *why, size_t size);
/* pc_curve_value of c at t for the call op, its failure explained in why (why_call.h): a
 * stroke's piece past its half-spline's reach as argument 1 (pc_half_why); another failure
 * leaves why empty. */
int pc_stroke_value_checked(const char *op, const pc_curve *c, double t, double *h, pc_why_call *why);
/* pc_stroke_piece_at of piece i at t for the call op, PC_EDOMAIN explained in why as argument
 * 2 past the reach of the piece's half-spline; another failure leaves why empty. */
int pc_stroke_piece_checked(const char *op, const pc_curve *c, int i, double t, double *x, pc_why_call *why);

#endif
