/* Binding of affine maps (stdlib/geom/affine.h).
 *
 *   f = affine({A, B, C}, {A2, B2, C2})   the map sending A to A2, B to B2, C to C2 (2-D by 3 pairs,
 *                                          3-D by 4; the images may have another dimension)
 *   f = affine.frame(O, X, Y [, Z])        (x, y, z) -> O + x(X - O) + y(Y - O) + z(Z - O); axes
 *                                          may also be given as vectors
 *   affine.identity(n)
 *   f(p), f(x, y, ...)                     apply (vectors ignore the translation)
 *   f * g, f:compose(g)                    g first, then f
 *   f:inverse()                            singular or non-square maps are an error */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "pcl_point.h"
#include "affine.h"

#define AMT lua_upvalueindex(1)

static pc_affine *tomap(lua_State *L, int idx) { return pcl_testudata(L, idx, AMT); }

static pc_affine *newmap(lua_State *L) {
    pc_affine *f = lua_newuserdatauv(L, sizeof(pc_affine), 0);
    lua_pushvalue(L, AMT);
    lua_setmetatable(L, -2);
    return f;
}

/* Points of a table (or a simplex) at arg into out; returns their count, *dim their dimension. */
static int read_points(lua_State *L, int arg, const char *what, double *out, int *dim) {
    int t = lua_type(L, arg);                        /* a table, or a simplex */
    if (t != LUA_TTABLE && t != LUA_TUSERDATA) return pcl_argerror(L, arg, what, "a table of points");
    int m = (int)luaL_len(L, arg);
    if (m > PC_MAXDIM + 1)
        return pcl_error(L, "%s: argument #%d (%s) holds %d points; the largest dimension is %d",
                          pcl_fname(L), arg, what, m, PC_MAXDIM);
    int n = 0;
    for (int i = 1; i <= m; i++) {
        lua_geti(L, arg, i);
        pcl_value *p = pcl_tovalue(L, -1);
        if (!p)
            return pcl_error(L, "%s: argument #%d (%s) item [%d] must be a point, got %s",
                              pcl_fname(L), arg, what, i, luaL_typename(L, -1));
        if (i == 1) n = p->n;
        if (p->n != n)
            return pcl_error(L, "%s: argument #%d (%s) mixes dimensions: item [%d] is %d-D, item "
                              "[1] is %d-D", pcl_fname(L), arg, what, i, p->n, n);
        if (pc_loc(n, p->h, out + (i - 1) * n) != PC_OK)
            return pcl_error(L, "%s: argument #%d (%s) item [%d] must be a point (weight 1), got "
                              "one of weight %f", pcl_fname(L), arg, what, i, p->h[n]);
        lua_pop(L, 1);
    }
    *dim = n;
    return m;
}

/* affine(src, dst), the __call of the affine table: the table itself is dropped, so that
 * src and dst are arguments #1 and #2 and a missing dst reads as nil. */
static int l_affine(lua_State *L) {
    lua_remove(L, 1);
    double src[(PC_MAXDIM + 1) * PC_MAXDIM], dst[(PC_MAXDIM + 1) * PC_MAXDIM];
    int nin, nout;
    int m = read_points(L, 1, "source points", src, &nin);
    int m2 = read_points(L, 2, "image points", dst, &nout);
    if (m < 2)
        return pcl_error(L, "affine: argument #1 (source points) holds %d points; a map of n-D "
                          "needs n + 1 (3 in the plane, 4 in space)", m);
    if (m != nin + 1)
        return pcl_error(L, "affine: argument #1 (source points) holds %d %d-D points; a map of "
                          "%d-D needs %d (dimension + 1)", m, nin, nin, nin + 1);
    if (m2 != m)
        return pcl_error(L, "affine: argument #2 (image points) holds %d points, argument #1 %d: "
                          "they must pair up", m2, m);
    pc_affine *f = newmap(L);
    int st = pc_affine_from_points(f, nin, nout, src, dst);
    if (st == PC_ECOINCIDENT || st == PC_ECOLLINEAR) {
        const char *how = nin == 1 ? "coincide" : nin == 2 ? "are collinear" :
                          nin == 3 ? "are coplanar" : "are dependent";
        return pcl_error(L, "affine: the source points %s, so they do not fix an affine map",
                          how);
    }
    if (st != PC_OK) return pcl_error(L, "affine: %s", pc_strerror(st));
    return 1;
}

static int l_frame(lua_State *L) {
    int m = lua_gettop(L);
    double o[PC_MAXDIM], axes[PC_MAXDIM * PC_MAXDIM];
    int n = pcl_checkloc(L, 1, "O", 0, 0, o);
    if (m < 2) pcl_argerror(L, 2, "X", "a point or vector");
    if (m - 1 > PC_MAXDIM)
        return pcl_error(L, "%s: %d axes; the largest dimension is %d", pcl_fname(L), m - 1,
                          PC_MAXDIM);
    static const char *names[] = {"X", "Y", "Z"};
    for (int j = 2; j <= m; j++) {
        const char *what = j - 2 < 3 ? names[j - 2] : NULL;
        pcl_value *p = pcl_checkvalue(L, j, what);
        if (p->n != n) pcl_dimerror(L, j, what, p->n, n, 1);
        double *a = axes + (j - 2) * n;
        if (pc_kind_of(p->h[n]) == PC_KIND_VECTOR) {
            memcpy(a, p->h, sizeof(double) * (size_t)n);          /* an axis vector */
        } else {
            pcl_checkloc(L, j, what, n, 1, a);                     /* a unit point: X - O */
            for (int i = 0; i < n; i++) a[i] -= o[i];
        }
    }
    pc_affine *f = newmap(L);
    pc_affine_frame(f, n, m - 1, o, axes);
    return 1;
}

static int l_identity(lua_State *L) {
    int isint;
    lua_Integer n = lua_tointegerx(L, 1, &isint);
    if (!isint || n < 1 || n > PC_MAXDIM) {
        char expected[48];
        snprintf(expected, sizeof expected, "a dimension 1..%d", PC_MAXDIM);
        return pcl_argerror(L, 1, "n", expected);
    }
    pc_affine_identity(newmap(L), (int)n);
    return 1;
}

static pc_affine *checkself(lua_State *L) {
    pc_affine *f = tomap(L, 1);
    if (!f) {
        const char *name = pcl_fname(L);
        pcl_error(L, "%s: must be called on an affine map, as f:%s(...)", name, name);
    }
    return f;
}

/* f(p) or f(x, y, ...); the map moves to the top so the arguments count from #1. */
static int l_apply(lua_State *L) {
    pc_affine *f = checkself(L);
    lua_rotate(L, 1, -1);
    int m = lua_gettop(L) - 1, nin = f->nin;
    pcl_value *p = m >= 1 ? pcl_tovalue(L, 1) : NULL;
    if (p) {
        if (m != 1)
            return pcl_error(L, "%s: takes one point or vector, got %d arguments", pcl_fname(L), m);
        if (p->n != nin)
            return pcl_error(L, "%s: argument #1 is %d-D, but the map takes %d-D: dimensions "
                              "cannot be mixed", pcl_fname(L), p->n, nin);
        pcl_value *r = pcl_newvalue(L, f->nout);
        pc_affine_apply(f, p->h, r->h);
        return 1;
    }
    if (m != nin || lua_type(L, 1) != LUA_TNUMBER)
        return pcl_error(L, "%s: takes a %d-D point or vector, or %d coordinates; got %s", pcl_fname(L),
                          nin, nin, m ? luaL_typename(L, 1) : "nothing");
    double in[PC_MAXDIM + 1];
    for (int i = 0; i < nin; i++) in[i] = pcl_checkfinite(L, i + 1, NULL);
    in[nin] = 1.0;
    pcl_value *r = pcl_newvalue(L, f->nout);
    pc_affine_apply(f, in, r->h);
    return 1;
}

static int compose(lua_State *L, pc_affine *f, pc_affine *g) {
    pc_affine h;
    if (pc_affine_compose(f, g, &h) != PC_OK)
        return pcl_error(L, "cannot compose: the first map applied gives %d-D, the second takes "
                          "%d-D", g->nout, f->nin);
    *newmap(L) = h;
    return 1;
}

static int l_mul(lua_State *L) {
    pc_affine *f = tomap(L, 1), *g = tomap(L, 2);
    if (!f || !g)
        return pcl_error(L, "cannot multiply an affine map by a %s: f * g composes two maps, and "
                          "f(p) applies one",
                          luaL_typename(L, f ? 2 : 1));
    return compose(L, f, g);
}

static int l_compose(lua_State *L) {
    pc_affine *f = checkself(L);
    pc_affine *g = tomap(L, 2);
    if (!g) return pcl_argerror(L, 2, "g", "an affine map");
    return compose(L, f, g);
}

static int l_inverse(lua_State *L) {
    pc_affine *f = checkself(L);
    pc_affine inv;
    int st = pc_affine_inverse(f, &inv);
    if (st == PC_EDIM)
        return pcl_error(L, "%s: a map from %d-D to %d-D (a projection or an embedding) has no "
                          "inverse", pcl_fname(L), f->nin, f->nout);
    if (st != PC_OK)
        return pcl_error(L, "%s: the map is singular (it flattens space), so it has no inverse",
                          pcl_fname(L));
    *newmap(L) = inv;
    return 1;
}

static void fmt_num(luaL_Buffer *b, double x) {
    char s[32];
    if (x == 0) x = 0;
    snprintf(s, sizeof s, "%.14g", x);
    luaL_addstring(b, s);
}

static int l_tostring(lua_State *L) {
    pc_affine *f = tomap(L, 1);
    if (!f) return pcl_error(L, "tostring: not an affine map");
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    lua_pushfstring(L, "affine map %d-D -> %d-D [", f->nin, f->nout);
    luaL_addvalue(&b);
    for (int i = 0; i < f->nout; i++) {
        if (i) luaL_addstring(&b, "; ");
        for (int j = 0; j <= f->nin; j++) {
            if (j) luaL_addstring(&b, j == f->nin ? " | " : " ");
            fmt_num(&b, PC_AFFINE_AT(f, i, j));
        }
    }
    luaL_addchar(&b, ']');
    luaL_pushresult(&b);
    return 1;
}

void pcl_open_affine(lua_State *L) {
    int module = lua_gettop(L);
    lua_newtable(L);                                     /* metatable of maps */
    int mt = lua_gettop(L);
    lua_pushliteral(L, "affine map");
    lua_setfield(L, mt, "__name");
    lua_pushliteral(L, "affine map");
    lua_setfield(L, mt, "__metatable");
    static const luaL_Reg meta[] = {
        {"__call", l_apply}, {"__mul", l_mul}, {"__tostring", l_tostring}, {NULL, NULL}
    };
    lua_pushvalue(L, mt);
    luaL_setfuncs(L, meta, 1);
    lua_newtable(L);                                     /* f:compose, f:inverse */
    static const luaL_Reg methods[] = {{"compose", l_compose}, {"inverse", l_inverse}, {NULL, NULL}};
    lua_pushvalue(L, mt);
    luaL_setfuncs(L, methods, 1);
    lua_setfield(L, mt, "__index");

    lua_newtable(L);                                     /* the affine table */
    static const luaL_Reg ctors[] = {{"frame", l_frame}, {"identity", l_identity}, {NULL, NULL}};
    lua_pushvalue(L, mt);
    luaL_setfuncs(L, ctors, 1);
    lua_newtable(L);                                     /* its metatable: affine(src, dst) */
    lua_pushvalue(L, mt);
    lua_pushcclosure(L, l_affine, 1);
    lua_setfield(L, -2, "__call");
    lua_setmetatable(L, -2);
    lua_setfield(L, module, "affine");
    lua_settop(L, module);
}
