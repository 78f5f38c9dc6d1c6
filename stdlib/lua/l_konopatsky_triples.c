/* The symbolic method of §2.2 in Lua (books/konopatsky/konop_triples.h):
 *   conic.scheme{triples = {{"A1", "A", "B"}, ...}, points = {A1 = P(...), ...}, (declared)
 *                current = {"C", "A1", "A5"}, result = "M" [, range = {t0, t1}]}
 *     -> curve, steps ({"A = A3A2 x A4A5", ...}) */
#include <string.h>
#include "pcl_args.h"
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
    pcl_val a[6] = {0};   /* the table, then triples, points, current, result, range */
    PCL_READ(L, a);
    names nm = {0};
    int tri[PC_TRIPLES_MAXTRI][3], ntri;
    unsigned char known[PC_TRIPLES_MAXPTS] = {0};
    double pts[PC_TRIPLES_MAXPTS * PC_MAXDIM];
    int dim = 0;
    /* the known points first: their names are the keys of points */
    lua_getfield(L, 1, "points");
    int ip = lua_gettop(L);
    if (!lua_istable(L, ip)) return pcl_fail(L, "field points must be a table {A1 = P(...), ...}");
    lua_pushnil(L);
    while (lua_next(L, ip)) {
        if (lua_type(L, -2) != LUA_TSTRING) return pcl_fail(L, "points must be named (A1 = P(...))");
        const char *s = lua_tostring(L, -2);
        pcl_value *v = pcl_tovalue(L, -1);
        double h[PC_MAXDIM + 1];
        if (v) memcpy(h, v->h, sizeof(double) * (size_t)(v->n + 1));
        /* the one weight rule: within 1e-9 of 1 is a point (pcl_snap_weight) */
        if (!v || v->n < 2 || (dim && v->n != dim) || pcl_snap_weight(v->n, h) != PC_KIND_POINT)
            return pcl_fail(L, "points.%s must be a %s point", s, dim ? (dim == 2 ? "2-D" : "3-D or more") : "2-D or more");
        dim = v->n;
        int i = index_of(&nm, s);
        if (i < 0) return pcl_fail(L, "at most %d points", PC_TRIPLES_MAXPTS);
        known[i] = 1;
        memcpy(pts + i * dim, h, sizeof(double) * (size_t)dim);
        lua_pop(L, 1);
    }
    if (!dim) return pcl_fail(L, "field points is empty");
    lua_getfield(L, 1, "triples");
    int it = lua_gettop(L);
    if (!lua_istable(L, it)) return pcl_fail(L, "field triples must be a list of {\"X\", \"Y\", \"Z\"}");
    ntri = (int)lua_rawlen(L, it);
    if (ntri < 1 || ntri > PC_TRIPLES_MAXTRI) return pcl_fail(L, "1 to %d triples, got %d", PC_TRIPLES_MAXTRI, ntri);
    for (int j = 0; j < ntri; j++) {
        lua_geti(L, it, j + 1);
        if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 3)
            return pcl_fail(L, "triples[%d] must be three point names", j + 1);
        for (int k = 0; k < 3; k++) {
            lua_geti(L, -1, k + 1);
            if (lua_type(L, -1) != LUA_TSTRING) return pcl_fail(L, "triples[%d][%d] must be a point name", j + 1, k + 1);
            tri[j][k] = index_of(&nm, lua_tostring(L, -1));
            if (tri[j][k] < 0) return pcl_fail(L, "at most %d points", PC_TRIPLES_MAXPTS);
            lua_pop(L, 1);       /* the name stays alive in the table */
        }
        lua_pop(L, 1);
    }
    lua_getfield(L, 1, "current");
    int ic = lua_gettop(L), cur[3];
    if (!lua_istable(L, ic) || lua_rawlen(L, ic) != 3)
        return pcl_fail(L, "field current must be {\"C\", \"P\", \"Q\"}: C runs as P t' + Q t");
    for (int k = 0; k < 3; k++) {
        lua_geti(L, ic, k + 1);
        if (lua_type(L, -1) != LUA_TSTRING) return pcl_fail(L, "current[%d] must be a point name", k + 1);
        cur[k] = index_of(&nm, lua_tostring(L, -1));
        lua_pop(L, 1);
    }
    if (!known[cur[1]] || !known[cur[2]])
        return pcl_fail(L, "the current point's line current[2], current[3] must join two given points");
    lua_getfield(L, 1, "result");
    int res = index_of(&nm, lua_tostring(L, -1));   /* a string: declared */
    double t0 = 0, t1 = 1;
    if (a[5].present) {
        t0 = a[5].list[0], t1 = a[5].list[1];
        if (!(t1 > t0)) return pcl_keyfail(L, "range", "must be {t0, t1} with t0 < t1");
    }
    pc_triples_plan plan;
    int st = pc_triples_plan_make(nm.n, ntri, (const int (*)[3])tri, known, cur[0], cur[1], cur[2], res, &plan);
    if (st == PC_EDOMAIN)
        return pcl_fail(L, "the table does not determine %s (each new point needs two lines of known points)",
                         nm.name[res]);
    if (st != PC_OK) return pcl_statuserror(L, pcl_name(L), st, NULL);
    pc_curve *c = pc_triples_curve(&plan, dim, pts, t0, t1, &st);
    if (!c) return pcl_statuserror(L, pcl_name(L), st, NULL);
    pcl_pushcurve(L, c, "conic.scheme");
    lua_createtable(L, plan.nsteps, 0);
    for (int s = 0; s < plan.nsteps; s++) {
        const pc_triple_step *p = &plan.step[s];
        lua_pushfstring(L, "%s = %s%s x %s%s", nm.name[p->x], nm.name[p->a], nm.name[p->b], nm.name[p->c], nm.name[p->d]);
        lua_rawseti(L, -2, s + 1);
    }
    return 2;
}

static const pcl_arg scheme_keys[] = {
    {.name = "triples", .kind = PCL_ANY, .flags = PCL_REQ, .expect = "a list of {\"X\", \"Y\", \"Z\"}"},
    {.name = "points", .kind = PCL_ANY, .flags = PCL_REQ, .expect = "a table {A1 = P(...), ...}"},
    {.name = "current", .kind = PCL_ANY, .flags = PCL_REQ, .expect = "{\"C\", \"P\", \"Q\"}"},
    {.name = "result", .kind = PCL_STRING, .flags = PCL_REQ},
    {.name = "range", .kind = PCL_NUMBERS, .lo = 2, .hi = 2}, PCL_END};
static const pcl_arg scheme_args[] = {{.name = "scheme", .kind = PCL_OPTIONS, .flags = PCL_CALLTABLE, .keys = scheme_keys}, PCL_END};
static const pcl_fn fns[] = {
    PCL_FN("conic.scheme", l_scheme, scheme_args, "curve, steps",
           "§2.2 The symbolic method: a table of collinear triples (each a line of the ruler construction) becomes its construction: the given points, the current point C = P t' + Q t (current = {\"C\", \"P\", \"Q\"}), and every other point the meet of two lines of the table whose other points are known, in the order found (steps, e.g. \"A = A3A2 x A4A5\"); the curve of the result over range (default {0, 1}). Baluba's systems (a) and (b) of Fig. 2.28 are two such tables."),
    PCL_END};

/* After pcl_open_konopatsky, with the module table on top. */
void pcl_open_konopatsky_triples(lua_State *L) {
    lua_getfield(L, -1, "conic");
    pcl_register(L, lua_gettop(L), fns, 0);
    lua_pop(L, 1);
}
