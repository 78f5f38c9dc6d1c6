/* Point equations in Lua (l_expr.c): the hooks by which the point, curve, surface and smoothstep
 * bindings hand an operation over when one of its operands is an equation (a value built on a
 * symbolic parameter, param "t").  Each hook is called only where the plain path has failed
 * (an operand that is not a point or a number), so numbers and points keep their speed. */
#ifndef PCL_EXPR_H
#define PCL_EXPR_H

#include "pcl.h"
#include "expr.h"   /* pc_expr_verb: the operations the point binding defers (their order) */

int pcl_isequation(lua_State *L, int idx);
/* If one of the operation's arguments is an equation: push the resulting equation and return
 * 1 (or raise the operation's error); else return 0 and leave the stack as it was. */
int pcl_eq_hook(lua_State *L, pc_expr_verb op);
/* g(t) of a smoothstep for an equation at idx: push it and return 1; 0 if idx is no equation. */
int pcl_eq_smooth(lua_State *L, int idx, const pc_gfun *g);
/* c(eq) of a single-piece Bezier curve c at the scalar equation at idx: push the composed
 * point equation and return 1; 0 if idx is no equation (raises for other curves). */
int pcl_eq_curve_apply(lua_State *L, const pc_curve *c, int idx);
/* curve(eq, t0, t1) (nwant 1) and surface(eq, u0, u1, v0, v1) (nwant 2; lo < hi checked by the
 * caller) of the equation at 1: the core object (the membership condition raised here). */
void *pcl_eq_object(lua_State *L, int nwant, const double *lo, const double *hi, int *status);

#endif
