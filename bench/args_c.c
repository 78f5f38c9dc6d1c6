/* The per-call cost of the declared argument layer (stdlib/lua/pcl_args.h) against bindings
 * written by hand with lua_tonumber, in one run of one Lua state: each function is called N
 * times from a Lua loop, best of R rounds, minus the loop alone.  Prints one line per function
 * (ns per call) and the ratios declared / hand-written.  A benchmark, not a test.
 * Usage: args_c [N [R]] */
#include <lauxlib.h>
#include <lualib.h>
#include <stdio.h>
#include <stdlib.h>
#include "pcl_args.h"
#include "qbnum.h"

int luaopen_pointcalc(lua_State *L);

/* ---- hand-written: what a binding without the layer types ------------------------------- */

static int hand_num(lua_State *L) {              /* f(x) -> x rounded to float32 */
    int ok;
    double x = lua_tonumberx(L, 1, &ok);
    if (!ok) return luaL_argerror(L, 1, "number expected");
    lua_pushnumber(L, qb_f32(x));
    return 1;
}

static int hand_num3(lua_State *L) {             /* f(x, y [, c]) -> x + y + c */
    int ok1, ok2;
    double x = lua_tonumberx(L, 1, &ok1), y = lua_tonumberx(L, 2, &ok2);
    if (!ok1 || !ok2) return luaL_error(L, "number expected");
    double c = luaL_optnumber(L, 3, 15);
    lua_pushnumber(L, x + y + c);
    return 1;
}

/* ---- the same two on the layer ----------------------------------------------------------- */

static const pcl_arg num_args[] = {A_NUM("x"), PCL_END};
static int decl_num(lua_State *L) {
    pcl_val a[1] = {0};
    PCL_READ(L, a);
    lua_pushnumber(L, qb_f32(a[0].x));
    return 1;
}

static const pcl_arg num3_args[] = {A_NUM("x"), A_NUM("y"), A_NUMOPT("c", 15, "15"), PCL_END};
static int decl_num3(lua_State *L) {
    pcl_val a[3] = {0};
    PCL_READ(L, a);
    lua_pushnumber(L, a[0].x + a[1].x + a[2].x);
    return 1;
}

static const pcl_fn decls[] = {PCL_FN("decl_num", decl_num, num_args, "number", "bench"),
                               PCL_FN("decl_num3", decl_num3, num3_args, "number", "bench"), PCL_END};

/* ---- the timing loop, in Lua ------------------------------------------------------------- */

/* Each round times every loop once, so that a load from elsewhere on the machine falls on all
 * of them alike; the best round of each counts. */
static const char SCRIPT[] =
    "local N, R = ...\n"
    "local clock = os.clock\n"
    "local pc = require 'pointcalc'\n"
    "pc.screen(12)\n"
    "local hand_num, hand_num3, decl_num, decl_num3 = hand_num, hand_num3, decl_num, decl_num3\n"
    "local f32, pset = pc.qb.f32, pc.pset\n"
    "local loops = {\n"
    "  {'loop1', function() local s = 0 for i = 1, N do s = s + i * 0.5 end end},\n"
    "  {'loop3', function() local s = 0 for i = 1, N do s = s + (i % 640) + (i % 480) end end},\n"
    "  {'hand_num', function() local s = 0 for i = 1, N do s = s + hand_num(i * 0.5) end end, 'loop1'},\n"
    "  {'decl_num', function() local s = 0 for i = 1, N do s = s + decl_num(i * 0.5) end end, 'loop1'},\n"
    "  {'qb.f32', function() local s = 0 for i = 1, N do s = s + f32(i * 0.5) end end, 'loop1'},\n"
    "  {'hand_num3', function() local s = 0 for i = 1, N do s = s + hand_num3(i % 640, i % 480, 3) end end, 'loop3'},\n"
    "  {'decl_num3', function() local s = 0 for i = 1, N do s = s + decl_num3(i % 640, i % 480, 3) end end, 'loop3'},\n"
    "  {'pset', function() for i = 1, N do pset(i % 640, i % 480, 3) end end, 'loop3'},\n"
    "}\n"
    "local best = {}\n"
    "for _ = 1, R do\n"
    "  for _, l in ipairs(loops) do\n"
    "    local t0 = clock()\n"
    "    l[2]()\n"
    "    local t = clock() - t0\n"
    "    best[l[1]] = math.min(best[l[1]] or math.huge, t)\n"
    "  end\n"
    "end\n"
    "local ns = {}\n"
    "for _, l in ipairs(loops) do\n"
    "  if l[3] then\n"
    "    ns[l[1]] = (best[l[1]] - best[l[3]]) / N * 1e9\n"
    "    print(string.format('%-10s %7.1f ns per call', l[1], ns[l[1]]))\n"
    "  end\n"
    "end\n"
    "print(string.format('ratio decl_num / hand_num   %.2f', ns.decl_num / ns.hand_num))\n"
    "print(string.format('ratio qb.f32 / hand_num     %.2f', ns['qb.f32'] / ns.hand_num))\n"
    "print(string.format('ratio decl_num3 / hand_num3 %.2f', ns.decl_num3 / ns.hand_num3))\n"
    "print(string.format('ratio pset / hand_num3      %.2f', ns.pset / ns.hand_num3))\n";

int main(int argc, char **argv) {
    long n = argc > 1 ? atol(argv[1]) : 1000000;
    long rounds = argc > 2 ? atol(argv[2]) : 15;
    lua_State *L = luaL_newstate();
    luaL_openlibs(L);
    luaL_requiref(L, "pointcalc", luaopen_pointcalc, 0);
    lua_pop(L, 1);
    lua_register(L, "hand_num", hand_num);
    lua_register(L, "hand_num3", hand_num3);
    lua_pushglobaltable(L);
    pcl_register(L, -1, decls, 0);
    lua_pop(L, 1);
    if (luaL_loadbuffer(L, SCRIPT, sizeof SCRIPT - 1, "=args_bench") != LUA_OK) {
        fprintf(stderr, "%s\n", lua_tostring(L, -1));
        return 1;
    }
    lua_pushinteger(L, n);
    lua_pushinteger(L, rounds);
    if (lua_pcall(L, 2, 0, 0) != LUA_OK) {
        fprintf(stderr, "%s\n", lua_tostring(L, -1));
        return 1;
    }
    lua_close(L);
    return 0;
}
