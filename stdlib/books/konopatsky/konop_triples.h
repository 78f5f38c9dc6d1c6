/* The symbolic method of §2.2 (digest konopatsky_ch1_2.md §5.9): a table of collinear triples
 * (each one line of a ruler construction) becomes its construction.  Given the known points and
 * a current point running on the line of two of them, every other point is found as the meet of
 * two lines of the table whose other points are already known, in an order the planner finds;
 * the curve of the result point is evaluated step by step with homogeneous meets.  The two
 * 7-line systems of Baluba (Fig. 2.28) are two such tables; any determinate table works. */
#ifndef PC_KONOP_TRIPLES_H
#define PC_KONOP_TRIPLES_H

#include <stddef.h>
#include "curve.h"

#define PC_TRIPLES_MAXPTS 32
#define PC_TRIPLES_MAXTRI 64

typedef struct { int x, a, b, c, d; } pc_triple_step;   /* X = ab x cd */

typedef struct {
    int npts, nsteps;
    pc_triple_step step[PC_TRIPLES_MAXPTS];
    int cur, cur_a, cur_b;     /* the current point cur = cur_a t' + cur_b t */
    int result;
} pc_triples_plan;

/* The construction of `result` from the triples tri (ntri rows of 3 point indices < npts) with
 * the points known[i] != 0 given and cur on the line cur_a cur_b (both known).  Each step meets
 * two lines of the table that share only the new point.  PC_EDOMAIN when the table does not
 * determine result this way (or names a point outside npts), PC_EDOMAIN2 unless cur_a and cur_b
 * are two known points, PC_EDIM for sizes beyond the limits. */
int pc_triples_plan_make(int npts, int ntri, const int (*tri)[3], const unsigned char *known,
                         int cur, int cur_a, int cur_b, int result, pc_triples_plan *plan);

/* The curve of the plan's result over [t0, t1] for the known points' coordinates pts (npts rows
 * of dim; rows of unknown points ignored): a FUNC curve (derivatives by differences); where a
 * meet is undefined at some t the evaluation fails there.  The curve copies the data.
 * PC_EDOMAIN3 unless t0 < t1. */
pc_curve *pc_triples_curve(const pc_triples_plan *plan, int dim, const double *pts, double t0,
                           double t1, int *status);
/* One evaluation: every point of the plan at t (npts rows of dim + 1, homogeneous; the known
 * ones as given).  PC_EDOMAIN where a meet is undefined. */
int pc_triples_eval(const pc_triples_plan *plan, int dim, const double *pts, double t, double *all);

/* The names of a table's points (the strings borrowed): pc_triples_name gives the index of s,
 * adding it when new, or -1 when there are PC_TRIPLES_MAXPTS names already. */
typedef struct {
    int n;
    const char *name[PC_TRIPLES_MAXPTS];
} pc_triples_names;
int pc_triples_name(pc_triples_names *nm, const char *s);
/* A table as a caller reads it by names (conic.scheme): the names, the given points (rows of
 * dim; dim 0 before the first), the triples and the current point by index. */
typedef struct {
    pc_triples_names nm;
    int dim, cur[3];
    unsigned char known[PC_TRIPLES_MAXPTS];
    double pts[PC_TRIPLES_MAXPTS * PC_MAXDIM];
    int tri[PC_TRIPLES_MAXTRI][3];
} pc_triples_table;
/* The index of name in t (added when new) into *idx: PC_EARG beyond PC_TRIPLES_MAXPTS names. */
int pc_triples_index(pc_triples_table *t, const char *name, int *idx);
/* Give t the point name = h (n + 1 homogeneous numbers; h NULL: no value): PC_EDIM unless it
 * is a point (its weight snapped to 1, pc_snap_weight) of 2-D or more and of the dimension of
 * the points before, PC_EARG beyond PC_TRIPLES_MAXPTS names. */
int pc_triples_give(pc_triples_table *t, const char *name, int n, const double *h);
/* The plan of result from t's first ntri triples, given points and current point:
 * pc_triples_plan_make's status (PC_EDOMAIN for a result beyond the names). */
int pc_triples_table_plan(pc_triples_table *t, int ntri, const char *result, pc_triples_plan *plan);

/* Step s of the plan as the book writes it, "A = A3A2 x A4A5", into buf (size bytes). */
void pc_triples_step_text(const pc_triples_plan *plan, int s, const pc_triples_names *nm, char *buf, size_t size);

#endif
