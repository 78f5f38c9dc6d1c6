/* Binding of the point calculus values (stdlib/geom/point.h, point_fn.h): P V, the operators,
 * and the functions of the registration table below.
 *
 * A value is a full userdata of variable size (header + n+1 doubles).  Every C function here
 * has the point metatable as upvalue 2 (upvalue 1 is a declared function's declaration), so
 * recognising a point is a pointer comparison, never a registry lookup by name; the hot paths
 * (P, lerp, + - * /, .x) allocate exactly one userdata and read nothing twice: the layer reads
 * the arguments again only to word an error. */
#include "pcl_args.h"
#include "pcl_point.h"
#include "pcl_core.h"
#include "pcl_expr.h"   /* equations take over when an operand is one (l_expr.c) */
#include "point_fn.h"

#define MSG_SIZE (PC_MAXDIM * 48 + 400)             /* a message of point_fn.h */
static const char POINT_MT_KEY = 'p';       /* registry key (its address) of the metatable */
#define MT lua_upvalueindex(2)
#define METHODS lua_upvalueindex(3)         /* metamethods: the method table (__index) */

/* ---- recognising and making values ------------------------------------------------------- */

/* p if it is NULL or a genuine value: its block exactly its header and n + 1 doubles, n =
 * 1..PC_MAXDIM (a userdata given the point metatable by the debug library has another size). */
static inline pcl_value *genuine(lua_State *L, int idx, pcl_value *p) {
    size_t len = p ? lua_rawlen(L, idx) : 0;
    if (p && !(len >= sizeof(pcl_value) && p->n >= 1 && p->n <= PC_MAXDIM &&
               len == sizeof(pcl_value) + (size_t)(p->n + 1) * sizeof(double)))
        pcl_genuine(L, idx, p, 0, "point");
    return p;
}

static inline pcl_value *topt(lua_State *L, int idx) { return genuine(L, idx, pcl_testudata(L, idx, MT)); }

/* a new value of dimension n with the metatable at index mt */
static inline pcl_value *alloc(lua_State *L, int n, int mt) {
    pcl_value *p = lua_newuserdatauv(L, sizeof(pcl_value) + (size_t)(n + 1) * sizeof(double), 0);
    p->n = n;
    lua_pushvalue(L, mt);
    lua_setmetatable(L, -2);
    return p;
}
#define newpt(L, n) alloc((L), (n), MT)

pcl_value *pcl_tovalue(lua_State *L, int idx) {
    idx = lua_absindex(L, idx);
    lua_rawgetp(L, LUA_REGISTRYINDEX, &POINT_MT_KEY);
    pcl_value *p = pcl_testudata(L, idx, lua_gettop(L));
    lua_pop(L, 1);
    return genuine(L, idx, p);
}

pcl_value *pcl_newvalue(lua_State *L, int n) {
    lua_rawgetp(L, LUA_REGISTRYINDEX, &POINT_MT_KEY);
    pcl_value *p = alloc(L, n, lua_gettop(L));
    lua_remove(L, -2);
    return p;
}

/* "FNAME: argument #N", or "FNAME: self" for the receiver of a method call */
static const char *argctx(lua_State *L, int arg) {
    int shown = pcl_arg_shown(L, arg);
    return lua_pushfstring(L, shown ? "%s: argument #%d" : "%s: self", pcl_fname(L), shown);
}

/* a new value of dimension n: the n coordinates x and the weight w (r: made by the caller) */
static void fill(pcl_value *r, int n, const double *x, double w) {
    memcpy(r->h, x, sizeof(double) * (size_t)n);
    r->h[n] = w;
}
void pcl_pushpoint(lua_State *L, int n, const double *x) { fill(pcl_newvalue(L, n), n, x, 1.0); }
void pcl_pushvector(lua_State *L, int n, const double *x) { fill(pcl_newvalue(L, n), n, x, 0.0); }

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

/* P(...) and V(...): the weight is the op of the registration table (upvalue 2) */
static int l_make(lua_State *L) {
    double weight = (double)lua_tointeger(L, PCL_UPVALUE(2));
    int n = lua_gettop(L), table = n == 1 && lua_type(L, 1) == LUA_TTABLE;   /* P{1, 2} */
    if (table) n = (int)lua_rawlen(L, 1);
    for (int i = 0; !table && i < n; i++)       /* an equation among the coordinates: P of it */
        if (lua_type(L, i + 1) != LUA_TNUMBER && pcl_eq_hook(L, weight == 1.0 ? PC_EQV_P : PC_EQV_V)) return 1;
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

/* An operand as the operators' messages show it: a value, a number, or another thing by its type */
static pc_operand operand(lua_State *L, int idx) {
    pcl_value *p = topt(L, idx);
    int isnum = lua_type(L, idx) == LUA_TNUMBER;
    const char *type = luaL_getmetafield(L, idx, "__name") == LUA_TSTRING ? lua_tostring(L, -1) : luaL_typename(L, idx);
    const char *what = p ? "a point" : isnum ? "a number" : lua_pushfstring(L, "a %s", type);
    return (pc_operand){p ? p->n : 0, p ? p->h : NULL, isnum, lua_tonumber(L, idx), what};
}

/* A + B, A - B, k*A, A*k, A/k and -A: weights add, so a point plus a vector is a point; u/v of
 * two parallel vectors is the number r with u = r v ((2.62)'s (T - A)/(T_C - A)). */
static inline int arith(lua_State *L, int op, pc_expr_verb hook) {
    pcl_value *a = topt(L, 1), *b = op == 'u' ? NULL : topt(L, 2), *p = a ? a : b;
    int fits, knum = lua_type(L, a ? 2 : 1) == LUA_TNUMBER;   /* the k of k*A, A*k, A/k */
    if (op == '+' || op == '-' || (op == '/' && b)) fits = a && b && a->n == b->n;
    else if (op == 'u') fits = a != NULL;
    else fits = (op == '*' ? p != NULL : a && !b) && !(a && b) && knum;
    if (fits && op == '/' && b) {
        double r;
        if (pc_value_ratio(a->n, a->h, b->h, &r) == PC_OK) return push_num(L, r);
    } else if (fits) {
        pcl_value *r = newpt(L, p->n);
        if (pc_value_arith(op, p->n, p->h, b ? b->h : NULL, lua_tonumber(L, a ? 2 : 1), r->h) == PC_OK) return 1;
    } else if (pcl_eq_hook(L, hook)) {
        return 1;
    }
    char msg[MSG_SIZE];
    pc_operand l = operand(L, 1), r = operand(L, 2);
    pc_arith_text(op, &l, &r, msg, sizeof msg);
    return pcl_error(L, "%s", msg);
}

static int l_add(lua_State *L) { return arith(L, '+', PC_EQV_ADD); }
static int l_sub(lua_State *L) { return arith(L, '-', PC_EQV_SUB); }
static int l_mul(lua_State *L) { return arith(L, '*', PC_EQV_MUL); }
static int l_div(lua_State *L) { return arith(L, '/', PC_EQV_DIV); }
static int l_unm(lua_State *L) { return arith(L, 'u', PC_EQV_NEG); }

static int l_eq(lua_State *L) {
    pcl_value *a = topt(L, 1), *b = topt(L, 2);
    return pcl_push_results(L, 0, "b", a && b && pc_value_same(a->n, a->h, b->n, b->h));
}

static int l_len(lua_State *L) {   /* only the VM calls it */
    pcl_value *p = pcl_meta_self(L, genuine(L, 1, lua_touserdata(L, 1)), "#: not a point");
    return pcl_push_results(L, 0, "i", p->n);
}

static int l_tostring(lua_State *L) {
    pcl_value *p = pcl_meta_self(L, topt(L, 1), "tostring: not a point");
    char s[PC_MAXDIM * 24 + 32];
    pc_value_text(p->n, p->h, s, sizeof s);
    return pcl_push_results(L, 0, "s", s);
}

int pcl_concat(lua_State *L) {
    luaL_tolstring(L, 1, NULL);
    luaL_tolstring(L, 2, NULL);
    lua_concat(L, 2);
    return 1;
}

/* coordinate i (0-based) of p as a location or vector component; key the field (NULL: p[i]) */
static inline int push_coord(lua_State *L, pcl_value *p, int i, const char *key) {
    double x;
    if (pc_coord(p->n, p->h, i, &x) == PC_OK) return push_num(L, x);
    char msg[MSG_SIZE];
    pc_coord_text(p->n, p->h, i, key, msg, sizeof msg);
    return pcl_error(L, "%s", msg);
}

/* __index: .x .y .z (coordinates), .w (the weight), p[i], then the methods.  Only the VM calls
 * it (the metatable is protected by __metatable), always with a point as argument 1. */
static int l_index(lua_State *L) {
    /* the VM calls it for any userdata with this metatable, a forged one too */
    pcl_value *p = pcl_meta_self(L, genuine(L, 1, lua_touserdata(L, 1)), "index: not a point");
    size_t len = 0;
    const char *k = lua_type(L, 2) == LUA_TSTRING ? lua_tolstring(L, 2, &len) : NULL;
    lua_Integer i = lua_type(L, 2) == LUA_TNUMBER ? lua_tointeger(L, 2) : 0;   /* 0: not integral */
    if (len == 1 && k[0] >= 'x' && k[0] <= 'z') return push_coord(L, p, k[0] - 'x', k);
    if (len == 1 && k[0] == 'w') return push_num(L, p->h[p->n]);          /* the weight */
    if (i >= 1 && i <= p->n) return push_coord(L, p, (int)i - 1, NULL);
    lua_rawget(L, METHODS);                                 /* a method, or nil: key on the top */
    return 1;
}

static int l_newindex(lua_State *L) {
    return pcl_error(L, "points are immutable: make a new one instead, e.g. P(x, p.y)");
}

/* ---- functions ------------------------------------------------------------------------------ */

/* A located argument of any weight (lerp, mid), and an end that may be a point at infinity. */
#define A_VAL(nm) {.name = nm, .kind = PCL_VALUE, .flags = PCL_SAMEDIM, .expect = "a point or vector"}
#define A_PROJ(nm) {.name = nm, .kind = PCL_LOC, .flags = PCL_SAMEDIM, .expect = "a point (or a point at infinity)"}
static const pcl_arg more_val = {.kind = PCL_VALUE, .flags = PCL_SAMEDIM, .expect = "a point or vector"};
static const pcl_arg more_pt = {.kind = PCL_POINT, .flags = PCL_SAMEDIM};

/* The core's point function op of the read arguments a (an absent one repeats the one before:
 * Sigma(A, B) is Sigma(A, B, B)): its results (meet: K, lambda, mu) pushed, or its error. */
static int finish(lua_State *L, int op, const pcl_val *a) {
    const double *v[4] = {a[0].v, a[1].v, a[2].v, a[3].v};
    for (int k = 1; k < 4; k++)
        if (!a[k].present) v[k] = v[k - 1];
    double out[PC_MAXDIM + 3];
    int value, n = a[0].n, st = pc_point_fn(op, n, v, a[2].x, out, &value);
    if (st == PC_ESKEW) {                               /* meet: skew lines, nil and their distance */
        lua_pushnil(L);
        return 1 + push_num(L, out[0]);
    }
    if (st != PC_OK && st != PC_IMPROPER) {
        char msg[MSG_SIZE];
        int k = pc_point_fn_text(op, st, n, v, a[2].x, msg, sizeof msg);
        return k ? pcl_argfail(L, k, "%s", msg) : pcl_fail(L, "%s", msg);
    }
    return pcl_push_packed(L, n, !value ? "n" : op == PC_FN_MEET ? "w n n" : "w", out);
}

/* The core's function op of the declared arguments, after the equations' hook (NOHOOK: none)
 * when an argument is not a point. */
#define NOHOOK (-1)
static int run(lua_State *L, int op, int hook) {
    int k = 1, m = lua_gettop(L);
    while (hook != NOHOOK && k <= m && topt(L, k)) k++;
    if (hook != NOHOOK && k <= m && pcl_eq_hook(L, hook)) return op == PC_FN_MEET ? 3 : 1;
    pcl_val a[4] = {0};
    PCL_READ(L, a);
    return finish(L, op, a);
}

/* An overload's other form: its m arguments args read one by one, in one dimension, then op */
static int other_form(lua_State *L, int op, int m, const pcl_arg *args) {
    pcl_val a[4] = {0};
    for (int k = 0; k < m; k++) pcl_readone(L, k + 1, k + 1, 0, &args[k], a[0].n, &a[k]);
    return finish(L, op, a);
}

/* The functions of pc_point_fn's one entry: the op and the hook are upvalues 2 and 3. */
static int l_fn(lua_State *L) {
    return run(L, (int)lua_tointeger(L, PCL_UPVALUE(2)), (int)lua_tointeger(L, PCL_UPVALUE(3)));
}

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
        if (pcl_eq_hook(L, PC_EQV_LERP)) return 1;
        pcl_val v[3] = {0};
        if (!a && !b && lua_type(L, 1) == LUA_TNUMBER && lua_type(L, 2) == LUA_TNUMBER) {
            pcl_readone(L, 3, 3, 0, &lerp_args[2], 0, &v[2]);
            double x[2] = {lua_tonumber(L, 1), 1}, y[2] = {lua_tonumber(L, 2), 1}, r[2];
            return pc_lerp(1, x, y, v[2].x, r) == PC_OK ? push_num(L, r[0]) : out_of_range(L, v[2].x);
        }
        PCL_READ(L, v);                                  /* the message, or two values and t */
        a = topt(L, 1), b = topt(L, 2), t = v[2].x;
    }
    pcl_value *r = newpt(L, a->n);
    return pc_lerp(a->n, a->h, b->h, t, r->h) == PC_OK ? 1 : out_of_range(L, t);   /* equal weights kept exactly */
}

static const pcl_arg t_arg[] = {A_NUM("t"), PCL_END};
static int l_bar(lua_State *L) {
    if (lua_type(L, 1) != LUA_TNUMBER && pcl_eq_hook(L, PC_EQV_BAR)) return 1;
    pcl_val a[1] = {0};
    PCL_READ(L, a);
    return push_num(L, 1.0 - a[0].x);
}

/* mid(A, B, ...): the midpoint, or the centroid of several values. */
static const pcl_arg mid_args[] = {A_VAL("A"), A_VAL("B"), PCL_END};
PCL_BODY(l_mid, a) {
    int m = lua_gettop(L), n = a[0].n;
    double s[PC_MAXDIM + 1];   /* each term divided first: mid(P(1e308, 0), P(1e308, 0)) is P(1e308, 0) */
    for (int i = 0; i <= n; i++) s[i] = a[0].v[i] / m;
    for (int j = 2; j <= m; j++) {                         /* a[1]: argument #j */
        if (j > 2) pcl_readone(L, j, j, 0, &more_val, n, &a[1]);
        for (int i = 0; i <= n; i++) s[i] += a[1].v[i] / m;
    }
    for (int i = 0; i <= n; i++)
        if (!isfinite(s[i]))
            return pcl_error(L, "%s: the result is out of range (not finite: a coordinate overflowed)", pcl_name(L));
    return pcl_push_packed(L, n, "w", s);
}

/* The hot path of dist and dot: two values of one dimension whose weights are exactly w (1:
 * points, 0: vectors).  Anything else goes to the layer, which reads it by the one weight rule
 * or words the message. */
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
    if (p && pc_kind_of(p->h[p->n]) == PC_KIND_VECTOR && lua_isnoneornil(L, 2))
        return other_form(L, PC_FN_NORM, 1, one_vector);
    return run(L, PC_FN_DIST, NOHOOK);
}

static const pcl_arg uv_args[] = {A_SAMEVECTOR("u"), A_SAMEVECTOR("v"), PCL_END};
static int l_dot(lua_State *L) {
    pcl_value *u, *v;
    if (exact_pair(L, 0.0, &u, &v)) return push_num(L, pc_dot(u->n, u->h, v->h));
    return run(L, PC_FN_DOT, PC_EQV_DOT);
}

/* angle(A, B, C): the angle at A of triangle ABC; angle(u, v): between two vectors.  The form
 * follows the first argument (a vector or not), so that angle(A, B, nil) names argument #3. */
static const pcl_arg three_points[] = {A_SAMEPOINT("A"), A_SAMEPOINT("B"), A_SAMEPOINT("C"), PCL_END};
static int l_angle(lua_State *L) {
    pcl_value *first = topt(L, 1);
    if (first ? pc_kind_of(first->h[first->n]) == PC_KIND_VECTOR : lua_isnoneornil(L, 3))
        return other_form(L, PC_FN_ANGLE_UV, 2, uv_args);
    return run(L, PC_FN_ANGLE, NOHOOK);
}

static const pcl_arg foot_args[] = {A_SAMEPOINT("C"), A_SAMEPOINT("A"), A_SAMEPOINT("B"), PCL_END};
static const pcl_arg sigma_args[] = {A_SAMEPOINT("A"), A_SAMEPOINT("B"),
                                     {.name = "C", .kind = PCL_POINT, .flags = PCL_SAMEDIM | PCL_OPT}, PCL_END};
static const pcl_arg sr_args[] = {A_SAMEPOINT("X"), A_SAMEPOINT("Y"), A_PROJ("Z"), PCL_END};
static const pcl_arg divide_args[] = {A_SAMEPOINT("X"), A_SAMEPOINT("Y"), {.name = "lambda", .kind = PCL_NUMBER, .flags = PCL_INF, .expect = "a number (not NaN)"}, PCL_END};
static const pcl_arg harmonic_args[] = {A_SAMEPOINT("A"), A_SAMEPOINT("B"), A_PROJ("T"), PCL_END};
static const pcl_arg cross_ratio_args[] = {A_SAMEPOINT("A"), A_SAMEPOINT("B"), A_PROJ("C"), A_PROJ("D"), PCL_END};
static const pcl_arg meet_args[] = {A_PROJ("A1"), A_PROJ("A2"), A_PROJ("B1"), A_PROJ("B2"), PCL_END};
static const pcl_arg four_points[] = {A_SAMEPOINT("A"), A_SAMEPOINT("B"), A_SAMEPOINT("C"), A_SAMEPOINT("D"), PCL_END};
static const pcl_arg any_value[] = {{.name = "p", .kind = PCL_VALUE, .expect = "a point or vector"}, PCL_END};

/* area(A, B, C): signed in 2-D (counter-clockwise positive), unsigned in any dimension;
 * area(A, B, C, D, ...) in 2-D: the signed area of the polygon. */
PCL_BODY(l_area, a) {
    int m = lua_gettop(L), n = a[0].n;
    pcl_val d;
    if (n < 2) return pcl_fail(L, "points must be 2-D or more, got 1-D");
    if (n > 2 && m > 3) return pcl_fail(L, "a polygon area needs 2-D points; in %d-D give a triangle", n);
    if (n > 2) return push_num(L, pc_area(n, a[0].v, a[1].v, a[2].v));
    double s = pc_area2(a[0].v, a[1].v, a[2].v);
    for (int j = 4; j <= m; j++, a[2] = d) {              /* a[2]: the vertex before d */
        pcl_readone(L, j, j, 0, &more_pt, 2, &d);
        s += pc_area2(a[0].v, a[2].v, d.v);
    }
    return push_num(L, s);
}

/* coords(p) -> x, y, ...: the coordinates of a point or the components of a vector. */
static const pcl_arg one_loc[] = {{.name = "p", .kind = PCL_LOC}, PCL_END};
PCL_BODY(l_coords, a) {
    return pcl_push_packed(L, a[0].n, "x", a[0].v);   /* n <= LUA_MINSTACK */
}

/* near(a, b [, eps]): numbers, or values of one dimension, equal within eps (default 1e-9)
 * relative to their size (at least 1). */
#define NUM_OR_VALUE "a number, point or vector"
static const pcl_arg near_args[] = {A_ANY("a", NULL, NUM_OR_VALUE), A_ANY("b", NULL, NUM_OR_VALUE),
                                    {.name = "eps", .kind = PCL_NUMBER, .flags = PCL_OPT | PCL_RANGE, .lo = 0, .hi = HUGE_VAL,
                                     .dflt = 1e-9, .expect = "a non-negative number"}, PCL_END};
static const pcl_arg near_value = {.kind = PCL_VALUE, .flags = PCL_SAMEDIM, .expect = NUM_OR_VALUE};
PCL_BODY(l_near, a) {
    pcl_val p = {0}, q = {0};
    if (lua_type(L, 1) == LUA_TNUMBER && lua_type(L, 2) == LUA_TNUMBER) {
        p.v[0] = lua_tonumber(L, 1);
        q.v[0] = lua_tonumber(L, 2);
    } else {
        pcl_readone(L, 1, 1, 0, &near_value, 0, &p);
        pcl_readone(L, 2, 2, 0, &near_value, p.n, &q);
    }
    return pcl_push_results(L, 0, "b", pc_near(p.n, p.v, q.v, a[2].x));
}

/* ---- the drawing layer's hook --------------------------------------------------------------- */

int pcl_topoint2(lua_State *L, int idx, double *x, double *y) {
    idx = lua_absindex(L, idx);
    pcl_value *p = pcl_tovalue(L, idx);
    if (!p) return 0;
    double xy[2];
    char msg[MSG_SIZE];
    /* with a camera set, drawing takes its points (3-D) and draws their images */
    int st = pc_drawn(p->n, p->h, p->n == 2 ? PC_OK : pcl_project(L, p->n, p->h, &xy[0], &xy[1]), xy);
    if (st != PC_OK && pc_drawn_text(argctx(L, idx), st, p->n, p->h, msg, sizeof msg)) return pcl_error(L, "%s", msg);
    *x = xy[0];
    *y = xy[1];
    return 1;
}

/* ---- registration --------------------------------------------------------------------------- */

/* The registration table: a declaration (each ended, to register alone with its upvalues), the
 * op and hook of l_fn, and whether it is also a method p:name(). */
#define OP(nm, args, res, op, hook, method, text) {{PCL_FN(nm, l_fn, args, res, text)}, op, hook, method}
static const struct {
    pcl_fn fn[2];
    int op, hook, method;
} fns[] = {
    {{{.name = "P", .fn = l_make, .sig = "P(x, y [, z, ...]) -> point", .help = "A point (weight 1) of any dimension from 1 up: P(1, 2), P(0, 0, 1)."}}, .op = 1},
    {{{.name = "V", .fn = l_make, .sig = "V(x, y [, z, ...]) -> vector", .help = "A vector (weight 0), as the difference of two points is: V(0, 1)."}}, .method = 0},
    {{PCL_FN("lerp", l_lerp, lerp_args, "value", "(B - A)t + A, the point of line AB with parameter t (t = 0 gives A, t = 1 gives B); also for vectors and numbers.")}, .method = 1},
    {{PCL_FN("bar", l_bar, t_arg, "number", "The complement 1 - t (the book's t with a bar), as in A*bar(t) + B*t.")}, .method = 0},
    {{{.name = "mid", .fn = l_mid, .args = mid_args, .sig = "mid(A, B, ...) -> value", .help = "The midpoint of two values, or the centroid of several."}}, .method = 1},
    {{{.name = "dist", .fn = l_dist, .args = two_points, .sig = "dist(A, B) | dist(v) -> number", .help = "The distance between two points, or the length of a vector."}}, .method = 1},
    {{PCL_FN("dot", l_dot, uv_args, "number", "The scalar product of two vectors.")}, .method = 1},
    OP("cross", uv_args, "vector | number", PC_FN_CROSS, PC_EQV_CROSS, 1, "The cross product: a vector in 3-D, the number u.x v.y - u.y v.x in 2-D."),
    OP("unit", one_vector, "vector", PC_FN_UNIT, PC_EQV_UNIT, 1, "The vector v scaled to length 1; the zero vector is an error."),
    OP("perp", one_vector, "vector", PC_FN_PERP, NOHOOK, 1, "The 2-D vector v turned by +90 degrees: V(-v.y, v.x)."),
    {{{.name = "angle", .fn = l_angle, .args = three_points, .sig = "angle(A, B, C) | angle(u, v) -> number", .help = "The angle at A of triangle ABC, or between two vectors: unsigned, in radians, 0..pi."}}, .method = 1},
    OP("foot", foot_args, "point", PC_FN_FOOT, NOHOOK, 0, "The foot of the perpendicular from C to line AB."),
    OP("Sigma", sigma_args, "number", PC_FN_SIGMA, NOHOOK, 0, "The metric operator (B - A).(C - A) of three points; Sigma(A, B) is the squared distance AB^2."),
    OP("sr", sr_args, "number", PC_FN_SR, NOHOOK, 0, "The simple ratio (XYZ) = (X - Z)/(Z - Y) in which Z divides XY; math.huge when Z = Y, -1 for the point at infinity."),
    OP("divide", divide_args, "point", PC_FN_DIVIDE, NOHOOK, 0, "The point Z with (XYZ) = lambda: (X + lambda Y)/(1 + lambda); lambda = -1 gives the point at infinity of XY."),
    OP("harmonic", harmonic_args, "point", PC_FN_HARMONIC, NOHOOK, 0, "The harmonic conjugate N of T with respect to A, B: (ABN) = -(ABT); the midpoint gives the point at infinity."),
    OP("cross_ratio", cross_ratio_args, "number", PC_FN_CROSS_RATIO, NOHOOK, 0, "The cross ratio (ABCD) = (ABC)/(ABD) of four collinear points (C, D may be points at infinity)."),
    OP("meet", meet_args, "K, lambda, mu", PC_FN_MEET, PC_EQV_MEET, 0, "The intersection K = A1 + (A2 - A1)lambda = B1 + (B2 - B1)mu of two lines, any dimension; an end may be a point at infinity (a vector: the line's direction); parallel lines give their direction (weight 0), skew ones nil and their distance. With point equations among the ends (param \"u\") K, lambda and mu are equations with exact derivatives, so a scheme of meets compiles with curve()."),
    {{{.name = "area", .fn = l_area, .args = three_points, .sig = "area(A, B, C) | area(A, B, C, D, ...) -> number", .help = "The area of a triangle (signed in 2-D, counter-clockwise positive) or of a 2-D polygon."}}, .method = 0},
    OP("volume", four_points, "number", PC_FN_VOLUME, NOHOOK, 0, "The volume of a tetrahedron: signed in 3-D (positive when right-handed), unsigned in 4-D and up."),
    OP("normalize", any_value, "point", PC_FN_NORMALIZE, NOHOOK, 1, "Divide a weighted value by its weight (projective normalisation); weight 0 is an error."),
    OP("weight", any_value, "number", PC_FN_WEIGHT, NOHOOK, 1, "The weight of a value: 1 for a point, 0 for a vector, k for k*A."),
    {{PCL_FN("coords", l_coords, one_loc, "x, y, ...", "The coordinates of a point or the components of a vector, as numbers.")}, .method = 1},
    {{PCL_FN("near", l_near, near_args, "boolean", "Numbers, or values of one dimension, equal within eps (default 1e-9) relative to their size.")}, .method = 1},
};

static const luaL_Reg point_meta[] = {
    {"__add", l_add}, {"__sub", l_sub}, {"__mul", l_mul}, {"__div", l_div}, {"__unm", l_unm},
    {"__eq", l_eq}, {"__len", l_len}, {"__tostring", l_tostring}, {"__concat", pcl_concat},
    {"__newindex", l_newindex}, {"__index", l_index},
    {NULL, NULL}
};

void pcl_open_point(lua_State *L) {
    int module = lua_gettop(L), methods = module + 1, mt = module + 2;
    lua_newtable(L);                                   /* methods for p:name(...), filled below */
    /* the metatable, also kept in the registry for pcl_tovalue and the other bindings */
    luaL_newmetatable(L, "point");                     /* __name "point" */
    lua_pushliteral(L, "point");                       /* getmetatable(p) == "point" */
    lua_setfield(L, mt, "__metatable");
    lua_pushvalue(L, mt);
    lua_rawsetp(L, LUA_REGISTRYINDEX, &POINT_MT_KEY);
    lua_pushboolean(L, 0);                             /* upvalue 1: no declaration */
    lua_pushvalue(L, mt);
    lua_pushvalue(L, methods);
    luaL_setfuncs(L, point_meta, 3);                   /* metamethods, upvalues 2, 3 = mt, methods */

    for (size_t i = 0; i < sizeof fns / sizeof fns[0]; i++) {
        lua_pushvalue(L, mt);                          /* upvalues 2..4: mt, op, hook */
        lua_pushinteger(L, fns[i].op);
        lua_pushinteger(L, fns[i].hook);
        pcl_register(L, module, fns[i].fn, 3);
        if (!fns[i].method) continue;
        lua_getfield(L, module, fns[i].fn[0].name);
        lua_setfield(L, methods, fns[i].fn[0].name);
    }
    lua_settop(L, module);
}
