/* Values (weighted points), their arithmetic and the metric of §1.4. */
#include "point.h"
#include <math.h>

pc_kind pc_kind_of(double w) {
    if (fabs(w - 1.0) <= PC_WEIGHT_TOL) return PC_KIND_POINT;
    if (fabs(w) <= PC_WEIGHT_TOL) return PC_KIND_VECTOR;
    return PC_KIND_WEIGHTED;
}

int pc_loc(int n, const double *h, double *out) {
    double w = h[n];
    switch (pc_kind_of(w)) {
    case PC_KIND_POINT:
        if (w == 1.0) for (int i = 0; i < n; i++) out[i] = h[i];
        else for (int i = 0; i < n; i++) out[i] = h[i] / w;
        return PC_OK;
    case PC_KIND_VECTOR: return PC_IMPROPER;
    default: return PC_EWEIGHT;
    }
}

int pc_normalize(int n, const double *h, double *out) {
    double w = h[n];
    if (pc_kind_of(w) == PC_KIND_VECTOR) return PC_IMPROPER;
    for (int i = 0; i < n; i++) out[i] = h[i] / w;
    out[n] = 1.0;
    return PC_OK;
}

void pc_add(int n, const double *a, const double *b, double *out) {
    for (int i = 0; i <= n; i++) out[i] = a[i] + b[i];
}

void pc_sub(int n, const double *a, const double *b, double *out) {
    for (int i = 0; i <= n; i++) out[i] = a[i] - b[i];
}

void pc_scale(int n, const double *a, double k, double *out) {
    for (int i = 0; i <= n; i++) out[i] = a[i] * k;
}

int pc_value_same(int n, const double *a, int m, const double *b) {
    int same = n == m;
    for (int i = 0; same && i <= n; i++) same = a[i] == b[i];
    return same;
}

int pc_lerp(int n, const double *a, const double *b, double t, double *out) {
    double s = 1.0 - t;                       /* t̄, the complement of the parameter */
    for (int i = 0; i < n; i++) out[i] = a[i] * s + b[i] * t;
    /* equal weights stay exact: w t̄ + w t = w, but rounded at t = 1e16 it is 0 and two
     * points would give a vector */
    out[n] = a[n] == b[n] ? a[n] : a[n] * s + b[n] * t;
    for (int i = 0; i <= n; i++)
        if (!isfinite(out[i])) return PC_ENONFINITE;
    return PC_OK;
}

double pc_dot(int n, const double *u, const double *v) {
    double s = 0;
    for (int i = 0; i < n; i++) s += u[i] * v[i];
    return s;
}

double pc_norm(int n, const double *u) {
    /* scaled to avoid overflow/underflow of the squares */
    double m = 0;
    for (int i = 0; i < n; i++) m = fmax(m, fabs(u[i]));
    if (m == 0 || !isfinite(m)) return m;
    double s = 0;
    for (int i = 0; i < n; i++) { double x = u[i] / m; s += x * x; }
    return m * sqrt(s);
}

double pc_dist(int n, const double *a, const double *b) {
    double d[PC_MAXDIM];
    for (int i = 0; i < n; i++) d[i] = b[i] - a[i];
    return pc_norm(n, d);
}

double pc_sigma(int n, const double *a, const double *b, const double *c) {
    double s = 0;                             /* Σ (B - A)(C - A), summed over the axes */
    for (int i = 0; i < n; i++) s += (b[i] - a[i]) * (c[i] - a[i]);
    return s;
}

int pc_unit(int n, const double *u, double *out) {
    double len = pc_norm(n, u);
    if (len == 0) return PC_EZERO;
    for (int i = 0; i < n; i++) out[i] = u[i] / len;
    return PC_OK;
}

void pc_perp2(const double *u, double *out) {
    double x = u[0], y = u[1];
    out[0] = -y;
    out[1] = x;
}

double pc_cross2(const double *u, const double *v) { return u[0] * v[1] - u[1] * v[0]; }

void pc_cross3(const double *u, const double *v, double *out) {
    double x = u[1] * v[2] - u[2] * v[1];
    double y = u[2] * v[0] - u[0] * v[2];
    double z = u[0] * v[1] - u[1] * v[0];
    out[0] = x; out[1] = y; out[2] = z;
}

int pc_angle(int n, const double *u, const double *v, double *out) {
    double lu = pc_norm(n, u), lv = pc_norm(n, v);
    if (lu == 0 || lv == 0) return PC_EZERO;
    /* |u^v| by the component of v orthogonal to u (accurate for small angles) */
    double uu[PC_MAXDIM], r[PC_MAXDIM];
    for (int i = 0; i < n; i++) uu[i] = u[i] / lu;
    double c = pc_dot(n, uu, v);
    for (int i = 0; i < n; i++) r[i] = v[i] - c * uu[i];
    *out = atan2(pc_norm(n, r), c);
    return PC_OK;
}

int pc_foot(int n, const double *c, const double *a, const double *b, double *out) {
    double len = pc_dist(n, a, b);
    if (len == 0) return PC_ECOINCIDENT;
    /* t = Σ^A_BC / Σ^A_BB, computed as ((C - A)·û)/|AB| with the unit û = (B - A)/|AB| so
     * that neither sum of squares overflows or underflows for very large or small figures */
    double t = 0;
    for (int i = 0; i < n; i++) t += (c[i] - a[i]) * ((b[i] - a[i]) / len);
    t /= len;
    for (int i = 0; i < n; i++) out[i] = a[i] + (b[i] - a[i]) * t;
    return PC_OK;
}
