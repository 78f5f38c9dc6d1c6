/* Shared between the canvas files; not part of the public API. */
#ifndef PC_CANVAS_INTERNAL_H
#define PC_CANVAS_INTERNAL_H

#include <stdarg.h>
#include "canvas.h"
#include "font.h"
#include "math_label.h"

int pc_fail_code(pc_canvas *c, int code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
#define pc_fail(c, ...) pc_fail_code((c), PC_EARG, __VA_ARGS__)

/* Resolve a colour argument: <0 means dflt; an attribute not in use is an error. */
int pc_check_color(pc_canvas *c, int *color, int dflt);
static inline int pc_valid_color(const pc_canvas *c, int color) {   /* inline: pset runs it */
    return (color >= 0 && color < c->ncolors) || (color >= 256 && color < 256 + c->ntrue);
}

/* Make room for `need` elements of size elem in *buf (doubling); 0 when out of memory. */
int pc_grow(void **buf, size_t *cap, size_t need, size_t elem);

/* The index of pen p in the canvas's table (added if new), or -1 (PC_ENOMEM in c->error). */
int pc_pen_index(pc_canvas *c, const pc_stroke *p);

/* Fill n pixels from p with an attribute. */
static inline void pc_fill_px(uint16_t *p, int color, size_t n) {
    for (size_t i = 0; i < n; i++) p[i] = (uint16_t)color;
}

/* Is distance d along a stroke in a dash of pen p (always, for a solid pen)? */
int pc_dash_on(const pc_stroke *p, double d);

/* The pixels of a styled LINE or BOX op (QBasic's style bits), in the order QBasic draws
 * them, each given to fn; the same for the raster and the SVG writer. */
void pc_styled_pixels(const pc_canvas *c, const pc_op *op, void (*fn)(void *, long, long),
                      void *ctx);

/* Flattening a cubic in screen space: the number of segments that keeps every point within
 * tol pixels of the curve (Wang's bound), and the point at t. */
int pc_cubic_segments(const pc_xy p[4], double tol);
pc_xy pc_cubic_at(const pc_xy p[4], double t);

/* Append the screen images of a path's n points (with their verbs' tags, checked) to the
 * canvas's points; *first: where they start.  stmt names the statement in messages. */
int pc_push_path_pts(pc_canvas *c, const char *stmt, size_t n, const double *xy,
                     const uint8_t *verbs, size_t nverbs, uint32_t *first);

pc_op *pc_push_op(pc_canvas *c, pc_op_kind kind, int color);
int pc_push_span(pc_canvas *c, int y, int x0, int x1);
/* Append a dot to the DOTS run at the end of the list, or start a run (new colour or clip). */
int pc_push_dot(pc_canvas *c, double x, double y, int color);
/* Fold the dots at the end of the list into one PIXELS op (dotfold.c; pc_push_dot calls it
 * when the run passes c->dot_budget).  Out of memory leaves the dots as they are. */
void pc_fold_dots(pc_canvas *c);
/* Forget every PIXELS op's pixels (with the display list: SCREEN, a full CLS). */
static inline void pc_lpx_clear(pc_canvas *c) { c->nlpx = 0; c->fold_mark = 0; }
int pc_push_clip(pc_canvas *c);
/* The index in c->clips of the clip of op i (a binary search over the runs). */
size_t pc_op_clip(const pc_canvas *c, size_t i);
/* The first op after the run of clip k (SIZE_MAX for the last clip). */
static inline size_t pc_clip_end(const pc_canvas *c, size_t k) {
    return k + 1 < c->nclips ? c->clips[k + 1].first : SIZE_MAX;
}
void pc_reset_cursor(pc_canvas *c);

/* Rasterise a TEXT op's glyphs at its cell box (x1, y1) and scale (text.c): how the layout
 * draws a label once it is placed. */
void pc_text_raster(pc_canvas *c, const pc_op *op);

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

/* Math labels in the VGA look (text.c): the layout over 8-pixel cells (the raster and the
 * SVG writer share it), and the VGA character nearest to one the font lacks. */
int pc_text_vga_layout(const char *utf8, int scale, pc_mlayout *L, char *err, size_t errlen);
uint32_t pc_vga_fallback(const pc_font *f, uint32_t cp);
/* The row offset (down positive) of pixel i of n of a \tilde's wave at a scale: one period of
 * a sine, scale pixels each way, up first: the nearest a row of pixels comes to ~. */
long pc_vga_tilde_dy(long i, long n, int scale);
/* The row of an \underline at row y of a label whose baseline is at row base: the cell's last
 * row at most, under the VGA font's descenders and inside the label's cells. */
long pc_vga_under_y(long base, long y, int scale);

/* Deferred furniture (furniture.c; canvas.h's deferred): draw the items recorded when op `at`
 * was next (all: at or after it) through the framing x -> sx x + tx, y -> sy y + ty of the
 * pixels they were recorded in; put each item's points into an extent (for framing); forget
 * them all (freed unless borrowed). */
int pc_furniture_expand(pc_canvas *c, size_t at, int all, double sx, double sy, double tx, double ty);
void pc_furniture_extent(const pc_canvas *c, pc_extent_fn put, void *ctx);
void pc_furniture_forget(pc_canvas *c);
/* pc_legend in a figure framed when written: 1 with the legend kept (*st its status) to be
 * drawn after the framing, in device units and out of the frame's extent; 0 to draw it now. */
int pc_furniture_defer_legend(pc_canvas *c, int n, const char *const *names, const int *colors,
                              int corner, int color, int *st);

#endif
