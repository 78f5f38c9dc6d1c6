/* The screen pages and DRAW state kept by the drawing binding (l_draw.c), for the binding of
 * QBasic's screen (l_qbscreen.c).  pcl_canvas (pcl.h) is the page shown; drawing goes to the
 * active page. */
#ifndef PCL_QBSCREEN_H
#define PCL_QBSCREEN_H

#include "pcl.h"
#include "qbscreen.h"

#define PCL_MAX_PAGES 8

pc_canvas *pcl_active_canvas(lua_State *L);
/* The number of pages of the current screen (SCREEN 7: 8, SCREEN 9: 2, else 1). */
int pcl_npages(lua_State *L);
/* Page n (made blank on first use); NULL when the screen has no such page. */
pc_canvas *pcl_page(lua_State *L, int page);
/* SCREEN , , apage, vpage: draw on page `active`, show page `visual` (both valid pages). */
void pcl_set_pages(lua_State *L, int active, int visual);
pc_draw_state *pcl_draw_state(lua_State *L);
/* A core call on canvas c returned rc: nothing if PC_OK, else its message raised under the
 * running function's declared name (a core statement's own name replaced: "pset: ..."). */
int pcl_check_canvas(lua_State *L, pc_canvas *c, int rc);

#endif
