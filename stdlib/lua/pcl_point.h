/* Shared by the point-calculus bindings (l_point.c, l_simplex.c, l_map.c): the point
 * userdata and its argument checks.  A value of dimension n is a full userdata holding n
 * weighted coordinates and the weight (see stdlib/geom/point.h), with the point metatable. */
#ifndef PCL_POINT_H
#define PCL_POINT_H

#include "pcl.h"
#include "point.h"

typedef struct {
    int n;          /* dimension */
    double h[];     /* h[0..n-1] weighted coordinates, h[n] the weight */
} pcl_value;

/* The value at idx, or NULL if it is not a point/vector. */
pcl_value *pcl_tovalue(lua_State *L, int idx);
/* Push a new value of dimension n (its doubles uninitialised). */
pcl_value *pcl_newvalue(lua_State *L, int n);
/* Push a point (weight 1) or a vector (weight 0) of dimension n. */
void pcl_pushpoint(lua_State *L, int n, const double *x);
void pcl_pushvector(lua_State *L, int n, const double *x);
/* __concat of points and equations: tostring of each operand, joined. */
int pcl_concat(lua_State *L);

#endif
