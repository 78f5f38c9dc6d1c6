/* What the bindings of the textbook's constructions need besides them (buimov_parts.c). */
#ifndef PC_BUIMOV_PARTS_H
#define PC_BUIMOV_PARTS_H

#include "curve.h"

/* The Cartesian control points of a polynomial single-piece Bezier curve (every weight 1)
 * into out, rows of c->dim: its degree, or -1 when c is rational, piecewise or of another
 * kind (§4.3 takes the control points as they are drawn). */
int pc_bezier_points(const pc_curve *c, double *out);
/* The name of a kind of joint of pc_bezier_joint: "none", "C0", "G1", "C1". */
const char *pc_bezier_joint_name(int kind);

#endif
