/* The print look: the display list rendered as a book or paper prints it, through cairo (PDF,
 * PostScript/EPS, PNG at any resolution) and an SVG writer of its own that keeps labels as
 * editable <text>.  Both sit behind one drawing interface (print_backend.h), so the walk over
 * the display list (print.c) is written once and every output of a figure has one geometry.
 *
 * Sizes: the canvas (640x480 pixels for SCREEN 12) is mapped at one scale onto the figure's
 * width and height in points (1 pt = 1/72 in), centred when both are given and their aspect
 * differs.  Text sizes are in pt whatever the window; pens are physical (pt), or a width in
 * pixels scales with the figure (w * s pt, at least PC_PRINT_PEN_MIN_PT), so a dense mesh
 * stays as light as the screen shows it.
 *
 * Pure C: no Lua. */
#ifndef PC_PRINT_H
#define PC_PRINT_H

#include <stdio.h>
#include "canvas.h"
#include "writers.h"

#define PC_PRINT_PEN_MIN_PT 0.25 /* the thinnest line a pixel pen becomes (0.09 mm) */
#define PC_PRINT_PEN_PT 0.71     /* 0.25 mm: a physical pen given without a width */
#define PC_PRINT_SIZE_PT 10.0    /* the label size when neither figure nor label sets one */

/* One length with its unit: "12cm", "0.5mm", "3in", "10pt", "96px" (px: 1/96 in, as CSS),
 * a decimal number straight before the unit.  PC_EARG with a message naming what (the
 * option) when there is no unit, an unknown unit, or the value is not a positive finite number. */
int pc_parse_length(const char *s, const char *what, double *pt, char *err, size_t errlen);

/* A figure size: "12cm" (the width, the height from the aspect: *h = 0) or "12cmx8cm". */
int pc_parse_size(const char *s, double *w, double *h, char *err, size_t errlen);

/* The named engineering pens: "main" (0.5 mm), "thin" (0.25 mm), "hidden" (0.35 mm, dashes
 * 3 mm, gaps 1.5 mm), "centre" or "center" (0.25 mm, chain 12-1.5-1-1.5 mm). */
int pc_pen_named(pc_canvas *c, const char *name);

/* Check and set the figure (c->figure = *f with on = 1).  PC_EARG for a size out of range
 * (1 pt .. 5 m), dpi outside 10..2400, a raster image above 20000 pixels a side, a text size
 * outside 1..200 pt, or a font that is not installed. */
int pc_figure_set(pc_canvas *c, const pc_figure *f);

/* The page (pt) and the map from canvas pixels: x_pt = ox + x * s (y likewise). */
typedef struct { double width, height, s, ox, oy, dpi; } pc_page;
void pc_print_page(const pc_canvas *c, pc_page *pg);

/* The family that `font` names ("serif", "sans", "mono" or a family such as "DejaVu Serif";
 * "" or NULL: serif), checked through fontconfig.  PC_EARG with a message naming the Debian
 * package when it is not installed. */
int pc_font_family(const char *font, const char **family, char *err, size_t errlen);

/* Render the canvas in the print look as PDF, EPS, PS, PNG or SVG to out.  PC_OK, PC_EARG (a
 * font, a label's math: the message in err), PC_ENOMEM or PC_EIO. */
int pc_encode_print(const pc_canvas *c, pc_format fmt, FILE *out, char *err, size_t errlen);

/* The print look's measuring hook (pc_canvas.measure, print_measure.c): the Pango box of a
 * label at the figure's font and size times scale, halo included, in screen pixels; ctx is
 * the canvas.  pc_print_resolve resolves c for a print-look writer with that hook: *tmp gets a
 * shallow copy of c with the hook set, and the result (tmp itself when nothing is pending) is
 * released with pc_layout_release(tmp, result). */
int pc_print_measure(void *ctx, const char *utf8, size_t n, int scale, double *w, double *h);
const pc_canvas *pc_print_resolve(const pc_canvas *c, pc_canvas *tmp);
/* The same, saying why on NULL (layout.h's pc_layout_resolve_why). */
const pc_canvas *pc_print_resolve_why(const pc_canvas *c, pc_canvas *tmp, int *status, char *why,
                                      size_t whylen);

/* The print-look colour of an attribute: the paper theme's, "#rrggbb" exactly. */
pc_rgb pc_print_rgb(const pc_canvas *c, int attr);

/* pen{width =, dash =}: pixels, or lengths in pt with their units (the print pen), never
 * mixed (PC_EARG naming the option); no width: 1 px, or the print pen's 0.25 mm. */
typedef struct {
    int has_width, width_len, has_dash, dash_len, ndash;
    double width;
    const double *dash;
} pc_pen_opts;
int pc_pen_options(pc_canvas *c, const pc_pen_opts *o);
/* figure{width =, height =, dpi =, font =, size =} (pt; each with has_*): the canvas's figure
 * with those given, framed to its content (frame = 1), set by pc_figure_set; a width or a
 * height given clears the other when absent (a width alone keeps the window's aspect). */
typedef struct {
    int has_width, has_height, has_dpi, has_size;
    double width, height, dpi, size;
    const char *font;   /* NULL: the figure's */
} pc_figure_opts;
int pc_figure_options(pc_canvas *c, const pc_figure_opts *o);

#endif
