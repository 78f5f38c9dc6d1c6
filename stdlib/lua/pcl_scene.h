/* The 3-D scene of the bindings (l_figure_layout.c, stdlib/draw/scene.h): with a camera set
 * by camera(f, {hidden = "dashed"|"hide"|"show"}), 3-D strokes go into a scene attached to the
 * canvas instead of being drawn, and the writers resolve it whatever the drawing order. */
#ifndef PCL_SCENE_H
#define PCL_SCENE_H

#include "pcl.h"
#include "curve.h"
#include "scene.h"

/* The camera's hidden-line mode: -1 none, else a pc_hidden_mode (l_camera.c sets it). */
void pcl_set_hidden_mode(lua_State *L, int mode);
/* The scene 3-D strokes go into now, or NULL when the camera has no hidden mode (or is not
 * 3-D). */
pc_scene *pcl_scene(lua_State *L);
/* Add curve c (3-D), sampled at n + 1 parameters, to the scene in colour color. */
int pcl_scene_curve(lua_State *L, pc_scene *sc, const pc_curve *c, int n, int color);
/* line(A, B [, colour]) with 3-D points and a scene: adds the segment and returns 1; else 0
 * (the caller draws as usual). */
int pcl_scene_line(lua_State *L);
/* pset(P [, colour]) with a 3-D point and a scene: adds the dot and returns 1; else 0. */
int pcl_scene_pset(lua_State *L);
/* path(points, {closed =, color =, arrow =}) with 3-D points and a scene (the arguments read):
 * adds the polyline and its heads (PC_ARROW_* bits) and returns 1; else 0 (the caller draws as
 * usual). */
int pcl_scene_path(lua_State *L, int closed, int color, int heads);
/* label(text, P [, direction [, colour [, scale]]] [, {font, size, halo}]) with a 3-D point and
 * a scene, its arguments a read by label's declaration (l_draw.c): the markup checked, the
 * label shows only where its point is seen; returns 1, or 0 for the caller to draw as usual. */
int pcl_scene_label(lua_State *L, const pcl_val *a);

#endif
