/* The 3-D scene of the bindings (l_camera.c, stdlib/draw/scene.h): with a camera set
 * by camera(f, {hidden = "dashed"|"hide"|"show"}), 3-D strokes go into a scene attached to the
 * canvas instead of being drawn, and the writers resolve it whatever the drawing order. */
#ifndef PCL_SCENE_H
#define PCL_SCENE_H

#include "pcl.h"
#include "scene.h"

/* The scene 3-D strokes go into now, or NULL when the camera has no hidden mode (or is not
 * 3-D). */
pc_scene *pcl_scene(lua_State *L);

#endif
