/* Shared by the toolkit bindings (l_smooth.c, l_curves.c, l_curvilinear.c, l_complex.c): argument
 * checks in the house style with an explicit function name (the toolkit's functions live in
 * sub-tables and objects, e.g. "smooth.half", "S:piece"), points in and out, and the private
 * table _tk through which the Lua helpers of stdlib/lua reach core functions that are not API. */
#ifndef PCL_TK_H
#define PCL_TK_H

#include "pcl_point.h"
#include "status.h"
#include "smooth.h"

/* "FNAME: argument #ARG (WHAT) must be EXPECTED, got VALUE" */
int tk_argerror(lua_State *L, const char *fname, int arg, const char *what, const char *expected);
/* The same for a method or __call: the value at stack index idx is shown as argument #shown. */
int tk_argerror_at(lua_State *L, const char *fname, int idx, int shown, const char *what,
                   const char *expected);
/* A finite number at arg. */
double tk_checknum(lua_State *L, const char *fname, int arg, const char *what);
/* The same for a method or __call argument at stack index idx, shown as argument #idx - 1. */
double tk_checknum_m(lua_State *L, const char *fname, int idx, const char *what);
double tk_optnum(lua_State *L, const char *fname, int arg, const char *what, double dflt);
/* Push a point (weight 1) or a vector (weight 0) of dimension n. */
void tk_pushpoint(lua_State *L, int n, const double *x);
void tk_pushvector(lua_State *L, int n, const double *x);
/* Push x as text the way points print their coordinates: %.14g, no "-0". */
const char *tk_pushnum(lua_State *L, double x);
/* Raise "FNAME: MESSAGE" for a core status. */
int tk_statuserror(lua_State *L, const char *fname, int status, const char *context);
/* Push the private table _tk of the module table at index module (created on first use). */
void tk_private(lua_State *L, int module);

/* From l_smooth.c, for the curve builders: is f smooth.sine or smooth.cubic (*kind is then a
 * pc_gkind)?  The half-spline object at idx, or NULL. */
int pcl_smooth_isfunc(lua_CFunction f, int *kind);
pc_hspline *pcl_tohspline(lua_State *L, int idx);
#endif
