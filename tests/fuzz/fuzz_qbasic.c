/* libFuzzer target: the QBasic translator.  The input is a QBasic program; it is translated in
 * the host's Lua state (safe mode) and the Lua text it gives is compiled.  A translation may be
 * refused with a located message; the findings are a crash, an internal error of the
 * translator (an error escaping it, or its "internal error" message) and a translation that is
 * not valid Lua.  Build: cmake -DPC_FUZZ=ON with clang (docs/safety.md). */
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <lauxlib.h>
#include "host.h"

static lua_State *L;

static int translate(lua_State *S) {
    lua_getglobal(S, "require");
    lua_pushliteral(S, "qbasic");
    lua_call(S, 1, 1);
    lua_getfield(S, -1, "translate");
    lua_pushvalue(S, 1);
    lua_pushliteral(S, "fuzz.bas");
    lua_call(S, 2, 2);
    return 2;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (!L) {
        sandbox_config cfg = sandbox_untrusted;
        L = host_new_state(&cfg);
        if (!L) __builtin_trap();
    }
    lua_settop(L, 0);
    lua_pushcfunction(L, translate);
    lua_pushlstring(L, (const char *)data, size);
    if (lua_pcall(L, 1, 2, 0) != LUA_OK) {
        fprintf(stderr, "the translator raised: %s\n", lua_tostring(L, -1));
        __builtin_trap();
    }
    if (lua_isnil(L, 1)) {
        const char *msg = lua_tostring(L, 2);
        if (!msg || strstr(msg, "internal error") || strncmp(msg, "fuzz.bas:", 9) != 0) {
            fprintf(stderr, "bad refusal: %s\n", msg ? msg : "(no message)");
            __builtin_trap();
        }
    } else {
        size_t len;
        const char *text = lua_tolstring(L, 1, &len);
        if (luaL_loadbufferx(L, text, len, "=fuzz.bas", "t") != LUA_OK) {
            fprintf(stderr, "invalid Lua: %s\n", lua_tostring(L, -1));
            __builtin_trap();
        }
    }
    lua_settop(L, 0);
    lua_gc(L, LUA_GCCOLLECT, 0);
    return 0;
}
