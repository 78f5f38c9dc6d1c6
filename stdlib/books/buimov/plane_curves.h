/* Plane curves of the textbook (Buimov ch. 3): circles by the book's three constructions,
 * conics in the general form a x^2 + b xy + c y^2 + d x + e y + f = 0 (classification and
 * rotation of the axes), the book's point generators (parametric, rational, explicit and the
 * incremental recurrences of §3.2-§3.5, with the digest's errata corrected), and the conics as
 * curves of the one curve type: rational quadratic Bezier pieces, exact conics. */
#ifndef PC_PLANE_CURVES_H
#define PC_PLANE_CURVES_H
#include "curve.h"

/* A circle (x - m)^2 + (y - n)^2 = r^2 = x^2 + y^2 + d x + e y + f (§3.2). */
typedef struct {
    double c[2], r;      /* centre (m, n) and radius */
    double d, e, f;      /* d = -2m, e = -2n, f = m^2 + n^2 - r^2 */
} pc_circle_eq;

/* The circle through three points (§3.2, example 1: the linear system in d, e, f).
 * PC_ECOINCIDENT if two points coincide, PC_ECOLLINEAR if they lie on a line. */
int pc_circle3(const double p1[2], const double p2[2], const double p3[2], pc_circle_eq *out);
/* The two circles of radius r through two points (§3.2, example 2; the book prints a rounded
 * iterate of the first and omits the second): out[0] has its centre on the right of the
 * direction p1 -> p2 (the book's), out[1] on the left; both the same when r is half the
 * chord.  PC_ECOINCIDENT if p1 = p2, PC_EDOMAIN if 2r is shorter than the chord (or r is not
 * finite and positive). */
int pc_circle2r(const double p1[2], const double p2[2], double r, pc_circle_eq out[2]);
/* The circles through p1 with the slope m1 there and the slope m2 at a point whose abscissa
 * is x_end (§3.2, example 3, Fig 3.1).  The centre lies on the normal at p1; each solution
 * comes with its end point (ends: 2 per solution).  *nsol is 1 or 2; for m2 = 0 both points of
 * the circle at x = x_end have the slope 0, so the two solutions are one circle with its two
 * end points (the book's [3; 1.8] and [3; -3.8]).  Solutions are ordered by the end point's y,
 * highest first.  PC_EDOMAIN if x_end = p1's x, for non-finite input, or if no circle fits. */
int pc_circle_slopes(const double p1[2], double m1, double x_end, double m2, pc_circle_eq out[2],
                     double ends[4], int *nsol);

/* --- conics in the general form: coef = {a, b, c, d, e, f} ---------------------------------- */
typedef enum { PC_CONIC_ELLIPSE, PC_CONIC_PARABOLA, PC_CONIC_HYPERBOLA } pc_conic_class;
/* By the discriminant b^2 - 4ac (§3.1, eq. 4.1.1): < 0 ellipse (or circle), = 0 parabola,
 * > 0 hyperbola; "= 0" within 1e-12 of the larger of b^2 and |4ac|.  PC_EDOMAIN if a = b = c
 * = 0 (no conic), PC_ENONFINITE for NaN/inf. */
int pc_conic_classify(double a, double b, double c, pc_conic_class *out);
/* The coefficients after the substitution x' = x cos t - y sin t, y' = x sin t + y cos t in
 * the conic `in` (§3.3; the book's formulas are the case b' = 0, with its misprint
 * b = 2(c' - d') cos sin corrected to 2(c' - a') cos sin).  The point (x, y) satisfies the new
 * equation exactly when (x', y') satisfies the old. */
void pc_conic_rotate(const double in[6], double t, double out[6]);
/* The value of the conic's left-hand side at (x, y). */
double pc_conic_value(const double coef[6], double x, double y);
/* The general-form coefficients of the book's conics with axes along x and y:
 * ellipse (x-m)^2/A^2 + (y-n)^2/B^2 = 1 (§3.3: a' = B^2, c' = A^2, ...), hyperbola
 * (x-m)^2/A^2 - (y-n)^2/B^2 = 1 (§3.5), parabola (x-m)^2 = 4p(y-n) (§3.4, with f = m^2 + 4pn,
 * corrected from the printed m^2 - 4pn; here A is p and B unused). */
void pc_conic_ellipse_coef(double m, double n, double A, double B, double out[6]);
void pc_conic_hyperbola_coef(double m, double n, double A, double B, double out[6]);
void pc_conic_parabola_coef(double m, double n, double p, double out[6]);

/* The same by kind (0 ellipse, 1 hyperbola: semi-axes A, B; 2 parabola: p = A, vertex c):
 * PC_EDOMAIN unless A > 0 and B > 0 for an ellipse or a hyperbola. */
int pc_conic_coef(int kind, const double c[2], double A, double B, double out[6]);

/* --- the book's point generators ------------------------------------------------------------ */
typedef enum {
    PC_GEN_CIRCLE,          /* radius A: x = A cos th, y = A sin th */
    PC_GEN_ELLIPSE,         /* x = A cos th, y = B sin th (§3.3) */
    PC_GEN_PARABOLA,        /* y^2 = 4 A x: x = A th^2, y = 2 A th (§3.4; the book writes 2px) */
    PC_GEN_HYPERBOLA_SEC,   /* x = A sec th, y = B tan th (§3.5) */
    PC_GEN_HYPERBOLA_COSH   /* x = A ch th, y = B sh th (§3.5) */
} pc_gen_kind;
typedef enum {
    PC_GEN_PARAM,           /* the parametric form at th = i step */
    PC_GEN_RECURRENCE,      /* the book's increments from the starting point, step constant */
    PC_GEN_RATIONAL,        /* circle only: x = A(1 - t^2)/(1 + t^2), y = 2At/(1 + t^2), t = i step */
    PC_GEN_EXPLICIT         /* circle only: y = sqrt(A^2 - x^2) at x = A - i step (Fig 3.2) */
} pc_gen_method;
/* n + 1 points (xy: 2(n+1) doubles), i = 0..n, of the conic by the method.  The recurrences,
 * with the digest's corrections: ellipse x' = x cos - (A/B) y sin, y' = (B/A) x sin + y cos;
 * parabola x' = x + y dth + A dth^2, y' = y + 2A dth (the book prints -y dth); hyperbola
 * x' = B x/(B cos - y sin), y' = B(y + B tan)/(B - y tan) (the book prints B + y tan in the
 * denominator), and the ch/sh rotation.  PC_EDOMAIN for a method the kind has not, A <= 0,
 * B <= 0 where used, n < 0, or a step that leaves the curve's domain (the explicit circle
 * beyond x = -A, the sec form at th >= pi/2); PC_ENONFINITE for NaN/inf. */
int pc_conic_points(pc_gen_kind kind, pc_gen_method method, double A, double B, double step,
                    int n, double *xy);

/* --- conics as curves (rational quadratic Bezier pieces of at most 90 degrees / a unit of the
 * hyperbolic parameter, exact at every breakpoint; the domain is the book's parameter) ------ */
/* The ellipse c + (A cos th, B sin th), th in [th0, th1] (th0 < th1, at most one turn more
 * than 2 pi is refused); A = B is a circle (arc).  PC_EDOMAIN for A, B <= 0 or th1 <= th0. */
pc_curve *pc_curve_ellipse(const double c[2], double A, double B, double th0, double th1,
                           int *status);
/* The parabola (A th^2, 2A th), th in [th0, th1]: one quadratic Bezier, the book's own
 * parameter exactly. */
pc_curve *pc_curve_parabola(double A, double th0, double th1, int *status);
/* The hyperbola branch (A ch t, B sh t), t in [t0, t1]. */
pc_curve *pc_curve_hyperbola(double A, double B, double t0, double t1, int *status);
/* The arc of a circle through three points, counter-clockwise from p1 or p3 (whichever
 * starts the arc that passes through p2).  Statuses of pc_circle3. */
pc_curve *pc_curve_arc3(const double p1[2], const double p2[2], const double p3[2], int *status);
/* The arc of the circle (c, r) from a to b that leaves a along dir (a and b on the circle,
 * within 1e-9 r), counter-clockwise over increasing angles: from a when dir turns
 * counter-clockwise about c, else from b.  PC_EDOMAIN if a point is off the circle, dir is
 * along the radius, or a = b. */
pc_curve *pc_curve_arc_dir(const double c[2], double r, const double a[2], const double dir[2],
                           const double b[2], int *status);

#endif
