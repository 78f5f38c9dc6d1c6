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

/* A field a script reads of a curve (c.dim, c.t0, ...): its type, the value in *v. */
typedef enum { PC_FIELD_NONE, PC_FIELD_INTEGER, PC_FIELD_NUMBER, PC_FIELD_BOOLEAN } pc_field_type;
/* The field key of c: dim; lo and t0, hi and t1 (the domain); closed; degree (not of a function
 * curve); pieces (a stroke's, a Bezier curve's segments, else 1); n (a Fourier curve's order). */
pc_field_type pc_curve_field(const pc_curve *c, const char *key, double *v);

#endif
