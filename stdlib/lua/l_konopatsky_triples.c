/* The symbolic method of §2.2 in Lua (books/konopatsky/konop_triples.h): conic.scheme{...}. */
#include "pcl_args.h"
#include "pcl_core.h"
#include "pcl_point.h"
#include "konop_triples.h"
#include "konop_why.h"

#define CHECK(st) pcl_check(L, (st), pc_konop_why)

/* the three point names of the list at the stack top (popped) into idx, added to nm; 0 if it is
 * no such list */
static int names3(lua_State *L, pc_triples_names *nm, int *idx) {
    int t = lua_gettop(L), ok = lua_istable(L, t) && lua_rawlen(L, t) == 3;
    for (int k = 0; ok && k < 3; k++) {
        ok = lua_geti(L, t, k + 1) == LUA_TSTRING;
        idx[k] = ok ? pc_triples_name(nm, lua_tostring(L, -1)) : 0;   /* the name stays alive in the table */
        if (idx[k] < 0) pcl_fail(L, "at most %d points", PC_TRIPLES_MAXPTS);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return ok;
}

PCL_BODY(l_scheme, a) {   /* the table, then triples, points, current, result, range */
    pc_triples_names nm = {0};
    int tri[PC_TRIPLES_MAXTRI][3], cur[3], dim = 0;
    unsigned char known[PC_TRIPLES_MAXPTS] = {0};
    double pts[PC_TRIPLES_MAXPTS * PC_MAXDIM];
    /* the known points first: their names are the keys of points */
    lua_getfield(L, 1, "points");
    int ip = lua_gettop(L);
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
        int i = pc_triples_name(&nm, s);
        if (i < 0) return pcl_fail(L, "at most %d points", PC_TRIPLES_MAXPTS);
        known[i] = 1;
        memcpy(pts + i * dim, h, sizeof(double) * (size_t)dim);
        lua_pop(L, 1);
    }
    if (!dim) return pcl_fail(L, "field points is empty");
    lua_getfield(L, 1, "triples");
    int it = lua_gettop(L), ntri = (int)lua_rawlen(L, it);
    if (ntri < 1 || ntri > PC_TRIPLES_MAXTRI) return pcl_fail(L, "1 to %d triples, got %d", PC_TRIPLES_MAXTRI, ntri);
    for (int j = 0; j < ntri; j++) {
        lua_geti(L, it, j + 1);
        if (!names3(L, &nm, tri[j])) return pcl_fail(L, "triples[%d] must be three point names", j + 1);
    }
    lua_getfield(L, 1, "current");
    if (!names3(L, &nm, cur))
        return pcl_fail(L, "field current must be three point names {\"C\", \"P\", \"Q\"}: C runs as P t' + Q t");
    int res = pc_triples_name(&nm, a[4].s);
    pc_triples_plan plan;
    int st = pc_triples_plan_make(nm.n, ntri, (const int (*)[3])tri, known, cur[0], cur[1], cur[2], res, &plan);
    if (st == PC_EDOMAIN)
        return pcl_fail(L, "the table does not determine %s (each new point needs two lines of known points)", a[4].s);
    CHECK(st);
    double t0 = a[5].present ? a[5].list[0] : 0, t1 = a[5].present ? a[5].list[1] : 1;
    pcl_made(L, pc_triples_curve(&plan, dim, pts, t0, t1, &st), &st, pc_konop_why);
    lua_createtable(L, plan.nsteps, 0);
    for (int s = 0; s < plan.nsteps; s++) {
        char text[4 * 64];
        pc_triples_step_text(&plan, s, &nm, text, sizeof text);
        lua_pushstring(L, text);
        lua_rawseti(L, -2, s + 1);
    }
    return 2;
}

static const pcl_arg scheme_keys[] = {
    {.name = "triples", .kind = PCL_TABLE, .flags = PCL_REQ, .expect = "a list of {\"X\", \"Y\", \"Z\"}"},
    {.name = "points", .kind = PCL_TABLE, .flags = PCL_REQ, .expect = "a table {A1 = P(...), ...}"},
    {.name = "current", .kind = PCL_ANY, .flags = PCL_REQ, .expect = "{\"C\", \"P\", \"Q\"}"},
    {.name = "result", .kind = PCL_STRING, .flags = PCL_REQ},
    {.name = "range", .kind = PCL_NUMBERS, .lo = 2, .hi = 2}, PCL_END};
static const pcl_arg scheme_args[] = {{.name = "scheme", .kind = PCL_OPTIONS, .flags = PCL_CALLTABLE, .keys = scheme_keys}, PCL_END};
static const pcl_fn fns[] = {
    PCL_FN("conic.scheme", l_scheme, scheme_args, "curve, steps", "§2.2 The symbolic method: a table of collinear triples (each a line of the ruler construction) becomes its construction: the given points, the current point C = P t' + Q t (current = {\"C\", \"P\", \"Q\"}), and every other point the meet of two lines of the table whose other points are known, in the order found (steps, e.g. \"A = A3A2 x A4A5\"); the curve of the result over range (default {0, 1}). Baluba's systems (a) and (b) of Fig. 2.28 are two such tables."),
    PCL_END};

/* After pcl_open_konopatsky, with the module table on top. */
void pcl_open_konopatsky_triples(lua_State *L) {
    pcl_register_into(L, lua_gettop(L), "conic", fns);
}
