/* A curve as tostring shows it: the one curve type, with the strokes, spline2 and Fourier
 * curves of the article (spline.h, fourier.h) telling their nodes and points. */
#ifndef PC_CURVE_TEXT_H
#define PC_CURVE_TEXT_H

#include <stddef.h>
#include "curve.h"

/* The text of c made by the constructor `kind` into buf (as snprintf: the length it needs):
 * fourier(8 points, 2-D), spline2(2-D), stroke(4 nodes, 3 pieces, 2-D[, closed]),
 * KIND(2-D, t in [0, 1]) for another function curve, KIND(2-D, degree 3, 4 control points,
 * t in [0, 1]) for a Bezier or B-spline curve; numbers as %.14g, no "-0". */
size_t pc_curve_text(const pc_curve *c, const char *kind, char *buf, size_t size);

#endif
