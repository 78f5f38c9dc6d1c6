/* The maps made of numbers alone, by kind, and the map operations' why-table (map_make.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "map_make.h"

int pc_map_make(pc_map *f, pc_map_kind kind, const double *x) {
    switch (kind) {
    case PC_MM_IDENTITY:
        if (!(x[0] >= 1 && x[0] <= PC_MAXDIM)) return PC_EDOMAIN;
        pc_map_identity(f, (int)x[0]);
        return PC_OK;
    case PC_MM_ORTHOGRAPHIC:
        return x[0] >= 0 && x[0] < 3 ? pc_map_orthographic(f, "xyz"[(int)x[0]]) : PC_EDOMAIN;
    case PC_MM_AXONOMETRIC:
        pc_map_axonometric(f, x[0], x[1]);
        return PC_OK;
    case PC_MM_ISOMETRIC:
        pc_map_isometric(f);
        return PC_OK;
    case PC_MM_DIMETRIC:
        return pc_map_dimetric(f, x[0]);
    case PC_MM_OBLIQUE:
    case PC_MM_CAVALIER:
    case PC_MM_CABINET:
        pc_map_oblique(f, kind == PC_MM_OBLIQUE ? x[0] : kind == PC_MM_CAVALIER ? 1.0 : 0.5,
                       kind == PC_MM_OBLIQUE ? x[1] : x[0]);
        return PC_OK;
    case PC_MM_PERSPECTIVE_PQR:
        return pc_map_perspective_pqr(f, x[0], x[1], x[2]);
    }
    return PC_EDOMAIN;
}

int pc_map_kind_named(const char *name) {
    static const char *const names[] = {"identity", "orthographic", "axonometric", "isometric", "dimetric",
                                        "oblique", "cavalier", "cabinet", "perspective_pqr"};
    for (int i = 0; i < (int)(sizeof names / sizeof names[0]); i++)
        if (!strcmp(name, names[i])) return i;
    return -1;
}

int pc_map_translate_finite(pc_map *f, int n, const double *v) {
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i])) return PC_ENONFINITE;
    pc_map_translate(f, n, v);
    return PC_OK;
}

int pc_map_rotate_axis(pc_map *f, const double a[3], const double b[3], int b_is_direction, double angle) {
    double d[3];
    for (int i = 0; i < 3; i++) d[i] = b[i] - (b_is_direction ? 0 : a[i]);
    int st = pc_map_rotate3(f, a, d, angle);
    return st == PC_EZERO && !b_is_direction ? PC_ECOINCIDENT : st;
}

int pc_map_affine_checked(pc_map *f, int m, int nin, int m2, int nout, const double *src, const double *dst,
                          pc_why_call *w) {
    if (m < 2)
        return pc_why_call_set(w, "affine", PC_EDIM, 1, NULL,
                               "holds %d points; a map of n-D needs n + 1 (3 in the plane, 4 in space)", m);
    if (m != nin + 1)
        return pc_why_call_set(w, "affine", PC_EDIM, 1, NULL, "holds %d %d-D points; a map of %d-D needs %d (dimension + 1)",
                               m, nin, nin, nin + 1);
    if (m2 != m)
        return pc_why_call_set(w, "affine", PC_EDIM, 2, NULL, "holds %d points, argument #1 %d: they must pair up", m2, m);
    int st = pc_map_affine_points(f, nin, nout, src, dst);
    return pc_why_call_set(w, "affine", st, 0, NULL, "%s", pc_map_points_why(st, nin));
}

int pc_map_unit_name(const char *name) {
    if (name[0] != 'C' || name[1] < '0' || name[1] > '9' || (name[1] == '0' && name[2])) return -1;
    char *end;
    long i = strtol(name + 1, &end, 10);
    return *end || i > PC_MAXDIM ? -1 : (int)i;
}

const pc_why pc_map_why[] = {
    {"map.translate", PC_ENONFINITE, 1, NULL, "must be a finite vector, got %s"},
    {"map.matrix", PC_ESINGULAR, 0, NULL, "the zero matrix is no map (it sends every point nowhere)"},
    {"map.reflect", PC_EZERO, 2, NULL, "is the zero vector, which gives no mirror"},
    {"map.dimetric", PC_EDOMAIN, 1, NULL, "must be a number between 0 and 1 (the foreshortening of the z axis), got %s"},
    {"map.axial_affinity", PC_EZERO, 0, NULL, "the directions d and s must not be zero"},
    {"map.axial_affinity", PC_ECOLLINEAR, 0, NULL, "the direction s lies along the axis d: no affinity"},
    {"map.foreshortening", PC_EDOMAIN, 0, NULL,
     "a perspective (projective) map has no constant foreshortening; give an affine map (an axonometry)"},
    {"map.rotate", PC_EZERO, 0, NULL, "argument #2 (direction) is the zero vector, which gives no axis"},
    {"map.rotate", PC_ECOINCIDENT, 0, NULL, "the axis points A and B coincide, so they give no axis"},
    {"map.shear", PC_EDOMAIN, 0, NULL,
     "arguments #2 and #3 (i, j) name the same axis; a shear adds k times axis j to axis i"},
    {"f:inverse", PC_ESINGULAR, 0, NULL, "the map is singular (it flattens space), so it has no inverse"},
    {NULL, 0, 0, NULL, NULL}};
