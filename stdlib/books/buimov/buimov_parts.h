/* What the bindings of the textbook's constructions need besides them (buimov_parts.c). */
#ifndef PC_BUIMOV_PARTS_H
#define PC_BUIMOV_PARTS_H

#include "curve.h"
#include "buimov.h"
#include "why_call.h"

/* The Cartesian control points of a polynomial single-piece Bezier curve (every weight 1)
 * into out, rows of c->dim: its degree, or -1 when c is rational, piecewise or of another
 * kind (§4.3 takes the control points as they are drawn). */
int pc_bezier_points(const pc_curve *c, double *out);
/* The name of a kind of joint of pc_bezier_joint: "none", "C0", "G1", "C1". */
const char *pc_bezier_joint_name(int kind);

/* The conditions of buimov.spline's options on n points: the ends (*ends; given or not: end
 * tangents given without ends make them clamped), how many of the end tangents d0, d1 are
 * given (nd), whether param is, and the user's segment lengths len (nlen of them; -1: none).
 * PC_OK, or PC_EDOMAIN with the broken condition explained in w. */
int pc_book_spline_check(int n, pc_book_ends *ends, int ends_given, int nd, int param_given, int nlen,
                         const double *len, pc_why_call *w);
/* pc_book_basis with its conditions explained in w (buimov.basis): the knots must not
 * decrease, and N(i, k) needs the knots q[i] .. q[i + k]. */
int pc_book_basis_checked(const double *q, int nq, int i, int k, double t, double *out, pc_why_call *w);

#endif
