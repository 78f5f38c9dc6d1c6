/* Folding dots into pixels (issue 15, item 6): memory bounded by the picture, not by the
 * number of PSET calls.  A dot costs 16 bytes and, when its colour differs from the dot
 * before, an op of 80 more; a million dots in changing colours were 94 MB.  The dots drawn
 * one after another in one VIEW (the run at the end of the display list) only need, for the
 * SVG, the last colour of each pixel they hit: the raster already shows nothing else.  So
 * when that run passes c->dot_budget dots it becomes one PIXELS op (8 bytes a pixel hit),
 * and the dots drawn after it join the same op at the next fold. */
#include <stdlib.h>
#include <string.h>
#include "canvas_internal.h"

/* The start of the run at the end of the list: ops of kind DOTS (and a PIXELS op made by an
 * earlier fold) after the last other op, in the current clip. */
static size_t run_start(const pc_canvas *c) {
    size_t lo = c->nclips ? c->clips[c->nclips - 1].first : 0, s = c->nops;
    while (s > lo && (c->ops[s - 1].kind == PC_OP_DOTS || c->ops[s - 1].kind == PC_OP_PIXELS)) {
        s--;
        if (c->ops[s].kind == PC_OP_PIXELS) break;   /* an earlier fold: the run starts there */
    }
    return s;
}

void pc_fold_dots(pc_canvas *c) {
    size_t s = run_start(c);
    size_t d0 = c->ndots, l0 = c->nlpx;   /* where the run's dots and pixels start */
    for (size_t k = s; k < c->nops; k++) {
        if (c->ops[k].kind == PC_OP_DOTS && c->ops[k].first < d0) d0 = c->ops[k].first;
        if (c->ops[k].kind == PC_OP_PIXELS) l0 = c->ops[k].first;
    }
    /* a run cut short by another op is counted afresh from its start */
    if (c->ndots - d0 <= c->dot_budget / 2 || s == c->nops) {
        c->fold_mark = d0;
        return;
    }
    size_t npx = (size_t)c->width * (size_t)c->height;
    uint32_t *grid = calloc(npx, sizeof *grid);    /* 0: not hit; else attribute + 1 */
    if (!grid) {
        c->fold_mark = c->ndots;                   /* no memory: keep the dots, try later */
        return;
    }
    size_t lo = npx, hi = 0;                       /* the pixel indices hit */
    for (size_t i = l0; i < c->nlpx; i++) {        /* the earlier fold's pixels first */
        grid[c->lpx[i].idx] = (uint32_t)c->lpx[i].color + 1;
        if (c->lpx[i].idx < lo) lo = c->lpx[i].idx;
        if (c->lpx[i].idx + 1 > hi) hi = c->lpx[i].idx + 1;
    }
    /* then every dot, in order, where the raster put it: pc_px of its screen position, if
     * inside the clip (the run's view); the last dot of a pixel wins */
    const pc_rect r = c->clips[c->nclips - 1].r;
    for (size_t k = s; k < c->nops; k++) {
        const pc_op *op = &c->ops[k];
        if (op->kind != PC_OP_DOTS) continue;
        for (size_t j = op->first; j < (size_t)op->first + op->count; j++) {
            long ix = pc_px(c->dots[j].x), iy = pc_px(c->dots[j].y);
            if (ix < r.x0 || ix > r.x1 || iy < r.y0 || iy > r.y1) continue;
            size_t idx = (size_t)iy * (size_t)c->width + (size_t)ix;
            grid[idx] = (uint32_t)op->color + 1;
            if (idx < lo) lo = idx;
            if (idx + 1 > hi) hi = idx + 1;
        }
    }
    size_t count = 0;
    for (size_t i = lo; i < hi; i++) count += grid[i] != 0;
    if (l0 + count > UINT32_MAX ||
        !pc_grow((void **)&c->lpx, &c->caplpx, l0 + count + 1, sizeof *c->lpx)) {
        free(grid);                                /* nothing changed: keep the dots */
        c->fold_mark = c->ndots;
        return;
    }
    c->nlpx = l0;                                  /* the earlier fold's pixels are rewritten */
    for (size_t i = lo; i < hi; i++)
        if (grid[i]) c->lpx[c->nlpx++] = (pc_lpx){(uint32_t)i, (uint16_t)(grid[i] - 1)};
    free(grid);
    pc_op *op = &c->ops[s];
    memset(op, 0, sizeof *op);
    op->kind = PC_OP_PIXELS;
    op->first = (uint32_t)l0;
    op->count = (uint32_t)(c->nlpx - l0);
    c->nops = s + 1;
    c->ndots = d0;
    c->fold_mark = d0;
}
