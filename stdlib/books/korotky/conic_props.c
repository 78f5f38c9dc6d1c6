/* The conic of a rational quadratic arc and its centre, axes and asymptotes (conic_props.h,
 * digest korotky_curves_surfaces.md B.3). */
#include "conic_props.h"
#include <math.h>
#include <string.h>
#include "linalg.h"

int pc_conic_from_arc(const double *cp, double coef[6]) {
    for (int i = 0; i < 9; i++)
        if (!isfinite(cp[i])) return PC_ENONFINITE;
    /* M = [U W V] as columns; the middle row of cp is w W, so divide the weight back out
     * (its scale only scales beta, which C accounts for with w) */
    double M[9], w;
    const double *U = cp, *Wh = cp + 3, *V = cp + 6;
    if (U[2] == 0 || V[2] == 0) return PC_EDOMAIN;
    /* w W: a finite W has weight w (so w = Wh[2]); at infinity w is the length given to the
     * direction, which only scales beta: take W = Wh itself and w = 1 */
    double Wn[3];
    if (Wh[2] != 0) {
        w = Wh[2];
        for (int k = 0; k < 3; k++) Wn[k] = Wh[k] / w;
    } else {
        w = 1;
        memcpy(Wn, Wh, sizeof Wn);
    }
    for (int r = 0; r < 3; r++) {
        M[3 * r + 0] = U[r] / U[2];
        M[3 * r + 1] = Wn[r];
        M[3 * r + 2] = V[r] / V[2];
    }
    double det = M[0] * (M[4] * M[8] - M[5] * M[7]) - M[1] * (M[3] * M[8] - M[5] * M[6]) +
                 M[2] * (M[3] * M[7] - M[4] * M[6]);
    double scale = 0;
    for (int i = 0; i < 9; i++) scale = fmax(scale, fabs(M[i]));
    if (!(fabs(det) > 1e-13 * scale * scale * scale)) return PC_ECOLLINEAR;
    /* N = M^-1 (adjugate / det): rows give alpha, beta, gamma of a homogeneous point */
    double N[9] = {M[4] * M[8] - M[5] * M[7], M[2] * M[7] - M[1] * M[8], M[1] * M[5] - M[2] * M[4],
                   M[5] * M[6] - M[3] * M[8], M[0] * M[8] - M[2] * M[6], M[2] * M[3] - M[0] * M[5],
                   M[3] * M[7] - M[4] * M[6], M[1] * M[6] - M[0] * M[7], M[0] * M[4] - M[1] * M[3]};
    for (int i = 0; i < 9; i++) N[i] /= det;
    /* beta^2 - 4 w^2 alpha gamma: Q = N^T C N, C = [0 0 -2w^2; 0 1 0; -2w^2 0 0] */
    double Q[9], k = -2 * w * w;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            Q[3 * i + j] = N[3 + i] * N[3 + j] + k * (N[i] * N[6 + j] + N[6 + i] * N[j]);
    double c6[6] = {Q[0], 2 * Q[1], Q[4], 2 * Q[2], 2 * Q[5], Q[8]}, m = 0;
    for (int i = 0; i < 6; i++) m = fmax(m, fabs(c6[i]));
    if (!(m > 0) || !isfinite(m)) return PC_EDOMAIN;
    for (int i = 0; i < 6; i++) coef[i] = c6[i] / m;
    return PC_OK;
}

/* Unit eigenvectors of the symmetric [p r; r q] for its eigenvalues l[0], l[1]. */
static void eigen2(double p, double q, double r, double l[2], double v[2][2]) {
    double mean = (p + q) / 2, dif = (p - q) / 2, rad = hypot(dif, r);
    l[0] = mean + rad;
    l[1] = mean - rad;
    double th = 0.5 * atan2(2 * r, p - q);   /* direction of the eigenvector of l[0] */
    v[0][0] = cos(th); v[0][1] = sin(th);
    v[1][0] = -sin(th); v[1][1] = cos(th);
}

int pc_conic_elements_of(const double coef[6], pc_conic_elements *out) {
    for (int i = 0; i < 6; i++)
        if (!isfinite(coef[i])) return PC_ENONFINITE;
    double a = coef[0], b = coef[1], c = coef[2], d = coef[3], e = coef[4], f = coef[5];
    memset(out, 0, sizeof *out);
    /* the discriminant b^2 - 4ac, zero within rounding of the quadratic part's size (an arc
     * of weight 1 computed in floating point is a parabola) */
    double big2 = fmax(b * b, fmax(a * a, c * c)), disc = b * b - 4 * a * c;
    if (!(big2 > 0)) return PC_EDOMAIN;
    out->kind = fabs(disc) <= 1e-12 * big2 ? PC_CONIC_PARABOLA
              : disc < 0                   ? PC_CONIC_ELLIPSE
                                           : PC_CONIC_HYPERBOLA;
    double l[2], v[2][2];
    eigen2(a, c, b / 2, l, v);
    if (out->kind == PC_CONIC_PARABOLA) {
        /* the axis is the null direction of the quadratic part */
        int z = fabs(l[0]) < fabs(l[1]) ? 0 : 1;
        memcpy(out->axis[0], v[z], sizeof v[z]);
        memcpy(out->axis[1], v[1 - z], sizeof v[z]);
        return PC_OK;
    }
    double D = a * c - b * b / 4;
    out->central = 1;
    out->center[0] = (-d / 2 * c + e / 2 * b / 2) / D;
    out->center[1] = (-e / 2 * a + d / 2 * b / 2) / D;
    /* the value at the centre: the equation becomes l0 X^2 + l1 Y^2 + f0 = 0 */
    double f0 = f + (d * out->center[0] + e * out->center[1]) / 2;
    double big = fmax(fabs(l[0]), fabs(l[1]));
    if (!(fabs(f0) > 1e-12 * fmax(big, fabs(f)))) return PC_EDOMAIN;   /* a line pair */
    double s0 = -f0 / l[0], s1 = -f0 / l[1];
    if (out->kind == PC_CONIC_ELLIPSE) {
        if (!(s0 > 0)) return PC_EDOMAIN;   /* no real points */
        int maj = s0 >= s1 ? 0 : 1;         /* the major axis first */
        out->semi[0] = sqrt(maj ? s1 : s0);
        out->semi[1] = sqrt(maj ? s0 : s1);
        memcpy(out->axis[0], v[maj], sizeof v[0]);
        memcpy(out->axis[1], v[1 - maj], sizeof v[0]);
        return PC_OK;
    }
    /* hyperbola: the transverse axis is the one with -f0/lambda > 0 */
    int tr = s0 > 0 ? 0 : 1;
    out->semi[0] = sqrt(fabs(tr ? s1 : s0));
    out->semi[1] = sqrt(fabs(tr ? s0 : s1));
    memcpy(out->axis[0], v[tr], sizeof v[0]);
    memcpy(out->axis[1], v[1 - tr], sizeof v[0]);
    /* asymptotes: X/a = +-Y/b in the axes' frame */
    out->nasym = 2;
    for (int s = 0; s < 2; s++) {
        double sg = s ? -1 : 1, x = out->semi[0], y = sg * out->semi[1], n = hypot(x, y);
        for (int k = 0; k < 2; k++) out->asym[s][k] = (x * out->axis[0][k] + y * out->axis[1][k]) / n;
    }
    return PC_OK;
}
