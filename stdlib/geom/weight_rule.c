/* The one weight rule of every location (point.h, PC_WEIGHT_TOL), applied to a computed value:
 * a weight within 1e-9 of 1 is a point (snapped to exactly 1, the coordinates divided by it),
 * within 1e-9 of 0 a direction (snapped to 0). */
#include "point.h"

int pc_snap_weight(int n, double *h) {
    pc_kind k = pc_kind_of(h[n]);
    if (k == PC_KIND_VECTOR) {
        h[n] = 0;
    } else if (k == PC_KIND_POINT && h[n] != 1) {
        for (int i = 0; i < n; i++) h[i] /= h[n];
        h[n] = 1;
    }
    return (int)k;
}
