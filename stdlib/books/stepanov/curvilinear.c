/* Coordinate maps of the curvilinear-coordinates toolkit (stepanov_examples.md examples 2, 15,
 * 23-28, 32-34). */
#include "curvilinear.h"
#include <math.h>

static const double PI = 3.14159265358979323846;

void pc_bilinear(int d, const double *p0, const double *p1, const double *p2, const double *p3,
                 double t1, double t2, double *out) {
    for (int i = 0; i < d; i++)
        out[i] = p0[i] + t1 * (p1[i] - p0[i]) + t2 * (p3[i] - p0[i]) +
                 t1 * t2 * (p2[i] - p3[i] - p1[i] + p0[i]);
}

void pc_frame_point(const double o[2], const double e[2], double xi, double eta, double out[2]) {
    out[0] = o[0] + xi * e[0] + eta * e[1];
    out[1] = o[1] + xi * e[1] - eta * e[0];
}

int pc_frame_coords(const double o[2], const double e[2], const double x[2], double *xi,
                    double *eta) {
    double l = e[0] * e[0] + e[1] * e[1];
    if (!isfinite(l)) return PC_ENONFINITE;
    if (l == 0) return PC_EZERO;
    double dx = x[0] - o[0], dy = x[1] - o[1];
    *xi = (dx * e[0] + dy * e[1]) / l;
    *eta = (dx * e[1] - dy * e[0]) / l;
    return PC_OK;
}

void pc_patch_blend(const double u0[2], const double u2[2], double xi1, double eta1, double xi3,
                    double eta3, double t1, double out[2]) {
    double xi = xi3 + t1 * (xi1 - xi3), eta = eta3 + t1 * (eta1 - eta3);
    double e[2] = {u2[0] - u0[0], u2[1] - u0[1]};
    pc_frame_point(u0, e, xi, eta, out);
}

double pc_squash(double p) {
    if (isinf(p)) return p > 0 ? 1.0 : -1.0;
    return p / sqrt(p * p + 1.0);
}

double pc_squash01(double p) { return 0.5 * pc_squash(p) + 0.5; }

void pc_oblique_axes(const double c0[2], double r, double k, double u, double c[8]) {
    c[0] = c0[0];
    c[1] = c0[1];
    c[2] = c0[0] + r * cos(u);
    c[3] = c0[1] - r * k * sin(u);
    c[4] = c0[0] + r * cos(u + PI / 2);
    c[5] = c0[1] - r * k * sin(u + PI / 2);
    c[6] = c0[0];
    c[7] = c0[1] - r;
}

void pc_project4(const double c[8], double x, double y, double z, double out[2]) {
    out[0] = c[0] + x * (c[2] - c[0]) + y * (c[4] - c[0]) + z * (c[6] - c[0]);
    out[1] = c[1] + x * (c[3] - c[1]) + y * (c[5] - c[1]) + z * (c[7] - c[1]);
}

int pc_map_project4(pc_map *f, const double c[8]) {
    double axes[6];
    for (int i = 0; i < 3; i++)
        for (int d = 0; d < 2; d++) axes[2 * i + d] = c[2 * (i + 1) + d] - c[d];
    return pc_map_frame(f, 2, 3, c, axes);
}

int pc_mobius(double z0re, double z0im, double phi, double re, double im, double *wre,
              double *wim) {
    /* the listing's arithmetic: (p1 + i q1) / (p2 + i q2) with
     * p1 + i q1 = z - z0, p2 + i q2 = 1 - conj(z0) z */
    double p1 = re - z0re, q1 = im - z0im;
    double p2 = 1.0 - re * z0re - im * z0im, q2 = z0im * re - z0re * im;
    double den = p2 * p2 + q2 * q2;
    if (den == 0) return PC_EPOLE;
    double p3 = (p1 * p2 + q1 * q2) / den, q3 = (p2 * q1 - p1 * q2) / den;
    double c = cos(phi), s = sin(phi);
    *wre = p3 * c - q3 * s;
    *wim = p3 * s + q3 * c;
    if (!isfinite(*wre) || !isfinite(*wim)) return PC_ENONFINITE;
    return PC_OK;
}

void pc_mobius_inverse(double z0re, double z0im, double phi, double *z0re_inv,
                       double *z0im_inv, double *phi_inv) {
    double c = cos(phi), s = sin(phi);
    *z0re_inv = -(z0re * c - z0im * s);
    *z0im_inv = -(z0re * s + z0im * c);
    *phi_inv = -phi;
}
