/* A curve of the core drawn as one path on a canvas (c:draw, plot, the lines of surfaces and
 * of the curvilinear systems): the map to screen pixels (a projection, then WINDOW and VIEW,
 * the one conversion from world to device coordinates), the adaptive flattening through it
 * and the stroking of the polyline. */
#ifndef PC_CURVE_PATH_H
#define PC_CURVE_PATH_H

#include "canvas.h"
#include "curve.h"
#include "scene.h"
#include "why_call.h"

/* The image (x, y) under f (to the plane) of the homogeneous n-D value h: PC_OK, PC_EDIM when f
 * takes points of another dimension (or is NULL), PC_IMPROPER where h goes to infinity,
 * PC_ENONFINITE. */
int pc_map_image_xy(const pc_map *f, int n, const double *h, double *x, double *y);
/* The place on the plane of a drawn point h (homogeneous, weight 1): a 2-D one as it is, an
 * n-D one its image under the camera f as pc_map_image_xy gives it. */
int pc_place_xy(const pc_map *f, int n, const double *h, double *x, double *y);
/* The same for a point h of a list drawn (path, fill), a 2-D one of weight 1 only: PC_OK, or
 * pc_map_image_xy's status (PC_EARG for a 2-D value of another weight) with why the words
 * that follow the element's position ("[2]"), the point's text in place of their one %s:
 * ": %s has weight 2, not 1: ...", " must be a 2-D point, got the 3-D %s (...)". */
int pc_place_why(const pc_map *f, int n, const double *h, double *xy, char *why, size_t len);
/* The places (pc_place_xy) of n points given as rows of dim coordinates (weight 1) into xy,
 * 2 n numbers: -1, or the index of the first point that has none (then xy is partly set). */
long pc_place_rows(const pc_map *f, size_t n, int dim, const double *rows, double *xy);
/* The map to screen pixels: f (to the plane; NULL for plain 2-D points) then WINDOW and VIEW. */
void pc_screen_map(const pc_canvas *cv, const pc_map *f, pc_map *out);
/* Append to out c over [a, b] flattened through f (NULL: c is 2-D as it is) to within tol,
 * starting from `pieces` equal parts (at least 1) that join without a break.  PC_EDIM for a
 * curve that is not 2-D without f, else pc_curve_flatten_map's status. */
int pc_curve_flatten_parts(const pc_curve *c, double a, double b, int pieces, const pc_map *f,
                           double tol, pc_polyline *out);
/* c:flatten: c over its domain flattened through f as pc_curve_flatten_parts, for the call op,
 * the map's dimensions explained in why (why_call.h): f must take c's points to the plane
 * (argument 2), a curve that is not 2-D needs one; another failure leaves why empty.  out is
 * freed on a failure. */
int pc_curve_flatten_checked(const char *op, const pc_curve *c, const pc_map *f, double tol, pc_polyline *out,
                             pc_why_call *why);
/* c over its domain flattened through f and the screen map of cv to within tol pixels into
 * out (screen coordinates), leaving out what lies beyond the canvas and a margin as wide as
 * it (a wide pen, a dash pattern leaving and coming back keep their look). */
int pc_curve_flatten_screen(const pc_canvas *cv, const pc_curve *c, const pc_map *f, int pieces,
                            double tol, pc_polyline *out);
/* Does pl break anywhere (a vertex after the first starting a new piece)? */
int pc_polyline_broken(const pc_polyline *pl);
/* Stroke the screen-space polyline pl as one path (its vertices go to the canvas as they are),
 * each piece closed when closed is set: pc_path_screen's status, or PC_ENOMEM (the message in
 * cv->error either way). */
int pc_polyline_stroke(pc_canvas *cv, const pc_polyline *pl, int color, int closed);
/* Draw c as one path: flattened through f and the screen map of cv to within tol pixels from
 * `pieces` equal parts, then into the scene sc when one is given (a hidden-line camera's,
 * sampled as densely as the flattened path, with the pen) or stroked onto cv, closed when c is
 * or `closed` is set.  PC_OK, or the status, with why set when there is more to say than it (a
 * curve needing more vertices than a polyline holds at tol; the canvas's message). */
int pc_curve_draw(pc_canvas *cv, pc_scene *sc, int pen, const pc_curve *c, const pc_map *f, int pieces,
                  double tol, int color, int closed, char *why, size_t size);
/* The projection for drawing a dim-D object: the map given (given set; f NULL when the argument
 * is no map), which must take dim-D points to the plane, else the camera, which a 2-D object
 * uses only when it takes 2-D points.  NULL with why set when there is none to use (why empty:
 * a 2-D object drawn as it is). */
const pc_map *pc_drawing_map(const pc_map *f, int given, const pc_map *camera, int dim, char *why, size_t size);

#endif
