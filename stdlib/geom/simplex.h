/* Simplices (§1.2, §4.3 of the digest): k+1 independent points in n-space, n >= k.  Vertex 0
 * is the book's initial point (C in "simplex CAB", D in "DABC"); vertices 1..k carry the
 * natural parameters, so M = (A - C)p + (B - C)q + C (the initial-point form). */
#ifndef PC_SIMPLEX_H
#define PC_SIMPLEX_H

#include <stddef.h>
#include "point.h"

typedef struct {
    int n, k;          /* ambient dimension, simplex dimension (k+1 vertices) */
    double data[];     /* vertices (k+1 rows of n), then Q (k rows of n), then R (k x k) */
} pc_simplex;

#define PC_SIMPLEX_V(s) ((s)->data)
#define PC_SIMPLEX_Q(s) ((s)->data + ((s)->k + 1) * (s)->n)
#define PC_SIMPLEX_R(s) ((s)->data + ((s)->k + 1) * (s)->n + (s)->k * (s)->n)

/* Bytes needed for a simplex of k+1 vertices in n-space. */
size_t pc_simplex_size(int n, int k);
/* Build from k+1 vertices (rows of n, initial point first) in memory of pc_simplex_size
 * bytes.  PC_EDIM if k > n or the sizes exceed PC_MAXDIM; PC_ECOINCIDENT if a vertex
 * repeats the initial point; PC_ECOLLINEAR if the vertices are dependent (a flat simplex). */
int pc_simplex_init(pc_simplex *s, int n, int k, const double *vertices);

/* Natural parameters -> point: out = C + sum (A_i - C) p_i  (initial-point form, §4.3). */
void pc_simplex_eval(const pc_simplex *s, const double *p, double *out);
/* Barycentric evaluation, homogeneous: out (n+1) = sum A_i c_i + C c_k, with the weight
 * sum c.  Coefficients are given for vertices 1..k first, then for the initial point, as in
 * M = Ap + Bq + Cr for simplex CAB.  A sum other than 1 gives a weighted value. */
void pc_simplex_bary(const pc_simplex *s, const double *c, double *out);
/* Natural parameters of M (least squares when k < n) and the distance of M from the
 * simplex's flat.  M = eval(params) exactly when residual is 0. */
void pc_simplex_params(const pc_simplex *s, const double *m, double *p, double *residual);
/* Measure (length, area, volume, ...): signed when k = n (det of the edges / k!, so a
 * counter-clockwise triangle is positive), unsigned otherwise. */
double pc_simplex_measure(const pc_simplex *s);
/* S- and V-theorem (§1.3.3-1.3.4): the signed ratio of the measure of the k-simplex pts
 * (k+1 rows of n, lying in the simplex's flat) to the simplex's own (vertices in the order
 * given, initial point first), as the determinant of the points' parameters bordered by a
 * column of 1s.  The printed V-theorem (L501) divides that determinant by itself; the ratio
 * is the determinant alone, as the text says (misprint corrected, digest §9).
 * *residual: largest distance of a point from the flat. */
double pc_simplex_ratio(const pc_simplex *s, const double *pts, double *residual);

/* simplex_text.c: the failure st of pc_simplex_init(n, k, vertices v) as text into buf ("the 3
 * points are collinear: a flat (degenerate) triangle"; v may be NULL for PC_EDIM with k > n), and
 * the simplex as text, simplex(P(0, 0), P(1, 0), P(0, 1)).  Both return the length the text
 * needs (as snprintf). */
size_t pc_simplex_init_text(int st, int n, int k, const double *v, char *buf, size_t size);
size_t pc_simplex_text(const pc_simplex *s, char *buf, size_t size);

#endif
