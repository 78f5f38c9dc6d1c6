/* The furniture through points as one family (furniture.h): the kind by its name, one call. */
#include <string.h>
#include "furniture.h"

static const char *const NAMES[] = {"arrow", "dimension", "angle_mark", "ticks", "centre_line", NULL};

int pc_furniture_kind_of(const char *name) {
    for (int k = 0; NAMES[k]; k++)
        if (!strcmp(name, NAMES[k])) return k;
    return -1;
}

int pc_furniture(pc_canvas *c, pc_furniture_kind kind, const double *xy, double size, const char *text, int color,
                 double *measure) {
    *measure = 0;
    switch (kind) {
    case PC_FURN_ARROW: return pc_arrow(c, xy[0], xy[1], xy[2], xy[3], (int)size, 9, color);
    case PC_FURN_DIMENSION: return pc_dimension(c, xy[0], xy[1], xy[2], xy[3], size, text, color, measure);
    case PC_FURN_ANGLE: return pc_angle_mark(c, xy[0], xy[1], xy[2], xy[3], xy[4], xy[5], size, text, color, measure);
    case PC_FURN_TICKS: return pc_ticks(c, xy[0], xy[1], xy[2], xy[3], (int)size, 8, color);
    case PC_FURN_CENTRE: return pc_centre_line(c, xy[0], xy[1], xy[2], xy[3], size, color);
    }
    return PC_EARG;
}
