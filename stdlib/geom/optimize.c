/* Nelder-Mead (optimize.h). */
#include <math.h>
#include <string.h>
#include "optimize.h"
#include "status.h"

#define NM_MAX 32

static double safe(double v) { return isfinite(v) ? v : INFINITY; }

int pc_nelder_mead(int n, pc_objective_fn f, void *ud, double *x, double step, double ftol,
                   double xtol, int maxiter, double *fx, int *iters) {
    if (n < 1 || n > NM_MAX) return PC_EDIM;
    double p[NM_MAX + 1][NM_MAX], v[NM_MAX + 1], cen[NM_MAX], xr[NM_MAX], xe[NM_MAX];
    int it = 0, st = PC_ENOCONVERGE;
    for (int i = 0; i <= n; i++) {
        memcpy(p[i], x, sizeof(double) * (size_t)n);
        if (i > 0) p[i][i - 1] += step;
        v[i] = f(ud, p[i]);
        if (i == 0 && !isfinite(v[0])) return PC_ENONFINITE;
        v[i] = safe(v[i]);
    }
    for (; it < maxiter; it++) {
        /* insertion sort by value: stable, so ties keep their order */
        for (int i = 1; i <= n; i++)
            for (int j = i; j > 0 && v[j] < v[j - 1]; j--) {
                double tv = v[j]; v[j] = v[j - 1]; v[j - 1] = tv;
                double tp[NM_MAX];
                memcpy(tp, p[j], sizeof(double) * (size_t)n);
                memcpy(p[j], p[j - 1], sizeof(double) * (size_t)n);
                memcpy(p[j - 1], tp, sizeof(double) * (size_t)n);
            }
        double size = 0;
        for (int i = 1; i <= n; i++)
            for (int k = 0; k < n; k++) size = fmax(size, fabs(p[i][k] - p[0][k]));
        if (v[n] - v[0] <= ftol * (fabs(v[0]) + 1e-300) && size <= xtol) {
            st = PC_OK;
            break;
        }
        for (int k = 0; k < n; k++) {
            double s = 0;
            for (int i = 0; i < n; i++) s += p[i][k];
            cen[k] = s / n;
        }
        for (int k = 0; k < n; k++) xr[k] = 2 * cen[k] - p[n][k];
        double fr = safe(f(ud, xr));
        if (fr < v[0]) {
            for (int k = 0; k < n; k++) xe[k] = 3 * cen[k] - 2 * p[n][k];
            double fe = safe(f(ud, xe));
            if (fe < fr) memcpy(p[n], xe, sizeof(double) * (size_t)n), v[n] = fe;
            else memcpy(p[n], xr, sizeof(double) * (size_t)n), v[n] = fr;
        } else if (fr < v[n - 1]) {
            memcpy(p[n], xr, sizeof(double) * (size_t)n), v[n] = fr;
        } else {
            for (int k = 0; k < n; k++) xe[k] = cen[k] + 0.5 * (p[n][k] - cen[k]);
            double fc = safe(f(ud, xe));
            if (fc < v[n]) {
                memcpy(p[n], xe, sizeof(double) * (size_t)n), v[n] = fc;
            } else {
                for (int i = 1; i <= n; i++) {
                    for (int k = 0; k < n; k++) p[i][k] = p[0][k] + 0.5 * (p[i][k] - p[0][k]);
                    v[i] = safe(f(ud, p[i]));
                }
            }
        }
    }
    int best = 0;
    for (int i = 1; i <= n; i++)
        if (v[i] < v[best]) best = i;
    memcpy(x, p[best], sizeof(double) * (size_t)n);
    *fx = v[best];
    if (iters) *iters = it;
    return st;
}
