/* Binding of the smoothsteps (stdlib/geom/smooth.h): the table smooth with
 *   smooth.sine(t)  smooth.cubic(t)  smooth.power(n [, t])  smooth.half(n, m, t0 [, t])
 *   smooth.locus(n, m, t0)  smooth.clamp(t)  smooth.clamp_qb(t [, prev])
 * smooth.power(n) and smooth.half(n, m, t0) without t return a half-spline object g: g(t)
 * evaluates, g:deriv(t) is the slope, and g.n g.m g.t0 g.c1 g.c2 g.v (the junction ordinate
 * v(t0)) are its parameters.  The curve builders accept these objects, smooth.sine and
 * smooth.cubic as smoothsteps they evaluate natively. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "pcl_tk.h"
#include "smooth.h"
#include "pcl_expr.h"   /* g(t) of an equation t builds an equation (l_expr.c) */

#define HSPLINE_MT "halfspline"

/* g(t) pushed, or an error when it is not finite: an extrapolation far past [0, 1]
 * (smooth.cubic(1e308)) overflows, and no NaN or infinity is returned silently. */
static int push_value(lua_State *L, const char *fname, double t, double g) {
    if (!isfinite(g))
        return pcl_error(L, "%s: the value at t = %s is out of range (not finite)", fname,
                         pcl_pushnum(L, t));
    lua_pushnumber(L, g);
    return 1;
}

static int l_sine(lua_State *L) {
    static const pc_gfun g = {PC_G_SINE, {0, 0, 0, 0, 0}};
    if (lua_type(L, 1) != LUA_TNUMBER && pcl_eq_smooth(L, 1, &g)) return 1;
    double t = pcl_checknum(L, "smooth.sine", 1, "t");
    return push_value(L, "smooth.sine", t, pc_smooth_sine(t));
}

static int l_cubic(lua_State *L) {
    static const pc_gfun g = {PC_G_CUBIC, {0, 0, 0, 0, 0}};
    if (lua_type(L, 1) != LUA_TNUMBER && pcl_eq_smooth(L, 1, &g)) return 1;
    double t = pcl_checknum(L, "smooth.cubic", 1, "t");
    return push_value(L, "smooth.cubic", t, pc_smooth_cubic(t));
}

/* the smoothsteps the curve bindings recognise by identity */
int pcl_smooth_isfunc(lua_CFunction f, int *kind) {
    if (f == l_sine) *kind = PC_G_SINE;
    else if (f == l_cubic) *kind = PC_G_CUBIC;
    else return 0;
    return 1;
}

static pc_hspline *newhs(lua_State *L) {
    pc_hspline *h = lua_newuserdatauv(L, sizeof *h, 0);
    luaL_setmetatable(L, HSPLINE_MT);
    return h;
}

/* The half-spline at idx or NULL; one given the metatable by the debug library is refused. */
pc_hspline *pcl_tohspline(lua_State *L, int idx) {
    pc_hspline *h = luaL_testudata(L, idx, HSPLINE_MT);
    return pcl_genuine(L, idx, h, !h || lua_rawlen(L, idx) == sizeof *h, "half-spline");
}

/* g of g(t), g:deriv(t), g.n, tostring(g) */
static pc_hspline *checkhs(lua_State *L, const char *fn) {
    pc_hspline *h = pcl_tohspline(L, 1);
    if (!h) pcl_argerror_full(L, fn, 1, 0, NULL, "a half-spline (smooth.half(n, m, t0))");
    return h;
}

static void check_degree(lua_State *L, const char *fname, int arg, const char *what, double v) {
    if (!(v > 0)) pcl_argerror_full(L, fname, arg, arg, what, "a positive number");
}

/* The half-spline (n, m, t0), its parameters already checked one by one; degrees in the
 * hundreds make t0^(n-1) underflow, and the coefficients would be inf and NaN. */
static void init_checked(lua_State *L, const char *fname, pc_hspline *h, double n, double m,
                         double t0) {
    if (pc_hspline_init(h, n, m, t0) == PC_OK) return;
    const char *tn = pcl_pushnum(L, n), *tm = pcl_pushnum(L, m), *tt = pcl_pushnum(L, t0);
    pcl_error(L, "%s: the degrees n = %s, m = %s are too large for t0 = %s: the coefficients "
              "c1, c2 overflow a double", fname, tn, tm, tt);
}

/* g(t) at argument idx (shown as #shown), with the extrapolation domain of a fractional
 * degree: t^n needs t >= 0, (1 - t)^m needs t <= 1 unless the degree is whole. */
static double checked_t(lua_State *L, const pc_hspline *h, const char *fname, int idx,
                        int shown) {
    if (lua_type(L, idx) != LUA_TNUMBER) pcl_argerror_full(L, fname, idx, shown, "t", "a number");
    double t = lua_tonumber(L, idx);
    if (!isfinite(t)) pcl_argerror_full(L, fname, idx, shown, "t", "a finite number");
    if (pc_hspline_check(h, t) != PC_OK) {
        int low = t < 0;
        pcl_pushnum(L, low ? h->n : h->m);
        lua_pushfstring(L, "%s (the degree %s = %s is fractional, so the formula does not "
                        "extrapolate past %s)", low ? "at least 0" : "at most 1", low ? "n" : "m",
                        lua_tostring(L, -1), low ? "0" : "1");
        pcl_argerror_full(L, fname, idx, shown, "t", lua_tostring(L, -1));
    }
    return t;
}

static int l_power(lua_State *L) {
    const char *fn = "smooth.power";
    double n = pcl_checknum(L, fn, 1, "n");
    check_degree(L, fn, 1, "n", n);
    pc_hspline h;
    init_checked(L, fn, &h, n, n, 0.5);
    if (!lua_isnoneornil(L, 2)) {
        double t = checked_t(L, &h, fn, 2, 2);
        return push_value(L, fn, t, pc_hspline_eval(&h, t));
    }
    *newhs(L) = h;
    return 1;
}

static int l_half(lua_State *L) {
    const char *fn = "smooth.half";
    double n = pcl_checknum(L, fn, 1, "n"), m = pcl_checknum(L, fn, 2, "m");
    double t0 = pcl_checknum(L, fn, 3, "t0");
    check_degree(L, fn, 1, "n", n);
    check_degree(L, fn, 2, "m", m);
    if (!(t0 > 0 && t0 < 1)) pcl_argerror_full(L, fn, 3, 3, "t0", "a number in (0, 1)");
    pc_hspline h;
    init_checked(L, fn, &h, n, m, t0);
    if (!lua_isnoneornil(L, 4)) {
        double t = checked_t(L, &h, fn, 4, 4);
        return push_value(L, fn, t, pc_hspline_eval(&h, t));
    }
    *newhs(L) = h;
    return 1;
}

static int l_locus(lua_State *L) {
    const char *fn = "smooth.locus";
    double n = pcl_checknum(L, fn, 1, "n"), m = pcl_checknum(L, fn, 2, "m");
    double t0 = pcl_checknum(L, fn, 3, "t0");
    check_degree(L, fn, 1, "n", n);
    check_degree(L, fn, 2, "m", m);
    if (!(t0 >= 0 && t0 <= 1)) pcl_argerror_full(L, fn, 3, 3, "t0", "a number in [0, 1]");
    lua_pushnumber(L, pc_hspline_locus(n, m, t0));
    return 1;
}

static int l_clamp(lua_State *L) {
    lua_pushnumber(L, pc_smooth_clamp(pcl_checknum(L, "smooth.clamp", 1, "t")));
    return 1;
}

static int l_clamp_qb(lua_State *L) {
    const char *fn = "smooth.clamp_qb";
    double t = pcl_checknum(L, fn, 1, "t");   /* finite, as smooth.clamp's (QBasic has no NaN) */
    double prev = pcl_optnum(L, fn, 2, "prev", 0.0);
    lua_pushnumber(L, pc_smooth_clamp_qb(t, prev));
    return 1;
}

/* ---- the half-spline object ------------------------------------------------------------- */

static int hs_call(lua_State *L) {
    pc_hspline *h = checkhs(L, "halfspline");
    if (lua_type(L, 2) != LUA_TNUMBER) {
        pc_gfun g = {PC_G_HALF, *h};
        if (pcl_eq_smooth(L, 2, &g)) return 1;
    }
    double t = checked_t(L, h, "halfspline", 2, 1);
    return push_value(L, "halfspline", t, pc_hspline_eval(h, t));
}

static int hs_deriv(lua_State *L) {
    pc_hspline *h = checkhs(L, "g:deriv");
    double t = checked_t(L, h, "g:deriv", 2, 1);
    double d = pc_hspline_deriv(h, t);
    /* a degree below 1 has a vertical tangent at its end: t^n with n < 1 at t = 0 */
    if (!isfinite(d))
        return pcl_error(L, "g:deriv: the slope at t = %s is infinite (a degree below 1)",
                         pcl_pushnum(L, t));
    lua_pushnumber(L, d);
    return 1;
}

static int hs_index(lua_State *L) {
    pc_hspline *h = checkhs(L, "g.field");
    const char *k = lua_tostring(L, 2);
    if (!k) return 0;
    if (!strcmp(k, "n")) lua_pushnumber(L, h->n);
    else if (!strcmp(k, "m")) lua_pushnumber(L, h->m);
    else if (!strcmp(k, "t0")) lua_pushnumber(L, h->t0);
    else if (!strcmp(k, "c1")) lua_pushnumber(L, h->c1);
    else if (!strcmp(k, "c2")) lua_pushnumber(L, h->c2);
    else if (!strcmp(k, "v")) lua_pushnumber(L, pc_hspline_eval(h, h->t0));
    else if (!strcmp(k, "deriv")) lua_pushcfunction(L, hs_deriv);
    else return 0;
    return 1;
}

static int hs_tostring(lua_State *L) {
    pc_hspline *h = checkhs(L, "tostring");
    pcl_pushnum(L, h->n);
    pcl_pushnum(L, h->m);
    pcl_pushnum(L, h->t0);
    lua_pushfstring(L, "smooth.half(%s, %s, %s)", lua_tostring(L, -3), lua_tostring(L, -2),
                    lua_tostring(L, -1));
    return 1;
}

void pcl_open_smooth(lua_State *L) {
    int module = lua_gettop(L);
    luaL_newmetatable(L, HSPLINE_MT);
    static const luaL_Reg meta[] = {
        {"__call", hs_call}, {"__index", hs_index}, {"__tostring", hs_tostring}, {NULL, NULL}};
    luaL_setfuncs(L, meta, 0);
    lua_pop(L, 1);
    static const luaL_Reg fns[] = {
        {"sine", l_sine},   {"cubic", l_cubic}, {"power", l_power},       {"half", l_half},
        {"locus", l_locus}, {"clamp", l_clamp}, {"clamp_qb", l_clamp_qb}, {NULL, NULL}};
    lua_newtable(L);
    luaL_setfuncs(L, fns, 0);
    lua_setfield(L, module, "smooth");
}
