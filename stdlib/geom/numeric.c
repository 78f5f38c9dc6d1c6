/* Oresme lambda-functions and bisection (stepanov_examples.md examples 30, 31). */
#include "numeric.h"
#include <math.h>

int pc_oresme_fill(double lambda, int m, double y0, double y1, double *y) {
    if (m < 0 || m > PC_ORESME_MAXLEVEL) return PC_EDOMAIN;
    if (!isfinite(lambda) || !isfinite(y0) || !isfinite(y1)) return PC_ENONFINITE;
    long n = 1L << m;
    y[0] = y0;
    y[n] = y1;
    for (int i = 0; i < m; i++) {
        long s = n >> i;
        for (long j = 0; j <= n - s; j += s) y[j + s / 2] = lambda * y[j] + (1 - lambda) * y[j + s];
    }
    return PC_OK;
}

double pc_oresme_at(const double *y, int m, double t) {
    long n = 1L << m;
    double i = floor(t * (double)n);
    if (!(i > 0)) return y[0];   /* also NaN */
    if (i > (double)n) return y[n];
    return y[(long)i];
}

int pc_bisect(pc_scalar_fn f, void *ud, double a, double b, double tol, double *x, int *iters) {
    int count = 0;
    if (iters) *iters = 0;
    /* a NaN end never compares equal to the midpoint, so the loop below would not end */
    if (!isfinite(a) || !isfinite(b)) return PC_ENONFINITE;
    double fa = f(a, ud);
    if (!isfinite(fa)) return PC_ENONFINITE;
    if (fa == 0) {
        *x = a;
        return PC_OK;
    }
    double fb = f(b, ud);
    if (!isfinite(fb)) return PC_ENONFINITE;
    if (fb == 0) {
        *x = b;
        return PC_OK;
    }
    if ((fa < 0) == (fb < 0)) return PC_ENOBRACKET;
    double x0 = a, x1 = b, f0 = fa, mid;
    for (;;) {
        mid = (x0 + x1) / 2;
        if (count > 0 && (mid == x0 || mid == x1)) break;   /* the interval stopped shrinking */
        double fm = f(mid, ud);
        count++;
        if (!isfinite(fm)) {
            if (iters) *iters = count;
            return PC_ENONFINITE;
        }
        if (fm == 0) break;                                   /* an exact root */
        if ((fm < 0) != (f0 < 0)) {
            x1 = mid;
        } else {
            x0 = mid;
            f0 = fm;
        }
        if (fabs(x1 - x0) <= tol) break;
    }
    *x = mid;
    if (iters) *iters = count;
    return PC_OK;
}
