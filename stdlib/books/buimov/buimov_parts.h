/* What the bindings of the textbook's constructions need besides them (buimov_parts.c). */
#ifndef PC_BUIMOV_PARTS_H
#define PC_BUIMOV_PARTS_H

#include "curve.h"
#include "buimov.h"
#include "plane_curves.h"
#include "map.h"
#include "why_call.h"

/* The Cartesian control points of a polynomial single-piece Bezier curve (every weight 1)
 * into out, rows of c->dim: its degree, or -1 when c is rational, piecewise or of another
 * kind (§4.3 takes the control points as they are drawn). */
int pc_bezier_points(const pc_curve *c, double *out);
/* The name of a kind of joint of pc_bezier_joint: "none", "C0", "G1", "C1". */
const char *pc_bezier_joint_name(int kind);
/* pc_bezier_g1_next and pc_bezier_joint of the curves P (and Q), with their conditions
 * explained in w (buimov.g1_next, buimov.joint): polynomial Bezier curves (pc_bezier_points)
 * of one dimension; another status of the construction with an empty table. */
int pc_bezier_g1_next_of(const pc_curve *P, int m, double g, double *q0, double *q1, pc_why_call *w);
int pc_bezier_joint_of(const pc_curve *P, const pc_curve *Q, int *kind, double *g, pc_why_call *w);

/* The names of the point generators' kinds and methods (pc_gen_kind, pc_gen_method), of
 * pc_conic_coef's kinds, of the conic classes (pc_conic_class), of the spline's ends
 * (pc_book_ends) and parameter lengths (pc_book_spline_params' chord 0, 1), in order, NULL-ended:
 * the choices of plane.points, plane.conic_coef, buimov.spline and plane.classify's result. */
extern const char *const pc_gen_kind_names[];
extern const char *const pc_gen_method_names[];
extern const char *const pc_conic_coef_kinds[];
extern const char *const pc_conic_names[];
extern const char *const pc_book_ends_names[];
extern const char *const pc_book_param_names[];
/* The book's circles with their conditions explained in w (plane.circle2r, plane.circle_slopes:
 * the values that broke them). */
int pc_circle2r_checked(const double p1[2], const double p2[2], double r, pc_circle_eq out[2], pc_why_call *w);
int pc_circle_slopes_checked(const double p1[2], double m1, double x_end, double m2, pc_circle_eq out[2],
                             double ends[4], int *nsol, pc_why_call *w);
/* pc_conic_coef with B given or not (has_B), explained in w (plane.conic_coef). */
int pc_conic_coef_checked(int kind, const double c[2], double A, int has_B, double B, double out[6], pc_why_call *w);
/* pc_conic_points with B given or not (has_B), explained in w (plane.points): B where the
 * kind needs it, a method of the circle's only, the steps leaving the domain. */
int pc_conic_points_checked(pc_gen_kind kind, pc_gen_method method, double A, int has_B, double B, double step,
                            int n, double *xy, pc_why_call *w);

/* The conditions of buimov.spline's options on n points: the ends (*ends; given or not: end
 * tangents given without ends make them clamped), how many of the end tangents d0, d1 are
 * given (nd), whether param is, and the user's segment lengths len (nlen of them; -1: none).
 * PC_OK, or PC_EDOMAIN with the broken condition explained in w. */
int pc_book_spline_check(int n, pc_book_ends *ends, int ends_given, int nd, int param_given, int nlen,
                         const double *len, pc_why_call *w);
/* pc_calibrate_camera of the n points xyz and their m images xy (as many as the points), its
 * failure explained in w (buimov.calibrate: the counts, the rows of pc_buimov_why). */
int pc_calibrate_checked(int n, const double *xyz, int m, const double *xy, pc_map *cam, double *rms,
                         pc_why_call *w);
/* pc_book_basis with its conditions explained in w (buimov.basis): the knots must not
 * decrease, and N(i, k) needs the knots q[i] .. q[i + k]. */
int pc_book_basis_checked(const double *q, int nq, int i, int k, double t, double *out, pc_why_call *w);

#endif
