/* Argument checking shared by all bindings: the house error style
 * "NAME: argument #N (what) must be EXPECTED, got VALUE". */
#include "pcl_args.h"

/* A declared function's name is its declaration's (pcl_name: whatever the script called it
 * through, pcall(label, 5) as well); else the name Lua knows, or the caller's when called from
 * C (through the safe mode's wrapper of save, the name the script used is the caller's). */
const char *pcl_fname(lua_State *L) {
    lua_Debug ar;
    if (pcl_declared(L)) return pcl_name(L);
    if (lua_getstack(L, 0, &ar) && lua_getinfo(L, "n", &ar) && ar.name) return ar.name;
    if (lua_getstack(L, 1, &ar) && lua_getinfo(L, "nS", &ar) && ar.name && ar.what[0] == 'C')
        return ar.name;
    return "pointcalc";
}

int pcl_arg_shown(lua_State *L, int arg) {
    lua_Debug ar;
    if (lua_getstack(L, 0, &ar) && lua_getinfo(L, "n", &ar) && ar.namewhat &&
        strcmp(ar.namewhat, "method") == 0)
        return arg - 1;                                 /* A:dist(B): B is argument #1 */
    return arg;
}

/* What the caller passed; a missing argument reads "nil", as DESIGN.md's example has it. */
const char *pcl_shown(lua_State *L, int idx) {
    if (lua_isinteger(L, idx)) return lua_pushfstring(L, "%I", lua_tointeger(L, idx));
    if (lua_type(L, idx) == LUA_TNUMBER) return lua_pushfstring(L, "%f", lua_tonumber(L, idx));
    if (lua_isnone(L, idx)) return "nil";
    if (luaL_getmetafield(L, idx, "__name") == LUA_TSTRING) {
        const char *type = lua_tostring(L, -1);   /* a point as V(1, 1), not just "point" */
        return strcmp(type, "point") ? type : luaL_tolstring(L, idx, NULL);
    }
    return luaL_typename(L, idx);
}

int pcl_argerror_full(lua_State *L, const char *fname, int idx, int shown, const char *what,
                      const char *expected) {
    idx = lua_absindex(L, idx);
    const char *arg = shown == 0 ? "self" : lua_pushfstring(L, "argument #%d", shown);
    if (what && what[0]) arg = lua_pushfstring(L, "%s (%s)", arg, what);
    return pcl_error(L, "%s: %s must be %s, got %s", fname, arg, expected, pcl_shown(L, idx));
}

/* The innermost Lua function that is not one of pointcalc's embedded helpers: an error raised
 * in a toolkit function points at the user's line, not inside the toolkit. */
void pcl_pushwhere(lua_State *L) {
    lua_Debug ar;
    for (int level = 1; lua_getstack(L, level, &ar); level++) {
        lua_getinfo(L, "Sl", &ar);
        if (ar.currentline <= 0) continue;                          /* a C function */
        if (strncmp(ar.source, "=[pointcalc/", 12) == 0) continue;  /* an embedded helper */
        lua_pushfstring(L, "%s:%d: ", ar.short_src, ar.currentline);
        return;
    }
    lua_pushliteral(L, "");
}

int pcl_verror(lua_State *L, const char *prefix, const char *fmt, va_list ap) {
    pcl_pushwhere(L);
    lua_pushstring(L, prefix);
    lua_pushvfstring(L, fmt, ap);
    lua_concat(L, 3);
    return lua_error(L);
}

int pcl_error(lua_State *L, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    return pcl_verror(L, "", fmt, ap);
}

void *pcl_meta_self(lua_State *L, void *p, const char *msg) {
    if (!p) pcl_error(L, "%s", msg);
    return p;
}

/* ---- forged userdata (pcl.h) ---------------------------------------------------------------- */

void *pcl_genuine(lua_State *L, int idx, void *p, int ok, const char *type) {
    if (!p || ok) return p;
    int len = (int)lua_rawlen(L, idx);
    if (idx > 0 && idx <= lua_gettop(L))
        pcl_error(L, "%s: argument #%d is a forged %s (a userdata of %d bytes given the %s "
                  "metatable, e.g. by debug.setmetatable), not a %s", pcl_fname(L),
                  pcl_arg_shown(L, idx), type, len, type, type);
    pcl_error(L, "%s: a forged %s (a userdata of %d bytes given the %s metatable or put in an "
              "upvalue with the debug library), not a %s", pcl_fname(L), type, len, type, type);
    return NULL;
}

const char *pcl_pushnum(lua_State *L, double x) {
    char buf[40];
    return lua_pushstring(L, pc_num_text(x, buf, sizeof buf));
}

int pcl_statuserror(lua_State *L, const char *fname, int status, const char *context) {
    int ctx = context && context[0];
    return pcl_error(L, ctx ? "%s: %s (%s)" : "%s: %s%s", fname, ctx ? context : "", pc_strerror(status));
}

void pcl_private(lua_State *L, int module) { luaL_getsubtable(L, module, "_tk"); }

/* ---- Lua called from the core ------------------------------------------------------------- */

#define CBERR_KEY "pointcalc.callback_error"
static _Thread_local lua_State *current_L;

void pcl_callback_state(lua_State *L) { current_L = L; }

lua_State *pcl_current_state(void) { return current_L; }

int pcl_callback_failed(lua_State *L) {
    lua_setfield(L, LUA_REGISTRYINDEX, CBERR_KEY);   /* the error object */
    return PC_EARG;
}

int pcl_raise_status(lua_State *L, const char *fname, int status) {
    if (lua_getfield(L, LUA_REGISTRYINDEX, CBERR_KEY) != LUA_TNIL) {
        lua_pushnil(L);
        lua_setfield(L, LUA_REGISTRYINDEX, CBERR_KEY);
        return lua_error(L);
    }
    lua_pop(L, 1);
    return pcl_statuserror(L, fname, status, NULL);
}

/* ---- the same errors for the embedded Lua helpers (_tk) ------------------------------------- */

/* _tk.raise(msg): msg located at the user's code */
static int tk_raise(lua_State *L) { return pcl_error(L, "%s", luaL_checkstring(L, 1)); }

/* _tk.shown(value): a value as the messages show it */
static int tk_shown(lua_State *L) {
    lua_settop(L, 1);
    lua_pushstring(L, pcl_shown(L, 1));
    return 1;
}

/* _tk.argerror(fname, n, what, expected, value): "FNAME: argument #N (WHAT) must be EXPECTED,
 * got VALUE" at the user's line */
static int tk_argerror(lua_State *L) {
    lua_settop(L, 5);
    return pcl_argerror_full(L, luaL_checkstring(L, 1), 5, (int)luaL_checkinteger(L, 2), luaL_checkstring(L, 3),
                             luaL_checkstring(L, 4));
}

/* _tk.fielderror(fname, field, expected, value): "FNAME: FIELD must be EXPECTED, got VALUE" */
static int tk_fielderror(lua_State *L) {
    lua_settop(L, 4);
    const char *fname = luaL_checkstring(L, 1), *field = luaL_checkstring(L, 2), *expected = luaL_checkstring(L, 3);
    return pcl_error(L, "%s: %s must be %s, got %s", fname, field, expected, pcl_shown(L, 4));
}

/* _tk.global_hint(msg): "(did you mean 'label'?)" for a misspelt global, or nil (the REPL) */
static int tk_global_hint(lua_State *L) {
    if (!pcl_global_hint(L, luaL_checkstring(L, 1))) lua_pushnil(L);
    return 1;
}

void pcl_open_errors(lua_State *L) {
    pcl_private(L, -1);
    static const luaL_Reg fns[] = {{"raise", tk_raise}, {"shown", tk_shown}, {"argerror", tk_argerror},
                                   {"fielderror", tk_fielderror}, {"global_hint", tk_global_hint}, {NULL, NULL}};
    luaL_setfuncs(L, fns, 0);
    lua_pop(L, 1);
}
