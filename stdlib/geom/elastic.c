/* The elastic reference curve (least bending energy through points, free length) and the
 * measures that compare a model with it.  See elastic.h and korotky_curves_surfaces.md A.11. */
#include "elastic.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdio.h>
#include "optimize.h"

/* 16-point Gauss-Legendre on [0, 1] (nodes and weights of the symmetric half). */
static const double GL_X[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274,
                               0.6178762444026438, 0.7554044083550030, 0.8656312023878318,
                               0.9445750230732326, 0.9894009349916499};
static const double GL_W[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025,
                               0.1495959888165767, 0.1246289712555339, 0.0951585116824928,
                               0.0622535239386479, 0.0271524594117541};

static double cross2(const double *a, const double *b) { return a[0] * b[1] - a[1] * b[0]; }

/* kappa^2 |r'| from the first and second derivatives (any dimension). */
static double kappa2_speed(int dim, const double *d1, const double *d2) {
    double s11 = 0, s22 = 0, s12 = 0;
    for (int k = 0; k < dim; k++) {
        s11 += d1[k] * d1[k];
        s22 += d2[k] * d2[k];
        s12 += d1[k] * d2[k];
    }
    double c2 = s11 * s22 - s12 * s12;   /* |r' x r''|^2 */
    return (c2 > 0 ? c2 : 0) / pow(s11, 2.5);
}

/* ---- the Hermite pieces of the elastic model ---------------------------------------------- */

/* Energy of one plane Hermite piece (eq. (10)) from P0 to P1 with derivatives d0, d1. */
static double piece_energy(const double *P0, const double *P1, const double *d0, const double *d1) {
    double e = 0;
    for (int k = 0; k < 16; k++) {
        double t = k < 8 ? 0.5 - 0.5 * GL_X[7 - k] : 0.5 + 0.5 * GL_X[k - 8];
        double w = 0.5 * GL_W[k < 8 ? 7 - k : k - 8];
        double dh[4] = {-6 * t + 6 * t * t, 6 * t - 6 * t * t, 1 - 4 * t + 3 * t * t, -2 * t + 3 * t * t};
        double ddh[4] = {-6 + 12 * t, 6 - 12 * t, -4 + 6 * t, -2 + 6 * t};
        double r1[2], r2[2];
        for (int i = 0; i < 2; i++) {
            r1[i] = dh[0] * P0[i] + dh[1] * P1[i] + dh[2] * d0[i] + dh[3] * d1[i];
            r2[i] = ddh[0] * P0[i] + ddh[1] * P1[i] + ddh[2] * d0[i] + ddh[3] * d1[i];
        }
        double c = cross2(r1, r2), s = hypot(r1[0], r1[1]);
        if (!(s > 0)) return INFINITY;
        e += w * c * c / pow(s, 5);
    }
    return e;
}

#define EL_MAXNODES (4 * (PC_ELASTIC_MAXN - 1) + 1)

/* A free node inside a span moves along the normal of the starting spline at its start
 * position: sliding along the curve would barely change the energy, a flat valley that
 * slows the minimisation down a hundredfold without changing the shape. */
typedef struct {
    int n, K, nodes, clamped;
    const double *p;
    double ends[2];
    double base[2 * EL_MAXNODES], normal[2 * EL_MAXNODES];
} elastic_ctx;

/* Unpack the unknowns: node positions xy (nodes rows of 2), angles th (nodes), moduli m
 * (2 per piece).  Layout: angles of the free nodes (all, or all but the two ends when
 * clamped), then the free interior nodes' offsets along their normals, then the log
 * moduli. */
static void unpack(const elastic_ctx *e, const double *v, double *xy, double *th, double *m) {
    int N = e->nodes, k = 0;
    for (int j = 0; j < N; j++) {
        if (e->clamped && (j == 0 || j == N - 1)) th[j] = e->ends[j ? 1 : 0];
        else th[j] = v[k++];
    }
    for (int j = 0; j < N; j++) {
        if (j % e->K == 0) {
            xy[2 * j] = e->p[2 * (j / e->K)];
            xy[2 * j + 1] = e->p[2 * (j / e->K) + 1];
        } else {
            double o = v[k++];
            xy[2 * j] = e->base[2 * j] + o * e->normal[2 * j];
            xy[2 * j + 1] = e->base[2 * j + 1] + o * e->normal[2 * j + 1];
        }
    }
    for (int j = 0; j < 2 * (N - 1); j++) m[j] = exp(v[k++]);
}

static int nunknowns(const elastic_ctx *e) {
    int N = e->nodes;
    return (e->clamped ? N - 2 : N) + (N - 1 - (e->n - 1)) + 2 * (N - 1);
}

static double energy_of(void *ud, const double *v) {
    const elastic_ctx *e = ud;
    double xy[2 * EL_MAXNODES], th[EL_MAXNODES], m[2 * EL_MAXNODES];
    unpack(e, v, xy, th, m);
    double E = 0;
    for (int j = 0; j + 1 < e->nodes; j++) {
        double d0[2] = {m[2 * j] * cos(th[j]), m[2 * j] * sin(th[j])};
        double d1[2] = {m[2 * j + 1] * cos(th[j + 1]), m[2 * j + 1] * sin(th[j + 1])};
        E += piece_energy(xy + 2 * j, xy + 2 * j + 2, d0, d1);
    }
    return E;
}

pc_curve *pc_elastic(int n, const double *p, int pieces, const double *end_angles,
                     double *energy, int *status) {
    if (n < 2 || n > PC_ELASTIC_MAXN || pieces < 1 || pieces > 4) {
        *status = PC_EDIM;
        return NULL;
    }
    for (int i = 0; i < 2 * n; i++)
        if (!isfinite(p[i])) {
            *status = PC_ENONFINITE;
            return NULL;
        }
    if (end_angles && (!isfinite(end_angles[0]) || !isfinite(end_angles[1]))) {
        *status = PC_ENONFINITE;
        return NULL;
    }
    for (int i = 1; i < n; i++)
        if (p[2 * i] == p[2 * i - 2] && p[2 * i + 1] == p[2 * i - 1]) {
            *status = PC_ECOINCIDENT;
            return NULL;
        }
    static const elastic_ctx zero;
    elastic_ctx e = zero;
    e.n = n;
    e.K = pieces;
    e.nodes = (n - 1) * pieces + 1;
    e.clamped = end_angles != NULL;
    e.p = p;
    if (end_angles) {
        e.ends[0] = end_angles[0];
        e.ends[1] = end_angles[1];
    }
    int nv = nunknowns(&e);
    if (nv > PC_NEWTON_MAXN) {
        *status = PC_EDIM;
        return NULL;
    }
    /* start: the natural (or clamped) chord-length cubic spline */
    double d0[2], d1[2];
    if (end_angles) {
        d0[0] = cos(end_angles[0]); d0[1] = sin(end_angles[0]);
        d1[0] = cos(end_angles[1]); d1[1] = sin(end_angles[1]);
    }
    pc_curve *s = pc_curve_cubic_spline(2, n, p, NULL, end_angles ? PC_END_CLAMPED : PC_END_NATURAL,
                                        d0, d1, status);
    if (!s) return NULL;
    double v[PC_NEWTON_MAXN];
    int N = e.nodes, k = 0;
    double nodeu[EL_MAXNODES], dd[3 * 2];
    for (int j = 0; j < N; j++) {
        int span = j / pieces, sub = j % pieces;
        double ua = s->knots[span < n - 1 ? span : n - 2], ub = s->knots[span < n - 1 ? span + 1 : n - 1];
        nodeu[j] = span < n - 1 ? ua + (ub - ua) * sub / pieces : s->knots[n - 1];
    }
    for (int j = 0; j < N; j++) {
        pc_curve_derivs(s, nodeu[j], 1, dd);
        if (!(e.clamped && (j == 0 || j == N - 1))) v[k++] = atan2(dd[3], dd[2]);
    }
    for (int j = 0; j < N; j++)
        if (j % pieces) {
            pc_curve_derivs(s, nodeu[j], 1, dd);
            double l = hypot(dd[2], dd[3]);
            e.base[2 * j] = dd[0];
            e.base[2 * j + 1] = dd[1];
            e.normal[2 * j] = l > 0 ? -dd[3] / l : 0;
            e.normal[2 * j + 1] = l > 0 ? dd[2] / l : 0;
            v[k++] = 0;
        }
    for (int j = 0; j + 1 < N; j++) {
        double du = nodeu[j + 1] - nodeu[j];
        pc_curve_derivs(s, nodeu[j], 1, dd);
        v[k++] = log(fmax(1e-6, hypot(dd[2], dd[3]) * du));
        pc_curve_derivs(s, nodeu[j + 1], 1, dd);
        v[k++] = log(fmax(1e-6, hypot(dd[2], dd[3]) * du));
    }
    pc_curve_release(s);
    double E;
    int iters = 0;
    int st = pc_minimize(nv, energy_of, &e, v, 1e-8, 1e-6, 20000, &E, &iters);
    if (getenv("PC_ELASTIC_DEBUG")) fprintf(stderr, "elastic: %d iterations, status %d, E %.9g\n", iters, st, E);
    if (st != PC_OK) {
        *status = st;
        return NULL;
    }
    double xy[2 * EL_MAXNODES], th[EL_MAXNODES], m[2 * EL_MAXNODES];
    double dout[2 * EL_MAXNODES], din[2 * EL_MAXNODES], u[EL_MAXNODES];
    unpack(&e, v, xy, th, m);
    for (int j = 0; j < N; j++) {
        u[j] = (double)j / pieces;
        /* a piece spans 1/pieces of the parameter: d/du = pieces d/dt */
        double mo = j < N - 1 ? m[2 * j] : m[2 * j - 1], mi = j > 0 ? m[2 * j - 1] : m[0];
        dout[2 * j] = pieces * mo * cos(th[j]);
        dout[2 * j + 1] = pieces * mo * sin(th[j]);
        din[2 * j] = pieces * mi * cos(th[j]);
        din[2 * j + 1] = pieces * mi * sin(th[j]);
    }
    if (energy) *energy = E;
    return pc_curve_hermite(2, N, xy, dout, din, u, 0, status);
}

/* ---- measures ------------------------------------------------------------------------------- */

/* The breakpoints of c over its domain (at most max), into br; their number. */
static int breaks(const pc_curve *c, double *br, int max) {
    int nb = 0;
    br[nb++] = c->t0;
    if (c->nknots > 0)
        for (int i = 0; i < c->nknots && nb < max - 1; i++)
            if (c->knots[i] > br[nb - 1] && c->knots[i] < c->t1) br[nb++] = c->knots[i];
    br[nb++] = c->t1;
    return nb;
}

#define MAXBREAKS 4096

int pc_curve_bending_energy(const pc_curve *c, double *energy) {
    double *br = malloc(sizeof(double) * MAXBREAKS);
    if (!br) return PC_ENOMEM;
    int nb = breaks(c, br, MAXBREAKS), st = PC_OK;
    double E = 0, d[3 * PC_MAXDIM];
    for (int i = 0; i + 1 < nb && st == PC_OK; i++)
        for (int part = 0; part < 8 && st == PC_OK; part++) {
            double a = br[i] + (br[i + 1] - br[i]) * part / 8, b = br[i] + (br[i + 1] - br[i]) * (part + 1) / 8;
            for (int k = 0; k < 16; k++) {
                double x = k < 8 ? 0.5 - 0.5 * GL_X[7 - k] : 0.5 + 0.5 * GL_X[k - 8];
                double w = 0.5 * GL_W[k < 8 ? 7 - k : k - 8];
                /* inside a piece, never at its ends: each piece uses its own polynomial */
                st = pc_curve_derivs(c, a + (b - a) * x, 2, d);
                if (st != PC_OK) break;
                E += w * (b - a) * kappa2_speed(c->dim, d + c->dim, d + 2 * c->dim);
            }
        }
    free(br);
    if (st == PC_OK && !isfinite(E)) st = PC_EZERO;
    if (st == PC_OK) *energy = E;
    return st;
}

/* Curvature (signed in the plane) and the unit tangent from the derivatives. */
static int curv_tan(int dim, const double *d1, const double *d2, double *k, double *t) {
    double s = 0;
    for (int i = 0; i < dim; i++) s += d1[i] * d1[i];
    s = sqrt(s);
    if (!(s > 0)) return PC_EZERO;
    for (int i = 0; i < dim; i++) t[i] = d1[i] / s;
    *k = dim == 2 ? cross2(d1, d2) / (s * s * s) : sqrt(kappa2_speed(dim, d1, d2) / s);
    return PC_OK;
}

int pc_curve_joint_jumps(const pc_curve *c, double *dk, double *dangle, int *at) {
    *dk = *dangle = 0;
    if (at) *at = 0;
    if (c->kind != PC_CURVE_BEZIER || c->nknots < 3) return PC_OK;
    int w = c->dim + 1, deg = c->degree, st = PC_OK;
    pc_curve *prev = NULL;
    for (int i = 0; i + 1 < c->nknots && st == PC_OK; i++) {
        /* piece i as a Bezier curve over [0, 1]: its own end derivatives, exactly */
        pc_curve *piece = pc_curve_bezier(c->dim, deg + 1, c->cp + (size_t)i * deg * w, &st);
        if (!piece) break;
        if (prev) {
            double dl[3 * PC_MAXDIM], dr[3 * PC_MAXDIM], tl[PC_MAXDIM], tr[PC_MAXDIM], kl, kr;
            st = pc_curve_derivs(prev, 1, 2, dl);
            if (st == PC_OK) st = pc_curve_derivs(piece, 0, 2, dr);
            if (st == PC_OK) st = curv_tan(c->dim, dl + c->dim, dl + 2 * c->dim, &kl, tl);
            if (st == PC_OK) st = curv_tan(c->dim, dr + c->dim, dr + 2 * c->dim, &kr, tr);
            if (st == PC_OK) {
                /* the angle from its sine and cosine: acos alone loses half the digits near 0 */
                double cs = 0, sn2 = 0;
                for (int k = 0; k < c->dim; k++) cs += tl[k] * tr[k];
                for (int k = 0; k < c->dim; k++) sn2 += (tr[k] - cs * tl[k]) * (tr[k] - cs * tl[k]);
                double ang = atan2(sqrt(sn2), cs);
                if (fabs(kl - kr) > *dk) {
                    *dk = fabs(kl - kr);
                    if (at) *at = i;
                }
                if (ang > *dangle) *dangle = ang;
            }
            pc_curve_release(prev);
        }
        prev = piece;
    }
    pc_curve_release(prev);
    return st;
}

/* ---- Hausdorff distance --------------------------------------------------------------------- */

typedef struct {
    const pc_curve *c;
    int n;            /* samples */
    double *t, *x;    /* parameters and points (n rows of dim) */
} sampled;

static int sample(const pc_curve *c, int per, sampled *s) {
    double *br = malloc(sizeof(double) * MAXBREAKS);
    if (!br) return PC_ENOMEM;
    int nb = breaks(c, br, MAXBREAKS);
    s->c = c;
    s->n = (nb - 1) * per + 1;
    s->t = malloc(sizeof(double) * (size_t)s->n * (1 + (size_t)c->dim));
    if (!s->t) {
        free(br);
        return PC_ENOMEM;
    }
    s->x = s->t + s->n;
    int st = PC_OK, k = 0;
    for (int i = 0; i + 1 < nb; i++)
        for (int j = 0; j < per; j++) s->t[k++] = br[i] + (br[i + 1] - br[i]) * j / per;
    s->t[k] = c->t1;
    for (int i = 0; i < s->n && st == PC_OK; i++)
        st = pc_curve_eval(c, s->t[i], s->x + (size_t)i * c->dim);
    free(br);
    return st;
}

static double dist2(int dim, const double *a, const double *b) {
    double s = 0;
    for (int k = 0; k < dim; k++) s += (a[k] - b[k]) * (a[k] - b[k]);
    return s;
}

/* The distance from the point q to the sampled curve s: nearest sample, then golden section
 * on the parameter between its neighbours. */
static int point_curve(const sampled *s, const double *q, double *d) {
    int dim = s->c->dim, best = 0;
    double bd = INFINITY;
    for (int i = 0; i < s->n; i++) {
        double e = dist2(dim, q, s->x + (size_t)i * dim);
        if (e < bd) { bd = e; best = i; }
    }
    double a = s->t[best > 0 ? best - 1 : 0], b = s->t[best < s->n - 1 ? best + 1 : s->n - 1];
    const double g = 0.6180339887498949;
    double x1 = b - g * (b - a), x2 = a + g * (b - a), p[PC_MAXDIM], f1, f2;
    int st = pc_curve_eval(s->c, x1, p);
    f1 = dist2(dim, q, p);
    if (st == PC_OK) st = pc_curve_eval(s->c, x2, p);
    f2 = dist2(dim, q, p);
    for (int it = 0; it < 60 && st == PC_OK; it++) {
        if (f1 < f2) {
            b = x2; x2 = x1; f2 = f1; x1 = b - g * (b - a);
            st = pc_curve_eval(s->c, x1, p);
            f1 = dist2(dim, q, p);
        } else {
            a = x1; x1 = x2; f1 = f2; x2 = a + g * (b - a);
            st = pc_curve_eval(s->c, x2, p);
            f2 = dist2(dim, q, p);
        }
    }
    *d = sqrt(fmin(bd, fmin(f1, f2)));
    return st;
}

int pc_curve_hausdorff(const pc_curve *a, const pc_curve *b, int samples, double *d) {
    if (a->dim != b->dim) return PC_EDIM;
    if (samples < 8) samples = 8;
    if (samples > 4096) samples = 4096;
    sampled sa = {0}, sb = {0};
    int st = sample(a, samples, &sa);
    if (st == PC_OK) st = sample(b, samples, &sb);
    double h = 0;
    for (int pass = 0; pass < 2 && st == PC_OK; pass++) {
        const sampled *from = pass ? &sb : &sa, *to = pass ? &sa : &sb;
        for (int i = 0; i < from->n && st == PC_OK; i++) {
            double e;
            st = point_curve(to, from->x + (size_t)i * a->dim, &e);
            if (e > h) h = e;
        }
    }
    free(sa.t);
    free(sb.t);
    if (st == PC_OK) *d = h;
    return st;
}
