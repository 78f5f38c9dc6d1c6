/* Shared declarations of the Lua bindings.  Each module has one binding file l_NAME.c that
 * adds its functions to the pointcalc table on top of the stack (pcl_open_NAME). A binding
 * only checks arguments, calls the core, pushes results. */
#ifndef PCL_H
#define PCL_H

#include <math.h>      /* the C library every binding uses */
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

/* Userdata a script cannot forge.  With the debug library a script can give any userdata (a
 * file handle, another binding's object) a binding's metatable (debug.setmetatable), or put
 * one in a C function's upvalue (debug.setupvalue).  So a binding takes a userdata as its own
 * only when, besides the metatable, its block has the size its type stores (lua_rawlen, which
 * no script can change) and, for a type whose size alone does not tell (it holds pointers, or
 * has the size of a file handle or a point), begins with its own address tagged by its type
 * (PCL_SELF: a forged block holds something else there).  pcl_genuine(L, idx, p, ok, type):
 * p when ok or p is NULL, else raises "FNAME: argument #N is a forged TYPE (...)"; it never
 * shows the value (a forged point's __tostring would read it). */
void *pcl_genuine(lua_State *L, int idx, void *p, int ok, const char *type);
#define PCL_SELF uintptr_t self     /* the first field of such a userdata */
/* What self holds: the block's address mixed with the address of a static tag of the type,
 * so one type's object given another's metatable is refused as well. */
#define PCL_SELF_TAG(p, tag) ((uintptr_t)(const void *)(p) ^ (uintptr_t)(const void *)(tag))

/* The module openers pcl_open_NAME (l_NAME.c; errors: pcl_util.c, curves: l_curve.c), each adding
 * its functions to the module table on the stack top, in the order luaopen_pointcalc calls them:
 * conic_elements after konopatsky (conic) and buimov (plane).  The print look's pens and label
 * options: pcl_args.h. */
#define PCL_MODULES(X) X(errors) X(point) X(expr) X(simplex) X(map) X(draw) X(qb) X(qbscreen) \
    X(smooth) X(curves) X(surface) X(camera) X(konopatsky) X(konopatsky_ch1) X(konopatsky_schemes) \
    X(konopatsky_triples) X(params) X(korotky) X(buimov) X(conic_elements) \
    X(curvilinear) X(complex) X(figure) X(figure_layout)
#define PCL_DECLARE_OPEN(name) void pcl_open_##name(lua_State *L);
PCL_MODULES(PCL_DECLARE_OPEN)

/* The map userdata (l_map.c): the map at idx or NULL; push a new one (its matrix unset). */
pc_map *pcl_tomap(lua_State *L, int idx);
pc_map *pcl_newmap(lua_State *L);

/* A script's parameters (l_params.c): the value a slider of that name takes in the next run
 * (--set name=value, a live page, an animation frame); after a run, push the list of the
 * sliders it declared ({name =, min =, max =, default =, step =, animate =}, in order). */
void pcl_param_set(lua_State *L, const char *name, double value);
void pcl_push_params(lua_State *L);

/* The canvas of this Lua state (created on first use as SCREEN 12). */
pc_canvas *pcl_canvas(lua_State *L);
/* The theme used by save() and the host's -o (set by --paper). */
void pcl_set_theme(lua_State *L, pc_theme theme);
pc_theme pcl_theme(lua_State *L);

/* An optional colour argument (nil: -1, the default; an attribute or "#rrggbb"), l_draw.c. */
int pcl_optcolor(lua_State *L, int arg, pc_canvas *c);

/* Implemented by the point binding: if the value at idx is a point userdata, store its first
 * two coordinates and return 1 (raising the membership-condition error if its weight is not
 * 1, or a dimension error if it is not 2-D); return 0 if it is not a point. */
int pcl_topoint2(lua_State *L, int idx, double *x, double *y);

/* The house error style, "FNAME: argument #SHOWN (WHAT) must be EXPECTED, got VALUE" for the
 * value at idx (shown 0: "self"), for a binding not on the declared layer (pcl_args.h). */
int pcl_argerror_full(lua_State *L, const char *fname, int idx, int shown, const char *what,
                      const char *expected);
/* The value at idx as the messages show it ("got VALUE"): numbers by value, P(...) for a point,
 * userdata by type name, else the type (it may push a string). */
const char *pcl_shown(lua_State *L, int idx);
/* The name of the running C function, and the number an argument index is shown as. */
const char *pcl_fname(lua_State *L);
int pcl_arg_shown(lua_State *L, int arg);
/* luaL_error, but located at the user's code: frames of the embedded Lua helpers are skipped. */
int pcl_error(lua_State *L, const char *fmt, ...);
/* Push that location, "file:line: " (or ""), for a message kept rather than raised (a callback's). */
void pcl_pushwhere(lua_State *L);

/* Push x as text the way points print their coordinates: %.14g, no "-0". */
const char *pcl_pushnum(lua_State *L, double x);
/* Raise "FNAME: CONTEXT (MESSAGE)" or "FNAME: MESSAGE" for a core status. */
int pcl_statuserror(lua_State *L, const char *fname, int status, const char *context);
/* Push the private table _tk of the module table at index module (created on first use): how
 * the embedded Lua helpers reach core functions that are not API. */
void pcl_private(lua_State *L, int module);

/* The core calls Lua functions (curve(f, ...), surface(f, ...), a Lua smoothstep) through
 * callbacks that run them protected in the state set here; every binding entry that may
 * evaluate such an object sets it first.  A callback keeps its error with
 * pcl_callback_failed (the error object on the stack top; returns PC_EARG) and the core
 * returns a failure status; pcl_raise_status then raises the kept error, or "FNAME: <the
 * status message>". */
void pcl_callback_state(lua_State *L);
lua_State *pcl_current_state(void);
int pcl_callback_failed(lua_State *L);
int pcl_raise_status(lua_State *L, const char *fname, int status);
/* Inside a callback: call the function below the nargs arguments on the stack top, protected,
 * for one number into *y (any number: the caller judges NaN).  PC_OK, or PC_EARG with the
 * error kept: the function's own, or "file:line: FNAME: WHAT must return a number, got TYPE".
 * The function and its arguments are popped either way. */
int pcl_call_number(lua_State *L, int nargs, const char *fname, const char *what, double *y);

#endif
