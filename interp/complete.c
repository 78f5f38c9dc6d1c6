/* Tab completion through libedit: the candidates come from the Lua side of the REPL
 * (repl.lua's complete: global names and keywords, fields and methods after '.' and ':', REPL
 * commands and help topics), or from the file system after :load, :save and :watch. */
#include <stdlib.h>
#include <string.h>
#include <lauxlib.h>
#include "repl.h"

#ifdef PC_HAVE_LIBEDIT
#include <stdio.h>
#include <sys/stat.h>
#include <editline/readline.h>

static lua_State *state;

/* Lua names run across '.' and ':' (a.b:c is one word to complete); anything that can end an
 * expression breaks a word.  File names are rebuilt from the whole argument (see files). */
static char word_breaks[] = " \t\n\"\\'`@$><=;|&{(,+-*/%^~#[]";

typedef struct { char **v; int n, cap; } list;

static void push(list *l, char *s) {
    if (!s) return;
    if (l->n + 2 >= l->cap) {
        int cap = l->cap ? 2 * l->cap : 16;
        char **v = realloc(l->v, (size_t)cap * sizeof *v);
        if (!v) {
            free(s);
            return;
        }
        l->v = v;
        l->cap = cap;
    }
    l->v[++l->n] = s;   /* v[0] is reserved for the common prefix */
}

/* The readline form: matches[0] the longest common prefix (the whole match when unique),
 * then the candidates, then NULL. */
static char **finish(list *l) {
    if (l->n == 0) {
        free(l->v);
        return NULL;
    }
    size_t common = strlen(l->v[1]);
    for (int i = 2; i <= l->n; i++) {
        size_t k = 0;
        while (k < common && l->v[1][k] == l->v[i][k]) k++;
        common = k;
    }
    if (l->n == 1) {
        l->v[0] = l->v[1];
        l->v[1] = NULL;
    } else {
        l->v[0] = strndup(l->v[1], common);
        l->v[l->n + 1] = NULL;
    }
    return l->v;
}

/* File names.  libedit's word stops at '/', '-', blanks and quotes, so the argument is taken
 * whole from the line and the candidates are cut back to the part that replaces `text`.  The
 * REPL's commands read a quoted argument as one (split_args in repl.lua), so an argument that
 * starts with an open quote may hold blanks, and a name with a blank gets an opening quote
 * when completion starts it (and a closing one when it is finished). */
static char **files(const char *text, const char *before) {
    const char *arg = before;   /* the first argument: after the :command word */
    while (*arg == ' ' || *arg == '\t') arg++;
    while (*arg && *arg != ' ' && *arg != '\t') arg++;
    while (*arg == ' ' || *arg == '\t') arg++;
    char quote = (*arg == '"' || *arg == '\'') && !strchr(arg + 1, *arg) ? *arg : 0;
    const char *p = quote ? arg + 1 : before + strlen(before);
    if (!quote)
        while (p > before && p[-1] != ' ' && p[-1] != '\t') p--;
    size_t plen = strlen(p);
    char *full = malloc(plen + strlen(text) + 1);
    if (!full) return NULL;
    memcpy(full, p, plen);
    strcpy(full + plen, text);
    list l = {0};
    int dirs = 0, blanks = 0;
    char *m;
    for (int i = 0; (m = rl_filename_completion_function(full, i)) != NULL; i++) {
        struct stat st;
        int dir = stat(m, &st) == 0 && S_ISDIR(st.st_mode);
        size_t n = strlen(m);
        if (n >= plen) {
            char *s = malloc(n - plen + 4);
            if (s) {
                strcpy(s, m + plen);
                if (dir && (n == 0 || m[n - 1] != '/')) strcat(s, "/");
                push(&l, s);
                blanks += strpbrk(m, " \t") != NULL;
            }
        }
        dirs += dir;
        free(m);
    }
    free(full);
    /* a name with a blank, begun unquoted at the start of the argument: open a quote */
    if (!quote && blanks && plen == 0 && p == arg) {
        quote = '"';
        for (int i = 1; i <= l.n; i++) {
            memmove(l.v[i] + 1, l.v[i], strlen(l.v[i]) + 1);
            l.v[i][0] = quote;
        }
    }
    /* a unique file is finished (closing quote, then a space); a unique folder is not: its
     * files come next */
    int done = l.n == 1 && !dirs;
    if (done && quote) strncat(l.v[1], &quote, 1);
    rl_completion_append_character = done ? ' ' : 0;
    return finish(&l);
}

static char **candidates(const char *text, int start, int end) {
    (void)end;
    rl_attempted_completion_over = 1;   /* never fall back to libedit's own file names */
    rl_completion_append_character = 0;
    lua_State *L = state;
    int top = lua_gettop(L);
    char **matches = NULL;
    if (!repl_push_module(L)) goto done;
    lua_getfield(L, -1, "complete");
    lua_pushstring(L, text);
    const char *before = lua_pushlstring(L, rl_line_buffer, (size_t)start);
    lua_pushvalue(L, -1);
    lua_insert(L, -4);   /* keep `before` alive below the call */
    if (lua_pcall(L, 2, 1, 0) != LUA_OK) goto done;
    if (lua_type(L, -1) == LUA_TSTRING && !strcmp(lua_tostring(L, -1), "files")) {
        matches = files(text, before);
        goto done;
    }
    if (!lua_istable(L, -1)) goto done;
    list l = {0};
    int n = (int)luaL_len(L, -1);
    for (int i = 1; i <= n; i++) {
        lua_geti(L, -1, i);
        const char *s = lua_tostring(L, -1);
        if (s) push(&l, strdup(s));
        lua_pop(L, 1);
    }
    matches = finish(&l);
done:
    lua_settop(L, top);
    return matches;
}

void repl_completion_init(lua_State *L) {
    state = L;
    rl_readline_name = "pointcalc";
    rl_catch_signals = 0;   /* the REPL's own SIGINT handler stays in charge */
    rl_attempted_completion_function = candidates;
    rl_basic_word_break_characters = word_breaks;
    rl_completer_word_break_characters = word_breaks;
    rl_completion_append_character = 0;
}

#else

void repl_completion_init(lua_State *L) { (void)L; }

#endif
