/* Filled paths (pc_fill_path, canvas.h): a scanline fill of the closed subpaths by the
 * pixel-centre rule stated in canvas.h, and one PC_OP_FILLPATH operation, which the SVG
 * writer turns into a filled <path>.
 *
 * Why the rule makes shared edges exact: every edge is stored with its upper end first
 * (smaller y on the y-down screen), whichever way the subpath runs along it, and its
 * crossing with scanline j is computed from that end only.  Two polygons sharing an edge
 * therefore get the very same double for every crossing, and the half-open runs
 * ceil(x_left) <= i < ceil(x_right) on either side of it meet without overlap or gap. */
#include <math.h>
#include <stdlib.h>
#include "canvas.h"
#include "canvas_internal.h"

#define FAR_PX 1e15      /* beyond this a double's step is 1/8 px: the fill cannot be placed */
#define CUBIC_TOL 0.1    /* px: as strokes flatten cubics (raster.c) */

/* An edge that crosses scanlines: rows ya <= j < yb, x = xa + (j - ya) * slope; dir +1 when
 * the subpath runs down the screen along it, -1 when up (the winding number's step). */
typedef struct { double ya, yb, xa, slope; int dir; } edge;

typedef struct { edge *e; size_t n, cap; } edge_list;

static int add_edge(edge_list *L, pc_xy a, pc_xy b) {
    if (a.y == b.y) return 1;   /* level: no scanline meets it under the half-open rule */
    int down = a.y < b.y;
    pc_xy top = down ? a : b, bot = down ? b : a;
    if (ceil(top.y) >= bot.y) return 1;   /* between two rows of pixel centres */
    if (!pc_grow((void **)&L->e, &L->cap, L->n + 1, sizeof *L->e)) return 0;
    L->e[L->n++] = (edge){top.y, bot.y, top.x, (bot.x - top.x) / (bot.y - top.y), down ? 1 : -1};
    return 1;
}

/* The edges of the op's closed subpaths, cubics flattened; 0 when out of memory. */
static int path_edges(const pc_canvas *c, const pc_op *op, edge_list *L) {
    const pc_xy *p = c->pts + op->first;
    const uint8_t *tag = c->tags + op->first;
    size_t n = op->count;
    pc_xy cur = p[0], start = p[0];
    for (size_t i = 0; i < n;) {
        if (tag[i] == PC_PATH_MOVE) {
            if (!add_edge(L, cur, start)) return 0;   /* close the previous subpath */
            start = cur = p[i++];
        } else if (tag[i] == PC_PATH_LINE) {
            if (!add_edge(L, cur, p[i])) return 0;
            cur = p[i++];
        } else {
            const pc_xy q[4] = {cur, p[i], p[i + 1], p[i + 2]};
            int k = pc_cubic_segments(q, CUBIC_TOL);
            for (int j = 1; j <= k; j++) {
                pc_xy e = j == k ? q[3] : pc_cubic_at(q, (double)j / k);
                if (!add_edge(L, cur, e)) return 0;
                cur = e;
            }
            i += 3;
        }
    }
    return add_edge(L, cur, start);
}

static int by_top(const void *a, const void *b) {
    const edge *p = a, *q = b;
    return (p->ya > q->ya) - (p->ya < q->ya);
}

typedef struct { double x; int dir; } crossing;

static int inside(int rule, int winding) {
    return rule == PC_FILL_EVENODD ? winding % 2 != 0 : winding != 0;
}

/* Pixels ceil(xs) <= i < ceil(xe) of row j, within the view. */
static void run(pc_canvas *c, long j, double xs, double xe, int color) {
    const pc_rect *v = &c->view;
    double a = fmax(ceil(xs), v->x0), b = fmin(ceil(xe) - 1, v->x1);
    if (a > b) return;
    pc_fill_px(c->pixels + (size_t)j * c->width + (size_t)a, color, (size_t)(b - a + 1));
}

/* The scanline fill with an active edge list; 0 when out of memory. */
static int scan(pc_canvas *c, edge *e, size_t n, int rule, int color) {
    if (n == 0) return 1;
    qsort(e, n, sizeof *e, by_top);
    double ybot = e[0].yb;
    for (size_t k = 1; k < n; k++) ybot = fmax(ybot, e[k].yb);
    const pc_rect *v = &c->view;
    double j0 = fmax(ceil(e[0].ya), v->y0), j1 = fmin(ceil(ybot) - 1, v->y1);
    if (j0 > j1) return 1;
    size_t *act = malloc(n * sizeof *act);
    crossing *cr = malloc(n * sizeof *cr);
    if (!act || !cr) {
        free(act);
        free(cr);
        return 0;
    }
    size_t nact = 0, next = 0;
    for (long j = (long)j0; j <= (long)j1; j++) {
        while (next < n && e[next].ya <= j) act[nact++] = next++;
        size_t m = 0;
        for (size_t k = 0; k < nact; k++) {
            const edge *g = &e[act[k]];
            if (g->yb <= j) continue;   /* finished: dropped from the list */
            act[m++] = act[k];
        }
        nact = m;
        for (size_t k = 0; k < nact; k++) {   /* crossings by x: insertion sort (nearly sorted) */
            const edge *g = &e[act[k]];
            crossing x = {g->xa + ((double)j - g->ya) * g->slope, g->dir};
            size_t q = k;
            while (q > 0 && cr[q - 1].x > x.x) {
                cr[q] = cr[q - 1];
                q--;
            }
            cr[q] = x;
        }
        int w = 0;
        double xs = 0;
        for (size_t k = 0; k < nact; k++) {
            int was = inside(rule, w);
            w += cr[k].dir;
            int is = inside(rule, w);
            if (!was && is) xs = cr[k].x;
            else if (was && !is) run(c, j, xs, cr[k].x, color);
        }
    }
    free(act);
    free(cr);
    return 1;
}

int pc_fill_path(pc_canvas *c, size_t n, const double *xy, const uint8_t *verbs, size_t nverbs,
                 int rule, int color) {
    uint32_t first = 0;
    int ok = pc_check_color(c, &color, c->fg);
    int tile = rule >= 0 && rule & PC_FILL_TILE;
    if (tile) rule &= ~PC_FILL_TILE;
    if (ok == PC_OK && rule != PC_FILL_EVENODD && rule != PC_FILL_NONZERO)
        ok = pc_fail(c, "fill: the fill rule must be even-odd (%d) or nonzero (%d), got %d",
                     PC_FILL_EVENODD, PC_FILL_NONZERO, rule);
    if (ok == PC_OK) ok = pc_push_path_pts(c, "fill", n, xy, verbs, nverbs, &first);
    if (ok != PC_OK) return ok;
    for (size_t i = 0; i < n; i++) {
        const pc_xy *q = &c->pts[first + i];
        if (!(fabs(q->x) <= FAR_PX && fabs(q->y) <= FAR_PX)) {
            c->npts = first;
            return pc_fail(c, "fill: point %zu lies too far outside the screen (beyond %g pixels) "
                              "to place the fill to the pixel", i + 1, FAR_PX);
        }
    }
    pc_op tmp = {.kind = PC_OP_FILLPATH, .flags = (uint8_t)rule, .first = first,
                 .count = (uint32_t)n};
    edge_list L = {0};
    int done = path_edges(c, &tmp, &L) && scan(c, L.e, L.n, rule, color);
    free(L.e);
    if (!done) {
        c->npts = first;
        return pc_fail_code(c, PC_ENOMEM, "fill: out of memory");
    }
    pc_op *op = pc_push_op(c, PC_OP_FILLPATH, color);
    if (!op) return PC_ENOMEM;
    op->flags = (uint8_t)(tmp.flags | (tile ? PC_FILL_TILE : 0));
    op->first = first;
    op->count = tmp.count;
    c->last_x = xy[2 * n - 2];
    c->last_y = xy[2 * n - 1];
    return PC_OK;
}
