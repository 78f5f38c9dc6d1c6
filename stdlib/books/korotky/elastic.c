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
        double c = cross2(r1, r2), s2 = r1[0] * r1[0] + r1[1] * r1[1];
        if (!(s2 > 0)) return INFINITY;
        e += w * c * c / (s2 * s2 * sqrt(s2));
    }
    return e;
}

#define EL_MAXNODES (4 * (PC_ELASTIC_MAXN - 1) + 1)

/* The model is a C2 cubic spline through the pins and the free interior nodes (K per span),
 * in a parameter of its own: the unknowns are the parameter steps h_j (logarithms; the first
 * is fixed, a common scale does not change the curve), the free nodes' offsets along the
 * normal of the starting spline (sliding along the curve would barely change the energy, a
 * flat valley that slows the minimisation down), and with clamped ends the two end speeds.
 * Natural ends (r'' = 0) give kappa = 0 at free ends, as a ruler with unloaded ends has.
 * A spline's derivatives follow from the nodes and steps by one tridiagonal solve, so the
 * model is curvature-continuous by construction: the real ruler is, because a frictionless
 * pin applies a force, not a moment, and the bending moment EI kappa passes it unchanged. */
typedef struct {
    int n, K, nodes, clamped;
    const double *p;
    double length, lambda, mu;  /* a fixed length: the augmented Lagrangian's target, multiplier, weight */
    double ends[4];            /* clamped: the unit end directions */
    double base[2 * EL_MAXNODES], normal[2 * EL_MAXNODES];
} elastic_ctx;

static int nunknowns(const elastic_ctx *e) {
    return (e->nodes - 2) + (e->nodes - e->n) + (e->clamped ? 2 : 0);
}

/* Nodes xy (rows of 2) and steps h from the unknowns; end speeds into sp (clamped). */
static void unpack(const elastic_ctx *e, const double *v, double *xy, double *h, double *sp) {
    int N = e->nodes, k = 0;
    h[0] = 1;
    for (int j = 1; j < N - 1; j++) h[j] = exp(v[k++]);
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
    if (e->clamped) {
        sp[0] = exp(v[k++]);
        sp[1] = exp(v[k++]);
    }
}

/* The derivatives D (rows of 2, per unit of the spline's parameter) of the C2 cubic spline
 * through xy with steps h: h_j D_(j-1) + 2 (h_(j-1) + h_j) D_j + h_(j-1) D_(j+1)
 * = 3 (h_j dX_(j-1) / h_(j-1) + h_(j-1) dX_j / h_j), natural ends 2 D_0 + D_1 = 3 dX_0 / h_0,
 * or the end derivatives given (Thomas algorithm: the matrix is diagonally dominant). */
static void spline_derivs(int N, const double *xy, const double *h, const double *d0,
                          const double *d1, double *D) {
    double cprime[EL_MAXNODES];
    for (int j = 0; j < N; j++) {
        double a = 0, b, c = 0, r[2];
        if (j == 0) {
            if (d0) { b = 1; r[0] = d0[0]; r[1] = d0[1]; }
            else {
                b = 2; c = 1;
                for (int k = 0; k < 2; k++) r[k] = 3 * (xy[2 + k] - xy[k]) / h[0];
            }
        } else if (j == N - 1) {
            if (d1) { b = 1; r[0] = d1[0]; r[1] = d1[1]; }
            else {
                a = 1; b = 2;
                for (int k = 0; k < 2; k++) r[k] = 3 * (xy[2 * j + k] - xy[2 * j - 2 + k]) / h[j - 1];
            }
        } else {
            a = h[j]; b = 2 * (h[j - 1] + h[j]); c = h[j - 1];
            for (int k = 0; k < 2; k++)
                r[k] = 3 * (h[j] * (xy[2 * j + k] - xy[2 * j - 2 + k]) / h[j - 1] +
                            h[j - 1] * (xy[2 * j + 2 + k] - xy[2 * j + k]) / h[j]);
        }
        if (j > 0) {   /* forward elimination */
            double m = b - a * cprime[j - 1];
            b = m;
            r[0] -= a * D[2 * j - 2];
            r[1] -= a * D[2 * j - 1];
        }
        cprime[j] = c / b;
        D[2 * j] = r[0] / b;
        D[2 * j + 1] = r[1] / b;
    }
    for (int j = N - 2; j >= 0; j--) {
        D[2 * j] -= cprime[j] * D[2 * j + 2];
        D[2 * j + 1] -= cprime[j] * D[2 * j + 3];
    }
}

/* The model's nodes and derivatives (per unit of its parameter) for the unknowns v. */
static void model(const elastic_ctx *e, const double *v, double *xy, double *h, double *D) {
    double sp[2], d0[2], d1[2];
    unpack(e, v, xy, h, sp);
    if (e->clamped) {
        d0[0] = sp[0] * e->ends[0]; d0[1] = sp[0] * e->ends[1];
        d1[0] = sp[1] * e->ends[2]; d1[1] = sp[1] * e->ends[3];
    }
    spline_derivs(e->nodes, xy, h, e->clamped ? d0 : NULL, e->clamped ? d1 : NULL, D);
}

/* Length of one plane Hermite piece (16-point Gauss-Legendre on two halves). */
static double piece_length(const double *P0, const double *P1, const double *d0, const double *d1) {
    double len = 0;
    for (int half = 0; half < 2; half++)
        for (int k = 0; k < 16; k++) {
            double x = k < 8 ? 0.5 - 0.5 * GL_X[7 - k] : 0.5 + 0.5 * GL_X[k - 8];
            double t = 0.5 * (half + x), w = 0.25 * GL_W[k < 8 ? 7 - k : k - 8];
            double dh[4] = {-6 * t + 6 * t * t, 6 * t - 6 * t * t, 1 - 4 * t + 3 * t * t, -2 * t + 3 * t * t};
            double r0 = dh[0] * P0[0] + dh[1] * P1[0] + dh[2] * d0[0] + dh[3] * d1[0];
            double r1 = dh[0] * P0[1] + dh[1] * P1[1] + dh[2] * d0[1] + dh[3] * d1[1];
            len += w * hypot(r0, r1);
        }
    return len;
}

/* The bending energy of the model and (if len is not NULL) its length. */
static double energy_length(const elastic_ctx *e, const double *v, double *len) {
    double xy[2 * EL_MAXNODES], h[EL_MAXNODES], D[2 * EL_MAXNODES];
    model(e, v, xy, h, D);
    double E = 0, S = 0;
    for (int j = 0; j + 1 < e->nodes; j++) {
        /* piece j over t in [0, 1]: d/dt = h_j d/du */
        double d0[2] = {h[j] * D[2 * j], h[j] * D[2 * j + 1]};
        double d1[2] = {h[j] * D[2 * j + 2], h[j] * D[2 * j + 3]};
        E += piece_energy(xy + 2 * j, xy + 2 * j + 2, d0, d1);
        if (len) S += piece_length(xy + 2 * j, xy + 2 * j + 2, d0, d1);
    }
    if (len) *len = S;
    return E;
}

/* The objective: the energy, with a fixed length the augmented Lagrangian
 * E + lambda (S - L) + mu/2 (S - L)^2 (its minimisers tend to the constrained minimum as
 * lambda is updated, without mu growing: the problem stays well conditioned). */
static double energy_of(void *ud, const double *v) {
    const elastic_ctx *e = ud;
    if (!(e->length > 0)) return energy_length(e, v, NULL);
    double S, E = energy_length(e, v, &S), g = S - e->length;
    return E + e->lambda * g + 0.5 * e->mu * g * g;
}

pc_curve *pc_elastic(int n, const double *p, int pieces, const double *end_angles,
                     double *energy, int *status) {
    return pc_elastic_length(n, p, pieces, end_angles, 0, energy, status);
}

pc_curve *pc_elastic_length(int n, const double *p, int pieces, const double *end_angles,
                            double length, double *energy, int *status) {
    if (n < 2 || n > PC_ELASTIC_MAXN || pieces < 0 || pieces > 4) {
        *status = PC_EDIM;
        return NULL;
    }
    if (pieces == 0)   /* the most pieces (up to 4) whose unknowns the minimiser takes */
        for (pieces = 4; pieces > 1; pieces--)
            if (2 * (n - 1) * pieces - n + (end_angles ? 2 : 0) <= PC_NEWTON_MAXN) break;
    for (int i = 0; i < 2 * n; i++)
        if (!isfinite(p[i])) {
            *status = PC_ENONFINITE;
            return NULL;
        }
    if ((end_angles && (!isfinite(end_angles[0]) || !isfinite(end_angles[1]))) || !isfinite(length)) {
        *status = PC_ENONFINITE;
        return NULL;
    }
    for (int i = 1; i < n; i++)
        if (p[2 * i] == p[2 * i - 2] && p[2 * i + 1] == p[2 * i - 1]) {
            *status = PC_ECOINCIDENT;
            return NULL;
        }
    if (length != 0) {   /* a curve through the points is longer than their polyline */
        double poly = 0;
        for (int i = 1; i < n; i++) poly += hypot(p[2 * i] - p[2 * i - 2], p[2 * i + 1] - p[2 * i - 1]);
        if (!(length > poly * (1 + 1e-9))) {
            *status = PC_EDOMAIN;
            return NULL;
        }
    }
    static const elastic_ctx zero;
    elastic_ctx e = zero;
    e.n = n;
    e.K = pieces;
    e.nodes = (n - 1) * pieces + 1;
    e.clamped = end_angles != NULL;
    e.p = p;
    if (end_angles) {
        e.ends[0] = cos(end_angles[0]); e.ends[1] = sin(end_angles[0]);
        e.ends[2] = cos(end_angles[1]); e.ends[3] = sin(end_angles[1]);
    }
    int nv = nunknowns(&e), N = e.nodes, k = 0;
    if (nv > PC_NEWTON_MAXN) {
        *status = PC_EDIM;
        return NULL;
    }
    double v[PC_NEWTON_MAXN] = {0}, E = 0;
    if (nv > 0) {
        /* start: the chord-length natural (or clamped) cubic spline, its nodes at equal
         * parameter steps inside each span */
        pc_curve *s = pc_curve_cubic_spline(2, n, p, NULL, end_angles ? PC_END_CLAMPED : PC_END_NATURAL,
                                            e.ends, e.ends + 2, status);
        if (!s) return NULL;
        double nodeu[EL_MAXNODES], dd[3 * 2];
        for (int j = 0; j < N; j++) {
            int span = j / pieces, sub = j % pieces;
            nodeu[j] = span < n - 1 ? s->knots[span] + (s->knots[span + 1] - s->knots[span]) * sub / pieces
                                    : s->knots[n - 1];
        }
        double h0 = nodeu[1] - nodeu[0];
        for (int j = 1; j < N - 1; j++) v[k++] = log((nodeu[j + 1] - nodeu[j]) / h0);
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
        if (e.clamped) {   /* the spline's end speeds in units of the first step */
            v[k++] = log(h0);
            v[k++] = log(h0);
        }
        pc_curve_release(s);
        int iters = 0;
        int st = pc_minimize(nv, energy_of, &e, v, 1e-8, 1e-6, 20000, &E, &iters);
        if (getenv("PC_ELASTIC_DEBUG")) fprintf(stderr, "elastic: %d unknowns, %d iterations, status %d, E %.9g\n", nv, iters, st, E);
        if (st == PC_OK && length > 0) {
            /* the fixed length (a clamped ruler keeps its length between the clamps): from the
             * free minimum, the augmented Lagrangian's outer loop, lambda += mu (S - L) */
            e.length = length;
            e.mu = 100;
            double S = 0;
            int outer = 0;
            st = PC_ENOCONVERGE;
            for (; outer < 40; outer++) {
                /* an inner minimisation stopped by its iteration limit still improves v: the
                 * outer loop decides by the length met */
                int s2 = pc_minimize(nv, energy_of, &e, v, 1e-9, 1e-6, 5000, NULL, &iters);
                if (s2 != PC_OK && s2 != PC_ENOCONVERGE) { st = s2; break; }
                energy_length(&e, v, &S);
                if (getenv("PC_ELASTIC_DEBUG"))
                    fprintf(stderr, "elastic: outer %d, %d iterations, S - L %.3g\n", outer, iters, S - length);
                if (fabs(S - length) <= 1e-8 * length) { st = PC_OK; break; }
                e.lambda += e.mu * (S - length);
            }
            if (st == PC_ENOCONVERGE && fabs(S - length) <= 1e-6 * length) st = PC_OK;
            E = energy_length(&e, v, NULL);
        }
        if (st != PC_OK) {
            *status = st;
            return NULL;
        }
    } else if (length > 0) {
        *status = PC_EDIM;   /* nothing free: the length cannot be met (two points, one piece) */
        return NULL;
    }
    double xy[2 * EL_MAXNODES], h[EL_MAXNODES], D[2 * EL_MAXNODES];
    double dout[2 * EL_MAXNODES], din[2 * EL_MAXNODES], u[EL_MAXNODES];
    model(&e, v, xy, h, D);
    if (nv == 0) E = energy_length(&e, v, NULL);
    /* span i of the result runs over [i, i + 1]: its pieces keep their parameter ratios, so
     * the curve is C2 inside a span and at a pin only the speed changes (curvature and
     * tangent are continuous there) */
    for (int i = 0; i + 1 < n; i++) {
        double len = 0;
        for (int q = 0; q < pieces; q++) len += h[i * pieces + q];
        double acc = 0;
        for (int q = 0; q <= pieces; q++) {
            int j = i * pieces + q;
            if (q < pieces) {
                u[j] = i + acc / len;
                dout[2 * j] = D[2 * j] * len;
                dout[2 * j + 1] = D[2 * j + 1] * len;
                acc += h[j];
            }
            if (q > 0) {
                din[2 * j] = D[2 * j] * len;
                din[2 * j + 1] = D[2 * j + 1] * len;
            }
        }
    }
    u[N - 1] = n - 1;
    dout[2 * (N - 1)] = din[2 * (N - 1)];
    dout[2 * (N - 1) + 1] = din[2 * (N - 1) + 1];
    din[0] = dout[0];
    din[1] = dout[1];
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
