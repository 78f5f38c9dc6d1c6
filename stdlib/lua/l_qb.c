/* Binding of the QBasic number semantics (interp/qbasic/qbnum): the sub-table `qb` of the module.
 *
 *   qb.f32(x)                 x rounded to SINGLE (float32)
 *   qb.cint(x), qb.clng(x)    round to nearest, ties to even; second result false on overflow
 *   qb.rnd([n])               QBasic's RND(n) (n defaults to 1)
 *   qb.randomize(n)           QBasic's RANDOMIZE n
 *   qb.seed([s])              the generator's 24-bit seed (returned; set when s is given)
 *   qb.range(a, b [, step])   iterator over a FOR loop accumulating in float32:
 *                             for t in qb.range(0, 1, .001) do ... end  runs 1001 times
 *
 * The RND state belongs to the Lua state: a userdata shared as upvalue by rnd, randomize and
 * seed.  It starts at QBasic's initial seed. */
#include <math.h>
#include "pcl.h"
#include "qbnum.h"

/* A number argument, or the house error naming it ("f32: argument #1 (x) must be a number"). */
static double number_arg(lua_State *L, int arg, const char *what) {
    int isnum;
    double v = lua_tonumberx(L, arg, &isnum);
    if (!isnum) pcl_argerror(L, arg, what, "a number");
    return v;
}

static double finite_arg(lua_State *L, int arg, const char *what) {
    double v = number_arg(L, arg, what);
    if (!isfinite(v)) pcl_argerror(L, arg, what, "a finite number");
    return v;
}

static int l_f32(lua_State *L) {
    lua_pushnumber(L, qb_f32(number_arg(L, 1, "x")));
    return 1;
}

static int push_rounded(lua_State *L, double (*fn)(double, int *)) {
    int ok;
    double r = fn(number_arg(L, 1, "x"), &ok);
    if (ok) lua_pushinteger(L, (lua_Integer)r);
    else lua_pushnumber(L, r);
    lua_pushboolean(L, ok);
    return 2;
}
static int l_cint(lua_State *L) { return push_rounded(L, qb_cint); }
static int l_clng(lua_State *L) { return push_rounded(L, qb_clng); }

/* The state in the upvalue: the debug library can replace it (debug.setupvalue), so its type
 * and size are checked (pcl.h: forged userdata). */
static void *upvalue_state(lua_State *L, size_t size, const char *type) {
    void *p = lua_touserdata(L, lua_upvalueindex(1));
    int ok = p && lua_type(L, lua_upvalueindex(1)) == LUA_TUSERDATA &&
             lua_rawlen(L, lua_upvalueindex(1)) == size;
    if (!ok) pcl_error(L, "%s: its %s was replaced (debug.setupvalue)", pcl_fname(L), type);
    return p;
}

static qb_rnd_state *rnd_state(lua_State *L) {
    return upvalue_state(L, sizeof(qb_rnd_state), "random-number state");
}

static int l_rnd(lua_State *L) {
    double n = lua_isnoneornil(L, 1) ? 1.0 : number_arg(L, 1, "n");
    lua_pushnumber(L, qb_rnd(rnd_state(L), n));
    return 1;
}

static int l_randomize(lua_State *L) {
    qb_randomize(rnd_state(L), finite_arg(L, 1, "n"));
    return 0;
}

static int l_seed(lua_State *L) {
    qb_rnd_state *s = rnd_state(L);
    lua_pushinteger(L, s->seed);
    if (!lua_isnoneornil(L, 1)) {
        double v = number_arg(L, 1, "seed");
        if (!(v >= 0 && v <= 0xFFFFFF && v == floor(v)))
            return pcl_argerror(L, 1, "seed", "an integer 0..16777215");
        s->seed = (uint32_t)v;
    }
    return 1;
}

static int range_iter(lua_State *L) {
    qb_range *r = upvalue_state(L, sizeof(qb_range), "range");
    double v;
    if (!qb_range_next(r, &v)) return 0;
    lua_pushnumber(L, v);
    return 1;
}

static int l_range(lua_State *L) {
    double a = finite_arg(L, 1, "start");
    double b = finite_arg(L, 2, "limit");
    double step = lua_isnoneornil(L, 3) ? 1.0 : finite_arg(L, 3, "step");
    if (qb_f32(step) == 0) return pcl_argerror(L, 3, "step", "non-zero");
    qb_range *r = lua_newuserdatauv(L, sizeof *r, 0);
    qb_range_init(r, a, b, step);
    lua_pushcclosure(L, range_iter, 1);
    return 1;
}

void pcl_open_qb(lua_State *L) {
    lua_newtable(L);
    lua_pushcfunction(L, l_f32);
    lua_setfield(L, -2, "f32");
    lua_pushcfunction(L, l_cint);
    lua_setfield(L, -2, "cint");
    lua_pushcfunction(L, l_clng);
    lua_setfield(L, -2, "clng");
    lua_pushcfunction(L, l_range);
    lua_setfield(L, -2, "range");
    qb_rnd_state *s = lua_newuserdatauv(L, sizeof *s, 0);
    qb_rnd_init(s);
    static const luaL_Reg rnd_functions[] = {
        {"rnd", l_rnd}, {"randomize", l_randomize}, {"seed", l_seed}, {NULL, NULL}};
    luaL_setfuncs(L, rnd_functions, 1);   /* pops the state, shared as upvalue */
    lua_setfield(L, -2, "qb");
}
