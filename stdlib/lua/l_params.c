/* Binding of a script's declared parameters (issue 16: live pages and animation):
 *   slider(name, min, max, default [, step | {step =, animate = true}]) -> value
 * Run normally a slider is its default, or the value the host set for its name (the command
 * line's --set name=value, a live page's slider, an animation frame).  Every declaration is
 * recorded in order, so the host can build the page's sliders or run the frames of the
 * parameter marked animate.
 * The host's side (pcl.h): pcl_param_set before running a script, pcl_push_params after. */
#include "pcl_args.h"
#include "pcl_core.h"

#define SET_KEY "pointcalc.params.set"           /* name -> value given by the host */
#define DECLARED_KEY "pointcalc.params.declared" /* the list of declarations, in order */
#define NAMES_KEY "pointcalc.params.names"       /* name -> true once declared */

void pcl_param_set(lua_State *L, const char *name, double value) {
    luaL_getsubtable(L, LUA_REGISTRYINDEX, SET_KEY);
    lua_pushnumber(L, value);
    lua_setfield(L, -2, name);
    lua_pop(L, 1);
}

void pcl_push_params(lua_State *L) { luaL_getsubtable(L, LUA_REGISTRYINDEX, DECLARED_KEY); }

/* The name: one a URL and a command line can carry, letters, digits, _ (not first a digit). */
static int read_name(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    static const char OK[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_";
    size_t len;
    const char *s = out->s = lua_tolstring(L, idx, &len);
    return lua_type(L, idx) == LUA_TSTRING && len > 0 && len <= 64 && !(s[0] >= '0' && s[0] <= '9') &&
           strspn(s, OK) == len;
}
/* step: a number, or the table {step =, animate =} (read by the body) */
static int read_step(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    out->x = lua_tonumber(L, idx);
    return lua_istable(L, idx) || (lua_type(L, idx) == LUA_TNUMBER && isfinite(out->x));
}
static const pcl_arg slider_keys[] = {A_NUM("step"), {.name = "animate", .kind = PCL_BOOLEAN, .shown = "true"}, PCL_END};
static const pcl_arg slider_opts = {.name = "step", .kind = PCL_OPTIONS, .keys = slider_keys};
static const pcl_arg slider_args[] = {
    {.name = "name", .kind = PCL_ANY, .read = read_name, .expect = "a name of letters, digits and _ (up to 64)"},
    A_NUM("min"), A_NUM("max"), A_NUM("default"),
    {.name = "step", .kind = PCL_ANY, .flags = PCL_OPT, .read = read_step, .expect = "a number or a table {step =, animate =}"},
    PCL_END};

PCL_BODY(l_slider, a) {
    pcl_val k[2] = {0};   /* a: name, min, max, default, step; k: the table's step, animate */
    if (lua_istable(L, 5)) pcl_read_options(L, 5, 5, &slider_opts, k);
    const char *name = a[0].s;
    double lo = a[1].x, hi = a[2].x, dflt = a[3].x, step = lua_istable(L, 5) ? k[0].x : a[4].x;
    if (!(lo < hi)) return pcl_argfail(L, 3, "must be greater than min");
    if (dflt < lo || dflt > hi) return pcl_argfail(L, 4, "must be between min and max");
    if (step < 0 || step > hi - lo) return pcl_argfail(L, 5, "must be between 0 and max - min");

    /* the declaration, once per name (a script may ask for its slider again) */
    luaL_getsubtable(L, LUA_REGISTRYINDEX, NAMES_KEY);
    if (lua_getfield(L, -1, name) == LUA_TNIL) {
        lua_pushboolean(L, 1);
        lua_setfield(L, -3, name);
        luaL_getsubtable(L, LUA_REGISTRYINDEX, DECLARED_KEY);
        pcl_push_results(L, 0, "name=s min=n max=n default=n step=n animate=b", name, lo, hi, dflt, step, (int)k[1].x);
        lua_rawseti(L, -2, luaL_len(L, -2) + 1);
    }

    /* the value: the host's, checked against the range, else the default */
    luaL_getsubtable(L, LUA_REGISTRYINDEX, SET_KEY);
    double v = lua_getfield(L, -1, name) == LUA_TNUMBER ? lua_tonumber(L, -1) : dflt;
    if (v < lo || v > hi)
        return pcl_fail(L, "the value %s set for %s is outside its range [%s, %s]", pcl_pushnum(L, v), name,
                        pcl_pushnum(L, lo), pcl_pushnum(L, hi));
    return pcl_push_results(L, 0, "n", v);
}

/* _tk.param_set(name, value): what the host does, for tests and Lua-side tools */
static const pcl_arg set_args[] = {A_ANY("name", read_name, "a parameter name"), A_NUM("value"), PCL_END};
PCL_BODY(l_param_set, a) {
    pcl_param_set(L, a[0].s, a[1].x);
    return 0;
}

/* _tk.params() -> the list of declarations {name, min, max, default, step, animate} */
static int l_params(lua_State *L) {
    pcl_push_params(L);
    return 1;
}

void pcl_open_params(lua_State *L) {
    int module = lua_gettop(L);
    static const pcl_fn fns[] = {
        {.name = "slider", .fn = l_slider, .args = slider_args, .sig = "slider(name, min, max, default [, step | {step =, animate = true}]) -> value",
         .help = "A parameter of the script: its default, or the value given by --set name=value, a live page's slider (pointcalc serve) or an animation frame (--frames)."},
        PCL_END};
    pcl_register(L, module, fns, 0);
    pcl_private(L, module);
    static const pcl_fn priv[] = {PCL_FN("_tk.param_set", l_param_set, set_args, NULL, NULL),
                                  PCL_FN("_tk.params", l_params, NULL, NULL, NULL), PCL_END};
    pcl_register_private(L, -1, priv);
    lua_settop(L, module);
}
