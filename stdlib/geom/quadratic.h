/* Conics that know what they are: the implicit equation and the metric elements of a plane
 * conic, from the arc of a rational quadratic Bezier curve with any weights (signs and points at
 * infinity included), from five points, or from its coefficients; and the conic of any 2-D curve
 * of the one curve type that lies on one (curve.h).
 *
 * Coefficients are {a, b, c, d, e, f} of a x^2 + b x y + c y^2 + d x + e y + f = 0, scaled so
 * the largest |entry| is 1 and the first of a, b, c that is not 0 is positive (the convention
 * of the textbook's conic functions).  The kind is the type of the arc's weights where an arc
 * with three finite control points is known (Konopatsky digest §6: mu = w1^2/(w0 w2) < 1
 * ellipse, = 1 parabola, > 1 or < 0 hyperbola) and the sign of b^2 - 4ac otherwise (no arc, or
 * a control point at infinity). */
#ifndef PC_QUADRATIC_H
#define PC_QUADRATIC_H

#include "curve.h"

typedef enum { PC_CK_ELLIPSE, PC_CK_PARABOLA, PC_CK_HYPERBOLA } pc_ckind;
/* The names of the kinds in order, NULL-ended: "ellipse", "parabola", "hyperbola". */
extern const char *const pc_ckind_names[];

typedef struct pc_conic_info {
    double coef[6];
    pc_ckind kind;
    int circle;            /* an ellipse with equal semi-axes (within 1e-9 relative) */
    double disc;           /* b^2 - 4ac of coef */
    /* the arc's weights, when the conic came from one (else NaN):
     * mu = w1^2/(w0 w2), the normalised middle weight w = w1 sgn(w0)/sqrt(w0 w2) (NaN unless
     * w0 w2 > 0), the engineering discriminant k = 1/(1 + w) of (2.97), whose weights are
     * (k, 1 - k, k), and Ceva's k = 1/(4 mu) of (2.104), weights (1, 1/2, k) */
    double mu, w, k_ed, k_ceva;
    int central;           /* ellipse or hyperbola: the centre exists */
    double center[2];
    double vertex[2];      /* a parabola's vertex */
    double axis[2][2];     /* unit directions: [0] the major / transverse axis (towards +x, or
                              +y when vertical), or a parabola's axis pointing into the curve;
                              [1] the other, [0] turned by +90 degrees for a central conic */
    double semi[2];        /* semi-axes a, b (a hyperbola's conjugate b); 0 for a parabola */
    double focus[2][2];    /* foci: center +- c axis[0]; a parabola's one focus in focus[0] */
    int nfoci;             /* 2, or 1 for a parabola */
    double ecc;            /* eccentricity c/a (0 circle, 1 parabola) */
    double param;          /* the focal parameter p = b^2/a (a parabola's semi-latus rectum) */
    int nasym;             /* 2 for a hyperbola */
    double asym[2][2];     /* unit directions of the asymptotes through the centre */
} pc_conic_info;

/* The implicit equation of the arc with homogeneous control points h (3 rows of 3: w0 P0, w0 |
 * w1 P1, w1 | w2 P2, w2; a weight may be 0 or negative).  With H = [h0 h1 h2] as columns, the
 * point H (s^2, 2 s t, t^2) has b = H^-1 X with b1^2 = 4 b0 b2, so Q = H^-T C H^-1: no
 * normalisation is needed, and scaling every weight leaves Q as it is.  PC_ECOLLINEAR when
 * the arc is a straight segment (w1 = 0, or the three points collinear), PC_ENONFINITE. */
int pc_conic_coef_rquad(const double h[9], double coef[6]);

/* The conic through five points of the plane (pts: 5 rows of 2): the coefficients are the
 * signed 5x5 minors of the rows (x^2, xy, y^2, x, y, 1).  PC_ECOLLINEAR when the five points
 * do not fix one conic (four of them collinear, or coincident points), PC_ENONFINITE. */
int pc_conic_coef_five(const double pts[10], double coef[6]);

/* The conic of five linear conditions on its coefficients (rows: 5 rows of 6, each the
 * condition's coefficients of a, b, c, d, e, f), by the signed 5x5 minors.  The rows of
 * pc_conic_row_point and pc_conic_row_tangent mix freely: two points with their tangents and a
 * fifth point (Korotky's C-1), three points and one tangent, five points...  PC_ECOLLINEAR
 * when the conditions do not fix one conic (dependent rows). */
int pc_conic_coef_conditions(const double rows[30], double coef[6]);
/* The condition "the conic passes through (x, y)". */
void pc_conic_row_point(double x, double y, double row[6]);
/* The condition "the conic's tangent at (x, y) has the direction (dx, dy)": the gradient at
 * the point is normal to it, (2ax + by + d) dx + (bx + 2cy + e) dy = 0 (with the point's own
 * row it makes the line tangent there). */
void pc_conic_row_tangent(double x, double y, double dx, double dy, double row[6]);
/* The slope dy/dx of the conic at its point (x, y): -(2ax + by + d)/(bx + 2cy + e) (the
 * textbook's slope of an implicit curve, §3.1).  PC_EPOLE where the tangent is vertical,
 * PC_EZERO at a singular point (both partials 0). */
int pc_conic_slope(const double coef[6], double x, double y, double *slope);

/* The elements of the conic coef (copied into out->coef after scaling); the arc fields NaN.
 * PC_EDOMAIN for a degenerate conic (no quadratic part, a line pair, parallel lines, no real
 * points), PC_ENONFINITE. */
int pc_conic_info_coef(const double coef[6], pc_conic_info *out);

/* The elements of the arc h (as pc_conic_coef_rquad), the kind by mu (|mu - 1| <= 1e-12 a
 * parabola) and the weight fields filled in.  Errors as the two functions above. */
int pc_conic_info_rquad(const double h[9], pc_conic_info *out);

/* The conic a 2-D curve lies on: a rational quadratic Bezier curve (every piece, checked to
 * lie on the first piece's conic) by its control points, any other curve by five of its points
 * checked at eleven more (within 1e-9 of the curve's size).  PC_EDIM for a curve that is not
 * 2-D, PC_ENOTCOLLINEAR ("not on one conic") when the curve is not a conic, else as above. */
int pc_curve_conic(const pc_curve *c, pc_conic_info *out);

/* The value of the conic's equation at (x, y). */
double pc_conic_eq(const double coef[6], double x, double y);

#endif
