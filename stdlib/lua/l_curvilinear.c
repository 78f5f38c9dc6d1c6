/* Binding of the coordinate maps and scalar numerics (stdlib/books/stepanov/curvilinear.h, numeric.h):
 *   squash(p [, q])  squash01(p [, q])     the plane onto the open square (examples 26-28)
 *   oblique(C0, r, k, u)                    the oblique projection of examples 32-34
 *   projection(C0, C1, C2, C3)              the projection by four screen points
 *                                           (both are 3-D -> 2-D maps of l_map.c: pr(X), pr:xy, pr.C0)
 *   oresme(lambda [, m [, y0, y1]])         Oresme's lambda-function (example 31)
 *   bisect(f, a, b [, tol])                 bisection (example 30)
 * and, for stdlib/lua/curvilinear.lua, the numeric helpers _tk.bilinear, _tk.frame_point,
 * _tk.frame_coords, _tk.patch_blend. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "pcl_tk.h"
#include "curvilinear.h"
#include "map.h"
#include "numeric.h"

#define ORESME_MT "oresme"
static const char ORESME_TAG = 'o';   /* its address tags the type (PCL_SELF_TAG) */

/* ---- plane -> square ------------------------------------------------------------------------ */

static int squash_with(lua_State *L, const char *fn, double (*f)(double)) {
    int n = lua_gettop(L) < 2 ? 1 : 2;
    for (int i = 1; i <= n; i++) {
        if (lua_type(L, i) != LUA_TNUMBER) pcl_argerror_full(L, fn, i, i, i == 1 ? "p" : "q", "a number");
        double p = lua_tonumber(L, i);   /* +-inf are the square's sides; NaN is no place */
        if (isnan(p)) pcl_argerror_full(L, fn, i, i, i == 1 ? "p" : "q", "a number other than NaN");
        lua_pushnumber(L, f(p));
    }
    return n;
}
static int l_squash(lua_State *L) { return squash_with(L, "squash", pc_squash); }
static int l_squash01(lua_State *L) { return squash_with(L, "squash01", pc_squash01); }

/* ---- projections: maps of the one map type (l_map.c) ------------------------------------------ */

/* The 3-D -> 2-D affine map (x, y, z) -> C0 + x (C1 - C0) + y (C2 - C0) + z (C3 - C0) of the
 * four screen points c[8]; its translation and axes give the same sums as pc_project4. */
static void push_projection(lua_State *L, const double c[8]) {
    double axes[6];
    for (int i = 0; i < 3; i++)
        for (int d = 0; d < 2; d++) axes[2 * i + d] = c[2 * (i + 1) + d] - c[d];
    pc_map_frame(pcl_newmap(L), 2, 3, c, axes);
}

static int l_oblique(lua_State *L) {
    const char *fn = "oblique";
    double c0[2], c[8];
    pcl_checkloc(L, 1, "C0", 2, 0, c0);
    double r = pcl_checknum(L, fn, 2, "r"), k = pcl_checknum(L, fn, 3, "k");
    double u = pcl_checknum(L, fn, 4, "u");
    pc_oblique_axes(c0, r, k, u, c);
    push_projection(L, c);
    return 1;
}

static int l_projection(lua_State *L) {
    static const char *names[] = {"C0", "C1", "C2", "C3"};
    double c[8];
    for (int i = 0; i < 4; i++) pcl_checkloc(L, i + 1, names[i], 2, 1, c + 2 * i);
    push_projection(L, c);
    return 1;
}

/* ---- Oresme ----------------------------------------------------------------------------------- */

typedef struct {
    PCL_SELF;           /* a 2-D point has the size of a short sequence: self tells (pcl.h) */
    double lambda;
    int m;
    double y[];
} oresme;

/* The Oresme sequence of a method call (o(t), o[j], #o, tostring(o)); its block is exactly
 * the header and 2^m + 1 values, so one given the metatable by the debug library is refused. */
static oresme *checkoresme(lua_State *L, const char *fn) {
    oresme *o = luaL_testudata(L, 1, ORESME_MT);
    if (!o) pcl_argerror_full(L, fn, 1, 0, NULL, "an Oresme sequence (oresme(lambda, m))");
    size_t len = lua_rawlen(L, 1);
    int ok = len >= sizeof *o && o->self == PCL_SELF_TAG(o, &ORESME_TAG) && o->m >= 0 &&
             o->m <= PC_ORESME_MAXLEVEL &&
             len == sizeof *o + sizeof(double) * (size_t)((1L << o->m) + 1);
    return pcl_genuine(L, 1, o, ok, "Oresme sequence");
}

static int oresme_call(lua_State *L) {
    oresme *o = checkoresme(L, "oresme");
    lua_pushnumber(L, pc_oresme_at(o->y, o->m, pcl_checknum_m(L, "oresme", 2, "t")));
    return 1;
}

static int oresme_index(lua_State *L) {
    oresme *o = checkoresme(L, "o[j]");
    if (lua_isinteger(L, 2)) {
        lua_Integer j = lua_tointeger(L, 2);
        if (j < 0 || j > (1L << o->m)) return 0;
        lua_pushnumber(L, o->y[j]);
        return 1;
    }
    const char *k = lua_tostring(L, 2);
    if (!k) return 0;
    if (!strcmp(k, "lambda")) lua_pushnumber(L, o->lambda);
    else if (!strcmp(k, "m")) lua_pushinteger(L, o->m);
    else if (!strcmp(k, "n")) lua_pushinteger(L, 1L << o->m);
    else return 0;
    return 1;
}

static int oresme_len(lua_State *L) {
    oresme *o = checkoresme(L, "#");
    lua_pushinteger(L, 1L << o->m);
    return 1;
}

static int oresme_tostring(lua_State *L) {
    oresme *o = checkoresme(L, "tostring");
    pcl_pushnum(L, o->lambda);
    lua_pushfstring(L, "oresme(%s, %d)", lua_tostring(L, -1), o->m);
    return 1;
}

static int l_oresme(lua_State *L) {
    const char *fn = "oresme";
    double lambda = pcl_checknum(L, fn, 1, "lambda");
    lua_Integer m = 12;
    if (!lua_isnoneornil(L, 2)) {
        int isint;
        m = lua_tointegerx(L, 2, &isint);
        if (!isint || m < 0 || m > PC_ORESME_MAXLEVEL)
            pcl_argerror_full(L, fn, 2, 2, "m", "an integer 0..24 (2^m cells)");
    }
    double y0 = pcl_optnum(L, fn, 3, "y0", 0.0), y1 = pcl_optnum(L, fn, 4, "y1", 1.0);
    long n = 1L << m;
    oresme *o = lua_newuserdatauv(L, sizeof *o + sizeof(double) * (size_t)(n + 1), 0);
    o->self = PCL_SELF_TAG(o, &ORESME_TAG);
    o->lambda = lambda;
    o->m = (int)m;
    luaL_setmetatable(L, ORESME_MT);
    int st = pc_oresme_fill(lambda, (int)m, y0, y1, o->y);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    return 1;
}

/* ---- bisection --------------------------------------------------------------------------------- */

static double call_f(double x, void *ud) {
    lua_State *L = ud;
    lua_pushvalue(L, 1);
    lua_pushnumber(L, x);
    lua_call(L, 1, 1);
    int isnum;
    double v = lua_tonumberx(L, -1, &isnum);
    if (!isnum) {
        const char *type = luaL_typename(L, -1);
        pcl_error(L, "bisect: f(%s) must return a number, got %s", pcl_pushnum(L, x), type);
    }
    if (!isfinite(v)) {   /* name the x (the core would only say that some f(x) was not finite) */
        const char *tx = pcl_pushnum(L, x), *tv = pcl_pushnum(L, v);
        pcl_error(L, "bisect: f(%s) must return a finite number, got %s", tx, tv);
    }
    lua_pop(L, 1);
    return v;
}

static int l_bisect(lua_State *L) {
    const char *fn = "bisect";
    lua_settop(L, 4);
    if (!lua_isfunction(L, 1)) {
        if (luaL_getmetafield(L, 1, "__call") == LUA_TNIL) pcl_argerror_full(L, fn, 1, 1, "f", "a function");
        lua_pop(L, 1);
    }
    double a = pcl_checknum(L, fn, 2, "a"), b = pcl_checknum(L, fn, 3, "b");
    double tol = pcl_optnum(L, fn, 4, "tol", 1e-10);
    double x;
    int iters;
    int st = pc_bisect(call_f, L, a, b, tol, &x, &iters);
    if (st == PC_ENOBRACKET)
    {
        double fa = call_f(a, L), fb = call_f(b, L);
        const char *ta = pcl_pushnum(L, a), *tfa = pcl_pushnum(L, fa);
        const char *tb = pcl_pushnum(L, b), *tfb = pcl_pushnum(L, fb);
        return pcl_error(L, "bisect: f(a) and f(b) have the same sign (f(%s) = %s, f(%s) = %s): "
                          "the interval brackets no root", ta, tfa, tb, tfb);
    }
    if (st != PC_OK) return pcl_statuserror(L, fn, st, "f returned NaN or an infinity");
    lua_pushnumber(L, x);
    lua_pushinteger(L, iters);
    return 2;
}

/* ---- numeric helpers for the Lua side -------------------------------------------------------- */

/* _tk.bilinear(P0, P1, P2, P3) -> function(t1, t2) -> x, y[, z ...] */
static int bilinear_eval(lua_State *L) {
    const double *c = lua_touserdata(L, lua_upvalueindex(1));
    int d = (int)lua_tointeger(L, lua_upvalueindex(2));
    double t1 = pcl_checknum(L, "bilinear", 1, "t1"), t2 = pcl_checknum(L, "bilinear", 2, "t2");
    double out[PC_MAXDIM];
    pc_bilinear(d, c, c + d, c + 2 * d, c + 3 * d, t1, t2, out);
    for (int k = 0; k < d; k++) lua_pushnumber(L, out[k]);
    return d;
}

static int l_bilinear(lua_State *L) {
    static const char *names[] = {"P0", "P1", "P2", "P3"};
    double p[PC_MAXDIM];
    int d = pcl_checkloc(L, 1, names[0], 0, 0, p);
    double *c = lua_newuserdatauv(L, sizeof(double) * 4 * (size_t)d, 0);
    memcpy(c, p, sizeof(double) * (size_t)d);
    for (int i = 1; i < 4; i++) pcl_checkloc(L, i + 1, names[i], d, 1, c + i * d);
    lua_pushinteger(L, d);
    lua_pushcclosure(L, bilinear_eval, 2);
    return 1;
}

static int l_frame_point(lua_State *L) {
    double o[2] = {luaL_checknumber(L, 1), luaL_checknumber(L, 2)};
    double e[2] = {luaL_checknumber(L, 3), luaL_checknumber(L, 4)}, out[2];
    pc_frame_point(o, e, luaL_checknumber(L, 5), luaL_checknumber(L, 6), out);
    lua_pushnumber(L, out[0]);
    lua_pushnumber(L, out[1]);
    return 2;
}

static int l_frame_coords(lua_State *L) {
    double o[2] = {luaL_checknumber(L, 1), luaL_checknumber(L, 2)};
    double e[2] = {luaL_checknumber(L, 3), luaL_checknumber(L, 4)};
    double x[2] = {luaL_checknumber(L, 5), luaL_checknumber(L, 6)}, xi, eta;
    int st = pc_frame_coords(o, e, x, &xi, &eta);
    if (st != PC_OK) {
        lua_pushnil(L);
        lua_pushstring(L, pc_strerror(st));
        return 2;
    }
    lua_pushnumber(L, xi);
    lua_pushnumber(L, eta);
    return 2;
}

static int l_patch_blend(lua_State *L) {
    double u0[2] = {luaL_checknumber(L, 1), luaL_checknumber(L, 2)};
    double u2[2] = {luaL_checknumber(L, 3), luaL_checknumber(L, 4)}, out[2];
    pc_patch_blend(u0, u2, luaL_checknumber(L, 5), luaL_checknumber(L, 6), luaL_checknumber(L, 7),
                   luaL_checknumber(L, 8), luaL_checknumber(L, 9), out);
    lua_pushnumber(L, out[0]);
    lua_pushnumber(L, out[1]);
    return 2;
}

void pcl_open_curvilinear(lua_State *L) {
    int module = lua_gettop(L);
    luaL_newmetatable(L, ORESME_MT);
    static const luaL_Reg ometa[] = {{"__call", oresme_call}, {"__index", oresme_index},
                                     {"__len", oresme_len}, {"__tostring", oresme_tostring},
                                     {NULL, NULL}};
    luaL_setfuncs(L, ometa, 0);
    lua_settop(L, module);
    static const luaL_Reg fns[] = {
        {"squash", l_squash}, {"squash01", l_squash01}, {"oblique", l_oblique},
        {"projection", l_projection}, {"oresme", l_oresme}, {"bisect", l_bisect}, {NULL, NULL}};
    luaL_setfuncs(L, fns, 0);
    pcl_private(L, module);
    static const luaL_Reg priv[] = {{"bilinear", l_bilinear}, {"frame_point", l_frame_point},
                                    {"frame_coords", l_frame_coords},
                                    {"patch_blend", l_patch_blend}, {NULL, NULL}};
    luaL_setfuncs(L, priv, 0);
    lua_settop(L, module);
}
