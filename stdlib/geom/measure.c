/* Areas and volumes: signed in their own dimension (2-D area, 3-D volume), unsigned in any
 * dimension by orthogonalising the edges (equivalent to the Gram determinant of §4.10:
 * 2S = sqrt(Σ^A_BB Σ^A_CC - (Σ^A_BC)^2)). */
#include "point.h"
#include "linalg.h"
#include <math.h>

double pc_area2(const double *a, const double *b, const double *c) {
    /* S = ½ det[[xA, yA, 1], [xB, yB, 1], [xC, yC, 1]] (S-theorem, coordinate form) */
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
}

double pc_polygon_area2(int m, const double *p) {
    /* shoelace, relative to the first vertex for accuracy */
    double s = 0;
    for (int i = 1; i + 1 < m; i++) s += pc_area2(p, p + 2 * i, p + 2 * (i + 1));
    return s;
}

double pc_volume3(const double *a, const double *b, const double *c, const double *d) {
    double u[3], v[3], w[3], x[3];
    for (int i = 0; i < 3; i++) { u[i] = b[i] - a[i]; v[i] = c[i] - a[i]; w[i] = d[i] - a[i]; }
    pc_cross3(v, w, x);
    return pc_dot(3, u, x) / 6.0;
}

double pc_measure(int n, int k, const double *v) {
    if (k == 0) return 1.0;
    if (k < 0 || k > n || n > PC_MAXDIM) return 0.0;
    double e[PC_MAXDIM * PC_MAXDIM] = {0}, q[PC_MAXDIM * PC_MAXDIM], r[PC_MAXDIM * PC_MAXDIM];
    for (int i = 0; i < k; i++)
        for (int j = 0; j < n; j++) e[i * n + j] = v[(i + 1) * n + j] - v[j];
    if (pc_qr(n, k, e, q, r, 0.0) != PC_OK) return 0.0;
    double m = 1;
    for (int i = 0; i < k; i++) m *= r[i * k + i] / (i + 1);     /* Π r_ii / k! */
    return m;
}

double pc_area(int n, const double *a, const double *b, const double *c) {
    double v[3 * PC_MAXDIM];
    for (int j = 0; j < n; j++) { v[j] = a[j]; v[n + j] = b[j]; v[2 * n + j] = c[j]; }
    return pc_measure(n, 2, v);
}
