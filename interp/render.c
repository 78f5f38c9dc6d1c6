/* Rendering a script on demand in a fresh state with the sandbox's limits (render.h). */
#include "render.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <lauxlib.h>
#include "host.h"
#include "pcl.h"
#include "writers.h"

/* "file:LINE: message" and a traceback: keep the message, find the script's line in it */
static int msgh(lua_State *L) {
    const char *msg = lua_tostring(L, 1);
    if (!msg) msg = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
    lua_pushstring(L, msg);
    return 1;
}

static int line_of(const char *msg, const char *path) {
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    const char *p = strstr(msg, base);
    if (!p) return 0;
    p += strlen(base);
    return *p == ':' ? atoi(p + 1) : 0;
}

static int fail(render_run *r, const char *path, const char *msg) {
    snprintf(r->error, sizeof r->error, "%s", msg);
    r->line = line_of(msg, path);
    return 0;
}

int render_script(const char *path, const render_param *params, int nparams,
                  const sandbox_config *cfg, render_run *r) {
    memset(r, 0, sizeof *r);
    lua_State *L = r->L = host_new_state(cfg);
    if (!L) return fail(r, path, "out of memory for a Lua state");
    for (int i = 0; i < nparams; i++) pcl_param_set(L, params[i].name, params[i].value);
    lua_createtable(L, 0, 1);            /* arg[0]: the script, as a command-line run has it */
    lua_pushstring(L, path);
    lua_rawseti(L, -2, 0);
    lua_setglobal(L, "arg");
    size_t n = strlen(path);
    int qbasic = n > 4 && strcmp(path + n - 4, ".bas") == 0;
    if (qbasic) {
        if (!host_load_script(L, path, 1))
            return fail(r, path, "the QBasic program could not be translated (the message is on the "
                                 "server's terminal)");
    } else if (luaL_loadfilex(L, path, "t") != LUA_OK) {
        const char *msg = lua_tostring(L, -1);
        fail(r, path, msg ? msg : "cannot load the script");
        lua_pop(L, 1);
        return 0;
    }
    lua_pushcfunction(L, msgh);
    lua_insert(L, -2);
    sandbox_start(L);
    int status = lua_pcall(L, 0, 0, -2);
    sandbox_stop(L);
    if (status != LUA_OK) {
        sandbox_explain(L, status, path);   /* a refused allocation says so */
        fail(r, path, lua_tostring(L, -1) ? lua_tostring(L, -1) : "error");
        lua_pop(L, 2);
        return 0;
    }
    lua_pop(L, 1);
    return 1;
}

void render_close(render_run *r) {
    if (r->L) lua_close(r->L);
    r->L = NULL;
}

char *render_encode(render_run *r, pc_format fmt, size_t *len) {
    char *buf = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&buf, &size);
    if (!f) {
        snprintf(r->error, sizeof r->error, "out of memory");
        return NULL;
    }
    char why[512] = "";
    int rc = pc_encode(pcl_canvas(r->L), fmt, pcl_theme(r->L), f, why, sizeof why);
    if (fclose(f) != 0 || rc != PC_OK) {
        free(buf);
        snprintf(r->error, sizeof r->error, "cannot encode the picture%s%s", *why ? ": " : "", why);
        return NULL;
    }
    *len = size;
    return buf;
}

int render_parse_param(const char *s, render_param *p) {
    const char *eq = strchr(s, '=');
    if (!eq || eq == s || (size_t)(eq - s) >= sizeof p->name) return 0;
    memcpy(p->name, s, (size_t)(eq - s));
    p->name[eq - s] = 0;
    char *end;
    p->value = strtod(eq + 1, &end);
    return end != eq + 1 && *end == 0 && isfinite(p->value);
}
