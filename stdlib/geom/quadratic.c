/* The implicit equation and metric elements of a plane conic (quadratic.h). */
#include "quadratic.h"
#include <math.h>
#include <string.h>
#include "status.h"

const char *const pc_ckind_names[] = {"ellipse", "parabola", "hyperbola", NULL};

double pc_conic_eq(const double q[6], double x, double y) {
    return q[0] * x * x + q[1] * x * y + q[2] * y * y + q[3] * x + q[4] * y + q[5];
}

static int scale_coef(const double in[6], double out[6]) {
    double m = 0;
    for (int i = 0; i < 6; i++) {
        if (!isfinite(in[i])) return PC_ENONFINITE;
        m = fmax(m, fabs(in[i]));
    }
    if (!(m > 0)) return PC_EDOMAIN;
    /* one sign for one conic: the first of a, b, c that is not rounding noise is positive */
    for (int i = 0; i < 3; i++)
        if (fabs(in[i]) > 1e-12 * m) {
            if (in[i] < 0) m = -m;
            break;
        }
    for (int i = 0; i < 6; i++) out[i] = in[i] / m + 0.0;
    return PC_OK;
}

static double det3(const double *m) {
    return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
           m[2] * (m[3] * m[7] - m[4] * m[6]);
}

int pc_conic_coef_rquad(const double h[9], double coef[6]) {
    double M[9], big = 0;
    for (int i = 0; i < 9; i++)
        if (!isfinite(h[i])) return PC_ENONFINITE;
    /* M = [h0 h1 h2] as columns, each scaled to unit size (scaling a column only scales one
     * of b0, b1, b2, which the weights below account for) */
    double sc[3];
    for (int j = 0; j < 3; j++) {
        double n = fmax(fabs(h[3 * j]), fmax(fabs(h[3 * j + 1]), fabs(h[3 * j + 2])));
        if (!(n > 0)) return PC_ECOLLINEAR;   /* a zero row: no point at all */
        sc[j] = n;
        for (int r = 0; r < 3; r++) M[3 * r + j] = h[3 * j + r] / n;
    }
    for (int i = 0; i < 9; i++) big = fmax(big, fabs(M[i]));
    double det = det3(M);
    if (!(fabs(det) > 1e-12 * big * big * big)) return PC_ECOLLINEAR;
    double N[9] = {M[4] * M[8] - M[5] * M[7], M[2] * M[7] - M[1] * M[8], M[1] * M[5] - M[2] * M[4],
                   M[5] * M[6] - M[3] * M[8], M[0] * M[8] - M[2] * M[6], M[2] * M[3] - M[0] * M[5],
                   M[3] * M[7] - M[4] * M[6], M[1] * M[6] - M[0] * M[7], M[0] * M[4] - M[1] * M[3]};
    /* rows of N give b' = b * sc: b1^2 = 4 b0 b2 becomes b1'^2 / sc1^2 = 4 b0' b2' / (sc0 sc2),
     * i.e. b1'^2 - 4 g b0' b2' = 0 with g = sc1^2 / (sc0 sc2) */
    double g = sc[1] / sc[0] * (sc[1] / sc[2]), Q[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            Q[3 * i + j] = N[3 + i] * N[3 + j] - 2 * g * (N[i] * N[6 + j] + N[6 + i] * N[j]);
    double c6[6] = {Q[0], 2 * Q[1], Q[4], 2 * Q[2], 2 * Q[5], Q[8]};
    return scale_coef(c6, coef);
}

/* The 5x5 determinant of a (row-major) by elimination with partial pivoting. */
static double det5(double a[25]) {
    double d = 1;
    for (int k = 0; k < 5; k++) {
        int p = k;
        for (int i = k + 1; i < 5; i++)
            if (fabs(a[5 * i + k]) > fabs(a[5 * p + k])) p = i;
        if (a[5 * p + k] == 0) return 0;
        if (p != k) {
            for (int j = 0; j < 5; j++) {
                double t = a[5 * k + j];
                a[5 * k + j] = a[5 * p + j];
                a[5 * p + j] = t;
            }
            d = -d;
        }
        d *= a[5 * k + k];
        for (int i = k + 1; i < 5; i++) {
            double f = a[5 * i + k] / a[5 * k + k];
            for (int j = k; j < 5; j++) a[5 * i + j] -= f * a[5 * k + j];
        }
    }
    return d;
}

int pc_conic_coef_five(const double pts[10], double coef[6]) {
    double cx = 0, cy = 0, s = 0;
    for (int i = 0; i < 10; i++)
        if (!isfinite(pts[i])) return PC_ENONFINITE;
    for (int i = 0; i < 5; i++) cx += pts[2 * i] / 5, cy += pts[2 * i + 1] / 5;
    for (int i = 0; i < 5; i++) s = fmax(s, fmax(fabs(pts[2 * i] - cx), fabs(pts[2 * i + 1] - cy)));
    if (!(s > 0)) return PC_ECOLLINEAR;
    /* in centred, scaled coordinates X = (x - cx)/s the minors are well conditioned */
    double rows[5][6];
    for (int i = 0; i < 5; i++) {
        double x = (pts[2 * i] - cx) / s, y = (pts[2 * i + 1] - cy) / s;
        double r[6] = {x * x, x * y, y * y, x, y, 1};
        memcpy(rows[i], r, sizeof r);
    }
    double Q[6], m = 0;
    for (int j = 0; j < 6; j++) {
        double a[25];
        for (int i = 0; i < 5; i++)
            for (int k = 0, c = 0; k < 6; k++)
                if (k != j) a[5 * i + c++] = rows[i][k];
        Q[j] = (j % 2 ? -1 : 1) * det5(a);
        m = fmax(m, fabs(Q[j]));
    }
    /* four collinear points leave the conic undetermined: every minor vanishes */
    if (!(m > 1e-12)) return PC_ECOLLINEAR;
    /* back to x, y: substitute X = (x - cx)/s, Y = (y - cy)/s and multiply by s^2 */
    double A = Q[0], B = Q[1], C = Q[2], D = Q[3] * s, E = Q[4] * s, F = Q[5] * s * s;
    double c6[6] = {A, B, C, D - 2 * A * cx - B * cy, E - 2 * C * cy - B * cx,
                    F + A * cx * cx + B * cx * cy + C * cy * cy - D * cx - E * cy};
    return scale_coef(c6, coef);
}

void pc_conic_row_point(double x, double y, double row[6]) {
    double r[6] = {x * x, x * y, y * y, x, y, 1};
    memcpy(row, r, sizeof r);
}

void pc_conic_row_tangent(double x, double y, double dx, double dy, double row[6]) {
    double r[6] = {2 * x * dx, y * dx + x * dy, 2 * y * dy, dx, dy, 0};
    memcpy(row, r, sizeof r);
}

int pc_conic_coef_conditions(const double rows[30], double coef[6]) {
    double Q[6], m = 0, big = 0;
    for (int i = 0; i < 30; i++) {
        if (!isfinite(rows[i])) return PC_ENONFINITE;
        big = fmax(big, fabs(rows[i]));
    }
    if (!(big > 0)) return PC_ECOLLINEAR;
    for (int j = 0; j < 6; j++) {
        double a[25];
        for (int i = 0; i < 5; i++)
            for (int k = 0, c = 0; k < 6; k++)
                if (k != j) a[5 * i + c++] = rows[6 * i + k] / big;
        Q[j] = (j % 2 ? -1 : 1) * det5(a);
        m = fmax(m, fabs(Q[j]));
    }
    if (!(m > 1e-13)) return PC_ECOLLINEAR;
    return scale_coef(Q, coef);
}

int pc_conic_slope(const double q[6], double x, double y, double *slope) {
    if (!isfinite(x) || !isfinite(y)) return PC_ENONFINITE;
    double fx = 2 * q[0] * x + q[1] * y + q[3], fy = q[1] * x + 2 * q[2] * y + q[4];
    double s = fmax(1, fmax(fabs(x), fabs(y)));
    if (fabs(fx) <= 1e-14 * s && fabs(fy) <= 1e-14 * s) return PC_EZERO;
    if (fabs(fy) <= 1e-14 * s * fmax(1, fabs(fx))) return PC_EPOLE;
    *slope = -fx / fy;
    return PC_OK;
}

/* Unit eigenvectors of the symmetric [p r; r q] for its eigenvalues l[0] >= l[1]. */
static void eigen2(double p, double q, double r, double l[2], double v[2][2]) {
    double mean = (p + q) / 2, rad = hypot((p - q) / 2, r);
    l[0] = mean + rad;
    l[1] = mean - rad;
    double th = 0.5 * atan2(2 * r, p - q);
    v[0][0] = cos(th); v[0][1] = sin(th);
    v[1][0] = -sin(th); v[1][1] = cos(th);
}

static void no_arc(pc_conic_info *o) {
    o->mu = o->w = o->k_ed = o->k_ceva = NAN;
}

/* Parabola: in the frame (u, v), u the null direction, the equation is
 * lam Y^2 + D X + E Y + F = 0, i.e. (Y - Y0)^2 = -(D/lam)(X - X0); the focal length is
 * |D/lam|/4 and the semi-latus rectum twice that. */
static int parabola(pc_conic_info *o, double lam, const double u0[2], const double v[2]) {
    const double *q = o->coef;
    double u[2] = {u0[0], u0[1]};
    double D = q[3] * u[0] + q[4] * u[1], E = q[3] * v[0] + q[4] * v[1], F = q[5];
    if (!(fabs(D) > 1e-12 * fmax(fabs(lam), fmax(fabs(E), fabs(F))))) return PC_EDOMAIN;
    double Y0 = -E / (2 * lam), X0 = (E * E / (4 * lam) - F) / D, f4 = -D / lam;
    if (f4 < 0) {               /* turn u to point into the curve */
        u[0] = -u[0], u[1] = -u[1];
        X0 = -X0, f4 = -f4;
    }
    double fl = f4 / 4;
    for (int k = 0; k < 2; k++) {
        o->vertex[k] = X0 * u[k] + Y0 * v[k];
        o->focus[0][k] = o->vertex[k] + fl * u[k];
        o->axis[0][k] = u[k];
        o->axis[1][k] = v[k];
    }
    o->nfoci = 1;
    o->ecc = 1;
    o->param = 2 * fl;
    return PC_OK;
}

static int elements(pc_conic_info *o) {
    const double *q = o->coef;
    double a = q[0], b = q[1], c = q[2], d = q[3], e = q[4], f = q[5];
    double l[2], v[2][2];
    eigen2(a, c, b / 2, l, v);
    if (o->kind == PC_CK_PARABOLA) {
        int z = fabs(l[0]) < fabs(l[1]) ? 0 : 1;
        return parabola(o, l[1 - z], v[z], v[1 - z]);
    }
    double Dt = a * c - b * b / 4;
    if (!(fabs(Dt) > 0)) return PC_EDOMAIN;
    o->central = 1;
    o->center[0] = (-d / 2 * c + e / 2 * b / 2) / Dt;
    o->center[1] = (-e / 2 * a + d / 2 * b / 2) / Dt;
    /* the value at the centre: the equation is l0 X^2 + l1 Y^2 + f0 = 0 in the axes */
    double f0 = f + (d * o->center[0] + e * o->center[1]) / 2;
    double big = fmax(fabs(l[0]), fabs(l[1]));
    if (!(fabs(f0) > 1e-12 * fmax(big, fabs(f)))) return PC_EDOMAIN;   /* a line pair */
    double s0 = -f0 / l[0], s1 = -f0 / l[1];
    int first;
    if (o->kind == PC_CK_ELLIPSE) {
        if (!(s0 > 0) || !(s1 > 0)) return PC_EDOMAIN;                /* no real points */
        first = s0 >= s1 ? 0 : 1;                                    /* the major axis */
    } else {
        first = s0 > 0 ? 0 : 1;                                      /* the transverse axis */
    }
    double A = sqrt(fabs(first ? s1 : s0)), B = sqrt(fabs(first ? s0 : s1));
    o->semi[0] = A, o->semi[1] = B;
    /* one orientation for one conic: axis[0] points to +x (or +y when vertical), axis[1] is it
     * turned by +90 degrees, so focus[0] is the one on the side axis[0] points to */
    double ux = v[first][0], uy = v[first][1];
    if (ux < -1e-12 || (fabs(ux) <= 1e-12 && uy < 0)) ux = -ux, uy = -uy;
    o->axis[0][0] = ux, o->axis[0][1] = uy;
    o->axis[1][0] = -uy, o->axis[1][1] = ux;
    double cf = o->kind == PC_CK_ELLIPSE ? sqrt(fmax(A * A - B * B, 0)) : hypot(A, B);
    o->circle = o->kind == PC_CK_ELLIPSE && A - B <= 1e-9 * A;
    if (o->circle) cf = 0;
    for (int s = 0; s < 2; s++)
        for (int k = 0; k < 2; k++)
            o->focus[s][k] = o->center[k] + (s ? -cf : cf) * o->axis[0][k];
    o->nfoci = 2;
    o->ecc = cf / A;
    o->param = B * B / A;
    if (o->kind == PC_CK_HYPERBOLA) {
        o->nasym = 2;
        for (int s = 0; s < 2; s++) {
            double y = s ? -B : B, n = hypot(A, y);
            for (int k = 0; k < 2; k++) o->asym[s][k] = (A * o->axis[0][k] + y * o->axis[1][k]) / n;
        }
    }
    return PC_OK;
}

int pc_conic_info_coef(const double coef[6], pc_conic_info *out) {
    double in[6];
    memcpy(in, coef, sizeof in);     /* coef may be out->coef */
    memset(out, 0, sizeof *out);
    no_arc(out);
    int st = scale_coef(in, out->coef);
    if (st != PC_OK) return st;
    const double *q = out->coef;
    double big2 = fmax(q[1] * q[1], fmax(q[0] * q[0], q[2] * q[2]));
    if (!(big2 > 0)) return PC_EDOMAIN;      /* no quadratic part: a line */
    out->disc = q[1] * q[1] - 4 * q[0] * q[2];
    out->kind = fabs(out->disc) <= 1e-12 * big2 ? PC_CK_PARABOLA
              : out->disc < 0                  ? PC_CK_ELLIPSE
                                               : PC_CK_HYPERBOLA;
    return elements(out);
}

int pc_conic_info_rquad(const double h[9], pc_conic_info *out) {
    double coef[6];
    memset(out, 0, sizeof *out);
    no_arc(out);
    int st = pc_conic_coef_rquad(h, coef);
    if (st != PC_OK) return st;
    memcpy(out->coef, coef, sizeof coef);
    const double *q = out->coef;
    out->disc = q[1] * q[1] - 4 * q[0] * q[2];
    double w0 = h[2], w1 = h[5], w2 = h[8];
    if (w0 != 0 && w1 != 0 && w2 != 0) {
        /* digest §6: the type is fixed by mu = w1^2/(w0 w2), which no reparametrisation and
         * no common factor of the weights changes */
        out->mu = w1 * w1 / (w0 * w2);
        out->kind = fabs(out->mu - 1) <= 1e-12 ? PC_CK_PARABOLA
                  : out->mu > 0 && out->mu < 1 ? PC_CK_ELLIPSE
                                               : PC_CK_HYPERBOLA;
        out->k_ceva = 1 / (4 * out->mu);
        if (w0 * w2 > 0) {
            out->w = w1 * (w0 > 0 ? 1 : -1) / sqrt(w0 * w2);
            out->k_ed = 1 / (1 + out->w);
        }
    } else {
        /* a control point at infinity (an end, or the middle one of a semi-ellipse with
         * parallel end tangents): mu says nothing, the equation's discriminant does */
        double big2 = fmax(q[1] * q[1], fmax(q[0] * q[0], q[2] * q[2]));
        out->kind = fabs(out->disc) <= 1e-12 * big2 ? PC_CK_PARABOLA
                  : out->disc < 0                  ? PC_CK_ELLIPSE
                                                   : PC_CK_HYPERBOLA;
    }
    return elements(out);
}

/* ---- the conic of a curve ----------------------------------------------------------------- */

/* |Q(p)| / |grad Q(p)|, the distance of p from the conic to first order, relative to size. */
static int off_conic(const double q[6], const double p[2], double size) {
    double gx = 2 * q[0] * p[0] + q[1] * p[1] + q[3], gy = q[1] * p[0] + 2 * q[2] * p[1] + q[4];
    double g = hypot(gx, gy), v = fabs(pc_conic_eq(q, p[0], p[1]));
    return g > 0 ? v > 1e-9 * size * g : v > 1e-12;
}

int pc_curve_conic(const pc_curve *c, pc_conic_info *out) {
    if (c->dim != 2) return PC_EDIM;
    double lo[2], hi[2];
    int st = pc_curve_bbox(c, 1e-9, lo, hi);
    if (st != PC_OK && st != PC_IMPROPER) return st;
    double size = st == PC_OK ? hypot(hi[0] - lo[0], hi[1] - lo[1]) : 1;
    if (!(size > 0) || !isfinite(size)) size = 1;
    if (c->kind == PC_CURVE_BEZIER && c->degree == 2) {
        st = pc_conic_info_rquad(c->cp, out);
        if (st != PC_OK) return st;
        int nseg = c->nknots - 1;
        for (int i = 1; i < nseg; i++)
            for (int j = 0; j < 5; j++) {
                double t = c->knots[i] + (c->knots[i + 1] - c->knots[i]) * j / 4, p[2];
                if (pc_curve_eval(c, t, p) == PC_OK && off_conic(out->coef, p, size))
                    return PC_ENOTCOLLINEAR;
            }
        return PC_OK;
    }
    /* five points of the curve, away from its ends and from points at infinity */
    double pts[10], t0 = c->t0, t1 = c->t1;
    int n = 0;
    for (int i = 0; i < 40 && n < 5; i++) {
        double t = t0 + (t1 - t0) * (0.03 + 0.94 * ((i * 0.381966) - floor(i * 0.381966)));
        if (pc_curve_eval(c, t, pts + 2 * n) == PC_OK) n++;
    }
    if (n < 5) return PC_ENOTCOLLINEAR;
    double coef[6];
    st = pc_conic_coef_five(pts, coef);
    if (st == PC_ECOLLINEAR) return PC_ENOTCOLLINEAR;    /* a line, or a curve that stays put */
    if (st != PC_OK) return st;
    for (int i = 0; i <= 10; i++) {
        double t = t0 + (t1 - t0) * (0.01 + 0.98 * i / 10.0), p[2];
        if (pc_curve_eval(c, t, p) == PC_OK && off_conic(coef, p, size)) return PC_ENOTCOLLINEAR;
    }
    return pc_conic_info_coef(coef, out);
}
