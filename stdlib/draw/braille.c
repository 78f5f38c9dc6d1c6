/* The canvas as braille text: scaling to cells, choosing a colour per cell, and writing the
 * cells with terminal colour escapes.  See braille.h. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "braille.h"

uint8_t pc_braille_bit(int dx, int dy) {
    static const uint8_t bits[4][2] = {{0x01, 0x08}, {0x02, 0x10}, {0x04, 0x20}, {0x40, 0x80}};
    return bits[dy & 3][dx & 1];
}

double pc_braille_fit(int width, int height, int max_cols, int max_rows, int *cols, int *rows) {
    if (max_cols < 1) max_cols = 1;
    if (max_rows < 1) max_rows = 1;
    double sx = (double)width / (2.0 * max_cols), sy = (double)height / (4.0 * max_rows);
    double scale = sx > sy ? sx : sy;
    if (scale < 1) scale = 1;
    /* the small slack keeps exact fits (640 / 5 = 128 dots) from gaining a column */
    *cols = (int)ceil(width / (2.0 * scale) - 1e-9);
    *rows = (int)ceil(height / (4.0 * scale) - 1e-9);
    if (*cols < 1) *cols = 1;
    if (*rows < 1) *rows = 1;
    if (*cols > max_cols) *cols = max_cols;
    if (*rows > max_rows) *rows = max_rows;
    return scale;
}

/* Pixel bounds [lo[d], lo[d+1]) of each of n dots along an axis of `size` pixels. */
static void dot_bounds(int n, double scale, int size, int *lo) {
    for (int d = 0; d <= n; d++) {
        double v = floor(d * scale + 1e-9);
        lo[d] = v > size ? size : (int)v;
    }
}

void pc_braille_render(const pc_canvas *c, int background, double scale, int cols, int rows,
                       pc_braille_cell *cells) {
    int ndx = 2 * cols, ndy = 4 * rows;
    int *xlo = malloc((size_t)(ndx + 1) * sizeof *xlo);
    int *ylo = malloc((size_t)(ndy + 1) * sizeof *ylo);
    /* per attribute in use (palette and true colours): pixels of it in the cell */
    size_t nattr = 256 + (size_t)c->ntrue;
    int *counts = calloc(nattr, sizeof *counts);
    uint16_t *seen = malloc(nattr * sizeof *seen);
    if (!xlo || !ylo || !counts || !seen) {
        free(xlo);
        free(ylo);
        free(counts);
        free(seen);
        for (int i = 0; i < cols * rows; i++) cells[i] = (pc_braille_cell){0, -1};
        return;
    }
    dot_bounds(ndx, scale, c->width, xlo);
    dot_bounds(ndy, scale, c->height, ylo);
    for (int row = 0; row < rows; row++) {
        for (int col = 0; col < cols; col++) {
            pc_braille_cell cell = {0, -1};
            int nseen = 0;
            for (int dy = 0; dy < 4; dy++) {
                for (int dx = 0; dx < 2; dx++) {
                    int gx = 2 * col + dx, gy = 4 * row + dy;
                    int ink = 0;
                    for (int y = ylo[gy]; y < ylo[gy + 1]; y++) {
                        const uint16_t *p = c->pixels + (size_t)y * c->width;
                        for (int x = xlo[gx]; x < xlo[gx + 1]; x++) {
                            if (p[x] == background) continue;
                            ink = 1;
                            if (counts[p[x]]++ == 0) seen[nseen++] = p[x];
                        }
                    }
                    if (ink) cell.bits |= pc_braille_bit(dx, dy);
                }
            }
            /* the colour covering most pixels; ties go to the lower attribute */
            int best = -1;
            for (int i = 0; i < nseen; i++) {
                int a = seen[i];
                if (best < 0 || counts[a] > counts[best] || (counts[a] == counts[best] && a < best))
                    best = a;
            }
            for (int i = 0; i < nseen; i++) counts[seen[i]] = 0;
            cell.color = best;
            cells[row * cols + col] = cell;
        }
    }
    free(xlo);
    free(ylo);
    free(counts);
    free(seen);
}

/* ---- terminal colours ---------------------------------------------------------------------- */

/* The 16 ANSI colours in SGR order, with the VGA values most terminals use for them. */
static const pc_rgb ansi16[16] = {
    {0x00, 0x00, 0x00}, {0xaa, 0x00, 0x00}, {0x00, 0xaa, 0x00}, {0xaa, 0x55, 0x00},
    {0x00, 0x00, 0xaa}, {0xaa, 0x00, 0xaa}, {0x00, 0xaa, 0xaa}, {0xaa, 0xaa, 0xaa},
    {0x55, 0x55, 0x55}, {0xff, 0x55, 0x55}, {0x55, 0xff, 0x55}, {0xff, 0xff, 0x55},
    {0x55, 0x55, 0xff}, {0xff, 0x55, 0xff}, {0x55, 0xff, 0xff}, {0xff, 0xff, 0xff}};

static long dist2(pc_rgb a, int r, int g, int b) {
    long dr = a.r - r, dg = a.g - g, db = a.b - b;
    return dr * dr + dg * dg + db * db;
}

/* The nearest level of the xterm colour cube (0, 95, 135, 175, 215, 255). */
static int cube_index(int v) {
    static const int levels[6] = {0, 95, 135, 175, 215, 255};
    int best = 0;
    for (int i = 1; i < 6; i++)
        if (abs(levels[i] - v) < abs(levels[best] - v)) best = i;
    return best;
}

static int xterm256(pc_rgb c) {
    static const int levels[6] = {0, 95, 135, 175, 215, 255};
    int ri = cube_index(c.r), gi = cube_index(c.g), bi = cube_index(c.b);
    int cube = 16 + 36 * ri + 6 * gi + bi;
    long dc = dist2(c, levels[ri], levels[gi], levels[bi]);
    /* the grey ramp 232..255 is 8, 18, ..., 238 */
    int grey = (c.r + c.g + c.b) / 3;
    int gi2 = grey < 8 ? 0 : grey > 238 ? 23 : (grey - 8 + 5) / 10;
    int gv = 8 + 10 * gi2;
    long dg = dist2(c, gv, gv, gv);
    return dg < dc ? 232 + gi2 : cube;
}

char *pc_term_color(pc_rgb rgb, pc_term_colors mode, char *buf) {
    buf[0] = 0;
    switch (mode) {
    case PC_TERM_MONO: break;
    case PC_TERM_16: {
        int best = 0;
        for (int i = 1; i < 16; i++)
            if (dist2(ansi16[i], rgb.r, rgb.g, rgb.b) < dist2(ansi16[best], rgb.r, rgb.g, rgb.b))
                best = i;
        sprintf(buf, "%d", best < 8 ? 30 + best : 90 + best - 8);
        break;
    }
    case PC_TERM_256: sprintf(buf, "38;5;%d", xterm256(rgb)); break;
    case PC_TERM_RGB: sprintf(buf, "38;2;%d;%d;%d", rgb.r, rgb.g, rgb.b); break;
    }
    return buf;
}

/* ---- text ------------------------------------------------------------------------------- */

static void put_utf8(FILE *out, unsigned cp) {
    if (cp < 0x80) {
        fputc((int)cp, out);
    } else if (cp < 0x800) {
        fputc(0xc0 | (cp >> 6), out);
        fputc(0x80 | (cp & 0x3f), out);
    } else {
        fputc(0xe0 | (cp >> 12), out);
        fputc(0x80 | ((cp >> 6) & 0x3f), out);
        fputc(0x80 | (cp & 0x3f), out);
    }
}

static void frame_line(FILE *out, unsigned left, unsigned right, int cols, int dim) {
    if (dim) fputs("\x1b[2m", out);
    put_utf8(out, left);
    for (int i = 0; i < cols; i++) put_utf8(out, 0x2500);
    put_utf8(out, right);
    if (dim) fputs("\x1b[0m", out);
    fputc('\n', out);
}

static void frame_side(FILE *out, int dim) {
    if (dim) fputs("\x1b[2m", out);
    put_utf8(out, 0x2502);
    if (dim) fputs("\x1b[0m", out);
}

int pc_braille_print(FILE *out, const pc_braille_cell *cells, int cols, int rows,
                     const pc_rgb *palette, pc_term_colors mode, int frame) {
    int colored = mode != PC_TERM_MONO;
    if (frame) frame_line(out, 0x250c, 0x2510, cols, colored);
    for (int row = 0; row < rows; row++) {
        if (frame) frame_side(out, colored);
        int current = -1;   /* the colour in effect: -1 the terminal default */
        for (int col = 0; col < cols; col++) {
            const pc_braille_cell *cell = &cells[row * cols + col];
            if (cell->bits == 0) {
                fputc(' ', out);
                continue;
            }
            if (colored) {
                int want = cell->color;
                if (want >= 0) {
                    pc_rgb rgb = palette[want];
                    if (rgb.r == 255 && rgb.g == 255 && rgb.b == 255) want = -1;
                }
                if (want != current) {
                    char sgr[24];
                    if (want < 0) fputs("\x1b[39m", out);
                    else fprintf(out, "\x1b[%sm", pc_term_color(palette[want], mode, sgr));
                    current = want;
                }
            }
            put_utf8(out, 0x2800u + cell->bits);
        }
        if (current >= 0) fputs("\x1b[39m", out);
        if (frame) frame_side(out, colored);
        fputc('\n', out);
    }
    if (frame) frame_line(out, 0x2514, 0x2518, cols, colored);
    return ferror(out) ? -1 : 0;
}
