/* Binding of the one curve type (stdlib/geom/curve.h) and its constructors, Stepanov's curves
 * among them (examples 5, 10, 12).  All are one userdata "curve"; its methods are in the table
 * _tk.curve_methods, to which l_camera.c adds c:draw and stdlib/lua/curves.lua c:each. */
#include "pcl_args.h"
#include "pcl_core.h"
#include "spline.h"
#include "fourier.h"
#include "curve_text.h"
#include "pcl_expr.h"
#include "curve_why.h"
#include "curve_path.h"
#include "pcl_tagged.h"

#define CURVE_MT "curve"
static const char CURVE_TAG = 'c';   /* its address tags the type (PCL_SELF_TAG) */

typedef struct {
    PCL_SELF;           /* its own address: a forged curve is refused (pcl.h) */
    pc_curve *c;
    const char *kind;   /* the constructor's name (a static string) */
} lcurve;

/* ---- Lua functions called from the core (pcl_luafn, pcl_core.h) -----------------------------
 * For curve(f), whose function's nargs is the dimension of its values (it is called with t
 * alone), and for strokes whose smoothstep is a Lua function. */

/* The value a Lua curve function returned (the top nres results) as homogeneous h: its
 * dimension, or 0 with the message pushed.  dim 0: any dimension (the call that finds it). */
static int read_result(lua_State *L, int nres, int dim, double *h) {
    int base = lua_gettop(L) - nres + 1;
    pcl_value *v = nres >= 1 ? pcl_tovalue(L, base) : NULL;
    int d = v ? v->n : nres;
    const char *got = nres ? luaL_typename(L, base) : "nothing", *who = dim ? "curve: the function" : "a curve";
    const char *msg = NULL;   /* pushed when set */
    if (dim && d != dim)
        msg = v ? lua_pushfstring(L, "%s returned a %d-D value, but the curve is %d-D", who, d, dim)
                : lua_pushfstring(L, "%s must return a %d-D point or %d numbers, got %s", who, dim, dim, got);
    else if (d < 1 || d > PC_MAXDIM)
        msg = lua_pushfstring(L, "%s must return a point or 1..%d numbers, got %s", who, PC_MAXDIM, got);
    for (int k = 0; !msg && !v && k < d; k++) {
        int isnum;
        h[k] = lua_tonumberx(L, base + k, &isnum);
        got = luaL_typename(L, base + k);
        if (!isnum) msg = lua_pushfstring(L, "%s must return a point or numbers, got %s", who, got);
    }
    if (msg) return 0;
    if (v) memcpy(h, v->h, sizeof(double) * (size_t)(d + 1));
    else h[d] = 1;
    return d;
}

static int luafn_eval(void *ud, double t, int order, double *out) {
    pcl_luafn *f = ud;
    lua_State *L = pcl_current_state();
    if (order > 0) return PC_EDOMAIN;            /* the core differences */
    int top = lua_gettop(L);
    if (!lua_checkstack(L, f->nargs + 4)) return PC_ENOMEM;
    lua_rawgeti(L, LUA_REGISTRYINDEX, f->ref[0]);
    lua_pushnumber(L, t);
    if (lua_pcall(L, 1, LUA_MULTRET, 0) != LUA_OK) return pcl_callback_failed(L);
    if (!read_result(L, lua_gettop(L) - top, f->nargs, out)) return pcl_callback_failed(L);
    lua_settop(L, top);
    return PC_OK;
}

/* a stroke's Lua smoothstep g(t) (pc_gcall) */
static int luag_eval(void *ud, double t, double *g) {
    pcl_luafn *f = ud;
    int failed = f->failed;
    *g = pcl_luafn_call(f, 0, 0, "the smoothstep g", 1, &t);
    if (f->failed > failed) return PC_EARG;
    if (isfinite(*g)) return PC_OK;
    lua_State *L = pcl_current_state();
    const char *ts = pcl_pushnum(L, t), *gs = pcl_pushnum(L, *g);
    lua_pushfstring(L, "curve: the smoothstep g must return a finite number, got g(%s) = %s", ts, gs);
    return pcl_callback_failed(L);
}

/* ---- the userdata ---------------------------------------------------------------------------- */

int pcl_pushcurve(lua_State *L, pc_curve *c, const char *kind) {
    lcurve *u = pcl_tagged_new(L, sizeof *u, &CURVE_TAG, CURVE_MT);
    *u = (lcurve){u->self, c, kind};
    return 1;
}

int pcl_push_made(lua_State *L, pc_curve *c, const int *st, const char *kind) {
    if (!c) return pcl_raise_status(L, pcl_name(L), *st);
    return pcl_pushcurve(L, c, kind ? kind : pcl_name(L));
}

/* The curve object at idx or NULL; one given the metatable by the debug library is refused. */
static void *self_curve(lua_State *L, int idx) {
    lcurve *u = pcl_tagged_udata(L, idx, &CURVE_TAG, CURVE_MT, sizeof *u, 0);
    return u && u->c ? u : NULL;
}

pc_curve *pcl_tocurve(lua_State *L, int idx) {
    lcurve *u = self_curve(L, idx);
    return u ? u->c : NULL;
}

static int c_gc(lua_State *L) {
    lcurve *u = pcl_tagged_udata(L, 1, &CURVE_TAG, CURVE_MT, sizeof *u, PCL_TAG_GC);
    if (u && u->c) {   /* never a forged one */
        pcl_callback_state(L);
        pc_curve_release(u->c);
        u->c = NULL;
    }
    return 0;
}

/* The parameters of n nodes given as option key (or argument #k), checked by the core. */
static const double *params(lua_State *L, const pcl_val *v, int k, const char *key, int n, int any) {
    char why[160];
    if (!v->present) return NULL;
    if (pc_params_why(n, v->n, v->list, any, why, sizeof why) == PC_OK) return v->list;
    if (key) pcl_keyfail(L, key, "%s", why);
    pcl_argfail(L, k, "%s", why);
    return NULL;
}

/* ---- constructors ------------------------------------------------------------------------------ */

static const pcl_arg bezier_args[] = {A_VALUES("points", 2, PC_CURVE_MAXDEG + 1), PCL_END};
PCL_BODY(l_bezier, a) {
    int st;
    return pcl_push_made(L, pc_curve_bezier(a[0].dim, a[0].n, a[0].list, &st), &st, NULL);
}

pc_knot_kind pcl_checkknots(lua_State *L, int arg, int ncp, int degree, double **knots) {
    static const char *const kinds[] = {"open", "uniform", "periodic", NULL};
    static const pc_knot_kind kind_of[] = {PC_KNOTS_OPEN, PC_KNOTS_UNIFORM, PC_KNOTS_PERIODIC};
    static const pcl_arg named = {.name = "knots", .kind = PCL_ENUM, .choices = kinds,
                                  .expect = "\"open\", \"uniform\", \"periodic\" or a list of numbers"};
    static const pcl_arg list = A_NUMBERS("knots", 0, 0);
    pcl_val v = {0};
    char why[160];
    *knots = NULL;
    if (lua_isnoneornil(L, arg)) return PC_KNOTS_OPEN;
    pcl_readone(L, arg, arg, 0, lua_istable(L, arg) ? &list : &named, 0, &v);
    if (!lua_istable(L, arg)) return kind_of[v.n];
    if (pc_knots_why(ncp, degree, v.n, v.list, why, sizeof why) != PC_OK)
        pcl_error(L, "%s: argument #%d (knots) %s", pcl_name(L), arg, why);
    *knots = v.list;
    return PC_KNOTS_GIVEN;
}

static const pcl_arg bspline_args[] = {A_VALUES("points", 2, 0), {.name = "degree", .kind = PCL_INTEGER},
                                       {.name = "knots", .kind = PCL_ANY, .flags = PCL_OPT}, PCL_END};
PCL_BODY(l_bspline, a) {
    int m = a[0].n, st, periodic = lua_type(L, 3) == LUA_TSTRING && !strcmp(lua_tostring(L, 3), "periodic");
    char why[160];
    if (pc_bspline_degree_why(m, a[1].x, periodic, why, sizeof why) != PC_OK) return pcl_argfail(L, 2, "%s", why);
    double *knots;
    pc_knot_kind kk = pcl_checkknots(L, 3, m, (int)a[1].x, &knots);
    return pcl_push_made(L, pc_curve_bspline(a[0].dim, (int)a[1].x, m, a[0].list, kk, knots, &st), &st, NULL);
}

static const pcl_arg hermite_keys[] = {A_VECTORS("tin"), A_NUMBERS("u", 0, 0), {.name = "closed", .kind = PCL_BOOLEAN},
                                       PCL_END};
static const pcl_arg hermite_args[] = {{.name = "points", .kind = PCL_POINTS, .flags = PCL_SAMEDIM, .lo = 2},
                                       A_VECTORS("tangents"), A_OPTIONS("opts", hermite_keys), PCL_END};
PCL_BODY(l_hermite, a) {   /* points, tangents, opts, tin, u, closed */
    int n = a[0].n, st;
    if (a[1].n != n) return pcl_argfail(L, 2, "must hold %d vectors, got %d", n, a[1].n);
    if (a[3].present && a[3].n != n) return pcl_keyfail(L, "tin", "must hold %d vectors, got %d", n, a[3].n);
    pc_curve *c = pc_curve_hermite(a[0].dim, n, a[0].list, a[1].list, a[3].present ? a[3].list : NULL,
                                   params(L, &a[4], 3, "u", n, 0), (int)a[5].x, &st);
    return pcl_push_made(L, c, &st, NULL);
}

static const char *const ENDS[] = {"natural", "clamped", "periodic", NULL};
static const pcl_arg spline_keys[] = {A_ENUM("ends", ENDS), A_SAMEVECTOR("d0"), A_SAMEVECTOR("d1"),
                                      A_NUMBERS("u", 0, 0), PCL_END};
static const pcl_arg spline_args[] = {{.name = "points", .kind = PCL_POINTS, .flags = PCL_SAMEDIM, .lo = 2},
                                      A_OPTIONS("opts", spline_keys), PCL_END};
PCL_BODY(l_cubic_spline, a) {   /* points, opts, ends, d0, d1, u */
    static const pc_end_kind kinds[] = {PC_END_NATURAL, PC_END_CLAMPED, PC_END_PERIODIC};
    if (a[2].n == 1 && (!a[3].present || !a[4].present))
        return pcl_fail(L, "clamped ends need the end derivatives d0 and d1 (vectors)");
    int n = a[0].n, st;
    pc_curve *c = pc_curve_cubic_spline(a[0].dim, n, a[0].list, params(L, &a[5], 2, "u", n, 0),
                                        kinds[a[2].n], a[3].v, a[4].v, &st);
    return pcl_push_made(L, c, &st, NULL);
}

static const pcl_arg interpolate_args[] = {A_POINTS("points", 0, 2, PC_CURVE_MAXDEG + 1),
                                           {.name = "params", .kind = PCL_NUMBERS, .flags = PCL_OPT}, PCL_END};
PCL_BODY(l_interpolate, a) {
    int st;
    pc_curve *c = pc_curve_interpolate(a[0].dim, a[0].n, a[0].list, params(L, &a[1], 2, NULL, a[0].n, 1), &st);
    return pcl_push_made(L, c, &st, NULL);
}

static int read_curve_fn(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, PCL_UNUSED pcl_val *out) {
    return pcl_isequation(L, idx) || pcl_callable(L, idx);
}
static const pcl_arg curve_args[] = {{.name = "f", .kind = PCL_ANY, .read = read_curve_fn,
                                      .expect = "a function of t or an equation"}, A_NUM("t0"), A_NUM("t1"), PCL_END};
/* curve(f, t0, t1): the dimension is that of f(t0) */
PCL_BODY(l_curve, a) {
    int st;
    if (!(a[2].x > a[1].x)) return pcl_argfail(L, 3, "must be greater than t0");
    if (pcl_isequation(L, 1))                  /* a compiled point equation (l_expr.c) */
        return pcl_push_made(L, pcl_eq_object(L, 1, &a[1].x, &a[2].x, &st), &st, "equation");
    lua_settop(L, 3);
    lua_pushvalue(L, 1);
    lua_pushnumber(L, a[1].x);
    lua_call(L, 1, LUA_MULTRET);
    double h[PC_MAXDIM + 1];
    int d = read_result(L, lua_gettop(L) - 3, 0, h);
    if (!d) return pcl_fail(L, "%s", lua_tostring(L, -1));
    pcl_luafn *f = pcl_luafn_new(L, 1, (int[]){1});   /* its messages start "curve:" */
    f->nargs = d;
    pc_curve *c = pc_curve_func(d, a[1].x, a[2].x, 0, luafn_eval, pcl_luafn_free, f, &st);
    if (!c) pcl_luafn_free(f);
    return pcl_push_made(L, c, &st, NULL);
}

/* ---- Stepanov's curves ------------------------------------------------------------------------- */

/* The smoothstep at idx: nil (the default kind dflt), smooth.sine, smooth.cubic or a half-spline
 * object into g (1), any other callable (2: a Lua one); 0 if it is none of these. */
static int to_g(lua_State *L, int idx, int dflt, pc_gfun *g) {
    *g = (pc_gfun){.kind = (pc_gkind)dflt};
    if (lua_isnoneornil(L, idx)) return 1;
    int kind;
    pc_hspline *h;
    if (lua_iscfunction(L, idx) && pcl_smooth_isfunc(lua_tocfunction(L, idx), &kind)) g->kind = (pc_gkind)kind;
    else if ((h = pcl_tohspline(L, idx))) g->kind = PC_G_HALF, g->h = *h;
    else return pcl_callable(L, idx) ? 2 : 0;
    return 1;
}
static int read_g(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, PCL_UNUSED pcl_val *out) {
    pc_gfun g;
    return to_g(L, idx, PC_G_CUBIC, &g) != 0;
}

/* A stroke (or spline2) of np pieces as a curve: C smoothsteps in the core, a Lua one (at
 * stack index lua_g, else 0) through the callback. */
static int push_stroke(lua_State *L, int d, int np, int closed, const pc_piece *pc, int lua_g) {
    int st;
    pcl_luafn *f = lua_g ? pcl_luafn_new(L, 1, &lua_g) : NULL;   /* g(t): one number */
    if (f) f->fname = "curve";   /* "curve: the smoothstep g ...", as luag_eval's */
    pc_curve *c = pc_curve_stroke_fn(d, np, pc, closed, f ? luag_eval : NULL, f ? pcl_luafn_free : NULL, f,
                                     &st);
    if (!c && f) pcl_luafn_free(f);
    return pcl_push_made(L, c, &st, NULL);
}

#define G_ARG \
    {.name = "g", .kind = PCL_ANY, .flags = PCL_OPT, .read = read_g, .expect = "a smoothstep (a function of t)"}
static const pcl_arg spline2_args[] = {A_SAMEPOINT("A"), A_SAMEVECTOR("a"), A_SAMEPOINT("B"), A_SAMEVECTOR("b"),
                                       G_ARG, PCL_END};
PCL_BODY(l_spline2, a) {
    int d = a[0].n;
    pc_gfun g;
    pc_piece pc;
    int lua_g = to_g(L, 5, PC_G_CUBIC, &g) == 2 ? 5 : 0;
    pc_spline2_piece(d, a[0].v, a[1].v, a[2].v, a[3].v, &g, &pc);
    return push_stroke(L, d, 1, 0, &pc, lua_g);
}

/* the flat list of count numbers of argument a (NaN for an entry that is none), or NULL for nil */
static double *flat_numbers(lua_State *L, const pcl_val *a, int count, double *buf) {
    if (!a->present) return NULL;
    for (int i = 0; i < count; i++) {
        lua_geti(L, a->idx, i + 1);
        buf[i] = lua_isnumber(L, -1) ? lua_tonumber(L, -1) : NAN;
        lua_pop(L, 1);
    }
    return buf;
}

/* _tk.stroke(d, closed, nodes, ein, eout, rin, rout, n, m, t0 [, g]) -> curve, or
 * nil, status, bad node (1-based), message.  Arrays are flat (nodes, ein, eout: k rows of d)
 * with NaN for "default"; all but nodes may be nil. */
#define A_FLAT(nm) {.name = nm, .kind = PCL_TABLE, .flags = PCL_OPT}
static const pcl_arg stroke_args[] = {A_INT("d", 1, PC_CURVE_MAXDIM),
    {.name = "closed", .kind = PCL_BOOLEAN}, A_NUMBERS("nodes", 2, 0), A_FLAT("ein"), A_FLAT("eout"),
    A_FLAT("rin"), A_FLAT("rout"), A_FLAT("n"), A_FLAT("m"), A_FLAT("t0"), G_ARG, PCL_END};
PCL_BODY(l_stroke_raw, a) {
    int d = (int)a[0].x, closed = (int)a[1].x, k = a[2].n / d;
    if (k < 2) return pcl_argfail(L, 3, "must hold at least 2 nodes of %d numbers", d);
    double *buf = lua_newuserdatauv(L, sizeof(double) * (size_t)k * (size_t)(2 * d + 5), 0);
    double *arr[8] = {a[2].list};
    for (int i = 1, off = 0; i < 8; i++) {   /* ein, eout: rows of d; rin, rout, n, m, t0 */
        int len = i < 3 ? k * d : k;
        arr[i] = flat_numbers(L, &a[2 + i], len, buf + off);
        off += len;
    }
    pc_gfun g;
    int lua_g = to_g(L, 11, PC_G_HALF, &g) == 2 ? 11 : 0;
    int np = pc_stroke_npieces(k, closed), bad;
    pc_stroke_spec spec = {.d = d, .nnodes = k, .closed = closed, .nodes = arr[0], .ein = arr[1], .eout = arr[2],
                           .rin = arr[3], .rout = arr[4], .n = arr[5], .m = arr[6], .t0 = arr[7]};
    pc_piece *pc = lua_newuserdatauv(L, sizeof(pc_piece) * (size_t)np, 0);
    int st = pc_stroke_build(&spec, pc, &bad);
    if (st != PC_OK) {
        lua_pushnil(L);
        return pcl_push_results(L, 0, "i i s", st, bad + 1, pc_strerror(st)) + 1;
    }
    for (int i = 0; !lua_g && a[10].present && i < np; i++) pc[i].g = g;
    return push_stroke(L, d, np, closed, pc, lua_g);
}

static const pcl_arg fourier_args[] = {A_POINTS("points", 0, 2, 0), PCL_END};
PCL_BODY(l_fourier, a) {
    int count = a[0].n, st;
    if (count % 2) return pcl_argfail(L, 1, "must hold an even number (2n >= 2) of points, got %d", count);
    return pcl_push_made(L, pc_curve_fourier(a[0].dim, count / 2, a[0].list, &st), &st, NULL);
}

static const pcl_arg sphdir_args[] = {A_NUM("u1"), A_NUM("u2"), PCL_END};
PCL_BODY(l_sphdir, a) {
    double e[3];
    pc_dir3(a[0].x, a[1].x, e);
    return pcl_push_results(L, 3, "v", e);
}

/* ---- evaluation methods ------------------------------------------------------------------------ */

static const pcl_arg t_arg[] = {A_NUM("t"), PCL_END};
/* c(t), and c(u^2) of a scalar equation: a single-piece Bezier composed with it (l_expr.c) */
static int read_t(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    out->x = lua_tonumber(L, idx);
    return (lua_type(L, idx) == LUA_TNUMBER && isfinite(out->x)) || pcl_isequation(L, idx);
}
static const pcl_arg t_or_eq[] = {{.name = "t", .kind = PCL_ANY, .read = read_t,
                                   .expect = "a finite number or a scalar equation"}, PCL_END};
/* c(t), c:eval(t) and c:xy(t), one body told apart by the declared name */
PCL_METHOD(c_call, lcurve *u, a) {
    double h[PC_MAXDIM + 1];
    int d = u->c->dim;
    pc_why_call why;
    if (pcl_eq_curve_apply(L, u->c, 2)) return 1;
    pcl_check(L, pc_stroke_value_checked(pcl_name(L), u->c, a[0].x, h, &why), why.row);
    if (strcmp(pcl_name(L), "c:xy")) return pcl_push_packed(L, d, "w", h);   /* a point, or a vector at infinity */
    if (h[d] == 0) return pcl_check(L, PC_IMPROPER, pc_curve_why);
    return pcl_push_packed(L, d, "x", h);
}

/* c:deriv(t [, order] [, "left"|"right"]): any order; at a joint the right-hand piece unless
 * "left" is asked for.  The side may stand in the order's place: read_order reads it as the
 * side declared next (a + 1), its choice in s and n, the order 1. */
static int read_order(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    if (lua_type(L, idx) == LUA_TSTRING) pcl_readone(L, idx, 2, 0, a + 1, 0, out);
    out->x = out->s ? 1 : lua_tonumber(L, idx);
    return out->s || (lua_type(L, idx) == LUA_TNUMBER && out->x == floor(out->x) && out->x >= 1 &&
                      out->x <= PC_CURVE_MAXDEG);
}
static const char *const SIDES[] = {"left", "right", NULL};
static const pcl_arg deriv_args[] = {A_NUM("t"),
    {.name = "order", .kind = PCL_ANY, .flags = PCL_OPT, .read = read_order,
     .expect = "a whole number from 1 to 64, or \"left\" / \"right\""},
    {.name = "side", .kind = PCL_ENUM, .flags = PCL_OPT, .choices = SIDES, .dflt = 1}, PCL_END};
PCL_METHOD(c_deriv, lcurve *u, a) {
    const pcl_val *s = a[2].present ? &a[2] : &a[1];   /* the side, in its place or in the order's */
    int order = a[1].present ? (int)a[1].x : 1, side = s->s ? (s->n ? 1 : -1) : 0;
    double out[(PC_CURVE_MAXDEG + 1) * PC_MAXDIM];
    pc_why_call w;
    pcl_check(L, pc_curve_derivs_checked(pcl_name(L), u->c, a[0].x, order, side, out, &w), w.row);
    return pcl_push_results(L, u->c->dim, "v", out + (size_t)order * u->c->dim);
}

/* c:monomial([piece]): the power-basis coefficients of a piece in the curve's parameter:
 * {{a0, a1, ...} of x, {...} of y, ...}, and w = {...} for a rational curve */
static const pcl_arg piece_opt[] = {{.name = "piece", .kind = PCL_INTEGER, .flags = PCL_OPT, .dflt = 1, .shown = "1"},
                                    PCL_END};
PCL_METHOD(c_monomial, lcurve *u, a) {
    int n = u->c->dim, deg, rational;
    double rows[(PC_CURVE_MAXDEG + 1) * (PC_MAXDIM + 1)];
    pc_why_call why;
    pcl_check(L, pc_curve_monomial_checked(pcl_name(L), u->c, a[0].x, rows, &deg, &rational, &why), why.row);
    lua_createtable(L, n, 1);
    for (int x = 0; x <= n - !rational; x++) {
        pcl_push_numbers(L, deg + 1, rows + x * (deg + 1));
        if (x < n) lua_rawseti(L, -2, x + 1);
        else lua_setfield(L, -2, "w");
    }
    return 1;
}

/* c:tangent(t), c:normal(t) (pc_curve_frame) and c:curvature(t), one body told apart by the
 * declared name */
PCL_METHOD(c_frame, lcurve *u, a) {
    int normal = !strcmp(pcl_name(L), "c:normal"), curvature = !strcmp(pcl_name(L), "c:curvature");
    double e[PC_MAXDIM], nrm[PC_MAXDIM];
    pcl_check(L, curvature ? pc_curve_curvature(u->c, a[0].x, e) : pc_curve_frame(u->c, a[0].x, e, normal ? nrm : NULL),
              pc_curve_why);
    return pcl_push_packed(L, u->c->dim, curvature ? "n" : "v", normal ? nrm : e);
}

/* ---- operations --------------------------------------------------------------------------------- */

/* The parameter of argument #1 strictly inside the domain. */
static double inside(lua_State *L, lcurve *u, double t) {
    char why[160];
    if (pc_curve_inside_why(u->c, t, why, sizeof why) != PC_OK) pcl_argfail(L, 1, "%s", why);
    return t;
}

PCL_METHOD(c_split, lcurve *u, a) {
    pc_curve *l, *r;
    pcl_check(L, pc_curve_split(u->c, inside(L, u, a[0].x), &l, &r), NULL);
    pcl_pushcurve(L, l, u->kind);
    return pcl_pushcurve(L, r, u->kind) + 1;
}

static const pcl_arg ab_args[] = {A_NUM("a"), A_NUM("b"), PCL_END};
PCL_METHOD(c_sub, lcurve *u, a) {
    char why[200];
    if (pc_curve_part_why(u->c, a[0].x, a[1].x, why, sizeof why) != PC_OK) return pcl_fail(L, "%s", why);
    int st;
    return pcl_push_made(L, pc_curve_sub(u->c, a[0].x, a[1].x, &st), &st, u->kind);
}

static const pcl_arg u_arg[] = {A_NUM("u"), PCL_END};
PCL_METHOD(c_insert_knot, lcurve *u, a) {
    if (u->c->kind != PC_CURVE_BSPLINE) return pcl_fail(L, "not a B-spline (a %s)", u->kind);
    int st;
    return pcl_push_made(L, pc_curve_insert_knot(u->c, inside(L, u, a[0].x), &st), &st, u->kind);
}

static const pcl_arg ab_opt[] = {A_NUMOPT("a", 0, NULL), A_NUMOPT("b", 0, NULL), PCL_END};
PCL_METHOD(c_length, lcurve *u, a) {
    if (a[0].present != a[1].present) return pcl_fail(L, "give both ends a and b, or neither");
    double len;
    pcl_check(L, pc_curve_length(u->c, a[0].present ? a[0].x : u->c->t0, a[1].present ? a[1].x : u->c->t1, 1e-10, &len),
              pc_curve_why);
    return pcl_push_results(L, 0, "n", len);
}

PCL_METHOD(c_bbox, lcurve *u, a) {
    double lo[PC_MAXDIM], hi[PC_MAXDIM];
    pcl_check(L, pc_curve_bbox(u->c, 1e-9, lo, hi), pc_curve_why);
    return pcl_push_results(L, u->c->dim, "p p", lo, hi);
}

/* Argument #1 a whole number 1..n (what: "piece", "coordinate"), 0-based. */
static int number_arg(lua_State *L, const char *what, int n, const pcl_val *v) {
    char why[160];
    if (pc_number_why(what, v->x, n, why, sizeof why) != PC_OK) pcl_argfail(L, 1, "%s", why);
    return (int)v->x - 1;
}

/* c:controls(): the control values (weighted points as given); a stroke's c:controls(i) is
 * its piece's quadrilateral A, P, Q, B as before. */
static const pcl_arg i_opt[] = {{.name = "i", .kind = PCL_INTEGER, .flags = PCL_OPT}, PCL_END};
PCL_METHOD(c_controls, lcurve *u, a) {
    int d = u->c->dim, np;
    const pc_piece *pcs = pc_curve_stroke_pieces(u->c, &np);
    if (pcs) {
        const pc_piece *pc = &pcs[np == 1 && !a[0].present ? 0 : number_arg(L, "piece", np, &a[0])];
        return pcl_push_results(L, d, "p p p p", pc->a, pc->p, pc->q, pc->b);
    }
    if (pc_curve_fourier_coefs(u->c, NULL)) return pcl_fail(L, "a Fourier curve has no pieces");
    if (u->c->kind == PC_CURVE_FUNC) return pcl_fail(L, "a %s curve has no control points", u->kind);
    pcl_push_values(L, u->c->ncp, d, u->c->cp, 1);
    return 1;
}

PCL_METHOD(c_knots, lcurve *u, a) {
    if (u->c->kind == PC_CURVE_FUNC) return pcl_fail(L, "a %s curve has no knots", u->kind);
    return pcl_push_results(L, 0, "N", u->c->nknots, u->c->knots);
}

/* c:piece(i, t), c:piece_xy(i, t), one body told apart by the declared name: a stroke's piece i
 * at its own parameter t (any t: the piece's formula extrapolates, where its smoothstep has
 * values) */
static const pcl_arg piece_args[] = {{.name = "i", .kind = PCL_INTEGER}, A_NUM("t"), PCL_END};
PCL_METHOD(c_piece, lcurve *u, a) {
    int np, d = u->c->dim;
    double x[PC_MAXDIM];
    if (!pc_curve_stroke_pieces(u->c, &np))
        return pcl_fail(L, "a %s curve has no pieces", pc_curve_fourier_coefs(u->c, NULL) ? "Fourier" : u->kind);
    pc_why_call why;
    int i = number_arg(L, "piece", np, &a[0]);
    pcl_check(L, pc_stroke_piece_checked(pcl_name(L), u->c, i, a[1].x, x, &why), why.row);
    return pcl_push_results(L, d, strcmp(pcl_name(L), "c:piece") ? "x" : "p", x);   /* c:piece_xy: the numbers */
}

/* c:coef([k]) -> a, b: the Fourier coefficient lists of coordinate k (a[0] .. a[n]) */
static const pcl_arg k_opt[] = {{.name = "k", .kind = PCL_INTEGER, .flags = PCL_OPT, .dflt = 1, .shown = "1"}, PCL_END};
PCL_METHOD(c_coef, lcurve *u, a) {
    int n;
    const double *coef = pc_curve_fourier_coefs(u->c, &n);
    if (!coef) return pcl_fail(L, "not a Fourier curve");
    int k = number_arg(L, "coordinate", u->c->dim, &a[0]);
    for (int ab = 0; ab < 2; ab++) {
        const double *row = coef + (2 * k + ab) * (n + 1);
        pcl_push_numbers(L, n, row + 1);   /* [1] .. [n], then [0] */
        lua_pushnumber(L, row[0]);
        lua_rawseti(L, -2, 0);
    }
    return 2;
}

/* c:map(f): the image under a map (also f(c)) */
static const pcl_arg f_arg[] = {A_MAP("f"), PCL_END};
PCL_METHOD(c_map, lcurve *u, a) {
    pc_map *f = a[0].obj;
    if (f->nin != u->c->dim) return pcl_argfail(L, 1, "takes %d-D points, but the curve is %d-D", f->nin, u->c->dim);
    int st;
    return pcl_push_made(L, pc_curve_map(u->c, f, &st), &st, u->kind);
}

/* c:flatten([tol [, map]]) -> a list of polylines (lists of 2-D points) within tol of the curve
 * in its own units (default 1e-3); map projects a curve of another dimension to the plane. */
static const pcl_arg flatten_args[] = {{.name = "tol", .kind = PCL_NUMBER, .flags = PCL_OPT | PCL_POS, .dflt = 1e-3,
                                        .shown = "1e-3"}, {.name = "map", .kind = PCL_MAP, .flags = PCL_OPT}, PCL_END};
PCL_METHOD(c_flatten, lcurve *u, a) {
    pc_polyline pl = {0};
    pc_why_call why;
    pcl_check(L, pc_curve_flatten_checked(pcl_name(L), u->c, a[1].obj, a[0].x, &pl, &why), why.row);
    lua_newtable(L);
    for (size_t i = 0, start = 0, npl = 0; i < pl.n; i++)   /* one list of points per piece */
        if (i + 1 == pl.n || pl.move[i + 1]) {
            pcl_push_values(L, (int)(i + 1 - start), 2, pl.xy + 2 * start, 0);
            lua_rawseti(L, -2, (lua_Integer)++npl);
            start = i + 1;
        }
    pc_polyline_free(&pl);
    return 1;
}

static int c_index(lua_State *L) {
    lcurve *u = self_curve(L, 1);
    if (!u) return 0;
    lua_settop(L, 2);
    const char *k = lua_tostring(L, 2);
    double v;
    pc_field_type type = k ? pc_curve_field(u->c, k, &v) : PC_FIELD_NONE;
    if (k && !strcmp(k, "kind")) lua_pushstring(L, u->kind);
    else if (type == PC_FIELD_INTEGER) lua_pushinteger(L, (lua_Integer)v);
    else if (type == PC_FIELD_NUMBER) lua_pushnumber(L, v);
    else if (type == PC_FIELD_BOOLEAN) lua_pushboolean(L, v != 0);
    else lua_rawget(L, lua_upvalueindex(1));   /* the key at 2, on the top */
    return 1;
}

static int c_tostring(lua_State *L) {
    lcurve *u = pcl_meta_self(L, self_curve(L, 1), "tostring: not a curve");
    char text[200];
    pc_curve_text(u->c, u->kind, text, sizeof text);
    return pcl_push_results(L, 0, "s", text);
}

static const pcl_fn ctors[] = {
    {.name = "bezier", .fn = l_bezier, .args = bezier_args, .sig = "bezier{P0, P1, ..., Pn} -> curve", .help = "The Bezier curve of degree n over [0, 1] (2 to 65 points); weighted points w*P make it rational (a conic), vectors are control points at infinity."},
    {.name = "bspline", .fn = l_bspline, .args = bspline_args, .sig = "bspline(points, degree [, \"open\"|\"uniform\"|\"periodic\"|knots]) -> curve", .help = "The B-spline (NURBS with weighted points) of that degree; open knots by default, or a non-decreasing list of points + degree + 1 knots."},
    {.name = "hermite", .fn = l_hermite, .args = hermite_args, .sig = "hermite(points, tangents [, {tin = {...}, u = {...}, closed = false}]) -> curve", .help = "Piecewise cubic Hermite through the points with these derivatives (tin: the arriving ones, for corners); u: the parameters of the nodes."},
    {.name = "cubic_spline", .fn = l_cubic_spline, .args = spline_args, .sig = "cubic_spline(points [, {ends = \"natural\"|\"clamped\"|\"periodic\", d0 = V, d1 = V, u = {...}}]) -> curve", .help = "The C2 cubic spline through the points (parameters: accumulated chord lengths unless u is given)."},
    PCL_FN("interpolate", l_interpolate, interpolate_args, "curve", "The polynomial curve of degree n - 1 through n points (2 to 65) at the given parameters (default evenly spaced in [0, 1])."),
    PCL_FN("curve", l_curve, curve_args, "curve", "A Lua function t -> point (or numbers) over [t0, t1] as a curve: it flattens, measures and draws like any other."),
    {.name = "spline2", .fn = l_spline2, .args = spline2_args, .result = "curve", .help = "The curve from A with direction a to B with direction b, blended by the smoothstep g (default smooth.cubic): Stepanov's example 5."},
    {.name = "fourier", .fn = l_fourier, .args = fourier_args, .sig = "fourier({P1, P2, ..., P2n}) -> curve", .help = "The closed curve through 2n points by a finite Fourier series (example 12), t in [0, 2 pi]."},
    PCL_FN("sphdir", l_sphdir, sphdir_args, "vector", "The unit vector of longitude u1 and latitude u2 (example 33)."),
    PCL_END};

#define METHOD(nm, f, a, res, text) \
    {.name = nm, .fn = f, .args = a, .result = res, .help = text, .self = self_curve, .selftype = "curve"}
static const pcl_fn methods[] = {
    METHOD("c:xy", c_call, t_arg, "x, y", "The coordinates of the point at t as numbers."),
    METHOD("c:eval", c_call, t_or_eq, "point", "The point at t, as c(t)."),
    {.name = "c:deriv", .fn = c_deriv, .args = deriv_args, .sig = "c:deriv(t [, order] [, \"left\"|\"right\"]) -> vector", .self = self_curve, .selftype = "curve", .help = "The derivative of any order (default 1) at t, exact for Bezier and B-spline curves (rational ones by Leibniz's rule; up to order 2 for function curves). At a joint the default is the piece that starts there (the right-hand side, the left at the end of the domain); \"left\" takes the piece that ends there."},
    {.name = "c:monomial", .fn = c_monomial, .args = piece_opt, .sig = "c:monomial([piece]) -> {{a0, a1, ...}, {b0, b1, ...}, ... [, w = {...}]}", .self = self_curve, .selftype = "curve", .help = "The power-basis coefficients of a Bezier or B-spline piece (default 1) in the curve's own parameter: x(t) = a0 + a1 t + ..., one list per coordinate (ch. 4-5 print their results so); w the weight polynomial of a rational curve (the coordinates' lists are then its numerators)."},
    METHOD("c:tangent", c_frame, t_arg, "vector", "The unit tangent."),
    METHOD("c:normal", c_frame, t_arg, "vector", "The unit principal normal (in the plane: the tangent turned by +90 degrees)."),
    METHOD("c:curvature", c_frame, t_arg, "number", "The curvature: signed in the plane (positive turning counter-clockwise), unsigned in space."),
    METHOD("c:split", c_split, t_arg, "left, right", "The two parts at t (de Casteljau, knot insertion), of the same kind."),
    METHOD("c:sub", c_sub, ab_args, "curve", "The part over [a, b], of the same kind."),
    METHOD("c:insert_knot", c_insert_knot, u_arg, "curve", "The same B-spline with the knot u inserted (one more control point)."),
    {.name = "c:length", .fn = c_length, .args = ab_opt, .sig = "c:length([a, b]) -> number", .self = self_curve, .selftype = "curve", .help = "The arc length over the domain or [a, b] (adaptive Gauss-Legendre)."},
    METHOD("c:bbox", c_bbox, NULL, "lo, hi", "The corners of the axis-aligned bounding box."),
    {.name = "c:controls", .fn = c_controls, .args = i_opt, .sig = "c:controls() -> {values}\nc:controls(i) -> A, P, Q, B", .self = self_curve, .selftype = "curve", .help = "The control values (weighted as given); for a stroke, the quadrilateral of piece i."},
    METHOD("c:knots", c_knots, NULL, "{numbers}", "The knot vector of a B-spline, or the breakpoints of pieces."),
    METHOD("c:piece", c_piece, piece_args, "point", "A stroke's piece i at its own parameter t."),
    METHOD("c:piece_xy", c_piece, piece_args, "x, y", "The coordinates of a stroke's piece i at its own parameter t."),
    METHOD("c:coef", c_coef, k_opt, "a, b", "The Fourier coefficient lists of coordinate k of a fourier curve."),
    {.name = "c:map", .fn = c_map, .args = f_arg, .sig = "c:map(f) -> curve | f(c)", .self = self_curve, .selftype = "curve", .help = "The image under a map: control points mapped exactly, so a projective map keeps a rational curve rational."},
    METHOD("c:flatten", c_flatten, flatten_args, "{polylines}", "Adaptive polylines within tol of the curve (projected by map to the plane), broken where the curve passes through infinity."),
    PCL_END};
static const pcl_fn call[] = {{.name = "c", .fn = c_call, .args = t_or_eq, .result = "point", .key = "__call", .topic = "c(t)", .callname = 1, .self = self_curve, .selftype = "curve", .help = "The point of a curve at parameter t (a vector where a rational curve is at infinity). With t a scalar equation (param \"t\", t^2, ...) a single-piece Bezier curve gives the composed point equation: conic.ed(A, B, C, k)(t) is (2.97)."}, PCL_END};

void pcl_open_curves(lua_State *L) {
    int module = lua_gettop(L);
    pcl_private(L, module);
    int tk = lua_gettop(L);
    static const luaL_Reg meta[] = {{"__tostring", c_tostring}, {"__gc", c_gc}, {NULL, NULL}};
    pcl_open_type(L, CURVE_MT, meta, call, methods, c_index);
    lua_getfield(L, -1, "__index");   /* its methods, shared with the Lua helpers */
    lua_getupvalue(L, -1, 1);
    lua_setfield(L, tk, "curve_methods");

    static const pcl_fn priv[] = {PCL_FN("stroke", l_stroke_raw, stroke_args, NULL, NULL), PCL_END};
    pcl_register_private(L, tk, priv);
    pcl_register(L, module, ctors, 0);
    lua_settop(L, module);
}
