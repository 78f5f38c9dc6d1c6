/* Drawing a surface as its iso-lines or shaded (wireframe.h). */
#include "wireframe.h"
#include "view.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* the iso-curves of s: family dir (0: u = const), line i of n; n 0 with boundary: the edges */
static int family_parts(const pc_wireframe_opts *o, int dir) {
    int n = dir == 0 ? o->nu : o->nv;
    return n == 0 && o->boundary ? 1 : n;
}

static double family_value(const pc_surface *s, int dir, int i, int n) {
    double lo = dir == 0 ? s->u0 : s->v0, hi = dir == 0 ? s->u1 : s->v1;
    return lo + (hi - lo) * i / n;
}

/* a screen polyline as one path (its vertices go to the canvas as they are) */
static int stroke(pc_canvas *cv, const pc_polyline *pl, int color) {
    if (pl->n == 0) return PC_OK;
    uint8_t *verbs = malloc(pl->n);
    if (!verbs) return PC_ENOMEM;
    for (size_t i = 0; i < pl->n; i++) verbs[i] = (i == 0 || pl->move[i]) ? PC_PATH_MOVE : PC_PATH_LINE;
    int rc = pc_path_screen(cv, pl->n, pl->xy, verbs, pl->n, 0, color);
    free(verbs);
    return rc;
}

/* one iso-curve: flattened and stroked, or split into its seen and hidden runs */
static int draw_iso(pc_canvas *cv, const pc_curve *c, const pc_map *screen, const pc_occluder *occ,
                    const pc_wireframe_opts *o, pc_polyline run[2], int *drawn) {
    pc_polyline pl = {0};
    int st = pc_curve_flatten_map(c, c->t0, c->t1, screen, o->tol, &pl);
    if (st == PC_OK && !occ) *drawn = stroke(cv, &pl, o->color);
    if (st == PC_OK && occ) {
        int samples = (int)fmin(8192, fmax(64, 4.0 * (double)pl.n));
        st = pc_occluder_split(occ, screen, c, samples, &run[0], &run[1]);
        if (st == PC_OK) *drawn = stroke(cv, &run[0], o->color);
        if (st == PC_OK && *drawn == PC_OK && o->hidden == 2 && run[1].n) {
            pc_stroke pen = cv->pens[cv->pen];   /* restored after the dashed hidden parts */
            double dash[2] = {3, 3};
            pc_pen(cv, pen.width, dash, 2);
            *drawn = stroke(cv, &run[1], o->color);
            pc_pen(cv, pen.width, pen.dash, pen.ndash);
        }
        run[0].n = run[1].n = 0;
    }
    pc_polyline_free(&pl);
    return st;
}

/* the silhouette, each segment a path in world coordinates */
static int draw_silhouette(pc_canvas *cv, pc_surface *s, const pc_map *screen, const pc_wireframe_opts *o,
                           int *drawn) {
    double *seg;
    size_t nseg;
    int st = pc_surface_silhouette(s, screen, 4 * o->mesh, 4 * o->mesh, &seg, &nseg);
    for (size_t i = 0; st == PC_OK && *drawn == PC_OK && i < nseg; i++) {
        double xy[4];
        for (int e = 0; e < 2; e++) {
            const double *p = seg + 6 * i + 3 * e;
            double hx[4] = {p[0], p[1], p[2], 1}, q[3];
            pc_map_apply(screen, hx, q);
            pc_screen_to_world(cv, q[0] / q[2], q[1] / q[2], &xy[2 * e], &xy[2 * e + 1]);
        }
        *drawn = pc_path(cv, 2, xy, NULL, 0, 0, o->color);
    }
    if (st == PC_OK) free(seg);
    return st;
}

int pc_draw_wireframe(pc_canvas *cv, pc_surface *s, const pc_map *screen,
                      const pc_wireframe_opts *o, int *drawn) {
    int st = PC_OK;
    *drawn = PC_OK;
    pc_occluder *occ = NULL;
    if (o->hidden && !(occ = pc_occluder_new(s, screen, o->mesh, o->mesh, &st))) return st;
    pc_polyline run[2] = {{0}, {0}};   /* seen, hidden */
    for (int dir = 0; dir < 2 && st == PC_OK && *drawn == PC_OK; dir++) {
        int n = family_parts(o, dir);
        for (int i = 0; n > 0 && i <= n && st == PC_OK && *drawn == PC_OK; i++) {
            pc_curve *c = pc_surface_iso(s, dir, family_value(s, dir, i, n), &st);
            if (!c) break;
            st = draw_iso(cv, c, screen, occ, o, run, drawn);
            pc_curve_release(c);
        }
    }
    if (o->silhouette && st == PC_OK && *drawn == PC_OK) st = draw_silhouette(cv, s, screen, o, drawn);
    pc_polyline_free(&run[0]);
    pc_polyline_free(&run[1]);
    pc_occluder_free(occ);
    return st;
}

int pc_scene_wireframe(pc_scene *sc, pc_surface *s, const pc_map *screen,
                       const pc_wireframe_opts *o, int pen) {
    int st = pc_scene_add_surface(sc, s, o->mesh);
    for (int dir = 0; dir < 2 && st == PC_OK; dir++) {
        int n = family_parts(o, dir);
        for (int i = 0; n > 0 && i <= n && st == PC_OK; i++) {
            pc_curve *c = pc_surface_iso(s, dir, family_value(s, dir, i, n), &st);
            if (!c) break;
            st = pc_scene_add_curve(sc, c, 256, o->color, pen);
            pc_curve_release(c);
        }
    }
    if (o->silhouette && st == PC_OK) {
        double *seg;
        size_t nseg;
        int sil = pc_surface_silhouette(s, screen, 4 * o->mesh, 4 * o->mesh, &seg, &nseg);
        st = sil;
        for (size_t i = 0; st == PC_OK && i < nseg; i++)
            st = pc_scene_add_polyline(sc, 2, seg + 6 * i, NULL, o->color, pen);
        if (sil == PC_OK) free(seg);
    }
    return st;
}

int pc_draw_shaded_surface(pc_canvas *cv, pc_scene *sc, const pc_surface *s, const pc_map *screen,
                           const pc_shade_opts *o, pc_rgb base, int mesh, size_t *n, int *drawn) {
    pc_shade_quad *q;
    *drawn = PC_OK;
    int st = pc_shade_quads(s, screen, o, &q, n);
    if (st != PC_OK) return st;
    *drawn = pc_draw_shaded(cv, q, *n, base, mesh);
    free(q);
    int res = o->nu > o->nv ? o->nu : o->nv;
    if (*drawn != PC_OK || !sc) return PC_OK;
    return pc_scene_add_surface(sc, s, res > 48 ? res : 48);
}
