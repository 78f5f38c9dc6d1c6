/* Graphical differentiation (Korotky & Vitovtov 2021 measure the slopes tg delta of the
 * ruler at the pins from its drawing by graphical differentiation, their ref. [11]; digest
 * korotky_curves_surfaces.md A.3, A.12, C.3 item 12a): the slope of a curve known only as
 * samples, from a local fit.  (The pole construction that draws it: with the pole at
 * (-H, 0), the line through the pole parallel to the tangent cuts the y axis at H tg delta.) */
#ifndef PC_GRAPHDIFF_H
#define PC_GRAPHDIFF_H

#include "status.h"

/* The slope dy/dx at x of the curve sampled at n points (xy: rows of 2, x strictly
 * increasing): the least-squares parabola through the `window` samples nearest to x (3..n;
 * odd keeps it centred, 7 is a good choice), differentiated at x.  Near an end the window
 * is one-sided, as a draughtsman fits the end of a curve.  PC_EDOMAIN if x is outside
 * [x_0, x_(n-1)] or the x do not increase, PC_EDIM if n < 3 or window is outside 3..n,
 * PC_ENONFINITE for NaN/inf. */
int pc_graphical_slope(int n, const double *xy, double x, int window, double *slope);

#endif
