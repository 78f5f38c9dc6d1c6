/* Binding of simplices (stdlib/geom/simplex.h): simplex(C, A, B, ...) and its methods.
 *
 *   S = simplex(C, A, B)       C is the initial point (the book's "simplex CAB")
 *   S(p, q)                    (A - C)p + (B - C)q + C, the natural parameters
 *   S:bary(p, q, r)            Ap + Bq + Cr (weighted if p + q + r is not 1)
 *   S:params(M)                p, q, residual (least squares in any ambient dimension)
 *   S:measure()                length, area, volume ... (signed when the simplex is full-dimensional)
 *   S:ratio(P1, P2, P3)        S-/V-theorem: signed measure ratio of P1P2P3 to S, and a residual
 *   S[i], #S                   vertex i (1 = the initial point), number of vertices */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "pcl_point.h"
#include "simplex.h"

#define SMT lua_upvalueindex(1)

/* A genuine simplex's block is exactly pc_simplex_size(n, k) (pcl.h: forged userdata). */
static pc_simplex *tosimplex(lua_State *L, int idx) {
    pc_simplex *s = pcl_testudata(L, idx, SMT);
    if (!s) return NULL;
    size_t len = lua_rawlen(L, idx);
    int ok = len >= sizeof(pc_simplex) && s->n >= 1 && s->n <= PC_MAXDIM && s->k >= 1 &&
             s->k <= s->n && len == pc_simplex_size(s->n, s->k);
    return pcl_genuine(L, idx, s, ok, "simplex");
}

static pc_simplex *checkself(lua_State *L) {
    pc_simplex *s = tosimplex(L, 1);
    if (!s) {
        const char *f = pcl_fname(L);
        pcl_error(L, "%s: must be called on a simplex, as S:%s(...)", f, f);
    }
    return s;
}

static const char *shape(int k) {
    switch (k) {
    case 1: return "segment";
    case 2: return "triangle";
    case 3: return "tetrahedron";
    default: return "simplex";
    }
}

static int l_simplex(lua_State *L) {
    int m = lua_gettop(L);
    double v[(PC_MAXDIM + 1) * PC_MAXDIM];
    if (m < 1) pcl_argerror(L, 1, "C", "a point");
    int n = pcl_checkloc(L, 1, "C", 0, 0, v);
    if (m < 2) pcl_argerror(L, 2, "A", "a point");
    int k = m - 1;
    if (k > n)
        return pcl_error(L, "%s: %d points in %d-D are always dependent: a simplex has at most "
                          "dimension + 1 = %d vertices", pcl_fname(L), m, n, n + 1);
    for (int i = 1; i <= k; i++) pcl_checkloc(L, i + 1, NULL, n, 1, v + i * n);
    pc_simplex *s = lua_newuserdatauv(L, pc_simplex_size(n, k), 0);
    int st = pc_simplex_init(s, n, k, v);
    if (st == PC_ECOINCIDENT) {
        for (int i = 1; i <= k; i++)
            if (pc_dist(n, v, v + i * n) == 0)
                return pcl_error(L, "%s: argument #%d coincides with argument #1 (the initial "
                                  "point): a degenerate simplex", pcl_fname(L), i + 1);
    }
    if (st == PC_ECOLLINEAR) {
        const char *how = k == 2 ? "collinear" : k == 3 ? "coplanar" : "dependent";
        return pcl_error(L, "%s: the %d points are %s: a flat (degenerate) %s", pcl_fname(L), m,
                          how, shape(k));
    }
    if (st != PC_OK) return pcl_error(L, "%s: %s", pcl_fname(L), pc_strerror(st));
    lua_pushvalue(L, SMT);
    lua_setmetatable(L, -2);
    return 1;
}

/* S(p, q, ...): the point by its natural parameters.  One more number may follow and is
 * ignored, so that S(S:params(M)) works (params returns the residual last); with
 * coefficients summing to 1 it is also the initial point's barycentric coefficient, which
 * the natural parameters already imply.  The simplex moves to the top of the stack so that
 * the parameters are arguments #1..#k, as the script writes them. */
static int l_call(lua_State *L) {
    pc_simplex *s = checkself(L);
    lua_rotate(L, 1, -1);
    int m = lua_gettop(L) - 1, k = s->k;
    if (m != k && m != k + 1)
        return pcl_error(L, "%s: a %d-simplex takes %d natural parameters, got %d (for "
                          "barycentric parameters use S:bary)", pcl_fname(L), k, k, m);
    double p[PC_MAXDIM + 1];
    for (int i = 0; i < m; i++) {
        p[i] = lua_tonumber(L, i + 1);
        if (lua_type(L, i + 1) != LUA_TNUMBER || !isfinite(p[i])) {
            char what[24];                        /* the label only on the error path */
            snprintf(what, sizeof what, "parameter %d", i + 1);
            pcl_checkfinite(L, i + 1, what);
        }
    }
    pcl_value *r = pcl_newvalue(L, s->n);
    pc_simplex_eval(s, p, r->h);
    r->h[s->n] = 1.0;
    return 1;
}

/* S:bary(p, q, ..., r): coefficients of vertices 2..k+1, then of the initial point. */
static int l_bary(lua_State *L) {
    pc_simplex *s = checkself(L);
    int k = s->k, m = lua_gettop(L) - 1;
    if (m != k + 1)
        return pcl_error(L, "%s: a %d-simplex takes %d barycentric parameters, got %d",
                          pcl_fname(L), k, k + 1, m);
    double c[PC_MAXDIM + 1];
    for (int i = 0; i <= k; i++) c[i] = pcl_checkfinite(L, i + 2, NULL);
    pcl_value *r = pcl_newvalue(L, s->n);
    pc_simplex_bary(s, c, r->h);
    return 1;
}

static int l_params(lua_State *L) {
    pc_simplex *s = checkself(L);
    double m[PC_MAXDIM], p[PC_MAXDIM], res;
    int n = pcl_checkloc(L, 2, "M", 0, 0, m);
    if (n != s->n)
        return pcl_error(L, "%s: argument #1 (M) is %d-D, but the simplex is in %d-D: dimensions "
                          "cannot be mixed", pcl_fname(L), n, s->n);
    pc_simplex_params(s, m, p, &res);
    luaL_checkstack(L, s->k + 1, NULL);
    for (int i = 0; i < s->k; i++) lua_pushnumber(L, p[i]);
    lua_pushnumber(L, res);
    return s->k + 1;
}

static int l_measure(lua_State *L) {
    pc_simplex *s = checkself(L);
    lua_pushnumber(L, pc_simplex_measure(s));
    return 1;
}

static int l_ratio(lua_State *L) {
    pc_simplex *s = checkself(L);
    int k = s->k, n = s->n, m = lua_gettop(L) - 1;
    if (m != k + 1)
        return pcl_error(L, "%s: a %d-simplex compares with %d points, got %d", pcl_fname(L), k,
                          k + 1, m);
    double pts[(PC_MAXDIM + 1) * PC_MAXDIM], res;
    for (int i = 0; i <= k; i++) {
        int d = pcl_checkloc(L, i + 2, NULL, 0, 0, pts + i * n);
        if (d != n)
            return pcl_error(L, "%s: argument #%d is %d-D, but the simplex is in %d-D: dimensions "
                              "cannot be mixed", pcl_fname(L), i + 1, d, n);
    }
    lua_pushnumber(L, pc_simplex_ratio(s, pts, &res));
    lua_pushnumber(L, res);
    return 2;
}

static int l_index(lua_State *L) {
    pc_simplex *s = tosimplex(L, 1);
    if (!s) return pcl_error(L, "index: not a simplex");
    if (lua_type(L, 2) == LUA_TNUMBER) {
        int isint;
        lua_Integer i = lua_tointegerx(L, 2, &isint);
        if (isint && i >= 1 && i <= s->k + 1) {
            pcl_value *r = pcl_newvalue(L, s->n);
            memcpy(r->h, PC_SIMPLEX_V(s) + (i - 1) * s->n, sizeof(double) * (size_t)s->n);
            r->h[s->n] = 1.0;
            return 1;
        }
        lua_pushnil(L);
        return 1;
    }
    lua_pushvalue(L, 2);
    lua_rawget(L, lua_upvalueindex(2));
    return 1;
}

static int l_len(lua_State *L) {
    pc_simplex *s = tosimplex(L, 1);
    if (!s) return pcl_error(L, "#: not a simplex");
    lua_pushinteger(L, s->k + 1);
    return 1;
}

static int l_tostring(lua_State *L) {
    pc_simplex *s = tosimplex(L, 1);
    if (!s) return pcl_error(L, "tostring: not a simplex");
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    luaL_addstring(&b, "simplex(");
    for (int i = 0; i <= s->k; i++) {
        if (i) luaL_addstring(&b, ", ");
        lua_pushinteger(L, i + 1);
        lua_gettable(L, 1);                               /* the vertex as a point */
        luaL_tolstring(L, -1, NULL);
        lua_remove(L, -2);
        luaL_addvalue(&b);
    }
    luaL_addchar(&b, ')');
    luaL_pushresult(&b);
    return 1;
}

static const luaL_Reg simplex_methods[] = {
    {"bary", l_bary}, {"params", l_params}, {"measure", l_measure}, {"ratio", l_ratio},
    {NULL, NULL}
};

void pcl_open_simplex(lua_State *L) {
    int module = lua_gettop(L);
    lua_newtable(L);                                     /* the metatable */
    int mt = lua_gettop(L);
    lua_pushliteral(L, "simplex");
    lua_setfield(L, mt, "__name");
    lua_pushliteral(L, "simplex");
    lua_setfield(L, mt, "__metatable");
    static const luaL_Reg meta[] = {
        {"__call", l_call}, {"__len", l_len}, {"__tostring", l_tostring}, {NULL, NULL}
    };
    lua_pushvalue(L, mt);
    luaL_setfuncs(L, meta, 1);
    lua_newtable(L);                                     /* methods */
    int methods = lua_gettop(L);
    lua_pushvalue(L, mt);
    luaL_setfuncs(L, simplex_methods, 1);
    lua_pushvalue(L, mt);
    lua_pushvalue(L, methods);
    lua_pushcclosure(L, l_index, 2);
    lua_setfield(L, mt, "__index");
    lua_pushvalue(L, mt);
    lua_pushcclosure(L, l_simplex, 1);
    lua_setfield(L, module, "simplex");
    lua_settop(L, module);
}
