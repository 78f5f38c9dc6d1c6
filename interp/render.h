/* Rendering a script on demand: for the live page (serve.c) and animation frames (frames.c).
 * Each run is a fresh Lua state with the script's parameters set (slider(), l_params.c) and a
 * time limit, so a runaway script cannot hang the server, and one run cannot leak into the
 * next. */
#ifndef PC_RENDER_H
#define PC_RENDER_H

#include <stddef.h>
#include <lua.h>
#include "sandbox.h"
#include "writers.h"

typedef struct {
    char name[65];
    double value;
} render_param;

typedef struct {
    lua_State *L;          /* the state that ran (its canvas and declared sliders) */
    char error[1024];      /* on failure: "script.lua:LINE: message" */
    int line;              /* the line of the error in the script, or 0 */
} render_run;

/* Run the script (Lua, or QBasic when it ends in .bas) with these parameter values in a fresh
 * state made with cfg (safe mode and limits, sandbox.h).  1 on success; 0 with r->error set.
 * r->L stays open either way (the sliders declared before an error are still there): close it
 * with render_close. */
int render_script(const char *path, const render_param *params, int nparams,
                  const sandbox_config *cfg, render_run *r);
void render_close(render_run *r);

/* The run's canvas in memory as pc_write_file would write it (writers.h: PNG, SVG, PDF, ...;
 * the print look for PDF and for a script's figure{}), malloc'd; NULL with r->error on failure. */
char *render_encode(render_run *r, pc_format fmt, size_t *len);

/* Parse "name=value" (the command line's --set): 1 on success. */
int render_parse_param(const char *s, render_param *p);

#endif
