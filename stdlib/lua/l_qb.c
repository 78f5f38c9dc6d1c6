/* Binding of the QBasic number semantics (interp/qbasic/qbnum): the sub-table `qb` of the
 * module.  The RND state belongs to the Lua state: a userdata shared as upvalue by rnd,
 * randomize and seed; it starts at QBasic's initial seed. */
#include "pcl_args.h"
#include "pcl_core.h"   /* pcl_push_results */
#include "qbnum.h"

/* Any number, inf and NaN included (SINGLE overflows to inf; translated QBasic reports it),
 * as Lua converts it (a numeric string too, as before). */
static int read_qbnum(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    int isnum;
    out->x = lua_tonumberx(L, idx, &isnum);
    return isnum;
}
static const pcl_arg x_arg[] = {{.name = "x", .kind = PCL_ANY, .read = read_qbnum, .expect = "a number"}, PCL_END};
static const pcl_arg n_opt[] = {{.name = "n", .kind = PCL_ANY, .flags = PCL_OPT, .read = read_qbnum, .expect = "a number"}, PCL_END};
static const pcl_arg n_arg[] = {A_NUM("n"), PCL_END};
static const pcl_arg seed_arg[] = {{.name = "s", .kind = PCL_INTEGER, .flags = PCL_OPT | PCL_RANGE, .lo = 0, .hi = 0xFFFFFF}, PCL_END};
static const pcl_arg range_args[] = {A_NUM("start"), A_NUM("limit"), A_NUMOPT("step", 1, NULL), PCL_END};

/* qb.f32, and qb.csng: every SINGLE assignment of a translated program is a CSNG, one C call,
 * the error raised at the caller's line ("prog.bas:12: Overflow", as QBasic names it). */
PCL_BODY(l_f32, a) {
    double r = qb_f32(a[0].x);
    if (!isfinite(r) && !strcmp(pcl_name(L), "qb.csng")) return luaL_error(L, "Overflow");
    return pcl_push_results(L, 0, "n", r);
}

/* qb.cint and qb.clng, by the name called */
PCL_BODY(l_round, a) {
    int ok;
    double r = (strcmp(pcl_name(L), "qb.cint") ? qb_clng : qb_cint)(a[0].x, &ok);
    if (ok) return pcl_push_results(L, 0, "i b", (int)r, ok);   /* ok: an INTEGER or a LONG */
    return pcl_push_results(L, 0, "n b", r, ok);
}

/* The state in the shared upvalue: the debug library can replace it (debug.setupvalue), so
 * its type and size are checked (pcl.h: forged userdata). */
static void *upvalue_state(lua_State *L, int up, size_t size, const char *type) {
    void *p = lua_touserdata(L, up);
    int ok = p && lua_type(L, up) == LUA_TUSERDATA && lua_rawlen(L, up) == size;
    if (!ok) pcl_error(L, "%s: its %s was replaced (debug.setupvalue)", up == PCL_UPVALUE(1) ? pcl_name(L) : "qb.range", type);
    return p;
}

static qb_rnd_state *rnd_state(lua_State *L) {
    return upvalue_state(L, PCL_UPVALUE(1), sizeof(qb_rnd_state), "random-number state");
}

PCL_BODY(l_rnd, a) {
    return pcl_push_results(L, 0, "n", qb_rnd(rnd_state(L), a[0].present ? a[0].x : 1.0));
}

PCL_BODY(l_randomize, a) {
    qb_randomize(rnd_state(L), a[0].x);
    return 0;
}

PCL_BODY(l_seed, a) {
    qb_rnd_state *s = rnd_state(L);
    lua_pushinteger(L, s->seed);
    if (a[0].present) s->seed = (uint32_t)a[0].x;
    return 1;
}

static int range_iter(lua_State *L) {
    qb_range *r = upvalue_state(L, lua_upvalueindex(1), sizeof(qb_range), "range");
    double v;
    return qb_range_next(r, &v) ? pcl_push_results(L, 0, "n", v) : 0;
}

PCL_BODY(l_range, a) {
    if (qb_f32(a[2].x) == 0) return pcl_argfail(L, 3, "must be non-zero (in SINGLE), got %s", pcl_pushnum(L, a[2].x));
    qb_range *r = lua_newuserdatauv(L, sizeof *r, 0);
    qb_range_init(r, a[0].x, a[1].x, a[2].x);
    lua_pushcclosure(L, range_iter, 1);
    return 1;
}

static const pcl_fn fns[] = {
    PCL_FN("qb.f32", l_f32, x_arg, "number", "x rounded to QBasic's SINGLE (IEEE float32); beyond the SINGLE range (about 3.4E+38) it is +-inf, as a float32 is (translated QBasic reports Overflow)."),
    PCL_FN("qb.csng", l_f32, x_arg, "number", "QBasic's CSNG: x rounded to SINGLE, and the error \"Overflow\" (at the caller's line) beyond the SINGLE range or for NaN."),
    PCL_FN("qb.cint", l_round, x_arg, "integer, ok", "CINT: round to the nearest integer, ties to even; ok is false on INTEGER overflow."),
    PCL_FN("qb.clng", l_round, x_arg, "integer, ok", "CLNG: round to the nearest integer, ties to even; ok is false on LONG overflow."),
    PCL_FN("qb.range", l_range, range_args, "iterator", "A QBasic FOR loop accumulating in SINGLE: for t in qb.range(0, 1, .001) runs 1001 times, as QBasic does."),
    PCL_END};
static const pcl_fn rnd_fns[] = {   /* sharing the generator's state */
    PCL_FN("qb.rnd", l_rnd, n_opt, "number", "QBasic's RND(n): the next number of QBasic's own generator (n = 0 repeats, n < 0 reseeds)."),
    PCL_FN("qb.randomize", l_randomize, n_arg, NULL, "QBasic's RANDOMIZE n: reseed the generator."),
    PCL_FN("qb.seed", l_seed, seed_arg, "seed", "The generator's 24-bit seed; sets it when s is given."),
    PCL_END};

void pcl_open_qb(lua_State *L) {
    pcl_new_table(L, -1, "qb", fns, NULL);
    lua_getfield(L, -1, "qb");
    qb_rnd_init(lua_newuserdatauv(L, sizeof(qb_rnd_state), 0));
    pcl_register(L, -2, rnd_fns, 1);   /* pops the state, shared as upvalue */
    lua_pop(L, 1);
}
