/* The host program's pieces: the Lua state with pointcalc in globals, running chunks with
 * tracebacks, the QBasic front end hook, and the REPL. */
#ifndef PC_HOST_H
#define PC_HOST_H

#include <lua.h>
#include "sandbox.h"

/* A new Lua state with the standard libraries, pointcalc loaded into globals, and the host's
 * embedded Lua chunks (the QBasic translator) in package.preload; the rules and limits of cfg
 * (sandbox.h) apply to it. */
lua_State *host_new_state(const sandbox_config *cfg);

/* Run the function on top of the stack with nargs arguments under a traceback handler.
 * On error prints "MESSAGE\nstack traceback:..." to stderr and returns 0. */
int host_pcall(lua_State *L, int nargs);

/* Whether the last host_pcall failed on the time or memory limit (a QBasic program so
 * stopped still writes its picture). */
extern int host_limit_stopped;

/* Load a script file ("-" for standard input) as a Lua chunk, or, when qbasic is set, translate
 * it from QBasic first.  On failure prints the message and returns 0. */
int host_load_script(lua_State *L, const char *path, int qbasic);

/* Print the Lua translation of a QBasic program to standard output. 0 on failure. */
int host_emit_lua(lua_State *L, const char *path);

/* The interactive loop (repl.c).  watch: a file to rewrite whenever the canvas changes, or
 * NULL. */
void host_repl(lua_State *L, const char *watch);

/* The program name used in messages. */
extern const char *host_progname;

#endif
