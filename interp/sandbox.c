/* The safe mode and the limits of the host's Lua state (sandbox.h, docs/safety.md).
 *
 * One host state per process, so the limits live in one static record that the allocator,
 * the hook and the timer's signal handler share. */
#define _GNU_SOURCE   /* realpath, mallinfo2 */
#include "sandbox.h"
#include <errno.h>
#include <limits.h>
#include <malloc.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <time.h>
#include <unistd.h>
#include <lauxlib.h>
#include "pcl.h"
#include "memlimit.h"
#include "writers.h"

const sandbox_config sandbox_untrusted = {1, 0, {NULL}, 10, 256, 0};

/* --safe without --timeout or --max-memory (docs/safety.md): a script from elsewhere cannot
 * take the machine */
#define SAFE_DEFAULT_SECONDS 60
#define SAFE_DEFAULT_MB 1024

#define HOOK_COUNT 10000       /* instructions between two looks at the clock */
#define GRACE_SECONDS 2        /* a native call past the time limit is stopped this much later */

static struct {
    int safe;
    int nallow;
    char *allow[SANDBOX_MAX_ALLOW];   /* resolved (realpath) */
    int hardlinks;                    /* --allow-hardlinks */
    double timeout, max_mb;
    size_t max_bytes;                 /* 0: no memory limit */
    size_t hard_bytes;                /* no allocation beyond this */
    lua_Alloc alloc;                  /* the state's own allocator, wrapped */
    void *alloc_ud;
    size_t lua_bytes;                 /* the Lua heap now */
    size_t c_bytes;                   /* the C heap at the last look */
    size_t after_gc;                  /* the C heap after the hook's last collection */
    volatile sig_atomic_t refused;    /* an allocation was refused for the limit */
    struct timespec deadline;
    volatile sig_atomic_t armed, time_up;
    volatile sig_atomic_t running;    /* between sandbox_start and sandbox_stop */
    size_t refused_size;              /* the first refused request of the run */
    char refused_where[LUA_IDSIZE + 24];   /* "file:LINE" of it, or "" */
    char time_msg[LUA_IDSIZE + 200];  /* the first time-limit or Ctrl-C error of the run, or "" */
    volatile sig_atomic_t interrupted;     /* Ctrl-C came (sandbox_catch_interrupt) */
    int catching;                          /* SIGINT is ours; old_int is the one before */
    struct sigaction old_int;
    lua_State *L;
} S;

static double now_seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

/* ---- memory --------------------------------------------------------------------------------- */

static void on_refused(size_t request);
static void limit_hook(lua_State *L, lua_Debug *ar);
static const lua_Hook limit_hook_ptr = limit_hook;

/* The allocator: Lua's own, counting bytes.  The hook stops a script soon after it passes the
 * limit, at its line; an allocation that would take it past one and a half times the limit is
 * refused at once (Lua then raises "not enough memory", which sandbox_explain names). */
static void *counting_alloc(void *ud, void *ptr, size_t osize, size_t nsize) {
    (void)ud;
    size_t old = ptr ? osize : 0;   /* without ptr, osize is a type tag */
    if (nsize > old && S.max_bytes && S.lua_bytes + (nsize - old) > S.hard_bytes) {
        on_refused(nsize - old);
        return NULL;
    }
    void *p = S.alloc(S.alloc_ud, ptr, osize, nsize);
    if (p || nsize == 0) S.lua_bytes = S.lua_bytes - old + nsize;
    return p;
}

/* The C heap in use: exact from the accounting allocator (memlimit.c), else where the C
 * library tells (0 under AddressSanitizer's allocator). */
static size_t c_heap(void) {
    if (pc_mem_counting()) return pc_mem_in_use();
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
    struct mallinfo2 mi = mallinfo2();
    return mi.uordblks + mi.hblkhd;
#else
    return 0;
#endif
}


void sandbox_attach(lua_State *L, const sandbox_config *cfg) {
    S.L = L;
    S.timeout = cfg->timeout > 0 ? cfg->timeout : cfg->safe ? SAFE_DEFAULT_SECONDS : 0;
    S.max_mb = cfg->max_memory_mb > 0 ? cfg->max_memory_mb : cfg->safe ? SAFE_DEFAULT_MB : 0;
    S.max_bytes = S.max_mb > 0 ? (size_t)(S.max_mb * 1048576.0) : 0;
    /* with every allocation counted (memlimit.c) the limit itself is the hard one; else the
     * Lua heap may pass it by half before the hook sees the C heap */
    S.hard_bytes = pc_mem_counting() ? S.max_bytes : S.max_bytes + S.max_bytes / 2;
    pc_mem_set_limit(S.max_bytes, on_refused);
    S.safe = cfg->safe;
    S.hardlinks = cfg->allow_hardlinks;
    for (int i = 0; i < S.nallow; i++) free(S.allow[i]);   /* a server makes one state per render */
    S.nallow = 0;
    for (int i = 0; i < cfg->nallow && i < SANDBOX_MAX_ALLOW; i++) {
        char *r = realpath(cfg->allow[i], NULL);
        if (r) S.allow[S.nallow++] = r;
    }
    S.alloc = lua_getallocf(L, &S.alloc_ud);
    S.lua_bytes = (size_t)lua_gc(L, LUA_GCCOUNT, 0) * 1024 + (size_t)lua_gc(L, LUA_GCCOUNTB, 0);
    lua_setallocf(L, counting_alloc, NULL);
}

int sandbox_check_config(const sandbox_config *cfg, char *err, size_t errlen) {
    for (int i = 0; i < cfg->nallow; i++) {
        struct stat st;
        if (stat(cfg->allow[i], &st) != 0 || !S_ISDIR(st.st_mode)) {
            snprintf(err, errlen, "--allow '%s': %s", cfg->allow[i],
                     errno && stat(cfg->allow[i], &st) != 0 ? strerror(errno) : "not a folder");
            return 0;
        }
    }
    if (cfg->nallow > SANDBOX_MAX_ALLOW) {
        snprintf(err, errlen, "too many --allow options");
        return 0;
    }
    return 1;
}

/* "16.0 MB", "24 kB": a refused request's size, into buf. */
static const char *shown_size(size_t n, char *buf, size_t len) {
    if (n >= 1048576) snprintf(buf, len, "%.1f MB", n / 1048576.0);
    else snprintf(buf, len, "%zu kB", (n + 1023) / 1024);
    return buf;
}

/* pointcalc's own Lua helpers ("[pointcalc/curves.lua]"): the user's line is further down */
static int embedded(const lua_Debug *ar) { return !strncmp(ar->short_src, "[pointcalc/", 11); }

/* The script's place now, "file:LINE" of the nearest Lua function, into buf ("" if none). */
static void current_place(lua_State *L, char *buf, size_t len) {
    lua_Debug ar;
    buf[0] = 0;
    for (int level = 0; lua_getstack(L, level, &ar); level++)
        if (lua_getinfo(L, "Sl", &ar) && ar.currentline > 0) {
            if (!buf[0] || !embedded(&ar)) snprintf(buf, len, "%s:%d", ar.short_src, ar.currentline);
            if (!embedded(&ar)) return;
        }
}

/* An allocation was refused for the limit (called inside the allocator: no allocation here).
 * The first one of a run notes its size and the script's line; the hook then stops the script
 * at its next instruction, whatever the native call that met the refusal made of it.  (Up to
 * Lua 5.4.5 the call stack is consistent whenever Lua allocates; 5.4.6 moves it while it
 * grows the stack, so the line is then left to the binding's own message.) */
static void on_refused(size_t request) {
    if (!S.running || !S.L) return;
    if (!S.refused) {
        S.refused = 1;
        S.refused_size = request;
#if LUA_VERSION_RELEASE_NUM <= 50405
        current_place(S.L, S.refused_where, sizeof S.refused_where);
#else
        S.refused_where[0] = 0;
#endif
    }
    lua_sethook(S.L, limit_hook_ptr, LUA_MASKCOUNT, 1);
}

/* ---- time ----------------------------------------------------------------------------------- */

static int over_memory(void) {
    if (!S.max_bytes) return 0;
    S.c_bytes = c_heap();
    if (S.lua_bytes > S.max_bytes) return 1;
    return S.c_bytes > S.max_bytes;
}

static int over_time(void) {
    if (S.time_up) return 1;
    if (!S.timeout) return 0;
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec > S.deadline.tv_sec ||
           (t.tv_sec == S.deadline.tv_sec && t.tv_nsec >= S.deadline.tv_nsec);
}

/* Push "FILE:LINE: MESSAGE" for the instruction running now (or the nearest script line). */
static int push_place(lua_State *L, lua_Debug *ar, const char *msg) {
    if (ar && lua_getinfo(L, "Sl", ar) && ar->currentline > 0 && !embedded(ar)) {
        lua_pushfstring(L, "%s:%d: %s", ar->short_src, ar->currentline, msg);
        return 1;
    }
    /* a call or return event in a C function (pcall, a binding): the script's line is that of
     * the nearest Lua function below it */
    lua_Debug up;
    for (int level = 1; lua_getstack(L, level, &up); level++) {
        if (lua_getinfo(L, "Sl", &up) && up.currentline > 0 && !embedded(&up)) {
            lua_pushfstring(L, "%s:%d: %s", up.short_src, up.currentline, msg);
            return 1;
        }
    }
    if (ar && ar->currentline > 0) {   /* only pointcalc's own Lua code on the stack */
        lua_pushfstring(L, "%s:%d: %s", ar->short_src, ar->currentline, msg);
        return 1;
    }
    lua_pushstring(L, msg);
    return 1;
}

/* Raise "FILE:LINE: MESSAGE" at the instruction running now (luaL_error would name the
 * caller's line: a hook is no stack level of its own).  The hook then fires at every
 * instruction, so a script that catches the error with pcall cannot go on.  With memo, the
 * first message of the run is kept and raised again by every later firing: those come from
 * wherever the error is passing through (a pcall's handler, the QBasic runtime closing its
 * files), and the line the script was running when the limit came is the one to report. */
static int raise_here(lua_State *L, lua_Debug *ar, const char *msg, char *memo, size_t memolen) {
    lua_sethook(L, limit_hook, LUA_MASKCOUNT, 1);
    if (memo && memo[0]) {
        lua_pushstring(L, memo);
        return lua_error(L);
    }
    push_place(L, ar, msg);   /* pushes the located message */
    if (memo) snprintf(memo, memolen, "%s", lua_tostring(L, -1));
    return lua_error(L);
}

static void limit_hook(lua_State *L, lua_Debug *ar) {
    char msg[160];
    if (S.interrupted) raise_here(L, ar, SANDBOX_INTERRUPTED, S.time_msg, sizeof S.time_msg);
    if (over_time()) {
        snprintf(msg, sizeof msg, "time limit of %g s exceeded", S.timeout);
        raise_here(L, ar, msg, S.time_msg, sizeof S.time_msg);
    }
    if (S.refused) {
        char size[32];
        snprintf(msg, sizeof msg, "memory limit of %g MB exceeded (a request of %s was refused)",
                 S.max_mb, shown_size(S.refused_size, size, sizeof size));
        raise_here(L, ar, msg, NULL, 0);
    }
    if (over_memory()) {
        lua_gc(L, LUA_GCCOLLECT, 0);   /* garbage does not count against a script */
        if (over_memory()) {
            snprintf(msg, sizeof msg, "memory limit of %g MB exceeded", S.max_mb);
            raise_here(L, ar, msg, NULL, 0);
        }
    }
    /* near the limit, collect: the core's next big block should not be refused for garbage */
    if (S.max_bytes && S.c_bytes > S.max_bytes / 4 * 3 && S.c_bytes > S.after_gc + S.max_bytes / 8) {
        lua_gc(L, LUA_GCCOLLECT, 0);
        S.after_gc = c_heap();
    }
    lua_sethook(L, limit_hook, LUA_MASKCOUNT, HOOK_COUNT);
}

/* The timer: at the deadline, the hook runs at the next instruction (a native call may be
 * running); GRACE_SECONDS later a native call that still has not returned ends the process,
 * removing a half-written file first. */
static void on_alarm(int sig) {
    (void)sig;
    if (!S.armed) return;
    if (!S.time_up) {
        S.time_up = 1;
        if (S.L) lua_sethook(S.L, limit_hook, LUA_MASKCOUNT | LUA_MASKCALL | LUA_MASKRET, 1);
        struct itimerval it = {{0, 0}, {GRACE_SECONDS, 0}};
        setitimer(ITIMER_REAL, &it, NULL);
        return;
    }
    pc_write_file_abort();
    /* the script's line: the call stack is consistent while a native call runs (reading it
     * here is a last resort, the process ends next) */
    char where[LUA_IDSIZE + 24], msg[LUA_IDSIZE + 128];
    if (S.L) current_place(S.L, where, sizeof where);
    else where[0] = 0;
    int n = snprintf(msg, sizeof msg, "%s%stime limit of %g s exceeded in a native call; stopped\n",
                     where[0] ? where : "pointcalc", where[0] ? ": " : ": ", S.timeout);
    if (n > 0) (void)!write(STDERR_FILENO, msg, (size_t)n < sizeof msg ? (size_t)n : sizeof msg - 1);
    _exit(SANDBOX_EXIT_NATIVE_TIMEOUT);
}

/* Ctrl-C: the first one stops the script at its next instruction (or when the native call
 * running returns), as the time limit does; a second one ends the process at once. */
static void on_interrupt(int sig) {
    if (S.interrupted || !S.running || !S.L) {
        sigaction(SIGINT, &S.old_int, NULL);
        raise(sig);
        return;
    }
    S.interrupted = 1;
    lua_sethook(S.L, limit_hook, LUA_MASKCOUNT | LUA_MASKCALL | LUA_MASKRET, 1);
}

void sandbox_catch_interrupt(int on) {
    if (on && !S.catching) {
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_interrupt;
        sa.sa_flags = SA_RESTART;
        sigemptyset(&sa.sa_mask);
        sigaction(SIGINT, &sa, &S.old_int);
        S.catching = 1;
    } else if (!on && S.catching) {
        sigaction(SIGINT, &S.old_int, NULL);
        S.catching = 0;
    }
}

void sandbox_start(lua_State *L) {
    S.refused = 0;
    S.refused_where[0] = 0;
    S.time_msg[0] = 0;
    S.interrupted = 0;
    S.after_gc = 0;
    S.time_up = 0;
    S.running = 1;
    if (!S.timeout && !S.max_bytes) return;
    if (S.timeout) {
        double end = now_seconds() + S.timeout;
        S.deadline.tv_sec = (time_t)end;
        S.deadline.tv_nsec = (long)((end - (double)S.deadline.tv_sec) * 1e9);
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_alarm;
        sa.sa_flags = SA_RESTART;
        sigemptyset(&sa.sa_mask);
        sigaction(SIGALRM, &sa, NULL);
        double whole = (double)(long)S.timeout;
        struct itimerval it = {{0, 0}, {(long)whole, (long)((S.timeout - whole) * 1e6)}};
        if (it.it_value.tv_sec == 0 && it.it_value.tv_usec == 0) it.it_value.tv_usec = 1;
        S.armed = 1;
        setitimer(ITIMER_REAL, &it, NULL);
    }
    lua_sethook(L, limit_hook, LUA_MASKCOUNT, HOOK_COUNT);
}

void sandbox_stop(lua_State *L) {
    if (S.armed) {
        struct itimerval off = {{0, 0}, {0, 0}};
        setitimer(ITIMER_REAL, &off, NULL);
        S.armed = 0;
    }
    S.time_up = 0;
    S.running = 0;
    lua_sethook(L, NULL, 0, 0);
}

int sandbox_explain(lua_State *L, int status, const char *where) {
    if (!S.refused || status == LUA_OK) return 0;
    char msg[1200], size[32];
    const char *old = lua_tostring(L, -1);
    shown_size(S.refused_size, size, sizeof size);
    if (status == LUA_ERRMEM || !old) {
        /* Lua's own "not enough memory" has no place: the one noted at the refusal */
        const char *at = S.refused_where[0] ? S.refused_where : where;
        snprintf(msg, sizeof msg, "%s%smemory limit of %g MB exceeded (a request of %s was refused)",
                 at ? at : "", at ? ": " : "", S.max_mb, size);
    } else if (!strstr(old, "memory limit of")) {
        /* a binding's "CALL: out of memory ..." at the script's line: say why, before the
         * traceback */
        int head = (int)strcspn(old, "\n");
        snprintf(msg, sizeof msg, "%.*s (the memory limit of %g MB was reached: a request of %s "
                 "was refused)%s", head, old, S.max_mb, size, old + head);
    } else {
        S.refused = 0;
        return 1;
    }
    lua_pop(L, 1);
    lua_pushstring(L, msg);
    S.refused = 0;
    return 1;
}

/* ---- file names --------------------------------------------------------------------------- */

int sandbox_is_safe(lua_State *L) {
    (void)L;
    return S.safe;
}

/* The file name shown in a message: quoted, a NUL as \0. */
static const char *shown_path(lua_State *L, const char *p, size_t len) {
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    luaL_addchar(&b, '\'');
    for (size_t i = 0; i < len && i < 200; i++) {
        if (p[i]) luaL_addchar(&b, p[i]);
        else luaL_addstring(&b, "\\0");
    }
    luaL_addchar(&b, '\'');
    luaL_pushresult(&b);
    return lua_tostring(L, -1);
}

/* Where a name leads: the real path of an existing file (through links), or of the folder of a
 * new one with the name appended; NULL if that cannot be known (a dangling link, a missing
 * folder). */
static char *resolve(const char *path) {
    struct stat st;
    if (lstat(path, &st) == 0) return realpath(path, NULL);
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    if (!*base || !strcmp(base, ".") || !strcmp(base, "..")) return NULL;
    char *dir;
    if (!slash) dir = realpath(".", NULL);
    else if (slash == path) dir = realpath("/", NULL);
    else {
        char *d = strndup(path, (size_t)(slash - path));
        dir = d ? realpath(d, NULL) : NULL;
        free(d);
    }
    if (!dir) return NULL;
    size_t n = strlen(dir) + strlen(base) + 2;
    char *full = malloc(n);
    if (full) snprintf(full, n, "%s%s%s", dir, strcmp(dir, "/") ? "/" : "", base);
    free(dir);
    return full;
}

static int under(const char *path, const char *dir) {
    size_t n = strlen(dir);
    if (n == 1 && dir[0] == '/') return 1;
    return !strncmp(path, dir, n) && (path[n] == '/' || path[n] == 0);
}

int sandbox_hardlinks_allowed(void) { return S.hardlinks; }

int sandbox_under_allowed(const char *real) {
    for (int i = 0; i < S.nallow; i++)
        if (under(real, S.allow[i])) return 1;
    return 0;
}

/* "a file under an allowed folder (...)", into err */
static void allowed_text(int write, char *err, size_t errlen) {
    if (S.nallow == 0) {
        snprintf(err, errlen, "a file under a folder given with --allow (in safe mode no folder "
                 "is %s without one)", write ? "written" : "read");
        return;
    }
    size_t n = (size_t)snprintf(err, errlen, "a file under an allowed folder (");
    for (int i = 0; i < S.nallow && n < errlen; i++)
        n += (size_t)snprintf(err + n, errlen - n, "%s%s", i ? ", " : "", S.allow[i]);
    if (n < errlen) snprintf(err + n, errlen - n, ")");
}

/* Why path (len bytes) may not be used, into err ("" when it may). */
static void path_problem(const char *path, size_t len, int write, char *err, size_t errlen) {
    err[0] = 0;
    if (strlen(path) != len) {
        snprintf(err, errlen, "a name without NUL bytes");
        return;
    }
    if (!S.safe) return;
    char *real = resolve(path);
    int ok = real && sandbox_under_allowed(real);
    free(real);
    if (!ok) allowed_text(write, err, errlen);
}

int sandbox_refuse_path(lua_State *L, const char *fname, int arg, int write, const char *why) {
    char text[400];
    if (!why) allowed_text(write, text, sizeof text);
    size_t len;
    const char *path = lua_tolstring(L, arg, &len);
    return pcl_error(L, "%s: argument #%d (file name) must be %s, got %s", fname, arg,
                     why ? why : text, shown_path(L, path ? path : "?", path ? len : 1));
}

int sandbox_path_ok(lua_State *L, int idx, int write, char *err, size_t errlen) {
    size_t len;
    const char *path = lua_tolstring(L, idx, &len);
    char why[400];
    path_problem(path, len, write, why, sizeof why);
    if (!why[0]) return 1;
    const char *got = shown_path(L, path, len);
    snprintf(err, errlen, "cannot %s %s: it must be %s", write ? "write" : "read", got, why);
    lua_pop(L, 1);
    return 0;
}

void sandbox_check_path(lua_State *L, const char *fname, int arg, int write) {
    size_t len;
    const char *path = luaL_checklstring(L, arg, &len);
    char why[400];
    path_problem(path, len, write, why, sizeof why);
    if (why[0])
        pcl_error(L, "%s: argument #%d (file name) must be %s, got %s", fname, arg, why,
                  shown_path(L, path, len));
}

/* ---- the wrapped functions ------------------------------------------------------------------ */

/* sandbox_check_path of argument arg as its string, leaving the argument as it is. */
static void check_name_copy(lua_State *L, const char *fname, int arg, int write) {
    size_t len;
    lua_pushvalue(L, arg);
    const char *path = lua_tolstring(L, -1, &len);
    char why[400];
    path_problem(path, len, write, why, sizeof why);
    if (why[0])
        pcl_error(L, "%s: argument #%d (file name) must be %s, got %s", fname, arg, why,
                  shown_path(L, path, len));
    lua_pop(L, 1);
}

/* A wrapper: check the file-name arguments named by the upvalues, then call the original
 * (upvalue 1) with all the arguments.  Upvalue 2: the function's name; 3: the index of the
 * name to check (0: none); 4: 1 for writing, 2 for "look at the mode argument" (io.open);
 * 5: the index of a second name (os.rename) or 0. */
static int checked_call(lua_State *L) {
    const char *fname = lua_tostring(L, lua_upvalueindex(2));
    int arg = (int)lua_tointeger(L, lua_upvalueindex(3));
    int how = (int)lua_tointeger(L, lua_upvalueindex(4));
    int arg2 = (int)lua_tointeger(L, lua_upvalueindex(5));
    int write = how == 1;
    if (how == 2) {   /* io.open(name, mode): "r" and "rb" read, anything else may write */
        const char *mode = luaL_optstring(L, 2, "r");
        write = strcmp(mode, "r") && strcmp(mode, "rb");
    }
    /* a number is a name too (Lua converts it): in safe mode checked as the string it becomes
     * (the original still gets the number, and says what it says of one) */
    if (arg && (lua_type(L, arg) == LUA_TSTRING || (S.safe && lua_type(L, arg) == LUA_TNUMBER)))
        check_name_copy(L, fname, arg, write);
    if (arg2 && (lua_type(L, arg2) == LUA_TSTRING || (S.safe && lua_type(L, arg2) == LUA_TNUMBER)))
        check_name_copy(L, fname, arg2, 1);
    int n = lua_gettop(L);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, n, LUA_MULTRET);
    return lua_gettop(L);
}

/* Replace t[name] (t at index idx) by a checked call of itself. */
static void wrap(lua_State *L, int idx, const char *name, const char *shown, int arg, int how,
                 int arg2) {
    idx = lua_absindex(L, idx);
    if (lua_getfield(L, idx, name) != LUA_TFUNCTION) {
        lua_pop(L, 1);
        return;
    }
    lua_pushstring(L, shown);
    lua_pushinteger(L, arg);
    lua_pushinteger(L, how);
    lua_pushinteger(L, arg2);
    lua_pushcclosure(L, checked_call, 5);
    lua_setfield(L, idx, name);
}

/* load(chunk [, chunkname [, mode [, env]]]): source text only, whatever mode says.  An env
 * that is not given stays not given (load sets _ENV to an explicit nil). */
static int text_load(lua_State *L) {
    int n = lua_gettop(L) >= 4 ? 4 : 3;
    lua_settop(L, n);
    lua_pushliteral(L, "t");
    lua_replace(L, 3);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, n, LUA_MULTRET);
    return lua_gettop(L);
}

/* loadfile([name [, mode [, env]]]): likewise, with the name checked. */
static int text_loadfile(lua_State *L) {
    const char *name = luaL_optstring(L, 1, NULL);
    if (name) sandbox_check_path(L, "loadfile", 1, 0);
    int env = !lua_isnone(L, 3);
    if (luaL_loadfilex(L, name, "t") != LUA_OK) {
        luaL_pushfail(L);
        lua_insert(L, -2);
        return 2;
    }
    if (env) {
        lua_pushvalue(L, 3);
        if (!lua_setupvalue(L, -2, 1)) lua_pop(L, 1);
    }
    return 1;
}

/* dofile([name]) */
static int text_dofile(lua_State *L) {
    const char *name = luaL_optstring(L, 1, NULL);
    if (name) sandbox_check_path(L, "dofile", 1, 0);
    lua_settop(L, 1);
    if (luaL_loadfilex(L, name, "t") != LUA_OK) return lua_error(L);
    lua_call(L, 0, LUA_MULTRET);
    return lua_gettop(L) - 1;
}

static int refused(lua_State *L) {
    return pcl_error(L, "%s is not available in safe mode (pointcalc --safe)",
                     lua_tostring(L, lua_upvalueindex(1)));
}

static void refuse(lua_State *L, int idx, const char *name, const char *shown) {
    idx = lua_absindex(L, idx);
    lua_pushstring(L, shown);
    lua_pushcclosure(L, refused, 1);
    lua_setfield(L, idx, name);
}

/* The debug library for the host's own REPL code, out of the scripts' reach. */
#define HOST_DEBUG "pointcalc.host.debug"

int sandbox_apply(lua_State *L) {
    lua_pushglobaltable(L);
    int g = lua_gettop(L);
    lua_getfield(L, g, "load");
    lua_pushcclosure(L, text_load, 1);
    lua_setfield(L, g, "load");
    lua_pushcfunction(L, S.safe ? sandbox_safe_loadfile : text_loadfile);
    lua_setfield(L, g, "loadfile");
    lua_pushcfunction(L, S.safe ? sandbox_safe_dofile : text_dofile);
    lua_setfield(L, g, "dofile");

    lua_getglobal(L, "io");
    int io = lua_gettop(L);
    lua_getglobal(L, "os");
    int os = lua_gettop(L);
    if (S.safe) sandbox_safe_files(L, io, os);   /* checked and opened without a race */
    else {
        wrap(L, io, "open", "io.open", 1, 2, 0);
        wrap(L, io, "lines", "io.lines", 1, 0, 0);
        wrap(L, io, "input", "io.input", 1, 0, 0);
        wrap(L, io, "output", "io.output", 1, 1, 0);
        wrap(L, os, "remove", "os.remove", 1, 1, 0);
        wrap(L, os, "rename", "os.rename", 1, 1, 2);
    }
    wrap(L, g, "save", "save", 1, 1, 0);
    lua_getglobal(L, "pointcalc");
    if (lua_istable(L, -1)) wrap(L, -1, "save", "save", 1, 1, 0);
    lua_pop(L, 1);

    if (S.safe) {
        refuse(L, os, "execute", "os.execute");
        refuse(L, os, "exit", "os.exit");
        refuse(L, os, "getenv", "os.getenv");
        refuse(L, os, "tmpname", "os.tmpname");
        refuse(L, os, "setlocale", "os.setlocale");
        refuse(L, io, "popen", "io.popen");
        refuse(L, io, "tmpfile", "io.tmpfile");   /* unnamed files: disk without a folder */
        lua_getglobal(L, "package");
        int pkg = lua_gettop(L);
        refuse(L, pkg, "loadlib", "package.loadlib");
        refuse(L, pkg, "searchpath", "package.searchpath");   /* it tells what exists */
        lua_pushliteral(L, "");
        lua_setfield(L, pkg, "path");
        lua_pushliteral(L, "");
        lua_setfield(L, pkg, "cpath");
        /* require finds only what is built in (package.preload): no Lua or C files */
        lua_getfield(L, pkg, "searchers");
        for (lua_Integer i = luaL_len(L, -1); i > 1; i--) {
            lua_pushnil(L);
            lua_rawseti(L, -2, i);
        }
        lua_pop(L, 1);
        /* no debug library: with it a script can forge a userdata's type and crash a
         * binding; the REPL's own code keeps it (host.c gives it to the "repl" module) */
        lua_getfield(L, g, "debug");
        lua_setfield(L, LUA_REGISTRYINDEX, HOST_DEBUG);
        lua_pushnil(L);
        lua_setfield(L, g, "debug");
        lua_getfield(L, pkg, "loaded");
        lua_pushnil(L);
        lua_setfield(L, -2, "debug");
        lua_pop(L, 2);
    }
    lua_settop(L, g - 1);
    return 0;
}
