/* A 3-D scene resolved at write time (scene.h): each stroke is sampled along its length, each
 * sample tested against every surface's occluder, and the runs of seen and hidden samples
 * drawn as paths. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "canvas_internal.h"
#include "furniture.h"
#include "layout.h"
#include "scene.h"

typedef struct {
    size_t first, n;        /* into pts (3 numbers each) */
    int color, pen;
    int mark, style;        /* a marker (1): its style and size; a label (2): anchor, scale;
                               a dot (3); an arrow head (4): its size, from point 0 to 1 */
    double size;
    char *text;             /* a label's text (owned) */
    char *font;             /* a label's {font =} (owned; NULL: the figure's) */
    double pt;              /* its {size =} in pt (0: the figure's) */
    int halo, styled;       /* its {halo =} (-1: the figure's); styled: pc_text_style it */
} stroke;

struct pc_scene {
    pc_map screen;
    pc_occluder **occ; size_t nocc, capocc;
    stroke *st; size_t nst, capst;
    double *pts; uint8_t *brk; size_t npts, cappts;
};

static int grow(void **p, size_t *cap, size_t need, size_t elem) {
    if (need <= *cap) return 1;
    size_t cap2 = *cap ? *cap : 16;
    while (cap2 < need) cap2 *= 2;
    void *q = realloc(*p, cap2 * elem);
    if (!q) return 0;
    *p = q;
    *cap = cap2;
    return 1;
}

pc_scene *pc_scene_new(const pc_map *screen, int *status) {
    pc_viewer v;
    int st = pc_viewer_of(screen, &v);
    if (st != PC_OK) {
        *status = st;
        return NULL;
    }
    pc_scene *sc = calloc(1, sizeof *sc);
    if (!sc) {
        *status = PC_ENOMEM;
        return NULL;
    }
    sc->screen = *screen;
    *status = PC_OK;
    return sc;
}

void pc_scene_free(pc_scene *sc) {
    if (!sc) return;
    for (size_t i = 0; i < sc->nocc; i++) pc_occluder_free(sc->occ[i]);
    for (size_t i = 0; i < sc->nst; i++) free(sc->st[i].text), free(sc->st[i].font);
    free(sc->occ);
    free(sc->st);
    free(sc->pts);
    free(sc->brk);
    free(sc);
}

int pc_scene_add_surface(pc_scene *sc, const pc_surface *s, int mesh) {
    int st;
    if (!grow((void **)&sc->occ, &sc->capocc, sc->nocc + 1, sizeof *sc->occ)) return PC_ENOMEM;
    pc_occluder *o = pc_occluder_new(s, &sc->screen, mesh, mesh, &st);
    if (!o) return st;
    sc->occ[sc->nocc++] = o;
    return PC_OK;
}

static int add(pc_scene *sc, size_t n, const double *xyz, const uint8_t *brk, stroke s) {
    for (size_t i = 0; i < 3 * n; i++)
        if (!isfinite(xyz[i])) return PC_ENONFINITE;
    if (!grow((void **)&sc->st, &sc->capst, sc->nst + 1, sizeof *sc->st) ||
        !grow((void **)&sc->pts, &sc->cappts, sc->npts + n, 3 * sizeof *sc->pts))
        return PC_ENOMEM;
    size_t cap = sc->cappts;   /* brk follows pts' capacity */
    uint8_t *b = realloc(sc->brk, cap ? cap : 1);
    if (!b) return PC_ENOMEM;
    sc->brk = b;
    memcpy(sc->pts + 3 * sc->npts, xyz, 3 * n * sizeof *xyz);
    for (size_t i = 0; i < n; i++) sc->brk[sc->npts + i] = i == 0 || (brk && brk[i]);
    s.first = sc->npts;
    s.n = n;
    sc->st[sc->nst++] = s;
    sc->npts += n;
    return PC_OK;
}

int pc_scene_add_polyline(pc_scene *sc, size_t n, const double *xyz, const uint8_t *brk,
                          int color, int pen) {
    if (n == 0) return PC_OK;
    return add(sc, n, xyz, brk, (stroke){0, 0, color, pen, 0, 0, 0, NULL, NULL, 0, -1, 0});
}

int pc_scene_add_mark(pc_scene *sc, const double xyz[3], int style, double size, int color) {
    return add(sc, 1, xyz, NULL, (stroke){0, 0, color, 0, 1, style, size, NULL, NULL, 0, -1, 0});
}

int pc_scene_add_dot(pc_scene *sc, const double xyz[3], int color) {
    return add(sc, 1, xyz, NULL, (stroke){0, 0, color, 0, 3, 0, 0, NULL, NULL, 0, -1, 0});
}

int pc_scene_add_arrow_head(pc_scene *sc, const double from[3], const double tip[3], double len,
                            int color) {
    double xyz[6] = {from[0], from[1], from[2], tip[0], tip[1], tip[2]};
    return add(sc, 2, xyz, NULL, (stroke){0, 0, color, 0, 4, 0, len, NULL, NULL, 0, -1, 0});
}

int pc_scene_add_label(pc_scene *sc, const double xyz[3], const char *utf8, int anchor, int scale,
                       int color) {
    size_t n = strlen(utf8);
    char *t = malloc(n + 1);
    if (!t) return PC_ENOMEM;
    memcpy(t, utf8, n + 1);
    int st = add(sc, 1, xyz, NULL, (stroke){0, 0, color, 0, 2, anchor, scale, t, NULL, 0, -1, 0});
    if (st != PC_OK) free(t);
    return st;
}

int pc_scene_style_label(pc_scene *sc, const char *font, double size_pt, int halo) {
    stroke *s = sc->nst ? &sc->st[sc->nst - 1] : NULL;
    if (!s || s->mark != 2) return PC_EARG;
    if (font && *font) {
        size_t n = strlen(font);
        if (!(s->font = malloc(n + 1))) return PC_ENOMEM;
        memcpy(s->font, font, n + 1);
    }
    s->pt = size_pt;
    s->halo = halo;
    s->styled = 1;
    return PC_OK;
}

size_t pc_scene_nsurfaces(const pc_scene *sc) { return sc->nocc; }
size_t pc_scene_nstrokes(const pc_scene *sc) { return sc->nst; }

int pc_scene_visible(const pc_scene *sc, const double x[3]) {
    for (size_t i = 0; i < sc->nocc; i++)
        if (!pc_occluder_visible(sc->occ[i], x)) return 0;
    return 1;
}

/* The screen image of a 3-D point; 0 where it has none. */
static int project(const pc_scene *sc, const double *x, double *sx, double *sy) {
    double h[4] = {x[0], x[1], x[2], 1}, o[3];
    pc_map_apply(&sc->screen, h, o);
    if (o[2] == 0) return 0;
    *sx = o[0] / o[2];
    *sy = o[1] / o[2];
    return isfinite(*sx) && isfinite(*sy);
}

int pc_scene_extent(const pc_scene *sc, const pc_canvas *c, pc_extent_fn put, void *ctx) {
    for (size_t i = 0; i < sc->nst; i++) {
        const stroke *s = &sc->st[i];
        for (size_t k = 0; k < s->n; k++) {
            double sx, sy, w = 0, h = 0, r = 0;
            if (!project(sc, sc->pts + 3 * (s->first + k), &sx, &sy)) continue;
            if (s->mark == 1) r = s->size / 2;
            if (s->mark == 2) {   /* a label: its box on any side, PC_FIT_LABEL_GAP off */
                int st = pc_text_measure(c, s->text, strlen(s->text), (int)s->size, &w, &h);
                if (st != PC_OK) return st;
                put(ctx, sx, sy, -w - PC_FIT_LABEL_GAP, -h - PC_FIT_LABEL_GAP, w + PC_FIT_LABEL_GAP,
                    h + PC_FIT_LABEL_GAP);
                continue;
            }
            put(ctx, sx, sy, -r, -r, r, r);
        }
    }
    return PC_OK;
}

void pc_scene_reframe(pc_scene *sc, double sx, double sy, double tx, double ty) {
    pc_map *f = &sc->screen;   /* rows x, y, w of a 3 -> 2 map: x' = sx x + tx w */
    for (int j = 0; j < 4; j++) {
        PC_MAP_AT(f, 0, j) = sx * PC_MAP_AT(f, 0, j) + tx * PC_MAP_AT(f, 2, j);
        PC_MAP_AT(f, 1, j) = sy * PC_MAP_AT(f, 1, j) + ty * PC_MAP_AT(f, 2, j);
    }
}

/* A run of screen points being gathered, drawn as one path when it ends. */
typedef struct {
    pc_canvas *c;
    double *xy;
    size_t n, cap;
    int nomem;
} run;

static void run_add(run *r, double sx, double sy) {
    if (!grow((void **)&r->xy, &r->cap, r->n + 1, 2 * sizeof *r->xy)) {
        r->nomem = 1;
        return;
    }
    pc_screen_to_world(r->c, sx, sy, &r->xy[2 * r->n], &r->xy[2 * r->n + 1]);
    r->n++;
}

static int run_flush(run *r, int color, int pen, int hidden, pc_hidden_mode mode) {
    int st = PC_OK;
    if (r->n >= 2 && !(hidden && mode == PC_HIDDEN_HIDE)) {
        pc_canvas *c = r->c;
        int old = c->pen;
        c->pen = pen < (int)c->npens ? pen : 0;
        if (hidden && mode == PC_HIDDEN_DASHED) {
            static const double dash[2] = {4, 3};
            st = pc_pen(c, c->pens[c->pen].width, dash, 2);
        }
        if (st == PC_OK) st = pc_path(c, r->n, r->xy, NULL, 0, 0, color);
        c->pen = old;
    }
    r->n = 0;
    return r->nomem ? PC_ENOMEM : st;
}

/* The point at t of segment a-b, and its screen image (0: none). */
static int at_t(const pc_scene *sc, const double *a, const double *b, double t, double x[3],
                double *sx, double *sy) {
    for (int j = 0; j < 3; j++) x[j] = a[j] + t * (b[j] - a[j]);
    return project(sc, x, sx, sy);
}

#define SAMPLE_PX 3   /* the visibility is sampled this far apart, each change then bisected */

/* One stroke: each segment (straight in space and on the screen) is sampled SAMPLE_PX pixels
 * apart; where the visibility changes between two samples the change is found by bisection
 * to 1/1024 of the step, and the runs keep only their ends and the changes as vertices. */
static int draw_stroke(const pc_scene *sc, const stroke *s, run *r, pc_hidden_mode mode) {
    int st = PC_OK, cur = -1;   /* cur: the visibility of the run being gathered */
    int show = mode == PC_HIDDEN_SHOW;
    for (size_t i = 0; i < s->n && st == PC_OK; i++) {
        const double *b = sc->pts + 3 * (s->first + i);
        if (sc->brk[s->first + i]) {   /* a new piece: flush, start at this point */
            st = run_flush(r, s->color, s->pen, cur == 0, mode);
            double sx, sy;
            if (!project(sc, b, &sx, &sy)) { cur = -1; continue; }
            cur = show || pc_scene_visible(sc, b);
            run_add(r, sx, sy);
            continue;
        }
        const double *a = b - 3;
        double ax, ay, bx, by, x[3];
        if (cur < 0 || !project(sc, a, &ax, &ay) || !project(sc, b, &bx, &by)) {
            st = run_flush(r, s->color, s->pen, cur == 0, mode);
            cur = -1;
            if (project(sc, b, &bx, &by)) {   /* start again at b */
                cur = show || pc_scene_visible(sc, b);
                run_add(r, bx, by);
            }
            continue;
        }
        int m = (int)fmin(4096, ceil(hypot(bx - ax, by - ay) / SAMPLE_PX));
        if (m < 1) m = 1;
        double tprev = 0;
        for (int k = 1; k <= m && st == PC_OK; k++) {
            double t = (double)k / m, sx, sy;
            if (!at_t(sc, a, b, t, x, &sx, &sy)) continue;
            int vis = show || pc_scene_visible(sc, x);
            if (vis != cur) {   /* the run ends where the visibility changes */
                double lo = tprev, hi = t;
                for (int it = 0; it < 10; it++) {
                    double mid = (lo + hi) / 2, mx, my;
                    if (!at_t(sc, a, b, mid, x, &mx, &my)) break;
                    if ((show || pc_scene_visible(sc, x)) == cur) lo = mid;
                    else hi = mid;
                }
                double hx, hy;
                if (at_t(sc, a, b, (lo + hi) / 2, x, &hx, &hy)) run_add(r, hx, hy);
                st = run_flush(r, s->color, s->pen, cur == 0, mode);
                if (at_t(sc, a, b, (lo + hi) / 2, x, &hx, &hy)) run_add(r, hx, hy);
                cur = vis;
            }
            tprev = t;
        }
        run_add(r, bx, by);
    }
    if (st == PC_OK) st = run_flush(r, s->color, s->pen, cur == 0, mode);
    return st;
}

int pc_scene_draw(const pc_scene *sc, pc_canvas *c, pc_hidden_mode mode) {
    run r = {c, NULL, 0, 0, 0};
    pc_stroke pen = c->pens[c->pen];   /* the dashed runs change it: restored at the end */
    int st = PC_OK;
    for (size_t i = 0; i < sc->nst && st == PC_OK; i++) {
        const stroke *s = &sc->st[i];
        if (!s->mark) {
            st = draw_stroke(sc, s, &r, mode);
            continue;
        }
        const double *x = sc->pts + 3 * s->first;
        double sx, sy, wx, wy;
        if (s->mark == 4) {   /* an arrow head: only where its tip is seen */
            double tx, ty, fx, fy, t2x, t2y;
            if (!project(sc, x, &fx, &fy) || !project(sc, x + 3, &tx, &ty)) continue;
            if (!pc_scene_visible(sc, x + 3) && mode != PC_HIDDEN_SHOW) continue;
            pc_screen_to_world(c, fx, fy, &wx, &wy);
            pc_screen_to_world(c, tx, ty, &t2x, &t2y);
            if (fx != tx || fy != ty) st = pc_arrow_head(c, wx, wy, t2x, t2y, s->size, s->color);
            continue;
        }
        if (!project(sc, x, &sx, &sy)) continue;
        int vis = pc_scene_visible(sc, x);
        if (s->mark == 2) {   /* a label: only where its point is seen */
            pc_screen_to_world(c, sx, sy, &wx, &wy);
            if (vis || mode == PC_HIDDEN_SHOW)
                st = pc_text(c, wx, wy, s->text, s->style, 3, (int)s->size, s->color);
            if (st == PC_OK && s->styled && (vis || mode == PC_HIDDEN_SHOW))
                st = pc_text_style(c, s->font ? s->font : "", s->pt, s->halo);
            continue;
        }
        if (s->mark == 3) {   /* a dot: only where it is seen */
            pc_screen_to_world(c, sx, sy, &wx, &wy);
            if (vis || mode == PC_HIDDEN_SHOW) st = pc_pset(c, wx, wy, s->color);
            continue;
        }
        if (!vis && mode != PC_HIDDEN_SHOW) {
            if (mode == PC_HIDDEN_HIDE) continue;
        }
        pc_screen_to_world(c, sx, sy, &wx, &wy);
        int style = !vis && mode == PC_HIDDEN_DASHED && s->style == PC_MARK_DOT ? PC_MARK_OPEN : s->style;
        st = pc_mark(c, wx, wy, style, s->size, s->color);
    }
    free(r.xy);
    int back = pc_pen(c, pen.width, pen.ndash ? pen.dash : NULL, pen.ndash);
    return st != PC_OK ? st : back;
}
