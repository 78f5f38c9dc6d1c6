/* Views with z up, and silhouettes of surfaces (view.h). */
#include "view.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "hidden.h"
#include "linalg.h"
#include "point.h"

static const double PI = 3.14159265358979323846;

int pc_map_view(pc_map *f, const double from[3], const double to[3], const double *up,
                int perspective) {
    pc_map m;   /* the perspective's frame: rows right, up, line of sight / distance */
    int st = pc_map_perspective(&m, from, to, up);
    if (st != PC_OK || perspective) {
        if (st == PC_OK) *f = m;
        return st;
    }
    /* parallel: the same right and up rows, weight 1 everywhere, origin at `to` */
    *f = m;
    for (int j = 0; j < 3; j++) PC_MAP_AT(f, 2, j) = 0;
    PC_MAP_AT(f, 2, 3) = 1;
    for (int r = 0; r < 2; r++) {
        double o = 0;
        for (int j = 0; j < 3; j++) o += PC_MAP_AT(f, r, j) * to[j];
        PC_MAP_AT(f, r, 3) = -o;
    }
    return PC_OK;
}

int pc_map_view_azel(pc_map *f, const double to[3], double azimuth, double elevation,
                     double dist, int perspective) {
    if (!isfinite(azimuth) || !isfinite(elevation) || !isfinite(dist)) return PC_ENONFINITE;
    if (!(dist > 0)) return PC_ECOINCIDENT;
    double a = azimuth * PI / 180, e = elevation * PI / 180;
    double from[3] = {to[0] + dist * cos(e) * cos(a), to[1] + dist * cos(e) * sin(a),
                      to[2] + dist * sin(e)};
    double zup[3] = {0, 0, 1}, side[3] = {-cos(a), -sin(a), 0};   /* looking straight down */
    return pc_map_view(f, from, to, fabs(cos(e)) < 1e-12 ? side : zup, perspective);
}

/* ---- silhouettes ------------------------------------------------------------------------- */

typedef struct {
    const pc_surface *s;
    pc_viewer view;
} sil;

/* g(u, v): the normal against the direction towards the viewer; *x gets the point. */
static int g_at(const sil *z, double u, double v, double *g, double x[3]) {
    double n[3], t[3];
    double p[9];
    int st = pc_surface_partials(z->s, u, v, p);
    if (st != PC_OK) return st;
    memcpy(x, p, 3 * sizeof *x);
    pc_cross3(p + 3, p + 6, n);
    if ((st = pc_viewer_toward(&z->view, x, t)) != PC_OK) return st;
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    *g = len > 0 ? (n[0] * t[0] + n[1] * t[1] + n[2] * t[2]) / len : 0;
    return PC_OK;
}

/* The zero of g on the edge from (u0, v0) (where g has sign pos0) to (u1, v1), by
 * bisection: the 3-D point there. */
static int edge_zero(const sil *z, double u0, double v0, int pos0, double u1, double v1,
                     double out[3]) {
    double a = 0, b = 1, x[3], g;
    for (int it = 0; it < 34; it++) {   /* 2^-34 of a cell edge */
        double m = (a + b) / 2;
        int st = g_at(z, u0 + m * (u1 - u0), v0 + m * (v1 - v0), &g, x);
        if (st != PC_OK) return st;
        if ((g >= 0) == pos0) a = m;
        else b = m;
    }
    double m = (a + b) / 2;
    return g_at(z, u0 + m * (u1 - u0), v0 + m * (v1 - v0), &g, out);
}

typedef struct { double *xyz; size_t n, cap; } segs;

static int push_seg(segs *o, const double a[3], const double b[3]) {
    if (o->n == o->cap) {
        size_t cap = o->cap ? 2 * o->cap : 64;
        double *p = realloc(o->xyz, cap * 6 * sizeof *p);
        if (!p) return PC_ENOMEM;
        o->xyz = p;
        o->cap = cap;
    }
    memcpy(o->xyz + 6 * o->n, a, 3 * sizeof *a);
    memcpy(o->xyz + 6 * o->n + 3, b, 3 * sizeof *b);
    o->n++;
    return PC_OK;
}

int pc_surface_silhouette(const pc_surface *s, const pc_map *screen, int nu, int nv,
                          double **xyz, size_t *nseg) {
    *xyz = NULL;
    *nseg = 0;
    if (!s || s->dim != 3 || !screen || screen->nin != 3 || screen->nout != 2) return PC_EDIM;
    if (nu < 2 || nv < 2 || nu > 2048 || nv > 2048) return PC_EDOMAIN;
    sil z = {s, {0}};
    int st = pc_viewer_of(screen, &z.view);
    if (st != PC_OK) return st;
    double *g = malloc((size_t)(nu + 1) * (nv + 1) * sizeof *g), x[3];
    if (!g) return PC_ENOMEM;
    double du = (s->u1 - s->u0) / nu, dv = (s->v1 - s->v0) / nv;
    for (int i = 0; i <= nu && st == PC_OK; i++)
        for (int j = 0; j <= nv && st == PC_OK; j++)
            st = g_at(&z, s->u0 + i * du, s->v0 + j * dv, &g[i * (nv + 1) + j], x);
    segs out = {0};
    /* each cell: corners 0 (i, j), 1 (i+1, j), 2 (i+1, j+1), 3 (i, j+1); edge k from corner k
     * to corner k+1 */
    static const int cu[4] = {0, 1, 1, 0}, cv[4] = {0, 0, 1, 1};
    for (int i = 0; i < nu && st == PC_OK; i++)
        for (int j = 0; j < nv && st == PC_OK; j++) {
            int pos[4], ncut = 0, cut_edge[4];
            double pts[4][3];
            for (int k = 0; k < 4; k++) pos[k] = g[(i + cu[k]) * (nv + 1) + j + cv[k]] >= 0;
            for (int k = 0; k < 4 && st == PC_OK; k++) {
                int k1 = (k + 1) % 4;
                if (pos[k] == pos[k1]) continue;
                st = edge_zero(&z, s->u0 + (i + cu[k]) * du, s->v0 + (j + cv[k]) * dv, pos[k],
                               s->u0 + (i + cu[k1]) * du, s->v0 + (j + cv[k1]) * dv, pts[ncut]);
                cut_edge[ncut++] = k;
            }
            if (st != PC_OK) break;
            if (ncut == 2) st = push_seg(&out, pts[0], pts[1]);
            else if (ncut == 4) {   /* a saddle: the centre's sign says which corners join */
                double gc;
                st = g_at(&z, s->u0 + (i + 0.5) * du, s->v0 + (j + 0.5) * dv, &gc, x);
                if (st != PC_OK) break;
                if ((gc >= 0) == pos[0]) {   /* 0 and 2 joined: cut off corners 1 and 3 */
                    st = push_seg(&out, pts[0], pts[1]);
                    if (st == PC_OK) st = push_seg(&out, pts[2], pts[3]);
                } else {
                    st = push_seg(&out, pts[0], pts[3]);
                    if (st == PC_OK) st = push_seg(&out, pts[1], pts[2]);
                }
            }
            (void)cut_edge;
        }
    free(g);
    if (st != PC_OK) {
        free(out.xyz);
        return st;
    }
    *xyz = out.xyz;
    *nseg = out.n;
    return PC_OK;
}
