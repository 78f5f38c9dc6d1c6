/* Automatic label placement: each label takes the best of a fixed list of candidate boxes round
 * its point.  The candidates are the eight sides at two near distances, then four rings
 * further out joined to the point by a leader line.  The cost ranks, from most to least
 * important: overlapping another label, leaving the picture, covering another label's point,
 * the ink covered (a summed-area table of the stroked pixels), then distance and side.
 * Placing is greedy in the labels' order, then each label left overlapping is placed again
 * against all the others (twice), which resolves most of what the greedy order got wrong
 * (the others are at their best already: ink and points do not move); no randomness, so
 * the same picture always gives the same layout.  Other labels are found through a uniform
 * grid of cells, so n labels cost O(n) candidates each looking at a few neighbours. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "layout.h"

/* ---- the ink map ------------------------------------------------------------------------- */

int pc_inkmap_init(pc_inkmap *m, const uint8_t *mask, int w, int h) {
    m->w = w;
    m->h = h;
    m->sum = calloc((size_t)(w + 1) * (h + 1), sizeof *m->sum);
    if (!m->sum) return PC_ENOMEM;
    for (int y = 0; y < h; y++) {
        uint32_t row = 0;
        uint32_t *s = m->sum + (size_t)(y + 1) * (w + 1), *up = s - (w + 1);
        for (int x = 0; x < w; x++) {
            row += mask[(size_t)y * w + x] != 0;
            s[x + 1] = up[x + 1] + row;
        }
    }
    return PC_OK;
}

void pc_inkmap_free(pc_inkmap *m) {
    free(m->sum);
    m->sum = NULL;
}

static long clampl(double v, long lo, long hi) {
    long r = (long)floor(v);
    return r < lo ? lo : r > hi ? hi : r;
}

uint32_t pc_inkmap_count(const pc_inkmap *m, pc_box2 b) {
    long x0 = clampl(b.x0, 0, m->w), x1 = clampl(b.x1, 0, m->w);
    long y0 = clampl(b.y0, 0, m->h), y1 = clampl(b.y1, 0, m->h);
    if (x1 <= x0 || y1 <= y0) return 0;
    size_t W = (size_t)m->w + 1;
    return m->sum[y1 * W + x1] - m->sum[y0 * W + x1] - m->sum[y1 * W + x0] + m->sum[y0 * W + x0];
}

/* ---- candidate boxes ------------------------------------------------------------------------ */

/* text.c's rule for a cell box w x h beside pixel (X, Y), g pixels off. */
pc_box2 pc_label_box(double px, double py, double w, double h, int anchor, double gap) {
    double X = nearbyint(px), Y = nearbyint(py), g = nearbyint(gap), left, top;
    switch (anchor) {
    case PC_ANCHOR_NE: case PC_ANCHOR_E: case PC_ANCHOR_SE: left = X + g; break;
    case PC_ANCHOR_NW: case PC_ANCHOR_W: case PC_ANCHOR_SW: left = X - g - w + 1; break;
    default: left = X - floor(w / 2); break;
    }
    switch (anchor) {
    case PC_ANCHOR_NW: case PC_ANCHOR_N: case PC_ANCHOR_NE: top = Y - g - h + 1; break;
    case PC_ANCHOR_SW: case PC_ANCHOR_S: case PC_ANCHOR_SE: top = Y + g; break;
    default: top = Y - floor(h / 2); break;
    }
    return (pc_box2){left, top, left + w, top + h};
}

/* Sides in order of preference (the diagonals first: they leave the point's lines free), and
 * the rings: distance in pixels and the cost of going that far.  The near rings use the eight
 * sides as pc_text does; from LEADER_RING on, a label may sit in any of 16 directions (so the
 * labels of neighbouring points do not queue along the same eight rays) and a leader joins
 * it. */
static const int sides[8] = {PC_ANCHOR_NE, PC_ANCHOR_SE, PC_ANCHOR_NW, PC_ANCHOR_SW,
                             PC_ANCHOR_E, PC_ANCHOR_W, PC_ANCHOR_N, PC_ANCHOR_S};
static const double ring_gap[] = {3, 8, 16, 26, 40, 60, 90, 130, 180};
static const double ring_cost[] = {0, 30, 200, 260, 330, 420, 540, 700, 900};
#define NRINGS (sizeof ring_gap / sizeof ring_gap[0])
#define LEADER_RING 2
#define NDIRS 16

/* A far candidate: the box in direction k (of NDIRS, counter-clockwise from east, y down on
 * the screen) whose nearest edge is gap pixels off the point; its side is the nearest of the
 * eight (for the leader's end and for what a script reads back). */
static pc_box2 far_box(const pc_label *l, int k, double gap, int *anchor) {
    static const int side_of[8] = {PC_ANCHOR_E, PC_ANCHOR_NE, PC_ANCHOR_N, PC_ANCHOR_NW,
                                   PC_ANCHOR_W, PC_ANCHOR_SW, PC_ANCHOR_S, PC_ANCHOR_SE};
    static const double cs[NDIRS][2] = {   /* cos, sin of k * 22.5 degrees */
        {1, 0}, {0.92387953251128674, 0.38268343236508978}, {0.70710678118654757, 0.70710678118654757},
        {0.38268343236508978, 0.92387953251128674}, {0, 1}, {-0.38268343236508978, 0.92387953251128674},
        {-0.70710678118654757, 0.70710678118654757}, {-0.92387953251128674, 0.38268343236508978},
        {-1, 0}, {-0.92387953251128674, -0.38268343236508978}, {-0.70710678118654757, -0.70710678118654757},
        {-0.38268343236508978, -0.92387953251128674}, {0, -1}, {0.38268343236508978, -0.92387953251128674},
        {0.70710678118654757, -0.70710678118654757}, {0.92387953251128674, -0.38268343236508978}};
    double ca = cs[k][0], sa = cs[k][1];
    double d = gap + 0.5 * (fabs(ca) * l->w + fabs(sa) * l->h);
    double cx = nearbyint(l->px + d * ca - l->w / 2), cy = nearbyint(l->py - d * sa - l->h / 2);
    *anchor = side_of[((k + 1) / 2) % 8];
    return (pc_box2){cx, cy, cx + l->w, cy + l->h};
}

#define COST_OVERLAP 1e9
#define COST_OUTSIDE 1e11   /* worse than an overlap: a label off the picture is lost */
#define COST_POINT 1e5
#define COST_CROSSED 2000.0   /* any ink at all: more than going out with a leader */
#define COST_INK 60.0
#define LEADER_INK 800.0      /* a leader across a stroke: nearly as bad as the label across it */
#define PASSES 3              /* the greedy pass, then the labels left in conflict again */
#define OWN_MARK 2            /* the ink this close to a label's own point is its dot's */

/* ---- a grid of cells holding label indices --------------------------------------------- */

#define CELL 48.0
typedef struct { size_t *idx; size_t n, cap; } cell;
typedef struct {
    int nx, ny;
    double ox, oy;          /* the grid's origin: the labels may lie off the picture */
    cell *cells;
} grid;

static int grid_init(grid *g, double x0, double y0, double x1, double y1) {
    g->ox = x0;
    g->oy = y0;
    g->nx = (int)ceil((x1 - x0) / CELL) + 1;
    g->ny = (int)ceil((y1 - y0) / CELL) + 1;
    if (g->nx > 4096) g->nx = 4096;
    if (g->ny > 4096) g->ny = 4096;
    g->cells = calloc((size_t)g->nx * g->ny, sizeof *g->cells);
    return g->cells ? PC_OK : PC_ENOMEM;
}

static void grid_free(grid *g) {
    for (size_t i = 0; i < (size_t)g->nx * g->ny; i++) free(g->cells[i].idx);
    free(g->cells);
}

static void cell_range(const grid *g, pc_box2 b, int *i0, int *j0, int *i1, int *j1) {
    *i0 = (int)clampl((b.x0 - g->ox) / CELL, 0, g->nx - 1);
    *i1 = (int)clampl((b.x1 - g->ox) / CELL, 0, g->nx - 1);
    *j0 = (int)clampl((b.y0 - g->oy) / CELL, 0, g->ny - 1);
    *j1 = (int)clampl((b.y1 - g->oy) / CELL, 0, g->ny - 1);
}

static int grid_add(grid *g, pc_box2 b, size_t k) {
    int i0, j0, i1, j1;
    cell_range(g, b, &i0, &j0, &i1, &j1);
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            cell *c = &g->cells[(size_t)j * g->nx + i];
            if (c->n == c->cap) {
                size_t cap = c->cap ? 2 * c->cap : 4;
                size_t *p = realloc(c->idx, cap * sizeof *p);
                if (!p) return PC_ENOMEM;
                c->idx = p;
                c->cap = cap;
            }
            c->idx[c->n++] = k;
        }
    return PC_OK;
}

static void grid_remove(grid *g, pc_box2 b, size_t k) {
    int i0, j0, i1, j1;
    cell_range(g, b, &i0, &j0, &i1, &j1);
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            cell *c = &g->cells[(size_t)j * g->nx + i];
            for (size_t m = 0; m < c->n; m++)
                if (c->idx[m] == k) {
                    c->idx[m] = c->idx[--c->n];
                    break;
                }
        }
}

/* ---- placing ------------------------------------------------------------------------------ */

typedef struct {
    pc_label *lab;
    size_t n;
    const pc_inkmap *ink;
    double width, height;
    grid boxes, points;     /* the placed boxes; every label's point (a 1-pixel box) */
    uint8_t *placed;
    uint32_t *seen;         /* per label: the last query that counted it (no double counting) */
    uint32_t stamp;
    double *pt;             /* per label: its point's pixel, x then y */
    pc_box2 *box;           /* per label: its box as placed (compact, for the overlap test) */
    grid leaders;           /* the leader lines drawn so far, by their bounding boxes */
    double *lead;           /* per label: its leader's ends (x0, y0, x1, y1) */
    uint8_t *has_lead;
} placer;

/* Does segment s (x0, y0, x1, y1) enter box b (Liang-Barsky)? */
static int seg_hits(const double *s, pc_box2 b) {
    double t0 = 0, t1 = 1, dx = s[2] - s[0], dy = s[3] - s[1];
    double pq[4][2] = {{-dx, s[0] - b.x0}, {dx, b.x1 - s[0]}, {-dy, s[1] - b.y0}, {dy, b.y1 - s[1]}};
    for (int i = 0; i < 4; i++) {
        double pp = pq[i][0], q = pq[i][1];
        if (pp == 0) {
            if (q <= 0) return 0;
        } else {
            double r = q / pp;
            if (pp < 0) t0 = fmax(t0, r);
            else t1 = fmin(t1, r);
            if (t0 >= t1) return 0;
        }
    }
    return 1;
}

static pc_box2 seg_box(const double *s) {
    return (pc_box2){fmin(s[0], s[2]), fmin(s[1], s[3]), fmax(s[0], s[2]) + 1, fmax(s[1], s[3]) + 1};
}

int pc_label_leader(const pc_label *l, double seg[4]) {
    pc_box2 b = pc_label_clear(l->box);   /* it stops short of the room the label keeps */
    double qx = fmax(b.x0, fmin(l->px, b.x1 - 1)), qy = fmax(b.y0, fmin(l->py, b.y1 - 1));
    double dx = qx - l->px, dy = qy - l->py, d = hypot(dx, dy);
    if (d < 4) return 0;
    seg[0] = nearbyint(l->px + 2 * dx / d);   /* clear of the point's mark */
    seg[1] = nearbyint(l->py + 2 * dy / d);
    seg[2] = nearbyint(qx - dx / d);
    seg[3] = nearbyint(qy - dy / d);
    return 1;
}

/* Is there ink on pixel (x, y)?  Four look-ups in the summed-area table. */
static int ink_at(const pc_inkmap *m, long x, long y) {
    if (x < 0 || y < 0 || x >= m->w || y >= m->h) return 0;
    size_t W = (size_t)m->w + 1;
    const uint32_t *a = m->sum + (size_t)y * W + x, *b = a + W;
    return b[1] - a[1] - b[0] + a[0] != 0;
}

/* What a leader costs: the ink it crosses (sampled a pixel apart) and, the most, every other
 * label it would cross; counting stops once it reaches `budget`. */
static double leader_cost(placer *p, size_t k, const double *seg, double budget) {
    double cost = 0, len = hypot(seg[2] - seg[0], seg[3] - seg[1]);
    uint32_t ink = 0;
    if (p->ink && len > 0) {
        double dx = (seg[2] - seg[0]) / len, dy = (seg[3] - seg[1]) / len;
        for (double t = 0; t <= len; t += 1) {
            ink += ink_at(p->ink, lrint(seg[0] + t * dx), lrint(seg[1] + t * dy));
            if (ink && LEADER_INK >= budget) return LEADER_INK;   /* lost already */
        }
    }
    if (ink) cost += LEADER_INK + COST_INK / 4 * ink;
    if (cost >= budget) return cost;
    int i0, j0, i1, j1;
    p->stamp++;
    cell_range(&p->boxes, seg_box(seg), &i0, &j0, &i1, &j1);
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            const cell *c = &p->boxes.cells[(size_t)j * p->boxes.nx + i];
            for (size_t m = 0; m < c->n; m++) {
                size_t o = c->idx[m];
                if (o == k || p->seen[o] == p->stamp) continue;
                p->seen[o] = p->stamp;
                if (seg_hits(seg, p->box[o])) cost += COST_CROSSED;
            }
        }
    return cost;
}

static pc_box2 point_box(const pc_label *l) {
    double X = nearbyint(l->px), Y = nearbyint(l->py);
    return (pc_box2){X, Y, X + 1, Y + 1};
}

/* Does pixel (x, y) lie in box b? */
static int px_in(const double *q, pc_box2 b) {
    return q[0] >= b.x0 && q[0] < b.x1 && q[1] >= b.y0 && q[1] < b.y1;
}

/* The ink under clear box b of label k but its own point's dot. */
static uint32_t box_ink(const placer *p, size_t k, pc_box2 b) {
    if (!p->ink) return 0;
    const double *q = p->pt + 2 * k;
    pc_box2 own = {q[0] - OWN_MARK, q[1] - OWN_MARK, q[0] + OWN_MARK + 1, q[1] + OWN_MARK + 1};
    pc_box2 both = {fmax(own.x0, b.x0), fmax(own.y0, b.y0), fmin(own.x1, b.x1), fmin(own.y1, b.y1)};
    uint32_t ink = pc_inkmap_count(p->ink, b);
    if (both.x1 > both.x0 && both.y1 > both.y0) ink -= pc_inkmap_count(p->ink, both);
    return ink;
}

/* The cost of box b for label k on top of `base`; the cheap terms (the edge, the ink) first,
 * and the searches of the grids only while the total can still beat `best`. */
static double cost_of(placer *p, size_t k, pc_box2 b, double base, double best) {
    double cost = base;
    int i0, j0, i1, j1;
    pc_box2 in = p->lab[k].bounds;
    if (!(in.x1 > in.x0 && in.y1 > in.y0)) in = (pc_box2){0, 0, p->width, p->height};
    b = pc_label_clear(b);   /* from here on the box with its clearance */
    if (b.x0 < in.x0 || b.y0 < in.y0 || b.x1 > in.x1 || b.y1 > in.y1) {
        double ix = fmin(b.x1, in.x1) - fmax(b.x0, in.x0), iy = fmin(b.y1, in.y1) - fmax(b.y0, in.y0);
        double inside = ix > 0 && iy > 0 ? ix * iy : 0;
        cost += COST_OUTSIDE + ((b.x1 - b.x0) * (b.y1 - b.y0) - inside);
    }
    pc_box2 near = b;
    uint32_t ink = box_ink(p, k, near);
    if (ink) cost += COST_CROSSED + COST_INK * ink;
    if (cost >= best) return cost;
    /* an overlapping box is counted in the one cell holding the top-left corner of the
     * overlap, so a box in several cells counts once */
    cell_range(&p->boxes, b, &i0, &j0, &i1, &j1);
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            const cell *c = &p->boxes.cells[(size_t)j * p->boxes.nx + i];
            for (size_t m = 0; m < c->n; m++) {
                size_t o = c->idx[m];
                const pc_box2 *q = &p->box[o];
                if (o == k || !pc_box2_overlap(b, *q)) continue;
                if (clampl((fmax(b.x0, q->x0) - p->boxes.ox) / CELL, 0, p->boxes.nx - 1) == i &&
                    clampl((fmax(b.y0, q->y0) - p->boxes.oy) / CELL, 0, p->boxes.ny - 1) == j)
                    cost += COST_OVERLAP;
                if (cost >= best) return cost;   /* lost already: no need to count on */
            }
        }
    if (cost >= best) return cost;
    p->stamp++;   /* the leaders of others across it */
    cell_range(&p->leaders, near, &i0, &j0, &i1, &j1);
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            const cell *c = &p->leaders.cells[(size_t)j * p->leaders.nx + i];
            for (size_t m = 0; m < c->n; m++) {
                size_t o = c->idx[m];
                if (o == k || p->seen[o] == p->stamp) continue;
                p->seen[o] = p->stamp;
                if (seg_hits(p->lead + 4 * o, near)) cost += COST_CROSSED;
                if (cost >= best) return cost;
            }
        }
    if (cost >= best) return cost;
    p->stamp++;
    cell_range(&p->points, near, &i0, &j0, &i1, &j1);
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            const cell *c = &p->points.cells[(size_t)j * p->points.nx + i];
            for (size_t m = 0; m < c->n; m++) {
                size_t o = c->idx[m];
                if (o == k || p->seen[o] == p->stamp) continue;
                p->seen[o] = p->stamp;
                const double *q = p->pt + 2 * o, *mine = p->pt + 2 * k;
                if (px_in(q, near) && !(q[0] == mine[0] && q[1] == mine[1])) cost += COST_POINT;
            }
        }
    return cost;
}

static int place_one(placer *p, size_t k, double *cost_out) {
    pc_label *l = &p->lab[k];
    if (p->placed[k]) grid_remove(&p->boxes, p->box[k], k);
    if (p->has_lead[k]) grid_remove(&p->leaders, seg_box(p->lead + 4 * k), k);
    p->has_lead[k] = 0;
    double best = INFINITY, near_cost = INFINITY;
    pc_label near = *l;
    for (size_t r = 0; r < NRINGS; r++) {
        if (r == LEADER_RING) near_cost = best, near = *l;   /* the best of the eight sides */
        for (int s = 0; s < (r < LEADER_RING ? 8 : NDIRS); s++) {
            int anchor = r < LEADER_RING ? sides[s] : 0;
            pc_box2 b = r < LEADER_RING
                ? pc_label_box(l->px, l->py, l->w, l->h, anchor, ring_gap[r])
                : far_box(l, (s + 2) % NDIRS, ring_gap[r], &anchor);   /* from NE round */
            double cost = ring_cost[r] + 2.0 * s, seg[4];
            if (cost >= best) continue;
            cost = cost_of(p, k, b, cost, best);
            if (cost < best && r >= LEADER_RING && !l->no_leader) {
                pc_label cand = *l;
                cand.box = b;
                if (pc_label_leader(&cand, seg)) cost += leader_cost(p, k, seg, best - cost);
            }
            if (cost < best) {
                best = cost;
                l->box = b;
                l->anchor = anchor;
                l->gap = ring_gap[r];
                l->leader = r >= LEADER_RING && !l->no_leader;
            }
        }
    }
    /* gone far but crossed there too: better crossed beside its point, without a leader */
    if (l->gap > ring_gap[LEADER_RING - 1] && near_cost < COST_OVERLAP &&
        box_ink(p, k, pc_label_clear(l->box)) > 0) {
        *l = near;
        best = near_cost;
    }
    p->placed[k] = 1;
    p->box[k] = pc_label_clear(l->box);
    *cost_out = best;
    if (l->leader && pc_label_leader(l, p->lead + 4 * k)) {
        p->has_lead[k] = 1;
        int st = grid_add(&p->leaders, seg_box(p->lead + 4 * k), k);
        if (st != PC_OK) return st;
    }
    return grid_add(&p->boxes, p->box[k], k);
}

/* ---- the last placement, kept ---------------------------------------------------------------
 * One run writes a picture to several files (PNG and SVG): each resolves its own copy of the
 * canvas, with the same labels among the same ink.  The last placement is kept (per thread)
 * with what it was made from: the labels as given, the picture's size and a 64-bit hash of
 * the ink map; the same inputs give back the same result without placing again. */
typedef struct { pc_label *in, *out; size_t n; double width, height; uint64_t ink; } kept;
static _Thread_local kept last;

/* A label as given: what placement reads, its results cleared. */
static pc_label given(const pc_label *l) {
    pc_label g;
    memset(&g, 0, sizeof g);
    g.px = l->px; g.py = l->py; g.w = l->w; g.h = l->h; g.fixed = l->fixed;
    if (l->fixed) g.box = l->box, g.anchor = l->anchor;
    g.bounds = l->bounds;
    g.no_leader = l->no_leader;
    return g;
}

static uint64_t ink_hash(const pc_inkmap *m) {
    uint64_t h = 1469598103934665603u;   /* FNV-1a over the table's words */
    if (!m) return h;
    size_t N = (size_t)(m->w + 1) * (m->h + 1);
    for (size_t i = 0; i < N; i++) h = (h ^ m->sum[i]) * 1099511628211u;
    return h ^ ((uint64_t)m->w << 32 | (uint32_t)m->h);
}

static int recall(pc_label *lab, size_t n, uint64_t ink, double width, double height) {
    if (!last.in || last.n != n || last.ink != ink || last.width != width || last.height != height) return 0;
    for (size_t k = 0; k < n; k++) {
        pc_label g = given(&lab[k]);
        if (memcmp(&g, &last.in[k], sizeof g)) return 0;
    }
    memcpy(lab, last.out, n * sizeof *lab);
    return 1;
}

static void keep(const pc_label *in, const pc_label *lab, size_t n, uint64_t ink, double width,
                 double height) {
    free(last.in);
    free(last.out);
    last = (kept){malloc(n * sizeof *lab), malloc(n * sizeof *lab), n, width, height, ink};
    if (!last.in || !last.out) {   /* no memory: nothing kept */
        free(last.in);
        free(last.out);
        last = (kept){0};
        return;
    }
    memcpy(last.in, in, n * sizeof *in);
    memcpy(last.out, lab, n * sizeof *lab);
}

static int place(pc_label *lab, size_t n, const pc_inkmap *ink, double width, double height);

int pc_place_labels(pc_label *lab, size_t n, const pc_inkmap *ink, double width, double height) {
    if (n == 0) return PC_OK;
    uint64_t h = ink_hash(ink);
    if (recall(lab, n, h, width, height)) return PC_OK;
    pc_label *in = malloc(n * sizeof *in);
    for (size_t k = 0; in && k < n; k++) in[k] = given(&lab[k]);
    int st = place(lab, n, ink, width, height);
    if (st == PC_OK && in) keep(in, lab, n, h, width, height);
    free(in);
    return st;
}

static int place(pc_label *lab, size_t n, const pc_inkmap *ink, double width, double height) {
    placer p = {lab, n, ink, width, height, {0}, {0}, NULL, NULL, 0, NULL, NULL, {0}, NULL, NULL};
    /* the grids cover the picture and every point (with the farthest ring round it) */
    double x0 = 0, y0 = 0, x1 = width, y1 = height, reach = ring_gap[NRINGS - 1];
    for (size_t k = 0; k < n; k++) {
        double wx = lab[k].w + reach, hy = lab[k].h + reach;
        if (lab[k].fixed) {
            x0 = fmin(x0, lab[k].box.x0); y0 = fmin(y0, lab[k].box.y0);
            x1 = fmax(x1, lab[k].box.x1); y1 = fmax(y1, lab[k].box.y1);
        }
        x0 = fmin(x0, lab[k].px - wx); y0 = fmin(y0, lab[k].py - hy);
        x1 = fmax(x1, lab[k].px + wx); y1 = fmax(y1, lab[k].py + hy);
    }
    int st = grid_init(&p.boxes, x0, y0, x1, y1);
    if (st == PC_OK) st = grid_init(&p.points, x0, y0, x1, y1);
    if (st == PC_OK) st = grid_init(&p.leaders, x0, y0, x1, y1);
    p.lead = malloc(4 * n * sizeof *p.lead);
    p.has_lead = calloc(n, 1);
    if (!p.lead || !p.has_lead) st = PC_ENOMEM;
    p.placed = calloc(n, 1);
    p.seen = calloc(n, sizeof *p.seen);
    p.pt = malloc(2 * n * sizeof *p.pt);
    p.box = malloc(n * sizeof *p.box);
    if (!p.placed || !p.seen || !p.pt || !p.box) st = PC_ENOMEM;
    for (size_t k = 0; st == PC_OK && k < n; k++) {
        p.box[k] = pc_label_clear(lab[k].box);
        p.pt[2 * k] = nearbyint(lab[k].px);
        p.pt[2 * k + 1] = nearbyint(lab[k].py);
    }
    for (size_t k = 0; k < n && st == PC_OK; k++) {
        st = grid_add(&p.points, point_box(&lab[k]), k);
        if (st == PC_OK && lab[k].fixed) {
            p.placed[k] = 1;
            st = grid_add(&p.boxes, p.box[k], k);
        }
    }
    /* the greedy pass, then two more for the labels left overlapping another or the edge: the
     * others are at their best already, since neither ink nor points move */
    double *cost = calloc(n, sizeof *cost);
    if (!cost) st = PC_ENOMEM;
    for (int pass = 0; pass < PASSES && st == PC_OK; pass++)
        for (size_t k = 0; k < n && st == PC_OK; k++)
            if (!lab[k].fixed && (pass == 0 || cost[k] >= COST_OVERLAP)) st = place_one(&p, k, &cost[k]);
    free(cost);
    if (p.boxes.cells) grid_free(&p.boxes);
    if (p.points.cells) grid_free(&p.points);
    if (p.leaders.cells) grid_free(&p.leaders);
    free(p.lead);
    free(p.has_lead);
    free(p.placed);
    free(p.seen);
    free(p.pt);
    free(p.box);
    return st;
}
