/* What QBasic's statements resolve from their arguments before drawing (qbscreen.h): VIEW's
 * corners as whole pixels, PALETTE's colour numbers, PMAP's conversions. */
#include <math.h>
#include <string.h>
#include "qbscreen.h"
#include "canvas_internal.h"

int pc_view_at(pc_canvas *c, double x1, double y1, double x2, double y2, int fill, int border, int screen) {
    /* the corners beyond any screen are refused before the conversion to int could wrap them
     * onto it */
    const double lim = 1e6;
    if (!(fabs(x1) <= lim && fabs(y1) <= lim && fabs(x2) <= lim && fabs(y2) <= lim))
        return pc_fail(c, "view (%.14g, %.14g)-(%.14g, %.14g) is not inside the %dx%d screen", x1, y1, x2, y2,
                       c->width, c->height);
    return pc_view(c, (int)lrint(x1), (int)lrint(y1), (int)lrint(x2), (int)lrint(y2), fill, border, screen);
}

int pc_rgb_qbasic(long long q, pc_rgb *out) {
    int r = (int)(q & 0xff), g = (int)((q >> 8) & 0xff), b = (int)((q >> 16) & 0xff);
    if (q < 0 || q > 0x3f3f3f || r > 63 || g > 63 || b > 63) return PC_EARG;
    /* 6-bit components to 8 bits, the top bits repeated: 63 is 255 */
    *out = (pc_rgb){(uint8_t)((r << 2) | (r >> 4)), (uint8_t)((g << 2) | (g >> 4)), (uint8_t)((b << 2) | (b >> 4))};
    return PC_OK;
}

double pc_pmap(const pc_canvas *c, double v, int fn) {
    double sx, sy, wx, wy;
    /* physical coordinates count from the view's corner, unless VIEW SCREEN */
    double ox = c->view_screen ? 0 : c->view.x0, oy = c->view_screen ? 0 : c->view.y0;
    switch (fn) {
    case 0:
        pc_world_to_screen(c, v, 0, &sx, &sy);
        return (double)lrint(sx - ox);
    case 1:
        pc_world_to_screen(c, 0, v, &sx, &sy);
        return (double)lrint(sy - oy);
    case 2:
        pc_screen_to_world(c, v + ox, oy, &wx, &wy);
        return wx;
    default:
        pc_screen_to_world(c, ox, v + oy, &wx, &wy);
        return wy;
    }
}

int pc_line_stmt(pc_canvas *c, double x1, double y1, double x2, double y2, int color, int box, long pattern) {
    if (pattern >= 0 && box != 2)   /* QBasic ignores the style of a filled box */
        return pc_line_styled(c, x1, y1, x2, y2, color, box, (unsigned)(pattern & 0xffff));
    if (box == 0) return pc_line(c, x1, y1, x2, y2, color);
    return pc_box(c, x1, y1, x2, y2, color, box == 2);
}

const char *pc_canvas_message(const pc_canvas *c) {
    /* a core message may start with the core statement's name ("pset: coordinates ..."): the
     * caller's name replaces it, so preset reports as preset and line_to as line_to */
    const char *msg = c->error, *colon = strstr(msg, ": ");
    if (colon && colon > msg && strspn(msg, "abcdefghijklmnopqrstuvwxyz_") == (size_t)(colon - msg)) return colon + 2;
    return msg;
}
