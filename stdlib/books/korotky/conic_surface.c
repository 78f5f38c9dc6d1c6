/* Conic arcs from three points and two tangents, the conic sweep and the elliptic domes of
 * Korotky (2015).  See conic_surface.h and korotky_curves_surfaces.md B.3, B.5, B.7. */
#include "conic_surface.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double dotn(int n, const double *a, const double *b) {
    double s = 0;
    for (int i = 0; i < n; i++) s += a[i] * b[i];
    return s;
}

/* Make e (n) orthogonal to the unit vector f and return its remaining length. */
static double orth(int n, double *e, const double *f) {
    double d = dotn(n, e, f);
    for (int i = 0; i < n; i++) e[i] -= d * f[i];
    return sqrt(dotn(n, e, e));
}

/* The length of the part of d outside the plane spanned by the orthonormal e1, e2. */
static double off_plane(int n, const double *d, const double *e1, const double *e2) {
    double r[PC_MAXDIM];
    memcpy(r, d, sizeof(double) * (size_t)n);
    orth(n, r, e1);
    return orth(n, r, e2);
}

int pc_conic_arc_cp(int dim, const double *U, const double *tU, const double *V,
                    const double *tV, const double *T, double *cp, double *w) {
    if (dim < 2 || dim > PC_MAXDIM) return PC_EDIM;
    for (int i = 0; i < dim; i++)
        if (!isfinite(U[i]) || !isfinite(V[i]) || !isfinite(T[i]) || !isfinite(tU[i]) ||
            !isfinite(tV[i]))
            return PC_ENONFINITE;
    double e1[PC_MAXDIM], e2[PC_MAXDIM], t[PC_MAXDIM];
    for (int i = 0; i < dim; i++) e1[i] = V[i] - U[i];
    double L = sqrt(dotn(dim, e1, e1));
    if (!(L > 0)) return PC_ECOINCIDENT;
    for (int i = 0; i < dim; i++) e1[i] /= L;
    double lu = sqrt(dotn(dim, tU, tU)), lv = sqrt(dotn(dim, tV, tV));
    if (!(lu > 0) || !(lv > 0)) return PC_EZERO;
    /* the plane of the conic: U, V and T, or the tangent at U when T is on the chord */
    for (int i = 0; i < dim; i++) t[i] = T[i] - U[i];
    const double tol = 1e-10;
    const double *cand[3] = {t, tU, tV};
    const double sz[3] = {L, lu, lv};
    int found = 0;
    for (int c = 0; c < 3 && !found; c++) {
        memcpy(e2, cand[c], sizeof(double) * (size_t)dim);
        double l2 = orth(dim, e2, e1);
        if (l2 > tol * sz[c]) {
            for (int i = 0; i < dim; i++) e2[i] /= l2;
            found = 1;
        }
    }
    if (!found) {
        /* U, V, T and both tangents on one line: the chord itself */
        for (int i = 0; i <= dim; i++) {
            cp[i] = i < dim ? U[i] : 1;
            cp[dim + 1 + i] = 0;
            cp[2 * (dim + 1) + i] = i < dim ? V[i] : 1;
        }
        *w = 0;
        return PC_OK;
    }
    if (off_plane(dim, tU, e1, e2) > 1e-9 * lu || off_plane(dim, tV, e1, e2) > 1e-9 * lv ||
        off_plane(dim, t, e1, e2) > 1e-9 * L)
        return PC_ESKEW;
    /* plane coordinates: U = (0, 0), V = (L, 0) */
    double Tx = dotn(dim, t, e1), Ty = dotn(dim, t, e2);
    double du[2] = {dotn(dim, tU, e1) / lu, dotn(dim, tU, e2) / lu};
    double dv[2] = {dotn(dim, tV, e1) / lv, dotn(dim, tV, e2) / lv};
    /* W = U + a du = V + b dv: a du - b dv = (L, 0) */
    double det = -du[0] * dv[1] + du[1] * dv[0];
    double Wh[3];
    if (fabs(det) <= 1e-12) {        /* parallel tangents: W at infinity, the direction du */
        Wh[0] = du[0]; Wh[1] = du[1]; Wh[2] = 0;
    } else {
        double a = (-L * dv[1]) / det;
        Wh[0] = a * du[0]; Wh[1] = a * du[1]; Wh[2] = 1;
    }
    /* T = alpha U + beta W + gamma V in homogeneous plane coordinates (Cramer) */
    double M[3][3] = {{0, Wh[0], L}, {0, Wh[1], 0}, {1, Wh[2], 1}}, r[3] = {Tx, Ty, 1};
    double D = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
               M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
               M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
    if (!(fabs(D) > 1e-14 * L * L)) return PC_EDOMAIN;   /* W on the chord: no conic */
    double x[3];
    for (int c = 0; c < 3; c++) {
        double N[3][3];
        memcpy(N, M, sizeof N);
        for (int i = 0; i < 3; i++) N[i][c] = r[i];
        x[c] = (N[0][0] * (N[1][1] * N[2][2] - N[1][2] * N[2][1]) -
                N[0][1] * (N[1][0] * N[2][2] - N[1][2] * N[2][0]) +
                N[0][2] * (N[1][0] * N[2][1] - N[1][1] * N[2][0])) / D;
    }
    double al = x[0], be = x[1], ga = x[2];
    if (Wh[2] != 0 && fabs(al) <= 1e-12 && fabs(ga) <= 1e-12) {
        /* T = W: alpha = gamma = 0, w = beta/(2 sqrt(alpha gamma)) is infinite.  The limit
         * is the line pair U W V, the degenerate hyperbola AOD of Fig. 3c (digest B.3 step 3,
         * B.6 (3c)); cp holds U, W, V as points and pc_conic_arc_value walks the two sides */
        for (int i = 0; i < dim; i++) {
            cp[i] = U[i];
            cp[dim + 1 + i] = U[i] + Wh[0] * e1[i] + Wh[1] * e2[i];
            cp[2 * (dim + 1) + i] = V[i];
        }
        cp[dim] = cp[2 * dim + 1] = cp[3 * dim + 2] = 1;
        *w = INFINITY;
        return PC_OK;
    }
    if (!(al > 0) || !(ga > 0)) return PC_EDOMAIN;
    double ww = be / (2 * sqrt(al * ga));
    if (!(ww > -1)) return PC_EDOMAIN;
    for (int i = 0; i < dim; i++) {
        cp[i] = U[i];
        cp[2 * (dim + 1) + i] = V[i];
        double dir = Wh[0] * e1[i] + Wh[1] * e2[i];
        cp[dim + 1 + i] = ww * (Wh[2] ? U[i] + dir : dir);
    }
    cp[dim] = 1;
    cp[2 * (dim + 1) + dim] = 1;
    cp[dim + 1 + dim] = ww * Wh[2];
    *w = ww;
    return PC_OK;
}

void pc_conic_arc_value(int dim, const double *cp, double w, double v, double *out) {
    const double *a = cp, *b = cp + dim + 1;
    if (isinf(w)) {          /* the line pair: U -> W over [0, 1/2], W -> V over [1/2, 1] */
        double s = 2 * v;
        if (v > 0.5) a = b, b = cp + 2 * (dim + 1), s = 2 * v - 1;
        for (int k = 0; k <= dim; k++) out[k] = a[k] + (b[k] - a[k]) * s;
        return;
    }
    double b0 = (1 - v) * (1 - v), b1 = 2 * v * (1 - v), b2 = v * v;
    for (int k = 0; k <= dim; k++) out[k] = b0 * cp[k] + b1 * cp[dim + 1 + k] + b2 * cp[2 * (dim + 1) + k];
}

pc_curve *pc_conic_arc(int dim, const double *U, const double *tU, const double *V,
                       const double *tV, const double *T, double *w, int *status) {
    double cp[5 * (PC_MAXDIM + 1)];
    *status = pc_conic_arc_cp(dim, U, tU, V, tV, T, cp, w);
    if (*status != PC_OK) return NULL;
    if (isinf(*w)) {
        /* the limit of the arcs as T -> W: two straight pieces U W, W V, kept as quadratic
         * Bezier pieces (middle points at the midpoints) over 0, 1/2, 1 */
        double *r = cp;
        for (int k = 0; k <= dim; k++) {
            double u = r[k], wv = r[dim + 1 + k], vv = r[2 * (dim + 1) + k];
            r[k] = u;
            r[dim + 1 + k] = (u + wv) / 2;
            r[2 * (dim + 1) + k] = wv;
            r[3 * (dim + 1) + k] = (wv + vv) / 2;
            r[4 * (dim + 1) + k] = vv;
        }
        const double brk[3] = {0, 0.5, 1};
        return pc_curve_bezier_pieces(dim, 2, 2, cp, brk, status);
    }
    return pc_curve_bezier(dim, 3, cp, status);
}

const char *pc_conic_kind(double w) {
    if (isinf(w)) return "line pair";
    if (fabs(w) <= 1e-12) return "segment";
    if (fabs(fabs(w) - 1) <= 1e-12) return "parabola";
    return fabs(w) < 1 ? "ellipse" : "hyperbola";
}

/* ---- the conic sweep (B-2) ------------------------------------------------------------------ */

typedef struct { pc_curve *c[5]; } sweep_data;

static void sweep_free(void *ud) {
    sweep_data *d = ud;
    for (int i = 0; i < 5; i++) pc_curve_release(d->c[i]);
    free(d);
}

static int sweep_eval(void *ud, double u, double v, int order, double *out) {
    if (order > 0) return PC_EDOMAIN;
    sweep_data *d = ud;
    double h[5][4], pt[3][3], tan[2][3];
    for (int i = 0; i < 5; i++) {
        const pc_curve *c = d->c[i];
        int st = pc_curve_eval_h(c, c->t0 + u * (c->t1 - c->t0), 0, h[i]);
        if (st != PC_OK) return st;
    }
    for (int i = 0; i < 3; i++) {   /* U, V, T must be points */
        if (h[i][3] == 0) return PC_IMPROPER;
        for (int k = 0; k < 3; k++) pt[i][k] = h[i][k] / h[i][3];
    }
    for (int j = 0; j < 2; j++) {   /* P (at U) and Q (at V): points or directions */
        const double *q = h[3 + j];
        for (int k = 0; k < 3; k++) tan[j][k] = q[3] != 0 ? q[k] / q[3] - pt[j][k] : q[k];
    }
    double cp[12], w;
    int st = pc_conic_arc_cp(3, pt[0], tan[0], pt[1], tan[1], pt[2], cp, &w);
    if (st != PC_OK) return st;
    pc_conic_arc_value(3, cp, w, v, out);
    return PC_OK;
}

pc_surface *pc_surface_conic_sweep(pc_curve *U, pc_curve *V, pc_curve *T, pc_curve *P,
                                   pc_curve *Q, double *bad_u, int *status) {
    pc_curve *c[5] = {U, V, T, P, Q};
    for (int i = 0; i < 5; i++)
        if (!c[i] || c[i]->dim != 3) {
            *status = c[i] ? PC_EDIM : PC_EARG;
            return NULL;
        }
    sweep_data *d = malloc(sizeof *d);
    if (!d) {
        *status = PC_ENOMEM;
        return NULL;
    }
    for (int i = 0; i < 5; i++) d->c[i] = pc_curve_retain(c[i]);
    pc_surface *s = pc_surface_func(3, 0, 1, 0, 1, sweep_eval, sweep_free, d, status);
    if (!s) {
        sweep_free(d);
        return NULL;
    }
    /* every generator must exist: check the data on a fine grid of u, so that a script learns
     * of degenerate guides when it builds the surface, not when it draws it */
    for (int i = 0; i <= 64; i++) {
        double out[4];
        int st = sweep_eval(d, i / 64.0, .5, 0, out);
        if (st != PC_OK) {
            if (bad_u) *bad_u = i / 64.0;
            *status = st;
            pc_surface_release(s);
            return NULL;
        }
    }
    return s;
}

/* ---- elliptic domes (B-4) ----------------------------------------------------------------- */

/* The semi-ellipse over [0, 2a] with height 1 at the middle, x(u) = 2a u^2 / D and
 * f(u) = 2u(1 - u) / D with D = (1 - u)^2 + u^2, is the rational quadratic of weights 1, 0, 1
 * with the middle control point at infinity; the dome is z = c0 f(u) g(v), so its net is the
 * product of the two: numerators (xnum_i w_j, ynum_j w_i, c0 z_i z_j), weight w_i w_j. */
pc_surface *pc_surface_dome_rect(double a0, double b0, double c0, const double *origin,
                                 int *status) {
    if (!isfinite(a0) || !isfinite(b0) || !isfinite(c0) ||
        (origin && (!isfinite(origin[0]) || !isfinite(origin[1]) || !isfinite(origin[2])))) {
        *status = PC_ENONFINITE;
        return NULL;
    }
    if (!(a0 > 0) || !(b0 > 0) || !(c0 > 0)) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    const double wt[3] = {1, 0, 1}, zt[3] = {0, 1, 0};
    const double xn[3] = {0, 0, 2 * a0}, yn[3] = {0, 0, 2 * b0};
    double o[3] = {0, 0, 0}, cp[9 * 4];
    if (origin) memcpy(o, origin, sizeof o);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double *r = cp + 4 * (3 * i + j), W = wt[i] * wt[j];
            r[0] = xn[i] * wt[j] + o[0] * W;
            r[1] = yn[j] * wt[i] + o[1] * W;
            r[2] = c0 * zt[i] * zt[j] + o[2] * W;
            r[3] = W;
        }
    return pc_surface_bezier(3, 2, 2, cp, status);
}

double pc_dome_rect_height(double a0, double b0, double c0, double x, double y) {
    double q = x * (2 * a0 - x) * y * (2 * b0 - y);
    if (!(q > 0) || x < 0 || y < 0) return 0;
    return c0 * sqrt(q) / (a0 * b0);
}

typedef struct { double A[3], B[3], C[3], h; } tri_dome;

static int tri_eval(void *ud, double u, double v, int order, double *out) {
    if (order > 0) return PC_EDOMAIN;
    const tri_dome *d = ud;
    double l1 = 1 - u, l2 = u * (1 - v), l3 = u * v, q = 27 * l1 * l2 * l3;
    for (int k = 0; k < 3; k++) out[k] = l1 * d->A[k] + l2 * d->B[k] + l3 * d->C[k];
    out[2] += d->h * sqrt(q > 0 ? q : 0);
    out[3] = 1;
    return PC_OK;
}

pc_surface *pc_surface_dome_tri(const double *A, const double *B, const double *C, double h,
                                int *status) {
    for (int k = 0; k < 3; k++)
        if (!isfinite(A[k]) || !isfinite(B[k]) || !isfinite(C[k])) {
            *status = PC_ENONFINITE;
            return NULL;
        }
    if (!isfinite(h)) {
        *status = PC_ENONFINITE;
        return NULL;
    }
    if (!(h > 0)) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    double ab[2] = {B[0] - A[0], B[1] - A[1]}, ac[2] = {C[0] - A[0], C[1] - A[1]};
    double area = ab[0] * ac[1] - ab[1] * ac[0];
    double scale = fmax(hypot(ab[0], ab[1]), hypot(ac[0], ac[1]));
    if (!(fabs(area) > 1e-12 * scale * scale)) {   /* flat in plan: no dome over it */
        *status = PC_ECOLLINEAR;
        return NULL;
    }
    tri_dome *d = malloc(sizeof *d);
    if (!d) {
        *status = PC_ENOMEM;
        return NULL;
    }
    memcpy(d->A, A, sizeof d->A);
    memcpy(d->B, B, sizeof d->B);
    memcpy(d->C, C, sizeof d->C);
    d->h = h;
    pc_surface *s = pc_surface_func(3, 0, 1, 0, 1, tri_eval, free, d, status);
    if (!s) free(d);
    return s;
}

int pc_dome_tri_height_through(const double *A, const double *B, const double *C,
                               const double *D, double *h) {
    double ab[2] = {B[0] - A[0], B[1] - A[1]}, ac[2] = {C[0] - A[0], C[1] - A[1]};
    double ad[2] = {D[0] - A[0], D[1] - A[1]};
    double area = ab[0] * ac[1] - ab[1] * ac[0];
    if (!isfinite(area) || !isfinite(D[0]) || !isfinite(D[1]) || !isfinite(D[2]))
        return PC_ENONFINITE;
    if (area == 0) return PC_ECOLLINEAR;
    double l2 = (ad[0] * ac[1] - ad[1] * ac[0]) / area, l3 = (ab[0] * ad[1] - ab[1] * ad[0]) / area;
    double l1 = 1 - l2 - l3;
    if (!(l1 > 0 && l2 > 0 && l3 > 0)) return PC_EDOMAIN;
    double base = l1 * A[2] + l2 * B[2] + l3 * C[2];
    double hh = (D[2] - base) / sqrt(27 * l1 * l2 * l3);
    if (!(hh > 0)) return PC_EDOMAIN;
    *h = hh;
    return PC_OK;
}
