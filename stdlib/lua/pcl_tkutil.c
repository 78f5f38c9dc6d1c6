/* Argument checks and point conversion shared by the toolkit bindings (see pcl_tk.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "pcl_tk.h"

int tk_argerror(lua_State *L, const char *fname, int arg, const char *what, const char *expected) {
    return tk_argerror_at(L, fname, arg, arg, what, expected);
}

int tk_argerror_at(lua_State *L, const char *fname, int idx, int arg, const char *what,
                   const char *expected) {
    return pcl_argerror_full(L, fname, idx, arg, what, expected);
}

double tk_checknum(lua_State *L, const char *fname, int arg, const char *what) {
    if (lua_type(L, arg) != LUA_TNUMBER) tk_argerror(L, fname, arg, what, "a number");
    double v = lua_tonumber(L, arg);
    if (!isfinite(v)) tk_argerror(L, fname, arg, what, "a finite number");
    return v;
}

double tk_checknum_m(lua_State *L, const char *fname, int idx, const char *what) {
    if (lua_type(L, idx) != LUA_TNUMBER) tk_argerror_at(L, fname, idx, idx - 1, what, "a number");
    double v = lua_tonumber(L, idx);
    if (!isfinite(v)) tk_argerror_at(L, fname, idx, idx - 1, what, "a finite number");
    return v;
}

double tk_optnum(lua_State *L, const char *fname, int arg, const char *what, double dflt) {
    if (lua_isnoneornil(L, arg)) return dflt;
    return tk_checknum(L, fname, arg, what);
}

void tk_pushpoint(lua_State *L, int n, const double *x) {
    pcl_value *p = pcl_newvalue(L, n);
    memcpy(p->h, x, sizeof(double) * (size_t)n);
    p->h[n] = 1.0;
}

void tk_pushvector(lua_State *L, int n, const double *x) {
    pcl_value *p = pcl_newvalue(L, n);
    memcpy(p->h, x, sizeof(double) * (size_t)n);
    p->h[n] = 0.0;
}

const char *tk_pushnum(lua_State *L, double x) {
    char buf[40];
    if (x == 0) x = 0;   /* no "-0" */
    snprintf(buf, sizeof buf, "%.14g", x);
    return lua_pushstring(L, buf);
}

int tk_statuserror(lua_State *L, const char *fname, int status, const char *context) {
    if (context && context[0])
        return pcl_error(L, "%s: %s (%s)", fname, context, pc_strerror(status));
    return pcl_error(L, "%s: %s", fname, pc_strerror(status));
}

void tk_private(lua_State *L, int module) {
    module = lua_absindex(L, module);
    if (lua_getfield(L, module, "_tk") != LUA_TTABLE) {
        lua_pop(L, 1);
        lua_newtable(L);
        lua_pushvalue(L, -1);
        lua_setfield(L, module, "_tk");
    }
}
