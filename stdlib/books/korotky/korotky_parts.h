/* What the bindings of Korotky's constructions need besides the constructions themselves
 * (korotky_parts.c): the polynomial spline of a list of points, the ridge shell of guides that
 * may be fixed points, the line pair of a degenerate conic section, and what each
 * construction's failure statuses mean, in the words the messages use. */
#ifndef PC_KOROTKY_PARTS_H
#define PC_KOROTKY_PARTS_H

#include "ferguson.h"
#include "pencils4.h"
#include "conic_shells.h"
#include "quadratic.h"
#include "why_call.h"

/* pc_poly_spline and pc_poly_spline_curve of the points p (n rows of 2, x increasing): the
 * coefficients into coef, the curve returned (NULL: *status and *bad as pc_poly_spline). */
pc_curve *pc_poly_spline_points(int n, const double *p, pc_end_kind ends, double s0, double s1,
                                double *coef, int *bad, int *status);
/* The names of the polynomial spline's ends (pc_end_kind: "natural", "clamped") and of the
 * substitution's roots (pc_ferguson_substitution's root_max 0, 1: "min", "max"), NULL-ended:
 * the choices of korotky.poly_spline and korotky.ferguson_substitution. */
extern const char *const pc_poly_spline_ends[];
extern const char *const pc_ferguson_roots[];
/* The Ferguson spline of system (22) through the n points p (rows of 2) with the unit end
 * tangents tA, tE scaled to the moduli wA, wE and the n - 2 ratios lambda: pc_ferguson_lambda's
 * Hermite segments as a curve (NULL: *status and *bad as pc_ferguson_lambda; PC_EZERO for a
 * zero end tangent). */
pc_curve *pc_ferguson_lambda_curve(int n, const double *p, const double tA[2], const double tE[2], double wA,
                                   double wE, const double *lambda, int *bad, int *status);
/* pc_surface_ridge_shell of the guides U, R, V, T1, T2, P, H, Q in that order, each a 3-D
 * curve or (c NULL) the fixed homogeneous point h[0..3] (a constant curve). */
pc_surface *pc_surface_ridge_shell_of(const pc_pencil_point g[8], double *bad_u, int *status);
/* The two quadratic pieces of korotky.conic_arc with T = W (5 homogeneous 2-D control points
 * cp, U .. W .. V): 1 if both are straight (the line pair U W V), with W into w[2]; else 0. */
int pc_conic_line_pair(const double *cp, double w[2]);

/* The meaning of a failure status: of the Ferguson solvers (at a knot), of pc_conic_arc, of
 * pc_surface_conic_revolve, of pc_meet_planes4 (plane_meet: two planes given; pencil: the
 * planes of two pencils).  Other statuses: pc_strerror. */
const char *pc_ferguson_why(int st);
const char *pc_conic_arc_why(int st);
const char *pc_conic_revolve_why(int st);
const char *pc_meet_planes4_why(int st, int pencil);
/* The failure st of the polynomial spline or a Ferguson solver at knot bad (0-based; -1: at no
 * knot) explained in w for the construction op (korotky.poly_spline: the x must increase;
 * korotky.ferguson_lambda: the end tangents and the ratios lambda; the others: the knot); an
 * empty table for a failure at no knot.  Returns st. */
int pc_ferguson_explain(const char *op, int st, int bad, pc_why_call *w);
/* korotky.ferguson: pc_ferguson_curve with nm moduli (2n - 2 needed: argument #3), a failure
 * explained in w (the count; the curve's status, on the tangents); the table empty on success. */
pc_curve *pc_ferguson_checked(int n, const double *p, const double *T, int nm, const double *mags, int *status,
                              pc_why_call *w);
/* korotky.poly_spline: pc_poly_spline_points, clamped ends needing both end slopes (slopes 1:
 * s0 and s1 given), a failure explained in w (pc_ferguson_explain; the table empty on success). */
pc_curve *pc_poly_spline_checked(int n, const double *p, pc_end_kind ends, int slopes, double s0,
                                 double s1, double *coef, int *status, pc_why_call *w);
/* korotky.ferguson_lambda: pc_ferguson_lambda_curve with nl ratios lambda (-1: none given; past
 * two points n - 2 are needed), a failure explained in w as pc_poly_spline_checked's. */
pc_curve *pc_ferguson_lambda_checked(int n, const double *p, const double tA[2], const double tE[2],
                                     double wA, double wE, int nl, const double *lambda,
                                     int *status, pc_why_call *w);

/* The elements of a 2-D conic arc c: one rational quadratic piece (pc_conic_info_rquad and its
 * statuses), or the two pieces of korotky.conic_arc with T = W: PC_ESAME_LINE when they are the
 * line pair U W V (the degenerate section AOD of Fig. 3c), its lines meeting at W (into w), else
 * PC_EDIM.  PC_EDIM for any other curve. */
int pc_conic_info_arc(const pc_curve *c, pc_conic_info *out, double w[2]);
/* 1 if c has the shape pc_conic_info_arc takes: a 2-D quadratic Bezier curve of one piece (3
 * control points) or of the two pieces of korotky.conic_arc with T = W (5), else 0. */
int pc_conic_arc_shaped(const pc_curve *c);
/* The elements of korotky.conic_elements: of the arc c (pc_conic_info_arc) or, c NULL, of the
 * coefficients coef (pc_conic_info_coef), a failure explained in w: the line pair U W V with the
 * point W where its lines meet, else the rows of pc_korotky_why (another status with an empty
 * table).  Returns the status. */
int pc_conic_elements_checked(const pc_curve *c, const double coef[6], pc_conic_info *out,
                              pc_why_call *w);

/* The failure st of pc_elastic_length for n points, pieces per span (0: as the points allow)
 * and the length len (0: free), explained in w (korotky.elastic; an empty table for a status
 * it does not explain); returns st. */
int pc_elastic_explain(int st, int n, int pieces, double len, pc_why_call *w);
/* korotky.elastic: pc_elastic_length, a failure explained in w (pc_elastic_explain; the table
 * empty on success). */
pc_curve *pc_elastic_checked(int n, const double *p, int pieces, const double *end_angles,
                             double len, double *energy, int *status, pc_why_call *w);
/* pc_graphical_slope with its conditions explained in w (korotky.graphical_slope): the window
 * 3..n, the x increasing, x within the samples. */
int pc_graphical_slope_checked(int n, const double *xy, double x, int window, double *slope, pc_why_call *w);

/* pc_curve_hausdorff of the model and the reference, their mixed dimensions explained in w
 * (korotky.deviation; another status with an empty table). */
int pc_curve_hausdorff_checked(const pc_curve *model, const pc_curve *ref, int samples, double *d, pc_why_call *w);

/* The failure st at u of a sweep's conic explained in w (ridge: korotky.ridge_shell's profile
 * arcs, else korotky.conic_sweep's conics; korotky.conic_revolve's are pc_conic_revolve_why's). */
int pc_sweep_explain(int ridge, int st, double u, pc_why_call *w);
/* korotky.ridge_shell (ridge: pc_surface_ridge_shell_of of the eight guides g) or
 * korotky.conic_sweep (pc_surface_conic_sweep of the curves of g[0..4]), a failure explained in
 * w (pc_sweep_explain; the table empty on success). */
pc_surface *pc_sweep_checked(int ridge, const pc_pencil_point g[8], int *status, pc_why_call *w);
pc_surface *pc_conic_revolve_explained(const double A[3], const double B[3], const double nA[3], const double nB[3],
                                       pc_curve *ridge, int *status, pc_why_call *w);
/* pc_dome_tri_height_through explained in w (korotky.dome_tri: the apex D is argument #4). */
int pc_dome_tri_height_checked(const double *A, const double *B, const double *C, const double *D, double *h,
                               pc_why_call *w);
/* korotky.dome_tri: pc_surface_dome_tri of height h > 0, or (h 0) through the apex D
 * (pc_dome_tri_height_checked), a failure explained in w (also by the rows of pc_korotky_why;
 * another status with an empty table). */
pc_surface *pc_dome_tri_explained(const double *A, const double *B, const double *C, double h,
                                  const double *D, int *status, pc_why_call *w);

/* The explanations of the statuses of the constructions of the korotky table, by the name the
 * API gives each (why.h). */
extern const pc_why pc_korotky_why[];

#endif
