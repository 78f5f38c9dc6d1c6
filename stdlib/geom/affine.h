/* Affine maps x -> M x + t from nin-space to nout-space ("change of simplex", §1.2.2: an
 * affine transformation of the object).  Acting on a value (n+1 doubles) the translation is
 * multiplied by the weight, so vectors (weight 0) ignore it and weights are preserved. */
#ifndef PC_AFFINE_H
#define PC_AFFINE_H

#include "point.h"

typedef struct {
    int nin, nout;
    double m[PC_MAXDIM * (PC_MAXDIM + 1)];   /* nout rows of nin+1: [M | t] */
} pc_affine;

#define PC_AFFINE_AT(f, i, j) ((f)->m[(i) * ((f)->nin + 1) + (j)])

void pc_affine_identity(pc_affine *f, int n);
/* The map sending src[i] to dst[i] for i = 0..nin (src: nin+1 rows of nin, dst: nin+1 rows
 * of nout): 3 pairs in the plane, 4 in space; nout may differ from nin (4 image points of a
 * 3-D frame in the plane give an oblique projection).  PC_ECOINCIDENT/PC_ECOLLINEAR if the
 * source points are dependent, PC_EDIM on bad sizes. */
int pc_affine_from_points(pc_affine *f, int nin, int nout, const double *src, const double *dst);
/* The map of a frame: (x1, ..., xk) -> O + x1 a1 + ... + xk ak, with naxes vectors a_i (rows
 * of nout).  No independence is required (a projection is a valid frame map). */
int pc_affine_frame(pc_affine *f, int nout, int naxes, const double *o, const double *axes);
/* Apply to a value: in has nin+1 doubles (weight last), out nout+1. */
void pc_affine_apply(const pc_affine *f, const double *in, double *out);
/* h = f o g (apply g first).  PC_EDIM unless g->nout == f->nin. */
int pc_affine_compose(const pc_affine *f, const pc_affine *g, pc_affine *h);
/* PC_EDIM unless nin == nout; PC_ESINGULAR for a singular linear part. */
int pc_affine_inverse(const pc_affine *f, pc_affine *inv);

#endif
