/* More constructors and measures of the one map type (map.h): the textbook's perspective by
 * (p, q, r), the foreshortening factors of an axonometry, the axial affinity of the plane. */
#include "map.h"
#include <math.h>
#include <string.h>

int pc_map_perspective_pqr(pc_map *f, double p, double q, double r) {
    if (!isfinite(p) || !isfinite(q) || !isfinite(r)) return PC_ENONFINITE;
    /* Buimov §2.8.5: [x y z 1] [[1,0,0,p],[0,1,0,q],[0,0,1,r],[0,0,0,1]] = [x y z h],
     * h = px + qy + rz + 1: the last row of the column-vector matrix is (p q r | 1) */
    pc_map_identity(f, 3);
    PC_MAP_AT(f, 3, 0) = p;
    PC_MAP_AT(f, 3, 1) = q;
    PC_MAP_AT(f, 3, 2) = r;
    return PC_OK;
}

int pc_map_foreshortening(const pc_map *f, double *factors) {
    if (!pc_map_is_affine(f)) return PC_EDOMAIN;      /* a perspective has no constant factor */
    /* the image of the unit vector e_i is column i of M (an affine map sends vectors to the
     * linear part's columns) */
    for (int i = 0; i < f->nin; i++) {
        double s = 0;
        for (int k = 0; k < f->nout; k++) s += PC_MAP_AT(f, k, i) * PC_MAP_AT(f, k, i);
        factors[i] = sqrt(s);
    }
    return PC_OK;
}

int pc_map_axial_affinity(pc_map *f, const double a[2], const double d[2], const double s[2],
                          double k) {
    if (!isfinite(a[0]) || !isfinite(a[1]) || !isfinite(d[0]) || !isfinite(d[1]) ||
        !isfinite(s[0]) || !isfinite(s[1]) || !isfinite(k))
        return PC_ENONFINITE;
    double det = d[0] * s[1] - d[1] * s[0], nd = hypot(d[0], d[1]), ns = hypot(s[0], s[1]);
    if (!(nd > 0) || !(ns > 0)) return PC_EZERO;
    if (!(fabs(det) > PC_DEGEN_TOL * nd * ns)) return PC_ECOLLINEAR;   /* s along the axis */
    /* M - A = alpha d + beta s goes to alpha d + k beta s: L = [d s] diag(1, k) [d s]^-1 */
    double inv[4] = {s[1] / det, -s[0] / det, -d[1] / det, d[0] / det};   /* rows: alpha, beta */
    double L[4];
    for (int r = 0; r < 2; r++)
        for (int c = 0; c < 2; c++) L[2 * r + c] = d[r] * inv[c] + k * s[r] * inv[2 + c];
    pc_map_identity(f, 2);
    PC_MAP_AT(f, 0, 0) = L[0], PC_MAP_AT(f, 0, 1) = L[1];
    PC_MAP_AT(f, 1, 0) = L[2], PC_MAP_AT(f, 1, 1) = L[3];
    /* the axis is fixed: M' = A + L (M - A) */
    PC_MAP_AT(f, 0, 2) = a[0] - L[0] * a[0] - L[1] * a[1];
    PC_MAP_AT(f, 1, 2) = a[1] - L[2] * a[0] - L[3] * a[1];
    return PC_OK;
}
