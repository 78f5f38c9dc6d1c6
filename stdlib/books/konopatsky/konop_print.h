/* The book's printed form of a curve's coordinates (ch. 2's coordinate systems, Fig. 2.17's
 * x = 4t(9t + 0,8)/(70t^2 - 75t + 44,2), ch. 4-5's polynomials): each coordinate expanded in
 * powers of the parameter. */
#ifndef PC_KONOP_PRINT_H
#define PC_KONOP_PRINT_H
#include <stddef.h>

/* Coordinate `axis` of the power-basis coefficients coef ((deg + 1) rows of dim + 1: the
 * weighted coordinates and the weight, as pc_curve_monomial gives them) as text, "x = ..."
 * (y, z, then x4, x5, ...): a polynomial when the weight is constant, else N(t)/D(t) with D
 * made monic (a rational form has no other canonical scale; the book's own scale is arbitrary).
 * Coefficients within 1e-12 of the largest are left out, numbers in %.6g, highest power first.
 * PC_EDIM for a bad dim or axis, PC_EDOMAIN for a weight that is identically 0, PC_ENOMEM
 * when buf is too short. */
int pc_k_coordinate_text(const double *coef, int dim, int deg, int axis, const char *var,
                         char *buf, size_t n);
/* The same of coordinate `axis` of the curve c's first piece (pc_curve_monomial): PC_EDOMAIN
 * for a function curve, which has no power-basis form. */
struct pc_curve;
int pc_k_curve_text(const struct pc_curve *c, int axis, const char *var, char *buf, size_t n);

#endif
