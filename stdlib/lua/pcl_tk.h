/* Shared by the toolkit bindings (l_smooth.c, l_curve.c, l_curvilinear.c, l_complex.c): the
 * hooks through which the curve builders recognise the smoothsteps of l_smooth.c. */
#ifndef PCL_TK_H
#define PCL_TK_H

#include "pcl_point.h"
#include "smooth.h"

/* Is f smooth.sine or smooth.cubic (*kind then a pc_gkind)?  The half-spline at idx, or NULL. */
int pcl_smooth_isfunc(lua_CFunction f, int *kind);
pc_hspline *pcl_tohspline(lua_State *L, int idx);
#endif
