/* Curves plotted dot by dot (PSET in a loop), found again as curves: the print look strokes
 * them instead of printing each dot as a tiny square of the screen's pixel (print.c).  The
 * rule is the SVG writer's (svg.c: DENSE runs become polylines): consecutive dots each within
 * PC_DOTRUN_DENSE pixels of the one before form a run; a run of at least PC_DOTRUN_MIN dots
 * reaching PC_DOTRUN_EXTENT pixels or more from its first dot is a curve.  Pure C. */
#ifndef PC_DOTRUN_H
#define PC_DOTRUN_H

#include <stddef.h>
#include "canvas.h"

#define PC_DOTRUN_DENSE 1.5
#define PC_DOTRUN_MIN 4
#define PC_DOTRUN_EXTENT 2.0

/* The curves among the n dots d[0..n): their [start, end) index pairs into runs (2 per curve,
 * room for n), the number of curves returned. */
size_t pc_dot_runs(const pc_xy *d, size_t n, size_t *runs);

/* The vertices of the run d[0..n) to stroke: the first dot, then each dot at least step
 * pixels from the last one kept, and the last dot; into out (room for n), their count. */
size_t pc_dot_run_thin(const pc_xy *d, size_t n, double step, pc_xy *out);

#endif
