/* Graphical differentiation: the slope of a sampled curve (graphdiff.h). */
#include "graphdiff.h"
#include <math.h>

int pc_graphical_slope(int n, const double *xy, double x, int window, double *slope) {
    if (n < 3 || window < 3 || window > n) return PC_EDIM;
    if (!isfinite(x)) return PC_ENONFINITE;
    for (int i = 0; i < 2 * n; i++)
        if (!isfinite(xy[i])) return PC_ENONFINITE;
    for (int i = 1; i < n; i++)
        if (!(xy[2 * i] > xy[2 * i - 2])) return PC_EDOMAIN;
    if (x < xy[0] || x > xy[2 * n - 2]) return PC_EDOMAIN;
    /* the sample nearest to x, then the window around it, shifted inside at the ends */
    int lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (xy[2 * mid] <= x) lo = mid;
        else hi = mid;
    }
    int near = x - xy[2 * lo] <= xy[2 * hi] - x ? lo : hi;
    int first = near - window / 2;
    if (first < 0) first = 0;
    if (first + window > n) first = n - window;
    /* y = c0 + c1 (X - x) + c2 (X - x)^2 by the normal equations in scaled X (the window is
     * short, the system small and well conditioned after scaling by the window's width) */
    double h = fmax(fabs(xy[2 * first] - x), fabs(xy[2 * (first + window - 1)] - x));
    if (!(h > 0)) h = 1;
    double S[5] = {0}, R[3] = {0};
    for (int i = first; i < first + window; i++) {
        double t = (xy[2 * i] - x) / h, y = xy[2 * i + 1], p = 1;
        for (int k = 0; k < 5; k++) {
            S[k] += p;
            if (k < 3) R[k] += p * y;
            p *= t;
        }
    }
    /* solve [[S0 S1 S2] [S1 S2 S3] [S2 S3 S4]] c = R (Cramer: 3 x 3) */
    double A[3][3] = {{S[0], S[1], S[2]}, {S[1], S[2], S[3]}, {S[2], S[3], S[4]}};
    double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
                 A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                 A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
    if (!(fabs(det) > 1e-300)) return PC_ESINGULAR;
    /* c1: the middle column replaced by R */
    double d1 = A[0][0] * (R[1] * A[2][2] - A[1][2] * R[2]) - R[0] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                A[0][2] * (A[1][0] * R[2] - R[1] * A[2][0]);
    *slope = d1 / det / h;
    return isfinite(*slope) ? PC_OK : PC_ENONFINITE;
}
