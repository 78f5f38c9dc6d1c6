/* One convention for every 3-D view: z up.  A view looks from a point towards another with a
 * given up direction (default the z axis); the picture has x to the right as the viewer sees
 * it and y along the projection of up, origin at the target.  Orthographic or perspective
 * alike, so a script changes the projection without changing its camera.
 *
 * And the silhouette (outline) of a surface seen through such a map: where the surface turns
 * away from the viewer, its normal perpendicular to the line of sight. */
#ifndef PC_VIEW_H
#define PC_VIEW_H

#include "map.h"
#include "surface.h"

/* The view from `from` towards `to`, up (NULL: the z axis).  perspective != 0: the central
 * projection with the eye at from onto the plane through to perpendicular to the line of
 * sight (pc_map_perspective); else the parallel projection along it, lengths in planes
 * perpendicular to the line of sight kept.  PC_ECOINCIDENT if from = to, PC_EZERO for up = 0,
 * PC_ECOLLINEAR for up along the line of sight, PC_ENONFINITE for NaN or inf. */
int pc_map_view(pc_map *f, const double from[3], const double to[3], const double *up,
                int perspective);
/* The same by azimuth (degrees counter-clockwise from the x axis, seen from above) and
 * elevation (degrees above the xy plane) of the viewer, at distance dist from to (which
 * only a perspective feels).  Elevation +-90 looks along z: up is then the y axis turned by
 * the azimuth. */
int pc_map_view_azel(pc_map *f, const double to[3], double azimuth, double elevation,
                     double dist, int perspective);

/* The silhouette of the 3-D surface s seen through `screen` (a 3-D -> 2-D map; its viewer by
 * pc_viewer_of): the contour g = 0 of g(u, v) = n(u, v) . (towards the viewer) on a grid of
 * nu x nv cells (marching squares, each crossing refined by bisection to 1e-10 of a cell),
 * as 3-D segments: *xyz gets 6 numbers a segment, *nseg segments (malloc'd; free it).
 * PC_EDIM unless s is 3-D and the map 3 -> 2, PC_EDOMAIN for a grid outside 2..2048, a
 * surface status where it cannot be evaluated. */
int pc_surface_silhouette(const pc_surface *s, const pc_map *screen, int nu, int nv,
                          double **xyz, size_t *nseg);

#endif
