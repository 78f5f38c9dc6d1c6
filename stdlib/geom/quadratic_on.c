/* The slope of an implicit conic at its point (quadratic_on.h). */
#include <math.h>
#include "quadratic.h"
#include "quadratic_on.h"

int pc_conic_slope_on(const double q[6], double x, double y, double *slope, double *value) {
    double v = pc_conic_eq(q, x, y), g = hypot(2 * q[0] * x + q[1] * y + q[3], q[1] * x + 2 * q[2] * y + q[4]);
    *value = v;
    if (!(fabs(v) <= 1e-9 * fmax(g, 1) * fmax(1, hypot(x, y)))) return PC_EDOMAIN;
    return pc_conic_slope(q, x, y, slope);
}
