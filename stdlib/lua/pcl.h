/* Shared declarations of the Lua bindings: one file l_NAME.c per module (pcl_open_NAME). */
#ifndef PCL_H
#define PCL_H

#include <math.h>      /* the C library every binding uses */
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <lua.h>
#include <lauxlib.h>
#include "canvas.h"
#include "writers.h"
#include "map.h"

#define PCL_VERSION "0.1.0"

/* The userdata at idx if its metatable is the value at index mt (a pseudo-index such as an
 * upvalue, or an absolute index), else NULL: how every binding recognises its own objects. */
static inline void *pcl_testudata(lua_State *L, int idx, int mt) {
    void *p = lua_touserdata(L, idx);
    if (p == NULL || !lua_getmetatable(L, idx)) return NULL;
    int ok = lua_rawequal(L, -1, mt);
    lua_pop(L, 1);
    return ok ? p : NULL;
}

/* Userdata a script cannot forge (debug.setmetatable, debug.setupvalue): a binding takes a
 * userdata as its own only when its block has its type's size (lua_rawlen) and, where size
 * does not tell, begins with its own address tagged by its type (PCL_SELF).
 * pcl_genuine(L, idx, p, ok, type): p when ok or NULL, else "FNAME: argument #N is a forged
 * TYPE (...)", never showing the value (a forged point's __tostring would read it). */
void *pcl_genuine(lua_State *L, int idx, void *p, int ok, const char *type);
#define PCL_SELF uintptr_t self     /* the first field of such a userdata */
/* What self holds: the block's address mixed with the address of a static tag of the type,
 * so one type's object given another's metatable is refused as well. */
#define PCL_SELF_TAG(p, tag) ((uintptr_t)(const void *)(p) ^ (uintptr_t)(const void *)(tag))

/* The module openers pcl_open_NAME (errors: pcl_util.c, curves: l_curve.c), in the order
 * luaopen_pointcalc calls them: conic_elements after konopatsky (conic) and buimov (plane). */
#define PCL_MODULES(X) X(errors) X(point) X(expr) X(simplex) X(map) X(draw) X(qb) X(qbscreen) \
    X(smooth) X(curves) X(surface) X(camera) X(konopatsky) \
    X(params) X(korotky) X(buimov) X(conic_elements) \
    X(curvilinear) X(complex) X(figure) X(figure_layout)
#define PCL_DECLARE_OPEN(name) void pcl_open_##name(lua_State *L);
PCL_MODULES(PCL_DECLARE_OPEN)

/* The map userdata (l_map.c): the map at idx or NULL; push a new one (its matrix unset). */
pc_map *pcl_tomap(lua_State *L, int idx);
pc_map *pcl_newmap(lua_State *L);

/* A script's parameters (l_params.c): the value a slider takes in the next run (--set, a live
 * page, a frame); after a run, push the sliders it declared ({name =, min =, max =, ...}). */
void pcl_param_set(lua_State *L, const char *name, double value);
void pcl_push_params(lua_State *L);

/* The canvas of this Lua state (created on first use as SCREEN 12). */
pc_canvas *pcl_canvas(lua_State *L);
/* The theme used by save() and the host's -o (set by --paper). */
void pcl_set_theme(lua_State *L, pc_theme theme);
pc_theme pcl_theme(lua_State *L);

/* l_point.c: a point at idx into x, y and 1 (its weight must be 1, it 2-D), or 0 if no point. */
int pcl_topoint2(lua_State *L, int idx, double *x, double *y);

/* "FNAME: argument #SHOWN (WHAT) must be EXPECTED, got VALUE" (shown 0: "self"), off the layer. */
int pcl_argerror_full(lua_State *L, const char *fname, int idx, int shown, const char *what,
                      const char *expected);
/* The value at idx as the messages show it ("got VALUE"): numbers by value, P(...) for a point,
 * userdata by type name, else the type (it may push a string). */
const char *pcl_shown(lua_State *L, int idx);
/* The running C function's name (a declared one's: pcl_name); the number arg is shown as. */
const char *pcl_fname(lua_State *L);
int pcl_arg_shown(lua_State *L, int arg);
/* luaL_error, but located at the user's code: frames of the embedded Lua helpers are skipped
 * (pcl_verror: PREFIX then the message). */
int pcl_error(lua_State *L, const char *fmt, ...);
/* A metamethod's receiver p, or (p NULL: called on another value) raise msg as pcl_error. */
void *pcl_meta_self(lua_State *L, void *p, const char *msg);
int pcl_verror(lua_State *L, const char *prefix, const char *fmt, va_list ap);
/* Push that location, "file:line: " (or ""), for a message kept rather than raised (a callback's). */
void pcl_pushwhere(lua_State *L);

/* Push x as text the way points print their coordinates: %.14g, no "-0". */
const char *pcl_pushnum(lua_State *L, double x);
/* Raise "FNAME: CONTEXT (MESSAGE)" or "FNAME: MESSAGE" for a core status. */
int pcl_statuserror(lua_State *L, const char *fname, int status, const char *context);
/* Push the private table _tk of the module table (the embedded Lua helpers' own functions). */
void pcl_private(lua_State *L, int module);

/* The core calls Lua functions through callbacks run protected in the state set here (every
 * binding that may evaluate one sets it first).  A callback keeps its error with
 * pcl_callback_failed (the error on the stack top; PC_EARG); pcl_raise_status raises the kept
 * error, or "FNAME: <the status message>". */
void pcl_callback_state(lua_State *L);
lua_State *pcl_current_state(void);
int pcl_callback_failed(lua_State *L);
int pcl_raise_status(lua_State *L, const char *fname, int status);

#endif
