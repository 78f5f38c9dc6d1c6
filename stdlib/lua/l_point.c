/* Binding of the point calculus values (stdlib/geom/point.h): P V, the operators, and
 * lerp bar mid dist dot cross unit perp angle foot sr divide harmonic cross_ratio meet area
 * volume Sigma normalize weight coords near, declared on the argument layer (pcl_args.h).
 *
 * A value is a full userdata of variable size (header + n+1 doubles).  Every C function here
 * has the point metatable as upvalue 2 (upvalue 1 is a declared function's declaration), so
 * recognising a point is a pointer comparison, never a registry lookup by name; the hot paths
 * (P, lerp, + - * /, .x) allocate exactly one userdata and read nothing twice: the layer reads
 * the arguments again only to word an error. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "pcl_args.h"
#include "pcl_point.h"
#include "pcl_curve.h"
#include "pcl_expr.h"   /* equations take over when an operand is one (l_expr.c) */

static const char POINT_MT_KEY = 'p';       /* registry key (its address) of the metatable */
#define MT lua_upvalueindex(2)
#define METHODS lua_upvalueindex(3)         /* __index only: the method table */

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

static const char *push_value_text(lua_State *L, const pcl_value *p) {
    char s[PC_MAXDIM * 24 + 32];
    pc_value_text(p->n, p->h, s, sizeof s);
    return lua_pushstring(L, s);
}

/* ---- the messages of the operators and the drawing hook ------------------------------------ */

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
    const char *wt = pcl_pushnum(L, w);
    return pcl_error(L, "%s has weight %s, so it is neither a point (weight 1) nor a vector "
                      "(weight 0): %s; write offsets with V(), e.g. V(x, y)*100 + P(320, 240), "
                      "or use normalize(p) for a projective point", ctx, wt, MEMBERSHIP);
}

static const char *argctx(lua_State *L, int arg, const char *what) {
    const char *an = argname(L, arg);
    if (what && what[0]) return lua_pushfstring(L, "%s: %s (%s)", pcl_fname(L), an, what);
    return lua_pushfstring(L, "%s: %s", pcl_fname(L), an);
}

/* a new value of dimension n: the n coordinates x and the weight w (r: made by the caller) */
static void fill(pcl_value *r, int n, const double *x, double w) {
    memcpy(r->h, x, sizeof(double) * (size_t)n);
    r->h[n] = w;
}
void pcl_pushpoint(lua_State *L, int n, const double *x) { fill(pcl_newvalue(L, n), n, x, 1.0); }
void pcl_pushvector(lua_State *L, int n, const double *x) { fill(pcl_newvalue(L, n), n, x, 0.0); }
static void push_w(lua_State *L, int n, const double *x, double w) { fill(newpt(L, n), n, x, w); }
/* the n + 1 homogeneous h */
static void push_h(lua_State *L, int n, const double *h) { fill(newpt(L, n), n, h, h[n]); }
static int push_num(lua_State *L, double x) {
    lua_pushnumber(L, x);
    return 1;
}

/* ---- construction ------------------------------------------------------------------------- */

/* Coordinate i (0-based) of P(...) at stack index idx, or [i + 1] of the table P{...}: the
 * layer's message when it is not a finite number. */
static double coordinate(lua_State *L, int idx, int i, int table) {
    if (lua_type(L, idx) == LUA_TNUMBER && isfinite(lua_tonumber(L, idx))) return lua_tonumber(L, idx);
    static const char *xyz[] = {"x", "y", "z"};
    char name[24];
    snprintf(name, sizeof name, "coordinate %d", i + 1);
    pcl_arg a = {.name = table ? "coordinates" : i < 3 ? xyz[i] : name, .kind = PCL_NUMBER};
    pcl_val v;
    pcl_readone(L, idx, table ? 1 : i + 1, table ? i + 1 : 0, &a, 0, &v);
    return v.x;
}

static int make(lua_State *L, double weight) {
    int n = lua_gettop(L), table = n == 1 && lua_type(L, 1) == LUA_TTABLE;   /* P{1, 2} */
    if (table) n = (int)lua_rawlen(L, 1);
    for (int i = 0; !table && i < n; i++)       /* an equation among the coordinates: P of it */
        if (lua_type(L, i + 1) != LUA_TNUMBER && pcl_eq_hook(L, weight == 1.0 ? PCL_EQ_P : PCL_EQ_V)) return 1;
    if (n < 1) return pcl_fail(L, table ? "the table has no coordinates" : "needs at least one coordinate");
    if (n > PC_MAXDIM) return pcl_fail(L, "%d coordinates, but the largest dimension is %d", n, PC_MAXDIM);
    pcl_value *p = newpt(L, n);
    for (int i = 0; i < n; i++) {
        if (table) lua_rawgeti(L, 1, i + 1);
        p->h[i] = coordinate(L, table ? lua_gettop(L) : i + 1, i, table);
        if (table) lua_pop(L, 1);
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

/* A + B and A - B (sign -1): weights add, so a point plus a vector is a point. */
static int add_sub(lua_State *L, double sign) {
    pcl_value *a = topt(L, 1), *b = topt(L, 2);
    if ((!a || !b) && pcl_eq_hook(L, sign > 0 ? PCL_EQ_ADD : PCL_EQ_SUB)) return 1;
    if ((!a || !b) && sign > 0)
        return pcl_error(L, "cannot add %s and %s: points and vectors add only to points and "
                          "vectors; to shift a point write A + V(dx, dy)",
                          opnd_name(L, 1), opnd_name(L, 2));
    if (!a || !b)
        return pcl_error(L, "cannot subtract %s from %s: points and vectors subtract only "
                          "points and vectors; to shift a point write A - V(dx, dy)",
                          opnd_name(L, 2), opnd_name(L, 1));
    int n = a->n;
    if (b->n != n) return mixed_error(L, sign > 0 ? "add" : "subtract", a, b);
    pcl_value *r = newpt(L, n);
    for (int i = 0; i <= n; i++) r->h[i] = a->h[i] + sign * b->h[i];
    return finite_or_error(L, r, sign > 0 ? "A + B" : "A - B");
}
static int l_add(lua_State *L) { return add_sub(L, 1.0); }
static int l_sub(lua_State *L) { return add_sub(L, -1.0); }

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

/* A located argument of any weight (lerp, mid), and an end that may be a point at infinity. */
#define A_VAL(nm) {.name = nm, .kind = PCL_VALUE, .flags = PCL_SAMEDIM, .expect = "a point or vector"}
#define A_PROJ(nm) {.name = nm, .kind = PCL_LOC, .flags = PCL_SAMEDIM, .expect = "a point (or a point at infinity)"}
static const pcl_arg more_val = {.kind = PCL_VALUE, .flags = PCL_SAMEDIM, .expect = "a point or vector"};
static const pcl_arg more_pt = {.kind = PCL_POINT, .flags = PCL_SAMEDIM};

static int out_of_range(lua_State *L, double t) {
    return pcl_fail(L, "the result is out of range (not finite) for t = %s", pcl_pushnum(L, t));
}

/* lerp(A, B, t) = (B - A) t + A (Fig. 1.1), for points, vectors or numbers. */
static const pcl_arg lerp_args[] = {A_VAL("A"), A_VAL("B"), A_NUM("t"), PCL_END};
static int l_lerp(lua_State *L) {
    pcl_value *a = topt(L, 1), *b = topt(L, 2);
    int isnum = lua_type(L, 3) == LUA_TNUMBER;          /* no string coercion, as in P() */
    double t = isnum ? lua_tonumber(L, 3) : 0;
    if (!(a && b && isnum && a->n == b->n && isfinite(t))) {     /* not the hot path */
        if (pcl_eq_hook(L, PCL_EQ_LERP)) return 1;
        pcl_val v[3] = {0};
        if (!a && !b && lua_type(L, 1) == LUA_TNUMBER && lua_type(L, 2) == LUA_TNUMBER) {
            pcl_readone(L, 3, 3, 0, &lerp_args[2], 0, &v[2]);
            double x = lua_tonumber(L, 1), y = lua_tonumber(L, 2), r = x * (1 - v[2].x) + y * v[2].x;
            if (!isfinite(r)) return out_of_range(L, v[2].x);
            return push_num(L, r);
        }
        PCL_READ(L, v);                                  /* the message, or two values and t */
        a = topt(L, 1), b = topt(L, 2), t = v[2].x;
    }
    int n = a->n;
    pcl_value *r = newpt(L, n);
    pc_lerp(n, a->h, b->h, t, r->h);     /* equal weights kept exactly (t = 1e16) */
    for (int i = 0; i <= n; i++)
        if (!isfinite(r->h[i])) return out_of_range(L, t);
    return 1;
}

static const pcl_arg t_arg[] = {A_NUM("t"), PCL_END};
static int l_bar(lua_State *L) {
    if (lua_type(L, 1) != LUA_TNUMBER && pcl_eq_hook(L, PCL_EQ_BAR)) return 1;
    pcl_val a[1] = {0};
    PCL_READ(L, a);
    return push_num(L, 1.0 - a[0].x);
}

/* mid(A, B, ...): the midpoint, or the centroid of several values. */
static const pcl_arg mid_args[] = {A_VAL("A"), A_VAL("B"), PCL_END};
static int l_mid(lua_State *L) {
    int m = lua_gettop(L);
    pcl_val a[2] = {0}, v;
    PCL_READ(L, a);
    int n = a[0].n;
    double s[PC_MAXDIM + 1];   /* each term divided first: mid(P(1e308, 0), P(1e308, 0)) is P(1e308, 0) */
    for (int i = 0; i <= n; i++) s[i] = a[0].v[i] / m + a[1].v[i] / m;
    for (int j = 3; j <= m; j++) {
        pcl_readone(L, j, j, 0, &more_val, n, &v);
        for (int i = 0; i <= n; i++) s[i] += v.v[i] / m;
    }
    pcl_value *r = newpt(L, n);
    fill(r, n, s, s[n]);
    return finite_or_error(L, r, pcl_name(L));
}

/* The hot path of dist, dot and cross: two values of one dimension whose weights are exactly
 * w (1: points, 0: vectors).  Anything else goes to the layer, which reads it by the one
 * weight rule or words the message. */
static int exact_pair(lua_State *L, double w, pcl_value **a, pcl_value **b) {
    *a = topt(L, 1), *b = topt(L, 2);
    return *a && *b && (*a)->n == (*b)->n && (*a)->h[(*a)->n] == w && (*b)->h[(*b)->n] == w;
}

/* dist(A, B) between points, or dist(v), the length of a vector.  The form follows the
 * first argument, so that dist(A, nil) names the missing argument #2. */
static const pcl_arg two_points[] = {A_SAMEPOINT("A"), A_SAMEPOINT("B"), PCL_END};
static const pcl_arg one_vector[] = {A_VECTOR("v", 0), PCL_END};
static int l_dist(lua_State *L) {
    pcl_value *p, *q;
    if (exact_pair(L, 1.0, &p, &q)) return push_num(L, pc_dist(p->n, p->h, q->h));
    pcl_val a[2] = {0};
    if (p && pc_kind_of(p->h[p->n]) == PC_KIND_VECTOR && lua_isnoneornil(L, 2)) {
        pcl_readone(L, 1, 1, 0, &one_vector[0], 0, &a[0]);
        return push_num(L, pc_norm(a[0].n, a[0].v));
    }
    PCL_READ(L, a);
    return push_num(L, pc_dist(a[0].n, a[0].v, a[1].v));
}

static const pcl_arg uv_args[] = {A_SAMEVECTOR("u"), A_SAMEVECTOR("v"), PCL_END};
static int l_dot(lua_State *L) {
    pcl_value *u, *v;
    if (exact_pair(L, 0.0, &u, &v)) return push_num(L, pc_dot(u->n, u->h, v->h));
    if ((!u || !v) && pcl_eq_hook(L, PCL_EQ_DOT)) return 1;
    pcl_val a[2] = {0};
    PCL_READ(L, a);
    return push_num(L, pc_dot(a[0].n, a[0].v, a[1].v));
}

/* cross(u, v): a vector in 3-D, the number u.x v.y - u.y v.x in 2-D. */
static int l_cross(lua_State *L) {
    if ((!topt(L, 1) || !topt(L, 2)) && pcl_eq_hook(L, PCL_EQ_CROSS)) return 1;
    pcl_val a[2] = {0};
    PCL_READ(L, a);
    double w[3];
    if (a[0].n == 2) {
        return push_num(L, pc_cross2(a[0].v, a[1].v));
    }
    if (a[0].n != 3) return pcl_fail(L, "vectors must be 2-D or 3-D, got %d-D", a[0].n);
    pc_cross3(a[0].v, a[1].v, w);
    push_w(L, 3, w, 0.0);
    return 1;
}

static int l_unit(lua_State *L) {
    if (!topt(L, 1) && pcl_eq_hook(L, PCL_EQ_UNIT)) return 1;
    pcl_val a[1] = {0};
    PCL_READ(L, a);
    double w[PC_MAXDIM];
    if (pc_unit(a[0].n, a[0].v, w) != PC_OK) return pcl_fail(L, "the zero vector has no direction");
    push_w(L, a[0].n, w, 0.0);
    return 1;
}

static int l_perp(lua_State *L) {
    pcl_val a[1] = {0};
    PCL_READ(L, a);
    double w[2];
    if (a[0].n != 2)
        return pcl_argfail(L, 1, "must be a 2-D vector, got %d-D (in space a perpendicular is not unique: use cross(u, v))", a[0].n);
    pc_perp2(a[0].v, w);
    push_w(L, 2, w, 0.0);
    return 1;
}

/* angle(A, B, C): the angle at A of triangle ABC; angle(u, v): between two vectors.
 * Unsigned, in radians, in [0, pi].  The form follows the first argument (a vector or not),
 * so that angle(A, B, nil) names the missing argument #3. */
static const pcl_arg three_points[] = {A_SAMEPOINT("A"), A_SAMEPOINT("B"), A_SAMEPOINT("C"), PCL_END};
static int l_angle(lua_State *L) {
    pcl_value *first = topt(L, 1);
    pcl_val a[3] = {0};
    double b[PC_MAXDIM], c[PC_MAXDIM], ang;
    if (first ? pc_kind_of(first->h[first->n]) == PC_KIND_VECTOR : lua_isnoneornil(L, 3)) {
        pcl_readone(L, 1, 1, 0, &uv_args[0], 0, &a[0]);
        pcl_readone(L, 2, 2, 0, &uv_args[1], a[0].n, &a[1]);
        memcpy(b, a[0].v, sizeof b);
        memcpy(c, a[1].v, sizeof c);
    } else {
        PCL_READ(L, a);
        for (int i = 0; i < a[0].n; i++) b[i] = a[1].v[i] - a[0].v[i], c[i] = a[2].v[i] - a[0].v[i];
    }
    if (pc_angle(a[0].n, b, c, &ang) != PC_OK) return pcl_fail(L, "a side has zero length, so the angle is undefined");
    return push_num(L, ang);
}

static const pcl_arg foot_args[] = {A_SAMEPOINT("C"), A_SAMEPOINT("A"), A_SAMEPOINT("B"), PCL_END};
static int l_foot(lua_State *L) {
    pcl_val a[3] = {0};
    PCL_READ(L, a);
    double h[PC_MAXDIM];
    if (pc_foot(a[0].n, a[0].v, a[1].v, a[2].v, h) != PC_OK) return pcl_fail(L, "A and B coincide, so they do not define a line");
    push_w(L, a[0].n, h, 1.0);
    return 1;
}

static const pcl_arg sigma_args[] = {A_SAMEPOINT("A"), A_SAMEPOINT("B"),
                                     {.name = "C", .kind = PCL_POINT, .flags = PCL_SAMEDIM | PCL_OPT}, PCL_END};
static int l_sigma(lua_State *L) {
    pcl_val a[3] = {0};
    PCL_READ(L, a);
    lua_pushnumber(L, pc_sigma(a[0].n, a[0].v, a[1].v, a[a[2].present ? 2 : 1].v));   /* Σ^A_BB = AB² */
    return 1;
}

/* ---- ratios -------------------------------------------------------------------------------- */

static int ratio_error(lua_State *L, int st) {
    switch (st) {
    case PC_ECOINCIDENT: return pcl_fail(L, "the points coincide, so the ratio is undefined");
    case PC_ENOTCOLLINEAR: return pcl_fail(L, "the points are not collinear");
    case PC_EZERO: return pcl_fail(L, "a point at infinity with a zero direction");
    default: return pcl_fail(L, "%s", pc_strerror(st));
    }
}

/* sr(X, Y, Z) = (X - Z)/(Z - Y): Z divides XY in this ratio.  math.huge when Z = Y; -1 when Z
 * is the improper point of the line. */
static const pcl_arg sr_args[] = {A_SAMEPOINT("X"), A_SAMEPOINT("Y"), A_PROJ("Z"), PCL_END};
static int l_sr(lua_State *L) {
    pcl_val a[3] = {0};
    PCL_READ(L, a);
    double lam;
    int st = pc_sr(a[0].n, a[0].v, a[1].v, a[2].v, &lam);
    if (st != PC_OK) return ratio_error(L, st);
    return push_num(L, lam);
}

/* divide(X, Y, lambda) = (X + lambda Y)/(1 + lambda); lambda = -1 gives the improper point,
 * math.huge gives Y. */
static const pcl_arg divide_args[] = {A_SAMEPOINT("X"), A_SAMEPOINT("Y"), {.name = "lambda", .kind = PCL_NUMBER, .flags = PCL_INF, .expect = "a number (not NaN)"}, PCL_END};
static int l_divide(lua_State *L) {
    pcl_val a[3] = {0};
    PCL_READ(L, a);
    int n = a[0].n;
    double out[PC_MAXDIM + 1];
    if (pc_divide(n, a[0].v, a[1].v, a[2].x, out) == PC_ENONFINITE)
        return pcl_fail(L, "the point is out of range (not finite) for lambda = %s", pcl_pushnum(L, a[2].x));
    push_h(L, n, out);
    return 1;
}

static const pcl_arg harmonic_args[] = {A_SAMEPOINT("A"), A_SAMEPOINT("B"), A_PROJ("T"), PCL_END};
static int l_harmonic(lua_State *L) {
    pcl_val a[3] = {0};
    PCL_READ(L, a);
    double out[PC_MAXDIM + 1];
    int st = pc_harmonic(a[0].n, a[0].v, a[1].v, a[2].v, out);
    if (st != PC_OK && st != PC_IMPROPER) return ratio_error(L, st);
    push_h(L, a[0].n, out);
    return 1;
}

static const pcl_arg cross_ratio_args[] = {A_SAMEPOINT("A"), A_SAMEPOINT("B"), A_PROJ("C"), A_PROJ("D"), PCL_END};
static int l_cross_ratio(lua_State *L) {
    pcl_val a[4] = {0};
    PCL_READ(L, a);
    double r;
    int st = pc_cross_ratio(a[0].n, a[0].v, a[1].v, a[2].v, a[3].v, &r);
    if (st != PC_OK) return ratio_error(L, st);
    return push_num(L, r);
}

/* ---- incidence and measure ---------------------------------------------------------------- */

/* meet(A1, A2, B1, B2) -> K, lambda, mu with K = A1 + (A2 - A1) lambda = B1 + (B2 - B1) mu.
 * An end may be a point at infinity (a direction, weight 0), as in the book's homogeneous
 * meet: a point P and a direction D (either order) give the line through P along D, with
 * K = P + D lambda; two directions give the line at infinity (of their plane).
 * Parallel lines: their common improper point (the direction of the first line, weight 0),
 * math.huge, math.huge; likewise a line and a line at infinity.  Skew lines (3-D and up): nil
 * and the distance between them (math.huge for a line that misses a line at infinity). */
static const pcl_arg meet_args[] = {A_PROJ("A1"), A_PROJ("A2"), A_PROJ("B1"), A_PROJ("B2"), PCL_END};
static int l_meet(lua_State *L) {
    if (!(topt(L, 1) && topt(L, 2) && topt(L, 3) && topt(L, 4)) && pcl_eq_hook(L, PCL_EQ_MEET)) return 3;
    pcl_val a[4] = {0};
    PCL_READ(L, a);
    int n = a[0].n;
    for (int k = 0; k < 4; k++)
        if (a[k].v[n] == 0 && pc_norm(n, a[k].v) == 0)
            return pcl_argfail(L, k + 1, "is the zero vector %s, which has no direction, so it is no point at infinity",
                               push_value_text(L, topt(L, k + 1)));
    double out[PC_MAXDIM + 1], lam, mu, res;
    int st = pc_meet_h(n, a[0].v, a[1].v, a[2].v, a[3].v, out, &lam, &mu, &res);
    switch (st) {
    case PC_OK:
    case PC_IMPROPER:
        push_h(L, n, out);
        lua_pushnumber(L, lam);
        lua_pushnumber(L, mu);
        return 3;
    case PC_ESKEW:
        lua_pushnil(L);
        lua_pushnumber(L, res);
        return 2;
    case PC_ESAME_LINE:
        return pcl_fail(L, "the two lines coincide, so they have no single meet");
    case PC_ECOINCIDENT: {
        /* which line: the meet of line A with itself fails the same way only if A is bad */
        int bad_a = pc_meet_h(n, a[0].v, a[1].v, a[0].v, a[1].v, out, NULL, NULL, NULL) == st;
        const char *names = bad_a ? "A1 and A2" : "B1 and B2";
        if (a[bad_a ? 0 : 2].v[n] == 0)
            return pcl_fail(L, "%s are the same point at infinity (parallel directions), so they do not define a line", names);
        return pcl_fail(L, "%s coincide, so they do not define a line", names);
    }
    case PC_EDIM:
        return pcl_fail(L, "lines in 1-D all coincide; meet needs 2-D or more");
    }
    return pcl_fail(L, "%s", pc_strerror(st));
}

/* area(A, B, C): signed in 2-D (counter-clockwise positive), unsigned in any dimension;
 * area(A, B, C, D, ...) in 2-D: the signed area of the polygon. */
static int l_area(lua_State *L) {
    int m = lua_gettop(L);
    pcl_val a[3] = {0}, d;
    PCL_READ(L, a);
    int n = a[0].n;
    if (n < 2) return pcl_fail(L, "points must be 2-D or more, got 1-D");
    if (n > 2 && m > 3) return pcl_fail(L, "a polygon area needs 2-D points; in %d-D give a triangle", n);
    if (n > 2) {
        return push_num(L, pc_area(n, a[0].v, a[1].v, a[2].v));
    }
    double s = pc_area2(a[0].v, a[1].v, a[2].v), prev[2] = {a[2].v[0], a[2].v[1]};
    for (int j = 4; j <= m; j++) {
        pcl_readone(L, j, j, 0, &more_pt, 2, &d);
        s += pc_area2(a[0].v, prev, d.v);
        prev[0] = d.v[0], prev[1] = d.v[1];
    }
    return push_num(L, s);
}

/* volume(A, B, C, D): signed in 3-D (positive when B - A, C - A, D - A are right-handed),
 * unsigned in 4-D and up. */
static const pcl_arg four_points[] = {A_SAMEPOINT("A"), A_SAMEPOINT("B"), A_SAMEPOINT("C"), A_SAMEPOINT("D"), PCL_END};
static int l_volume(lua_State *L) {
    pcl_val a[4] = {0};
    PCL_READ(L, a);
    int n = a[0].n;
    if (n < 3) return pcl_fail(L, "points must be 3-D or more, got %d-D", n);
    double v[4 * PC_MAXDIM];
    for (int j = 0; j < 4; j++) memcpy(v + j * n, a[j].v, sizeof(double) * (size_t)n);
    return push_num(L, n == 3 ? pc_volume3(v, v + 3, v + 6, v + 9) : pc_measure(n, 3, v));
}

/* ---- weights -------------------------------------------------------------------------------- */

static const pcl_arg any_value[] = {{.name = "p", .kind = PCL_VALUE, .expect = "a point or vector"}, PCL_END};
static int l_normalize(lua_State *L) {
    pcl_val a[1] = {0};
    PCL_READ(L, a);
    double out[PC_MAXDIM + 1];
    if (pc_normalize(a[0].n, a[0].v, out) != PC_OK)
        return pcl_fail(L, "%s has weight 0 (a vector, or a point at infinity), so it has no finite location",
                        push_value_text(L, topt(L, 1)));
    push_h(L, a[0].n, out);
    return 1;
}

static int l_weight(lua_State *L) {
    pcl_val a[1] = {0};
    PCL_READ(L, a);
    return push_num(L, a[0].v[a[0].n]);
}

/* coords(p) -> x, y, ...: the coordinates of a point or the components of a vector. */
static const pcl_arg one_loc[] = {{.name = "p", .kind = PCL_LOC}, PCL_END};
static int l_coords(lua_State *L) {
    pcl_val a[1] = {0};
    PCL_READ(L, a);
    luaL_checkstack(L, a[0].n, "too many coordinates");
    for (int i = 0; i < a[0].n; i++) lua_pushnumber(L, a[0].v[i]);
    return a[0].n;
}

/* near(a, b [, eps]): numbers, or values of one dimension, equal within eps (default 1e-9)
 * relative to their size (at least 1). */
#define NUM_OR_VALUE "a number, point or vector"
static const pcl_arg near_args[] = {A_ANY("a", NULL, NUM_OR_VALUE), A_ANY("b", NULL, NUM_OR_VALUE),
                                    {.name = "eps", .kind = PCL_NUMBER, .flags = PCL_OPT | PCL_RANGE, .lo = 0, .hi = HUGE_VAL,
                                     .dflt = 1e-9, .expect = "a non-negative number"}, PCL_END};
static const pcl_arg near_value = {.kind = PCL_VALUE, .flags = PCL_SAMEDIM, .expect = NUM_OR_VALUE};
static int l_near(lua_State *L) {
    pcl_val a[3] = {0}, p, q;
    PCL_READ(L, a);
    double eps = a[2].x;
    if (lua_type(L, 1) == LUA_TNUMBER && lua_type(L, 2) == LUA_TNUMBER) {
        double x = lua_tonumber(L, 1), y = lua_tonumber(L, 2);
        lua_pushboolean(L, fabs(x - y) <= eps * fmax(1.0, fmax(fabs(x), fabs(y))));
        return 1;
    }
    pcl_readone(L, 1, 1, 0, &near_value, 0, &p);
    pcl_readone(L, 2, 2, 0, &near_value, p.n, &q);
    double scale = 1, d = 0;
    for (int i = 0; i <= p.n; i++) {
        scale = fmax(scale, fmax(fabs(p.v[i]), fabs(q.v[i])));
        d = fmax(d, fabs(p.v[i] - q.v[i]));
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

static const pcl_fn fns[] = {
    {.name = "P", .fn = l_P, .sig = "P(x, y [, z, ...]) -> point", .help = "A point (weight 1) of any dimension from 1 up: P(1, 2), P(0, 0, 1)."},
    {.name = "V", .fn = l_V, .sig = "V(x, y [, z, ...]) -> vector", .help = "A vector (weight 0), as the difference of two points is: V(0, 1)."},
    PCL_FN("lerp", l_lerp, lerp_args, "value", "(B - A)t + A, the point of line AB with parameter t (t = 0 gives A, t = 1 gives B); also for vectors and numbers."),
    PCL_FN("bar", l_bar, t_arg, "number", "The complement 1 - t (the book's t with a bar), as in A*bar(t) + B*t."),
    {.name = "mid", .fn = l_mid, .args = mid_args, .sig = "mid(A, B, ...) -> value", .help = "The midpoint of two values, or the centroid of several."},
    {.name = "dist", .fn = l_dist, .args = two_points, .sig = "dist(A, B) | dist(v) -> number", .help = "The distance between two points, or the length of a vector."},
    PCL_FN("dot", l_dot, uv_args, "number", "The scalar product of two vectors."),
    PCL_FN("cross", l_cross, uv_args, "vector | number", "The cross product: a vector in 3-D, the number u.x v.y - u.y v.x in 2-D."),
    PCL_FN("unit", l_unit, one_vector, "vector", "The vector v scaled to length 1; the zero vector is an error."),
    PCL_FN("perp", l_perp, one_vector, "vector", "The 2-D vector v turned by +90 degrees: V(-v.y, v.x)."),
    {.name = "angle", .fn = l_angle, .args = three_points, .sig = "angle(A, B, C) | angle(u, v) -> number",
     .help = "The angle at A of triangle ABC, or between two vectors: unsigned, in radians, 0..pi."},
    PCL_FN("foot", l_foot, foot_args, "point", "The foot of the perpendicular from C to line AB."),
    PCL_FN("Sigma", l_sigma, sigma_args, "number", "The metric operator (B - A).(C - A) of three points; Sigma(A, B) is the squared distance AB^2."),
    PCL_FN("sr", l_sr, sr_args, "number", "The simple ratio (XYZ) = (X - Z)/(Z - Y) in which Z divides XY; math.huge when Z = Y, -1 for the point at infinity."),
    PCL_FN("divide", l_divide, divide_args, "point", "The point Z with (XYZ) = lambda: (X + lambda Y)/(1 + lambda); lambda = -1 gives the point at infinity of XY."),
    PCL_FN("harmonic", l_harmonic, harmonic_args, "point", "The harmonic conjugate N of T with respect to A, B: (ABN) = -(ABT); the midpoint gives the point at infinity."),
    PCL_FN("cross_ratio", l_cross_ratio, cross_ratio_args, "number", "The cross ratio (ABCD) = (ABC)/(ABD) of four collinear points (C, D may be points at infinity)."),
    PCL_FN("meet", l_meet, meet_args, "K, lambda, mu", "The intersection K = A1 + (A2 - A1)lambda = B1 + (B2 - B1)mu of two lines, any dimension; an end may be a point at infinity (a vector: the line's direction); parallel lines give their direction (weight 0), skew ones nil and their distance. With point equations among the ends (param \"u\") K, lambda and mu are equations with exact derivatives, so a scheme of meets compiles with curve()."),
    {.name = "area", .fn = l_area, .args = three_points, .sig = "area(A, B, C) | area(A, B, C, D, ...) -> number",
     .help = "The area of a triangle (signed in 2-D, counter-clockwise positive) or of a 2-D polygon."},
    PCL_FN("volume", l_volume, four_points, "number", "The volume of a tetrahedron: signed in 3-D (positive when right-handed), unsigned in 4-D and up."),
    PCL_FN("normalize", l_normalize, any_value, "point", "Divide a weighted value by its weight (projective normalisation); weight 0 is an error."),
    PCL_FN("weight", l_weight, any_value, "number", "The weight of a value: 1 for a point, 0 for a vector, k for k*A."),
    PCL_FN("coords", l_coords, one_loc, "x, y, ...", "The coordinates of a point or the components of a vector, as numbers."),
    PCL_FN("near", l_near, near_args, "boolean", "Numbers, or values of one dimension, equal within eps (default 1e-9) relative to their size."),
    PCL_END};

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
    lua_pushboolean(L, 0);                             /* upvalue 1: no declaration */
    lua_pushvalue(L, mt);
    luaL_setfuncs(L, point_meta, 2);                   /* metamethods, upvalue 2 = mt */

    lua_pushvalue(L, mt);                              /* functions, upvalue 2 = mt */
    pcl_register(L, module, fns, 1);

    lua_newtable(L);                                   /* methods for p:name(...) */
    int methods = lua_gettop(L);
    for (const char *const *m = method_names; *m; m++) {
        lua_getfield(L, module, *m);
        lua_setfield(L, methods, *m);
    }
    lua_pushboolean(L, 0);
    lua_pushvalue(L, mt);
    lua_pushvalue(L, methods);
    lua_pushcclosure(L, l_index, 3);
    lua_setfield(L, mt, "__index");
    lua_settop(L, module);
}
