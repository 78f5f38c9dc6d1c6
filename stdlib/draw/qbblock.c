/* GET and PUT of graphics blocks (qbscreen.h): a rectangle of attributes copied off the screen
 * and put back with one of QBasic's five actions. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "canvas_internal.h"
#include "qbscreen.h"

/* A world point to a screen pixel inside the view; PC_EARG (QBasic: Illegal function call)
 * outside it. */
static int view_pixel(pc_canvas *c, const char *what, double x, double y, long *px, long *py) {
    if (!(isfinite(x) && isfinite(y)))
        return pc_fail(c, "%s: coordinates must be finite numbers, got (%g, %g)", what, x, y);
    double sx, sy;
    pc_world_to_screen(c, x, y, &sx, &sy);
    *px = pc_px(sx);
    *py = pc_px(sy);
    const pc_rect *v = &c->view;
    if (*px < v->x0 || *px > v->x1 || *py < v->y0 || *py > v->y1)
        return pc_fail(c, "%s: pixel (%ld, %ld) is outside the view %d,%d-%d,%d", what, *px, *py,
                       v->x0, v->y0, v->x1, v->y1);
    return PC_OK;
}

int pc_get_block(pc_canvas *c, double x1, double y1, double x2, double y2, pc_block **out) {
    long ax, ay, bx, by;
    int ok = view_pixel(c, "get", x1, y1, &ax, &ay);
    if (ok == PC_OK) ok = view_pixel(c, "get", x2, y2, &bx, &by);
    if (ok != PC_OK) return ok;
    if (ax > bx) { long t = ax; ax = bx; bx = t; }
    if (ay > by) { long t = ay; ay = by; by = t; }
    pc_block *b = malloc(sizeof *b);
    int w = (int)(bx - ax + 1), h = (int)(by - ay + 1);
    uint16_t *px = malloc((size_t)w * h * sizeof *px);
    if (!b || !px) {
        free(b);
        free(px);
        return pc_fail_code(c, PC_ENOMEM, "get: out of memory for a %dx%d block", w, h);
    }
    for (int r = 0; r < h; r++)
        memcpy(px + (size_t)r * w, c->pixels + (size_t)(ay + r) * c->width + ax, (size_t)w * sizeof *px);
    b->w = w;
    b->h = h;
    b->px = px;
    *out = b;
    return PC_OK;
}

void pc_block_free(pc_block *b) {
    if (!b) return;
    free(b->px);
    free(b);
}

long pc_block_bytes(const pc_canvas *c, int w, int h) {
    if (c->ncolors == 256) return 4 + (long)w * h;                       /* SCREEN 13 */
    int bits = c->ncolors == 2 ? 1 : 2, planes = 1;                       /* SCREEN 2, 1 */
    if (c->ncolors == 16) bits = 1, planes = 4;                           /* EGA/VGA planes */
    return 4 + ((long)w * bits + 7) / 8 * planes * h;
}

int pc_put_block(pc_canvas *c, double x, double y, const pc_block *b, int action) {
    if (!b || b->w < 1 || b->h < 1) return pc_fail(c, "put: no block");
    if (action < PC_PUT_PSET || action > PC_PUT_XOR)
        return pc_fail(c, "put: action %d is not PSET, PRESET, AND, OR or XOR", action);
    long ax, ay;
    int ok = view_pixel(c, "put", x, y, &ax, &ay);
    if (ok != PC_OK) return ok;
    const pc_rect *v = &c->view;
    if (ax + b->w - 1 > v->x1 || ay + b->h - 1 > v->y1)
        return pc_fail(c, "put: a %dx%d block at pixel (%ld, %ld) does not fit in the view", b->w,
                       b->h, ax, ay);
    /* the colour bits of an attribute: PRESET and the logical actions work within them */
    unsigned mask = (unsigned)c->ncolors - 1;
    for (int r = 0; r < b->h; r++) {
        uint16_t *dst = c->pixels + (size_t)(ay + r) * c->width + ax;
        const uint16_t *src = b->px + (size_t)r * b->w;
        for (int i = 0; i < b->w; i++) {
            unsigned s = src[i], d = dst[i];
            if (s >= 256 || d >= 256) {   /* a true colour: only PSET has a meaning */
                if (action != PC_PUT_PSET) return pc_fail(c, "put: true colours only with PSET");
                dst[i] = (uint16_t)s;
                continue;
            }
            switch (action) {
            case PC_PUT_PSET: d = s; break;
            case PC_PUT_PRESET: d = ~s & mask; break;
            case PC_PUT_AND: d = s & d; break;
            case PC_PUT_OR: d = (s | d) & mask; break;
            default: d = (s ^ d) & mask; break;
            }
            dst[i] = (uint16_t)d;
        }
    }
    c->version++;
    return pc_record_pixels(c, (int)ax, (int)ay, (int)ax + b->w - 1, (int)ay + b->h - 1);
}
