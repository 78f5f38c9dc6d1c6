/* What a script may do (docs/safety.md): the safe mode and the time and memory limits of the
 * host's Lua state.
 *
 * Always: `load`, `loadfile` and `dofile` take source text only (Lua does not verify bytecode,
 * and a damaged binary chunk crashes the interpreter), and a file name with a NUL byte is an
 * error in every function that takes one (instead of being cut at the NUL).
 *
 * Safe mode (`--safe`, and the default for any script that does not come from the user's own
 * command line): no processes, no C modules, no binary chunks, no `debug`, no `os.exit`,
 * `os.getenv`, `os.tmpname`, `os.setlocale`, `io.tmpfile`, `package.searchpath`; files are read
 * and written only under the folders given with `--allow`, opened without a race
 * (safe_files.c); default limits of 60 s and 1024 MB.
 *
 * Limits: a wall-clock time limit (an instruction-count hook, backed by a timer for long
 * native calls) and a memory limit (the accounting allocator of memlimit.c refuses any block
 * past it, wherever it is asked for; the hook then stops the script at its line). */
#ifndef PC_SANDBOX_H
#define PC_SANDBOX_H

#include <stddef.h>
#include <lua.h>

#define SANDBOX_MAX_ALLOW 32

typedef struct {
    int safe;                          /* the safe mode */
    int nallow;                        /* folders given with --allow, as the user wrote them */
    const char *allow[SANDBOX_MAX_ALLOW];
    double timeout;                    /* seconds; 0: no limit */
    double max_memory_mb;              /* megabytes; 0: no limit */
    int allow_hardlinks;               /* files with other hard links may be opened */
} sandbox_config;

/* The configuration for a script that did not come from the user's own command line (a
 * server, a web page): safe, nothing allowed, 10 s, 256 MB. */
extern const sandbox_config sandbox_untrusted;

/* Check the folders (they must exist) before a state is made.  0 with a message in err. */
int sandbox_check_config(const sandbox_config *cfg, char *err, size_t errlen);

/* Put the counting allocator under a new state (before anything else is allocated). */
void sandbox_attach(lua_State *L, const sandbox_config *cfg);

/* Apply the rules to the globals of a state that has pointcalc loaded: text-only loading and
 * NUL-free file names always, and the safe mode when configured.  Raises on failure (call
 * protected). */
int sandbox_apply(lua_State *L);

/* Run the limits around a chunk: the clock starts at sandbox_start; sandbox_stop disarms the
 * hook and the timer.  The REPL starts and stops them around every statement. */
void sandbox_start(lua_State *L);
void sandbox_stop(lua_State *L);

/* While on, Ctrl-C (SIGINT) stops the running script with "FILE:LINE: interrupted (Ctrl-C)"
 * (a QBasic program then still writes its picture); a second Ctrl-C ends the process. */
#define SANDBOX_INTERRUPTED "interrupted (Ctrl-C)"
void sandbox_catch_interrupt(int on);

/* After a call failed with status: 1 if it was a refused allocation; its message ("WHERE: memory
 * limit of N MB exceeded ...", where may be NULL) then replaces Lua's "not enough memory". */
int sandbox_explain(lua_State *L, int status, const char *where);

/* The exit status of a process whose native call ran past the time limit (after its message
 * "FILE:LINE: time limit of N s exceeded in a native call; stopped" on standard error). */
#define SANDBOX_EXIT_NATIVE_TIMEOUT 1

/* Whether the state is in safe mode, and the check the safe mode makes of a file name: raises
 * the house-style error for argument arg of fname unless path may be used. */
int sandbox_is_safe(lua_State *L);
void sandbox_check_path(lua_State *L, const char *fname, int arg, int write);
/* The same for the REPL's commands, without raising: 0 with "cannot write 'PATH': it must be
 * ..." in err.  The string is at stack index idx. */
int sandbox_path_ok(lua_State *L, int idx, int write, char *err, size_t errlen);

/* For safe_files.c: whether a real (resolved) path is under an allowed folder; the safe mode's
 * error for argument arg of fname (why: NULL for "a file under an allowed folder ..."). */
int sandbox_under_allowed(const char *real);
int sandbox_hardlinks_allowed(void);
int sandbox_refuse_path(lua_State *L, const char *fname, int arg, int write, const char *why);
/* safe_files.c: the race-free io and os functions, loadfile and dofile of the safe mode. */
void sandbox_safe_files(lua_State *L, int io, int os);
int sandbox_safe_loadfile(lua_State *L);
int sandbox_safe_dofile(lua_State *L);

#endif
