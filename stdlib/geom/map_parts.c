/* Parts of a map the bindings show (map.h): the images of the unit points and of the axis
 * directions, and what the failures of the constructors by points and by an eye mean. */
#include <string.h>
#include "map.h"

int pc_map_unit_image(const pc_map *f, int i, double *out) {
    if (i < 0 || i > f->nin) return PC_EDOMAIN;
    double in[PC_MAXDIM + 1] = {0};
    in[f->nin] = 1;
    if (i > 0) in[i - 1] = 1;
    return pc_map_image(f, in, out);
}

int pc_map_vanishing_points(const pc_map *f, double out[3][PC_MAXDIM + 1], int finite[3]) {
    if (f->nin != 3 || f->nout < 2 || f->nout > 3) return PC_EDIM;
    for (int i = 0; i < 3; i++) {
        double in[4] = {0, 0, 0, 0};
        in[i] = 1;
        finite[i] = pc_map_image(f, in, out[i]) == PC_OK && out[i][f->nout] != 0;
    }
    return PC_OK;
}

const char *pc_map_points_why(int st, int nin) {
    if (st != PC_ECOINCIDENT && st != PC_ECOLLINEAR) return pc_strerror(st);
    return nin == 1   ? "the source points coincide, so they do not fix an affine map"
           : nin == 2 ? "the source points are collinear, so they do not fix an affine map"
           : nin == 3 ? "the source points are coplanar, so they do not fix an affine map"
                      : "the source points are dependent, so they do not fix an affine map";
}

const char *pc_map_perspective_why(int st, int up_given) {
    switch (st) {
    case PC_ECOINCIDENT: return "the eye and p0 coincide, so there is no direction of view";
    case PC_EZERO: return "argument #3 (up) is the zero vector";
    case PC_ECOLLINEAR:
        return up_given ? "argument #3 (up) is along the line of sight, so it gives no upward direction in the "
                          "picture; give another up"
                        : "the default up, the z axis, is along the line of sight, so it gives no upward "
                          "direction in the picture; give another up";
    default: return pc_strerror(st);
    }
}
