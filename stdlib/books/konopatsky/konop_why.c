/* The explanations of the statuses of Konopatsky's constructions (konop_why.h): arg > 0 the
 * argument the condition concerns, arg < 0 the argument whose value %s shows in a message of
 * its own, key an option key. */
#include <math.h>
#include <stddef.h>
#include "konop_why.h"
#include "quadratic_on.h"
#include "names.h"

#define ANY_ARC "a function curve has no power-basis form (only Bezier and B-spline curves: build the equation " \
    "as bezier{...} or with conic.*, oneratio.*, interp.*)"
#define NO_MEET "a meet of the scheme is undefined at this parameter (its lines coincide)"
#define OUTSIDE(op) "the points or parameters are outside the form's conditions (see :help " op ")"
#define FORM(op) {op, PC_EDOMAIN, 0, NULL, OUTSIDE(op)}, \
    {op, PC_EDOMAIN2, 0, "range", "must be two finite numbers t0 < t1"}
#define NONZERO "must be a non-zero number, got 0"
#define PERPENDICULAR "CA and CB must be perpendicular semi-axes"

const pc_why pc_konop_why[] = {
    /* chapter 2: conic */
    {"conic.ed", PC_EDOMAIN, 4, NULL, "must be a non-zero number (k = 0 collapses the arc to C), got 0"},
    {"conic.ed_k", PC_ENOTCOLLINEAR, 4, NULL, "must lie on the median from C to the midpoint of AB"},
    {"conic.circle_k", PC_EDOMAIN, 0, NULL, "|CA| must equal |CB| (tangents from C to a circle)"},
    {"conic.circle", PC_EDOMAIN, 0, NULL, "|CA| must equal |CB| for the arc (or give delta or R)"},
    {"conic.circle", PC_EDOMAIN2, 0, "range", "must be two finite numbers t0 < t1"},
    FORM("conic.ellipse"), FORM("conic.hyperbola"), FORM("conic.reparam"), FORM("conic.sinusoid"),
    FORM("conic.cycloid"),
    {"conic.five_points2", PC_EDOMAIN, 0, NULL, "options 'p1' and 'q3' must be in (0, 1]"},
    {"conic.five_points2", PC_EDOMAIN2, 0, NULL,
     "options 'p2' and 'q2' must be in (0, 1) (A2 inside the triangle C A1 A3)"},
    {"conic.cones", PC_EDIM, -1, NULL, "the points must be 3-D or more (a tetrahedron ABCD), got A = %s"},
    {"conic.cones", PC_EDOMAIN, 5, NULL, "must be a number in (0, 1), got %s"},
    {"conic.cones", PC_EDOMAIN2, 6, NULL, "must be a number in (0, 1), got %s"},
    {"conic.cones", PC_EDOMAIN3, 7, NULL, "must be a number other than 0 and 1, got %s"},
    {"conic.focal_point", PC_EDOMAIN, 0, NULL, PERPENDICULAR},
    {"conic.focal_point", PC_EDOMAIN2, 0, NULL, PERPENDICULAR ", CA the major one (the foci on it)"},
    {"conic.ceva", PC_EDOMAIN, 4, NULL, "must be a non-zero number, got 0"},
    {"conic.ceva_k", PC_EDOMAIN, 0, NULL,
     "the cevians through K must meet the sides A2A3 and A3A1 at finite points other than A3"},
    {"conic.parabola", PC_EDOMAIN, 4, NULL, "must be a number in (0, 1), got %s"},
    {"conic.five_points", PC_EDOMAIN, 0, NULL, "the five points must lie in one plane with no three of them collinear"},
    {"conic.five_points", PC_ECOLLINEAR, 0, NULL, "A, B and C must not be collinear"},
    {"conic.five_points", PC_EDOMAIN2, 0, "u1", "must be greater than u0"},
    {"conic.triples", PC_EDOMAIN, 0, NULL, "the lines A2A3 and A4A5 must meet"},
    {"conic.triples", PC_EDOMAIN2, 7, NULL, "must be greater than t0"},
    {"conic.scheme", PC_EDOMAIN2, 0, NULL,
     "the current point's line current[2], current[3] must join two given points"},
    {"conic.scheme", PC_EDOMAIN3, 0, "range", "must be {t0, t1} with t0 < t1"},
    {"conic.redundant", PC_EPOLE, 0, NULL, "u = 0 and v = 1 make both lines AB: K is undefined"},
    {"conic.cones", PC_ECOLLINEAR, 0, NULL, "A, B, C, D must span a tetrahedron"},
    {"conic.ed_scheme", PC_EARG, 4, NULL, "must not be 0 (the arc collapses to C)"},
    {"conic.ed_scheme", PC_ECOLLINEAR, 0, NULL, "A, B, C are collinear"},
    {"conic.ed_scheme", PC_EDOMAIN, 0, NULL, NO_MEET},
    {"conic.five_scheme", PC_ECOLLINEAR, 0, NULL, "A, B, C are collinear"},
    {"conic.five_scheme", PC_EDOMAIN, 0, NULL, NO_MEET},
    {"conic.ceva_scheme", PC_EDOMAIN, 4, NULL, "must not be 0"},
    {"conic.ceva_scheme", PC_EPOLE, -5, NULL, "the arc is at infinity at t = %s"},
    {"conic.ceva_scheme", PC_ECOLLINEAR, 0, NULL, "A1, A2, A3 are collinear"},
    {"conic.foci", PC_EDOMAIN, 0, NULL,
     "CA and CB must be the axes (perpendicular); for conjugate semi-diameters use c:conic()"},
    {"conic.foci", PC_ECOLLINEAR, 0, NULL, "a semi-axis is zero (A or B coincides with C)"},
    {"conic.focal_point", PC_EPOLE, -4, NULL, "phi = %s is an asymptote's direction (1 - e cos phi = 0)"},
    {"conic.focal_point", PC_ECOLLINEAR, 0, NULL, "a semi-axis is zero"},
    {"conic.ceva_to_ed", PC_EDOMAIN, 1, NULL, "must be a positive Ceva k, got %s"},
    {"conic.ed_to_ceva", PC_EDOMAIN, 1, NULL, "must be an engineering discriminant in (0, 1), got %s"},
    /* chapter 3: oneratio */
    {"oneratio.double_contact", PC_EDOMAIN, 4, NULL, NONZERO},
    {"oneratio.double_contact", PC_EDOMAIN2, 5, NULL, NONZERO},
    {"oneratio.double_contact", PC_EDOMAIN3, 5, NULL, "must be different from kp (else M is the conic P = Q)"},
    {"oneratio.closed", PC_EDOMAIN, 4, NULL, NONZERO},
    {"oneratio.closed", PC_EDOMAIN2, 5, NULL, NONZERO},
    {"oneratio.smooth_scheme", PC_ECOLLINEAR, 0, NULL, "A, B, C are collinear"},
    {"oneratio.smooth_scheme", PC_EDOMAIN, 0, NULL, NO_MEET},
    /* chapter 4: interp */
    {"interp.lagrange", PC_ECOINCIDENT, 2, NULL, "must be distinct"},
    {"interp.controls", PC_ECOINCIDENT, 2, NULL, "must be distinct"},
    {"interp.weights", PC_ECOINCIDENT, 0, NULL, "argument #1 (params) must be distinct"},
    {"interp.weights", PC_ENONFINITE, -2, NULL, "the weights are out of range (not finite) for t = %s"},
    {"interp.conic", PC_EDOMAIN, 4, NULL, "must be a number other than 0 and 1, got %s"},
    {"interp.prototype", PC_ESINGULAR, 0, NULL, "the exponents must be distinct (singular system)"},
    {"interp.basis", PC_ESINGULAR, 0, NULL, "the collocation matrix g_i(t_j) is singular"},
    {"interp.basis", PC_EDOMAIN2, 0, NULL, "the parameter range must not be empty"},
    {"interp.rational22", PC_ESINGULAR, 0, NULL, "a coordinate has no rational (2,2) fit"},
    /* chapter 5: approx */
    {"approx.optimal_nodes", PC_EDOMAIN, 3, NULL, "must be greater than a"},
    {"approx.chebyshev", PC_EDOMAIN, 3, NULL, "must be greater than a"},
    {"approx.lagrange_mse", PC_ECOINCIDENT, 2, NULL, "must be distinct"},
    /* chapter 1: konopatsky */
    {"konopatsky.area_k", PC_EPOLE, 0, NULL, "a lambda is -1 (its point is at infinity): k is undefined"},
    {"konopatsky.area_theorem", PC_ECOLLINEAR, 0, NULL, "the triangle A1A2A3 is flat"},
    {"konopatsky.area_theorem", PC_ENOTCOLLINEAR, 0, NULL,
     "each Bi must lie on its side line (B1 on A1A2, B2 on A2A3, B3 on A3A1)"},
    {"konopatsky.o_theorem", PC_EDOMAIN, 0, NULL, "the line D1D2 passes through a vertex"},
    {"konopatsky.o_theorem", PC_ESKEW, 0, NULL, "the line D1D2 must lie in the polygon's plane and be no side line"},
    {"konopatsky.o_theorem", PC_ESAME_LINE, 0, NULL,
     "the line D1D2 must lie in the polygon's plane and be no side line"},
    {"konopatsky.simplex_ratio", PC_EDOMAIN, 0, NULL, "each row's parameters must sum to 1 (the membership condition)"},
    {"konopatsky.meet_line_plane", PC_ESAME_LINE, 0, NULL, "the line A1A2 lies in the plane P1P2P3: no single meet"},
    {"konopatsky.meet_line_plane", PC_ESKEW, 0, NULL,
     "the line A1A2 and the plane P1P2P3 do not meet (they span more than 3-D)"},
    {"konopatsky.meet_line_plane", PC_ECOINCIDENT, 0, NULL, "A1 and A2 coincide: no line"},
    {"konopatsky.meet_line_plane", PC_ECOLLINEAR, 0, NULL, "P1, P2, P3 are collinear: no plane"},
    {"konopatsky.polar", PC_ECOLLINEAR, 0, NULL, "C, A, B are collinear (or coincide): no plane, no angle"},
    {"konopatsky.rotate", PC_ECOLLINEAR, 0, NULL, "C, A, B are collinear (or coincide): no plane, no angle"},
    {"konopatsky.equation", PC_EDOMAIN, 0, NULL, ANY_ARC},
    /* the conic a curve lies on (quadratic.h) */
    {"c:conic", PC_ENOTCOLLINEAR, 0, NULL, "the curve does not lie on one conic"},
    {"c:conic", PC_ECOLLINEAR, 0, NULL,
     "the points are a straight line (a middle weight 0, or collinear points): no conic"},
    {"c:conic", PC_EDOMAIN, 0, NULL, "a degenerate conic (a line pair, parallel lines, or no real points)"},
    {"conic.elements", PC_ENOTCOLLINEAR, 0, NULL, "the curve does not lie on one conic"},
    {"conic.elements", PC_ECOLLINEAR, 0, NULL,
     "the points are a straight line (a middle weight 0, or collinear points): no conic"},
    {"conic.elements", PC_EDOMAIN, 0, NULL, "a degenerate conic (a line pair, parallel lines, or no real points)"},
    {"conic.elements", PC_ESINGULAR, 0, NULL, "the conditions do not fix one conic (they are dependent)"},
    {"conic.elements", PC_ECOINCIDENT, 0, NULL,
     "the five points fix no single conic (four of them are collinear, or two coincide)"},
    {"plane.conic_slope", PC_EZERO, 0, NULL, "X is a singular point of the curve (both partial derivatives are 0)"},
    {0}};

int pc_conic_slope_checked(const double coef[6], const double X[2], double *slope, pc_why_call *w) {
    const char *op = "plane.conic_slope";
    double v;
    char at[40];
    int st = pc_conic_slope_on(coef, X[0], X[1], slope, &v);
    if (st == PC_EPOLE) *slope = HUGE_VAL, st = PC_OK;   /* a vertical tangent */
    if (st == PC_EDOMAIN)
        return pc_why_call_set(w, op, st, 0, NULL, "the point X is not on the curve (the equation gives %s there)",
                               pc_num_text(v, at, sizeof at));
    return pc_why_call_row(w, pc_konop_why, op, st);
}
