/* What the drawing bindings share (l_draw.c, l_qbscreen.c, l_figure_layout.c, l_camera.c): the
 * canvas and QBasic's pages kept by l_draw.c, the house error for a core call on a canvas, and
 * the readers of the drawing kinds; the headers they all include. */
#ifndef PCL_DRAW_H
#define PCL_DRAW_H

#include "pcl_args.h"
#include "pcl_core.h"     /* pcl_push_results, pcl_project (3-D points through the camera) */
#include "qbscreen.h"
#include "curve_path.h"   /* places through the camera, and scene.h */
#include "pcl_tagged.h"   /* pcl_tagged_new, pcl_tagged_udata beside pcl_tagged below */

/* The screen's pages (qbscreen.h); pcl_canvas (pcl.h) is the page shown, drawing goes to the
 * active page. */
pc_pages *pcl_pages(lua_State *L);
pc_canvas *pcl_active_canvas(lua_State *L);
/* A core call on canvas c returned rc: nothing if PC_OK, else its message raised under the
 * running function's declared name (a core statement's own name replaced: "pset: ..."). */
int pcl_check_canvas(lua_State *L, pc_canvas *c, int rc);
/* The same for a core call on the active canvas (pcl_active_canvas). */
int pcl_drawn(lua_State *L, int rc);
/* The scene 3-D strokes go into now (l_camera.c, scene.h), or NULL when the camera has no
 * hidden mode (camera(f, {hidden = "dashed"|"hide"|"show"})) or is not 3-D: attached to the
 * canvas, it is resolved at write whatever the drawing order. */
pc_scene *pcl_scene(lua_State *L);

/* The colour at idx on canvas c: an attribute 0..ncolors-1 (with truecolors, also a true
 * colour's number 256..) or "#rrggbb" (a true colour, allocated on first use); -2 if none.
 * pcl_read_color (pcl_args.h) reads one as a declared argument, true colours with its dim 1. */
int pcl_color_at(lua_State *L, int idx, pc_canvas *c, int truecolors);
/* An attribute 0..ncolors-1 of the screen drawn on (no "#rrggbb": QBasic's numbers) into
 * out->x; its message names the screen's range, as an attribute (a->dim 1) or a colour number. */
int pcl_read_attr(lua_State *L, int idx, const pcl_arg *a, pcl_val *out);
/* A string of lo..hi bytes into out->s, out->n; hi 0: any length without NUL bytes, which would
 * cut a label or DRAW's commands short; with a->dim 1 a number too, shown as Lua shows it. */
int pcl_read_bytes(lua_State *L, int idx, const pcl_arg *a, pcl_val *out);
/* The userdata at idx if its block is a genuine one of size bytes tagged by tag (PCL_SELF,
 * pcl.h), else NULL: a canvas box, a block of get_block. */
static inline void *pcl_tagged(lua_State *L, int idx, size_t size, const void *tag) {   /* inline: pset's path */
    uintptr_t *self = lua_touserdata(L, idx);
    int ok = self && lua_type(L, idx) == LUA_TUSERDATA && lua_rawlen(L, idx) == size && *self == PCL_SELF_TAG(self, tag);
    return ok ? self : NULL;
}
/* PCL_BODY for a statement whose coordinate pairs may each be one point (pcl_read_pairs, which
 * clears the values itself). */
#define PCL_PAIRS_BODY(f, a) \
    static int f##_body(lua_State *L, pcl_val *a); \
    static int f(lua_State *L) { \
        pcl_val f##_v[pcl_nvalues(L)]; \
        pcl_read_pairs(L, f##_v, (int)(sizeof f##_v / sizeof f##_v[0])); \
        return f##_body(L, f##_v); \
    } \
    static int f##_body(lua_State *L, pcl_val *a)
/* The points of a declared list (rows of list->dim) as places on the screen, 2-D as they are,
 * n-D through the camera, in a scratch userdata pushed; else "NAME: WHAT [i] must be ...". */
double *pcl_places(lua_State *L, const pcl_val *list, const char *what);
#define PCL_PLACE_TEXT "a 2-D point (or an n-D one through the camera)"

#endif
