/* Deterministic quasi-Newton minimisation (optimize.h): BFGS with an Armijo line search and
 * central-difference gradients; the elastic reference curve of Korotky's articles uses it. */
#include "optimize.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double maxabs(int n, const double *v) {
    double m = 0;
    for (int i = 0; i < n; i++) m = fmax(m, fabs(v[i]));
    return m;
}


static int gradient(pc_objective_fn f, void *ud, int n, double *x, double h, double *g) {
    for (int i = 0; i < n; i++) {
        double xi = x[i], e = h * fmax(1, fabs(xi));
        x[i] = xi + e;
        double fp = f(ud, x);
        x[i] = xi - e;
        double fm = f(ud, x);
        x[i] = xi;
        g[i] = (fp - fm) / (2 * e);
        if (!isfinite(g[i])) return PC_ENONFINITE;
    }
    return PC_OK;
}

int pc_minimize(int n, pc_objective_fn f, void *ud, double *x, double gtol, double h, int maxit,
                double *fx, int *iters) {
    if (iters) *iters = 0;
    if (n < 1 || n > PC_NEWTON_MAXN) return PC_EDIM;
    if (!(h > 0)) h = 1e-6;
    double H[PC_NEWTON_MAXN * PC_NEWTON_MAXN], g[PC_NEWTON_MAXN], gn[PC_NEWTON_MAXN];
    double d[PC_NEWTON_MAXN], xn[PC_NEWTON_MAXN], s[PC_NEWTON_MAXN], y[PC_NEWTON_MAXN];
    double Hy[PC_NEWTON_MAXN];
    double f0 = f(ud, x);
    if (!isfinite(f0)) return PC_ENONFINITE;
    if (gradient(f, ud, n, x, h, g) != PC_OK) return PC_ENONFINITE;
    for (int i = 0; i < n * n; i++) H[i] = (i % (n + 1)) == 0;
    int st = PC_ENOCONVERGE, stall = 0;
    for (int it = 1; it <= maxit; it++) {
        if (iters) *iters = it;
        if (maxabs(n, g) < gtol) { st = PC_OK; break; }
        double gd = 0;
        for (int i = 0; i < n; i++) {
            d[i] = 0;
            for (int j = 0; j < n; j++) d[i] -= H[i * n + j] * g[j];
            gd += g[i] * d[i];
        }
        if (!(gd < 0)) {   /* not a descent direction: restart from the gradient */
            for (int i = 0; i < n * n; i++) H[i] = (i % (n + 1)) == 0;
            gd = 0;
            for (int i = 0; i < n; i++) { d[i] = -g[i]; gd -= g[i] * g[i]; }
        }
        double a = 1, fnew = f0;
        int found = 0;
        for (int k = 0; k < 60; k++, a *= .5) {
            for (int i = 0; i < n; i++) xn[i] = x[i] + a * d[i];
            fnew = f(ud, xn);
            if (isfinite(fnew) && fnew <= f0 + 1e-4 * a * gd) { found = 1; break; }
        }
        if (!found || !(fnew < f0)) { st = PC_OK; break; }   /* no further decrease possible */
        /* decreases at the rounding level of f for several steps: the minimum as the
         * differences see it */
        stall = f0 - fnew <= 1e-15 * fabs(f0) ? stall + 1 : 0;
        if (stall >= 8) { f0 = fnew; memcpy(x, xn, sizeof(double) * (size_t)n); st = PC_OK; break; }
        if (gradient(f, ud, n, xn, h, gn) != PC_OK) return PC_ENONFINITE;
        double sy = 0, yHy = 0;
        for (int i = 0; i < n; i++) { s[i] = xn[i] - x[i]; y[i] = gn[i] - g[i]; sy += s[i] * y[i]; }
        if (sy > 1e-14) {
            for (int i = 0; i < n; i++) {
                Hy[i] = 0;
                for (int j = 0; j < n; j++) Hy[i] += H[i * n + j] * y[j];
                yHy += y[i] * Hy[i];
            }
            for (int i = 0; i < n; i++)
                for (int j = 0; j < n; j++)
                    H[i * n + j] += (sy + yHy) * s[i] * s[j] / (sy * sy) -
                                    (Hy[i] * s[j] + s[i] * Hy[j]) / sy;
        }
        memcpy(x, xn, sizeof(double) * (size_t)n);
        memcpy(g, gn, sizeof(double) * (size_t)n);
        f0 = fnew;
    }
    if (fx) *fx = f0;
    return st;
}
