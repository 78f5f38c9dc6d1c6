/* Binding of Stepanov's coordinate maps and scalar numerics (stdlib/books/stepanov/curvilinear.h,
 * numeric.h), and the numeric helpers of stdlib/lua/curvilinear.lua in _tk. */
#include "pcl_args.h"
#include "pcl_core.h"
#include "pcl_tagged.h"
#include "curvilinear.h"
#include "numeric.h"

#define ORESME_MT "oresme"
static const char ORESME_TAG = 'o';   /* its address tags the type (PCL_SELF_TAG) */

/* ---- plane -> square ------------------------------------------------------------------------ */

/* A number other than NaN: +-inf are the square's sides; NaN is no place. */
#define A_PLACE(nm, fl) {.name = nm, .kind = PCL_NUMBER, .flags = PCL_INF | (fl)}
static const pcl_arg squash_args[] = {A_PLACE("p", 0), A_PLACE("q", PCL_OPT), PCL_END};

/* squash and squash01, one body told apart by the declared name */
PCL_BODY(l_squash, a) {
    double (*f)(double) = strcmp(pcl_name(L), "squash") ? pc_squash01 : pc_squash;
    for (int i = 0; i < 1 + a[1].present; i++) lua_pushnumber(L, f(a[i].x));
    return 1 + a[1].present;
}

/* ---- projections: maps of the one map type (l_map.c) ------------------------------------------ */

static const pcl_arg oblique_args[] = {A_POINT("C0", 2), A_NUM("r"), A_NUM("k"), A_NUM("u"), PCL_END};
static const pcl_arg projection_args[] = {A_SAMEPOINT("C0"), A_SAMEPOINT("C1"), A_SAMEPOINT("C2"),
                                          A_SAMEPOINT("C3"), PCL_END};

/* oblique and projection, one body told apart by the declared name: the map by the screen
 * points C0..C3 of its origin and axes (oblique's made from r, k and u) */
PCL_BODY(l_projection, a) {
    double c[8];
    if (!strcmp(pcl_name(L), "oblique")) pc_oblique_axes(a[0].v, a[1].x, a[2].x, a[3].x, c);
    else if (a[0].n != 2) return pcl_argfail(L, 1, "must be a 2-D point, got a %d-D one", a[0].n);
    else pcl_point_rows(a, 4, 2, c);
    pc_map_project4(pcl_newmap(L), c);
    return 1;
}

/* ---- Oresme ----------------------------------------------------------------------------------- */

typedef struct {
    PCL_SELF;           /* a 2-D point has the size of a short sequence: self tells (pcl.h) */
    double lambda;
    int m;
    double y[];
} oresme;

/* The Oresme sequence at idx, or NULL (for a metamethod fn, o[j], #o, tostring(o), which Lua
 * calls only on one: an error); its block is exactly the header and 2^m + 1 values, so one
 * given the metatable by the debug library is refused. */
static oresme *tooresme(lua_State *L, int idx, const char *fn) {
    oresme *o = luaL_testudata(L, idx, ORESME_MT);
    size_t len = o ? lua_rawlen(L, idx) : 0;
    int ok = len >= sizeof *o && o->self == PCL_SELF_TAG(o, &ORESME_TAG) && o->m >= 0 &&
             o->m <= PC_ORESME_MAXLEVEL && len == sizeof *o + sizeof(double) * (size_t)((1L << o->m) + 1);
    o = pcl_genuine(L, idx, o, ok, "Oresme sequence");
    if (!o && fn) pcl_error(L, "%s: not an Oresme sequence (oresme(lambda, m))", fn);
    return o;
}
static void *self_oresme(lua_State *L, int idx) { return tooresme(L, idx, NULL); }

static const pcl_arg t_arg[] = {A_NUM("t"), PCL_END};
PCL_METHOD(oresme_call, oresme *o, a) {
    return pcl_push_results(L, 0, "n", pc_oresme_at(o->y, o->m, a[0].x));
}

static int oresme_index(lua_State *L) {
    oresme *o = tooresme(L, 1, "o[j]");
    int isint = lua_isinteger(L, 2);
    lua_Integer j = isint ? lua_tointeger(L, 2) : -1;
    const char *k = isint ? "" : lua_tostring(L, 2);
    if (j >= 0 && j <= (1L << o->m)) lua_pushnumber(L, o->y[j]);
    else if (k && !strcmp(k, "lambda")) lua_pushnumber(L, o->lambda);
    else if (k && (!strcmp(k, "m") || !strcmp(k, "n"))) lua_pushinteger(L, *k == 'm' ? o->m : 1L << o->m);
    else return 0;
    return 1;
}

static int oresme_len(lua_State *L) {
    return pcl_push_results(L, 0, "i", 1 << tooresme(L, 1, "#")->m);
}

static int oresme_tostring(lua_State *L) {
    oresme *o = tooresme(L, 1, "tostring");
    lua_pushfstring(L, "oresme(%s, %d)", pcl_pushnum(L, o->lambda), o->m);
    return 1;
}

static const pcl_arg oresme_args[] = {
    A_NUM("lambda"), {.name = "m", .kind = PCL_INTEGER, .flags = PCL_OPT | PCL_RANGE, .hi = PC_ORESME_MAXLEVEL,
                      .dflt = 12, .expect = "an integer 0..24 (2^m cells)"},
    A_NUMOPT("y0", 0, NULL), A_NUMOPT("y1", 1, NULL), PCL_END};
PCL_BODY(l_oresme, a) {
    int m = (int)a[1].x;
    long n = 1L << m;
    oresme *o = pcl_tagged_new(L, sizeof *o + sizeof(double) * (size_t)(n + 1), &ORESME_TAG, ORESME_MT);
    o->lambda = a[0].x;
    o->m = m;
    pcl_check(L, pc_oresme_fill(a[0].x, m, a[2].x, a[3].x, o->y), NULL);
    return 1;
}

/* ---- bisection --------------------------------------------------------------------------------- */

/* f(x) for the core, which words the failures of finite numbers (pc_bisect_why) */
static double call_f(double x, void *ud) {
    lua_State *L = ud;
    lua_pushvalue(L, 1);
    lua_pushnumber(L, x);
    lua_call(L, 1, 1);
    int isnum;
    double v = lua_tonumberx(L, -1, &isnum);
    const char *type = luaL_typename(L, -1);
    if (!isnum) pcl_fail(L, "f(%s) must return a number, got %s", pcl_pushnum(L, x), type);
    lua_pop(L, 1);
    return v;
}

static const pcl_arg bisect_args[] = {{.name = "f", .kind = PCL_CALLABLE}, A_NUM("a"), A_NUM("b"),
                                      A_NUMOPT("tol", 1e-10, NULL), PCL_END};
PCL_BODY(l_bisect, a) {
    double x;
    int iters;
    char why[200];
    if (pc_bisect_why(call_f, L, a[1].x, a[2].x, a[3].x, &x, &iters, why, sizeof why) != PC_OK)
        return pcl_fail(L, "%s", why);
    return pcl_push_results(L, 0, "n i", x, iters);
}

/* ---- numeric helpers for the Lua side -------------------------------------------------------- */

/* _tk.bilinear(P0, P1, P2, P3) -> function(t1, t2) -> x, y[, z ...] */
static const pcl_arg t12_args[] = {A_NUM("t1"), A_NUM("t2"), PCL_END};
PCL_BODY(bilinear_eval, a) {
    const double *c = lua_touserdata(L, PCL_UPVALUE(1));   /* the corners: 4 rows of d */
    int d = (int)(lua_rawlen(L, PCL_UPVALUE(1)) / (4 * sizeof *c));
    double out[PC_MAXDIM];
    pc_bilinear(d, c, c + d, c + 2 * d, c + 3 * d, a[0].x, a[1].x, out);
    return pcl_push_results(L, d, "x", out);
}
static const pcl_fn bilinear_fn = PCL_FN("bilinear", bilinear_eval, t12_args, "x, y, ...", NULL);

static const pcl_arg corner_args[] = {A_SAMEPOINT("P0"), A_SAMEPOINT("P1"), A_SAMEPOINT("P2"), A_SAMEPOINT("P3"), PCL_END};
PCL_BODY(l_bilinear, a) {
    int d = a[0].n;
    double *c = lua_newuserdatauv(L, sizeof(double) * 4 * (size_t)d, 0);
    pcl_point_rows(a, 4, d, c);
    pcl_pushfn(L, &bilinear_fn, 1);
    return 1;
}

/* _tk.frame_point(o, e, xi, eta), _tk.frame_coords(o, e, x) -> xi, eta | nil, message,
 * _tk.patch_blend(u0, u2, ...): the pairs as numbers x1..x9 (curvilinear.lua), one body told
 * apart by the declared name */
#define X(k) A_NUM("x" #k)
static const pcl_arg six_args[] = {X(1), X(2), X(3), X(4), X(5), X(6), PCL_END};
static const pcl_arg nine_args[] = {X(1), X(2), X(3), X(4), X(5), X(6), X(7), X(8), X(9), PCL_END};
PCL_BODY(l_frame, a) {
    const char *name = pcl_name(L);
    int n = strcmp(name, "_tk.patch_blend") ? 6 : 9, st = PC_OK;
    double x[9], out[2];
    for (int i = 0; i < n; i++) x[i] = a[i].x;
    if (n == 9) pc_patch_blend(x, x + 2, x[4], x[5], x[6], x[7], x[8], out);
    else if (!strcmp(name, "_tk.frame_point")) pc_frame_point(x, x + 2, x[4], x[5], out);
    else st = pc_frame_coords(x, x + 2, x + 4, &out[0], &out[1]);
    if (st == PC_OK) return pcl_push_results(L, 0, "n n", out[0], out[1]);
    lua_pushnil(L);
    return pcl_push_results(L, 0, "s", pc_strerror(st)) + 1;
}

static const pcl_fn fns[] = {
    PCL_FN("squash", l_squash, squash_args, "numbers", "The plane onto the open square: p/sqrt(p^2 + 1) in (-1, 1), for each argument (examples 26-28)."),
    PCL_FN("squash01", l_squash, squash_args, "numbers", "The plane onto the open unit square: .5 p/sqrt(p^2 + 1) + .5 in (0, 1), for each argument."),
    PCL_FN("oblique", l_projection, oblique_args, "map", "The oblique projection of examples 32-34 (a 3-D -> 2-D map): the x and y axes of length r at angles u and u + 90 degrees on an ellipse squeezed by k, the z axis straight up."),
    PCL_FN("projection", l_projection, projection_args, "map", "The projection (x, y, z) -> C0 + x(C1 - C0) + y(C2 - C0) + z(C3 - C0) by four screen points, a 3-D -> 2-D map; pr(P), pr:xy(x, y, z), pr.C0."),
    {.name = "oresme", .fn = l_oresme, .args = oresme_args, .result = "o", .sig = "oresme(lambda [, m [, y0, y1]]) -> o", .help = "Oresme's lambda-function on 2^m cells (m = 12 by default) from y0 to y1 (example 31): o(t), o[j], #o."},
    PCL_FN("bisect", l_bisect, bisect_args, "x, iterations", "A root of f in [a, b] by bisection, as example 30 does it (tol 1e-10 by default)."),
    PCL_END};
static const pcl_fn ocall[] = {{.name = "o", .fn = oresme_call, .args = t_arg, .result = "number", .key = "__call", .topic = "o(t)", .callname = 1, .self = self_oresme, .selftype = "sequence made by oresme", .help = "The value at t in [0, 1]: y[floor(t 2^m)], the ends outside (a step function)."}, PCL_END};

void pcl_open_curvilinear(lua_State *L) {
    int module = lua_gettop(L);
    static const luaL_Reg ometa[] = {{"__index", oresme_index}, {"__len", oresme_len},
                                     {"__tostring", oresme_tostring}, {NULL, NULL}};
    pcl_open_type(L, ORESME_MT, ometa, ocall, NULL, NULL);
    pcl_register(L, module, fns, 0);
    pcl_private(L, module);
    static const pcl_fn priv[] = {PCL_FN("bilinear", l_bilinear, corner_args, NULL, NULL),
                                  PCL_FN("_tk.frame_point", l_frame, six_args, NULL, NULL),
                                  PCL_FN("_tk.frame_coords", l_frame, six_args, NULL, NULL),
                                  PCL_FN("_tk.patch_blend", l_frame, nine_args, NULL, NULL), PCL_END};
    pcl_register_private(L, -1, priv);
    lua_settop(L, module);
}
