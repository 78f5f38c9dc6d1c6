/* Konopatsky's conic arcs as rational quadratic Bezier curves (conic.h; digest
 * konopatsky_ch1_2.md §5.3-5.10 and the table of §6). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "conic.h"
#include "simplex.h"

#define ROW(dim) ((dim) + 1)

static int finite_pts(int dim, int m, const double *const *p) {
    for (int i = 0; i < m; i++)
        for (int k = 0; k < dim; k++)
            if (!isfinite(p[i][k])) return 0;
    return 1;
}

/* h = w P (homogeneous row of the point P with weight w) */
static void hpoint(int dim, const double *p, double w, double *h) {
    for (int k = 0; k < dim; k++) h[k] = w * p[k];
    h[dim] = w;
}

/* (A - C) x + (B - C) y + C den, weight den: a point equation in the simplex CAB written
 * over its common denominator. */
static void hcab(int dim, const double *c, const double *a, const double *b, double x, double y,
                 double den, double *h) {
    for (int k = 0; k < dim; k++) h[k] = (a[k] - c[k]) * x + (b[k] - c[k]) * y + c[k] * den;
    h[dim] = den;
}

static pc_curve *fail(int *status, int st) {
    *status = st;
    return NULL;
}

/* The natural parameters (p, q) of X in the simplex CAB (§2 item 6) and whether X lies in
 * its plane. */
static int natural(int dim, const double *c, const double *a, const double *b, int m,
                   const double *const *x, double *pq) {
    if (dim < 2 || dim > PC_MAXDIM) return PC_EDIM;
    double mem[(3 * PC_MAXDIM + 4 + 8 * PC_MAXDIM) + 16];
    pc_simplex *s = (pc_simplex *)mem;
    double v[3 * PC_MAXDIM];
    memcpy(v, c, sizeof(double) * (size_t)dim);
    memcpy(v + dim, a, sizeof(double) * (size_t)dim);
    memcpy(v + 2 * dim, b, sizeof(double) * (size_t)dim);
    int st = pc_simplex_init(s, dim, 2, v);
    if (st == PC_ECOINCIDENT) st = PC_ECOLLINEAR;
    if (st) return st;
    double scale = pc_dist(dim, c, a) + pc_dist(dim, c, b);
    for (int i = 0; i < m; i++) {
        double res;
        pc_simplex_params(s, x[i], pq + 2 * i, &res);
        if (res > PC_ON_TOL * (scale + pc_dist(dim, c, x[i]))) return PC_EDOMAIN;
    }
    return PC_OK;
}

pc_curve *pc_rquad_from_samples(int dim, const double *h0, const double *hm, const double *h1,
                                double u0, double u1, int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    if (!(u1 > u0) || !isfinite(u0) || !isfinite(u1)) return fail(status, PC_EDOMAIN);
    double cp[3 * ROW(PC_MAXDIM)];
    int r = ROW(dim);
    for (int k = 0; k < r; k++) {
        cp[k] = h0[k];
        cp[r + k] = 2 * hm[k] - 0.5 * (h0[k] + h1[k]);   /* H(1/2) = P0/4 + P1/2 + P2/4 */
        cp[2 * r + k] = h1[k];
    }
    double brk[2] = {u0, u1};
    return pc_curve_bezier_pieces(dim, 2, 1, cp, brk, status);
}

pc_curve *pc_conic_parabola(int dim, const double *a1, const double *a3, const double *a2,
                            int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    double cp[3 * ROW(PC_MAXDIM)];
    hpoint(dim, a1, 1, cp);
    hpoint(dim, a3, 1, cp + ROW(dim));
    hpoint(dim, a2, 1, cp + 2 * ROW(dim));
    return pc_curve_bezier(dim, 3, cp, status);
}

pc_curve *pc_conic_parabola3(int dim, const double *a, const double *c, const double *b,
                             double tc, int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    if (!(tc > 0 && tc < 1)) return fail(status, PC_EDOMAIN);
    /* (2.62) is Lagrange's quadratic through the nodes 0, tC, 1 (digest §5.3) */
    double p[3 * PC_MAXDIM], u[3] = {0, tc, 1};
    memcpy(p, a, sizeof(double) * (size_t)dim);
    memcpy(p + dim, c, sizeof(double) * (size_t)dim);
    memcpy(p + 2 * dim, b, sizeof(double) * (size_t)dim);
    return pc_curve_interpolate(dim, 3, p, u, status);
}

pc_curve *pc_conic_ed(int dim, const double *a, const double *b, const double *c, double k,
                      int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    if (!isfinite(k)) return fail(status, PC_ENONFINITE);
    if (k == 0) return fail(status, PC_EDOMAIN);
    /* (2.97) = [k u'^2 A + 2(1 - k) u u' C + k u^2 B] / [k u'^2 + 2(1 - k) u u' + k u^2]
     * (digest §5.6: the denominator k(1 - 2u)^2 + 2u'u expands to this) */
    double cp[3 * ROW(PC_MAXDIM)];
    hpoint(dim, a, k, cp);
    hpoint(dim, c, 1 - k, cp + ROW(dim));
    hpoint(dim, b, k, cp + 2 * ROW(dim));
    return pc_curve_bezier(dim, 3, cp, status);
}

int pc_conic_ed_k(int dim, const double *a, const double *b, const double *c, const double *kpt,
                  double *k) {
    if (dim < 1 || dim > PC_MAXDIM) return PC_EDIM;
    double m[PC_MAXDIM], d[PC_MAXDIM];
    for (int i = 0; i < dim; i++) {
        m[i] = 0.5 * (a[i] + b[i]) - c[i];   /* T1 - C, the median */
        d[i] = kpt[i] - c[i];
    }
    double mm = pc_dot(dim, m, m);
    if (!(mm > 0)) return PC_ECOLLINEAR;
    double kk = pc_dot(dim, d, m) / mm, res = 0;
    for (int i = 0; i < dim; i++) res += (d[i] - kk * m[i]) * (d[i] - kk * m[i]);
    if (sqrt(res) > PC_ON_TOL * (sqrt(mm) + pc_norm(dim, d))) return PC_ENOTCOLLINEAR;
    *k = kk;
    return PC_OK;
}

int pc_conic_ed_circle_k(int dim, const double *a, const double *b, const double *c, double *k) {
    if (dim < 1 || dim > PC_MAXDIM) return PC_EDIM;
    double ca = pc_dist(dim, c, a), cb = pc_dist(dim, c, b), ab = pc_dist(dim, a, b);
    if (!(ca > 0 && cb > 0 && ab > 0)) return PC_ECOINCIDENT;
    if (fabs(ca - cb) > 1e-9 * (ca + cb)) return PC_EDOMAIN;
    /* (2.107) k = 1/2 + 2h^2/c^2 with h the height and c the chord; with the half arc angle
     * theta, h = R(1 - cos theta), c = 2R sin theta, so k = 1/(1 + cos theta), and
     * cos theta = c/(2|CA|) (the tangent CA is perpendicular to the radius). */
    double ct = ab / (2 * ca);
    if (ct >= 1) return PC_ECOLLINEAR;
    double st = sqrt(1 - ct * ct), h_over_c = (1 - ct) / (2 * st);
    *k = 0.5 + 2 * h_over_c * h_over_c;
    return PC_OK;
}

pc_curve *pc_conic_circle_arc(int dim, const double *a, const double *b, const double *c, int *status) {
    double k;
    int st = pc_conic_ed_circle_k(dim, a, b, c, &k);
    return st ? fail(status, st) : pc_conic_ed(dim, a, b, c, k, status);
}

pc_curve *pc_conic_ed3(int dim, const double *a, const double *kpt, const double *b, double k,
                       int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    if (!isfinite(k)) return fail(status, PC_ENONFINITE);
    if (k == 0 || k == 1) return fail(status, PC_EDOMAIN);
    /* §4.1 change of simplex: C k' = K - K_C k with K_C = (A + B)/2; the print's "K 1/k" is
     * K/k' (digest ch. 3-5 §2.1) */
    double c[PC_MAXDIM], kb = 1 - k;
    for (int i = 0; i < dim; i++) c[i] = kpt[i] / kb - 0.5 * (a[i] + b[i]) * k / kb;
    return pc_conic_ed(dim, a, b, c, k, status);
}

pc_curve *pc_conic_ceva(int dim, const double *a1, const double *a2, const double *a3, double k,
                        int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    if (!isfinite(k)) return fail(status, PC_ENONFINITE);
    if (k == 0) return fail(status, PC_EDOMAIN);
    /* (2.104): numerator A2(1 - t)^2 + A3 t(1 - t) + A1 k t^2 over 1 - t(1 - kt): Bernstein
     * weights 1, 1/2, k on A2, A3, A1 (digest §6) */
    double cp[3 * ROW(PC_MAXDIM)];
    hpoint(dim, a2, 1, cp);
    hpoint(dim, a3, 0.5, cp + ROW(dim));
    hpoint(dim, a1, k, cp + 2 * ROW(dim));
    return pc_curve_bezier(dim, 3, cp, status);
}

int pc_conic_ceva_k(int dim, const double *a1, const double *a2, const double *a3,
                    const double *kpt, double *k) {
    if (dim < 2 || dim > PC_MAXDIM) return PC_EDIM;
    double k1[PC_MAXDIM + 1], k2[PC_MAXDIM + 1], v23, v31;
    int st = pc_meet(dim, a1, kpt, a2, a3, k1, NULL, NULL, NULL);
    if (st) return st == PC_IMPROPER ? PC_EDOMAIN : st;
    st = pc_meet(dim, a2, kpt, a3, a1, k2, NULL, NULL, NULL);
    if (st) return st == PC_IMPROPER ? PC_EDOMAIN : st;
    if ((st = pc_sr(dim, a2, a3, k1, &v23)) || (st = pc_sr(dim, a3, a1, k2, &v31))) return st;
    if (v23 == 0 || !isfinite(v23) || !isfinite(v31)) return PC_EDOMAIN;
    *k = v31 / v23;   /* (2.100) */
    return PC_OK;
}

pc_curve *pc_conic_conjugate(int dim, const double *c, const double *a, const double *b,
                             int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    const double *pts[3] = {a, b, c};
    if (!finite_pts(dim, 3, pts)) return fail(status, PC_ENONFINITE);
    double h[3][ROW(PC_MAXDIM)];
    for (int i = 0; i < 3; i++) {       /* (2.32) over 1 + t^2 at t = 0, 1/2, 1 */
        double t = 0.5 * i;
        hcab(dim, c, a, b, 1 - t * t, 2 * t, 1 + t * t, h[i]);
    }
    return pc_rquad_from_samples(dim, h[0], h[1], h[2], 0, 1, status);
}

pc_curve *pc_conic_conjugate2(int dim, const double *kpt, const double *a, const double *b,
                              double lambda, int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    if (!(lambda > 0 && lambda < 1)) return fail(status, PC_EDOMAIN);
    double h[3][ROW(PC_MAXDIM)];
    for (int i = 0; i < 3; i++) {       /* §2.1.1.6 over t^2 - 2 lambda t + lambda */
        double t = 0.5 * i;
        hcab(dim, kpt, a, b, t * (t - lambda), t * (1 - t), t * t - 2 * lambda * t + lambda, h[i]);
    }
    return pc_rquad_from_samples(dim, h[0], h[1], h[2], 0, 1, status);
}

/* ---- the conic through five points, §2.1.4 corrected -------------------------------------- */

typedef struct { double pd, qd, pe, qe; } five;

/* The corrected closed form (digest §5.4): X, Y over Den, all quadratic in u. */
static void five_h(const five *f, double u, double *x, double *y, double *den) {
    double pd = f->pd, qd = f->qd, pe = f->pe, qe = f->qe;
    double d0 = pe * (pd * qe - pe * qd) * (pd + qd - 1);
    double d2 = qd * (pd * qe - pd - pe * qd + pe);
    double d1 = pd * pd * qe * qe - pd * pd * qe - 2 * pd * pe * qd * qe + 2 * pd * pe * qd
                - pd * qe * qe + pd * qe + pe * pe * qd * qd - pe * pe * qd + pe * qd * qd - pe * qd;
    *x = pd * u * (pe - (1 - qe) * u) * (pd * qe - pe * qd + qd - qe);
    *y = qd * qe * u * (u - 1) * (pd * qe - pd - pe * qd + pe);
    *den = d2 * u * u + d1 * u + d0;
}

static double safe_div(double n, double d) {
    return d != 0 ? n / d : (n == 0 ? NAN : (n > 0 ? INFINITY : -INFINITY));
}

static void five_params(const five *f, double upar[5]) {
    double pd = f->pd, qd = f->qd, pe = f->pe, qe = f->qe;
    upar[0] = 1;                                   /* A */
    upar[1] = safe_div(pe, 1 - qe);                /* B: corrected u_B */
    upar[2] = 0;                                   /* C */
    upar[3] = safe_div(pe * qd - pd * qe, qd - qe);/* D */
    upar[4] = safe_div(-pe * (pd * qe - pe * qd) * (pd + qd - 1),
                       pd * pd * qe * qe - pd * pd * qe - 2 * pd * pe * qd * qe + 2 * pd * pe * qd
                       + pd * qd * qe - pd * qd - pd * qe * qe + pd * qe + pe * pe * qd * qd
                       - pe * pe * qd);            /* E */
}

static int five_setup(int dim, const double *a, const double *b, const double *c,
                      const double *d, const double *e, five *f) {
    const double *pts[5] = {a, b, c, d, e};
    if (!finite_pts(dim, 5, pts)) return PC_ENONFINITE;
    const double *x[2] = {d, e};
    double pq[4];
    int st = natural(dim, c, a, b, 2, x, pq);
    if (st) return st;
    /* no three of the five collinear (else the conic degenerates): signed areas in the
     * natural parameters, where ABC has area 1/2 */
    double P[5][2] = {{1, 0}, {0, 1}, {0, 0}, {pq[0], pq[1]}, {pq[2], pq[3]}};
    for (int i = 0; i < 5; i++)
        for (int j = i + 1; j < 5; j++)
            for (int k = j + 1; k < 5; k++) {
                double s = (P[j][0] - P[i][0]) * (P[k][1] - P[i][1])
                         - (P[k][0] - P[i][0]) * (P[j][1] - P[i][1]);
                if (fabs(s) < 1e-12) return PC_EDOMAIN;
            }
    f->pd = pq[0], f->qd = pq[1], f->pe = pq[2], f->qe = pq[3];
    return PC_OK;
}

int pc_conic_five_points_params(int dim, const double *a, const double *b, const double *c,
                                const double *d, const double *e, double upar[5]) {
    five f;
    int st = five_setup(dim, a, b, c, d, e, &f);
    if (st) return st;
    five_params(&f, upar);
    return PC_OK;
}

void pc_conic_five_points_span(const double upar[5], double *u0, double *u1) {
    *u0 = 0;
    *u1 = 1;
    for (int i = 0; i < 5; i++) {
        if (!isfinite(upar[i]) || fabs(upar[i]) >= 1e6) continue;
        *u0 = fmin(*u0, upar[i]);
        *u1 = fmax(*u1, upar[i]);
    }
}

pc_curve *pc_conic_five_points(int dim, const double *a, const double *b, const double *c,
                               const double *d, const double *e, double u0, double u1,
                               int whole, double upar[5], int *status) {
    if (dim < 2 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    five f;
    int st = five_setup(dim, a, b, c, d, e, &f);
    if (st) return fail(status, st);
    double up[5], s0, s1;
    five_params(&f, up);
    if (upar) memcpy(upar, up, sizeof up);
    pc_conic_five_points_span(up, &s0, &s1);
    if (isnan(u0)) u0 = s0;
    if (isnan(u1)) u1 = s1;
    if (!(u1 > u0) || !isfinite(u0) || !isfinite(u1)) return fail(status, PC_EDOMAIN2);
    double h[3][ROW(PC_MAXDIM)];
    for (int i = 0; i < 3; i++) {
        double x, y, den;
        five_h(&f, u0 + 0.5 * i * (u1 - u0), &x, &y, &den);
        hcab(dim, c, a, b, x, y, den, h[i]);
    }
    if (!whole) return pc_rquad_from_samples(dim, h[0], h[1], h[2], u0, u1, status);
    /* the complementary arc of a rational quadratic: the same ends, the middle control point
     * negated (weight included) */
    int r = ROW(dim);
    double cp[5 * ROW(PC_MAXDIM)], brk[3] = {u0, u1, 2 * u1 - u0};
    for (int k = 0; k < r; k++) {
        double mid = 2 * h[1][k] - 0.5 * (h[0][k] + h[2][k]);
        cp[k] = h[0][k];
        cp[r + k] = mid;
        cp[2 * r + k] = h[2][k];
        cp[3 * r + k] = -mid;
        cp[4 * r + k] = h[0][k];
    }
    return pc_curve_bezier_pieces(dim, 2, 2, cp, brk, status);
}

/* ---- §2.1.5 ------------------------------------------------------------------------------- */

pc_curve *pc_conic_five_points2(int dim, const double *c, const double *a, const double *b,
                                double p1, double p2, double q2, double q3, int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    if (!(p1 > 0 && p1 <= 1 && q3 > 0 && q3 <= 1)) return fail(status, PC_EDOMAIN);
    if (!(p2 > 0 && p2 < 1 && q2 > 0 && q2 < 1)) return fail(status, PC_EDOMAIN2);
    double h[3][ROW(PC_MAXDIM)], p2b = 1 - p2;
    double y0 = p2 * q2 * q3, k0 = 1 - p2b * q2;      /* Y0, K0 of (2.90) */
    for (int i = 0; i < 3; i++) {
        /* corrected (2.93) (digest §5.5): q2(p2 t' + p1 p2') where the print has
         * p2 q2 (t' + p2'), and (t' - p1) for (t' - p2) */
        double t = 0.5 * i, tb = 1 - t, g = q2 * (p2 * tb + p1 * p2b);
        double den = (p2 * q2 * t + y0 - k0) * tb - g * (y0 - tb * k0);
        double x = (y0 - k0) * (tb - g) * tb + p1 * p2b * q2 * (q2 - 1) * t * tb;
        double y = p2 * p2b * q2 * q2 * q3 * t * (tb - p1);
        hcab(dim, c, a, b, x, y, den, h[i]);
    }
    return pc_rquad_from_samples(dim, h[0], h[1], h[2], 0, 1, status);
}

int pc_redundant_point(int dim, const double *c, const double *a, const double *b, double u,
                       double v, double *out) {
    if (dim < 1 || dim > PC_MAXDIM) return PC_EDIM;
    if (!isfinite(u) || !isfinite(v)) return PC_ENONFINITE;
    double den = 1 - v * (1 - u);
    if (fabs(den) < 1e-15) return PC_EPOLE;
    for (int k = 0; k < dim; k++)
        out[k] = (a[k] - c[k]) * (1 - u) * (1 - v) / den + (b[k] - c[k]) * u * v / den + c[k];
    return PC_OK;
}

/* ---- §2.2 (b) ------------------------------------------------------------------------------ */

typedef struct {
    int dim;
    double a1[PC_MAXDIM + 1], a3[PC_MAXDIM + 1], a4[PC_MAXDIM + 1], a5[PC_MAXDIM + 1],
           a2[PC_MAXDIM + 1], a[PC_MAXDIM + 1];
} triples;

static int triples_eval(void *ud, double t, int order, double *out) {
    const triples *s = ud;
    int n = s->dim;
    if (order > 0) return PC_EDOMAIN;
    double cpt[PC_MAXDIM + 1], bpt[PC_MAXDIM + 1];
    pc_lerp(n, s->a1, s->a5, t, cpt);                           /* C = A1 t' + A5 t */
    int st = pc_meet_h(n, s->a, s->a1, s->a2, cpt, bpt, NULL, NULL, NULL);  /* B = AA1 x A2C */
    if (st != PC_OK && st != PC_IMPROPER) return st;
    st = pc_meet_h(n, bpt, s->a3, cpt, s->a4, out, NULL, NULL, NULL);      /* M = BA3 x CA4 */
    if (st == PC_ESAME_LINE || st == PC_ECOINCIDENT) {
        /* at A1 (t = 0) the two lines of the last meet coincide in the limit: the point is A1 */
        if (t == 0) {
            memcpy(out, s->a1, sizeof(double) * (size_t)(n + 1));
            return PC_OK;
        }
    }
    return st == PC_IMPROPER ? PC_OK : st;
}

pc_curve *pc_triples_conic(int dim, const double *a1, const double *a2, const double *a3,
                           const double *a4, const double *a5, double t0, double t1,
                           int *status) {
    if (dim < 2 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    const double *pts[5] = {a1, a2, a3, a4, a5};
    if (!finite_pts(dim, 5, pts)) return fail(status, PC_ENONFINITE);
    if (!(t1 > t0)) return fail(status, PC_EDOMAIN2);
    triples *s = malloc(sizeof *s);
    if (!s) return fail(status, PC_ENOMEM);
    s->dim = dim;
    hpoint(dim, a1, 1, s->a1);
    hpoint(dim, a2, 1, s->a2);
    hpoint(dim, a3, 1, s->a3);
    hpoint(dim, a4, 1, s->a4);
    hpoint(dim, a5, 1, s->a5);
    int st = pc_meet_h(dim, s->a2, s->a3, s->a4, s->a5, s->a, NULL, NULL, NULL);
    if (st != PC_OK && st != PC_IMPROPER) {
        free(s);
        return fail(status, PC_EDOMAIN);
    }
    pc_curve *cv = pc_curve_func(dim, t0, t1, 0, triples_eval, free, s, status);
    if (!cv) free(s);
    return cv;
}

int pc_ceva_to_ed(double k, double *out) {
    if (!isfinite(k)) return PC_ENONFINITE;
    if (!(k > 0)) return PC_EDOMAIN;
    double r = sqrt(k);
    *out = 2 * r / (1 + 2 * r);
    return PC_OK;
}

int pc_ed_to_ceva(double k, double *out) {
    if (!isfinite(k)) return PC_ENONFINITE;
    if (!(k > 0 && k < 1)) return PC_EDOMAIN;
    double r = k / (2 * (1 - k));
    *out = r * r;
    return PC_OK;
}
