/* Surfaces built from curves (surface.h): ruled (Buimov §5.3), the linear Coons patch
 * (§5.4: the boolean sum of two ruled surfaces less the bilinear one of the corners) and
 * surfaces of revolution (Rodrigues' rotation of the profile about the axis).  They evaluate
 * the curves' Cartesian points and derivatives, so rational curves (conic arcs) stay exact;
 * the homogeneous value has weight 1. */
#include "surface.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define HROW (PC_MAXDIM + 1)

/* The point (and with order 1 the derivative d/ds) of c at s in [0, 1] mapped onto its
 * domain as (1 - s) t0 + s t1, exact at both ends: out (order+1) rows of dim. */
static int curve_at01(const pc_curve *c, double s, int order, double *out) {
    double t = (1 - s) * c->t0 + s * c->t1;
    int st = pc_curve_derivs(c, t, order, out);
    if (st != PC_OK) return st;
    if (order)
        for (int i = 0; i < c->dim; i++) out[c->dim + i] *= c->t1 - c->t0;
    return PC_OK;
}

static int bad_curve(const pc_curve *c) {
    return !c || c->dim < 1 || c->dim > PC_MAXDIM;
}

pc_surface *pc_surface_ruled(pc_curve *c0, pc_curve *c1, int *status) {
    int st = PC_OK;
    pc_surface *s = NULL;
    if (bad_curve(c0) || bad_curve(c1))
        st = PC_EARG;
    else if (c0->dim != c1->dim)
        st = PC_EDIM;
    else if ((s = pc_surf_alloc(PC_SURF_RULED, c0->dim, &st))) {
        s->curves[0] = pc_curve_retain(c0);
        s->curves[1] = pc_curve_retain(c1);
        s->u0 = 0, s->u1 = 1, s->v0 = 0, s->v1 = 1;
    }
    if (status) *status = st;
    return s;
}

/* The linear Coons patch keeps its corners P00, P10, P01, P11 in cp (4 rows of dim+1, weight
 * 1), each the mean of the two curve ends that meet there. */
pc_surface *pc_surface_coons(pc_curve *cu0, pc_curve *cu1, pc_curve *c0v, pc_curve *c1v,
                             int *status) {
    int st = PC_OK;
    pc_surface *s = NULL;
    pc_curve *c[4] = {cu0, cu1, c0v, c1v};
    int n = 0;
    for (int k = 0; k < 4 && st == PC_OK; k++)
        if (bad_curve(c[k])) st = PC_EARG;
    if (st == PC_OK) {
        n = cu0->dim;
        for (int k = 1; k < 4; k++)
            if (c[k]->dim != n) st = PC_EDIM;
    }
    /* ends[k][e]: curve k at its start (e = 0) and end (e = 1) */
    double ends[4][2][PC_MAXDIM];
    for (int k = 0; k < 4 && st == PC_OK; k++)
        for (int e = 0; e < 2 && st == PC_OK; e++) {
            st = pc_curve_eval(c[k], e ? c[k]->t1 : c[k]->t0, ends[k][e]);
            if (st == PC_IMPROPER) st = PC_EDOMAIN;   /* a corner at infinity meets nothing */
        }
    if (st == PC_OK) {
        /* corner (a, b) is the end a of the u-curve b and the end b of the v-curve a */
        double scale = 0;
        for (int k = 0; k < 4; k++)
            for (int e = 0; e < 2; e++)
                for (int i = 0; i < n; i++) scale = fmax(scale, fabs(ends[k][e][i]));
        for (int a = 0; a < 2 && st == PC_OK; a++)
            for (int b = 0; b < 2; b++)
                if (pc_dist(n, ends[b][a], ends[2 + a][b]) > 1e-9 * scale) st = PC_EDOMAIN;
    }
    if (st == PC_OK && (s = pc_surf_alloc(PC_SURF_COONS, n, &st))) {
        s->u0 = 0, s->u1 = 1, s->v0 = 0, s->v1 = 1;
        s->nu = s->nv = 2;
        if (!(s->cp = malloc(4 * (size_t)(n + 1) * sizeof *s->cp))) {
            pc_surface_release(s);
            s = NULL;
            st = PC_ENOMEM;
        } else {
            for (int k = 0; k < 4; k++) {
                int a = k & 1, b = k >> 1;               /* P00, P10, P01, P11 */
                for (int i = 0; i < n; i++)
                    s->cp[k * (n + 1) + i] = 0.5 * (ends[b][a][i] + ends[2 + a][b][i]);
                s->cp[k * (n + 1) + n] = 1;
            }
            for (int k = 0; k < 4; k++) s->curves[k] = pc_curve_retain(c[k]);
        }
    }
    if (status) *status = st;
    return s;
}

pc_surface *pc_surface_revolution(pc_curve *profile, const double *a, const double *d,
                                  double v0, double v1, int *status) {
    int st = PC_OK;
    pc_surface *s = NULL;
    double k[3];
    if (bad_curve(profile) || !a || !d)
        st = PC_EARG;
    else if (profile->dim != 3)
        st = PC_EDIM;
    else if (!isfinite(a[0]) || !isfinite(a[1]) || !isfinite(a[2]) || !isfinite(d[0]) ||
             !isfinite(d[1]) || !isfinite(d[2]) || !isfinite(v0) || !isfinite(v1))
        st = PC_ENONFINITE;
    else if ((st = pc_unit(3, d, k)) != PC_OK)
        ;
    else if (!(v0 < v1))
        st = PC_EDOMAIN;
    else if ((s = pc_surf_alloc(PC_SURF_REVOLUTION, 3, &st))) {
        s->curves[0] = pc_curve_retain(profile);
        memcpy(s->axis, a, 3 * sizeof *a);
        memcpy(s->axis + 3, k, 3 * sizeof *k);
        s->u0 = profile->t0, s->u1 = profile->t1, s->v0 = v0, s->v1 = v1;
    }
    if (status) *status = st;
    return s;
}

/* x turned about the unit axis k by the angle (cos c, sin s) (Rodrigues):
 * x c + (k x x) s + k (k.x)(1 - c). */
static void rotate(const double *k, double c, double s, const double *x, double *out) {
    double kx[3], kd = pc_dot(3, k, x);
    pc_cross3(k, x, kx);
    for (int i = 0; i < 3; i++) out[i] = x[i] * c + kx[i] * s + k[i] * kd * (1 - c);
}

int pc_surf_curves_eval_h(const pc_surface *s, double u, double v, int order, double *out) {
    int n = s->dim, m = n + 1, st;
    double A[2 * PC_MAXDIM], B[2 * PC_MAXDIM], C[2 * PC_MAXDIM], D[2 * PC_MAXDIM];
    memset(out, 0, (size_t)(2 * order + 1) * m * sizeof *out);
    switch (s->kind) {
    case PC_SURF_RULED:
        if ((st = curve_at01(s->curves[0], u, order, A)) != PC_OK ||
            (st = curve_at01(s->curves[1], u, order, B)) != PC_OK)
            break;
        for (int i = 0; i < n; i++) {
            out[i] = (1 - v) * A[i] + v * B[i];
            if (order) {
                out[m + i] = (1 - v) * A[n + i] + v * B[n + i];
                out[2 * m + i] = B[i] - A[i];
            }
        }
        break;
    case PC_SURF_COONS: {
        if ((st = curve_at01(s->curves[0], u, order, A)) != PC_OK ||
            (st = curve_at01(s->curves[1], u, order, B)) != PC_OK ||
            (st = curve_at01(s->curves[2], v, order, C)) != PC_OK ||
            (st = curve_at01(s->curves[3], v, order, D)) != PC_OK)
            break;
        const double *P00 = s->cp, *P10 = s->cp + m, *P01 = s->cp + 2 * m, *P11 = s->cp + 3 * m;
        /* S = (1-v) (A - (1-u) P00 - u P10) + v (B - (1-u) P01 - u P11) + (1-u) C + u D:
         * each bracket vanishes on its own edge, so the boundaries come out as the curves */
        for (int i = 0; i < n; i++) {
            double e0 = A[i] - (1 - u) * P00[i] - u * P10[i];
            double e1 = B[i] - (1 - u) * P01[i] - u * P11[i];
            out[i] = (1 - v) * e0 + v * e1 + (1 - u) * C[i] + u * D[i];
            if (order) {
                out[m + i] = (1 - v) * (A[n + i] + P00[i] - P10[i]) +
                             v * (B[n + i] + P01[i] - P11[i]) - C[i] + D[i];
                out[2 * m + i] = e1 - e0 + (1 - u) * C[n + i] + u * D[n + i];
            }
        }
        break;
    }
    case PC_SURF_REVOLUTION: {
        if ((st = pc_curve_derivs(s->curves[0], u, order, A)) != PC_OK) break;
        const double *a = s->axis, *k = s->axis + 3;
        double r[3], R[3], c = cos(v), sn = sin(v);
        for (int i = 0; i < 3; i++) r[i] = A[i] - a[i];
        rotate(k, c, sn, r, R);
        for (int i = 0; i < 3; i++) out[i] = a[i] + R[i];
        if (order) {
            rotate(k, c, sn, A + 3, out + m);      /* dS/du: the turned profile tangent */
            pc_cross3(k, R, out + 2 * m);          /* dS/dv = k x (S - a) */
        }
        break;
    }
    default:
        return PC_EARG;
    }
    if (st != PC_OK) {
        memset(out, 0, (size_t)(2 * order + 1) * m * sizeof *out);
        return st;
    }
    out[n] = 1;
    return PC_OK;
}
