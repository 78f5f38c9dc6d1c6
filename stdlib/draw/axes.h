/* Axes, ticks at round numbers, grids and legends, drawn through the display list's own ops
 * (furniture.h's rules: world coordinates for places, pixels for sizes). */
#ifndef PC_AXES_H
#define PC_AXES_H

#include "canvas.h"

/* Round ticks for the range lo..hi: a step of 1, 2 or 5 times a power of ten giving about
 * `target` intervals (at least 1), the first tick the least multiple of the step >= lo.
 * *n ticks in all (at most 1000).  PC_EARG unless lo < hi, both finite. */
int pc_nice_ticks(double lo, double hi, int target, double *first, double *step, int *n);

typedef struct {
    double x0, x1, y0, y1;   /* the ranges drawn, world units */
    double ox, oy;           /* where the axes cross (clamped into the ranges) */
    int ticks;               /* about this many intervals on each axis (0: none) */
    int labels;              /* tick labels ("%g" of the value), except at the crossing */
    int arrows;              /* a head at the positive end of each axis */
    int grid;                /* dotted lines at every tick across the ranges */
    int grid_color;          /* < 0: the axes' colour */
} pc_axes_spec;

/* Both axes with their ticks (6 px across), labels below the x axis and left of the y axis,
 * heads and the grid as asked.  *nticks (may be NULL) gets the number of ticks drawn. */
int pc_axes(pc_canvas *c, const pc_axes_spec *a, int color, int *nticks);
/* pc_axes in a figure framed when written (furniture.c): 1 with the axes kept (*st its status,
 * *nticks the count they will have) to be drawn once the frame is known; 0 to draw them now. */
int pc_furniture_defer_axes(pc_canvas *c, const pc_axes_spec *a, int color, int *nticks, int *st);

/* A legend: n entries (a 20 px line in colour colors[i], then names[i]) in a box in the
 * corner `corner` (PC_ANCHOR_NE, NW, SE or SW) of the picture, 8 px in, in device units. */
int pc_legend(pc_canvas *c, int n, const char *const *names, const int *colors, int corner,
              int color);

/* The spec of axes{} without options: the ranges the window's (or the screen's) view shows,
 * crossing at the origin, 5 ticks, labels, arrows, no grid. */
void pc_axes_default(const pc_canvas *c, pc_axes_spec *s);
/* axes{}: the default spec with the options given (x, y: {lo, hi}, NULL for the window's;
 * origin NULL: (0, 0)); PC_EARG naming the option unless lo < hi. */
typedef struct {
    const double *x, *y, *origin;
    int ticks, labels, arrows, grid, grid_color;
} pc_axes_opts;
int pc_axes_options(pc_canvas *c, const pc_axes_opts *o, int color, int *nticks);

#endif
