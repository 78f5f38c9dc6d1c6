/* What failed in the methods and constructors of the one curve type (curve.h), for the
 * bindings to say: the statuses of its methods by name (why.h), and the conditions of a
 * B-spline's degree and knots with the numbers that break them. */
#ifndef PC_CURVE_WHY_H
#define PC_CURVE_WHY_H

#include <stddef.h>
#include "curve.h"
#include "why.h"
#include "why_call.h"

/* The methods' statuses: op the method as scripts call it ("c:tangent"); arg -2 shows t. */
extern const pc_why pc_curve_why[];

/* The degree of a B-spline of ncp control points (periodic: the points repeat, so the degree
 * may reach ncp; else it must be below ncp, and at most PC_CURVE_MAXDEG): PC_OK, or
 * PC_EDOMAIN with what it must be into why ("must be an integer from 1 to 3 (fewer than the 4
 * points), got 5"). */
int pc_bspline_degree_why(int ncp, double degree, int periodic, char *why, size_t size);
/* The n given knots of a B-spline of ncp control points and that degree: ncp + degree + 1 of
 * them, non-decreasing, with a domain [knot degree + 1, knot ncp + 1] that is not empty (the
 * knots 1-based as a script counts them): PC_OK, or PC_EDOMAIN with the broken condition and
 * its numbers into why. */
int pc_knots_why(int ncp, int degree, int n, const double *knots, char *why, size_t size);
/* The parameters u of n nodes (got of them): n, increasing unless any order will do (an
 * interpolation's: distinct, which its constructor checks): PC_OK, or PC_EDOMAIN with the
 * broken condition into why ("must increase, but [3] = 1 follows [2] = 2"). */
int pc_params_why(int n, int got, const double *u, int any, char *why, size_t size);
/* A whole number v from 1 to n naming one of n things (what: "piece", "coordinate"): PC_OK,
 * or PC_EDOMAIN with "must be a piece number 1..3, got 4" into why. */
int pc_number_why(const char *what, double v, int n, char *why, size_t size);
/* A parameter t strictly inside c's domain (where c splits): PC_OK, or PC_EDOMAIN with "must be
 * inside the domain (0, 1), got 1" into why. */
int pc_curve_inside_why(const pc_curve *c, double t, char *why, size_t size);
/* A part [a, b] of c's domain, a < b: PC_OK, or PC_EDOMAIN with the condition, the domain and
 * the ends given into why. */
int pc_curve_part_why(const pc_curve *c, double a, double b, char *why, size_t size);
/* pc_curve_monomial_rows of piece (1-based, as a script gives it) for the call op, its
 * conditions explained in why (why_call.h): a function curve has no power basis, piece must be
 * 1..npieces (argument 1); another failure leaves why empty. */
int pc_curve_monomial_checked(const char *op, const pc_curve *c, double piece, double *rows, int *degree, int *rational,
                              pc_why_call *why);
/* pc_curve_derivs_n for the call op, its failure explained in why (why_call.h): a function
 * curve's order beyond 2, else the row of pc_curve_why for op and the status (at infinity);
 * another failure leaves why empty. */
int pc_curve_derivs_checked(const char *op, const pc_curve *c, double t, int order, int side,
                            double *out, pc_why_call *why);

#endif
