/* The non-rational curves of Konopatsky's chapter 2 as FUNC curves (konop_curves.h; digest
 * konopatsky_ch1_2.md §5.1-5.2, 5.8, 5.11-5.15). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "konop_curves.h"

typedef struct {
    pc_kcurve_kind kind;
    int dim;
    double c[PC_MAXDIM], a[PC_MAXDIM], b[PC_MAXDIM];
    double par[PC_KC_MAXPAR];
    int npar;
    double ca, cb, gamma;   /* |CA|, |CB|, angle BCA */
} kcurve;

static pc_curve *fail(int *status, int st) {
    *status = st;
    return NULL;
}

/* The coefficients of M = (A - C)F + (B - C)G + C W over the weight W at t. */
static int kc_coef(const kcurve *k, double t, double *F, double *G, double *W) {
    double ea = k->ca, eb = k->cb;           /* §2.1.1-2: a = |CA|, b = |CB| */
    double fa = k->cb, fb = k->ca, g = k->gamma;   /* Fig. 2.1: a = |BC|, b = |CA| */
    *W = 1;
    switch (k->kind) {
    case PC_KC_ELLIPSE_ANGLE: {          /* (2.11) */
        double s = sqrt(ea * ea * sin(t) * sin(t) + eb * eb * cos(t) * cos(t));
        *F = eb * cos(t) / s, *G = ea * sin(t) / s;
        return PC_OK;
    }
    case PC_KC_ELLIPSE_RADIUS: {         /* (2.15), quadrant by signs */
        double d = sqrt(ea * ea - eb * eb);
        *F = sqrt(fmax(t * t - eb * eb, 0)) / d, *G = sqrt(fmax(ea * ea - t * t, 0)) / d;
        int q = (int)k->par[0];
        if (q == 2 || q == 3) *F = -*F;
        if (q == 3 || q == 4) *G = -*G;
        return PC_OK;
    }
    case PC_KC_ELLIPSE_FOCAL: {          /* (2.18); denominator >= a - c > 0 */
        double c = sqrt(ea * ea - eb * eb), d = ea - c * cos(t);
        *F = (ea * cos(t) - c) / d, *G = eb * sin(t) / d;
        return PC_OK;
    }
    case PC_KC_ELLIPSE_COMPRESSION:      /* (2.24) */
        *F = cos(t), *G = sin(t);
        return PC_OK;
    case PC_KC_ELLIPSE_ALGEBRAIC:        /* sin phi = t in (2.24) */
        *F = sqrt(fmax(1 - t * t, 0)), *G = t;
        return PC_OK;
    case PC_KC_HYPERBOLA_ANGLE: {        /* (2.49) over its root: weight 0 on the asymptotes */
        double s2 = eb * eb * cos(t) * cos(t) - ea * ea * sin(t) * sin(t);
        *F = eb * cos(t), *G = ea * sin(t), *W = sqrt(fmax(s2, 0));
        return PC_OK;
    }
    case PC_KC_HYPERBOLA_RADIUS: {       /* (2.53), rho in [a, inf) (the print: [b; a]) */
        double c = sqrt(ea * ea + eb * eb);
        *F = sqrt(t * t + eb * eb) / c, *G = sqrt(fmax(t * t - ea * ea, 0)) / c;
        return PC_OK;
    }
    case PC_KC_HYPERBOLA_FOCAL: {        /* (2.56) over a - c cos phi */
        double c = sqrt(ea * ea + eb * eb);
        *F = c - ea * cos(t), *G = eb * sin(t), *W = ea - c * cos(t);
        return PC_OK;
    }
    case PC_KC_CIRCLE_ANGLE: {           /* (2.115) */
        double dl = k->par[0], s = sin(t + dl) / (sin(dl) * sin(g));
        *F = s * sin(g - t), *G = s * fb * sin(t) / fa;
        return PC_OK;
    }
    case PC_KC_CIRCLE_RADIUS: {          /* (2.118) */
        double R = k->par[0];
        *F = R * sin(g - t) / (fb * sin(g)), *G = R * sin(t) / (fa * sin(g));
        return PC_OK;
    }
    case PC_KC_PARABOLA_ANGLE: {         /* §2.4.1 from (2.128) */
        double p = fa * fmax(sin(g - t), 0), q = fb * fmax(sin(t), 0);
        double s = sqrt(p) + sqrt(q);
        *F = p / (s * s), *G = q / (s * s);
        return PC_OK;
    }
    case PC_KC_PARABOLA_SIGMA: {         /* (2.134), (2.135) with sigma = CK + KM */
        double D = sqrt(fmax(fa * t + fb * t - fa * fb, 0)), s = fa + fb;
        if ((int)k->par[0] == 1) *F = (fa + D) / s * (fa + D) / s, *G = (fb - D) / s * (fb - D) / s;
        else *F = (fa - D) / s * (fa - D) / s, *G = (fb + D) / s * (fb + D) / s;
        return PC_OK;
    }
    case PC_KC_SINUSOID: {               /* (2.145) */
        double prod = 1;
        for (int i = 1; i <= (int)k->par[0]; i++) {
            double ki = k->par[i];
            prod *= sqrt(fmax(1 + ki * ki + 2 * ki * cos(ki * t), 0)) / ki;
        }
        *F = sin(g - t) / sin(g) * prod, *G = fb * sin(t) / (fa * sin(g)) * prod;
        return PC_OK;
    }
    case PC_KC_CYCLOID:                  /* §2.8 "(3.11)", "(3.12)" */
        *F = (1 - cos(t)) / 2;
        *G = (M_PI - t + (k->par[0] == 0 ? sin(t) : -sin(t))) / M_PI;
        return PC_OK;
    default:
        return PC_EDOMAIN;
    }
}

static int kc_eval(void *ud, double t, int order, double *out) {
    const kcurve *k = ud;
    if (order > 0) return PC_EDOMAIN;     /* the core differences */
    double F, G, W;
    int st = kc_coef(k, t, &F, &G, &W);
    if (st) return st;
    if (!isfinite(F) || !isfinite(G) || !isfinite(W)) return PC_ENONFINITE;
    for (int i = 0; i < k->dim; i++)
        out[i] = (k->a[i] - k->c[i]) * F + (k->b[i] - k->c[i]) * G + k->c[i] * W;
    out[k->dim] = W;
    return PC_OK;
}

/* Fill the triangle data and check the kind's parameters; the book's range into t0, t1. */
static int kc_setup(kcurve *k, pc_kcurve_kind kind, int dim, const double *c, const double *a,
                    const double *b, const double *par, int npar, double *t0, double *t1) {
    if (dim < 1 || dim > PC_MAXDIM) return PC_EDIM;
    if ((unsigned)kind >= PC_KC_NKINDS || npar < 0 || npar > PC_KC_MAXPAR) return PC_EDOMAIN;
    memset(k, 0, sizeof *k);
    k->kind = kind, k->dim = dim, k->npar = npar;
    for (int i = 0; i < dim; i++) {
        k->c[i] = c[i], k->a[i] = a[i], k->b[i] = b[i];
        if (!isfinite(c[i]) || !isfinite(a[i]) || !isfinite(b[i])) return PC_ENONFINITE;
    }
    for (int i = 0; i < npar; i++) {
        if (!isfinite(par[i])) return PC_ENONFINITE;
        k->par[i] = par[i];
    }
    double u[PC_MAXDIM], v[PC_MAXDIM];
    for (int i = 0; i < dim; i++) u[i] = a[i] - c[i], v[i] = b[i] - c[i];
    k->ca = pc_norm(dim, u), k->cb = pc_norm(dim, v);
    if (!(k->ca > 0 && k->cb > 0)) return PC_ECOLLINEAR;
    if (pc_angle(dim, u, v, &k->gamma)) return PC_ECOLLINEAR;
    if (sin(k->gamma) < PC_DEGEN_TOL) return PC_ECOLLINEAR;
    double ea = k->ca, eb = k->cb, g = k->gamma;
    switch (kind) {
    case PC_KC_ELLIPSE_ANGLE: case PC_KC_ELLIPSE_COMPRESSION:
    case PC_KC_CIRCLE_RADIUS:
        *t0 = 0, *t1 = 2 * M_PI;
        if (kind == PC_KC_CIRCLE_RADIUS && (npar < 1 || !(par[0] > 0))) return PC_EDOMAIN;
        return PC_OK;
    case PC_KC_ELLIPSE_RADIUS:
        if (!(ea > eb * (1 + 1e-12))) return PC_EDOMAIN;      /* a = b: 0/0 */
        if (npar < 1) k->par[0] = 1, k->npar = 1;
        if (k->par[0] != 1 && k->par[0] != 2 && k->par[0] != 3 && k->par[0] != 4) return PC_EDOMAIN;
        *t0 = eb, *t1 = ea;
        return PC_OK;
    case PC_KC_ELLIPSE_FOCAL:
        if (!(ea >= eb)) return PC_EDOMAIN;
        *t0 = 0, *t1 = 2 * M_PI;
        return PC_OK;
    case PC_KC_ELLIPSE_ALGEBRAIC:
        *t0 = -1, *t1 = 1;
        return PC_OK;
    case PC_KC_HYPERBOLA_ANGLE: case PC_KC_HYPERBOLA_FOCAL: {
        if (npar < 1) k->par[0] = 1, k->npar = 1;
        if (k->par[0] != 1 && k->par[0] != 2) return PC_EDOMAIN;
        double inf = atan2(eb, ea);                /* arcsin(b/c): the asymptotes */
        int br = (int)k->par[0];
        if (kind == PC_KC_HYPERBOLA_ANGLE) {
            *t0 = br == 1 ? -inf : M_PI - inf, *t1 = br == 1 ? inf : M_PI + inf;
        } else {                                   /* cos phi = a/c at the asymptotes */
            double fi = acos(ea / sqrt(ea * ea + eb * eb));
            *t0 = br == 1 ? fi : -fi, *t1 = br == 1 ? 2 * M_PI - fi : fi;
        }
        return PC_OK;
    }
    case PC_KC_HYPERBOLA_RADIUS:
        *t0 = ea, *t1 = 3 * ea;
        return PC_OK;
    case PC_KC_CIRCLE_ANGLE:
        if (npar < 1 || !(par[0] > 0 && par[0] < M_PI)) return PC_EDOMAIN;
        *t0 = 0, *t1 = M_PI;
        return PC_OK;
    case PC_KC_PARABOLA_ANGLE:
        *t0 = 0, *t1 = g;
        return PC_OK;
    case PC_KC_PARABOLA_SIGMA: {
        if (npar < 1) k->par[0] = 1, k->npar = 1;
        if (k->par[0] != 1 && k->par[0] != 2) return PC_EDOMAIN;
        double fa = k->cb, fb = k->ca;             /* Fig. 2.1 notation */
        *t0 = fa * fb / (fa + fb), *t1 = k->par[0] == 1 ? fb : fa;
        return PC_OK;
    }
    case PC_KC_SINUSOID: {
        if (npar < 2 || par[0] != (int)par[0] || par[0] < 1 || par[0] > npar - 1) return PC_EDOMAIN;
        for (int i = 1; i <= (int)par[0]; i++)
            if (!(par[i] > 0)) return PC_EDOMAIN;
        *t0 = 0, *t1 = 2 * M_PI;
        return PC_OK;
    }
    case PC_KC_CYCLOID:
        if (npar < 1) k->par[0] = 0, k->npar = 1;
        if (k->par[0] != 0 && k->par[0] != 1) return PC_EDOMAIN;
        *t0 = 0, *t1 = M_PI;
        return PC_OK;
    default:
        return PC_EDOMAIN;
    }
}

int pc_kcurve_range(pc_kcurve_kind kind, int dim, const double *c, const double *a,
                    const double *b, const double *par, int npar, double *t0, double *t1) {
    kcurve k;
    return kc_setup(&k, kind, dim, c, a, b, par, npar, t0, t1);
}

pc_curve *pc_kcurve(pc_kcurve_kind kind, int dim, const double *c, const double *a,
                    const double *b, const double *par, int npar, double t0, double t1,
                    int *status) {
    kcurve *k = malloc(sizeof *k);
    if (!k) return fail(status, PC_ENOMEM);
    double r0, r1;
    int st = kc_setup(k, kind, dim, c, a, b, par, npar, &r0, &r1);
    if (st) {
        free(k);
        return fail(status, st);
    }
    if (isnan(t0)) t0 = r0;
    if (isnan(t1)) t1 = r1;
    if (!(t1 > t0) || !isfinite(t0) || !isfinite(t1)) {
        free(k);
        return fail(status, PC_EDOMAIN2);
    }
    /* the radial forms have no real points outside their range */
    if ((kind == PC_KC_ELLIPSE_RADIUS && (t0 < r0 - 1e-12 || t1 > r1 + 1e-12)) ||
        (kind == PC_KC_HYPERBOLA_RADIUS && t0 < r0 - 1e-12) ||
        (kind == PC_KC_PARABOLA_SIGMA && (t0 < r0 - 1e-12 || t1 > r1 + 1e-12)) ||
        (kind == PC_KC_ELLIPSE_ALGEBRAIC && (t0 < -1 || t1 > 1)) ||
        (kind == PC_KC_PARABOLA_ANGLE && (t0 < 0 || t1 > r1 + 1e-12))) {
        free(k);
        return fail(status, PC_EDOMAIN3);
    }
    int closed = (kind == PC_KC_ELLIPSE_ANGLE || kind == PC_KC_ELLIPSE_COMPRESSION ||
                  kind == PC_KC_ELLIPSE_FOCAL || kind == PC_KC_CIRCLE_RADIUS ||
                  kind == PC_KC_SINUSOID) && fabs(t1 - t0 - 2 * M_PI) < 1e-12;
    if (kind == PC_KC_CIRCLE_ANGLE && fabs(t1 - t0 - M_PI) < 1e-12) closed = 1;
    pc_curve *cv = pc_curve_func(dim, t0, t1, closed, kc_eval, free, k, status);
    if (!cv) free(k);
    return cv;
}

int pc_ellipse_tilted_axes(int dim, const double *a, const double *b, const double *c,
                           double theta, double m, double n, double *p, double *q) {
    if (dim < 1 || dim > PC_MAXDIM) return PC_EDIM;
    if (!isfinite(theta) || !isfinite(m) || !isfinite(n)) return PC_ENONFINITE;
    if (!(m > 0 && n > 0)) return PC_EDOMAIN;
    double u[PC_MAXDIM], v[PC_MAXDIM], w[PC_MAXDIM];
    for (int i = 0; i < dim; i++) u[i] = b[i] - a[i], v[i] = c[i] - a[i], w[i] = b[i] - c[i];
    double ta = pc_norm(dim, w), tb = pc_norm(dim, v), tc = pc_norm(dim, u), al, ga;
    if (!(ta > 0 && tb > 0 && tc > 0)) return PC_ECOLLINEAR;
    double ca[PC_MAXDIM], cb[PC_MAXDIM];
    for (int i = 0; i < dim; i++) ca[i] = a[i] - c[i], cb[i] = b[i] - c[i];
    if (pc_angle(dim, u, v, &al) || pc_angle(dim, ca, cb, &ga)) return PC_ECOLLINEAR;
    if (sin(al) < PC_DEGEN_TOL || sin(ga) < PC_DEGEN_TOL) return PC_ECOLLINEAR;
    /* Printed algorithm, steps 2-3 (digest §5.1), correct for every theta */
    double pa = m / sin(al) * (sin(theta) / tb - sin(al + theta) / tc);
    double pb = m * sin(al + theta) / (tc * sin(al));
    double qa = n * cos(ga + al + theta) / (tb * sin(ga));
    double qb = -n * cos(al + theta) / (ta * sin(ga));    /* (C - B) n cos(alpha + theta)/(a sin gamma) */
    for (int i = 0; i < dim; i++) {
        p[i] = ca[i] * pa + cb[i] * pb + c[i];
        q[i] = ca[i] * qa + cb[i] * qb + c[i];
    }
    return PC_OK;
}

/* The derivation's auxiliary points of §2.1.1.1 (Fig. 2.5): K = CP x AB with the printed K's
 * missing factor c restored, K = A (c sin theta - b sin(alpha + theta))/(c sin theta) +
 * B b sin(alpha + theta)/(c sin theta), homogeneous (a direction at theta = 0, where CP is
 * parallel to AB); A rotated about C by omega = 3 pi/2 - alpha - theta towards B with the printed
 * (C - A) corrected to (A - C); and tau = angle ACK = pi - alpha - theta (digest §5.1). */
int pc_ellipse_tilted_scheme(int dim, const double *a, const double *b, const double *c,
                             double theta, double *k, double *arot, double *tau) {
    if (dim < 1 || dim > PC_MAXDIM) return PC_EDIM;
    if (!isfinite(theta)) return PC_ENONFINITE;
    double u[PC_MAXDIM], v[PC_MAXDIM], ca[PC_MAXDIM], cb[PC_MAXDIM];
    for (int i = 0; i < dim; i++)
        u[i] = b[i] - a[i], v[i] = c[i] - a[i], ca[i] = a[i] - c[i], cb[i] = b[i] - c[i];
    double ta = pc_norm(dim, cb), tb = pc_norm(dim, v), tc = pc_norm(dim, u), al, ga;
    if (!(ta > 0 && tb > 0 && tc > 0)) return PC_ECOLLINEAR;
    if (pc_angle(dim, u, v, &al) || pc_angle(dim, ca, cb, &ga)) return PC_ECOLLINEAR;
    if (sin(al) < PC_DEGEN_TOL || sin(ga) < PC_DEGEN_TOL) return PC_ECOLLINEAR;
    double w = tc * sin(theta), wa = w - tb * sin(al + theta), wb = tb * sin(al + theta);
    if (fabs(w) < 1e-12 * tc) {           /* K at infinity: the direction of AB, towards B */
        for (int i = 0; i < dim; i++) k[i] = u[i] / tc;
        k[dim] = 0;
    } else {
        for (int i = 0; i < dim; i++) k[i] = (a[i] * wa + b[i] * wb) / w;
        k[dim] = 1;
    }
    double ra = cos(ga + al + theta) / sin(ga), rb = -tb * cos(al + theta) / (ta * sin(ga));
    for (int i = 0; i < dim; i++) arot[i] = ca[i] * ra + cb[i] * rb + c[i];
    *tau = M_PI - al - theta;
    return PC_OK;
}

pc_curve *pc_ellipse_tilted(int dim, const double *a, const double *b, const double *c, double theta,
                            double m, double n, double *out, int *status) {
    double *p = out, *q = out + dim, *k = out + 2 * dim, *arot = k + dim + 1;
    int st = pc_ellipse_tilted_axes(dim, a, b, c, theta, m, n, p, q);
    if (!st) st = pc_ellipse_tilted_scheme(dim, a, b, c, theta, k, arot, arot + dim);
    return st ? fail(status, st) : pc_kcurve(PC_KC_ELLIPSE_ANGLE, dim, c, p, q, NULL, 0, NAN, NAN, status);
}

/* ---- §2.6 the cubic of two cones ------------------------------------------------------------ */

typedef struct {
    int dim;
    double a[PC_MAXDIM], b[PC_MAXDIM], c[PC_MAXDIM], d[PC_MAXDIM], nn[PC_MAXDIM];
    double fp, fq;
} cones;

static void ed_point(int dim, const double *a, const double *b, const double *c, double k,
                     double u, double *out) {
    double ub = 1 - u, den = k * (1 - 2 * u) * (1 - 2 * u) + 2 * u * ub;   /* (2.97) */
    for (int i = 0; i < dim; i++)
        out[i] = (a[i] - c[i]) * k * ub * ub / den + (b[i] - c[i]) * k * u * u / den + c[i];
}

static int cones_at(const cones *s, double u, double *out) {
    double p[PC_MAXDIM], q[PC_MAXDIM], fp = s->fp, fq = s->fq;
    ed_point(s->dim, s->a, s->b, s->c, fp, u, p);
    double v = fp * (1 - fq) * u / (fp * (1 - fq) * u + fq * (1 - fp) * (1 - u));   /* (2.148) */
    if (!isfinite(v)) return PC_EPOLE;
    ed_point(s->dim, s->a, s->b, s->c, fq, v, q);
    return pc_meet(s->dim, s->d, p, s->nn, q, out, NULL, NULL, NULL);     /* M = DP x NQ */
}

static int cones_eval(void *ud, double t, int order, double *out) {
    const cones *s = ud;
    if (order > 0) return PC_EDOMAIN;
    int st = cones_at(s, t, out);
    if (st == PC_ESAME_LINE || st == PC_ECOINCIDENT) {
        /* at u = 0 both generators are the common line AD: the point is the limit */
        double h = 1e-7, m1[PC_MAXDIM + 1], m2[PC_MAXDIM + 1];
        double s1 = t < 0.5 ? t + h : t - h, s2 = t < 0.5 ? t + 2 * h : t - 2 * h;
        if ((st = cones_at(s, s1, m1)) || (st = cones_at(s, s2, m2))) return st;
        for (int i = 0; i <= s->dim; i++) out[i] = 2 * m1[i] - m2[i];
        return PC_OK;
    }
    return st;
}

pc_curve *pc_cubic_cones(int dim, const double *a, const double *b, const double *c,
                         const double *d, double fp, double fq, double n, int *status) {
    if (dim < 3 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    if (!isfinite(fp) || !isfinite(fq) || !isfinite(n)) return fail(status, PC_ENONFINITE);
    if (!(fp > 0 && fp < 1)) return fail(status, PC_EDOMAIN);
    if (!(fq > 0 && fq < 1)) return fail(status, PC_EDOMAIN2);
    if (n == 0 || n == 1) return fail(status, PC_EDOMAIN3);
    cones *s = malloc(sizeof *s);
    if (!s) return fail(status, PC_ENOMEM);
    s->dim = dim, s->fp = fp, s->fq = fq;
    for (int i = 0; i < dim; i++) {
        s->a[i] = a[i], s->b[i] = b[i], s->c[i] = c[i], s->d[i] = d[i];
        s->nn[i] = (d[i] - a[i]) * n + a[i];                  /* (2.156) */
    }
    double e1[PC_MAXDIM], e2[PC_MAXDIM], e3[PC_MAXDIM];
    for (int i = 0; i < dim; i++) e1[i] = a[i] - d[i], e2[i] = b[i] - d[i], e3[i] = c[i] - d[i];
    /* a tetrahedron: the three edges from D independent (Gram determinant) */
    double g11 = pc_dot(dim, e1, e1), g22 = pc_dot(dim, e2, e2), g33 = pc_dot(dim, e3, e3);
    double g12 = pc_dot(dim, e1, e2), g13 = pc_dot(dim, e1, e3), g23 = pc_dot(dim, e2, e3);
    double det = g11 * (g22 * g33 - g23 * g23) - g12 * (g12 * g33 - g23 * g13) + g13 * (g12 * g23 - g22 * g13);
    if (!(det > 1e-18 * g11 * g22 * g33)) {
        free(s);
        return fail(status, PC_ECOLLINEAR);
    }
    pc_curve *cv = pc_curve_func(dim, 0, 1, 0, cones_eval, free, s, status);
    if (!cv) free(s);
    return cv;
}

/* ---- (2.161) the general contour arc ------------------------------------------------------ */

typedef struct {
    int dim, has_d;
    double a1[PC_MAXDIM], a2[PC_MAXDIM], a3[PC_MAXDIM];
    pc_real_fn f;
    void (*ffree)(void *);
    void *ud;
} contour;

static void contour_free(void *p) {
    contour *s = p;
    if (s->ffree) s->ffree(s->ud);
    free(s);
}

static double deriv(const contour *s, int which, double t) {
    if (s->has_d) return s->f(s->ud, which + 2, t);
    double h = 1e-6;
    return (s->f(s->ud, which, t + h) - s->f(s->ud, which, t - h)) / (2 * h);
}

static int contour_eval(void *ud, double t, int order, double *out) {
    const contour *s = ud;
    int n = s->dim;
    if (order > 0) return PC_EDOMAIN;
    if (t == 0 || t == 1) {           /* the limits A1, A2 (0/0 in general) */
        const double *e = t == 0 ? s->a1 : s->a2;
        for (int i = 0; i < n; i++) out[i] = e[i];
        out[n] = 1;
        return PC_OK;
    }
    double u = s->f(s->ud, 0, t), v = s->f(s->ud, 1, t), du = deriv(s, 0, t), dv = deriv(s, 1, t);
    if (!isfinite(u) || !isfinite(v) || !isfinite(du) || !isfinite(dv)) return PC_ENONFINITE;
    /* (2.161) over its denominator u'v + v'(1 - u) */
    double w1 = dv * (1 - u) * (1 - u), w2 = du * v * v, w3 = du * v * (1 - v) + dv * u * (1 - u);
    for (int i = 0; i < n; i++) out[i] = w1 * s->a1[i] + w2 * s->a2[i] + w3 * s->a3[i];
    out[n] = w1 + w2 + w3;
    return PC_OK;
}

pc_curve *pc_contour_arc(int dim, const double *a1, const double *a2, const double *a3,
                         pc_real_fn f, int has_derivs, void (*fn_free)(void *ud), void *ud,
                         int *status) {
    if (dim < 1 || dim > PC_MAXDIM) return fail(status, PC_EDIM);
    contour *s = malloc(sizeof *s);
    if (!s) return fail(status, PC_ENOMEM);
    s->dim = dim, s->has_d = has_derivs, s->f = f, s->ud = ud, s->ffree = NULL;
    memcpy(s->a1, a1, sizeof(double) * (size_t)dim);
    memcpy(s->a2, a2, sizeof(double) * (size_t)dim);
    memcpy(s->a3, a3, sizeof(double) * (size_t)dim);
    pc_curve *cv = pc_curve_func(dim, 0, 1, 0, contour_eval, contour_free, s, status);
    if (!cv) {
        free(s);
        return NULL;
    }
    s->ffree = fn_free;   /* owned from here on */
    return cv;
}
