/* What failed in a construction of the monograph: the explanation of each status of each
 * operation of the conic, oneratio, interp, approx, konopatsky and plane.conic_slope tables,
 * by the name the API gives the operation (why.h). */
#ifndef PC_KONOP_WHY_H
#define PC_KONOP_WHY_H

#include "why.h"

extern const pc_why pc_konop_why[];

#endif
