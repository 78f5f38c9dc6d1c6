/* What a surface's constructors and drawing calls need, by status (surface.h, why.h). */
#include "surface.h"

const pc_why pc_surface_why[] = {
    {"surface.coons", PC_EDOMAIN, 0, NULL, "the boundary curves do not meet at the corners (cu0 and c0v must start "
                                           "together, cu0 must end where c1v starts, ...)"},
    {"surface.revolution", PC_EZERO, 3, NULL, "must be a nonzero vector (the axis)"},
    {"s:shade", PC_EZERO, 0, "light", "must be a nonzero vector (the direction towards the light), got V(0, 0, 0)"},
    {"s:shade", PC_ESINGULAR, 0, NULL, "the projection is singular (it flattens space onto a line)"},
    {NULL, 0, 0, NULL, NULL}};
