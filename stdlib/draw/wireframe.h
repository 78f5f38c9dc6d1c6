/* Drawing a surface as its iso-lines (s:wireframe): the lines u = u0 + i (u1 - u0)/nu and
 * v = v0 + j (v1 - v0)/nv, each flattened through a map to the screen and stroked as one path,
 * the parts the surface itself hides left out or dashed (hidden.h), and its silhouette; or the
 * same strokes put into a 3-D scene (scene.h), which resolves them at write.  And as shaded
 * quads (s:shade).  Pure C: no Lua. */
#ifndef PC_WIREFRAME_H
#define PC_WIREFRAME_H
#include "canvas.h"
#include "scene.h"
#include "shaded.h"

typedef struct {
    int nu, nv;            /* parts of each family (0: none of it, or its two edges with boundary) */
    int color;             /* an attribute; < 0 the foreground */
    double tol;            /* flattening tolerance in pixels */
    int hidden;            /* 0 every line as it is, 1 leave out what the surface hides, 2 dash it */
    int mesh;              /* the occluder's grid (hidden lines, silhouette) */
    int silhouette, boundary;
} pc_wireframe_opts;

/* Draw s through `screen` (a map from s's dimension to screen pixels, y down: a projection
 * then WINDOW and VIEW) onto the canvas.  A hidden mode and the silhouette need a 3-D s.
 * Returns the status of the geometry (PC_OK, PC_ENOMEM, the occluder's and the curves'
 * failures); *drawn gets the canvas's status (its message in the canvas). */
int pc_draw_wireframe(pc_canvas *cv, pc_surface *s, const pc_map *screen,
                      const pc_wireframe_opts *o, int *drawn);
/* The same into a scene: s as an occluder on a mesh x mesh grid, its iso-lines (sampled at
 * 257 parameters) and silhouette as 3-D strokes with the pen `pen`; `screen` is the scene's. */
int pc_scene_wireframe(pc_scene *sc, pc_surface *s, const pc_map *screen,
                       const pc_wireframe_opts *o, int pen);
/* s as o->nu x o->nv quads through `screen`, each filled with its Lambert shade of base
 * (shade.h) in painter's order, its outline over it in colour mesh when mesh >= 0
 * (pc_draw_shaded); with a scene sc (may be NULL) s joins it as an occluder as fine as the
 * quads (48 at least), so the scene's strokes behind it are hidden at write whatever the order
 * of the calls.  *n: the quads drawn.  The status of the geometry (PC_ESINGULAR for a map that
 * flattens space onto a line); *drawn the canvas's. */
int pc_draw_shaded_surface(pc_canvas *cv, pc_scene *sc, const pc_surface *s, const pc_map *screen,
                           const pc_shade_opts *o, pc_rgb base, int mesh, size_t *n, int *drawn);

#endif
