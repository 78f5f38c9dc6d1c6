/* The slope of an implicit conic at a point that must lie on it (plane.conic_slope). */
#ifndef PC_QUADRATIC_ON_H
#define PC_QUADRATIC_ON_H

/* pc_conic_slope at (x, y) once the point is found on the conic: PC_EDOMAIN when the equation's
 * value there (*value) exceeds 1e-9 of the gradient's size and of the point's (a point off the
 * curve); else the statuses of pc_conic_slope (PC_EPOLE: a vertical tangent). */
int pc_conic_slope_on(const double coef[6], double x, double y, double *slope, double *value);

#endif
