/* The maps made of numbers alone, by kind: one entry for callers that hold the numbers in
 * order (the constructors of the map and affine tables), and the explanation of each status
 * of each map operation, by the name the API gives it (why.h). */
#ifndef PC_MAP_MAKE_H
#define PC_MAP_MAKE_H

#include "map.h"
#include "why_call.h"

typedef enum {
    PC_MM_IDENTITY,         /* n: pc_map_identity */
    PC_MM_ORTHOGRAPHIC,     /* the axis dropped, 0 x, 1 y, 2 z: pc_map_orthographic */
    PC_MM_AXONOMETRIC,      /* phi, theta */
    PC_MM_ISOMETRIC,        /* no numbers */
    PC_MM_DIMETRIC,         /* fz */
    PC_MM_OBLIQUE,          /* k, alpha */
    PC_MM_CAVALIER,         /* alpha: the oblique projection with k = 1 */
    PC_MM_CABINET,          /* alpha: k = 1/2 */
    PC_MM_PERSPECTIVE_PQR   /* p, q, r */
} pc_map_kind;

/* The map of the kind from its numbers x in order into f: the status of the kind's own
 * function (PC_EDOMAIN for an unknown kind or axis, n outside 1..PC_MAXDIM). */
int pc_map_make(pc_map *f, pc_map_kind kind, const double *x);
/* The kind the API names ("identity", "orthographic", ..., "perspective_pqr": the enum's names
 * in lower case), or -1 for any other name. */
int pc_map_kind_named(const char *name);

/* pc_map_translate by a finite vector v (one made by overflow gives no map): PC_ENONFINITE. */
int pc_map_translate_finite(pc_map *f, int n, const double *v);

/* Space turned by angle about the axis through a and b, or (b_is_direction) through a along
 * b: pc_map_rotate3, with PC_ECOINCIDENT for b = a and PC_EZERO for a zero direction. */
int pc_map_rotate_axis(pc_map *f, const double a[3], const double b[3], int b_is_direction, double angle);
/* pc_map_affine_points from m source points of nin-D to m2 image points of nout-D, their
 * counts and dependence explained in w (affine(src, dst)). */
int pc_map_affine_checked(pc_map *f, int m, int nin, int m2, int nout, const double *src, const double *dst,
                          pc_why_call *w);

/* The index i of the field name "Ci" of a map (C0, C1, ...: the image of the origin and of the
 * axes' unit points, pc_map_unit_image), no leading zero; -1 for any other name. */
int pc_map_unit_name(const char *name);

extern const pc_why pc_map_why[];

#endif
