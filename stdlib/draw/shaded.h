/* Drawing shaded quads (stdlib/geom/shade.h) onto the canvas: each quad, in the order given
 * (the painter's), filled with its shade of the base colour as a true colour, and with mesh
 * >= 0 its outline drawn over it in that colour with the current pen.  Pure C: no Lua. */
#ifndef PC_SHADED_H
#define PC_SHADED_H
#include "canvas.h"
#include "shade.h"

/* The quads' corners are screen coordinates (as pc_shade_quads gives them through a map to
 * the screen); they are taken back through WINDOW and VIEW to the world coordinates the
 * drawing statements take.  A quad is one filled path (nonzero rule), so adjacent quads share
 * their edges' pixels exactly once (canvas.h).  PC_OK, or the canvas's status with its
 * message (too many colours, out of memory). */
int pc_draw_shaded(pc_canvas *c, const pc_shade_quad *q, size_t n, pc_rgb base, int mesh);

#endif
