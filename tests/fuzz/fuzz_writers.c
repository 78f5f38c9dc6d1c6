/* libFuzzer target: the drawing layer and the three writers.  The input is read as a program of
 * drawing operations (one opcode byte, then its operands as bytes) on a small canvas, which is
 * then encoded as PNG, SVG and PPM into memory.  Every status is allowed; a crash, a sanitizer
 * report or a leak is the finding.  Build: cmake -DPC_FUZZ=ON with clang (docs/safety.md). */
#define _GNU_SOURCE   /* open_memstream */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "canvas.h"
#include "writers.h"

typedef struct { const uint8_t *p; size_t n; } input;

static int byte(input *in) {
    if (!in->n) return 0;
    in->n--;
    return *in->p++;
}

/* a coordinate: mostly on the canvas, sometimes far off it or not finite */
static double coord(input *in) {
    int b = byte(in), k = byte(in);
    switch (k & 7) {
    case 0: return (double)(b - 64) * 1e6;
    case 1: return k & 8 ? 1e308 : -1e308;
    case 2: return k & 16 ? 0.0 / 0.0 : 1.0 / 0.0;
    default: return b - 32 + k / 256.0;
    }
}

static void encode(const pc_canvas *c, pc_theme theme) {
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (!f) return;
    pc_encode_png(c, theme, f);
    pc_encode_svg(c, theme, f);
    pc_encode_ppm(c, theme, f);
    fclose(f);
    free(buf);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    input in = {data, size};
    pc_canvas *c = pc_canvas_new(1 + byte(&in) % 200, 1 + byte(&in) % 150, byte(&in) & 1 ? 256 : 16);
    if (!c) return 0;
    double dash[4];
    while (in.n) {
        int op = byte(&in) % 10, color = byte(&in);
        double x1 = coord(&in), y1 = coord(&in), x2 = coord(&in), y2 = coord(&in);
        switch (op) {
        case 0: pc_pset(c, x1, y1, color); break;
        case 1: pc_line(c, x1, y1, x2, y2, color); break;
        case 2: pc_box(c, x1, y1, x2, y2, color, color & 1); break;
        case 3: pc_circle(c, x1, y1, x2, color, y2, x1 - x2, y1 / 16); break;
        case 4: pc_paint(c, x1, y1, color, byte(&in)); break;
        case 5: pc_palette(c, color, (pc_rgb){(uint8_t)x1, (uint8_t)y1, (uint8_t)x2}); break;
        case 6: pc_pset(c, x1, y1, pc_rgb_color(c, (pc_rgb){(uint8_t)color, (uint8_t)y1, 7})); break;
        case 7:
            for (int i = 0; i < 4; i++) dash[i] = coord(&in) / 8;
            pc_pen(c, x1 / 64, dash, byte(&in) % 5);
            break;
        case 8: pc_cls(c); break;
        default: pc_color(c, color, byte(&in) - 1); break;
        }
    }
    encode(c, PC_THEME_SCREEN);
    encode(c, PC_THEME_PAPER);
    pc_canvas_free(c);
    return 0;
}
