/* Argument checking shared by all bindings: the house error style
 * "NAME: argument #N (what) must be EXPECTED, got VALUE". */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "pcl.h"

static const char *function_name(lua_State *L) {
    lua_Debug ar;
    if (lua_getstack(L, 0, &ar) && lua_getinfo(L, "n", &ar) && ar.name) return ar.name;
    return "pointcalc";
}

/* What the caller actually passed: numbers are shown by value, everything else by type. */
static const char *got(lua_State *L, int arg) {
    if (lua_type(L, arg) == LUA_TNUMBER) {
        if (lua_isinteger(L, arg)) return lua_pushfstring(L, "%I", lua_tointeger(L, arg));
        return lua_pushfstring(L, "%f", lua_tonumber(L, arg));
    }
    if (lua_isnone(L, arg)) return "nil";
    if (luaL_getmetafield(L, arg, "__name") == LUA_TSTRING) return lua_tostring(L, -1);
    return luaL_typename(L, arg);
}

int pcl_argerror(lua_State *L, int arg, const char *what, const char *expected) {
    const char *name = function_name(L);
    const char *value = got(L, arg);
    return luaL_error(L, "%s: argument #%d (%s) must be %s, got %s", name, arg, what, expected,
                      value);
}

/* The coordinate at arg; `what` names the pair ("" or e.g. "centre"), axis is "x" or "y".
 * The label is only built on the error path: this runs for every pset. */
static double check_coord(lua_State *L, int arg, const char *what, const char *axis) {
    int isnum;
    double v = lua_tonumberx(L, arg, &isnum);
    if (isnum && isfinite(v)) return v;
    char label[48];
    snprintf(label, sizeof label, "%s%s%s", what, what[0] ? " " : "", axis);
    pcl_argerror(L, arg, label, isnum ? "a finite number" : "a number or a point");
    return 0;
}

void pcl_checkxy(lua_State *L, int *arg, double *x, double *y, const char *what) {
    if (lua_type(L, *arg) != LUA_TNUMBER && pcl_topoint2(L, *arg, x, y)) {
        *arg += 1;
        return;
    }
    *x = check_coord(L, *arg, what, "x");
    *y = check_coord(L, *arg + 1, what, "y");
    *arg += 2;
}

int pcl_optxy(lua_State *L, int *arg, double *x, double *y, const char *what) {
    if (lua_isnoneornil(L, *arg)) return 0;
    pcl_checkxy(L, arg, x, y, what);
    return 1;
}
