/* Drawing shaded quads (shaded.h). */
#include "shaded.h"

int pc_draw_shaded(pc_canvas *c, const pc_shade_quad *q, size_t n, pc_rgb base, int mesh) {
    const uint8_t b[3] = {base.r, base.g, base.b};
    for (size_t k = 0; k < n; k++) {
        uint8_t rgb[3];
        pc_shade_rgb(b, q[k].shade, rgb);
        int color = pc_rgb_color(c, (pc_rgb){rgb[0], rgb[1], rgb[2]});
        if (color < 0) return PC_ENOMEM;   /* the message is in the canvas */
        double xy[8];
        for (int v = 0; v < 4; v++)
            pc_screen_to_world(c, q[k].xy[2 * v], q[k].xy[2 * v + 1], &xy[2 * v], &xy[2 * v + 1]);
        int rc = pc_fill_path(c, 4, xy, NULL, 0, PC_FILL_NONZERO | PC_FILL_TILE, color);
        if (rc == PC_OK && mesh >= 0) rc = pc_path(c, 4, xy, NULL, 0, 1, mesh);
        if (rc != PC_OK) return rc;
    }
    return PC_OK;
}
