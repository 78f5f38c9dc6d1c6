/* The explanations of the statuses of the textbook's constructions (buimov_why.h): arg > 0
 * the argument the condition concerns, 0 the construction as a whole. */
#include <stddef.h>
#include "buimov_why.h"

#define COINCIDE "two of the points coincide"
#define ON_A_LINE "the three points lie on one line, so no circle passes through them"

const pc_why pc_buimov_why[] = {
    /* chapter 3: plane curves */
    {"plane.circle3", PC_ECOINCIDENT, 0, NULL, COINCIDE},
    {"plane.circle3", PC_ECOLLINEAR, 0, NULL, ON_A_LINE},
    {"plane.arc3", PC_ECOINCIDENT, 0, NULL, COINCIDE},
    {"plane.arc3", PC_ECOLLINEAR, 0, NULL, ON_A_LINE},
    {"plane.classify", PC_EDOMAIN, 0, NULL, "a = b = c = 0 is a line, not a conic"},
    {"plane.ellipse", PC_EDOMAIN, 0, NULL, "need th0 < th1 (at most 8 turns apart)"},
    {"plane.parabola", PC_EDOMAIN, 0, NULL, "need th0 < th1"},
    {"plane.hyperbola", PC_EDOMAIN, 0, NULL, "need t0 < t1"},
    /* chapters 4 and 5: curves and surfaces */
    {"buimov.bspline", PC_EDOMAIN, 0, NULL, "a vertex is repeated so often that the knots leave no span"},
    {"buimov.spline", PC_ECOINCIDENT, 0, NULL, "two consecutive points coincide (a chord of length 0)"},
    {"buimov.helix", PC_EDOMAIN, 0, NULL, "need t0 < t1"},
    {"buimov.sphere", PC_EDOMAIN, 0, NULL, "need th0 < th1 and ph0 < ph1"},
    /* chapter 2.8.6: views and cameras */
    {"buimov.reconstruct", PC_ESINGULAR, 0, NULL, "the views do not fix a point (their lines of sight are parallel)"},
    {"buimov.calibrate", PC_ESINGULAR, 0, NULL,
     "the points do not fix a camera (they lie in one plane, or the origin is on the camera's vanishing plane, "
     "where T44 = 0)"},
    {NULL, 0, 0, NULL, NULL}};
