/* Binding of the point calculus values (stdlib/geom/point.h): P V, the operators, and
 * lerp bar mid dist dot cross unit perp angle foot sr divide harmonic cross_ratio meet area
 * volume Sigma normalize weight coords near.
 *
 * A value is a full userdata of variable size (header + n+1 doubles).  Every function here is
 * a closure whose first upvalue is the point metatable, so recognising a point is a pointer
 * comparison, never a registry lookup by name; the hot paths (P, lerp, + - * /, .x) allocate
 * exactly one userdata and do nothing else. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "pcl_point.h"
#include "pcl_curve.h"
#include "pcl_expr.h"   /* equations take over when an operand is one (l_expr.c) */

static const char POINT_MT_KEY = 'p';       /* registry key (its address) of the metatable */
#define MT lua_upvalueindex(1)
#define METHODS lua_upvalueindex(2)         /* __index only: the method table */

/* ---- recognising and making values ------------------------------------------------------- */

/* A genuine value's block is exactly its header and n + 1 doubles, n = 1..PC_MAXDIM: a
 * userdata given the point metatable by the debug library has another size (pcl.h). */
static inline int genuine_value(lua_State *L, int idx, const pcl_value *p) {
    size_t len = lua_rawlen(L, idx);
    return len >= sizeof(pcl_value) && p->n >= 1 && p->n <= PC_MAXDIM &&
           len == sizeof(pcl_value) + (size_t)(p->n + 1) * sizeof(double);
}

static inline pcl_value *topt(lua_State *L, int idx) {
    pcl_value *p = pcl_testudata(L, idx, MT);
    if (p && !genuine_value(L, idx, p)) pcl_genuine(L, idx, p, 0, "point");
    return p;
}

static inline pcl_value *newpt(lua_State *L, int n) {
    pcl_value *p = lua_newuserdatauv(L, sizeof(pcl_value) + (size_t)(n + 1) * sizeof(double), 0);
    p->n = n;
    lua_pushvalue(L, MT);
    lua_setmetatable(L, -2);
    return p;
}

void pcl_push_point_mt(lua_State *L) { lua_rawgetp(L, LUA_REGISTRYINDEX, &POINT_MT_KEY); }

pcl_value *pcl_tovalue(lua_State *L, int idx) {
    idx = lua_absindex(L, idx);
    pcl_push_point_mt(L);
    pcl_value *p = pcl_testudata(L, idx, lua_gettop(L));
    lua_pop(L, 1);
    if (p && !genuine_value(L, idx, p)) pcl_genuine(L, idx, p, 0, "point");
    return p;
}

pcl_value *pcl_newvalue(lua_State *L, int n) {
    pcl_value *p = lua_newuserdatauv(L, sizeof(pcl_value) + (size_t)(n + 1) * sizeof(double), 0);
    p->n = n;
    pcl_push_point_mt(L);
    lua_setmetatable(L, -2);
    return p;
}

/* ---- text ---------------------------------------------------------------------------------- */

static void fmt_num(luaL_Buffer *b, double x) {
    char s[32];
    if (x == 0) x = 0;                                  /* no "-0" */
    snprintf(s, sizeof s, "%.14g", x);
    luaL_addstring(b, s);
}

/* P(1, 2), V(0, 1), or k*P(x, y) for a weight k other than 0 and 1: valid Lua that rebuilds
 * the value. */
static void add_value(luaL_Buffer *b, const pcl_value *p) {
    int n = p->n;
    double w = p->h[n];
    pc_kind kind = pc_kind_of(w);
    double div = 1;
    if (kind == PC_KIND_WEIGHTED) {
        fmt_num(b, w);
        luaL_addchar(b, '*');
        div = w;
    } else if (kind == PC_KIND_POINT) {
        div = w;
    }
    luaL_addstring(b, kind == PC_KIND_VECTOR ? "V(" : "P(");
    for (int i = 0; i < n; i++) {
        if (i) luaL_addstring(b, ", ");
        fmt_num(b, div == 1 ? p->h[i] : p->h[i] / div);
    }
    luaL_addchar(b, ')');
}

static const char *push_value_text(lua_State *L, const pcl_value *p) {
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    add_value(&b, p);
    luaL_pushresult(&b);
    return lua_tostring(L, -1);
}

static const char *push_num_text(lua_State *L, double x) {
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    fmt_num(&b, x);
    luaL_pushresult(&b);
    return lua_tostring(L, -1);
}

/* ---- errors -------------------------------------------------------------------------------- */

/* "argument #N", or "self" for the receiver of a method call */
static const char *argname(lua_State *L, int arg) {
    int shown = pcl_arg_shown(L, arg);
    return shown == 0 ? "self" : lua_pushfstring(L, "argument #%d", shown);
}

static const char MEMBERSHIP[] =
    "the coefficients of a point equation must sum to 1 for a point and to 0 for a vector "
    "(the membership condition)";

/* A value used as a location whose weight is not 1.  ctx names where it was used. */
static int location_error(lua_State *L, const char *ctx, const pcl_value *p) {
    const char *text = push_value_text(L, p);
    double w = p->h[p->n];
    if (pc_kind_of(w) == PC_KIND_VECTOR)
        return pcl_error(L, "%s is a vector %s (weight 0), not a point: %s; to place a vector, "
                          "add it to a point, e.g. P(0, 0) + v", ctx, text, MEMBERSHIP);
    const char *wt = push_num_text(L, w);
    return pcl_error(L, "%s has weight %s, so it is neither a point (weight 1) nor a vector "
                      "(weight 0): %s; write offsets with V(), e.g. V(x, y)*100 + P(320, 240), "
                      "or use normalize(p) for a projective point", ctx, wt, MEMBERSHIP);
}

static const char *argctx(lua_State *L, int arg, const char *what) {
    const char *an = argname(L, arg);
    if (what && what[0]) return lua_pushfstring(L, "%s: %s (%s)", pcl_fname(L), an, what);
    return lua_pushfstring(L, "%s: %s", pcl_fname(L), an);
}

int pcl_dimerror(lua_State *L, int arg, const char *what, int got_dim, int dim, int dim_arg) {
    const char *ctx = argctx(L, arg, what);
    if (dim_arg > 0)
        return pcl_error(L, "%s is %d-D, but %s is %d-D: dimensions cannot be mixed",
                          ctx, got_dim, argname(L, dim_arg), dim);
    return pcl_error(L, "%s must be %d-D, got %d-D", ctx, dim, got_dim);
}

void pcl_pushpoint(lua_State *L, int n, const double *x) {
    pcl_value *p = pcl_newvalue(L, n);
    memcpy(p->h, x, sizeof(double) * (size_t)n);
    p->h[n] = 1.0;
}

void pcl_pushvector(lua_State *L, int n, const double *x) {
    pcl_value *p = pcl_newvalue(L, n);
    memcpy(p->h, x, sizeof(double) * (size_t)n);
    p->h[n] = 0.0;
}

double pcl_checkfinite(lua_State *L, int arg, const char *what) {
    int isnum;
    double v = lua_tonumberx(L, arg, &isnum);
    if (!isnum || lua_type(L, arg) != LUA_TNUMBER) pcl_argerror(L, arg, what, "a number");
    if (!isfinite(v)) pcl_argerror(L, arg, what, "a finite number");
    return v;
}

pcl_value *pcl_checkvalue(lua_State *L, int arg, const char *what) {
    pcl_value *p = pcl_tovalue(L, arg);
    if (!p) pcl_argerror(L, arg, what, "a point or vector");
    return p;
}

static int loc_of(lua_State *L, pcl_value *p, int arg, const char *what, int dim, int dim_arg,
                  double *out) {
    if (dim > 0 && p->n != dim) pcl_dimerror(L, arg, what, p->n, dim, dim_arg);
    if (pc_loc(p->n, p->h, out) != PC_OK) location_error(L, argctx(L, arg, what), p);
    return p->n;
}

int pcl_checkloc(lua_State *L, int arg, const char *what, int dim, int dim_arg, double *out) {
    pcl_value *p = pcl_tovalue(L, arg);
    if (!p) pcl_argerror(L, arg, what, "a point");
    return loc_of(L, p, arg, what, dim, dim_arg, out);
}

static int vec_of(lua_State *L, pcl_value *p, int arg, const char *what, int dim, int dim_arg,
                  double *out) {
    if (dim > 0 && p->n != dim) pcl_dimerror(L, arg, what, p->n, dim, dim_arg);
    if (pc_kind_of(p->h[p->n]) != PC_KIND_VECTOR) {
        const char *ctx = argctx(L, arg, what);
        const char *text = push_value_text(L, p);
        const char *wt = push_num_text(L, p->h[p->n]);
        return pcl_error(L, "%s must be a vector (weight 0), got %s (weight %s); a difference "
                          "of points is a vector, e.g. B - A", ctx, text, wt);
    }
    memcpy(out, p->h, sizeof(double) * (size_t)p->n);
    return p->n;
}

int pcl_checkvec(lua_State *L, int arg, const char *what, int dim, int dim_arg, double *out) {
    pcl_value *p = pcl_tovalue(L, arg);
    if (!p) pcl_argerror(L, arg, what, "a vector");
    return vec_of(L, p, arg, what, dim, dim_arg, out);
}

/* Fast local variants using the upvalue metatable. */
static inline pcl_value *checkval(lua_State *L, int arg, const char *what) {
    pcl_value *p = topt(L, arg);
    if (!p) pcl_argerror(L, arg, what, "a point or vector");
    return p;
}

static int checkloc(lua_State *L, int arg, const char *what, int dim, int dim_arg, double *out) {
    pcl_value *p = topt(L, arg);
    if (!p) pcl_argerror(L, arg, what, "a point");
    return loc_of(L, p, arg, what, dim, dim_arg, out);
}

static int checkvec(lua_State *L, int arg, const char *what, int dim, int dim_arg, double *out) {
    pcl_value *p = topt(L, arg);
    if (!p) pcl_argerror(L, arg, what, "a vector");
    return vec_of(L, p, arg, what, dim, dim_arg, out);
}

static void push_loc(lua_State *L, int n, const double *x) {
    pcl_value *r = newpt(L, n);
    memcpy(r->h, x, sizeof(double) * (size_t)n);
    r->h[n] = 1.0;
}

static void push_vec(lua_State *L, int n, const double *x) {
    pcl_value *r = newpt(L, n);
    memcpy(r->h, x, sizeof(double) * (size_t)n);
    r->h[n] = 0.0;
}

/* ---- construction ------------------------------------------------------------------------- */

static const char *coord_name(int i, char *buf, size_t sz) {
    static const char *xyz[] = {"x", "y", "z"};
    if (i < 3) return xyz[i];
    snprintf(buf, sz, "coordinate %d", i + 1);
    return buf;
}

static int make(lua_State *L, double weight) {
    int n = lua_gettop(L);
    if (n == 1 && lua_type(L, 1) == LUA_TTABLE) {          /* P{1, 2} */
        n = (int)lua_rawlen(L, 1);
        if (n < 1) return pcl_error(L, "%s: the table has no coordinates", pcl_fname(L));
        if (n > PC_MAXDIM)
            return pcl_error(L, "%s: %d coordinates, but the largest dimension is %d",
                              pcl_fname(L), n, PC_MAXDIM);
        pcl_value *p = newpt(L, n);
        for (int i = 0; i < n; i++) {
            lua_rawgeti(L, 1, i + 1);
            int isnum;
            double v = lua_tonumberx(L, -1, &isnum);
            if (!isnum || !isfinite(v) || lua_type(L, -1) != LUA_TNUMBER) {
                char buf[24];
                return pcl_error(L, "%s: argument #1 (table) field [%d] (%s) must be a finite "
                                  "number, got %s", pcl_fname(L), i + 1,
                                  coord_name(i, buf, sizeof buf), luaL_typename(L, -1));
            }
            lua_pop(L, 1);
            p->h[i] = v;
        }
        p->h[n] = weight;
        return 1;
    }
    if (n < 1) return pcl_error(L, "%s: needs at least one coordinate", pcl_fname(L));
    if (n > PC_MAXDIM)
        return pcl_error(L, "%s: %d coordinates, but the largest dimension is %d", pcl_fname(L),
                          n, PC_MAXDIM);
    pcl_value *p = newpt(L, n);
    for (int i = 0; i < n; i++) {
        int isnum;
        double v = lua_tonumberx(L, i + 1, &isnum);
        if (!isnum || !isfinite(v) || lua_type(L, i + 1) != LUA_TNUMBER) {
            lua_settop(L, n);
            if (pcl_eq_hook(L, weight == 1.0 ? PCL_EQ_P : PCL_EQ_V)) return 1;
            char buf[24];
            const char *what = coord_name(i, buf, sizeof buf);
            if (!isnum || lua_type(L, i + 1) != LUA_TNUMBER) pcl_argerror(L, i + 1, what, "a number");
            pcl_argerror(L, i + 1, what, "a finite number");
        }
        p->h[i] = v;
    }
    p->h[n] = weight;
    return 1;
}

static int l_P(lua_State *L) { return make(L, 1.0); }
static int l_V(lua_State *L) { return make(L, 0.0); }

/* ---- operators ---------------------------------------------------------------------------- */

static const char *opnd_name(lua_State *L, int idx) {
    if (topt(L, idx)) return "a point";
    if (lua_type(L, idx) == LUA_TNUMBER) return "a number";
    if (luaL_getmetafield(L, idx, "__name") == LUA_TSTRING) {
        const char *s = lua_pushfstring(L, "a %s", lua_tostring(L, -1));
        return s;
    }
    return lua_pushfstring(L, "a %s", luaL_typename(L, idx));
}

/* A result that overflowed (1e308 + 1e308) or became NaN is an error, never a point drawn at
 * infinity: 1 when r is finite. */
static int finite_or_error(lua_State *L, const pcl_value *r, const char *what) {
    for (int i = 0; i <= r->n; i++)
        if (!isfinite(r->h[i]))
            return pcl_error(L, "%s: the result is out of range (not finite: a coordinate "
                             "overflowed)", what);
    return 1;
}

static int mixed_error(lua_State *L, const char *op, const pcl_value *a, const pcl_value *b) {
    return pcl_error(L, "cannot %s a %d-D value and a %d-D value: dimensions cannot be mixed",
                      op, a->n, b->n);
}

static int l_add(lua_State *L) {
    pcl_value *a = topt(L, 1), *b = topt(L, 2);
    if ((!a || !b) && pcl_eq_hook(L, PCL_EQ_ADD)) return 1;
    if (!a || !b)
        return pcl_error(L, "cannot add %s and %s: points and vectors add only to points and "
                          "vectors; to shift a point write A + V(dx, dy)",
                          opnd_name(L, 1), opnd_name(L, 2));
    int n = a->n;
    if (b->n != n) return mixed_error(L, "add", a, b);
    pcl_value *r = newpt(L, n);
    for (int i = 0; i <= n; i++) r->h[i] = a->h[i] + b->h[i];
    return finite_or_error(L, r, "A + B");
}

static int l_sub(lua_State *L) {
    pcl_value *a = topt(L, 1), *b = topt(L, 2);
    if ((!a || !b) && pcl_eq_hook(L, PCL_EQ_SUB)) return 1;
    if (!a || !b)
        return pcl_error(L, "cannot subtract %s from %s: points and vectors subtract only "
                          "points and vectors; to shift a point write A - V(dx, dy)",
                          opnd_name(L, 2), opnd_name(L, 1));
    int n = a->n;
    if (b->n != n) return mixed_error(L, "subtract", a, b);
    pcl_value *r = newpt(L, n);
    for (int i = 0; i <= n; i++) r->h[i] = a->h[i] - b->h[i];
    return finite_or_error(L, r, "A - B");
}

static int l_mul(lua_State *L) {
    pcl_value *p;
    int k_idx;
    if ((p = topt(L, 1)) != NULL) k_idx = 2;
    else if ((p = topt(L, 2)) != NULL) k_idx = 1;
    else if (pcl_eq_hook(L, PCL_EQ_MUL)) return 1;
    else return pcl_error(L, "cannot multiply %s by %s", opnd_name(L, 1), opnd_name(L, 2));
    if (lua_type(L, k_idx) != LUA_TNUMBER) {
        if (pcl_eq_hook(L, PCL_EQ_MUL)) return 1;
        if (topt(L, k_idx))
            return pcl_error(L, "cannot multiply a point by a point: use dot(u, v) or "
                              "cross(u, v) for products of vectors");
        return pcl_error(L, "cannot multiply a point by %s", opnd_name(L, k_idx));
    }
    double k = lua_tonumber(L, k_idx);
    if (!isfinite(k)) return pcl_error(L, "cannot multiply a point by %f", k);
    int n = p->n;
    pcl_value *r = newpt(L, n);
    for (int i = 0; i <= n; i++) r->h[i] = p->h[i] * k;
    return finite_or_error(L, r, "k * A");
}

/* u / v of two parallel vectors: the number r with u = r v ((2.62)'s (T - A)/(T_C - A)) */
static int vec_ratio(lua_State *L, const pcl_value *u, const pcl_value *v) {
    int n = u->n;
    if (v->n != n) return pcl_error(L, "cannot divide a %d-D vector by a %d-D one (mixed dimensions)", n, v->n);
    if (fabs(u->h[n]) > PC_WEIGHT_TOL || fabs(v->h[n]) > PC_WEIGHT_TOL)
        return pcl_error(L, "cannot divide %s by %s: only a vector divides a parallel vector (u/v = r with u = r v; "
                         "the difference of two points is a vector)", opnd_name(L, 1), opnd_name(L, 2));
    double r, ang;
    int st = pc_vec_ratio(n, u->h, v->h, &r, &ang);
    if (st == PC_EZERO) return pcl_error(L, "division of a vector by the zero vector");
    if (st == PC_ENOTCOLLINEAR)
        return pcl_error(L, "cannot divide vectors that are not parallel: they are %s degrees apart "
                         "(the ratio u/v needs u = r v, within 1e-9)", pcl_pushnum(L, ang * 180 / 3.14159265358979323846));
    if (st != PC_OK) return pcl_statuserror(L, "/", st, NULL);
    lua_pushnumber(L, r);
    return 1;
}

static int l_div(lua_State *L) {
    pcl_value *p = topt(L, 1);
    pcl_value *q = topt(L, 2);
    if (p && q) return vec_ratio(L, p, q);
    if ((!p || lua_type(L, 2) != LUA_TNUMBER) && pcl_eq_hook(L, PCL_EQ_DIV)) return 1;
    if (!p) return pcl_error(L, "cannot divide %s by a point", opnd_name(L, 1));
    if (lua_type(L, 2) != LUA_TNUMBER)
        return pcl_error(L, "cannot divide a point by %s", opnd_name(L, 2));
    double k = lua_tonumber(L, 2);
    if (k == 0) return pcl_error(L, "division of a point by zero");
    if (!isfinite(k)) return pcl_error(L, "cannot divide a point by %f", k);
    int n = p->n;
    pcl_value *r = newpt(L, n);
    for (int i = 0; i <= n; i++) r->h[i] = p->h[i] / k;   /* the weight is divided too */
    return finite_or_error(L, r, "A / k");
}

static int l_unm(lua_State *L) {
    pcl_value *p = topt(L, 1);
    if (!p && pcl_eq_hook(L, PCL_EQ_UNM)) return 1;
    if (!p) return pcl_error(L, "cannot negate %s", opnd_name(L, 1));
    int n = p->n;
    pcl_value *r = newpt(L, n);
    for (int i = 0; i <= n; i++) r->h[i] = -p->h[i];
    return 1;
}

static int l_eq(lua_State *L) {
    pcl_value *a = topt(L, 1), *b = topt(L, 2);
    int eq = a && b && a->n == b->n;
    for (int i = 0; eq && i <= a->n; i++) eq = a->h[i] == b->h[i];
    lua_pushboolean(L, eq);
    return 1;
}

static int l_len(lua_State *L) {
    pcl_value *p = lua_touserdata(L, 1);                /* only the VM calls it */
    if (!p) return pcl_error(L, "#: not a point");
    if (!genuine_value(L, 1, p)) pcl_genuine(L, 1, p, 0, "point");
    lua_pushinteger(L, p->n);
    return 1;
}

static int l_tostring(lua_State *L) {
    pcl_value *p = topt(L, 1);
    if (!p) return pcl_error(L, "tostring: not a point");
    push_value_text(L, p);
    return 1;
}

static int l_concat(lua_State *L) {
    luaL_tolstring(L, 1, NULL);
    luaL_tolstring(L, 2, NULL);
    lua_concat(L, 2);
    return 1;
}

/* The membership-condition error for reading coordinate i (0-based) of p; key is the field
 * name (NULL for p[i]). */
static int coord_error(lua_State *L, pcl_value *p, int i, const char *key) {
    const char *label = key ? lua_pushfstring(L, ".%s", key) : lua_pushfstring(L, "p[%d]", i + 1);
    const char *ctx = lua_pushfstring(L, "reading %s: the value %s", label, push_value_text(L, p));
    return location_error(L, ctx, p);
}

/* coordinate i (0-based) of p as a location or vector component */
static inline int push_coord(lua_State *L, pcl_value *p, int i, const char *key) {
    double w = p->h[p->n];
    if (w == 1.0 || w == 0.0) {                         /* the common case */
        lua_pushnumber(L, p->h[i]);
        return 1;
    }
    switch (pc_kind_of(w)) {
    case PC_KIND_POINT: lua_pushnumber(L, p->h[i] / w); return 1;
    case PC_KIND_VECTOR: lua_pushnumber(L, p->h[i]); return 1;
    default: return coord_error(L, p, i, key);
    }
}

/* __index: .x .y .z (coordinates), .w (the weight), p[i], then the methods.  Only the VM calls
 * it (the metatable is protected by __metatable), always with a point as argument 1. */
static int l_index(lua_State *L) {
    pcl_value *p = lua_touserdata(L, 1);
    if (!p) return pcl_error(L, "index: not a point");
    /* the VM calls it for any userdata with this metatable, a forged one too */
    if (!genuine_value(L, 1, p)) pcl_genuine(L, 1, p, 0, "point");
    int t = lua_type(L, 2);
    if (t == LUA_TSTRING) {
        size_t len;
        const char *k = lua_tolstring(L, 2, &len);
        if (len == 1) {
            int i;
            switch (k[0]) {
            case 'x': i = 0; break;
            case 'y': i = 1; break;
            case 'z': i = 2; break;
            case 'w': lua_pushnumber(L, p->h[p->n]); return 1;     /* the weight */
            default: i = -1;
            }
            if (i >= 0) {
                if (i >= p->n) {
                    const char *text = push_value_text(L, p);
                    return pcl_error(L, "%s is %d-D: it has no coordinate .%s", text, p->n, k);
                }
                return push_coord(L, p, i, k);
            }
        }
        lua_pushvalue(L, 2);
        lua_rawget(L, METHODS);
        return 1;
    }
    if (t == LUA_TNUMBER) {
        int isint;
        lua_Integer i = lua_tointegerx(L, 2, &isint);
        if (isint && i >= 1 && i <= p->n) return push_coord(L, p, (int)i - 1, NULL);
    }
    lua_pushnil(L);
    return 1;
}

static int l_newindex(lua_State *L) {
    return pcl_error(L, "points are immutable: make a new one instead, e.g. P(x, p.y)");
}

/* ---- helpers ----------------------------------------------------------------------------- */

/* lerp(A, B, t) = (B - A) t + A (Fig. 1.1), for points, vectors or numbers. */
static int l_lerp(lua_State *L) {
    pcl_value *a = topt(L, 1), *b = topt(L, 2);
    int isnum = lua_type(L, 3) == LUA_TNUMBER;          /* no string coercion, as in P() */
    double t = isnum ? lua_tonumber(L, 3) : 0;
    if (a && b && isnum && a->n == b->n && isfinite(t)) {       /* the hot path */
        int n = a->n;
        pcl_value *r = newpt(L, n);
        pc_lerp(n, a->h, b->h, t, r->h);     /* equal weights kept exactly (t = 1e16) */
        for (int i = 0; i <= n; i++)
            if (!isfinite(r->h[i]))
                return pcl_error(L, "%s: the result is out of range (not finite) for t = %s",
                                 pcl_fname(L), pcl_pushnum(L, t));
        return 1;
    }
    if (!isnum && pcl_eq_hook(L, PCL_EQ_LERP)) return 1;
    if (!a && !b && lua_type(L, 1) == LUA_TNUMBER && lua_type(L, 2) == LUA_TNUMBER) {
        double x = lua_tonumber(L, 1), y = lua_tonumber(L, 2);
        t = pcl_checkfinite(L, 3, "t");
        double v = x * (1 - t) + y * t;
        if (!isfinite(v))
            return pcl_error(L, "%s: the result is out of range (not finite) for t = %s",
                             pcl_fname(L), pcl_pushnum(L, t));
        lua_pushnumber(L, v);
        return 1;
    }
    if (pcl_eq_hook(L, PCL_EQ_LERP)) return 1;
    if (!a) pcl_argerror(L, 1, "A", "a point or vector");
    if (!b) pcl_argerror(L, 2, "B", "a point or vector");
    if (a->n != b->n) pcl_dimerror(L, 2, "B", b->n, a->n, 1);
    pcl_checkfinite(L, 3, "t");
    return 0;
}

static int l_bar(lua_State *L) {
    if (lua_type(L, 1) != LUA_TNUMBER && pcl_eq_hook(L, PCL_EQ_BAR)) return 1;
    lua_pushnumber(L, 1.0 - pcl_checkfinite(L, 1, "t"));
    return 1;
}

/* mid(A, B, ...): the midpoint, or the centroid of several values. */
static int l_mid(lua_State *L) {
    int m = lua_gettop(L);
    pcl_value *a = checkval(L, 1, "A");
    if (m < 2) pcl_argerror(L, 2, "B", "a point or vector");
    int n = a->n;
    for (int j = 2; j <= m; j++) {
        pcl_value *b = checkval(L, j, NULL);
        if (b->n != n) pcl_dimerror(L, j, NULL, b->n, n, 1);
    }
    pcl_value *r = newpt(L, n);
    for (int i = 0; i <= n; i++) {
        double s = 0;
        for (int j = 1; j <= m; j++) s += ((pcl_value *)lua_touserdata(L, j))->h[i] / m;
        r->h[i] = s;   /* each term divided first: mid(P(1e308, 0), P(1e308, 0)) is P(1e308, 0) */
    }
    return finite_or_error(L, r, pcl_fname(L));
}

/* dist(A, B) between points, or dist(v), the length of a vector.  The form follows the
 * first argument, so that dist(A, nil) names the missing argument #2. */
static int l_dist(lua_State *L) {
    double a[PC_MAXDIM], b[PC_MAXDIM];
    pcl_value *p = topt(L, 1);
    if (p && pc_kind_of(p->h[p->n]) == PC_KIND_VECTOR && lua_isnoneornil(L, 2)) {
        int n = vec_of(L, p, 1, "v", 0, 0, a);
        lua_pushnumber(L, pc_norm(n, a));
        return 1;
    }
    int n = checkloc(L, 1, "A", 0, 0, a);
    checkloc(L, 2, "B", n, 1, b);
    lua_pushnumber(L, pc_dist(n, a, b));
    return 1;
}

static int l_dot(lua_State *L) {
    double u[PC_MAXDIM], v[PC_MAXDIM];
    if ((!topt(L, 1) || !topt(L, 2)) && pcl_eq_hook(L, PCL_EQ_DOT)) return 1;
    int n = checkvec(L, 1, "u", 0, 0, u);
    checkvec(L, 2, "v", n, 1, v);
    lua_pushnumber(L, pc_dot(n, u, v));
    return 1;
}

/* cross(u, v): a vector in 3-D, the number u.x v.y - u.y v.x in 2-D. */
static int l_cross(lua_State *L) {
    double u[PC_MAXDIM], v[PC_MAXDIM];
    if ((!topt(L, 1) || !topt(L, 2)) && pcl_eq_hook(L, PCL_EQ_CROSS)) return 1;
    int n = checkvec(L, 1, "u", 0, 0, u);
    checkvec(L, 2, "v", n, 1, v);
    if (n == 2) {
        lua_pushnumber(L, pc_cross2(u, v));
        return 1;
    }
    if (n != 3)
        return pcl_error(L, "%s: vectors must be 2-D or 3-D, got %d-D", pcl_fname(L), n);
    double w[3];
    pc_cross3(u, v, w);
    push_vec(L, 3, w);
    return 1;
}

static int l_unit(lua_State *L) {
    double u[PC_MAXDIM], w[PC_MAXDIM];
    if (!topt(L, 1) && pcl_eq_hook(L, PCL_EQ_UNIT)) return 1;
    int n = checkvec(L, 1, "v", 0, 0, u);
    if (pc_unit(n, u, w) != PC_OK)
        return pcl_error(L, "%s: the zero vector has no direction", pcl_fname(L));
    push_vec(L, n, w);
    return 1;
}

static int l_perp(lua_State *L) {
    double u[PC_MAXDIM], w[2];
    int n = checkvec(L, 1, "v", 0, 0, u);
    if (n != 2)
        return pcl_error(L, "%s: argument #1 (v) must be a 2-D vector, got %d-D (in space "
                          "a perpendicular is not unique: use cross(u, v))", pcl_fname(L), n);
    pc_perp2(u, w);
    push_vec(L, 2, w);
    return 1;
}

/* angle(A, B, C): the angle at A of triangle ABC; angle(u, v): between two vectors.
 * Unsigned, in radians, in [0, pi].  The form follows the first argument (a vector or not),
 * so that angle(A, B, nil) names the missing argument #3. */
static int l_angle(lua_State *L) {
    double a[PC_MAXDIM], b[PC_MAXDIM], c[PC_MAXDIM], ang;
    int n;
    pcl_value *first = topt(L, 1);
    int vectors = first ? pc_kind_of(first->h[first->n]) == PC_KIND_VECTOR
                        : lua_isnoneornil(L, 3);
    if (vectors) {
        n = checkvec(L, 1, "u", 0, 0, b);
        checkvec(L, 2, "v", n, 1, c);
    } else {
        n = checkloc(L, 1, "A", 0, 0, a);
        checkloc(L, 2, "B", n, 1, b);
        checkloc(L, 3, "C", n, 1, c);
        for (int i = 0; i < n; i++) { b[i] -= a[i]; c[i] -= a[i]; }
    }
    if (pc_angle(n, b, c, &ang) != PC_OK)
        return pcl_error(L, "%s: a side has zero length, so the angle is undefined", pcl_fname(L));
    lua_pushnumber(L, ang);
    return 1;
}

static int l_foot(lua_State *L) {
    double c[PC_MAXDIM], a[PC_MAXDIM], b[PC_MAXDIM], h[PC_MAXDIM];
    int n = checkloc(L, 1, "C", 0, 0, c);
    checkloc(L, 2, "A", n, 1, a);
    checkloc(L, 3, "B", n, 1, b);
    if (pc_foot(n, c, a, b, h) != PC_OK)
        return pcl_error(L, "%s: A and B coincide, so they do not define a line", pcl_fname(L));
    push_loc(L, n, h);
    return 1;
}

static int l_sigma(lua_State *L) {
    double a[PC_MAXDIM], b[PC_MAXDIM], c[PC_MAXDIM];
    int n = checkloc(L, 1, "A", 0, 0, a);
    checkloc(L, 2, "B", n, 1, b);
    if (lua_isnoneornil(L, 3)) memcpy(c, b, sizeof(double) * (size_t)n);   /* Σ^A_BB = AB² */
    else checkloc(L, 3, "C", n, 1, c);
    lua_pushnumber(L, pc_sigma(n, a, b, c));
    return 1;
}

/* ---- ratios -------------------------------------------------------------------------------- */

/* A point or an improper point (weight 0) at arg, as a value of dimension n. */
static pcl_value *check_proj(lua_State *L, int arg, const char *what, int n, int dim_arg) {
    pcl_value *p = topt(L, arg);
    if (!p) pcl_argerror(L, arg, what, "a point (or a point at infinity)");
    if (p->n != n) pcl_dimerror(L, arg, what, p->n, n, dim_arg);
    if (pc_kind_of(p->h[n]) == PC_KIND_WEIGHTED) location_error(L, argctx(L, arg, what), p);
    return p;
}

static int ratio_error(lua_State *L, int st) {
    const char *f = pcl_fname(L);
    switch (st) {
    case PC_ECOINCIDENT: return pcl_error(L, "%s: the points coincide, so the ratio is undefined", f);
    case PC_ENOTCOLLINEAR: return pcl_error(L, "%s: the points are not collinear", f);
    case PC_EZERO: return pcl_error(L, "%s: a point at infinity with a zero direction", f);
    default: return pcl_error(L, "%s: %s", f, pc_strerror(st));
    }
}

/* sr(X, Y, Z) = (X - Z)/(Z - Y): Z divides XY in this ratio.  math.huge when Z = Y; -1 when Z
 * is the improper point of the line. */
static int l_sr(lua_State *L) {
    double x[PC_MAXDIM], y[PC_MAXDIM], lam;
    int n = checkloc(L, 1, "X", 0, 0, x);
    checkloc(L, 2, "Y", n, 1, y);
    pcl_value *z = check_proj(L, 3, "Z", n, 1);
    int st = pc_sr(n, x, y, z->h, &lam);
    if (st != PC_OK) return ratio_error(L, st);
    lua_pushnumber(L, lam);
    return 1;
}

/* divide(X, Y, lambda) = (X + lambda Y)/(1 + lambda); lambda = -1 gives the improper point. */
static int l_divide(lua_State *L) {
    double x[PC_MAXDIM], y[PC_MAXDIM];
    int n = checkloc(L, 1, "X", 0, 0, x);
    checkloc(L, 2, "Y", n, 1, y);
    if (lua_type(L, 3) != LUA_TNUMBER) pcl_argerror(L, 3, "lambda", "a number");
    double lam = lua_tonumber(L, 3);
    if (isnan(lam)) pcl_argerror(L, 3, "lambda", "a number, not NaN");
    double xh[PC_MAXDIM + 1], yh[PC_MAXDIM + 1];
    memcpy(xh, x, sizeof(double) * (size_t)n);
    memcpy(yh, y, sizeof(double) * (size_t)n);
    xh[n] = yh[n] = 1.0;
    double out[PC_MAXDIM + 1];
    int st = pc_divide(n, xh, yh, lam, out);
    if (st == PC_ENONFINITE)
        return pcl_error(L, "divide: the point is out of range (not finite) for lambda = %s",
                         pcl_pushnum(L, lam));
    pcl_value *r = newpt(L, n);
    memcpy(r->h, out, sizeof(double) * (size_t)(n + 1));
    return 1;
}

static int l_harmonic(lua_State *L) {
    double a[PC_MAXDIM], b[PC_MAXDIM];
    int n = checkloc(L, 1, "A", 0, 0, a);
    checkloc(L, 2, "B", n, 1, b);
    pcl_value *t = check_proj(L, 3, "T", n, 1);
    double out[PC_MAXDIM + 1];
    int st = pc_harmonic(n, a, b, t->h, out);
    if (st != PC_OK && st != PC_IMPROPER) return ratio_error(L, st);
    pcl_value *r = newpt(L, n);
    memcpy(r->h, out, sizeof(double) * (size_t)(n + 1));
    return 1;
}

static int l_cross_ratio(lua_State *L) {
    double a[PC_MAXDIM], b[PC_MAXDIM], r;
    int n = checkloc(L, 1, "A", 0, 0, a);
    checkloc(L, 2, "B", n, 1, b);
    pcl_value *c = check_proj(L, 3, "C", n, 1);
    pcl_value *d = check_proj(L, 4, "D", n, 1);
    int st = pc_cross_ratio(n, a, b, c->h, d->h, &r);
    if (st != PC_OK) return ratio_error(L, st);
    lua_pushnumber(L, r);
    return 1;
}

/* ---- incidence and measure ---------------------------------------------------------------- */

/* An end of a line for meet: a point, or a point at infinity (weight 0) with a direction. */
static pcl_value *check_end(lua_State *L, int arg, const char *what, int n, int dim_arg) {
    pcl_value *p = topt(L, arg);
    if (p && n == 0) n = p->n;
    p = check_proj(L, arg, what, n, dim_arg);
    if (pc_kind_of(p->h[n]) == PC_KIND_VECTOR && pc_norm(n, p->h) == 0)
        pcl_error(L, "%s is the zero vector %s, which has no direction, so it is no point at "
                  "infinity", argctx(L, arg, what), push_value_text(L, p));
    return p;
}

/* meet(A1, A2, B1, B2) -> K, lambda, mu with K = A1 + (A2 - A1) lambda = B1 + (B2 - B1) mu.
 * An end may be a point at infinity (a direction, weight 0), as in the book's homogeneous
 * meet: a point P and a direction D (either order) give the line through P along D, with
 * K = P + D lambda; two directions give the line at infinity (of their plane).
 * Parallel lines: their common improper point (the direction of the first line, weight 0),
 * math.huge, math.huge; likewise a line and a line at infinity.  Skew lines (3-D and up): nil
 * and the distance between them (math.huge for a line that misses a line at infinity). */
static int l_meet(lua_State *L) {
    if (!(topt(L, 1) && topt(L, 2) && topt(L, 3) && topt(L, 4)) && pcl_eq_hook(L, PCL_EQ_MEET)) return 3;
    pcl_value *a1 = check_end(L, 1, "A1", 0, 0);
    int n = a1->n;
    pcl_value *a2 = check_end(L, 2, "A2", n, 1);
    pcl_value *b1 = check_end(L, 3, "B1", n, 1);
    pcl_value *b2 = check_end(L, 4, "B2", n, 1);
    double out[PC_MAXDIM + 1], lam, mu, res;
    const char *f = pcl_fname(L);
    int st = pc_meet_h(n, a1->h, a2->h, b1->h, b2->h, out, &lam, &mu, &res);
    switch (st) {
    case PC_OK:
    case PC_IMPROPER: {
        pcl_value *r = newpt(L, n);
        memcpy(r->h, out, sizeof(double) * (size_t)(n + 1));
        lua_pushnumber(L, lam);
        lua_pushnumber(L, mu);
        return 3;
    }
    case PC_ESKEW:
        lua_pushnil(L);
        lua_pushnumber(L, res);
        return 2;
    case PC_ESAME_LINE:
        return pcl_error(L, "%s: the two lines coincide, so they have no single meet", f);
    case PC_ECOINCIDENT: {
        /* which line: the meet of line A with itself fails the same way only if A is bad */
        int bad_a = pc_meet_h(n, a1->h, a2->h, a1->h, a2->h, out, NULL, NULL, NULL) == st;
        pcl_value *e1 = bad_a ? a1 : b1;
        const char *names = bad_a ? "A1 and A2" : "B1 and B2";
        if (pc_kind_of(e1->h[n]) == PC_KIND_VECTOR)
            return pcl_error(L, "%s: %s are the same point at infinity (parallel directions), "
                              "so they do not define a line", f, names);
        return pcl_error(L, "%s: %s coincide, so they do not define a line", f, names);
    }
    case PC_EDIM:
        return pcl_error(L, "%s: lines in 1-D all coincide; meet needs 2-D or more", f);
    }
    return pcl_error(L, "%s: %s", f, pc_strerror(st));
}

/* area(A, B, C): signed in 2-D (counter-clockwise positive), unsigned in any dimension;
 * area(A, B, C, D, ...) in 2-D: the signed area of the polygon. */
static int l_area(lua_State *L) {
    int m = lua_gettop(L);
    double a[PC_MAXDIM], b[PC_MAXDIM], c[PC_MAXDIM];
    int n = checkloc(L, 1, "A", 0, 0, a);
    if (n < 2) return pcl_error(L, "%s: points must be 2-D or more, got 1-D", pcl_fname(L));
    checkloc(L, 2, "B", n, 1, b);
    checkloc(L, 3, "C", n, 1, c);
    if (n == 2) {
        if (m == 3) {
            lua_pushnumber(L, pc_area2(a, b, c));
            return 1;
        }
        double s = pc_area2(a, b, c), prev[2] = {c[0], c[1]};
        for (int j = 4; j <= m; j++) {
            double d[2];
            checkloc(L, j, NULL, 2, 1, d);
            s += pc_area2(a, prev, d);
            prev[0] = d[0]; prev[1] = d[1];
        }
        lua_pushnumber(L, s);
        return 1;
    }
    if (m > 3)
        return pcl_error(L, "%s: a polygon area needs 2-D points; in %d-D give a triangle",
                          pcl_fname(L), n);
    lua_pushnumber(L, pc_area(n, a, b, c));
    return 1;
}

/* volume(A, B, C, D): signed in 3-D (positive when B - A, C - A, D - A are right-handed),
 * unsigned in 4-D and up. */
static int l_volume(lua_State *L) {
    double v[4 * PC_MAXDIM];
    static const char *names[] = {"A", "B", "C", "D"};
    int n = checkloc(L, 1, "A", 0, 0, v);
    if (n < 3) return pcl_error(L, "%s: points must be 3-D or more, got %d-D", pcl_fname(L), n);
    for (int j = 1; j < 4; j++) checkloc(L, j + 1, names[j], n, 1, v + j * n);
    if (n == 3) lua_pushnumber(L, pc_volume3(v, v + 3, v + 6, v + 9));
    else lua_pushnumber(L, pc_measure(n, 3, v));
    return 1;
}

/* ---- weights -------------------------------------------------------------------------------- */

static int l_normalize(lua_State *L) {
    pcl_value *p = checkval(L, 1, "p");
    int n = p->n;
    double out[PC_MAXDIM + 1];
    if (pc_normalize(n, p->h, out) != PC_OK)
        return pcl_error(L, "%s: %s has weight 0 (a vector, or a point at infinity), so it has "
                          "no finite location", pcl_fname(L), push_value_text(L, p));
    pcl_value *r = newpt(L, n);
    memcpy(r->h, out, sizeof(double) * (size_t)(n + 1));
    return 1;
}

static int l_weight(lua_State *L) {
    pcl_value *p = checkval(L, 1, "p");
    lua_pushnumber(L, p->h[p->n]);
    return 1;
}

/* coords(p) -> x, y, ...: the coordinates of a point or the components of a vector. */
static int l_coords(lua_State *L) {
    pcl_value *p = checkval(L, 1, "p");
    int n = p->n;
    double w = p->h[n];
    if (pc_kind_of(w) == PC_KIND_WEIGHTED) location_error(L, argctx(L, 1, "p"), p);
    luaL_checkstack(L, n, "too many coordinates");
    double div = (pc_kind_of(w) == PC_KIND_POINT) ? w : 1.0;
    for (int i = 0; i < n; i++) lua_pushnumber(L, p->h[i] / div);
    return n;
}

/* near(a, b [, eps]): numbers, or values of one dimension, equal within eps (default 1e-9)
 * relative to their size (at least 1). */
static int l_near(lua_State *L) {
    double eps = 1e-9;
    if (!lua_isnoneornil(L, 3)) {
        eps = pcl_checkfinite(L, 3, "eps");
        if (eps < 0) pcl_argerror(L, 3, "eps", "a non-negative number");
    }
    if (lua_type(L, 1) == LUA_TNUMBER && lua_type(L, 2) == LUA_TNUMBER) {
        double a = lua_tonumber(L, 1), b = lua_tonumber(L, 2);
        lua_pushboolean(L, fabs(a - b) <= eps * fmax(1.0, fmax(fabs(a), fabs(b))));
        return 1;
    }
    pcl_value *a = checkval(L, 1, "a"), *b = checkval(L, 2, "b");
    if (a->n != b->n) pcl_dimerror(L, 2, "b", b->n, a->n, 1);
    double scale = 1, d = 0;
    for (int i = 0; i <= a->n; i++) {
        scale = fmax(scale, fmax(fabs(a->h[i]), fabs(b->h[i])));
        d = fmax(d, fabs(a->h[i] - b->h[i]));
    }
    lua_pushboolean(L, d <= eps * scale);
    return 1;
}

/* ---- the drawing layer's hook --------------------------------------------------------------- */

int pcl_topoint2(lua_State *L, int idx, double *x, double *y) {
    idx = lua_absindex(L, idx);
    pcl_value *p = pcl_tovalue(L, idx);
    if (!p) return 0;
    if (p->n != 2) {
        /* with a camera set, drawing takes its points (3-D) and draws their images */
        int st = pcl_project(L, p->n, p->h, x, y);
        if (st == PC_OK) return 1;
        if (st == PC_IMPROPER)
            return pcl_error(L, "%s: argument #%d (%s) projects to infinity (it lies in the "
                              "camera's vanishing plane)", pcl_fname(L), idx, push_value_text(L, p));
        const char *text = push_value_text(L, p);
        return pcl_error(L, "%s: argument #%d must be a 2-D point, got the %d-D %s", pcl_fname(L),
                          idx, p->n, text);
    }
    double loc[2];
    if (pc_loc(2, p->h, loc) != PC_OK) location_error(L, argctx(L, idx, NULL), p);
    if (!isfinite(loc[0]) || !isfinite(loc[1]))        /* arithmetic overflowed */
        return pcl_error(L, "%s has infinite or NaN coordinates", argctx(L, idx, NULL));
    *x = loc[0];
    *y = loc[1];
    return 1;
}

/* ---- registration --------------------------------------------------------------------------- */

static const luaL_Reg point_functions[] = {
    {"P", l_P}, {"V", l_V},
    {"lerp", l_lerp}, {"bar", l_bar}, {"mid", l_mid}, {"dist", l_dist}, {"dot", l_dot},
    {"cross", l_cross}, {"unit", l_unit}, {"perp", l_perp}, {"angle", l_angle},
    {"foot", l_foot}, {"Sigma", l_sigma},
    {"sr", l_sr}, {"divide", l_divide}, {"harmonic", l_harmonic}, {"cross_ratio", l_cross_ratio},
    {"meet", l_meet}, {"area", l_area}, {"volume", l_volume},
    {"normalize", l_normalize}, {"weight", l_weight}, {"coords", l_coords}, {"near", l_near},
    {NULL, NULL}
};

/* p:method() for the one-receiver functions */
static const char *const method_names[] = {
    "lerp", "mid", "dist", "dot", "cross", "unit", "perp", "angle", "normalize", "weight",
    "coords", "near", NULL
};

static const luaL_Reg point_meta[] = {
    {"__add", l_add}, {"__sub", l_sub}, {"__mul", l_mul}, {"__div", l_div}, {"__unm", l_unm},
    {"__eq", l_eq}, {"__len", l_len}, {"__tostring", l_tostring}, {"__concat", l_concat},
    {"__newindex", l_newindex},
    {NULL, NULL}
};

void pcl_open_point(lua_State *L) {
    int module = lua_gettop(L);
    /* the metatable, also kept in the registry for pcl_tovalue and the other bindings */
    lua_newtable(L);
    int mt = lua_gettop(L);
    lua_pushliteral(L, "point");
    lua_setfield(L, mt, "__name");
    lua_pushliteral(L, "point");                       /* getmetatable(p) == "point" */
    lua_setfield(L, mt, "__metatable");
    lua_pushvalue(L, mt);
    lua_rawsetp(L, LUA_REGISTRYINDEX, &POINT_MT_KEY);
    lua_pushvalue(L, mt);
    luaL_setfuncs(L, point_meta, 1);                   /* metamethods, upvalue = mt */

    lua_pushvalue(L, module);                          /* functions, upvalue = mt */
    lua_pushvalue(L, mt);
    luaL_setfuncs(L, point_functions, 1);
    lua_pop(L, 1);

    lua_newtable(L);                                   /* methods for p:name(...) */
    int methods = lua_gettop(L);
    for (const char *const *m = method_names; *m; m++) {
        lua_getfield(L, module, *m);
        lua_setfield(L, methods, *m);
    }
    lua_pushvalue(L, mt);
    lua_pushvalue(L, methods);
    lua_pushcclosure(L, l_index, 2);
    lua_setfield(L, mt, "__index");
    lua_settop(L, module);
}
