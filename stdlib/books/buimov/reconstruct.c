/* Three-dimensional information from pictures (Buimov §2.8.6): see reconstruct.h. */
#include "reconstruct.h"
#include "linalg.h"
#include <math.h>
#include <stdlib.h>

int pc_reconstruct_point(int nviews, const pc_map *views, const double *xy, double *x,
                         double *resid) {
    if (nviews < 2) return PC_EDOMAIN;
    if (nviews > 64) return PC_ENOMEM;
    double a[2 * 64 * 3], b[2 * 64];
    for (int v = 0; v < nviews; v++) {
        const pc_map *f = &views[v];
        if (f->nin != 3 || f->nout != 2) return PC_EDIM;
        for (int r = 0; r < 2; r++) {         /* r = 0: the x* equation, 1: the y* equation */
            double s = xy[2 * v + r];
            if (!isfinite(s)) return PC_ENONFINITE;
            double *row = a + (2 * v + r) * 3;
            /* (T_j1 - T_j4 x*): the book's column 1 (or 2) and column 4 are rows r and 2 of M */
            for (int j = 0; j < 3; j++) row[j] = PC_MAP_AT(f, r, j) - s * PC_MAP_AT(f, 2, j);
            b[2 * v + r] = s * PC_MAP_AT(f, 2, 3) - PC_MAP_AT(f, r, 3);   /* T44 x* - T41 */
        }
    }
    int m = 2 * nviews;
    int st = pc_lsq_solve(m, 3, a, b);
    if (st != PC_OK) return st;
    for (int j = 0; j < 3; j++) x[j] = b[j];
    if (resid) {
        double r = 0;
        for (int i = 3; i < m; i++) r = hypot(r, b[i]);
        *resid = r;
    }
    return PC_OK;
}

int pc_calibrate_camera(int n, const double *xyz, const double *xy, pc_map *cam, double *rms) {
    if (n < 6) return PC_EDOMAIN;
    if (n > 100000) return PC_ENOMEM;
    for (int i = 0; i < 3 * n; i++) if (!isfinite(xyz[i])) return PC_ENONFINITE;
    for (int i = 0; i < 2 * n; i++) if (!isfinite(xy[i])) return PC_ENONFINITE;
    /* The unknowns: M's rows x~ (4), y~ (4) and h~ without its last entry (3), which is
     * T44 = 1.  Row for x*: x M00 + y M01 + z M02 + M03 - x*(x M20 + y M21 + z M22) = x*. */
    double *a = calloc((size_t)2 * n * 11, sizeof(double));
    double *b = malloc(sizeof(double) * (size_t)2 * n);
    if (!a || !b) {
        free(a); free(b);
        return PC_ENOMEM;
    }
    for (int i = 0; i < n; i++) {
        const double *p = xyz + 3 * i;
        for (int r = 0; r < 2; r++) {
            double s = xy[2 * i + r], *row = a + (size_t)(2 * i + r) * 11;
            for (int j = 0; j < 3; j++) {
                row[4 * r + j] = p[j];
                row[8 + j] = -s * p[j];
            }
            row[4 * r + 3] = 1;
            b[2 * i + r] = s;
        }
    }
    int st = pc_lsq_solve(2 * n, 11, a, b);
    free(a);
    if (st == PC_OK) {
        double m[12];
        for (int j = 0; j < 11; j++) m[j] = b[j];
        m[11] = 1;
        st = pc_map_from_matrix(cam, 3, 2, m, 0);
    }
    free(b);
    if (st != PC_OK) return st;
    if (rms) {
        double sum = 0;
        for (int i = 0; i < n; i++) {
            double in[4] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], 1}, out[3];
            pc_map_apply(cam, in, out);
            double dx = out[0] / out[2] - xy[2 * i], dy = out[1] / out[2] - xy[2 * i + 1];
            sum += dx * dx + dy * dy;
        }
        *rms = sqrt(sum / n);
        if (!isfinite(*rms)) *rms = INFINITY;       /* a point on the camera's vanishing plane */
    }
    return PC_OK;
}
