/* The conic of a rational quadratic arc and its centre, axes and asymptotes (conic_props.h,
 * digest korotky_curves_surfaces.md B.3). */
#include "conic_props.h"
#include <math.h>
#include <string.h>
#include "quadratic.h"

int pc_conic_from_arc(const double *cp, double coef[6]) {
    /* the kernel's conic of the homogeneous control points: the weights as they are, so an
     * arc whose end weights are not 1 (or not positive) is read right (quadratic.h) */
    return pc_conic_coef_rquad(cp, coef);
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
