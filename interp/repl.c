/* The interactive loop: read a line (with line editing when libedit is there), run it as an
 * expression whose values are printed, or as a statement; an incomplete chunk continues on the
 * next line, as in lua5.4. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <lauxlib.h>
#include "host.h"
#ifdef PC_HAVE_LIBEDIT
#include <editline/readline.h>
#endif

static char *read_line(const char *prompt) {
#ifdef PC_HAVE_LIBEDIT
    char *line = readline(prompt);
    if (line && *line) add_history(line);
    return line;
#else
    fputs(prompt, stdout);
    fflush(stdout);
    char buf[4096];
    if (!fgets(buf, sizeof buf, stdin)) return NULL;
    buf[strcspn(buf, "\n")] = 0;
    return strdup(buf);
#endif
}

/* Is the load error an unfinished chunk (the parser reached <eof>)? */
static int incomplete(lua_State *L, int status) {
    if (status != LUA_ERRSYNTAX) return 0;
    size_t len;
    const char *msg = lua_tolstring(L, -1, &len);
    return len >= 5 && strcmp(msg + len - 5, "<eof>") == 0;
}

static void print_results(lua_State *L, int base) {
    int n = lua_gettop(L) - base;
    if (n == 0) return;
    for (int i = 1; i <= n; i++) {
        luaL_tolstring(L, base + i, NULL);
        fputs(lua_tostring(L, -1), stdout);
        fputs(i < n ? "\t" : "\n", stdout);
        lua_pop(L, 1);
    }
    lua_settop(L, base);
}

static int run(lua_State *L, int base) {
    lua_getglobal(L, "debug");
    lua_getfield(L, -1, "traceback");
    lua_remove(L, -2);
    lua_insert(L, base + 1);
    int status = lua_pcall(L, 0, LUA_MULTRET, base + 1);
    lua_remove(L, base + 1);
    if (status != LUA_OK) {
        fprintf(stderr, "%s\n", lua_tostring(L, -1));
        lua_settop(L, base);
        return 0;
    }
    print_results(L, base);
    return 1;
}

void host_repl(lua_State *L) {
    printf("pointcalc REPL (Lua 5.4): Ctrl-D to quit\n");
    luaL_Buffer chunk;
    char *line;
    while ((line = read_line("> ")) != NULL) {
        int base = lua_gettop(L);
        lua_pushstring(L, line);
        free(line);
        for (;;) {
            /* first as an expression whose values are printed, then as statements */
            const char *src = lua_tostring(L, base + 1);
            const char *expr = lua_pushfstring(L, "return %s;", src);
            int status = luaL_loadbuffer(L, expr, strlen(expr), "=stdin");
            lua_remove(L, -2);
            if (status != LUA_OK) {
                lua_pop(L, 1);
                status = luaL_loadbuffer(L, src, strlen(src), "=stdin");
            }
            if (incomplete(L, status)) {
                lua_pop(L, 1);
                char *more = read_line(">> ");
                if (!more) break;
                luaL_buffinit(L, &chunk);
                lua_pushvalue(L, base + 1);
                luaL_addvalue(&chunk);
                luaL_addchar(&chunk, '\n');
                luaL_addstring(&chunk, more);
                free(more);
                luaL_pushresult(&chunk);
                lua_replace(L, base + 1);
                continue;
            }
            if (status != LUA_OK) {
                fprintf(stderr, "%s\n", lua_tostring(L, -1));
                lua_pop(L, 1);
            } else {
                lua_remove(L, base + 1);   /* the source */
                run(L, base);
            }
            break;
        }
        lua_settop(L, base);
    }
    putchar('\n');
}
