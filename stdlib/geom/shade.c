/* Shaded surfaces (shade.h): the grid's corners, each quad's normal, shade and depth, and the
 * painter's order. */
#include "shade.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "point.h"

/* A grid corner: the point in space, its screen image, and the sign of its homogeneous w
 * (which side of the vanishing plane it is on); ok 0 when it has no finite image. */
typedef struct { double x[3], sx, sy; int side, ok; } corner;

static int corner_at(const pc_surface *s, const pc_map *scr, double u, double v, corner *c) {
    double p[PC_MAXDIM];
    c->ok = 0;
    int st = pc_surface_eval(s, u, v, p);
    if (st == PC_IMPROPER || st == PC_ENONFINITE) return PC_OK;   /* at infinity, NaN: no image */
    if (st != PC_OK) return st;
    if (!(isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]))) return PC_OK;
    double h[4] = {p[0], p[1], p[2], 1}, o[3];
    pc_map_apply(scr, h, o);
    if (o[2] == 0) return PC_OK;
    c->sx = o[0] / o[2];
    c->sy = o[1] / o[2];
    if (!(isfinite(c->sx) && isfinite(c->sy))) return PC_OK;
    memcpy(c->x, p, sizeof c->x);
    c->side = o[2] > 0;
    c->ok = 1;
    return PC_OK;
}

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static int unit3(double *a) {
    double len = sqrt(dot3(a, a));
    if (!(len > 0) || !isfinite(len)) return 0;
    for (int k = 0; k < 3; k++) a[k] /= len;
    return 1;
}

/* The shade of the quad with corners q[0..3] (P00, P10, P11, P01) centred at c; (u, v) the
 * centre's parameters, for the fallback normal. */
static double quad_shade(const pc_surface *s, const pc_viewer *view, const pc_shade_opts *o,
                         const double light[3], const corner *q[4], const double c[3], double u,
                         double v) {
    double d1[3], d2[3], n[3], to_eye[3], l[3];
    for (int k = 0; k < 3; k++) {
        d1[k] = q[2]->x[k] - q[0]->x[k];
        d2[k] = q[3]->x[k] - q[1]->x[k];
    }
    pc_cross3(d1, d2, n);
    if (!unit3(n) && pc_surface_normal(s, u, v, n) != PC_OK) return o->ambient;
    if (pc_viewer_toward(view, c, to_eye) != PC_OK) return o->ambient;   /* the eye on the quad */
    if (dot3(n, to_eye) < 0)
        for (int k = 0; k < 3; k++) n[k] = -n[k];   /* the side the viewer sees */
    if (o->has_light) memcpy(l, light, sizeof l);
    else memcpy(l, to_eye, sizeof l);
    double cosine = dot3(n, l);
    return o->ambient + (1 - o->ambient) * (cosine > 0 ? fmin(cosine, 1) : 0);
}

static int farthest_first(const void *a, const void *b) {
    const pc_shade_quad *p = a, *q = b;
    if (p->depth != q->depth) return p->depth < q->depth ? -1 : 1;
    if (p->i != q->i) return p->i < q->i ? -1 : 1;
    return (p->j > q->j) - (p->j < q->j);
}

int pc_shade_quads(const pc_surface *s, const pc_map *screen, const pc_shade_opts *o,
                   pc_shade_quad **out, size_t *n) {
    *out = NULL;
    *n = 0;
    if (!s || !screen || s->dim != 3 || screen->nin != 3 || screen->nout != 2) return PC_EDIM;
    if (o->nu < 1 || o->nv < 1 || o->nu > 1024 || o->nv > 1024) return PC_EDOMAIN;
    if (!(o->ambient >= 0 && o->ambient <= 1)) return PC_EDOMAIN;
    double light[3] = {0, 0, 0};
    if (o->has_light) {
        memcpy(light, o->light, sizeof light);
        if (!(isfinite(light[0]) && isfinite(light[1]) && isfinite(light[2]))) return PC_ENONFINITE;
        if (!unit3(light)) return PC_EZERO;
    }
    pc_viewer view;
    int st = pc_viewer_of(screen, &view);
    if (st != PC_OK) return st;
    int nu = o->nu, nv = o->nv, w = nv + 1;
    corner *g = malloc(sizeof *g * (size_t)(nu + 1) * (size_t)w);
    pc_shade_quad *qs = malloc(sizeof *qs * (size_t)nu * (size_t)nv);
    if (!g || !qs) {
        free(g);
        free(qs);
        return PC_ENOMEM;
    }
    double du = (s->u1 - s->u0) / nu, dv = (s->v1 - s->v0) / nv;
    for (int i = 0; i <= nu && st == PC_OK; i++)
        for (int j = 0; j <= nv && st == PC_OK; j++)
            st = corner_at(s, screen, i == nu ? s->u1 : s->u0 + du * i,
                           j == nv ? s->v1 : s->v0 + dv * j, &g[i * w + j]);
    size_t m = 0;
    for (int i = 0; i < nu && st == PC_OK; i++)
        for (int j = 0; j < nv; j++) {
            const corner *q[4] = {&g[i * w + j], &g[(i + 1) * w + j], &g[(i + 1) * w + j + 1],
                                  &g[i * w + j + 1]};
            int ok = 1, sides = 0;
            for (int k = 0; k < 4; k++) {
                ok &= q[k]->ok;
                sides += q[k]->side;
            }
            if (!ok || (sides != 0 && sides != 4)) continue;   /* across the vanishing plane */
            pc_shade_quad *r = &qs[m++];
            double c[3] = {0, 0, 0};
            for (int k = 0; k < 4; k++) {
                r->xy[2 * k] = q[k]->sx;
                r->xy[2 * k + 1] = q[k]->sy;
                for (int a = 0; a < 3; a++) c[a] += q[k]->x[a] / 4;
            }
            r->i = i;
            r->j = j;
            r->depth = pc_viewer_depth(&view, c);
            r->shade = quad_shade(s, &view, o, light, q, c, s->u0 + du * (i + 0.5),
                                  s->v0 + dv * (j + 0.5));
        }
    free(g);
    if (st != PC_OK) {
        free(qs);
        return st;
    }
    qsort(qs, m, sizeof *qs, farthest_first);
    if (m == 0) {
        free(qs);
        qs = NULL;
    }
    *out = qs;
    *n = m;
    return PC_OK;
}

void pc_shade_rgb(const uint8_t base[3], double k, uint8_t out[3]) {
    if (!(k > 0)) k = 0;   /* NaN too */
    if (k > 1) k = 1;
    for (int c = 0; c < 3; c++) out[c] = (uint8_t)lrint(base[c] * k);
}
