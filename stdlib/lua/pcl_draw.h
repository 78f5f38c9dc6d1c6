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

#endif
