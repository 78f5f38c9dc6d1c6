/* A curve drawn as one path (curve_path.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "curve_path.h"
#include "names.h"

int pc_map_image_xy(const pc_map *f, int n, const double *h, double *x, double *y) {
    if (!f || f->nin != n) return PC_EDIM;
    double o[3];
    pc_map_apply(f, h, o);
    if (o[2] == 0) return PC_IMPROPER;
    *x = o[0] / o[2];
    *y = o[1] / o[2];
    return isfinite(*x) && isfinite(*y) ? PC_OK : PC_ENONFINITE;
}

int pc_place_xy(const pc_map *f, int n, const double *h, double *x, double *y) {
    if (n != 2) return pc_map_image_xy(f, n, h, x, y);
    *x = h[0] / h[2];
    *y = h[1] / h[2];
    return PC_OK;
}

int pc_place_why(const pc_map *f, int n, const double *h, double *xy, char *why, size_t len) {
    if (n == 2) {
        char w[40];
        if (pc_loc(2, h, xy) == PC_OK) return PC_OK;
        snprintf(why, len, ": %%s has weight %s, not 1: a location must be a point (the membership condition; "
                 "normalize(p) for a projective point)", pc_num_text(h[2], w, sizeof w));
        return PC_EARG;
    }
    int st = pc_map_image_xy(f, n, h, xy, xy + 1);
    if (st == PC_IMPROPER) snprintf(why, len, ": %%s projects to infinity (it lies in the camera's vanishing plane)");
    else if (st == PC_EDIM) snprintf(why, len, " must be a 2-D point, got the %d-D %%s (3-D points need a camera)", n);
    else if (st != PC_OK) snprintf(why, len, ": the image of %%s is not finite");
    return st;
}

long pc_place_rows(const pc_map *f, size_t n, int dim, const double *rows, double *xy) {
    for (size_t i = 0; i < n; i++) {
        double h[PC_MAXDIM + 1];
        memcpy(h, rows + i * (size_t)dim, sizeof(double) * (size_t)dim);
        h[dim] = 1;
        if (pc_place_xy(f, dim, h, &xy[2 * i], &xy[2 * i + 1]) != PC_OK) return (long)i;
    }
    return -1;
}

void pc_screen_map(const pc_canvas *cv, const pc_map *f, pc_map *out) {
    double o[2], ex[2], ey[2];
    pc_world_to_screen(cv, 0, 0, &o[0], &o[1]);
    pc_world_to_screen(cv, 1, 0, &ex[0], &ex[1]);
    pc_world_to_screen(cv, 0, 1, &ey[0], &ey[1]);
    pc_map w;
    pc_map_identity(&w, 2);
    for (int r = 0; r < 2; r++) {
        PC_MAP_AT(&w, r, 0) = ex[r] - o[r];
        PC_MAP_AT(&w, r, 1) = ey[r] - o[r];
        PC_MAP_AT(&w, r, 2) = o[r];
    }
    if (f) pc_map_compose(&w, f, out);
    else *out = w;
}

int pc_curve_flatten_parts(const pc_curve *c, double a, double b, int pieces, const pc_map *f,
                           double tol, pc_polyline *out) {
    if (!f && c->dim != 2) return PC_EDIM;
    if (pieces < 1) pieces = 1;
    for (int i = 0; i < pieces; i++) {
        double lo = a + (b - a) * i / pieces, hi = i == pieces - 1 ? b : a + (b - a) * (i + 1) / pieces;
        size_t before = out->n;
        int st = pc_curve_flatten_map(c, lo, hi, f, tol, out);
        if (st != PC_OK) return st;
        /* the next part starts where this one ended: keep one vertex, no break */
        if (before > 0 && out->n > before && out->xy[2 * before] == out->xy[2 * before - 2] &&
            out->xy[2 * before + 1] == out->xy[2 * before - 1]) {
            memmove(out->xy + 2 * before, out->xy + 2 * (before + 1),
                    sizeof(double) * 2 * (out->n - before - 1));
            memmove(out->move + before, out->move + before + 1, out->n - before - 1);
            out->n--;
        }
    }
    return PC_OK;
}

int pc_curve_flatten_checked(const char *op, const pc_curve *c, const pc_map *f, double tol, pc_polyline *out,
                             pc_why_call *why) {
    if (f && (f->nin != c->dim || f->nout != 2))
        return pc_why_call_set(why, op, PC_EDIM, 2, NULL, "must be a map from %d-D to 2-D", c->dim);
    if (!f && c->dim != 2)
        return pc_why_call_set(why, op, PC_EDIM, 0, NULL, "a %d-D curve needs a map to the plane (argument #2)", c->dim);
    int st = pc_curve_flatten_parts(c, c->t0, c->t1, 1, f, tol, out);
    if (st != PC_OK) pc_polyline_free(out);
    return pc_why_call_set(why, NULL, st, 0, NULL, "");
}

int pc_curve_flatten_screen(const pc_canvas *cv, const pc_curve *c, const pc_map *f, int pieces,
                            double tol, pc_polyline *out) {
    pc_map scr;
    pc_screen_map(cv, f, &scr);
    double m = cv->width > cv->height ? cv->width : cv->height;
    double clip[4] = {-m, -m, cv->width + m, cv->height + m};
    out->clip = clip;
    int st = pc_curve_flatten_parts(c, c->t0, c->t1, pieces, &scr, tol, out);
    out->clip = NULL;
    return st;
}

int pc_polyline_broken(const pc_polyline *pl) {
    for (size_t i = 1; i < pl->n; i++)
        if (pl->move[i]) return 1;
    return 0;
}

int pc_polyline_stroke(pc_canvas *cv, const pc_polyline *pl, int color, int closed) {
    if (pl->n == 0) return PC_OK;
    uint8_t *verbs = malloc(pl->n);
    if (!verbs) {
        snprintf(cv->error, sizeof cv->error, "%s", pc_strerror(PC_ENOMEM));
        return PC_ENOMEM;
    }
    for (size_t i = 0; i < pl->n; i++) verbs[i] = (i == 0 || pl->move[i]) ? PC_PATH_MOVE : PC_PATH_LINE;
    int st = pc_path_screen(cv, pl->n, pl->xy, verbs, pl->n, closed, color);
    free(verbs);
    return st;
}

int pc_curve_draw(pc_canvas *cv, pc_scene *sc, int pen, const pc_curve *c, const pc_map *f, int pieces,
                  double tol, int color, int closed, char *why, size_t size) {
    pc_polyline pl = {0};
    char num[40];
    *why = 0;
    int st = pc_curve_flatten_screen(cv, c, f, pieces, tol, &pl);
    if (st == PC_ENOMEM && pl.n >= PC_POLYLINE_MAX)
        snprintf(why, size, "the curve needs more than %d vertices at tol = %s px; draw it with a larger tol",
                 (int)PC_POLYLINE_MAX, pc_num_text(tol, num, sizeof num));
    if (st == PC_OK && sc)   /* into the scene, sampled as densely as the flattened path */
        st = pc_scene_add_curve(sc, c, (int)fmin(8192, fmax(64, 4.0 * (double)pl.n)), color, pen);
    else if (st == PC_OK) {
        st = pc_polyline_stroke(cv, &pl, color, (c->closed || closed) && !pc_polyline_broken(&pl));
        if (st != PC_OK) snprintf(why, size, "%s", cv->error);
    }
    pc_polyline_free(&pl);
    return st;
}

const pc_map *pc_drawing_map(const pc_map *f, int given, const pc_map *camera, int dim, char *why, size_t size) {
    *why = 0;
    if (given && (!f || f->nout != 2 || f->nin != dim))
        snprintf(why, size, "map must be a map from %d-D to 2-D", dim);
    if (given) return *why ? NULL : f;
    if (dim == 2) return camera && camera->nin == 2 ? camera : NULL;   /* a 3-D camera leaves 2-D drawing alone */
    if (!camera)
        snprintf(why, size, "a %d-D object needs a projection: set one with camera(f) or give map = f", dim);
    else if (camera->nin != dim)
        snprintf(why, size, "the camera takes %d-D points, but this is %d-D", camera->nin, dim);
    return *why ? NULL : camera;
}
