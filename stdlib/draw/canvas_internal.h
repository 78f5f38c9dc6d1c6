/* Shared between the canvas files; not part of the public API. */
#ifndef PC_CANVAS_INTERNAL_H
#define PC_CANVAS_INTERNAL_H

#include <stdarg.h>
#include "canvas.h"

int pc_fail_code(pc_canvas *c, int code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
#define pc_fail(c, ...) pc_fail_code((c), PC_EARG, __VA_ARGS__)

/* Resolve a colour argument: <0 means dflt; out of range is an error. */
int pc_check_color(pc_canvas *c, int *color, int dflt);

pc_op *pc_push_op(pc_canvas *c, pc_op_kind kind, int color);
int pc_push_span(pc_canvas *c, int y, int x0, int x1);
/* Append a dot to the DOTS run at the end of the list, or start a run (new colour or clip). */
int pc_push_dot(pc_canvas *c, double x, double y, int color);
int pc_push_clip(pc_canvas *c);
void pc_reset_cursor(pc_canvas *c);

/* Screen-pixel primitives used by VIEW's border and fill and by CLS. */
int pc_box_screen(pc_canvas *c, int x0, int y0, int x1, int y1, int color, int filled);
int pc_fill_view(pc_canvas *c, int color);

/* A screen coordinate to a whole pixel: nearest, ties to even; clamped to +-1e9 first (far off
 * any screen either way) so the conversion is always defined.  Used by the rasteriser and the
 * SVG writer, so both put a coordinate in the same pixel. */
long pc_px(double v);

/* Clip the segment (x0,y0)-(x1,y1) to the rectangle, in place (Liang-Barsky); 0 if nothing of
 * it is inside.  Used by the rasteriser and the SVG writer. */
int pc_clip_segment(double *x0, double *y0, double *x1, double *y1, double xmin, double ymin,
                    double xmax, double ymax);

#endif
