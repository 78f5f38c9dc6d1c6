/* The symbolic method of §2.2 in Lua (books/konopatsky/konop_triples.h):
 *   conic.scheme{triples = {{"A1", "A", "B"}, ...}, points = {A1 = P(...), ...},
 *                current = {"C", "A1", "A5"}, result = "M" [, range = {t0, t1}]}
 *     -> curve, steps ({"A = A3A2 x A4A5", ...}) */
#include <string.h>
#include "pcl.h"
#include "pcl_curve.h"
#include "pcl_point.h"
#include "konop_triples.h"

typedef struct {
    int n;
    const char *name[PC_TRIPLES_MAXPTS];
} names;

/* the index of name s (added when new); -1 when there are too many */
static int index_of(names *nm, const char *s) {
    for (int i = 0; i < nm->n; i++)
        if (!strcmp(nm->name[i], s)) return i;
    if (nm->n == PC_TRIPLES_MAXPTS) return -1;
    nm->name[nm->n] = s;
    return nm->n++;
}

static int l_scheme(lua_State *L) {
    const char *fn = "conic.scheme";
    if (!lua_istable(L, 1)) return pcl_argerror_full(L, fn, 1, 1, "scheme", "a table {triples =, points =, current =, result =}");
    lua_settop(L, 1);
    static const char *keys[5] = {"triples", "points", "current", "result", "range"};
    lua_pushnil(L);
    while (lua_next(L, 1)) {
        const char *k = lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : NULL;
        int ok = 0;
        for (int i = 0; k && i < 5; i++) ok |= !strcmp(k, keys[i]);
        if (!ok) return pcl_error(L, "%s: unknown field %s (the fields are triples, points, current, result, range)", fn,
                                  k ? k : "with a number index");
        lua_pop(L, 1);
    }
    names nm = {0};
    int tri[PC_TRIPLES_MAXTRI][3], ntri;
    unsigned char known[PC_TRIPLES_MAXPTS] = {0};
    double pts[PC_TRIPLES_MAXPTS * PC_MAXDIM];
    int dim = 0;
    /* the known points first: their names are the keys of points */
    lua_getfield(L, 1, "points");                                   /* 2 */
    if (!lua_istable(L, 2)) return pcl_error(L, "%s: field points must be a table {A1 = P(...), ...}", fn);
    lua_pushnil(L);
    while (lua_next(L, 2)) {
        if (lua_type(L, -2) != LUA_TSTRING) return pcl_error(L, "%s: points must be named (A1 = P(...))", fn);
        const char *s = lua_tostring(L, -2);
        pcl_value *v = pcl_tovalue(L, -1);
        if (!v || v->n < 2 || (dim && v->n != dim) || v->h[v->n] != 1)
            return pcl_error(L, "%s: points.%s must be a %s point", fn, s, dim ? (dim == 2 ? "2-D" : "3-D or more") : "2-D or more");
        dim = v->n;
        int i = index_of(&nm, s);
        if (i < 0) return pcl_error(L, "%s: at most %d points", fn, PC_TRIPLES_MAXPTS);
        known[i] = 1;
        memcpy(pts + i * dim, v->h, sizeof(double) * (size_t)dim);
        lua_pop(L, 1);
    }
    if (!dim) return pcl_error(L, "%s: field points is empty", fn);
    lua_getfield(L, 1, "triples");                                  /* 3 */
    if (!lua_istable(L, 3)) return pcl_error(L, "%s: field triples must be a list of {\"X\", \"Y\", \"Z\"}", fn);
    ntri = (int)luaL_len(L, 3);
    if (ntri < 1 || ntri > PC_TRIPLES_MAXTRI) return pcl_error(L, "%s: 1 to %d triples, got %d", fn, PC_TRIPLES_MAXTRI, ntri);
    for (int j = 0; j < ntri; j++) {
        lua_geti(L, 3, j + 1);
        if (!lua_istable(L, -1) || luaL_len(L, -1) != 3)
            return pcl_error(L, "%s: triples[%d] must be three point names", fn, j + 1);
        for (int k = 0; k < 3; k++) {
            lua_geti(L, -1, k + 1);
            if (lua_type(L, -1) != LUA_TSTRING) return pcl_error(L, "%s: triples[%d][%d] must be a point name", fn, j + 1, k + 1);
            tri[j][k] = index_of(&nm, lua_tostring(L, -1));
            if (tri[j][k] < 0) return pcl_error(L, "%s: at most %d points", fn, PC_TRIPLES_MAXPTS);
            lua_pop(L, 1);       /* the name stays alive in the table */
        }
        lua_pop(L, 1);
    }
    lua_getfield(L, 1, "current");                                  /* 4 */
    int cur[3];
    if (!lua_istable(L, 4) || luaL_len(L, 4) != 3)
        return pcl_error(L, "%s: field current must be {\"C\", \"P\", \"Q\"}: C runs as P t' + Q t", fn);
    for (int k = 0; k < 3; k++) {
        lua_geti(L, 4, k + 1);
        if (lua_type(L, -1) != LUA_TSTRING) return pcl_error(L, "%s: current[%d] must be a point name", fn, k + 1);
        cur[k] = index_of(&nm, lua_tostring(L, -1));
        lua_pop(L, 1);
    }
    if (!known[cur[1]] || !known[cur[2]])
        return pcl_error(L, "%s: the current point's line current[2], current[3] must join two given points", fn);
    lua_getfield(L, 1, "result");                                   /* 5 */
    if (lua_type(L, 5) != LUA_TSTRING) return pcl_error(L, "%s: field result must be a point name", fn);
    int res = index_of(&nm, lua_tostring(L, 5));
    double t0 = 0, t1 = 1;
    lua_getfield(L, 1, "range");                                    /* 6 */
    if (!lua_isnil(L, 6)) {
        lua_geti(L, 6, 1);
        lua_geti(L, 6, 2);
        if (!lua_isnumber(L, -2) || !lua_isnumber(L, -1) || !(lua_tonumber(L, -1) > lua_tonumber(L, -2)))
            return pcl_error(L, "%s: field range must be {t0, t1} with t0 < t1", fn);
        t0 = lua_tonumber(L, -2), t1 = lua_tonumber(L, -1);
        lua_pop(L, 2);
    }
    pc_triples_plan plan;
    int st = pc_triples_plan_make(nm.n, ntri, (const int (*)[3])tri, known, cur[0], cur[1], cur[2], res, &plan);
    if (st == PC_EDOMAIN)
        return pcl_error(L, "%s: the table does not determine %s (each new point needs two lines of known points)", fn,
                         nm.name[res]);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    pc_curve *c = pc_triples_curve(&plan, dim, pts, t0, t1, &st);
    if (!c) return pcl_statuserror(L, fn, st, NULL);
    pcl_pushcurve(L, c, fn);
    lua_createtable(L, plan.nsteps, 0);
    for (int s = 0; s < plan.nsteps; s++) {
        const pc_triple_step *p = &plan.step[s];
        lua_pushfstring(L, "%s = %s%s x %s%s", nm.name[p->x], nm.name[p->a], nm.name[p->b], nm.name[p->c], nm.name[p->d]);
        lua_rawseti(L, -2, s + 1);
    }
    return 2;
}

/* After pcl_open_konopatsky, with the module table on top. */
void pcl_open_konopatsky_triples(lua_State *L) {
    lua_getfield(L, -1, "conic");
    lua_pushcfunction(L, l_scheme);
    lua_setfield(L, -2, "scheme");
    lua_pop(L, 1);
}
