/* Binding of the point equations (stdlib/geom/expr.h):
 *   param "t"                 a symbolic parameter: arithmetic on it builds an equation
 *   M = A*bar(t)^2 + 2*B*t*bar(t) + C*t^2      with + - * / ^ unary -, lerp bar dot cross unit,
 *                             P(x, y) of scalar equations, math.sin cos tan exp log sqrt abs,
 *                             smooth.sine smooth.cubic and half-splines
 *   M(0.3), M{t = .3, s = 1}  the value (a point, vector, weighted point or number)
 *   M:with{s = 0.5}           the family M(t; s) at s = 0.5 (or s = another equation)
 *   M:show{A = A, B = B}      the text with the points named; tostring(M) without names
 *   M:sample(a, b, n [, s])   n values at evenly spaced t, computed in C (a "samples" object;
 *                             given s, into it again)
 *   M.dim, M.params           0 for a scalar; the parameters' names in order
 *   curve(M, t0, t1), surface(M, u0, u1, v0, v1): see pcl_expr.h.
 * Every Lua state has one pool of nodes (the equations share their common parts); compiled
 * programs are copies, so curves outlive nothing.  The math functions are wrapped once for
 * the whole module: a number goes straight to Lua's own function. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "pcl_expr.h"
#include "pcl_point.h"
#include "expr.h"

#define EQ_MT "equation"
static const char EQ_TAG = 'e', SAMPLES_TAG = 'S';   /* its address tags the type (PCL_SELF_TAG) */
#define SAMPLES_MT "samples"
static const char POOL_KEY = 'q';

static const char MEMBERSHIP[] =
    "the coefficients of a point equation must sum to 1 for a point and to 0 for a vector "
    "(the membership condition)";

typedef struct {
    PCL_SELF;               /* its own address: a forged equation is refused (pcl.h) */
    int id;
    pc_expr_prog *prog;     /* compiled on first evaluation, inputs: its parameters in order */
} leq;

typedef struct {
    PCL_SELF;               /* a 2-D point has the size of two samples: self tells (pcl.h) */
    long n;
    int dim;                /* 0: numbers */
    double v[];
} lsamples;

/* ---- the pool and the userdata ------------------------------------------------------------ */

static int pool_gc(lua_State *L) {
    pc_expr_pool **pp = lua_touserdata(L, 1);
    if (pp && *pp) {
        pc_expr_pool_free(*pp);
        *pp = NULL;
    }
    return 0;
}

static pc_expr_pool *pool(lua_State *L) {
    lua_rawgetp(L, LUA_REGISTRYINDEX, &POOL_KEY);
    pc_expr_pool **pp = lua_touserdata(L, -1);
    lua_pop(L, 1);
    if (!pp || !*pp) luaL_error(L, "equations: the pool is gone");
    return *pp;
}

static int genuine_eq(lua_State *L, int idx, const leq *e) {
    return lua_rawlen(L, idx) == sizeof *e && e->self == PCL_SELF_TAG(e, &EQ_TAG);
}

static leq *toeq(lua_State *L, int idx) {
    leq *e = luaL_testudata(L, idx, EQ_MT);
    return pcl_genuine(L, idx, e, !e || genuine_eq(L, idx, e), "equation");
}

/* Samples: exactly the header and n values of max(dim, 1) numbers (pcl.h: forged userdata). */
static lsamples *tosamples(lua_State *L, int idx) {
    lsamples *s = luaL_testudata(L, idx, SAMPLES_MT);
    if (!s) return NULL;
    size_t len = lua_rawlen(L, idx);
    int ok = len >= sizeof *s && s->self == PCL_SELF_TAG(s, &SAMPLES_TAG) && s->dim >= 0 && s->dim <= PC_MAXDIM && s->n >= 0 &&
             (size_t)s->n <= len / sizeof(double) &&
             len == sizeof *s + sizeof(double) * (size_t)s->n * (size_t)(s->dim ? s->dim : 1);
    return pcl_genuine(L, idx, s, ok, "samples");
}

int pcl_isequation(lua_State *L, int idx) { return toeq(L, idx) != NULL; }

static void push_eq(lua_State *L, int id) {
    leq *e = lua_newuserdatauv(L, sizeof *e, 0);
    e->self = PCL_SELF_TAG(e, &EQ_TAG);
    e->id = id;
    e->prog = NULL;
    luaL_setmetatable(L, EQ_MT);
}

static int eq_gc(lua_State *L) {
    leq *e = luaL_testudata(L, 1, EQ_MT);
    if (e && genuine_eq(L, 1, e) && e->prog) {   /* never a forged one */
        pc_expr_prog_free(e->prog);
        e->prog = NULL;
    }
    return 0;
}

/* "a 2-D point equation", "a scalar equation", "a number", "a point", ... */
static const char *describe(lua_State *L, int idx) {
    leq *e = toeq(L, idx);
    if (e) {
        int d = pc_expr_dim(pool(L), e->id);
        return d ? lua_pushfstring(L, "a %d-D point equation", d) : "a scalar equation";
    }
    pcl_value *v = pcl_tovalue(L, idx);
    if (v) return lua_pushfstring(L, "the %d-D value %s", v->n, luaL_tolstring(L, idx, NULL));
    if (lua_type(L, idx) == LUA_TNUMBER) return "a number";
    return lua_pushfstring(L, "a %s", luaL_typename(L, idx));
}

/* The node of an operand: an equation, a number (a constant), a point or vector (a constant
 * value); -1 for anything else. */
static int node_of(lua_State *L, int idx) {
    leq *e = toeq(L, idx);
    if (e) return e->id;
    int st;
    if (lua_type(L, idx) == LUA_TNUMBER) {
        double x = lua_tonumber(L, idx);
        if (!isfinite(x)) return -1;
        return pc_expr_const(pool(L), x, &st);
    }
    pcl_value *v = pcl_tovalue(L, idx);
    if (v) return pc_expr_vconst(pool(L), v->n, v->h, &st);
    return -1;
}

static int any_eq(lua_State *L, int from, int to) {
    for (int i = from; i <= to; i++)
        if (toeq(L, i)) return 1;
    return 0;
}

static int raise_status(lua_State *L, const char *fname, int st) {
    if (st == PC_ENOMEM) return pcl_error(L, "%s: out of memory (too many equation nodes)", fname);
    return pcl_error(L, "%s: %s", fname, pc_strerror(st));
}

/* ---- operators -------------------------------------------------------------------------------- */

static const char *const OPNAME[] = {"add", "subtract", "multiply", "divide", "negate"};

static int arith(lua_State *L, pcl_eq_op op) {
    pc_expr_pool *p = pool(L);
    int a = node_of(L, 1), b = op == PCL_EQ_UNM ? 0 : node_of(L, 2);
    if (a < 0 || b < 0) {
        if (op == PCL_EQ_UNM) return pcl_error(L, "cannot negate %s", describe(L, 1));
        return pcl_error(L, "cannot %s %s and %s: equations combine with numbers, points, "
                         "vectors and equations", OPNAME[op], describe(L, 1), describe(L, 2));
    }
    int st = PC_OK, r;
    switch (op) {
    case PCL_EQ_ADD: r = pc_expr_add(p, a, b, &st); break;
    case PCL_EQ_SUB: r = pc_expr_sub(p, a, b, &st); break;
    case PCL_EQ_MUL: r = pc_expr_mul(p, a, b, &st); break;
    case PCL_EQ_DIV: r = pc_expr_div(p, a, b, &st); break;
    default: r = pc_expr_neg(p, a, &st); break;
    }
    if (r >= 0) {
        push_eq(L, r);
        return 1;
    }
    int da = pc_expr_dim(p, a), db = op == PCL_EQ_UNM ? 0 : pc_expr_dim(p, b);
    if (st == PC_EDIM) {
        if (da && db && da != db)
            return pcl_error(L, "cannot %s %s and %s: dimensions cannot be mixed", OPNAME[op],
                             describe(L, 1), describe(L, 2));
        if (op == PCL_EQ_MUL)
            return pcl_error(L, "cannot multiply %s by %s: use dot(u, v) or cross(u, v) for "
                             "products of vectors", describe(L, 1), describe(L, 2));
        if (op == PCL_EQ_DIV)
            return pcl_error(L, "cannot divide %s by %s: divide by numbers or scalar equations",
                             describe(L, 1), describe(L, 2));
        return pcl_error(L, "cannot %s %s and %s: points and vectors add only to points and "
                         "vectors; to shift a point write A + V(dx, dy)", OPNAME[op],
                         describe(L, 1), describe(L, 2));
    }
    if (st == PC_EDOMAIN && op == PCL_EQ_DIV) return pcl_error(L, "division of an equation by zero");
    return raise_status(L, "equation", st);
}

static int m_add(lua_State *L) { return arith(L, PCL_EQ_ADD); }
static int m_sub(lua_State *L) { return arith(L, PCL_EQ_SUB); }
static int m_mul(lua_State *L) { return arith(L, PCL_EQ_MUL); }
static int m_div(lua_State *L) { return arith(L, PCL_EQ_DIV); }
static int m_unm(lua_State *L) { return arith(L, PCL_EQ_UNM); }

static int m_pow(lua_State *L) {
    pc_expr_pool *p = pool(L);
    int a = node_of(L, 1), b = node_of(L, 2);
    if (a < 0 || b < 0 || pc_expr_dim(p, a) || pc_expr_dim(p, b))
        return pcl_error(L, "cannot raise %s to %s: powers are of numbers and scalar equations",
                         describe(L, 1), describe(L, 2));
    int st, r = pc_expr_pow(p, a, b, &st);
    if (r < 0) return raise_status(L, "^", st);
    push_eq(L, r);
    return 1;
}

static int m_eq(lua_State *L) {
    leq *a = toeq(L, 1), *b = toeq(L, 2);
    lua_pushboolean(L, a && b && a->id == b->id);        /* hash-consed: one node, one equation */
    return 1;
}

/* ---- the point functions on equations ------------------------------------------------------- */

/* The weight class of a value equation over [0, 1] in each of its parameters. */
static int weight_class(lua_State *L, int id) {
    pc_expr_pool *p = pool(L);
    unsigned mask = pc_expr_params(p, id);
    int in[PC_EXPR_MAXPARAM], n = 0, st;
    for (int k = 0; k < PC_EXPR_MAXPARAM; k++)
        if (mask & (1u << k)) in[n++] = k;
    pc_expr_prog *prog = pc_expr_compile(p, id, n, in, &st);
    if (!prog) return -1;
    double lo[PC_EXPR_MAXPARAM] = {0}, hi[PC_EXPR_MAXPARAM];
    for (int j = 0; j < n; j++) hi[j] = 1;
    int kind = pc_expr_prog_weight(prog, lo, hi, NULL, NULL);
    pc_expr_prog_free(prog);
    return kind;
}

/* a value operand of dot, cross, unit: a vector (weight 0), its node */
static int vec_arg(lua_State *L, const char *fname, int arg, const char *what, int dim, int dim_arg) {
    int id = node_of(L, arg);
    if (id < 0 || !pc_expr_dim(pool(L), id))
        return pcl_argerror_full(L, fname, arg, arg, what, "a vector or a vector equation");
    int d = pc_expr_dim(pool(L), id);
    if (dim && d != dim)
        return pcl_error(L, "%s: argument #%d (%s) is %d-D, but argument #%d is %d-D: dimensions "
                         "cannot be mixed", fname, arg, what, d, dim_arg, dim);
    if (weight_class(L, id) != PC_KIND_VECTOR)
        return pcl_error(L, "%s: argument #%d (%s) must be a vector (weight 0), got %s whose "
                         "weight is not 0; a difference of points is a vector, e.g. B - A",
                         fname, arg, what, describe(L, arg));
    return id;
}

static int scalar_arg(lua_State *L, const char *fname, int arg, const char *what) {
    int id = node_of(L, arg);
    if (id < 0 || pc_expr_dim(pool(L), id))
        return pcl_argerror_full(L, fname, arg, arg, what, "a number or a scalar equation");
    return id;
}

static int done(lua_State *L, const char *fname, int r, int st) {
    if (r < 0) return raise_status(L, fname, st);
    push_eq(L, r);
    return 1;
}

static int fn_lerp(lua_State *L) {
    pc_expr_pool *p = pool(L);
    int t = scalar_arg(L, "lerp", 3, "t");
    int a = node_of(L, 1), b = node_of(L, 2);
    if (a < 0) return pcl_argerror_full(L, "lerp", 1, 1, "A", "a point, a vector, a number or an equation");
    if (b < 0) return pcl_argerror_full(L, "lerp", 2, 2, "B", "a point, a vector, a number or an equation");
    int da = pc_expr_dim(p, a), db = pc_expr_dim(p, b);
    if (da != db) {
        if (da && db)
            return pcl_error(L, "lerp: argument #2 (B) is %d-D, but argument #1 is %d-D: "
                             "dimensions cannot be mixed", db, da);
        return pcl_error(L, "lerp: A and B must both be points (or vectors) or both numbers, got "
                         "%s and %s", describe(L, 1), describe(L, 2));
    }
    int st, r = pc_expr_lerp(p, a, b, t, &st);
    return done(L, "lerp", r, st);
}

static int fn_pack(lua_State *L, double weight, const char *fname) {
    int n = lua_gettop(L);
    if (n < 1 || n > PC_MAXDIM)
        return pcl_error(L, "%s: needs 1 to %d coordinates, got %d", fname, PC_MAXDIM, n);
    int x[PC_MAXDIM];
    static const char *xyz[] = {"x", "y", "z"};
    for (int i = 0; i < n; i++) x[i] = scalar_arg(L, fname, i + 1, i < 3 ? xyz[i] : "coordinate");
    int st, r = pc_expr_pack(pool(L), n, x, weight, &st);
    return done(L, fname, r, st);
}

/* meet(A1, A2, B1, B2) with equations among the ends: K, lambda, mu as equations */
static int fn_meet(lua_State *L) {
    static const char *nm[4] = {"A1", "A2", "B1", "B2"};
    pc_expr_pool *p = pool(L);
    int id[4], dim = 0;
    for (int i = 0; i < 4; i++) {
        id[i] = node_of(L, i + 1);
        if (id[i] < 0 || !pc_expr_dim(p, id[i]))
            return pcl_argerror_full(L, "meet", i + 1, i + 1, nm[i], "a point or an equation of a point");
        int d = pc_expr_dim(p, id[i]);
        if (i == 0) dim = d;
        else if (d != dim)
            return pcl_error(L, "meet: argument #%d (%s) is %d-D, but argument #1 is %d-D: dimensions cannot be mixed",
                             i + 1, nm[i], d, dim);
        if (weight_class(L, id[i]) != PC_KIND_POINT)
            return pcl_error(L, "meet: argument #%d (%s) must be a point (weight 1), got %s: the coefficients of a "
                             "point equation sum to 1 (membership condition)", i + 1, nm[i], describe(L, i + 1));
    }
    if (dim < 2) return pcl_error(L, "meet: lines meet in 2-D or more, got %d-D points", dim);
    int st, lam, mu, k = pc_expr_meet(p, id[0], id[1], id[2], id[3], &lam, &mu, &st);
    if (k < 0) return raise_status(L, "meet", st);
    push_eq(L, k);
    push_eq(L, lam);
    push_eq(L, mu);
    return 3;
}

int pcl_eq_hook(lua_State *L, pcl_eq_op op) {
    int top = lua_gettop(L);
    switch (op) {
    case PCL_EQ_ADD: case PCL_EQ_SUB: case PCL_EQ_MUL: case PCL_EQ_DIV:
        if (!any_eq(L, 1, 2)) return 0;
        return arith(L, op);
    case PCL_EQ_UNM:
        if (!any_eq(L, 1, 1)) return 0;
        return arith(L, op);
    case PCL_EQ_LERP:
        if (!any_eq(L, 1, 3)) return 0;
        return fn_lerp(L);
    case PCL_EQ_BAR: {
        if (!any_eq(L, 1, 1)) return 0;
        int t = scalar_arg(L, "bar", 1, "t"), st;
        return done(L, "bar", pc_expr_bar(pool(L), t, &st), st);
    }
    case PCL_EQ_DOT: case PCL_EQ_CROSS: {
        if (!any_eq(L, 1, 2)) return 0;
        const char *fname = op == PCL_EQ_DOT ? "dot" : "cross";
        int u = vec_arg(L, fname, 1, "u", 0, 0);
        int v = vec_arg(L, fname, 2, "v", pc_expr_dim(pool(L), u), 1), st;
        if (op == PCL_EQ_CROSS && pc_expr_dim(pool(L), u) != 2 && pc_expr_dim(pool(L), u) != 3)
            return pcl_error(L, "cross: vectors must be 2-D or 3-D, got %d-D", pc_expr_dim(pool(L), u));
        int r = op == PCL_EQ_DOT ? pc_expr_dot(pool(L), u, v, &st) : pc_expr_cross(pool(L), u, v, &st);
        return done(L, fname, r, st);
    }
    case PCL_EQ_UNIT: {
        if (!any_eq(L, 1, 1)) return 0;
        int u = vec_arg(L, "unit", 1, "v", 0, 0), st;
        int r = pc_expr_unit(pool(L), u, &st);
        if (r < 0 && st == PC_EZERO) return pcl_error(L, "unit: the zero vector has no direction");
        return done(L, "unit", r, st);
    }
    case PCL_EQ_P: case PCL_EQ_V:
        if (!any_eq(L, 1, top)) return 0;
        return fn_pack(L, op == PCL_EQ_P ? 1.0 : 0.0, op == PCL_EQ_P ? "P" : "V");
    case PCL_EQ_MEET:
        if (!any_eq(L, 1, 4)) return 0;
        return fn_meet(L);
    }
    return 0;
}

int pcl_eq_curve_apply(lua_State *L, const pc_curve *c, int idx) {
    leq *e = toeq(L, idx);
    if (!e) return 0;
    if (pc_expr_dim(pool(L), e->id))
        return pcl_error(L, "curve: the parameter must be a number or a scalar equation, got %s", describe(L, idx));
    if (c->kind != PC_CURVE_BEZIER || c->nknots != 2)
        return pcl_error(L, "curve: only a single-piece Bezier curve (a conic arc, a Bezier of any degree) "
                         "can be applied to an equation; this one has %s",
                         c->kind == PC_CURVE_FUNC ? "a function" : "several pieces");
    int st, r = pc_expr_bezier(pool(L), c->dim, c->degree, c->cp, c->t0, c->t1, e->id, &st);
    return done(L, "curve", r, st);
}

int pcl_eq_smooth(lua_State *L, int idx, const pc_gfun *g) {
    leq *e = toeq(L, idx);
    if (!e) return 0;
    if (pc_expr_dim(pool(L), e->id))
        return pcl_error(L, "smoothstep: the argument must be a number or a scalar equation, got %s",
                         describe(L, idx));
    int st;
    return done(L, "smoothstep", pc_expr_smooth(pool(L), g, e->id, &st), st);
}

/* ---- math.* on equations ------------------------------------------------------------------- */

static const struct { const char *name, *fname; pc_expr_op op; } MATHFN[] = {
    {"sin", "math.sin", PC_EX_SIN}, {"cos", "math.cos", PC_EX_COS}, {"tan", "math.tan", PC_EX_TAN},
    {"exp", "math.exp", PC_EX_EXP}, {"log", "math.log", PC_EX_LOG}, {"sqrt", "math.sqrt", PC_EX_SQRT},
    {"abs", "math.abs", PC_EX_ABS}};
enum { NMATH = sizeof MATHFN / sizeof *MATHFN };
static lua_CFunction math_orig[NMATH];   /* Lua's own functions (one library per process) */

static int math_eq(lua_State *L, int i) {
    const char *fname = MATHFN[i].fname;
    int a = scalar_arg(L, fname, 1, "x"), st;
    pc_expr_pool *p = pool(L);
    int r = pc_expr_fn(p, MATHFN[i].op, a, &st);
    if (r >= 0 && MATHFN[i].op == PC_EX_LOG && !lua_isnoneornil(L, 2)) {     /* log(x, base) */
        double base = pcl_checknum(L, fname, 2, "base");
        if (!(base > 0) || base == 1) return pcl_argerror_full(L, fname, 2, 2, "base", "a positive number other than 1");
        int k = pc_expr_const(p, 1 / log(base), &st);
        r = k < 0 ? -1 : pc_expr_mul(p, r, k, &st);
    }
    if (r < 0 && st == PC_EDOMAIN)
        return pcl_error(L, "%s: argument #1 (x) is outside the function's domain", fname);
    return done(L, fname, r, st);
}

/* A number takes one type test and goes to Lua's function: math.sin(x) keeps its speed. */
#define MATH_WRAPPER(i, name) \
    static int math_##name(lua_State *L) { \
        if (lua_type(L, 1) == LUA_TNUMBER || !toeq(L, 1)) return math_orig[i](L); \
        return math_eq(L, i); \
    }
MATH_WRAPPER(0, sin)
MATH_WRAPPER(1, cos)
MATH_WRAPPER(2, tan)
MATH_WRAPPER(3, exp)
MATH_WRAPPER(4, log)
MATH_WRAPPER(5, sqrt)
MATH_WRAPPER(6, abs)
static const lua_CFunction math_wrappers[NMATH] = {math_sin, math_cos, math_tan, math_exp,
                                                   math_log, math_sqrt, math_abs};

static void wrap_math(lua_State *L) {
    if (lua_getglobal(L, "math") != LUA_TTABLE) {
        lua_pop(L, 1);
        return;
    }
    for (int i = 0; i < NMATH; i++) {
        lua_getfield(L, -1, MATHFN[i].name);
        lua_CFunction f = lua_tocfunction(L, -1);
        lua_pop(L, 1);
        if (!f || f == math_wrappers[i]) continue;       /* wrapped already (a second state) */
        math_orig[i] = f;
        lua_pushcfunction(L, math_wrappers[i]);
        lua_setfield(L, -2, MATHFN[i].name);
    }
    lua_pop(L, 1);
}

/* ---- param, evaluation, methods -------------------------------------------------------------- */

static int l_param(lua_State *L) {
    size_t len;
    const char *name = lua_type(L, 1) == LUA_TSTRING ? lua_tolstring(L, 1, &len) : NULL;
    if (!name || len == 0 || len >= PC_EXPR_MAXNAME || strlen(name) != len)
        return pcl_argerror_full(L, "param", 1, 1, "name", "a name of 1 to 31 characters");
    int st, id = pc_expr_param(pool(L), name, &st);
    if (id < 0) return pcl_error(L, "param: at most %d parameters per script, and %s would be "
                                 "one more", PC_EXPR_MAXPARAM, name);
    push_eq(L, id);
    return 1;
}

/* the parameters of an equation in order: their indices */
static int params_of(lua_State *L, int id, int *in) {
    unsigned mask = pc_expr_params(pool(L), id);
    int n = 0;
    for (int k = 0; k < PC_EXPR_MAXPARAM; k++)
        if (mask & (1u << k)) in[n++] = k;
    return n;
}

/* "t and s", "t, s and u" */
static const char *names_of(lua_State *L, int n, const int *in) {
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    for (int j = 0; j < n; j++) {
        if (j) luaL_addstring(&b, j == n - 1 ? " and " : ", ");
        luaL_addstring(&b, pc_expr_param_name(pool(L), in[j]));
    }
    luaL_pushresult(&b);
    return lua_tostring(L, -1);
}

static pc_expr_prog *prog_of(lua_State *L, leq *e) {
    if (!e->prog) {
        int in[PC_EXPR_MAXPARAM], st;
        int n = params_of(L, e->id, in);
        e->prog = pc_expr_compile(pool(L), e->id, n, in, &st);
        if (!e->prog) raise_status(L, "equation", st);
    }
    return e->prog;
}

static void push_result(lua_State *L, int dim, const double *h) {
    if (!dim) {
        lua_pushnumber(L, h[0]);
        return;
    }
    pcl_value *v = pcl_newvalue(L, dim);
    memcpy(v->h, h, sizeof(double) * (size_t)(dim + 1));
}

/* M(t [, s ...]) with values in the order of M.params, or M{t = ..., s = ...} */
static int eq_call(lua_State *L) {
    leq *e = toeq(L, 1);
    int in[PC_EXPR_MAXPARAM], n = params_of(L, e->id, in);
    double x[PC_EXPR_MAXPARAM];
    pc_expr_pool *p = pool(L);
    if (lua_istable(L, 2)) {
        for (int j = 0; j < n; j++) {
            const char *nm = pc_expr_param_name(p, in[j]);
            lua_getfield(L, 2, nm);
            if (lua_type(L, -1) != LUA_TNUMBER || !isfinite(lua_tonumber(L, -1)))
                return pcl_error(L, "equation: field %s must be a finite number, got %s", nm,
                                 pcl_shown(L, -1));
            x[j] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
    } else {
        int given = lua_gettop(L) - 1;
        if (given != n)
            return pcl_error(L, "equation: needs %d parameter value%s (%s), got %d", n,
                             n == 1 ? "" : "s", n ? names_of(L, n, in) : "none", given);
        for (int j = 0; j < n; j++) x[j] = pcl_checknum(L, "equation", j + 2, pc_expr_param_name(p, in[j]));
    }
    pc_expr_prog *prog = prog_of(L, e);
    double h[PC_MAXDIM + 1];
    int st = pc_expr_eval(prog, 1, x, 0, h, NULL);
    if (st == PC_ENONFINITE) {
        luaL_Buffer b;
        luaL_buffinit(L, &b);
        for (int j = 0; j < n; j++) {
            if (j) luaL_addstring(&b, ", ");
            lua_pushfstring(L, "%s = %s", pc_expr_param_name(p, in[j]), pcl_pushnum(L, x[j]));
            lua_remove(L, -2);
            luaL_addvalue(&b);
        }
        luaL_pushresult(&b);
        return pcl_error(L, "equation: the value at %s is not finite (NaN or infinite: outside "
                         "the domain of a function, or a division by zero)", lua_tostring(L, -1));
    }
    if (st != PC_OK) return raise_status(L, "equation", st);
    push_result(L, pc_expr_dim(p, e->id), h);
    return 1;
}

static int eq_with(lua_State *L) {
    leq *e = toeq(L, 1);
    if (!e) return pcl_argerror_full(L, "M:with", 1, 0, NULL, "an equation");
    if (!lua_istable(L, 2)) return pcl_argerror_full(L, "M:with", 2, 1, "values", "a table {name = value}");
    pc_expr_pool *p = pool(L);
    int r = e->id;
    lua_pushnil(L);
    while (lua_next(L, 2)) {
        const char *nm = lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : NULL;
        int k = -1;
        for (int j = 0; nm && j < pc_expr_nparams(p); j++)
            if (!strcmp(pc_expr_param_name(p, j), nm)) k = j;
        if (k < 0 || !(pc_expr_params(p, e->id) & (1u << k))) {
            int in[PC_EXPR_MAXPARAM], n = params_of(L, e->id, in);
            return pcl_error(L, "M:with: the equation has no parameter %s (its parameters: %s)",
                             nm ? nm : pcl_shown(L, -2), n ? names_of(L, n, in) : "none");
        }
        int v = node_of(L, -1);
        if (v < 0 || pc_expr_dim(p, v))
            return pcl_error(L, "M:with: %s must be a number or a scalar equation, got %s", nm,
                             describe(L, -1));
        int st;
        r = pc_expr_subst(p, r, k, v, &st);
        if (r < 0) return pcl_error(L, "M:with: %s = %s: %s", nm, pcl_shown(L, -1), pc_strerror(st));
        lua_pop(L, 1);
    }
    push_eq(L, r);
    return 1;
}

/* The names given to M:show, looked up by value */
typedef struct { lua_State *L; int tbl; } namer_ud;

static const char *namer(void *ud, int dim, const double *h) {
    namer_ud *n = ud;
    lua_State *L = n->L;
    const char *found = NULL;
    lua_pushnil(L);
    while (!found && lua_next(L, n->tbl)) {
        pcl_value *v = pcl_tovalue(L, -1);
        if (v && v->n == dim && lua_type(L, -2) == LUA_TSTRING) {
            int same = 1;
            for (int i = 0; same && i <= dim; i++) same = v->h[i] == h[i];
            if (same) found = lua_tostring(L, -2);   /* the key stays in the table */
        }
        lua_pop(L, 1);
    }
    if (found) lua_pop(L, 1);
    return found;
}

static void push_text(lua_State *L, int id, int names) {
    namer_ud ud = {L, names};
    char small[512];
    int len = pc_expr_print(pool(L), id, names ? namer : NULL, &ud, small, sizeof small);
    if (len < (int)sizeof small) {
        lua_pushstring(L, small);
        return;
    }
    char *big = lua_newuserdatauv(L, (size_t)len + 1, 0);
    pc_expr_print(pool(L), id, names ? namer : NULL, &ud, big, (size_t)len + 1);
    lua_pushstring(L, big);
    lua_remove(L, -2);
}

static int eq_tostring(lua_State *L) {
    leq *e = toeq(L, 1);
    if (!e) return pcl_error(L, "tostring: not an equation");
    push_text(L, e->id, 0);
    return 1;
}

static int eq_show(lua_State *L) {
    leq *e = toeq(L, 1);
    if (!e) return pcl_argerror_full(L, "M:show", 1, 0, NULL, "an equation");
    if (!lua_isnoneornil(L, 2) && !lua_istable(L, 2))
        return pcl_argerror_full(L, "M:show", 2, 1, "names", "a table {A = A, ...}");
    push_text(L, e->id, lua_istable(L, 2) ? 2 : 0);
    return 1;
}

static int eq_concat(lua_State *L) {
    luaL_tolstring(L, 1, NULL);
    luaL_tolstring(L, 2, NULL);
    lua_concat(L, 2);
    return 1;
}

/* M:sample(a, b, n [, into]): n values at t = a .. b in C, into a new samples object or into the
 * one given (of that size: a renderer resampling every frame allocates nothing) */
static int eq_sample(lua_State *L) {
    leq *e = toeq(L, 1);
    if (!e) return pcl_argerror_full(L, "M:sample", 1, 0, NULL, "an equation");
    double a = pcl_checknum_m(L, "M:sample", 2, "a"), b = pcl_checknum_m(L, "M:sample", 3, "b");
    lua_Integer n = luaL_optinteger(L, 4, 1001);
    if (n < 1 || n > 100000000) return pcl_argerror_full(L, "M:sample", 4, 3, "n", "a count from 1 to 10^8");
    int in[PC_EXPR_MAXPARAM], np = params_of(L, e->id, in);
    if (np != 1)
        return pcl_error(L, "M:sample: the equation must have one parameter, it has %s",
                         np ? names_of(L, np, in) : "none");
    pc_expr_prog *prog = prog_of(L, e);
    int dim = pc_expr_prog_dim(prog), w = dim ? dim : 1;
    lsamples *s;
    if (!lua_isnoneornil(L, 5)) {                 /* M:sample(a, b, n, s): into s again */
        s = tosamples(L, 5);
        if (!s || s->n != (long)n || s->dim != dim) {
            lua_pushfstring(L, "samples of %d %d-D values (from M:sample)", (int)n, dim);
            return pcl_argerror_full(L, "M:sample", 5, 4, "into", lua_tostring(L, -1));
        }
        lua_pushvalue(L, 5);
    } else {
        s = lua_newuserdatauv(L, sizeof *s + sizeof(double) * (size_t)n * (size_t)w, 0);
        s->self = PCL_SELF_TAG(s, &SAMPLES_TAG);
        s->n = (long)n;
        s->dim = dim;
        luaL_setmetatable(L, SAMPLES_MT);
    }
    long bad = 0;
    int st = pc_expr_sample(prog, a, b, (long)n, s->v, &bad);
    if (st == PC_ENONFINITE) {
        double t = n > 1 ? a + (b - a) * (double)bad / (double)(n - 1) : a;
        return pcl_error(L, "M:sample: the value at %s = %s is not finite",
                         pc_expr_param_name(pool(L), in[0]), pcl_pushnum(L, t));
    }
    if (st != PC_OK) return raise_status(L, "M:sample", st);
    return 1;
}

static int eq_index(lua_State *L) {
    leq *e = toeq(L, 1);
    const char *k = lua_tostring(L, 2);
    if (e && k) {
        if (!strcmp(k, "dim")) { lua_pushinteger(L, pc_expr_dim(pool(L), e->id)); return 1; }
        if (!strcmp(k, "params")) {
            int in[PC_EXPR_MAXPARAM], n = params_of(L, e->id, in);
            lua_createtable(L, n, 0);
            for (int j = 0; j < n; j++) {
                lua_pushstring(L, pc_expr_param_name(pool(L), in[j]));
                lua_rawseti(L, -2, j + 1);
            }
            return 1;
        }
    }
    lua_pushvalue(L, 2);
    lua_rawget(L, lua_upvalueindex(1));
    return 1;
}

/* ---- samples ----------------------------------------------------------------------------------- */

static lsamples *checksamples(lua_State *L, const char *fname) {
    lsamples *s = tosamples(L, 1);
    if (!s) pcl_argerror_full(L, fname, 1, 0, NULL, "samples");
    return s;
}

static int s_len(lua_State *L) {
    lua_pushinteger(L, checksamples(L, "#")->n);
    return 1;
}

/* s:sum(): the sum of every coordinate (a checksum) */
static int s_sum(lua_State *L) {
    lsamples *s = checksamples(L, "s:sum");
    double sum = 0;
    for (long i = 0; i < s->n * (s->dim ? s->dim : 1); i++) sum += s->v[i];
    lua_pushnumber(L, sum);
    return 1;
}

static int s_index(lua_State *L) {
    lsamples *s = checksamples(L, "samples");
    if (lua_type(L, 2) == LUA_TNUMBER) {
        lua_Integer i = lua_tointeger(L, 2);
        if (i < 1 || i > s->n) {
            lua_pushnil(L);
            return 1;
        }
        if (!s->dim) lua_pushnumber(L, s->v[i - 1]);
        else pcl_pushpoint(L, s->dim, s->v + (size_t)(i - 1) * (size_t)s->dim);
        return 1;
    }
    const char *k = lua_tostring(L, 2);
    if (k && !strcmp(k, "sum")) { lua_pushcfunction(L, s_sum); return 1; }
    if (k && !strcmp(k, "dim")) { lua_pushinteger(L, s->dim); return 1; }
    lua_pushnil(L);
    return 1;
}

static int s_tostring(lua_State *L) {
    lsamples *s = checksamples(L, "tostring");
    lua_pushfstring(L, "samples(%d, %d-D)", (int)s->n, s->dim);
    return 1;
}

/* ---- curve(M, t0, t1), surface(M, u0, u1, v0, v1) ------------------------------------------------ */

/* the membership condition over the parameters' box */
static void check_weight(lua_State *L, const char *fname, pc_expr_prog *prog, const double *lo,
                         const double *hi, const int *in) {
    double xb[PC_EXPR_MAXPARAM], wb;
    int kind = pc_expr_prog_weight(prog, lo, hi, xb, &wb);
    if (kind == PC_KIND_POINT) return;
    pc_expr_prog_free(prog);
    if (kind == PC_KIND_VECTOR)
        pcl_error(L, "%s: argument #1 (equation) is a vector equation (weight 0), not a point: %s; "
                  "to place a vector, add it to a point, e.g. P(0, 0) + v", fname, MEMBERSHIP);
    if (kind == -2)
        pcl_error(L, "%s: argument #1 (equation) has no finite value anywhere it was probed in "
                  "its domain", fname);
    const char *at = lua_pushfstring(L, "%s = %s", pc_expr_param_name(pool(L), in[0]), pcl_pushnum(L, xb[0]));
    pcl_error(L, "%s: argument #1 (equation) has weight %s at %s, so it is neither a point "
              "(weight 1) nor a vector (weight 0): %s; write offsets with V(), or divide a "
              "rational equation by its total weight", fname, pcl_pushnum(L, wb), at, MEMBERSHIP);
}

static pc_expr_prog *compile_for(lua_State *L, const char *fname, int nwant, int *in) {
    leq *e = toeq(L, 1);
    pc_expr_pool *p = pool(L);
    if (!pc_expr_dim(p, e->id))
        pcl_error(L, "%s: argument #1 (equation) must be a point equation, got a scalar equation", fname);
    int n = params_of(L, e->id, in);
    if (n != nwant) {
        if (n == 0) pcl_error(L, "%s: argument #1 (equation) has no parameter (it is the constant %s)",
                              fname, luaL_tolstring(L, 1, NULL));
        pcl_error(L, "%s: argument #1 (equation) depends on %s, but a %s has %d parameter%s: fix "
                  "the others with M:with{name = value}", fname, names_of(L, n, in),
                  nwant == 1 ? "curve" : "surface", nwant, nwant == 1 ? "" : "s");
    }
    int st;
    pc_expr_prog *prog = pc_expr_compile(p, e->id, n, in, &st);
    if (!prog) raise_status(L, fname, st);
    return prog;
}

pc_curve *pcl_eq_curve(lua_State *L, const char *fname, int *status) {
    double t0 = pcl_checknum(L, fname, 2, "t0"), t1 = pcl_checknum(L, fname, 3, "t1");
    if (!(t1 > t0)) pcl_error(L, "%s: argument #3 (t1) must be greater than t0", fname);
    int in[PC_EXPR_MAXPARAM];
    pc_expr_prog *prog = compile_for(L, fname, 1, in);
    check_weight(L, fname, prog, &t0, &t1, in);
    return pc_expr_curve(prog, t0, t1, status);
}

pc_surface *pcl_eq_surface(lua_State *L, const char *fname, int *status) {
    double r[4];
    static const char *names[4] = {"u0", "u1", "v0", "v1"};
    for (int i = 0; i < 4; i++) r[i] = pcl_checknum(L, fname, i + 2, names[i]);
    if (!(r[1] > r[0]) || !(r[3] > r[2])) pcl_error(L, "%s: need u0 < u1 and v0 < v1", fname);
    int in[PC_EXPR_MAXPARAM];
    pc_expr_prog *prog = compile_for(L, fname, 2, in);
    double lo[2] = {r[0], r[2]}, hi[2] = {r[1], r[3]};
    check_weight(L, fname, prog, lo, hi, in);
    return pc_expr_surface(prog, r[0], r[1], r[2], r[3], status);
}

/* ---- registration ----------------------------------------------------------------------------------- */

void pcl_open_expr(lua_State *L) {
    int module = lua_gettop(L);
    pc_expr_pool **pp = lua_newuserdatauv(L, sizeof *pp, 0);
    *pp = pc_expr_pool_new();
    if (!*pp) luaL_error(L, "equations: out of memory");
    lua_newtable(L);
    lua_pushcfunction(L, pool_gc);
    lua_setfield(L, -2, "__gc");
    lua_setmetatable(L, -2);
    lua_rawsetp(L, LUA_REGISTRYINDEX, &POOL_KEY);

    luaL_newmetatable(L, EQ_MT);
    static const luaL_Reg meta[] = {
        {"__add", m_add}, {"__sub", m_sub}, {"__mul", m_mul}, {"__div", m_div}, {"__unm", m_unm},
        {"__pow", m_pow}, {"__eq", m_eq}, {"__call", eq_call}, {"__tostring", eq_tostring},
        {"__concat", eq_concat}, {"__gc", eq_gc}, {NULL, NULL}};
    luaL_setfuncs(L, meta, 0);
    lua_newtable(L);
    static const luaL_Reg methods[] = {
        {"with", eq_with}, {"show", eq_show}, {"sample", eq_sample}, {NULL, NULL}};
    luaL_setfuncs(L, methods, 0);
    lua_pushcclosure(L, eq_index, 1);
    lua_setfield(L, -2, "__index");
    lua_pop(L, 1);

    luaL_newmetatable(L, SAMPLES_MT);
    static const luaL_Reg smeta[] = {
        {"__len", s_len}, {"__index", s_index}, {"__tostring", s_tostring}, {NULL, NULL}};
    luaL_setfuncs(L, smeta, 0);
    lua_pop(L, 1);

    lua_pushcfunction(L, l_param);
    lua_setfield(L, module, "param");
    wrap_math(L);
    lua_settop(L, module);
}
