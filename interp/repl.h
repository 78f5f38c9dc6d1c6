/* Pieces of the REPL shared between its files (repl.c: the loop, the commands' native side and
 * --watch; complete.c: Tab completion through libedit).  The Lua side of the REPL (printing
 * values, completion candidates, the :commands, :help) is interp/repl.lua, `require "repl"`. */
#ifndef PC_REPL_H
#define PC_REPL_H

#include <lua.h>

/* Push the Lua side of the REPL (the table returned by require "repl"); 0 on failure (the
 * message is printed). */
int repl_push_module(lua_State *L);

/* Install Tab completion for this Lua state (no-op without libedit). */
void repl_completion_init(lua_State *L);

#endif
