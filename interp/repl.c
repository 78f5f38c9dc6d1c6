/* The interactive loop.
 *
 * A line is read (with line editing, persistent history and Tab completion when libedit is
 * there, plain stdio otherwise).  A line starting with ':' is a REPL command (:help, :show,
 * :save, ...), handled by the Lua side, interp/repl.lua.  Anything else is Lua: first tried as
 * an expression whose values are printed, then as statements; a chunk the parser finds
 * unfinished continues on the next line under the ">>" prompt, as in lua5.4.  Errors are
 * printed and the session goes on; Ctrl-C interrupts a running statement.
 *
 * This file also holds the native side of the commands that need C (the braille preview,
 * writing files, loading scripts, clearing the canvas) and --watch: after every statement that
 * changed the canvas (its version counter moved) the watched file is rewritten, atomically. */
#define _DEFAULT_SOURCE
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/ioctl.h>
#include <unistd.h>
#include <lauxlib.h>
#include "braille.h"
#include "host.h"
#include "pcl.h"
#include "repl.h"
#include "sandbox.h"
#ifdef PC_HAVE_LIBEDIT
#include <editline/readline.h>
#endif

#define HISTORY_FILE ".pointcalc_history"
#define HISTORY_MAX 1000

static struct {
    char *watch;          /* the --watch / :watch file, or NULL */
    uint64_t watched;     /* the canvas version last written to it */
    char *history;        /* the history file, or NULL */
    int editing;          /* lines come from a terminal through the line editor */
    long lineno;          /* lines read, for messages about piped input */
} S;

/* ---- reading lines ------------------------------------------------------------------------ */

static char nul_line[1];   /* read_plain_line's answer for a line with a NUL byte */
static char *read_plain_line(const char *prompt);

static volatile sig_atomic_t got_sigint;
static lua_State *running;    /* the state executing a statement, for the Ctrl-C hook */

static void stop_hook(lua_State *L, lua_Debug *ar) {
    (void)ar;
    lua_sethook(L, NULL, 0, 0);
    luaL_error(L, "interrupted");
}

static void on_sigint(int sig) {
    (void)sig;
    got_sigint = 1;
    if (running) lua_sethook(running, stop_hook, LUA_MASKCALL | LUA_MASKRET | LUA_MASKCOUNT, 1);
}

static void catch_sigint(struct sigaction *old) {
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, old);
}

/* The terminal was resized: the line editor learns the new width at the next prompt (it does
 * not watch signals itself, so that Ctrl-C stays the REPL's). */
static volatile sig_atomic_t resized;
static void on_sigwinch(int sig) {
    (void)sig;
    resized = 1;
}

static void catch_sigwinch(struct sigaction *old) {
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigwinch;
    sa.sa_flags = SA_RESTART;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGWINCH, &sa, old);
}

/* After Ctrl-C at a prompt: the terminal echoes "^C" itself unless the line editor has it. */
static void show_interrupt(void) {
    fputs(S.editing ? "^C\n" : "\n", stdout);
}

/* A line without its newline (malloc'ed), or NULL at end of input.  Only a terminal goes through
 * the line editor: piped input is read as bytes (libedit's readline corrupts its heap on a NUL
 * byte), and a line with a NUL byte is reported and skipped: the REPL passes lines on as C
 * strings, which would cut it there. */
static char *read_line(const char *prompt) {
#ifdef PC_HAVE_LIBEDIT
    if (S.editing) {
        if (resized) {
            resized = 0;
            rl_resize_terminal();
        }
        return readline(prompt);
    }
#endif
    for (;;) {
        char *line = read_plain_line(prompt);
        if (!line || line != nul_line) return line;
        fflush(stdout);
        fprintf(stderr, "stdin:%ld: the line contains a NUL byte; it is skipped\n", S.lineno);
    }
}

/* One line of plain input; nul_line for a line with a NUL byte. */
static char *read_plain_line(const char *prompt) {
    fputs(prompt, stdout);
    fflush(stdout);
    char *line = NULL;
    size_t cap = 0;
    ssize_t n = getline(&line, &cap, stdin);
    if (n < 0) {
        if (got_sigint) clearerr(stdin);
        free(line);
        return NULL;
    }
    S.lineno++;
    if (n > 0 && line[n - 1] == '\n') line[--n] = 0;
    if (memchr(line, 0, (size_t)n)) {
        free(line);
        return nul_line;
    }
    return line;
}

static void history_open(void) {
#ifdef PC_HAVE_LIBEDIT
    if (!S.editing) return;
    const char *home = getenv("HOME");
    if (home && *home) {
        size_t n = strlen(home) + sizeof HISTORY_FILE + 1;
        S.history = malloc(n);
        if (S.history) snprintf(S.history, n, "%s/%s", home, HISTORY_FILE);
    }
    if (!isatty(STDIN_FILENO)) {   /* lines piped in are not the user's history */
        free(S.history);
        S.history = NULL;
    }
    using_history();
    stifle_history(HISTORY_MAX);
    if (S.history) read_history(S.history);
#endif
}

/* Remember an entry (a whole chunk, newlines included) and save the history at once, so a
 * session that is killed keeps it. */
static void history_add(const char *entry) {
#ifdef PC_HAVE_LIBEDIT
    if (!S.editing || !*entry) return;
    HIST_ENTRY *last = history_length > 0 ? history_get(history_base + history_length - 1) : NULL;
    if (last && last->line && !strcmp(last->line, entry)) return;   /* no repeats */
    add_history(entry);
    if (S.history) write_history(S.history);
#else
    (void)entry;
#endif
}

/* ---- the terminal --------------------------------------------------------------------------- */

static void terminal_size(int *cols, int *rows) {
    *cols = 80;
    *rows = 24;
    struct winsize ws;
    if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0 && ws.ws_row > 0) {
        *cols = ws.ws_col;
        *rows = ws.ws_row;
        return;
    }
    const char *c = getenv("COLUMNS"), *r = getenv("LINES");
    if (c && atoi(c) > 0) *cols = atoi(c);
    if (r && atoi(r) > 0) *rows = atoi(r);
}

/* What colours the terminal takes: none when output is not a terminal, NO_COLOR is set
 * (https://no-color.org) or TERM is dumb; 24-bit when COLORTERM says so; else by TERM. */
static pc_term_colors terminal_colors(void) {
    const char *no = getenv("NO_COLOR"), *term = getenv("TERM"), *ct = getenv("COLORTERM");
    if (!isatty(STDOUT_FILENO) || (no && *no) || !term || !*term || !strcmp(term, "dumb"))
        return PC_TERM_MONO;
    if (ct && (!strcmp(ct, "truecolor") || !strcmp(ct, "24bit"))) return PC_TERM_RGB;
    if (strstr(term, "256color")) return PC_TERM_256;
    return PC_TERM_16;
}

/* ---- --watch --------------------------------------------------------------------------------- */

/* Rewrite the watched file if the canvas changed since the last write (always when force). */
static void watch_update(lua_State *L, int force) {
    if (!S.watch) return;
    pc_canvas *c = pcl_canvas(L);
    if (!c || (!force && pc_canvas_version(c) == S.watched)) return;
    char err[512];
    /* a failure is reported once per change, not on every line */
    S.watched = pc_canvas_version(c);
    if (pc_write_file(c, S.watch, pcl_theme(L), err, sizeof err) != PC_OK) {
        fflush(stdout);
        fprintf(stderr, "watch: %s\n", err);
    }
}

/* Start watching path (NULL: stop).  Returns 0 with a message for an unknown extension. */
static int watch_set(lua_State *L, const char *path, char *err, size_t errlen) {
    if (path && pc_format_from_path(path) == PC_FMT_UNKNOWN) {
        snprintf(err, errlen, "cannot watch '%s': the extension must be .png, .svg or .ppm", path);
        return 0;
    }
    free(S.watch);
    S.watch = path ? strdup(path) : NULL;
    watch_update(L, 1);
    return 1;
}

/* ---- the native side of the commands (called from repl.lua) ----------------------------------- */

/* show([columns]): the canvas in braille cells, fitted to the terminal or to `columns`. */
static int n_show(lua_State *L) {
    pc_canvas *c = pcl_canvas(L);
    int tcols, trows;
    terminal_size(&tcols, &trows);
    int max_cols = tcols - 2, max_rows = trows - 4;   /* the frame, the caption, the prompt */
    if (!lua_isnoneornil(L, 1)) {
        lua_Integer w = lua_isinteger(L, 1) ? lua_tointeger(L, 1) : 0;
        if (w < 4 || w > 2000) {   /* the user's command, not a place in the REPL's code */
            lua_pushfstring(L, ":show: COLUMNS must be a whole number from 4 to 2000, got %s",
                            luaL_tolstring(L, 1, NULL));
            return lua_error(L);
        }
        max_cols = (int)w;
        max_rows = 100000;
    }
    if (max_cols < 4) max_cols = 4;
    if (max_rows < 2) max_rows = 2;
    int cols, rows, width, height;
    pc_canvas_size(c, &width, &height);
    double scale = pc_braille_fit(width, height, max_cols, max_rows, &cols, &rows);
    pc_braille_cell *cells = malloc((size_t)cols * rows * sizeof *cells);
    if (!cells) return luaL_error(L, "out of memory");
    pc_braille_render(c, pc_canvas_paper(c), scale, cols, rows, cells);
    pc_braille_print(stdout, cells, cols, rows, pc_canvas_palette(c), terminal_colors(), 1);
    int ink = 0;
    for (int i = 0; i < cols * rows; i++) ink |= cells[i].bits;
    free(cells);
    printf(" %dx%d, %.3g pixel%s per dot%s\n", width, height, scale, scale == 1 ? "" : "s",
           ink ? "" : " (nothing drawn)");
    fflush(stdout);
    return 0;
}

/* save(path [, "paper"|"screen"]) -> true | nil, message */
static int n_save(lua_State *L) {
    const char *path = luaL_checkstring(L, 1);
    const char *t = luaL_optstring(L, 2, NULL);
    pc_theme theme = pcl_theme(L);
    char err[512];
    if (!sandbox_path_ok(L, 1, 1, err, sizeof err)) {
        lua_pushnil(L);
        lua_pushstring(L, err);
        return 2;
    }
    if (t && !strcmp(t, "paper")) theme = PC_THEME_PAPER;
    else if (t && !strcmp(t, "screen")) theme = PC_THEME_SCREEN;
    if (t && strcmp(t, "paper") && strcmp(t, "screen"))
        snprintf(err, sizeof err, "cannot write '%s': the theme must be paper or screen, got '%s'",
                 path, t);
    else if (pc_format_from_path(path) == PC_FMT_UNKNOWN)
        snprintf(err, sizeof err, "cannot write '%s': the extension must be .png, .svg or .ppm", path);
    else if (pc_write_file(pcl_canvas(L), path, theme, err, sizeof err) == PC_OK) {
        pc_canvas_mark_saved(pcl_canvas(L));
        lua_pushboolean(L, 1);
        return 1;
    }
    lua_pushnil(L);
    lua_pushstring(L, err);
    return 2;
}

/* load(path) -> boolean: run a Lua script, or a QBasic program (.bas), in the session. */
static int n_load(lua_State *L) {
    const char *path = luaL_checkstring(L, 1);
    size_t n = strlen(path);
    int qbasic = n > 4 && !strcasecmp(path + n - 4, ".bas");
    char err[512];
    if (!sandbox_path_ok(L, 1, 0, err, sizeof err)) {
        lua_pushboolean(L, 0);
        lua_pushstring(L, err);
        return 2;
    }
    if (access(path, R_OK) != 0) {
        lua_pushboolean(L, 0);
        lua_pushfstring(L, "cannot open '%s'", path);
        return 2;
    }
    fflush(stdout);
    if (!host_load_script(L, path, qbasic)) {   /* the message is printed */
        lua_pushboolean(L, 0);
        return 1;
    }
    lua_call(L, 0, 0);   /* a runtime error goes to the REPL's handler, with the script's lines */
    lua_pushboolean(L, 1);
    return 1;
}

/* clear(): erase the drawing, keeping the screen's settings (size, colours, palette, window,
 * view); the display list starts afresh. */
static int n_clear(lua_State *L) {
    pc_canvas *c = pcl_canvas(L);
    if (pc_canvas_clear(c) != PC_OK) return luaL_error(L, "%s", pc_canvas_error(c));
    return 0;
}

/* watch([path | false]) -> the watched path or nil.  No argument: just the query. */
static int n_watch(lua_State *L) {
    if (!lua_isnone(L, 1)) {
        const char *path = lua_toboolean(L, 1) ? luaL_checkstring(L, 1) : NULL;
        char err[512];
        if (path && !sandbox_path_ok(L, 1, 1, err, sizeof err)) {
            lua_pushstring(L, err);
            return lua_error(L);
        }
        if (!watch_set(L, path, err, sizeof err)) return luaL_error(L, "%s", err);
    }
    if (S.watch) lua_pushstring(L, S.watch);
    else lua_pushnil(L);
    return 1;
}

/* columns() -> the terminal's width, for wrapping help text */
static int n_columns(lua_State *L) {
    int cols, rows;
    terminal_size(&cols, &rows);
    lua_pushinteger(L, cols);
    return 1;
}

static const luaL_Reg natives[] = {
    {"show", n_show},   {"save", n_save},   {"load", n_load},       {"clear", n_clear},
    {"watch", n_watch}, {"columns", n_columns}, {NULL, NULL}};

/* ---- running chunks --------------------------------------------------------------------------- */

int repl_push_module(lua_State *L) {
    lua_getglobal(L, "require");
    lua_pushliteral(L, "repl");
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
        fprintf(stderr, "%s: the REPL failed to load: %s\n", host_progname, lua_tostring(L, -1));
        lua_pop(L, 1);
        return 0;
    }
    return 1;
}

/* Print the message on top of the stack (an error) to stderr and pop it. */
static void report(lua_State *L) {
    fflush(stdout);
    const char *msg = lua_tostring(L, -1);
    fprintf(stderr, "%s\n", msg ? msg : "(error object is not a string)");
    lua_pop(L, 1);
}

/* Call the function below its nargs arguments on top of the stack, with the REPL's error
 * handler and Ctrl-C armed; leaves nresults (or all) results.  0 on error (printed). */
static int call(lua_State *L, int mod, int nargs, int nresults) {
    int base = lua_gettop(L) - nargs;
    lua_getfield(L, mod, "on_error");
    lua_insert(L, base);
    got_sigint = 0;
    running = L;
    sandbox_start(L);   /* --timeout and --max-memory: per statement */
    int status = lua_pcall(L, nargs, nresults, base);
    running = NULL;
    sandbox_stop(L);    /* also removes the Ctrl-C hook */
    lua_remove(L, base);
    if (status != LUA_OK) {
        sandbox_explain(L, status, "stdin");
        if (got_sigint) fputc('\n', stderr);   /* after the terminal's "^C" */
        report(L);
        return 0;
    }
    return 1;
}

/* Compile src: first as an expression whose values are printed (`return src;`), then as
 * statements.  Leaves the function or the error message on the stack. */
static int compile(lua_State *L, const char *src) {
    size_t n = strlen(src);
    char *expr = malloc(n + 10);
    if (!expr) {
        lua_pushliteral(L, "not enough memory");
        return LUA_ERRMEM;
    }
    memcpy(expr, "return ", 7);
    memcpy(expr + 7, src, n);
    memcpy(expr + 7 + n, ";", 2);
    int status = luaL_loadbufferx(L, expr, n + 8, "=stdin", "t");
    free(expr);
    if (status == LUA_OK) return status;
    lua_pop(L, 1);
    return luaL_loadbufferx(L, src, n, "=stdin", "t");   /* source only, as scripts (host.c) */
}

/* Is the message on top of the stack a syntax error at the end of the input? */
static int incomplete(lua_State *L, int status) {
    if (status != LUA_ERRSYNTAX) return 0;
    size_t len;
    const char *msg = lua_tolstring(L, -1, &len);
    return len >= 5 && !strcmp(msg + len - 5, "<eof>");
}

/* Run the compiled chunk on top of the stack and print what it returns. */
static void run_chunk(lua_State *L, int mod, const char *src) {
    int base = lua_gettop(L);   /* the function */
    if (!call(L, mod, 0, LUA_MULTRET)) return;
    int n = lua_gettop(L) - base + 1;
    lua_getfield(L, mod, "after_chunk");   /* results -> text, hints */
    lua_pushstring(L, src);
    lua_rotate(L, base, 2);
    if (lua_pcall(L, n + 1, 1, 0) != LUA_OK) {
        report(L);
    } else if (lua_isstring(L, -1)) {
        fputs(lua_tostring(L, -1), stdout);
        fputc('\n', stdout);
    }
    lua_settop(L, base - 1);
}

static int is_command(const char *line) {
    while (*line == ' ' || *line == '\t') line++;
    return line[0] == ':' && line[1] != ':';   /* "::label::" is Lua */
}

/* A lone "help" or "?" when no such global exists: what a newcomer types first. */
static int is_help_word(lua_State *L, const char *line) {
    while (*line == ' ') line++;
    size_t n = strcspn(line, " \t");
    if (line[n + strspn(line + n, " \t")] != 0) return 0;
    if (!(n == 1 && line[0] == '?') && !(n == 4 && !strncmp(line, "help", 4))) return 0;
    int nil = lua_getglobal(L, "help") == LUA_TNIL;
    lua_pop(L, 1);
    return nil;
}

/* Handle one entry: a command, or a Lua chunk read to its end.  Returns 0 to quit. */
static int step(lua_State *L, int mod, char *line) {
    if (is_command(line) || is_help_word(L, line)) {
        history_add(line);
        lua_getfield(L, mod, "command");
        lua_pushstring(L, is_command(line) ? line : ":help");
        int quit = 0;
        if (call(L, mod, 1, 1)) quit = lua_toboolean(L, -1);
        lua_settop(L, mod);
        watch_update(L, 0);
        free(line);
        return !quit;
    }
    char *src = line;
    int status, more = 1;
    while ((status = compile(L, src)) != LUA_OK && incomplete(L, status)) {
        lua_pop(L, 1);
        got_sigint = 0;
        char *next = read_line(">> ");
        if (!next && got_sigint) {   /* Ctrl-C drops the unfinished chunk */
            show_interrupt();
            lua_settop(L, mod);
            free(src);
            return 1;
        }
        if (!next) {   /* end of input inside a chunk: report what is missing, then leave */
            more = 0;
            status = compile(L, src);
            break;
        }
        size_t a = strlen(src), b = strlen(next);
        char *joined = realloc(src, a + b + 2);
        if (!joined) {
            free(next);
            break;
        }
        src = joined;
        src[a] = '\n';
        memcpy(src + a + 1, next, b + 1);
        free(next);
    }
    if (src[strspn(src, " \t")]) history_add(src);
    if (status == LUA_OK) {
        run_chunk(L, mod, src);
        watch_update(L, 0);
    } else {
        report(L);
    }
    lua_settop(L, mod);
    free(src);
    return more;
}

void host_repl(lua_State *L, const char *watch) {
    if (!repl_push_module(L)) return;
    int mod = lua_gettop(L);
    lua_getfield(L, mod, "init");
    luaL_newlib(L, natives);
    if (lua_pcall(L, 1, 0, 0) != LUA_OK) {
        report(L);
        lua_settop(L, mod - 1);
        return;
    }
    S.editing = isatty(STDIN_FILENO);
    S.lineno = 0;
    history_open();
    if (S.editing) repl_completion_init(L);
    printf("pointcalc %s (%s). :help for help; Ctrl-D or :quit to leave.\n", PCL_VERSION,
           LUA_RELEASE);
    if (watch) {
        char err[512];
        if (watch_set(L, watch, err, sizeof err)) printf("watching %s\n", watch);
        else fprintf(stderr, "%s\n", err);
    }
    struct sigaction old_int, old_winch;
    catch_sigint(&old_int);   /* Ctrl-C at the prompt drops the line */
    catch_sigwinch(&old_winch);
    for (;;) {
        fflush(stdout);
        got_sigint = 0;
        char *line = read_line("> ");
        if (!line && got_sigint) {
            show_interrupt();
            continue;
        }
        if (!line) {
            putchar('\n');   /* Ctrl-D leaves the cursor after the prompt */
            break;
        }
        if (!step(L, mod, line)) break;
    }
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGWINCH, &old_winch, NULL);
    fflush(stdout);
    free(S.watch);
    free(S.history);
    S.watch = S.history = NULL;
    lua_settop(L, mod - 1);
}
