/* Hidden lines by a depth test against a triangulated surface (hidden.h). */
#include "hidden.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "linalg.h"

#define GRID 64   /* buckets per side of the picture's bounding box */

typedef struct { double x, y, d; int ok; } vert;   /* screen position, depth */

struct pc_occluder {
    pc_map map;
    pc_viewer view;
    double eps;            /* depth tolerance */
    int nu, nv;
    vert *v;               /* (nu+1) x (nv+1) */
    double x0, y0, cell;   /* the buckets: GRID x GRID cells of side `cell` from (x0, y0) */
    int *start, *tri;      /* CSR: triangles of cell k are tri[start[k] .. start[k+1]) */
};

double pc_viewer_depth(const pc_viewer *v, const double *x) {
    if (v->perspective) {
        double d[3] = {x[0] - v->eye[0], x[1] - v->eye[1], x[2] - v->eye[2]};
        return -sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    return x[0] * v->eye[0] + x[1] * v->eye[1] + x[2] * v->eye[2];
}

int pc_viewer_toward(const pc_viewer *v, const double *x, double out[3]) {
    if (!v->perspective) {
        for (int k = 0; k < 3; k++) out[k] = v->eye[k];
        return PC_OK;
    }
    double d[3] = {v->eye[0] - x[0], v->eye[1] - x[1], v->eye[2] - x[2]};
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(len > 0) || !isfinite(len)) return PC_EZERO;
    for (int k = 0; k < 3; k++) out[k] = d[k] / len;
    return PC_OK;
}

double pc_occluder_depth(const pc_occluder *o, const double *x) {
    return pc_viewer_depth(&o->view, x);
}

static int project(const pc_occluder *o, const double *x, vert *p) {
    double h[4] = {x[0], x[1], x[2], 1}, s[3];
    pc_map_apply(&o->map, h, s);
    p->ok = 0;
    if (s[2] == 0) return 0;
    p->x = s[0] / s[2];
    p->y = s[1] / s[2];
    p->d = pc_occluder_depth(o, x);
    p->ok = isfinite(p->x) && isfinite(p->y) && isfinite(p->d);
    return p->ok;
}

/* The centre of projection: the null vector of the 3 x 4 matrix, by cofactors. */
int pc_viewer_of(const pc_map *map, pc_viewer *v) {
    if (!map || map->nin != 3 || map->nout != 2) return PC_EDIM;
    double n[4], m[9];
    for (int j = 0; j < 4; j++) {
        for (int r = 0; r < 3; r++)
            for (int c = 0, k = 0; c < 4; c++)
                if (c != j) m[r * 3 + k++] = PC_MAP_AT(map, r, c);
        n[j] = (j % 2 ? -1 : 1) * pc_det(3, m);
    }
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] + n[3] * n[3]);
    if (!(len > 0) || !isfinite(len)) return PC_ESINGULAR;
    if (fabs(n[3]) > 1e-12 * len) {           /* a finite eye */
        v->perspective = 1;
        for (int k = 0; k < 3; k++) v->eye[k] = n[k] / n[3];
        return PC_OK;
    }
    /* parallel: towards the viewer is -(r1 x r2) on a y-down picture */
    double r1[3], r2[3], c[3];
    for (int k = 0; k < 3; k++) {
        r1[k] = PC_MAP_AT(map, 0, k);
        r2[k] = PC_MAP_AT(map, 1, k);
    }
    pc_cross3(r1, r2, c);
    double cl = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    if (!(cl > 0)) return PC_ESINGULAR;
    v->perspective = 0;
    for (int k = 0; k < 3; k++) v->eye[k] = -c[k] / cl;
    return PC_OK;
}

static void tri_verts(const pc_occluder *o, int t, const vert **a, const vert **b, const vert **c) {
    int q = t / 2, i = q / o->nv, j = q % o->nv, w = o->nv + 1;
    const vert *v00 = &o->v[i * w + j], *v10 = &o->v[(i + 1) * w + j];
    const vert *v01 = &o->v[i * w + j + 1], *v11 = &o->v[(i + 1) * w + j + 1];
    if (t % 2 == 0) { *a = v00; *b = v10; *c = v11; }
    else { *a = v00; *b = v11; *c = v01; }
}

static int cell_of(const pc_occluder *o, double x, double y, int *cx, int *cy) {
    double fx = floor((x - o->x0) / o->cell), fy = floor((y - o->y0) / o->cell);
    if (!(fx >= 0 && fx < GRID && fy >= 0 && fy < GRID)) return 0;
    *cx = (int)fx;
    *cy = (int)fy;
    return 1;
}

/* the cell range a triangle's box covers (clamped) */
static void cell_range(const pc_occluder *o, const vert *a, const vert *b, const vert *c,
                       int r[4]) {
    double xs[2] = {fmin(a->x, fmin(b->x, c->x)), fmax(a->x, fmax(b->x, c->x))};
    double ys[2] = {fmin(a->y, fmin(b->y, c->y)), fmax(a->y, fmax(b->y, c->y))};
    for (int k = 0; k < 2; k++) {
        double fx = floor((xs[k] - o->x0) / o->cell), fy = floor((ys[k] - o->y0) / o->cell);
        r[k] = (int)fmax(0, fmin(GRID - 1, fx));
        r[2 + k] = (int)fmax(0, fmin(GRID - 1, fy));
    }
}

pc_occluder *pc_occluder_new(const pc_surface *s, const pc_map *screen, int nu, int nv,
                             int *status) {
    int st = PC_OK;
    pc_occluder *o = NULL;
    if (!s || !screen || s->dim != 3 || screen->nin != 3 || screen->nout != 2) { st = PC_EDIM; goto fail; }
    if (nu < 1 || nv < 1 || nu > 1024 || nv > 1024) { st = PC_EDOMAIN; goto fail; }
    o = calloc(1, sizeof *o);
    if (!o) { st = PC_ENOMEM; goto fail; }
    o->map = *screen;
    o->nu = nu;
    o->nv = nv;
    if ((st = pc_viewer_of(&o->map, &o->view)) != PC_OK) goto fail;
    int w = nv + 1, ntri = 2 * nu * nv;
    o->v = malloc(sizeof(vert) * (size_t)(nu + 1) * w);
    o->start = calloc(GRID * GRID + 1, sizeof(int));
    if (!o->v || !o->start) { st = PC_ENOMEM; goto fail; }
    /* the grid and the mean edge length in space */
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY, edges = 0;
    int nedges = 0;
    double prev[PC_MAXDIM], row[1025][3];
    for (int i = 0; i <= nu; i++) {
        for (int j = 0; j <= nv; j++) {
            double u = s->u0 + (s->u1 - s->u0) * i / nu, v = s->v0 + (s->v1 - s->v0) * j / nv;
            double x[PC_MAXDIM];
            vert *p = &o->v[i * w + j];
            p->ok = 0;
            if (pc_surface_eval(s, u, v, x) != PC_OK) continue;
            if (!project(o, x, p)) continue;
            xmin = fmin(xmin, p->x); xmax = fmax(xmax, p->x);
            ymin = fmin(ymin, p->y); ymax = fmax(ymax, p->y);
            if (j > 0 && o->v[i * w + j - 1].ok) { edges += pc_dist(3, prev, x); nedges++; }
            if (i > 0 && o->v[(i - 1) * w + j].ok) { edges += pc_dist(3, row[j], x); nedges++; }
            memcpy(prev, x, sizeof(double) * 3);
            memcpy(row[j], x, sizeof(double) * 3);
        }
    }
    o->eps = nedges ? 0.25 * edges / nedges : 0;
    o->x0 = xmin;
    o->y0 = ymin;
    o->cell = fmax(xmax - xmin, ymax - ymin) / GRID * (1 + 1e-9);
    if (!(o->cell > 0) || !isfinite(o->cell)) o->cell = 1;
    /* bucket the triangles: count, prefix sums, fill */
    for (int pass = 0; pass < 2; pass++) {
        int *fill = NULL;
        if (pass == 1) {
            for (int k = 0; k < GRID * GRID; k++) o->start[k + 1] += o->start[k];
            o->tri = malloc(sizeof(int) * (size_t)(o->start[GRID * GRID] + 1));
            fill = calloc(GRID * GRID, sizeof(int));
            if (!o->tri || !fill) { free(fill); st = PC_ENOMEM; goto fail; }
        }
        for (int t = 0; t < ntri; t++) {
            const vert *a, *b, *c;
            tri_verts(o, t, &a, &b, &c);
            if (!a->ok || !b->ok || !c->ok) continue;
            int r[4];
            cell_range(o, a, b, c, r);
            for (int cy = r[2]; cy <= r[3]; cy++)
                for (int cx = r[0]; cx <= r[1]; cx++) {
                    int k = cy * GRID + cx;
                    if (pass == 0) o->start[k + 1]++;
                    else o->tri[o->start[k] + fill[k]++] = t;
                }
        }
        free(fill);
    }
    return o;
fail:
    pc_occluder_free(o);
    if (status) *status = st;
    return NULL;
}

void pc_occluder_free(pc_occluder *o) {
    if (!o) return;
    free(o->v);
    free(o->start);
    free(o->tri);
    free(o);
}

int pc_occluder_visible(const pc_occluder *o, const double *x) {
    vert p;
    int cx, cy;
    if (!project(o, x, &p) || !cell_of(o, p.x, p.y, &cx, &cy)) return 1;
    int k = cy * GRID + cx;
    for (int n = o->start[k]; n < o->start[k + 1]; n++) {
        const vert *a, *b, *c;
        tri_verts(o, o->tri[n], &a, &b, &c);
        /* barycentric coordinates of the image in the triangle's image */
        double det = (b->x - a->x) * (c->y - a->y) - (c->x - a->x) * (b->y - a->y);
        if (fabs(det) < 1e-12) continue;
        double l1 = ((p.x - a->x) * (c->y - a->y) - (c->x - a->x) * (p.y - a->y)) / det;
        double l2 = ((b->x - a->x) * (p.y - a->y) - (p.x - a->x) * (b->y - a->y)) / det;
        double l0 = 1 - l1 - l2;
        if (l0 < -1e-9 || l1 < -1e-9 || l2 < -1e-9) continue;
        double d = l0 * a->d + l1 * b->d + l2 * c->d;
        if (d > p.d + o->eps) return 0;
    }
    return 1;
}

/* the screen point of c at t and whether it is seen; 0 if it has no finite image */
static int split_sample(const pc_occluder *o, const pc_map *screen, const pc_curve *c, double t,
                        double xy[2], int *vis) {
    double x[PC_MAXDIM], hx[4], s[3];
    if (pc_curve_eval(c, t, x) != PC_OK) return 0;
    hx[0] = x[0], hx[1] = x[1], hx[2] = x[2], hx[3] = 1;
    pc_map_apply(screen, hx, s);
    if (s[2] == 0) return 0;
    xy[0] = s[0] / s[2];
    xy[1] = s[1] / s[2];
    if (!isfinite(xy[0]) || !isfinite(xy[1])) return 0;
    *vis = pc_occluder_visible(o, x);
    return 1;
}

int pc_occluder_split(const pc_occluder *o, const pc_map *screen, const pc_curve *c, int n,
                      pc_polyline *seen, pc_polyline *hidden) {
    double prev_t = c->t0;
    int prev_ok = 0, prev_vis = 1, st = PC_OK;
    for (int k = 0; k <= n && st == PC_OK; k++) {
        double t = c->t0 + (c->t1 - c->t0) * k / n, xy[2];
        int vis, ok = split_sample(o, screen, c, t, xy, &vis);
        if (ok && prev_ok && vis != prev_vis) {
            double lo = prev_t, hi = t, mxy[2] = {xy[0], xy[1]};
            for (int i = 0; i < 30; i++) {   /* where the visibility changes */
                double mid = (lo + hi) / 2, m[2];
                int mv;
                if (!split_sample(o, screen, c, mid, m, &mv)) break;
                if (mv == prev_vis) {
                    lo = mid;
                } else {
                    hi = mid;
                    mxy[0] = m[0];
                    mxy[1] = m[1];
                }
            }
            pc_polyline *from = prev_vis ? seen : hidden, *to = vis ? seen : hidden;
            st = pc_polyline_push(from, mxy[0], mxy[1], 0);
            if (st == PC_OK) st = pc_polyline_push(to, mxy[0], mxy[1], 1);
        }
        if (ok && st == PC_OK)   /* a run starts after a gap; a change started one above */
            st = pc_polyline_push(vis ? seen : hidden, xy[0], xy[1], !prev_ok);
        prev_t = t;
        prev_ok = ok;
        if (ok) prev_vis = vis;
    }
    return st;
}
