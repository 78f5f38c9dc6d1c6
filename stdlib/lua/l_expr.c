/* Binding of the point equations (stdlib/geom/expr.h): param "t" makes a symbolic parameter,
 * and arithmetic on it builds an equation (M = A*bar(t)^2 + 2*B*t*bar(t) + C*t^2), evaluated
 * as M(0.3) or M{t = .3}, shown, expanded and sampled by its methods (declared below).
 * The hooks (pcl_expr.h) run inside a declared point function (lerp, dot, P, ...) and word
 * their messages with its name, the metamethods (+ - * / ^) with the operation; the core
 * checks the operands and words what is wrong (pc_expr_apply).
 * Every Lua state has one pool of nodes (the equations share their common parts); compiled
 * programs are copies, so curves outlive nothing.  The math functions are wrapped once for
 * the whole module: a number goes straight to Lua's own function. */
#include "pcl_args.h"
#include "pcl_core.h"
#include "pcl_expr.h"
#include "pcl_point.h"
#include "pcl_tagged.h"
#include "konop_expanded.h"   /* the book's printed form of expanded coordinates */

#define EQ_MT "equation"
static const char EQ_TAG = 'e', SAMPLES_TAG = 'S';   /* its address tags the type (PCL_SELF_TAG) */
#define SAMPLES_MT "samples"
static const char POOL_KEY = 'q';

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

static int pool_gc(lua_State *L) {
    pc_expr_pool **pp = lua_touserdata(L, 1);   /* the registry's, never a script's */
    pc_expr_pool_free(*pp);
    *pp = NULL;
    return 0;
}

static pc_expr_pool *pool(lua_State *L) {
    lua_rawgetp(L, LUA_REGISTRYINDEX, &POOL_KEY);
    pc_expr_pool **pp = lua_touserdata(L, -1);
    lua_pop(L, 1);
    if (!pp || !*pp) luaL_error(L, "equations: the pool is gone");
    return *pp;
}

static void *toeq(lua_State *L, int idx) { return pcl_tagged_udata(L, idx, &EQ_TAG, EQ_MT, sizeof(leq), 0); }

/* Samples: exactly the header and n values of max(dim, 1) numbers (pcl.h: forged userdata). */
static void *tosamples(lua_State *L, int idx) {
    lsamples *s = pcl_tagged_udata(L, idx, &SAMPLES_TAG, SAMPLES_MT, sizeof *s, PCL_TAG_ATLEAST);
    size_t len = lua_rawlen(L, idx);
    int ok = !s || (s->dim >= 0 && s->dim <= PC_MAXDIM && s->n >= 0 && (size_t)s->n <= len / sizeof(double) &&
                    len == sizeof *s + sizeof(double) * (size_t)s->n * (size_t)(s->dim ? s->dim : 1));
    return pcl_genuine(L, idx, s, ok, SAMPLES_MT);
}

int pcl_isequation(lua_State *L, int idx) { return toeq(L, idx) != NULL; }

static int push_eq(lua_State *L, int id) {
    leq *e = pcl_tagged_new(L, sizeof *e, &EQ_TAG, EQ_MT);
    *e = (leq){e->self, id, NULL};
    return 1;
}

static int eq_gc(lua_State *L) {
    leq *e = pcl_tagged_udata(L, 1, &EQ_TAG, EQ_MT, sizeof *e, PCL_TAG_GC);   /* never a forged one */
    if (e) {
        pc_expr_prog_free(e->prog);
        e->prog = NULL;
    }
    return 0;
}

/* "a 2-D point equation", "a scalar equation", "a number", "a point", ... */
static const char *describe(lua_State *L, int idx) {
    leq *e = toeq(L, idx);
    pcl_value *v = e ? NULL : pcl_tovalue(L, idx);
    int d = e ? pc_expr_dim(pool(L), e->id) : 0;
    if (e) return d ? lua_pushfstring(L, "a %d-D point equation", d) : "a scalar equation";
    if (v) return lua_pushfstring(L, "the %d-D value %s", v->n, luaL_tolstring(L, idx, NULL));
    return lua_type(L, idx) == LUA_TNUMBER ? "a number" : lua_pushfstring(L, "a %s", luaL_typename(L, idx));
}

/* The node of an operand: an equation, a number (a constant), a point or vector (a constant
 * value); -1 for anything else. */
static int node_of(lua_State *L, int idx) {
    leq *e = toeq(L, idx);
    pcl_value *v = e ? NULL : pcl_tovalue(L, idx);
    double x = lua_tonumber(L, idx);
    int st;
    if (e) return e->id;
    if (v) return pc_expr_vconst(pool(L), v->n, v->h, &st);
    return lua_type(L, idx) == LUA_TNUMBER && isfinite(x) ? pc_expr_const(pool(L), x, &st) : -1;
}

/* v of the n operands from stack index first: push the results, or raise the core's message
 * with each "@k" replaced by what operand k is (a metamethod's message is whole) */
static int apply(lua_State *L, pc_expr_verb v, int first, int n, const pc_expr_how *how) {
    int ids[PC_MAXDIM], res[3], given = n < PC_MAXDIM ? n : PC_MAXDIM;
    char why[512];
    for (int i = 0; i < given; i++) ids[i] = node_of(L, first + i);
    int m = pc_expr_apply(pool(L), v, n, ids, how, res, why, sizeof why);
    if (m < 0) {
        const char *msg = why;
        for (int k = given; k >= 1; k--)
            msg = luaL_gsub(L, msg, lua_pushfstring(L, "@%d", k), describe(L, first + k - 1));
        return v <= PC_EQV_NEG || v == PC_EQV_POW ? pcl_error(L, "%s", msg) : pcl_fail(L, "%s", msg);
    }
    for (int i = 0; i < m; i++) push_eq(L, res[i]);
    return m;
}

static int m_add(lua_State *L) { return apply(L, PC_EQV_ADD, 1, 2, NULL); }
static int m_sub(lua_State *L) { return apply(L, PC_EQV_SUB, 1, 2, NULL); }
static int m_mul(lua_State *L) { return apply(L, PC_EQV_MUL, 1, 2, NULL); }
static int m_div(lua_State *L) { return apply(L, PC_EQV_DIV, 1, 2, NULL); }
static int m_unm(lua_State *L) { return apply(L, PC_EQV_NEG, 1, 1, NULL); }
static int m_pow(lua_State *L) { return apply(L, PC_EQV_POW, 1, 2, NULL); }

static int m_eq(lua_State *L) {
    leq *a = toeq(L, 1), *b = toeq(L, 2);
    return pcl_push_results(L, 0, "b", a && b && a->id == b->id);   /* hash-consed: one node, one equation */
}

/* the operands each hook looks at for an equation (-1: all); the order of pc_expr_verb */
static const signed char HOOK_ARGS[] = {2, 2, 2, 2, 1, 3, 1, 2, 2, 1, -1, -1, 4};

int pcl_eq_hook(lua_State *L, pc_expr_verb op) {
    int n = HOOK_ARGS[op] < 0 ? lua_gettop(L) : HOOK_ARGS[op];
    for (int i = 1; i <= n; i++)
        if (toeq(L, i)) return apply(L, op, 1, n, NULL);
    return 0;
}

int pcl_eq_curve_apply(lua_State *L, const pc_curve *c, int idx) {
    leq *e = toeq(L, idx);
    char why[512];
    int r = e ? pc_expr_curve_at(pool(L), c, e->id, why, sizeof why) : 0;
    if (r < 0) return pcl_error(L, "curve: %s", why);   /* c(t) names "curve" itself (it may not be declared) */
    return e ? push_eq(L, r) : 0;
}

int pcl_eq_smooth(lua_State *L, int idx, const pc_gfun *g) {
    return toeq(L, idx) ? apply(L, PC_EQV_SMOOTH, idx, 1, &(pc_expr_how){.g = g}) : 0;
}

/* the base of math.log(x, base): a positive number other than 1 */
static int read_base(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    out->x = lua_tonumber(L, idx);
    return lua_type(L, idx) == LUA_TNUMBER && isfinite(out->x) && out->x > 0 && out->x != 1;
}
static const pcl_arg base_arg = A_ANY("base", read_base, "a positive number other than 1");

/* math.NAME, upvalues Lua's own function and the index into MATHDECL: a number takes one type
 * test and goes to Lua's function, so math.sin(x) keeps its speed (and Lua's own messages for
 * what is neither a number nor an equation). */
static int math_fn(lua_State *L) {
    if (lua_type(L, 1) == LUA_TNUMBER || !toeq(L, 1)) return lua_tocfunction(L, PCL_UPVALUE(1))(L);
    pc_expr_op fn = PC_EX_SIN + (pc_expr_op)lua_tointeger(L, PCL_UPVALUE(2));   /* MATHDECL order */
    pcl_val base = {0};
    if (fn == PC_EX_LOG && !lua_isnoneornil(L, 2) && !pc_expr_dim(pool(L), node_of(L, 1)))
        pcl_readone(L, 2, 2, 0, &base_arg, 0, &base);                           /* log(x, base) */
    return apply(L, PC_EQV_MATH, 1, 1, &(pc_expr_how){.fn = fn, .base = base.x});
}

static const pcl_arg x_arg[] = {A_ANY("x", NULL, "a number or a scalar equation"), PCL_END};
#define MATHDECL(nm) {PCL_FN("math." nm, math_fn, x_arg, "number | equation", \
                             "Lua's math." nm " of a number; of a scalar equation (param), the equation of it."), PCL_END}
static const pcl_fn MATHDECL[][2] = {
    MATHDECL("sin"), MATHDECL("cos"), MATHDECL("tan"), MATHDECL("exp"),
    {{.name = "math.log", .fn = math_fn, .sig = "math.log(x [, base]) -> number | equation", .help = "Lua's math.log of a number; of a scalar equation (param), the equation of its logarithm (to base, default e)."}, PCL_END},
    MATHDECL("sqrt"), MATHDECL("abs")};

/* (pcl_open_expr restores the stack) */
static void wrap_math(lua_State *L) {
    if (lua_getglobal(L, "math") != LUA_TTABLE) return;
    for (int i = 0; i < (int)(sizeof MATHDECL / sizeof *MATHDECL); i++) {
        lua_getfield(L, -1, MATHDECL[i][0].name + 5);   /* "math.sin" */
        lua_CFunction f = lua_tocfunction(L, -1);
        if (f == math_fn) lua_getupvalue(L, -1, 2);   /* wrapped already: Lua's function again */
        lua_CFunction orig = lua_tocfunction(L, -1);
        lua_settop(L, lua_gettop(L) - (f == math_fn ? 2 : 1));
        if (!orig) continue;                          /* not Lua's: left alone */
        lua_pushcfunction(L, orig);
        lua_pushinteger(L, i);
        pcl_register(L, -3, MATHDECL[i], 2);
    }
}

/* a parameter's name: a string of 1 to 31 characters without a zero byte */
static int read_name(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    size_t len = 0;
    out->s = lua_type(L, idx) == LUA_TSTRING ? lua_tolstring(L, idx, &len) : NULL;
    return out->s && len > 0 && len < PC_EXPR_MAXNAME && strlen(out->s) == len;
}
static const pcl_arg param_args[] = {A_ANY("name", read_name, "a name of 1 to 31 characters"), PCL_END};
PCL_BODY(l_param, a) {
    int st, id = pc_expr_param(pool(L), a[0].s, &st);
    if (id < 0) return pcl_fail(L, "at most %d parameters per script, and %s would be one more", PC_EXPR_MAXPARAM, a[0].s);
    return push_eq(L, id);
}
/* "t and s", "t, s and u"; "none" */
static const char *names_of(lua_State *L, int n, const int *in) {
    char buf[PC_EXPR_MAXPARAM * (PC_EXPR_MAXNAME + 2)];
    pc_expr_param_names(pool(L), n, in, buf, sizeof buf);
    return lua_pushstring(L, n ? buf : "none");
}

/* the program of e, compiled on first use with its parameters in order as inputs */
static pc_expr_prog *prog_of(lua_State *L, leq *e) {
    int in[PC_EXPR_MAXPARAM], st;
    if (!e->prog) e->prog = pc_expr_compile(pool(L), e->id, pc_expr_param_list(pool(L), e->id, in), in, &st);
    if (!e->prog) pcl_fail(L, "%s", pc_expr_why(st));
    return e->prog;
}

/* The table at 2 as an option table whose keys are the parameters in[0..n-1], each declared
 * as key (keys: n + 1), into v: M{t = ..., s = ...} and M:with{s = ...} are read and worded by
 * the layer. */
static void read_named(lua_State *L, int n, const int *in, pcl_arg key, pcl_arg *keys, pcl_val *v) {
    pcl_arg table = {.name = "values", .kind = PCL_OPTIONS, .keys = keys};
    for (int j = 0; j < n; j++) {
        keys[j] = key;
        keys[j].name = pc_expr_param_name(pool(L), in[j]);
    }
    keys[n] = (pcl_arg){0};
    pcl_read_options(L, 2, 1, &table, v);
}

/* M(t [, s ...]) with values in the order of M.params, or M{t = ..., s = ...} */
static int eq_call(lua_State *L) {
    leq *e = toeq(L, 1);                  /* a __call: always an equation (the hot path) */
    pc_expr_pool *p = pool(L);
    int in[PC_EXPR_MAXPARAM], n = pc_expr_param_list(p, e->id, in), given = lua_gettop(L) - 1;
    int named = lua_istable(L, 2), dim = pc_expr_dim(p, e->id);
    double x[PC_EXPR_MAXPARAM], h[PC_MAXDIM + 1];
    char why[512];
    pcl_arg keys[PC_EXPR_MAXPARAM + 1];
    pcl_val v[PC_EXPR_MAXPARAM] = {0};
    if (named) read_named(L, n, in, (pcl_arg){.kind = PCL_NUMBER, .flags = PCL_REQ}, keys, v);
    else if (given != n)
        return pcl_fail(L, "needs %d parameter value%s (%s), got %d", n, n == 1 ? "" : "s", names_of(L, n, in), given);
    for (int j = 0; j < n; j++) {
        pcl_arg num = {.name = pc_expr_param_name(p, in[j]), .kind = PCL_NUMBER};
        x[j] = named ? v[j].x : lua_tonumber(L, j + 2);
        if (!named && (lua_type(L, j + 2) != LUA_TNUMBER || !isfinite(x[j])))
            pcl_readone(L, j + 2, j + 1, 0, &num, 0, v);
    }
    if (pc_expr_value_at(p, prog_of(L, e), n, in, x, h, why, sizeof why) != PC_OK) return pcl_fail(L, "%s", why);
    return pcl_push_packed(L, dim, dim ? "w" : "n", h);
}

/* A value of M:with{s = ...}: a number or a scalar equation, its node into out->n. */
static int read_subst(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    out->n = node_of(L, idx);
    return out->n >= 0 && !pc_expr_dim(pool(L), out->n);
}

static const pcl_arg with_args[] = {{.name = "values", .kind = PCL_TABLE, .expect = "a table {name = value}"}, PCL_END};
PCL_METHOD(eq_with, leq *e, a) {
    pcl_val v[PC_EXPR_MAXPARAM] = {0};
    pcl_arg keys[PC_EXPR_MAXPARAM + 1];
    int in[PC_EXPR_MAXPARAM], n = pc_expr_param_list(pool(L), e->id, in), r = e->id, st;
    read_named(L, n, in, (pcl_arg)A_ANY(NULL, read_subst, "a number or a scalar equation"), keys, v);
    for (int j = 0; j < n; j++)
        if (v[j].present && (r = pc_expr_subst(pool(L), r, in[j], v[j].n, &st)) < 0)
            return pcl_keyfail(L, keys[j].name, "cannot be substituted: %s", pc_strerror(st));
    return push_eq(L, r);
}

/* The names given to M:show, looked up by value */
typedef struct { lua_State *L; int tbl; } namer_ud;

static const char *namer(void *ud, int dim, const double *h) {
    namer_ud *n = ud;
    lua_State *L = n->L;
    lua_pushnil(L);
    while (lua_next(L, n->tbl)) {
        pcl_value *v = pcl_tovalue(L, -1);
        int same = v && lua_type(L, -2) == LUA_TSTRING && pc_value_same(v->n, v->h, dim, h);
        lua_pop(L, 1);
        if (same) {
            const char *name = lua_tostring(L, -1);   /* the key, which stays in the table */
            lua_pop(L, 1);
            return name;
        }
    }
    return NULL;
}

/* the text of equation id (names: the stack index of M:show's table, or 0), measured first */
static int push_text(lua_State *L, int id, int names) {
    namer_ud ud = {L, names};   /* (the namer's use of the stack is balanced, as a buffer needs) */
    luaL_Buffer b;
    size_t len = (size_t)pc_expr_print(pool(L), id, names ? namer : NULL, &ud, NULL, 0);
    pc_expr_print(pool(L), id, names ? namer : NULL, &ud, luaL_buffinitsize(L, &b, len + 1), len + 1);
    luaL_pushresultsize(&b, len);
    return 1;
}

static int eq_tostring(lua_State *L) {
    leq *e = pcl_meta_self(L, toeq(L, 1), "tostring: not an equation");
    return push_text(L, e->id, 0);
}

static const pcl_arg show_args[] = {{.name = "names", .kind = PCL_TABLE, .flags = PCL_OPT, .expect = "a table {A = A, ...}"}, PCL_END};
PCL_METHOD(eq_show, leq *e, a) {
    return push_text(L, e->id, a[0].present ? 2 : 0);
}

/* M:expanded(): the coordinates expanded in powers of the equation's one parameter as the
 * book prints them (konop_expanded.h); at most PC_MAXDIM results: LUA_MINSTACK has room */
PCL_METHOD(eq_expanded, leq *e, a) {
    enum { EACH = 4096 };
    char *texts = lua_newuserdatauv(L, (size_t)PC_MAXDIM * EACH, 0), why[512];
    int axes = pc_k_expanded(pool(L), e->id, texts, EACH, why, sizeof why);
    if (axes < 0) return pcl_fail(L, "%s", why);
    for (int x = 0; x < axes; x++) lua_pushstring(L, texts + (size_t)x * EACH);
    return axes;
}

/* M:sample(a, b, n [, into]): n values at t = a .. b in C, into a new samples object or into the
 * one given (of that size: a renderer resampling every frame allocates nothing) */
static const pcl_arg sample_args[] = {A_NUM("a"), A_NUM("b"),
    {.name = "n", .kind = PCL_INTEGER, .flags = PCL_OPT | PCL_RANGE, .lo = 1, .hi = 1e8, .dflt = 1001, .expect = "a count from 1 to 10^8"},
    {.name = "into", .kind = PCL_ANY, .flags = PCL_OPT, .expect = "samples (from M:sample)"}, PCL_END};
PCL_METHOD(eq_sample, leq *e, a) {
    long n = (long)a[2].x;
    int in[PC_EXPR_MAXPARAM], np = pc_expr_param_list(pool(L), e->id, in);
    if (np != 1) return pcl_fail(L, "the equation must have one parameter, it has %s", names_of(L, np, in));
    pc_expr_prog *prog = prog_of(L, e);
    int dim = pc_expr_prog_dim(prog), w = dim ? dim : 1;
    char why[256];
    lsamples *s;
    if (a[3].present) {                           /* M:sample(a, b, n, s): into s again */
        s = tosamples(L, 5);
        if (!s || s->n != n || s->dim != dim)
            return pcl_argfail(L, 4, "must be samples of %d %d-D values (from M:sample), got %s", (int)n, dim, luaL_tolstring(L, 5, NULL));
        lua_pushvalue(L, 5);
    } else {
        s = pcl_tagged_new(L, sizeof *s + sizeof(double) * (size_t)n * (size_t)w, &SAMPLES_TAG, SAMPLES_MT);
        *s = (lsamples){s->self, n, dim};
    }
    if (pc_expr_sample_at(pool(L), prog, in[0], a[0].x, a[1].x, n, s->v, why, sizeof why) != PC_OK)
        return pcl_fail(L, "%s", why);
    return 1;
}

/* the fields M.dim and M.params (the parameters' names in order), then the methods */
static int eq_index(lua_State *L) {
    leq *e = toeq(L, 1);
    const char *k = e ? lua_tostring(L, 2) : NULL;
    int in[PC_EXPR_MAXPARAM], n = k && !strcmp(k, "params") ? pc_expr_param_list(pool(L), e->id, in) : -1;
    if (k && !strcmp(k, "dim")) lua_pushinteger(L, pc_expr_dim(pool(L), e->id));
    else if (n < 0) lua_rawget(L, lua_upvalueindex(1));   /* the key at 2, on the top */
    else lua_createtable(L, n, 0);
    for (int j = 0; j < n; j++) {
        lua_pushstring(L, pc_expr_param_name(pool(L), in[j]));
        lua_rawseti(L, -2, j + 1);
    }
    return 1;
}

static int s_len(lua_State *L) {
    lsamples *s = pcl_meta_self(L, tosamples(L, 1), "#: not samples");
    return pcl_push_results(L, 0, "i", (int)s->n);
}

/* s:sum(): the sum of every coordinate (a checksum) */
PCL_METHOD(s_sum, lsamples *s, a) {
    double sum = 0;
    for (long i = 0; i < s->n * (s->dim ? s->dim : 1); i++) sum += s->v[i];
    return pcl_push_results(L, 0, "n", sum);
}

/* s[i] (a number or a point; nil past the ends), s.dim, then the methods */
static int s_index(lua_State *L) {
    lsamples *s = pcl_meta_self(L, tosamples(L, 1), "index: not samples");
    lua_Integer i = lua_type(L, 2) == LUA_TNUMBER ? lua_tointeger(L, 2) : 0;   /* 0: not integral */
    const char *k = lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : NULL;
    int in = i >= 1 && i <= s->n;
    if (in && !s->dim) lua_pushnumber(L, s->v[i - 1]);
    else if (in) pcl_pushpoint(L, s->dim, s->v + (size_t)(i - 1) * (size_t)s->dim);
    else if (k && !strcmp(k, "dim")) lua_pushinteger(L, s->dim);
    else lua_rawget(L, lua_upvalueindex(1));   /* the key at 2, on the top: sum, or nil */
    return 1;
}

static int s_tostring(lua_State *L) {
    lsamples *s = pcl_meta_self(L, tosamples(L, 1), "tostring: not samples");
    lua_pushfstring(L, "samples(%d, %d-D)", (int)s->n, s->dim);
    return 1;
}

void *pcl_eq_object(lua_State *L, int nwant, const double *lo, const double *hi, int *status) {
    char why[1024];
    pc_expr_prog *prog = pc_expr_compile_point(pool(L), node_of(L, 1), nwant, lo, hi, why, sizeof why);
    if (!prog) pcl_error(L, "%s: %s", pcl_name(L), luaL_gsub(L, why, "@1", luaL_tolstring(L, 1, NULL)));
    if (nwant == 1) return pc_expr_curve(prog, lo[0], hi[0], status);
    return pc_expr_surface(prog, lo[0], hi[0], lo[1], hi[1], status);
}

#define METHOD(nm, f, a, forms, text) {.name = nm, .fn = f, .args = a, .sig = forms, .help = text, .self = toeq, .selftype = "equation"}
static const pcl_fn methods[] = {
    METHOD("M:with", eq_with, with_args, "M:with{s = value | equation, ...} -> equation", "The one-parameter family M(t; s) at a value of s (or with s replaced by another equation)."),
    METHOD("M:show", eq_show, show_args, "M:show{A = A, B = B, ...} -> string", "The equation in the book's notation with the points named (tostring(M) prints them as P(x, y))."),
    METHOD("M:expanded", eq_expanded, NULL, "M:expanded() -> x, y, ...", "The coordinates expanded in powers of the equation's one parameter as the book prints them: x = 3t^2 - 2t + 1, or for a rational equation x = (numerator)/(denominator) with the denominator monic; numbers in %.6g; a scalar equation gives its one expression."),
    METHOD("M:sample", eq_sample, sample_args, "M:sample(a, b [, n = 1001 [, s]]) -> samples", "n values at evenly spaced t in [a, b], computed in C (into s when given): #s, s[i] (a point), s:sum()."),
    PCL_END};
static const pcl_fn call[] = {{.name = "M", .fn = eq_call, .self = toeq, .selftype = "equation", .key = "__call", .topic = "M(t)", .callname = 1, .sig = "M(t [, s ...]) -> value\nM{t = ..., s = ...} -> value", .help = "The equation's value at parameter values given in the order of M.params, or by name."}, PCL_END};
static const pcl_fn sample_methods[] = {{.name = "s:sum", .fn = s_sum, .result = "number", .self = tosamples, .selftype = "samples object", .help = "The sum of every coordinate of the samples of M:sample (a checksum)."}, PCL_END};
static const pcl_fn fns[] = {
    PCL_FN("param", l_param, param_args, "equation", "A symbolic parameter: local t = param \"t\"; then A*bar(t)^2 + 2*B*t*bar(t) + C*t^2 (with + - * / ^, lerp bar dot cross unit P V, math.sin ... and the smoothsteps) is an equation, not a value."),
    PCL_END};

void pcl_open_expr(lua_State *L) {
    int module = lua_gettop(L);
    pc_expr_pool **pp = lua_newuserdatauv(L, sizeof *pp, 0);
    *pp = pc_expr_pool_new();
    if (!*pp) luaL_error(L, "equations: out of memory");
    lua_newtable(L);
    luaL_setfuncs(L, (const luaL_Reg[]){{"__gc", pool_gc}, {NULL, NULL}}, 0);
    lua_setmetatable(L, -2);
    lua_rawsetp(L, LUA_REGISTRYINDEX, &POOL_KEY);

    static const luaL_Reg meta[] = {
        {"__add", m_add}, {"__sub", m_sub}, {"__mul", m_mul}, {"__div", m_div}, {"__unm", m_unm},
        {"__pow", m_pow}, {"__eq", m_eq}, {"__tostring", eq_tostring}, {"__concat", pcl_concat},
        {"__gc", eq_gc}, {NULL, NULL}};
    pcl_open_type(L, EQ_MT, meta, call, methods, eq_index);
    static const luaL_Reg smeta[] = {{"__len", s_len}, {"__tostring", s_tostring}, {NULL, NULL}};
    pcl_open_type(L, SAMPLES_MT, smeta, NULL, sample_methods, s_index);

    pcl_register(L, module, fns, 0);
    wrap_math(L);
    lua_settop(L, module);
}
