/* Smoothsteps and half-splines (stepanov_examples.md examples 3-8, 20-22). */
#include "smooth.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "names.h"

static const double PI = 3.14159265358979323846;

/* cos has period 2 in t: reduced first (fmod is exact), so a huge t gives its value, not
 * cos(inf) = NaN; t in (-2, 2) is unchanged. */
double pc_smooth_sine(double t) { return (1.0 - cos(PI * fmod(t, 2.0))) / 2.0; }

double pc_smooth_cubic(double t) { return t * t * (3.0 - 2.0 * t); }

double pc_smooth_power(double n, double t) {
    double c = pow(2.0, n - 1.0);
    if (t < 0.5) return c * pow(t, n);
    return 1.0 - c * pow(1.0 - t, n);
}

int pc_hspline_init(pc_hspline *h, double n, double m, double t0) {
    if (!isfinite(n) || !isfinite(m) || !isfinite(t0)) return PC_ENONFINITE;
    if (n <= 0 || m <= 0 || t0 <= 0 || t0 >= 1) return PC_EDOMAIN;
    double c1 = m / ((n - n * t0 + m * t0) * pow(t0, n - 1.0));
    double c2 = (1.0 - c1 * pow(t0, n)) / pow(1.0 - t0, m);
    if (!isfinite(c1) || !isfinite(c2)) return PC_EDOMAIN;   /* t0^(n-1) or (1-t0)^m underflowed */
    h->n = n;
    h->m = m;
    h->t0 = t0;
    h->c1 = c1;
    h->c2 = c2;
    return PC_OK;
}

double pc_hspline_eval(const pc_hspline *h, double t) {
    if (t < h->t0) return h->c1 * pow(t, h->n);
    return 1.0 - h->c2 * pow(1.0 - t, h->m);
}

double pc_hspline_deriv(const pc_hspline *h, double t) {
    if (t < h->t0) return h->n * h->c1 * pow(t, h->n - 1.0);
    return h->m * h->c2 * pow(1.0 - t, h->m - 1.0);
}

int pc_hspline_check(const pc_hspline *h, double t) {
    if (t < 0 && h->n != floor(h->n)) return PC_EDOMAIN;
    if (t > 1 && h->m != floor(h->m)) return PC_EDOMAIN;
    return PC_OK;
}

size_t pc_hspline_check_text(const pc_hspline *h, double t, char *buf, size_t size) {
    if (pc_hspline_check(h, t) == PC_OK) return 0;
    int low = t < 0;
    char d[40];
    pc_num_text(low ? h->n : h->m, d, sizeof d);
    int len = snprintf(buf, size, "must be %s (the degree %s = %s is fractional, so the formula does not extrapolate past %s)",
                       low ? "at least 0" : "at most 1", low ? "n" : "m", d, low ? "0" : "1");
    return len < 0 ? 0 : (size_t)len;
}

size_t pc_hspline_init_text(double n, double m, double t0, char *buf, size_t size) {
    char tn[40], tm[40], tt[40];
    int len = snprintf(buf, size, "the degrees n = %s, m = %s are too large for t0 = %s: the coefficients c1, c2 overflow a double",
                       pc_num_text(n, tn, sizeof tn), pc_num_text(m, tm, sizeof tm), pc_num_text(t0, tt, sizeof tt));
    return len < 0 ? 0 : (size_t)len;
}

double pc_hspline_locus(double n, double m, double t0) {
    return m * t0 / (n - n * t0 + m * t0);
}

double pc_smooth_clamp(double t) {
    if (t <= 0) return 0.0;
    if (t < 0.5) return 2.0 * t * t;
    if (t < 1) return 1.0 - 2.0 * (1.0 - t) * (1.0 - t);
    return 1.0;
}

double pc_smooth_clamp_qb(double t, double prev) {
    double s = prev;
    if (t < 0) s = 0.0;
    if (t > 0 && t < 0.5) s = 2.0 * t * t;
    if (t > 0.5 && t < 1) s = 1.0 - 2.0 * (1.0 - t) * (1.0 - t);
    if (t > 1) s = 1.0;
    return s;
}

double pc_gfun_eval(const pc_gfun *g, double t) {
    switch (g->kind) {
    case PC_G_HALF: return pc_hspline_eval(&g->h, t);
    case PC_G_CUBIC: return pc_smooth_cubic(t);
    case PC_G_SINE: return pc_smooth_sine(t);
    case PC_G_LINEAR: default: return t;
    }
}

int pc_gfun_check(const pc_gfun *g, double t) {
    return g->kind == PC_G_HALF ? pc_hspline_check(&g->h, t) : PC_OK;
}

int pc_hspline_field(const pc_hspline *h, const char *name, double *x) {
    static const char *const names[] = {"n", "m", "t0", "c1", "c2", "v", NULL};
    double values[] = {h->n, h->m, h->t0, h->c1, h->c2, pc_hspline_eval(h, h->t0)};
    for (int i = 0; names[i]; i++)
        if (strcmp(name, names[i]) == 0) {
            *x = values[i];
            return 1;
        }
    return 0;
}
