/* Three-dimensional information from pictures (Buimov §2.8.6): a point of space from its images
 * in two (or more) known views, and the projection matrix of a camera from six (or more)
 * points of space and their images.  A view is a 3-D -> 2-D map (map.h): in the book's
 * row-vector form the 4 x 4 matrix T with its third column zero, here the 3 x 4 matrix M = T^T
 * without that column (rows: x~, y~ and the weight h~). */
#ifndef PC_RECONSTRUCT_H
#define PC_RECONSTRUCT_H
#include "map.h"

/* The point x (3 doubles) whose images under views[i] are nearest to xy[2i], xy[2i+1] in the
 * book's sense: each view gives the two equations (3.8.6.3)
 *   (T11 - T14 x*) x + (T21 - T24 x*) y + (T31 - T34 x*) z + (T41 - T44 x*) = 0   (and y*),
 * solved together by least squares (the book solves them "approximately"; 4 equations in 3
 * unknowns for two views).  *resid (may be NULL): the residual of those equations.
 * PC_EDIM unless every view maps 3-D to 2-D, PC_EDOMAIN for fewer than 2 views,
 * PC_ENONFINITE for NaN/inf, PC_ESINGULAR when the views do not fix a point (the same view
 * twice, or lines of sight that are parallel). */
int pc_reconstruct_point(int nviews, const pc_map *views, const double *xy, double *x,
                         double *resid);

/* The camera (a 3-D -> 2-D map) sending the n >= 6 points xyz (rows of 3) to their images xy
 * (rows of 2), from the book's homogeneous system A' T = 0 (each point gives the rows
 * [x, 0, -x x*, y, 0, -y x*, z, 0, -z x*, 1, 0, -x*] and the same for y*; the book prints
 * +x*, +y* at the ends, corrected here) normalised by T44 = 1 (as Rogers & Adams do; the book
 * does not say) and solved by least squares for the other 11 entries.  *rms (may be NULL):
 * the root mean square distance of the points' images under the result from xy.
 * PC_EDOMAIN for n < 6, PC_ENONFINITE, PC_ESINGULAR when the points do not fix a camera
 * (coplanar points, or a camera whose T44 is 0: the origin on its vanishing plane). */
int pc_calibrate_camera(int n, const double *xyz, const double *xy, pc_map *cam, double *rms);

#endif
