/* Binary PPM (P6): the raster through the theme's palette (true colours as given), 8 bits per
 * channel. */
#include <stdlib.h>
#include "writers.h"

int pc_encode_ppm(const pc_canvas *c, pc_theme theme, FILE *out) {
    pc_rgb pal[256];
    pc_theme_palette(c, theme, pal);
    if (fprintf(out, "P6\n%d %d\n255\n", c->width, c->height) < 0) return PC_EIO;
    size_t w = (size_t)c->width;
    uint8_t *row = malloc(3 * w);
    if (!row) return PC_ENOMEM;
    int ok = PC_OK;
    for (int y = 0; y < c->height && ok == PC_OK; y++) {
        const uint16_t *src = c->pixels + (size_t)y * w;
        for (size_t x = 0; x < w; x++) {
            pc_rgb p = pc_attr_rgb(c, pal, src[x]);
            row[3 * x] = p.r;
            row[3 * x + 1] = p.g;
            row[3 * x + 2] = p.b;
        }
        if (fwrite(row, 3, w, out) != w) ok = PC_EIO;
    }
    free(row);
    if (ok == PC_OK && (fflush(out) != 0 || ferror(out))) ok = PC_EIO;
    return ok;
}
