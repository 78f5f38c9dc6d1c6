/* The one drawing interface of the print look (cairo's shape: one API, several surfaces).
 * print.c walks the display list once and speaks only this; print_cairo.c (PDF, PS, EPS,
 * PNG) and print_svg.c (SVG with editable <text>) implement it.  Coordinates are in pt on
 * the page, y down.  Not part of the public API. */
#ifndef PC_PRINT_BACKEND_H
#define PC_PRINT_BACKEND_H

#include "math_label.h"
#include "print.h"

typedef struct {
    double width;            /* pt */
    int ndash;
    double dash[PC_PEN_MAXDASH];   /* pt */
    int round;               /* round caps and joins (solid lines); else butt caps, miter joins */
} pc_pr_pen;

/* A label laid out: its runs (math_label.h) from the origin, the baseline's left end. */
typedef struct {
    const pc_mlayout *layout;
    const char *family;
    double x, y;             /* the origin in pt */
    pc_rgb color, halo_color;
    double halo;             /* the halo's stroke width in pt; 0: none */
    const char *source;      /* the label as written (the SVG keeps it for editors) */
} pc_pr_label;

typedef struct pc_pr_backend {
    void *self;
    void (*clip)(void *self, double x0, double y0, double x1, double y1);
    void (*move)(void *self, double x, double y);
    void (*line)(void *self, double x, double y);
    void (*curve)(void *self, double x1, double y1, double x2, double y2, double x3, double y3);
    void (*close)(void *self);
    void (*rect)(void *self, double x, double y, double w, double h);
    void (*stroke)(void *self, pc_rgb color, const pc_pr_pen *pen);
    void (*fill)(void *self, pc_rgb color, int evenodd);
    void (*text)(void *self, const pc_pr_label *label);
    /* Optional: n screen pixels (indices y * width + x, increasing) of one colour, each the
     * square of side s at (ox + x s, oy + y s), drawn as one mask; NULL: as rectangles. */
    void (*pixels)(void *self, const uint32_t *idx, size_t n, int width, const pc_page *pg,
                   pc_rgb color);
    int failed;              /* set by a backend that ran out of memory or could not write */
} pc_pr_backend;

/* Render the canvas through a backend (print.c).  The backend has painted the paper. */
int pc_print_walk(const pc_canvas *c, const pc_page *pg, pc_pr_backend *b, char *err,
                  size_t errlen);

/* Text through Pango (print_text.c): lay out a label (math: its $...$ are math; else as it
 * is) in a family at a size, with Pango's metrics (hinting off, so every surface has the same
 * advances). */
int pc_pr_layout(const char *label, int math, const char *family, double size, pc_mlayout *out,
                 char *err, size_t errlen);
/* Pango's description of a run's font ("CMU Serif Italic 7.0"-like, size absolute). */
void *pc_pr_font(const char *family, int italic, double size);   /* PangoFontDescription* */
void *pc_pr_context(void);                                       /* PangoContext*, shared */

#endif
