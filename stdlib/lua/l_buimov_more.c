/* The textbook's Bezier joints in Lua (books/buimov/buimov.h), in the table buimov:
 *   buimov.g1_next(P, m [, g]) -> Q0, Q1      the next curve's first two control points (§4.3)
 *   buimov.joint(P, Q) -> "none"|"C0"|"G1"|"C1", g */
#include <math.h>
#include "pcl.h"
#include "pcl_curve.h"
#include "pcl_point.h"
#include "buimov.h"

/* The Cartesian control points of a polynomial single-piece Bezier curve at arg. */
static int bez_points(lua_State *L, const char *fn, int arg, const char *what, double *out, int *dim) {
    pc_curve *c = pcl_tocurve(L, arg);
    int ok = c && c->kind == PC_CURVE_BEZIER && c->nknots == 2;
    for (int i = 0; ok && i < c->ncp; i++) ok = c->cp[i * (c->dim + 1) + c->dim] == 1;
    if (!ok) return pcl_argerror_full(L, fn, arg, arg, what, "a polynomial Bezier curve (bezier{P0, ..., Pn})");
    for (int i = 0; i < c->ncp; i++)
        for (int k = 0; k < c->dim; k++) out[i * c->dim + k] = c->cp[i * (c->dim + 1) + k];
    *dim = c->dim;
    return c->degree;
}

static int l_g1_next(lua_State *L) {
    const char *fn = "buimov.g1_next";
    double p[(PC_CURVE_MAXDEG + 1) * PC_MAXDIM], q0[PC_MAXDIM], q1[PC_MAXDIM];
    int dim, n = bez_points(L, fn, 1, "P", p, &dim);
    if (!lua_isinteger(L, 2) || lua_tointeger(L, 2) < 1 || lua_tointeger(L, 2) > PC_CURVE_MAXDEG)
        return pcl_argerror_full(L, fn, 2, 2, "m", "the next curve's degree 1..64");
    int m = (int)lua_tointeger(L, 2);
    double g = pcl_optnum(L, fn, 3, "g", 1);
    int st = pc_bezier_g1_next(dim, n, p, m, g, q0, q1);
    if (st == PC_EDOMAIN) return pcl_error(L, "%s: argument #3 (g) must be positive (the tangents keep their direction)", fn);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    pcl_pushpoint(L, dim, q0);
    pcl_pushpoint(L, dim, q1);
    return 2;
}

static int l_joint(lua_State *L) {
    const char *fn = "buimov.joint";
    double p[(PC_CURVE_MAXDEG + 1) * PC_MAXDIM], q[(PC_CURVE_MAXDEG + 1) * PC_MAXDIM], g;
    int dp, dq, n = bez_points(L, fn, 1, "P", p, &dp), m = bez_points(L, fn, 2, "Q", q, &dq), kind;
    if (dp != dq) return pcl_error(L, "%s: argument #2 (Q) is %d-D, but argument #1 (P) is %d-D: dimensions cannot be mixed", fn, dq, dp);
    int st = pc_bezier_joint(dp, n, p, m, q, &kind, &g);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    static const char *names[4] = {"none", "C0", "G1", "C1"};
    lua_pushstring(L, names[kind]);
    if (isnan(g)) lua_pushnil(L);
    else lua_pushnumber(L, g);
    return 2;
}

/* After pcl_open_buimov, with the module table on top. */
void pcl_open_buimov_more(lua_State *L) {
    lua_getfield(L, -1, "buimov");
    lua_pushcfunction(L, l_g1_next);
    lua_setfield(L, -2, "g1_next");
    lua_pushcfunction(L, l_joint);
    lua_setfield(L, -2, "joint");
    lua_pop(L, 1);
}
