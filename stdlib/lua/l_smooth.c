/* Binding of the smoothsteps (stdlib/geom/smooth.h): the table smooth, and the half-spline object g
 * of smooth.power(n) and smooth.half(n, m, t0) without t.  The curve builders accept these
 * objects, smooth.sine and smooth.cubic as smoothsteps they evaluate natively (pcl_tk.h). */
#include "pcl_args.h"
#include "pcl_core.h"
#include "pcl_expr.h"   /* g(t) of an equation t builds an equation (l_expr.c) */

#define HSPLINE_MT "halfspline"

/* g(t) pushed, or an error when it is not finite: an extrapolation far past [0, 1]
 * (smooth.cubic(1e308)) overflows, and no NaN or infinity is returned silently. */
static int push_value(lua_State *L, double t, double g) {
    if (!isfinite(g)) return pcl_fail(L, "the value at t = %s is out of range (not finite)", pcl_pushnum(L, t));
    return pcl_push_results(L, 0, "n", g);
}

static const pcl_arg t_arg[] = {A_NUM("t"), PCL_END};

/* smooth.sine and smooth.cubic (a number, or an equation: a smoothstep of it), smooth.locus,
 * smooth.clamp and smooth.clamp_qb (t finite, as smooth.clamp's: QBasic has no NaN) */
enum { LOCUS = PC_G_LINEAR + 1, CLAMP, CLAMP_QB };
static int numeric(lua_State *L, int kind) {
    pc_gfun g = {kind, {0, 0, 0, 0, 0}};
    if (kind < LOCUS && lua_type(L, 1) != LUA_TNUMBER && pcl_eq_smooth(L, 1, &g)) return 1;
    pcl_val a[3] = {0};
    PCL_READ(L, a);
    if (kind < LOCUS) return push_value(L, a[0].x, pc_gfun_eval(&g, a[0].x));
    if (kind == LOCUS) return pcl_push_results(L, 0, "n", pc_hspline_locus(a[0].x, a[1].x, a[2].x));
    return pcl_push_results(L, 0, "n", kind == CLAMP ? pc_smooth_clamp(a[0].x) : pc_smooth_clamp_qb(a[0].x, a[1].x));
}
static int l_sine(lua_State *L) { return numeric(L, PC_G_SINE); }
static int l_cubic(lua_State *L) { return numeric(L, PC_G_CUBIC); }
static int l_locus(lua_State *L) { return numeric(L, LOCUS); }
static int l_clamp(lua_State *L) { return numeric(L, CLAMP); }
static int l_clamp_qb(lua_State *L) { return numeric(L, CLAMP_QB); }
static const pcl_arg locus_args[] = {A_POSNUM("n"), A_POSNUM("m"), A_NUMIN("t0", 0, 1), PCL_END};
static const pcl_arg clamp_qb_args[] = {A_NUM("t"), A_NUMOPT("prev", 0, NULL), PCL_END};

/* the smoothsteps the curve bindings recognise by identity */
int pcl_smooth_isfunc(lua_CFunction f, int *kind) {
    *kind = f == l_sine ? PC_G_SINE : PC_G_CUBIC;
    return f == l_sine || f == l_cubic;
}

/* The half-spline at idx or NULL; one given the metatable by the debug library is refused. */
pc_hspline *pcl_tohspline(lua_State *L, int idx) {
    pc_hspline *h = luaL_testudata(L, idx, HSPLINE_MT);
    return pcl_genuine(L, idx, h, !h || lua_rawlen(L, idx) == sizeof *h, "half-spline");
}
static void *self_hs(lua_State *L, int idx) { return pcl_tohspline(L, idx); }

/* A number strictly between 0 and 1 (the junction t0 of smooth.half). */
static int open_unit(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    out->x = lua_tonumber(L, idx);
    return lua_type(L, idx) == LUA_TNUMBER && out->x > 0 && out->x < 1;
}

/* g(t) with the extrapolation domain of a fractional degree: t^n needs t >= 0, (1 - t)^m
 * needs t <= 1 unless the degree is whole. */
static int eval_at(lua_State *L, const pc_hspline *h, double t, int k) {
    char msg[200];
    if (pc_hspline_check_text(h, t, msg, sizeof msg)) return pcl_argfail(L, k, "%s", msg);
    return push_value(L, t, pc_hspline_eval(h, t));
}

/* smooth.power and smooth.half, one body told apart by the declared name: the half-spline
 * (n, m, t0) (power's (n, n, 1/2)), then g(t) when t is given, else g itself.  Degrees in the
 * hundreds make t0^(n-1) underflow: the coefficients would be inf and NaN. */
static const pcl_arg power_args[] = {A_POSNUM("n"), A_NUMOPT("t", 0, NULL), PCL_END};
static const pcl_arg half_args[] = {A_POSNUM("n"), A_POSNUM("m"), A_ANY("t0", open_unit, "a number in (0, 1)"),
                                    A_NUMOPT("t", 0, NULL), PCL_END};
PCL_BODY(l_half, a) {
    int half = !strcmp(pcl_name(L), "smooth.half"), k = half ? 4 : 2;   /* t: argument #k */
    double n = a[0].x, m = half ? a[1].x : n, t0 = half ? a[2].x : 0.5;
    pc_hspline h;
    char msg[200];
    if (pc_hspline_init(&h, n, m, t0) != PC_OK && pc_hspline_init_text(n, m, t0, msg, sizeof msg))
        return pcl_fail(L, "%s", msg);
    if (a[k - 1].present) return eval_at(L, &h, a[k - 1].x, k);
    pc_hspline *g = lua_newuserdatauv(L, sizeof *g, 0);
    *g = h;
    luaL_setmetatable(L, HSPLINE_MT);
    return 1;
}

/* ---- the half-spline object ------------------------------------------------------------- */

/* g(t) (t an equation: an equation) and g:deriv(t) */
static int hs_at(lua_State *L, int deriv) {
    pc_hspline *h = pcl_tohspline(L, 1);
    if (!deriv && h && lua_type(L, 2) != LUA_TNUMBER &&
        pcl_eq_smooth(L, 2, &(pc_gfun){PC_G_HALF, *h})) return 1;   /* g(t) of an equation t */
    pcl_val a[1] = {{.x = lua_tonumber(L, 2)}};
    if (!h || lua_type(L, 2) != LUA_TNUMBER || !isfinite(a[0].x)) h = PCL_READ(L, a);   /* the message */
    if (!deriv || pc_hspline_check(h, a[0].x) != PC_OK) return eval_at(L, h, a[0].x, 1);
    double d = pc_hspline_deriv(h, a[0].x);
    /* a degree below 1 has a vertical tangent at its end: t^n with n < 1 at t = 0 */
    if (!isfinite(d)) return pcl_fail(L, "the slope at t = %s is infinite (a degree below 1)", pcl_pushnum(L, a[0].x));
    return pcl_push_results(L, 0, "n", d);
}
static int hs_call(lua_State *L) { return hs_at(L, 0); }
static int hs_deriv(lua_State *L) { return hs_at(L, 1); }

/* g.n g.m g.t0 g.c1 g.c2 g.v (the junction ordinate v(t0)), then the methods */
static int hs_index(lua_State *L) {
    pc_hspline *h = pcl_tohspline(L, 1);
    const char *k = lua_tostring(L, 2);
    double x;
    if (!h || !k) return 0;
    if (pc_hspline_field(h, k, &x)) lua_pushnumber(L, x);
    else lua_getfield(L, lua_upvalueindex(1), k);
    return 1;
}

static int hs_tostring(lua_State *L) {
    pc_hspline *h = pcl_meta_self(L, pcl_tohspline(L, 1), "tostring: not a half-spline");
    const char *n = pcl_pushnum(L, h->n), *m = pcl_pushnum(L, h->m), *t0 = pcl_pushnum(L, h->t0);
    lua_pushfstring(L, "smooth.half(%s, %s, %s)", n, m, t0);
    return 1;
}

static const pcl_fn fns[] = {
    PCL_FN("smooth.sine", l_sine, t_arg, "number", "(1 - cos(pi t))/2, the smoothstep of examples 3 and 4."),
    PCL_FN("smooth.cubic", l_cubic, t_arg, "number", "3t^2 - 2t^3, the smoothstep of examples 5, 6 and 9."),
    PCL_FN("smooth.power", l_half, power_args, "number | g", "The symmetric power half-spline of degree n (example 7): 2^(n-1) t^n below 1/2, mirrored above; without t the half-spline g."),
    PCL_FN("smooth.half", l_half, half_args, "number | g", "The asymmetric half-spline of example 8: c1 t^n before t0, 1 - c2 (1 - t)^m after, slope continuous; without t the object g (g(t), g:deriv(t), g.c1, g.c2, g.v)."),
    PCL_FN("smooth.locus", l_locus, locus_args, "number", "The junction ordinate v(t0) = m t0/(n - n t0 + m t0) of the half-spline (n, m, t0): the locus of example 8."),
    PCL_FN("smooth.clamp", l_clamp, t_arg, "number", "The clamped smoothstep of examples 20-22: 0 before 0, 2t^2 to 1/2, 1 - 2(1 - t)^2 to 1, then 1."),
    PCL_FN("smooth.clamp_qb", l_clamp_qb, clamp_qb_args, "number", "smooth.clamp as the listings' strict IF chain computes it: at t exactly 0, 1/2 or 1 it keeps prev."),
    PCL_END};
static const pcl_fn methods[] = {{.name = "g:deriv", .fn = hs_deriv, .args = t_arg, .result = "number", .self = self_hs, .selftype = "half-spline",
                                  .help = "The slope g'(t) of a half-spline; infinite at an end where a degree is below 1 (an error)."}, PCL_END};
static const pcl_fn call[] = {{.name = "g", .fn = hs_call, .args = t_arg, .result = "number", .self = self_hs, .selftype = "half-spline",
                               .key = "__call", .topic = "g(t)", .callname = 1, .help = "The half-spline's value at t (t an equation: an equation)."}, PCL_END};

void pcl_open_smooth(lua_State *L) {
    int module = lua_gettop(L);
    static const luaL_Reg meta[] = {{"__tostring", hs_tostring}, {NULL, NULL}};
    pcl_open_type(L, HSPLINE_MT, meta, call, methods, hs_index);
    pcl_new_table(L, module, "smooth", fns, NULL);
    lua_settop(L, module);
}
