/* The scenes attached to a canvas (scene.h: pc_canvas_scene): 3-D strokes go into the scene of
 * the camera in use, a new one each time the camera's screen map or hidden mode changes; the
 * writers resolve them all, in order, when the picture is written. */
#include <stdlib.h>
#include <string.h>
#include "scene.h"
#include "curve.h"
#include "furniture.h"

typedef struct {
    pc_scene **sc;
    int *mode;
    pc_map *map;
    size_t n, cap;
} scene_set;

static int set_resolve(void *p, pc_canvas *copy) {
    scene_set *set = p;
    int st = PC_OK;
    for (size_t i = 0; i < set->n && st == PC_OK; i++) st = pc_scene_draw(set->sc[i], copy, set->mode[i]);
    return st;
}

static int set_extent(void *p, const pc_canvas *c, pc_extent_fn put, void *ctx) {
    scene_set *set = p;
    int st = PC_OK;
    for (size_t i = 0; i < set->n && st == PC_OK; i++) st = pc_scene_extent(set->sc[i], c, put, ctx);
    return st;
}

/* fit{} moved the picture: the scenes are drawn through the same framing */
static void set_frame(void *p, double sx, double sy, double tx, double ty) {
    scene_set *set = p;
    for (size_t i = 0; i < set->n; i++) pc_scene_reframe(set->sc[i], sx, sy, tx, ty);
}

static void set_drop(void *p) {
    scene_set *set = p;
    for (size_t i = 0; i < set->n; i++) pc_scene_free(set->sc[i]);
    free(set->sc);
    free(set->mode);
    free(set->map);
    free(set);
}

static int set_grow(scene_set *set) {
    size_t cap = set->cap ? 2 * set->cap : 4;
    pc_scene **a = realloc(set->sc, cap * sizeof *a);
    if (a) set->sc = a;
    int *m = realloc(set->mode, cap * sizeof *m);
    if (m) set->mode = m;
    pc_map *mp = realloc(set->map, cap * sizeof *mp);
    if (mp) set->map = mp;
    if (!a || !m || !mp) return PC_ENOMEM;
    set->cap = cap;
    return PC_OK;
}

pc_scene *pc_canvas_scene(pc_canvas *c, const pc_map *screen, int mode, int *status) {
    *status = PC_OK;
    scene_set *set = c->attach_resolve == set_resolve ? c->attach : NULL;
    if (!set) {
        if (c->attach) return NULL;   /* something else is attached: draw as usual */
        if (!(set = calloc(1, sizeof *set))) {
            *status = PC_ENOMEM;
            return NULL;
        }
        c->attach = set;
        c->attach_resolve = set_resolve;
        c->attach_drop = set_drop;
        c->attach_extent = set_extent;
        c->attach_frame = set_frame;
    }
    size_t n = set->n;
    if (n && set->mode[n - 1] == mode && !memcmp(&set->map[n - 1], screen, sizeof *screen)) return set->sc[n - 1];
    if (n == set->cap && (*status = set_grow(set)) != PC_OK) return NULL;
    pc_scene *sc = pc_scene_new(screen, status);
    if (!sc) return NULL;
    set->sc[n] = sc;
    set->mode[n] = mode;
    set->map[n] = *screen;
    set->n++;
    return sc;
}

int pc_scene_add_curve(pc_scene *sc, const pc_curve *c, int n, int color, int pen) {
    double *xyz = malloc(sizeof(double) * 3 * (size_t)(n + 1));
    uint8_t *brk = malloc((size_t)n + 1);
    if (!xyz || !brk) {
        free(xyz);
        free(brk);
        return PC_ENOMEM;
    }
    size_t m = 0;
    int gap = 1;
    for (int k = 0; k <= n; k++) {
        double x[PC_MAXDIM];
        if (pc_curve_eval(c, c->t0 + (c->t1 - c->t0) * k / n, x) != PC_OK) {
            gap = 1;   /* a point at infinity: the curve breaks there */
            continue;
        }
        memcpy(xyz + 3 * m, x, 3 * sizeof *x);
        brk[m++] = (uint8_t)gap;
        gap = 0;
    }
    int st = pc_scene_add_polyline(sc, m, xyz, brk, color, pen);
    free(xyz);
    free(brk);
    return st;
}

int pc_scene_add_path(pc_scene *sc, size_t n, const double *xyz, int closed, int heads, int color, int pen) {
    double *p = malloc(sizeof(double) * 3 * (n + 1));
    if (!p) return PC_ENOMEM;
    memcpy(p, xyz, sizeof(double) * 3 * n);
    if (closed && n > 1) {
        memcpy(p + 3 * n, p, 3 * sizeof *p);
        n++;
    }
    int st = pc_scene_add_polyline(sc, n, p, NULL, color, pen);
    /* the heads on the path's own end segments, hidden with their tips (9 px long, as a 2-D
     * path's) */
    if (st == PC_OK && (heads & PC_ARROW_END) && n >= 2)
        st = pc_scene_add_arrow_head(sc, p + 3 * (n - 2), p + 3 * (n - 1), 9, color);
    if (st == PC_OK && (heads & PC_ARROW_START) && n >= 2) st = pc_scene_add_arrow_head(sc, p + 3, p, 9, color);
    free(p);
    return st;
}
