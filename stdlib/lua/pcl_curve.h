/* Shared by the bindings of curves, surfaces, maps and 3-D drawing (l_curve.c, l_surface.c,
 * l_map.c, l_camera.c): the objects of the one curve, surface and map types, the current
 * projection, and the drawing of curves and polylines (stdlib/draw/curve_path.h). */
#ifndef PCL_CURVE_H
#define PCL_CURVE_H

#include "pcl_tk.h"
#include "curve.h"
#include "surface.h"

/* The core object of a curve / surface userdata at idx, or NULL (maps: pcl_tomap, pcl.h). */
pc_curve *pcl_tocurve(lua_State *L, int idx);
pc_surface *pcl_tosurface(lua_State *L, int idx);
/* Push a curve object owning the reference c (kind: the constructor's name, static); 1. */
int pcl_pushcurve(lua_State *L, pc_curve *c, const char *kind);
/* Push the curve a core constructor made (kind NULL: the running function's name), or, when it
 * made none (c NULL), raise its status *st (a kept callback error first).  1.  st by address:
 * pcl_push_made(L, pc_x(..., &st), &st, k) reads it after pc_x has set it.  Its twin for
 * surfaces (l_surface.c) raises under the name kind. */
int pcl_push_made(lua_State *L, pc_curve *c, const int *st, const char *kind);
int pcl_push_made_surface(lua_State *L, pc_surface *s, const int *st, const char *kind);

/* The knots argument at arg of a B-spline of ncp control points: nil ("open"), "open",
 * "uniform", "periodic", or a non-decreasing list of ncp + degree + 1 numbers (then *knots
 * points at them, in a scratch userdata left on the stack; else NULL). */
pc_knot_kind pcl_checkknots(lua_State *L, int arg, int ncp, int degree, double **knots);

/* The current projection set by camera(), or NULL. */
pc_map *pcl_camera(lua_State *L);
/* The image under the camera of the homogeneous n-D value h: PC_OK, PC_EDIM (no camera for
 * n-D points), PC_IMPROPER (it projects to infinity), PC_ENONFINITE. */
int pcl_project(lua_State *L, int n, const double *h, double *x, double *y);
/* pc_screen_map on the current canvas. */
void pcl_screen_map(lua_State *L, const pc_map *f, pc_map *out);
/* The projection to use for drawing a dim-D object with the map at idx (none or nil: the
 * camera); raises a clear error when there is none. */
const pc_map *pcl_drawing_map(lua_State *L, int idx, int dim, const char *fname);
/* pc_curve_draw (curve_path.h) of c through f (NULL: c is 2-D) onto the canvas, or into the
 * scene of a hidden-line camera; raises errors naming fname. */
void pcl_draw_curve(lua_State *L, pc_curve *c, const pc_map *f, int pieces, double tol,
                    int color, int closed, const char *fname);

#endif
