/* What failed in a construction of the monograph: the explanation of each status of each
 * operation of the conic, oneratio, interp, approx, konopatsky and plane.conic_slope tables,
 * by the name the API gives the operation (why.h). */
#ifndef PC_KONOP_WHY_H
#define PC_KONOP_WHY_H

#include "why_call.h"

extern const pc_why pc_konop_why[];

/* plane.conic_slope: the slope of the conic coef at its point X (pc_conic_slope_on; a vertical
 * tangent is +inf), a failure explained in w: X off the curve with the equation's value there,
 * else the rows of pc_konop_why (another status with an empty table). */
int pc_conic_slope_checked(const double coef[6], const double X[2], double *slope, pc_why_call *w);

#endif
