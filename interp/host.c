/* The Lua state of the host: standard libraries, pointcalc in globals, tracebacks, loading of
 * Lua and QBasic scripts. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <lauxlib.h>
#include <lualib.h>
#include "host.h"
#include "pcl.h"
#include "pcl_args.h"
#include "pcl_embed.h"
#include "sandbox.h"

int luaopen_pointcalc(lua_State *L);

const char *host_progname = "pointcalc";

static int load_embedded(lua_State *L) {
    const pc_chunk *ch = lua_touserdata(L, lua_upvalueindex(1));
    char chunkname[96];
    snprintf(chunkname, sizeof chunkname, "=[pointcalc/%s.lua]", ch->name);
    if (luaL_loadbuffer(L, ch->text, ch->len, chunkname) != LUA_OK) return lua_error(L);
    if (sandbox_is_safe(L) && !strcmp(ch->name, "repl")) {
        /* the REPL's own code (describing values, tracebacks) keeps the debug library that
         * safe mode takes from scripts: its _ENV reads the globals, but `debug` is its own */
        lua_newtable(L);
        lua_getfield(L, LUA_REGISTRYINDEX, "pointcalc.host.debug");
        lua_setfield(L, -2, "debug");
        lua_createtable(L, 0, 2);
        lua_pushglobaltable(L);
        lua_setfield(L, -2, "__index");
        lua_pushglobaltable(L);
        lua_setfield(L, -2, "__newindex");
        lua_setmetatable(L, -2);
        lua_setupvalue(L, -2, 1);
    }
    lua_pushvalue(L, 1);
    lua_call(L, 1, 1);
    return 1;
}

lua_State *host_new_state(const sandbox_config *cfg) {
    lua_State *L = luaL_newstate();
    if (!L) return NULL;
    /* scripts make many short-lived points: the generational collector suits them */
    lua_gc(L, LUA_GCGEN, 0, 0);
    luaL_openlibs(L);

    luaL_getsubtable(L, LUA_REGISTRYINDEX, LUA_PRELOAD_TABLE);
    lua_pushcfunction(L, luaopen_pointcalc);
    lua_setfield(L, -2, "pointcalc");
    for (const pc_chunk *ch = pc_interp_chunks; ch->name; ch++) {
        lua_pushlightuserdata(L, (void *)ch);
        lua_pushcclosure(L, load_embedded, 1);
        lua_setfield(L, -2, ch->name);
    }
    lua_pop(L, 1);

    /* require "pointcalc" and copy every field into the globals */
    lua_getglobal(L, "require");
    lua_pushliteral(L, "pointcalc");
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
        fprintf(stderr, "%s: %s\n", host_progname, lua_tostring(L, -1));
        lua_close(L);
        return NULL;
    }
    /* every public field; names starting with '_' (_VERSION, private helpers) stay inside */
    lua_pushglobaltable(L);
    lua_pushnil(L);
    while (lua_next(L, -3)) {
        if (lua_type(L, -2) == LUA_TSTRING && lua_tostring(L, -2)[0] == '_') {
            lua_pop(L, 1);
            continue;
        }
        lua_pushvalue(L, -2);
        lua_insert(L, -2);
        lua_settable(L, -4);
    }
    lua_pop(L, 1);
    lua_setglobal(L, "pointcalc");
    /* the rules for files, chunks and the safe mode, once the globals are complete; the
     * memory limit counts from here (pointcalc itself included) */
    sandbox_attach(L, cfg);
    lua_pushcfunction(L, sandbox_apply);
    if (lua_pcall(L, 0, 0, 0) != LUA_OK) {
        fprintf(stderr, "%s: %s\n", host_progname, lua_tostring(L, -1));
        lua_close(L);
        return NULL;
    }
    return L;
}

static int traceback(lua_State *L) {
    const char *msg = lua_tostring(L, 1);
    if (msg == NULL) {
        if (luaL_callmeta(L, 1, "__tostring") && lua_type(L, -1) == LUA_TSTRING) return 1;
        msg = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
    }
    const char *hint = pcl_global_hint(L, msg);   /* lable(...): (did you mean 'label'?) */
    if (hint) msg = lua_pushfstring(L, "%s %s", msg, hint);
    luaL_traceback(L, L, msg, 1);
    return 1;
}

int host_limit_stopped = 0;
static char qbasic_chunk[512];   /* the QBasic program being run, for its messages */

/* A limit stopped a QBasic program: the runtime could not name the program's line (no Lua code
 * runs once the time is up), so the message names the program and says what happened. */
static void print_qbasic_limit(const char *msg) {
    const char *what = strstr(msg, "time limit of");
    if (!what) what = strstr(msg, "memory limit of");
    size_t n = strcspn(what, "\n");
    if (!strncmp(msg, qbasic_chunk, strlen(qbasic_chunk)) && msg[strlen(qbasic_chunk)] == ':')
        fprintf(stderr, "%.*s\n", (int)(what - msg + n), msg);
    else
        fprintf(stderr, "%s: %.*s: the program was stopped\n", qbasic_chunk, (int)n, what);
}

int host_pcall(lua_State *L, int nargs) {
    int base = lua_gettop(L) - nargs;
    lua_pushcfunction(L, traceback);
    lua_insert(L, base);
    lua_Debug ar;   /* the chunk's name, for a memory error (it has no line) */
    char where[LUA_IDSIZE] = "";
    lua_pushvalue(L, base + 1);
    if (lua_getinfo(L, ">S", &ar)) snprintf(where, sizeof where, "%s", ar.short_src);
    sandbox_start(L);
    int status = lua_pcall(L, nargs, 0, base);
    sandbox_stop(L);
    lua_remove(L, base);
    if (status != LUA_OK) {
        sandbox_explain(L, status, where[0] ? where : NULL);
        const char *msg = lua_tostring(L, -1);
        int limit = msg && (strstr(msg, "time limit of") || strstr(msg, "memory limit of"));
        host_limit_stopped = limit;
        if (limit && qbasic_chunk[0] && !getenv("PC_QBASIC_TRACEBACK")) print_qbasic_limit(msg);
        else fprintf(stderr, "%s\n", msg ? msg : "(error object is not a string)");
        lua_pop(L, 1);
        return 0;
    }
    return 1;
}

/* Read a whole file ("-" is standard input) into a Lua string on the stack. */
static int push_file(lua_State *L, const char *path) {
    FILE *f = strcmp(path, "-") ? fopen(path, "rb") : stdin;
    if (!f) {
        fprintf(stderr, "%s: cannot open '%s': %s\n", host_progname, path, strerror(errno));
        return 0;
    }
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    char buf[8192];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0) luaL_addlstring(&b, buf, n);
    int bad = ferror(f);
    if (f != stdin) fclose(f);
    luaL_pushresult(&b);
    if (bad) {
        fprintf(stderr, "%s: cannot read '%s'\n", host_progname, path);
        lua_pop(L, 1);
        return 0;
    }
    return 1;
}

/* Translate the QBasic source on top of the stack; replaces it by the Lua text. */
static int translate_qbasic(lua_State *L, const char *path) {
    lua_getglobal(L, "require");
    lua_pushliteral(L, "qbasic");
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
        fprintf(stderr, "%s: the QBasic front end failed to load: %s\n", host_progname,
                lua_tostring(L, -1));
        return 0;
    }
    lua_getfield(L, -1, "translate");
    lua_pushvalue(L, -3);
    lua_pushstring(L, strcmp(path, "-") ? path : "stdin");
    snprintf(qbasic_chunk, sizeof qbasic_chunk, "%s", strcmp(path, "-") ? path : "stdin");
    if (lua_pcall(L, 2, 2, 0) != LUA_OK || lua_isnil(L, -2)) {
        fprintf(stderr, "%s\n", lua_tostring(L, -1));
        return 0;
    }
    lua_pop(L, 1);         /* second result */
    lua_replace(L, -3);    /* Lua text over the source */
    lua_pop(L, 1);         /* the qbasic module */
    return 1;
}

int host_load_script(lua_State *L, const char *path, int qbasic) {
    if (!push_file(L, path)) return 0;
    if (qbasic && !translate_qbasic(L, path)) return 0;
    size_t len;
    const char *text = lua_tolstring(L, -1, &len);
    if (!qbasic && len > 0 && text[0] == '#') {   /* skip a #! line, keeping line numbers */
        size_t i = 0;
        while (i < len && text[i] != '\n') i++;
        text += i;
        len -= i;
    }
    if (len > 0 && text[0] == LUA_SIGNATURE[0]) {
        /* Lua does not verify bytecode: a damaged or hostile binary chunk crashes the
         * interpreter, so scripts are source only (lua5.4 runs precompiled files if needed) */
        fprintf(stderr, "%s: cannot run '%s': it is a precompiled Lua chunk; pointcalc runs source "
                "scripts\n", host_progname, path);
        lua_pop(L, 1);
        return 0;
    }
    const char *chunkname = lua_pushfstring(L, "@%s", strcmp(path, "-") ? path : "stdin");
    int status = luaL_loadbufferx(L, text, len, chunkname, "t");
    lua_remove(L, -2);     /* chunk name */
    lua_remove(L, -2);     /* source text */
    if (status != LUA_OK) {
        fprintf(stderr, "%s\n", lua_tostring(L, -1));
        lua_pop(L, 1);
        return 0;
    }
    return 1;
}

int host_emit_lua(lua_State *L, const char *path) {
    if (!push_file(L, path) || !translate_qbasic(L, path)) return 0;
    size_t len;
    const char *text = lua_tolstring(L, -1, &len);
    fwrite(text, 1, len, stdout);
    lua_pop(L, 1);
    return 1;
}
