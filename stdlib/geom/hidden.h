/* Hidden lines: is a point of space seen, or does a surface hide it, in a picture made by a
 * projection?  The surface is sampled on a grid of nu x nv quads (two triangles each), projected
 * with the map; a point is hidden when a triangle covering its image lies nearer the viewer by
 * more than a tolerance (a quarter of the mean edge of the grid, so the triangles around a
 * point of the surface itself never hide it).
 *
 * "Nearer" comes from the map alone.  A 3-D -> 2-D map is a 3 x 4 matrix; its null vector is
 * the centre of projection.  A finite centre (a perspective) is the eye: nearer is closer to it.
 * A centre at infinity (a parallel projection) is the viewing direction, oriented by the
 * picture: the map's picture coordinates are taken as the screen's (x to the right, y down, as
 * pixels are), so the viewer is on the side -(r1 x r2) of the rows r1, r2 of its linear part. */
#ifndef PC_HIDDEN_H
#define PC_HIDDEN_H
#include "surface.h"

/* The viewer of a map from 3-D to a 2-D y-down screen: a finite eye (perspective) or a
 * direction towards the viewer (parallel), as described above.  Hidden lines and shaded
 * surfaces (shade.h) take "nearer" from here. */
typedef struct {
    int perspective;
    double eye[3];     /* the centre, or the unit direction towards the viewer */
} pc_viewer;

/* The viewer of `screen`: PC_EDIM unless it maps 3-D to 2-D, PC_ESINGULAR for rank < 3. */
int pc_viewer_of(const pc_map *screen, pc_viewer *v);
/* The depth of the 3-D point x: larger is nearer the viewer (minus the distance to the eye,
 * or the height along the direction towards the viewer). */
double pc_viewer_depth(const pc_viewer *v, const double *x);
/* The unit direction from x towards the viewer into out; PC_EZERO at the eye itself. */
int pc_viewer_toward(const pc_viewer *v, const double *x, double out[3]);

typedef struct pc_occluder pc_occluder;

/* An occluder for the 3-D surface s seen through `screen` (a map from 3-D to 2-D screen
 * pixels, y down).  NULL with *status: PC_EDIM unless s is 3-D and the map 3 -> 2,
 * PC_EDOMAIN for a grid outside 1..1024, PC_ENOMEM, PC_ESINGULAR for a map of rank < 3. */
pc_occluder *pc_occluder_new(const pc_surface *s, const pc_map *screen, int nu, int nv,
                             int *status);
void pc_occluder_free(pc_occluder *o);
/* 1 if the 3-D point x is seen, 0 if the surface hides it (a point that does not project to a
 * finite image counts as seen). */
int pc_occluder_visible(const pc_occluder *o, const double *x);
/* The depth used: larger is nearer the viewer (pc_viewer_depth of the map's viewer). */
double pc_occluder_depth(const pc_occluder *o, const double *x);
/* The 3-D curve c drawn through `screen` split into its seen and hidden runs, appended to the
 * screen polylines seen and hidden: n + 1 evenly spaced samples (at least as dense as the
 * flattened path should be), each change of visibility located by bisection and ending one
 * run where the other begins.  A sample without a finite image breaks the run.  PC_OK or
 * PC_ENOMEM. */
int pc_occluder_split(const pc_occluder *o, const pc_map *screen, const pc_curve *c, int n,
                      pc_polyline *seen, pc_polyline *hidden);

#endif
