/* Engineering-drawing furniture, expanded into the display list's own ops (paths, filled paths,
 * lines and text), so every writer draws it without knowing it: markers, arrows, dimension
 * lines, angle marks, equal-length ticks, hatching and centre lines.
 *
 * Points are world coordinates (through WINDOW and VIEW as every statement's); sizes are in
 * screen pixels, so a mark looks the same whatever the window.  The numbers written (a length,
 * an angle) are measured in world units: with unequal units on the two axes a drawn angle is
 * not the one measured, which is why figures are framed at true shape.  Colour < 0 is the
 * foreground.  Return PC_OK or PC_EARG (the message in c->error names the statement). */
#ifndef PC_FURNITURE_H
#define PC_FURNITURE_H

#include "canvas.h"

typedef enum { PC_MARK_DOT, PC_MARK_OPEN, PC_MARK_CROSS, PC_MARK_PLUS, PC_MARK_SQUARE } pc_mark_style;

/* A marker of diameter size pixels (1..200) centred on the point. */
int pc_mark(pc_canvas *c, double x, double y, int style, double size, int color);

/* An arrow head with its tip at (x2, y2), pointing from (x1, y1): a filled triangle len pixels
 * long (1..200), 2 * 0.3 len wide (the ISO 129 closed filled arrowhead, 15 degrees each side
 * is narrower; 17 degrees reads better at screen sizes). */
int pc_arrow_head(pc_canvas *c, double x1, double y1, double x2, double y2, double len, int color);
/* A line with heads: heads 1 at the end, 2 at the start, 3 at both; the line stops at the
 * heads' bases so a wide pen does not blunt the tips. */
enum { PC_ARROW_END = 1, PC_ARROW_START = 2, PC_ARROW_BOTH = 3 };
int pc_arrow(pc_canvas *c, double x1, double y1, double x2, double y2, int heads, double len,
             int color);

/* A dimension line of segment AB: extension lines from A and B out to `offset` pixels on the
 * left of A->B as seen on the screen (negative: the right), the dimension line between them
 * with a head at each end, and text (NULL: the length |AB| in world units, "%.4g") centred
 * beside it on the outer side.  *length (may be NULL) gets |AB|. */
int pc_dimension(pc_canvas *c, double ax, double ay, double bx, double by, double offset,
                 const char *text, int color, double *length);

/* An angle mark at O between rays OA and OB (the smaller angle): an arc of radius r pixels, or
 * the right-angle square when the angle is 90 degrees within 1e-9 rad; text (NULL: the angle
 * in degrees, "%.4g°") beside it on the bisector.  *angle (may be NULL) gets the angle in
 * radians, measured in world units. */
int pc_angle_mark(pc_canvas *c, double ax, double ay, double ox, double oy, double bx, double by,
                  double r, const char *text, int color, double *angle);

/* n (1..5) equal-length ticks across the middle of segment AB, size pixels long, 3 px apart. */
int pc_ticks(pc_canvas *c, double ax, double ay, double bx, double by, int n, double size,
             int color);

/* Hatching of the closed region of the n-point polygon xy (even-odd): parallel lines at
 * `angle` degrees (ISO 128: 45) on the screen, `spacing` pixels apart, clipped to the region.
 * *nlines (may be NULL) gets the number of hatch segments drawn. */
int pc_hatch(pc_canvas *c, size_t n, const double *xy, double spacing, double angle, int color,
             size_t *nlines);

/* A centre line through A and B extended by `extend` pixels beyond each end, in the ISO
 * long-dash dot pattern (the pen in force is kept for the width). */
int pc_centre_line(pc_canvas *c, double ax, double ay, double bx, double by, double extend,
                   int color);

/* A caption centred at the bottom (top: at the top) edge of the picture, whatever the window
 * and the view, in device units: framing leaves it (figure_items.c). */
int pc_caption(pc_canvas *c, const char *utf8, int top, int color);
/* Text with its first cell's top-left corner at the screen pixel (x, y), whatever the window,
 * in device units: framing leaves it. */
int pc_text_device(pc_canvas *c, double x, double y, const char *utf8, int scale, int color);
/* The graph y = f(x) for x from x0 to x1 as a path of n pieces: f sets *have = 0 (or gives a
 * non-finite y) where there is no value, and the path breaks there (a lone point draws
 * nothing); a status other than PC_OK from f stops the graph and is returned. */
typedef int (*pc_graph_fn)(void *ctx, double x, double *y, int *have);
int pc_graph(pc_canvas *c, double x0, double x1, int n, pc_graph_fn f, void *ctx, int color);

/* path{}: the polyline through n points (verbs as pc_path's), closed or not, in colour color,
 * with arrow heads 9 px long (PC_ARROW_* bits) on its last and first segments; or, filled, the
 * closed path filled in fill_color by rule (PC_FILL_*) and its outline on top if color >= 0. */
int pc_path_stmt(pc_canvas *c, size_t n, const double *xy, const uint8_t *verbs, int closed, int color, int heads,
                 int filled, int fill_color, int rule);

/* The furniture drawn through two or three points (one binding over them all): arrow,
 * dimension, angle mark (A, O, B), ticks, centre line, found by the name a script calls. */
typedef enum { PC_FURN_ARROW, PC_FURN_DIMENSION, PC_FURN_ANGLE, PC_FURN_TICKS, PC_FURN_CENTRE } pc_furniture_kind;
/* The kind named "arrow", "dimension", "angle_mark", "ticks" or "centre_line", or -1. */
int pc_furniture_kind_of(const char *name);
/* Furniture of that kind through the points xy (x, y pairs) with its one size (the arrow's
 * heads PC_ARROW_*, the dimension's offset, the angle's radius, the ticks' count, the centre
 * line's extension), text (dimension and angle; NULL: the number) and colour, as the functions
 * above draw it; *measure the length or the angle of the two that measure (else 0). */
int pc_furniture(pc_canvas *c, pc_furniture_kind kind, const double *xy, double size, const char *text, int color,
                 double *measure);

#endif
