/* What failed in a construction of the textbook: the explanation of each status of each
 * operation of the plane and buimov tables, by the name the API gives the operation (why.h). */
#ifndef PC_BUIMOV_WHY_H
#define PC_BUIMOV_WHY_H

#include "why.h"

extern const pc_why pc_buimov_why[];

#endif
