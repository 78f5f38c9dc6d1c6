/* Trigonometric interpolation of 2n equally spaced samples (stepanov_examples.md example 12). */
#include "fourier.h"
#include <math.h>
#include <stdlib.h>

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

double pc_fourier_deriv(int n, const double *a, const double *b, double u, int order) {
    if (order <= 0) return pc_fourier_eval(n, a, b, u);
    double s = 0;
    if (order == 1) {
        s = -a[n] * n * sin(n * u) / 2;
        for (int k = 1; k < n; k++) s += k * (b[k] * cos(k * u) - a[k] * sin(k * u));
    } else {
        s = -a[n] * (double)n * n * cos(n * u) / 2;
        for (int k = 1; k < n; k++) s -= (double)k * k * (a[k] * cos(k * u) + b[k] * sin(k * u));
    }
    return s;
}

/* --- as a curve of the core ------------------------------------------------------------------ */
typedef struct {
    int d, n;
    double coef[];    /* per coordinate: a[0..n], then b[0..n] */
} fourier_curve;

static int fourier_fn(void *ud, double u, int order, double *out) {
    const fourier_curve *f = ud;
    int m = f->n + 1, w = f->d + 1;
    for (int r = 0; r <= order; r++) {
        for (int k = 0; k < f->d; k++)
            out[r * w + k] = pc_fourier_deriv(f->n, f->coef + 2 * k * m, f->coef + (2 * k + 1) * m, u, r);
        out[r * w + f->d] = r == 0 ? 1 : 0;
    }
    return PC_OK;
}

pc_curve *pc_curve_fourier(int d, int n, const double *samples, int *status) {
    int st = PC_OK;
    if (d < 1 || d > PC_MAXDIM) st = PC_EDIM;
    else if (n < 1 || n > (1 << 20)) st = PC_EDOMAIN;
    else if (!samples) st = PC_EARG;
    fourier_curve *f = NULL;
    double *brk = NULL;
    if (!st) {
        f = malloc(sizeof *f + sizeof(double) * 2 * (size_t)(n + 1) * d);
        brk = malloc(sizeof(double) * 2 * (size_t)n);
        if (!f || !brk) st = PC_ENOMEM;
    }
    if (!st) {
        f->d = d;
        f->n = n;
        int m = n + 1;
        for (int k = 0; !st && k < d; k++)
            st = pc_fourier_coef(n, samples + k, d, f->coef + 2 * k * m, f->coef + (2 * k + 1) * m);
    }
    pc_curve *c = NULL;
    if (!st) {
        for (int i = 1; i < 2 * n; i++) brk[i - 1] = i * PI / n;
        c = pc_curve_func_breaks(d, 0, 2 * PI, 1, 2 * n - 1, brk, fourier_fn, free, f, &st);
    }
    if (!c) free(f);
    free(brk);
    if (status) *status = st;
    return c;
}

const double *pc_curve_fourier_coefs(const pc_curve *c, int *n) {
    int whole = c && c->kind == PC_CURVE_FUNC && c->func->eval == fourier_fn && c->t0 == 0 &&
                c->t1 == 2 * PI;
    const fourier_curve *f = whole ? c->func->ud : NULL;
    if (n) *n = f ? f->n : 0;
    return f ? f->coef : NULL;
}
