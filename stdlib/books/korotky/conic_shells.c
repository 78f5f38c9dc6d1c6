/* The rotational conic sweep and the composite ridge shell of Korotky (2015), Figs 3b, 3d
 * (conic_shells.h, digest korotky_curves_surfaces.md B.6). */
#include "conic_shells.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static void cross3(const double *a, const double *b, double *c) {
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}
static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* The value at s of a curve over its domain mapped to [0, 1], homogeneous (4). */
static int at(const pc_curve *c, double s, double *h) {
    return pc_curve_eval_h(c, c->t0 + s * (c->t1 - c->t0), 0, h);
}


/* ---- the rotational sweep (Fig. 3b) --------------------------------------------------------- */

typedef struct { double A[3], B[3], nA[3], nB[3]; pc_curve *l; } revolve;

static void revolve_free(void *ud) {
    revolve *r = ud;
    pc_curve_release(r->l);
    free(r);
}

/* The generator's control rows for the ridge parameter u. */
static int revolve_arc(const revolve *r, double u, double *cp, double *w) {
    double h[4], T[3], ab[3], at_[3], nPi[3], t[2][3];
    int st = at(r->l, u, h);
    if (st != PC_OK) return st;
    if (h[3] == 0) return PC_IMPROPER;
    for (int k = 0; k < 3; k++) {
        T[k] = h[k] / h[3];
        ab[k] = r->B[k] - r->A[k];
        at_[k] = T[k] - r->A[k];
    }
    cross3(ab, at_, nPi);   /* the normal of the plane A, B, T */
    double lab = sqrt(dot3(ab, ab));
    if (!(sqrt(dot3(nPi, nPi)) > 1e-12 * lab * sqrt(dot3(at_, at_)))) return PC_ECOLLINEAR;
    /* T's side of AB inside Pi: the component of T - A across AB */
    double side[3], f = dot3(at_, ab) / (lab * lab);
    for (int k = 0; k < 3; k++) side[k] = at_[k] - f * ab[k];
    const double *n[2] = {r->nA, r->nB};
    for (int j = 0; j < 2; j++) {
        cross3(nPi, n[j], t[j]);   /* the line Pi ^ pi_A (pi_B) */
        double len = sqrt(dot3(t[j], t[j]));
        if (!(len > 1e-12 * sqrt(dot3(nPi, nPi)) * sqrt(dot3(n[j], n[j])))) return PC_EDOMAIN;
        if (dot3(t[j], side) < 0)
            for (int k = 0; k < 3; k++) t[j][k] = -t[j][k];
    }
    return pc_conic_arc_cp(3, r->A, t[0], r->B, t[1], T, cp, w);
}

static int revolve_eval(void *ud, double u, double v, int order, double *out) {
    if (order > 0) return PC_EDOMAIN;
    double cp[12];
    double w;
    int st = revolve_arc(ud, u, cp, &w);
    if (st == PC_OK) pc_conic_arc_value(3, cp, w, v, out);
    return st;
}

/* Every generator must exist: check on a grid of u when the surface is built. */
static int check_grid(pc_surface_fn fn, void *ud, double *bad_u) {
    for (int i = 0; i <= 64; i++) {
        double out[4];
        int st = fn(ud, i / 64.0, .5, 0, out);
        if (st != PC_OK) {
            if (bad_u) *bad_u = i / 64.0;
            return st;
        }
    }
    return PC_OK;
}

pc_surface *pc_surface_conic_revolve(const double A[3], const double B[3], const double nA[3],
                                     const double nB[3], pc_curve *l, double *bad_u,
                                     int *status) {
    if (!l || l->dim != 3) {
        *status = l ? PC_EDIM : PC_EARG;
        return NULL;
    }
    for (int k = 0; k < 3; k++)
        if (!isfinite(A[k]) || !isfinite(B[k]) || !isfinite(nA[k]) || !isfinite(nB[k])) {
            *status = PC_ENONFINITE;
            return NULL;
        }
    if (A[0] == B[0] && A[1] == B[1] && A[2] == B[2]) {
        *status = PC_ECOINCIDENT;
        return NULL;
    }
    if (dot3(nA, nA) == 0 || dot3(nB, nB) == 0) {
        *status = PC_EZERO;
        return NULL;
    }
    revolve *r = malloc(sizeof *r);
    if (!r) {
        *status = PC_ENOMEM;
        return NULL;
    }
    memcpy(r->A, A, sizeof r->A);
    memcpy(r->B, B, sizeof r->B);
    memcpy(r->nA, nA, sizeof r->nA);
    memcpy(r->nB, nB, sizeof r->nB);
    r->l = pc_curve_retain(l);
    int st = check_grid(revolve_eval, r, bad_u);
    if (st != PC_OK) {
        revolve_free(r);
        *status = st;
        return NULL;
    }
    pc_surface *s = pc_surface_func(3, 0, 1, 0, 1, revolve_eval, revolve_free, r, status);
    if (!s) revolve_free(r);
    return s;
}

/* ---- the composite ridge shell (Fig. 3d) ---------------------------------------------------- */

enum { G_U, G_R, G_V, G_T1, G_T2, G_P, G_H, G_Q, G_N };

typedef struct { pc_curve *c[G_N]; } ridge;

static void ridge_free(void *ud) {
    ridge *r = ud;
    for (int i = 0; i < G_N; i++) pc_curve_release(r->c[i]);
    free(r);
}

static int ridge_eval(void *ud, double u, double v, int order, double *out) {
    if (order > 0) return PC_EDOMAIN;
    const ridge *r = ud;
    double h[G_N][4], pt[G_N][3];
    for (int i = 0; i < G_N; i++) {
        int st = at(r->c[i], u, h[i]);
        if (st != PC_OK) return st;
        if (i <= G_T2) {   /* U, R, V, T1, T2 are points */
            if (h[i][3] == 0) return PC_IMPROPER;
            for (int k = 0; k < 3; k++) pt[i][k] = h[i][k] / h[i][3];
        }
    }
    /* the tangents: towards P at U, along H at R (both arcs), towards Q at V */
    double tP[3], tH[3], tQ[3];
    const int base[3] = {G_U, G_R, G_V}, gi[3] = {G_P, G_H, G_Q};
    double *tt[3] = {tP, tH, tQ};
    for (int j = 0; j < 3; j++) {
        const double *q = h[gi[j]];
        for (int k = 0; k < 3; k++) tt[j][k] = q[3] != 0 ? q[k] / q[3] - pt[base[j]][k] : q[k];
    }
    double cp[12], w;   /* the arcs take tangent lines: H's sign does not matter */
    int second = v > 1;
    int st = second ? pc_conic_arc_cp(3, pt[G_R], tH, pt[G_V], tQ, pt[G_T2], cp, &w)
                    : pc_conic_arc_cp(3, pt[G_U], tP, pt[G_R], tH, pt[G_T1], cp, &w);
    if (st != PC_OK) return st;
    pc_conic_arc_value(3, cp, w, second ? v - 1 : v, out);
    return PC_OK;
}

static int ridge_check(void *ud, double u, double v, int order, double *out) {
    (void)v;
    int st = ridge_eval(ud, u, .5, order, out);
    return st == PC_OK ? ridge_eval(ud, u, 1.5, order, out) : st;
}

pc_surface *pc_surface_ridge_shell(const pc_ridge_shell *g, double *bad_u, int *status) {
    pc_curve *c[G_N] = {g->U, g->R, g->V, g->T1, g->T2, g->P, g->H, g->Q};
    for (int i = 0; i < G_N; i++)
        if (!c[i] || c[i]->dim != 3) {
            *status = c[i] ? PC_EDIM : PC_EARG;
            return NULL;
        }
    ridge *r = malloc(sizeof *r);
    if (!r) {
        *status = PC_ENOMEM;
        return NULL;
    }
    for (int i = 0; i < G_N; i++) r->c[i] = pc_curve_retain(c[i]);
    int st = check_grid(ridge_check, r, bad_u);
    if (st != PC_OK) {
        ridge_free(r);
        *status = st;
        return NULL;
    }
    pc_surface *s = pc_surface_func(3, 0, 1, 0, 2, ridge_eval, ridge_free, r, status);
    if (!s) ridge_free(r);
    return s;
}
