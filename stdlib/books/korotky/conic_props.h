/* The conic of a rational quadratic arc and its metric elements: centre, principal
 * diameters and asymptotes (Korotky 2015, Fig. 2c: the generator k2 of a conic sweep with its
 * centre O, axes and asymptotes e1, e2; digest korotky_curves_surfaces.md B.3 steps 5-6).
 * Coefficients are {a, b, c, d, e, f} of a x^2 + b x y + c y^2 + d x + e y + f = 0, the
 * convention of plane_curves.h. */
#ifndef PC_CONIC_PROPS_H
#define PC_CONIC_PROPS_H

#include "plane_curves.h"

/* The implicit equation of the plane arc with the homogeneous control points cp (3 rows of
 * 3: U, w W, V, as pc_conic_arc_cp writes them; W may be at infinity, any weight may differ
 * from 1).  In the barycentric coordinates (alpha, beta, gamma) of the triangle U, W, V the arc
 * is beta^2 = 4 w^2 alpha gamma (B.3 step 5, the bitangent pencil L_U L_V - mu L_UV^2 with
 * mu = 1/(4 w^2)): the kernel's pc_conic_coef_rquad (quadratic.h).  PC_ECOLLINEAR
 * when U, W, V are collinear (w = 0 is the chord, a double line: also PC_ECOLLINEAR),
 * PC_ENONFINITE for NaN/inf. */
int pc_conic_from_arc(const double *cp, double coef[6]);

typedef struct {
    pc_conic_class kind;
    int central;           /* 1 for an ellipse or a hyperbola (the centre exists) */
    double center[2];
    double axis[2][2];     /* unit principal directions: axis[0] the major (ellipse) or the
                              transverse (hyperbola) axis; a parabola's axis[0] is its axis */
    double semi[2];        /* semi-axes along axis[0], axis[1] (a hyperbola's conjugate
                              semi-axis in semi[1]); 0 where undefined (parabola) */
    int nasym;             /* 2 for a hyperbola */
    double asym[2][2];     /* unit directions of the asymptotes, through the centre */
} pc_conic_elements;

/* Centre (solve [a b/2; b/2 c] (x0, y0) = -(d/2, e/2)), principal directions (eigenvectors of
 * that matrix), semi-axes sqrt(-f0 / lambda_i) with f0 the value of the equation at the
 * centre, and for a hyperbola the asymptote directions (roots of a dx^2 + b dx dy + c dy^2 =
 * 0).  The kind by the discriminant b^2 - 4ac, "= 0" within 1e-12 of the largest of a^2,
 * b^2, c^2.  PC_EDOMAIN if a = b = c = 0 or the conic is degenerate (f0 = 0: a line pair, or no
 * real points), PC_ENONFINITE for NaN/inf. */
int pc_conic_elements_of(const double coef[6], pc_conic_elements *out);

#endif
