/* The non-rational curves of Konopatsky's chapter 2 (digest konopatsky_ch1_2.md §5): point
 * equations M = (A - C) F(t) + (B - C) G(t) + C in the simplex CAB whose coefficients involve
 * angles, radii or square roots.  Each is a FUNC curve of the one curve type with a C callback;
 * where the book's curve goes to infinity (hyperbolas) the callback returns the homogeneous
 * value with weight 0 there, so the flattener breaks the polyline instead of drawing across.
 *
 * Triangle notation as the book's sections use it: for the ellipse and hyperbola (§2.1.1-2)
 * a = |CA| (the real semi-axis) and b = |CB|; elsewhere Fig. 2.1's a = |BC|, b = |CA|,
 * gamma = angle BCA. */
#ifndef PC_KONOP_CURVES_H
#define PC_KONOP_CURVES_H

#include "curve.h"

typedef enum {
    PC_KC_ELLIPSE_ANGLE,       /* (2.11) central angle phi in [0, 2pi] */
    PC_KC_ELLIPSE_RADIUS,      /* (2.15) rho = |CM| in [b, a] (first quadrant), a > b */
    PC_KC_ELLIPSE_FOCAL,       /* (2.18) angle at the focus F2 = C - (A - C)e, phi in [0, 2pi] */
    PC_KC_ELLIPSE_COMPRESSION, /* (2.24) (A - C)cos phi + (B - C)sin phi + C, any CA, CB */
    PC_KC_ELLIPSE_ALGEBRAIC,   /* (A - C)sqrt(1 - t^2) + (B - C)t + C, t in [-1, 1] */
    PC_KC_HYPERBOLA_ANGLE,     /* (2.49) par[0] = branch: 1 through A, 2 through 2C - A */
    PC_KC_HYPERBOLA_RADIUS,    /* (2.53) rho in [a, rho_max] (first quadrant; range [2a] default) */
    PC_KC_HYPERBOLA_FOCAL,     /* (2.56) angle at F1 = C + (A - C)e; par[0] = branch */
    PC_KC_CIRCLE_ANGLE,        /* (2.115) par[0] = delta: angle AMC = delta, phi in [0, pi] */
    PC_KC_CIRCLE_RADIUS,       /* (2.118) par[0] = R: centre C, phi in [0, 2pi] */
    PC_KC_PARABOLA_ANGLE,      /* §2.4.1 the one-ratio parabola by phi = angle MCA in [0, gamma] */
    PC_KC_PARABOLA_SIGMA,      /* §2.4.2 by sigma = CK + KM (not |CM|, digest); par[0] = 1 or 2 */
    PC_KC_SINUSOID,            /* (2.145) par[0] = number of generations g, par[1..g] = k_i */
    PC_KC_CYCLOID,             /* §2.8 par[0] = 0 convex (3.11), 1 concave (3.12), phi in [0, pi] */
    PC_KC_NKINDS
} pc_kcurve_kind;

#define PC_KC_MAXPAR 9

/* The curve of `kind` in the simplex CAB (Cartesian points of dim), with par[0..npar-1] as the
 * kind says, over [t0, t1]; t0 and t1 NaN: the book's range (pc_kcurve_range).  PC_ECOLLINEAR
 * for a flat triangle, PC_EDOMAIN for parameters outside the book's conditions (a <= b for
 * the radial ellipse, delta not in (0, pi), ...), PC_EDOMAIN2 unless t0 < t1 (both finite),
 * PC_EDOMAIN3 for a range beyond the form's real points (pc_kcurve_range). */
pc_curve *pc_kcurve(pc_kcurve_kind kind, int dim, const double *c, const double *a,
                    const double *b, const double *par, int npar, double t0, double t1,
                    int *status);
/* The book's parameter range of that curve. */
int pc_kcurve_range(pc_kcurve_kind kind, int dim, const double *c, const double *a,
                    const double *b, const double *par, int npar, double *t0, double *t1);

/* §2.1.1.1 The tilted ellipse (Fig. 2.5): the ends P, Q of the semi-axes m (major) and n
 * (minor) of the ellipse centred at C whose major axis makes the angle theta with line AB (the
 * printed K lacks the factor c and the printed rotated A has (C - A); digest §5.1).  The
 * ellipse itself is then PC_KC_ELLIPSE_ANGLE in the simplex C P Q. */
int pc_ellipse_tilted_axes(int dim, const double *a, const double *b, const double *c,
                           double theta, double m, double n, double *p, double *q);

/* The auxiliary points of the same construction: K = CP x AB (homogeneous, dim + 1 numbers, a
 * direction at theta = 0), A rotated about C by 3 pi/2 - alpha - theta towards B (so that
 * Q = (arot - C) n/b + C) and tau = angle ACK = pi - alpha - theta.  The printed K lacks the
 * factor c, the printed rotated A has (C - A) for (A - C). */
int pc_ellipse_tilted_scheme(int dim, const double *a, const double *b, const double *c,
                             double theta, double *k, double *arot, double *tau);
/* The whole construction: the ellipse (PC_KC_ELLIPSE_ANGLE in the simplex C P Q), and into out
 * P, Q (dim each), K (dim + 1), the rotated A (dim) and tau; the statuses of the two above. */
pc_curve *pc_ellipse_tilted(int dim, const double *a, const double *b, const double *c, double theta,
                            double m, double n, double *out, int *status);

/* §2.6 The cubic as the meet of two quadric cones over the arcs APB (f_P) and AQB (f_Q) of
 * (2.97) in the plane ABC, with vertices D and N = (D - A)n + A: M = DP x NQ with Q at
 * v = f_P f_Q' u/(f_P f_Q' u + f_Q f_P' u') (2.148).  3-D or more; u in [0, 1].  The printed
 * z_Q has f_Q^2 for f_Q'^2 (digest §5.13); the line meet replaces the per-axis quotient
 * (2.159).  PC_EDIM below 3-D, PC_EDOMAIN unless 0 < f_P < 1, PC_EDOMAIN2 unless 0 < f_Q < 1,
 * PC_EDOMAIN3 for n = 0 or 1, PC_ECOLLINEAR unless ABCD is a tetrahedron. */
pc_curve *pc_cubic_cones(int dim, const double *a, const double *b, const double *c,
                         const double *d, double fp, double fq, double n, int *status);

/* (2.161) The general contour arc A1 -> A2 with tangents meeting at A3, driven by u(t), v(t)
 * with u(0) = v(0) = 0, u(1) = v(1) = 1 and their derivatives (du, dv; NULL: central
 * differences).  The functions are called with ud; a NaN result fails the evaluation with
 * PC_ENONFINITE.  The ends are the limits A1 and A2. */
typedef double (*pc_real_fn)(void *ud, int which, double t);   /* which: 0 u, 1 v, 2 u', 3 v' */
pc_curve *pc_contour_arc(int dim, const double *a1, const double *a2, const double *a3,
                         pc_real_fn f, int has_derivs, void (*fn_free)(void *ud), void *ud,
                         int *status);

#endif
