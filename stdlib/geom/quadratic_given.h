/* The elements of the conic fixed by given points and tangents (quadratic.h): the whole path
 * from the conditions to pc_conic_info, with a status of its own for each way the conditions
 * can fail to fix one conic. */
#ifndef PC_QUADRATIC_GIVEN_H
#define PC_QUADRATIC_GIVEN_H

#include "quadratic.h"

/* The conic through the five points pts (5 rows of 2): pc_conic_coef_five, then
 * pc_conic_info_coef.  PC_ECOINCIDENT where the points fix no single conic (four of them
 * collinear, or two coincide), else the statuses of pc_conic_info_coef. */
int pc_conic_info_five(const double pts[10], pc_conic_info *out);

/* The conic of np points (rows x, y) and nt tangents (rows x, y, dx, dy: the direction at a
 * point, given among the points or not), np + nt = 5: pc_conic_coef_conditions, then
 * pc_conic_info_coef.  PC_EDIM unless np + nt = 5, PC_ESINGULAR for dependent conditions,
 * else the statuses of pc_conic_info_coef. */
int pc_conic_info_given(int np, const double *pts, int nt, const double *tangents, pc_conic_info *out);

#endif
