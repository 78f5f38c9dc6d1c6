/* What the drawing bindings share (l_draw.c, l_qbscreen.c, l_figure_layout.c): the canvas and
 * QBasic's pages kept by l_draw.c, the house error for a core call on a canvas, and the
 * readers of the drawing kinds. */
#ifndef PCL_DRAW_H
#define PCL_DRAW_H

#include "pcl_args.h"
#include "qbscreen.h"

/* The screen's pages (qbscreen.h); pcl_canvas (pcl.h) is the page shown, drawing goes to the
 * active page. */
pc_pages *pcl_pages(lua_State *L);
pc_canvas *pcl_active_canvas(lua_State *L);
/* A core call on canvas c returned rc: nothing if PC_OK, else its message raised under the
 * running function's declared name (a core statement's own name replaced: "pset: ..."). */
int pcl_check_canvas(lua_State *L, pc_canvas *c, int rc);

/* The colour at idx on canvas c: an attribute 0..ncolors-1 (with truecolors, also a true
 * colour's number 256..) or "#rrggbb" (a true colour, allocated on first use); -2 if none.
 * pcl_read_color (pcl_args.h) reads one as a declared argument, true colours too when the
 * argument's dim is 1. */
int pcl_color_at(lua_State *L, int idx, pc_canvas *c, int truecolors);
/* Set the fields names[0..n-1] of the table on the stack top to x[0..n-1] (as integers). */
void pcl_set_fields(lua_State *L, int n, const char *const *names, const double *x, int integers);
/* n rows of dim coordinates as places on the screen into xy (2-D as they are, n-D through
 * the camera): -1, or the index of the first that has no place. */
int pcl_rows_to_xy(lua_State *L, int n, int dim, const double *rows, double *xy);

#endif
