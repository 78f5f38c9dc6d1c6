/* Trigonometric interpolation of 2n equally spaced samples (stepanov_examples.md example 12). */
#include "fourier.h"
#include <math.h>

static const double PI = 3.14159265358979323846;

int pc_fourier_coef(int n, const double *f, int stride, double *a, double *b) {
    if (n < 1) return PC_EDOMAIN;
    for (int i = 0; i < 2 * n; i++)
        if (!isfinite(f[i * stride])) return PC_ENONFINITE;
    for (int k = 0; k <= n; k++) {
        double sa = 0, sb = 0;
        for (int i = 0; i < 2 * n; i++) {
            double w = PI * k * i / n;
            sa += f[i * stride] * cos(w);
            sb += f[i * stride] * sin(w);
        }
        a[k] = sa / n;
        b[k] = (k == 0 || k == n) ? 0.0 : sb / n;
    }
    return PC_OK;
}

double pc_fourier_eval(int n, const double *a, const double *b, double u) {
    double s = a[0] / 2 + a[n] * cos(n * u) / 2;
    for (int k = 1; k < n; k++) s += a[k] * cos(k * u) + b[k] * sin(k * u);
    return s;
}
