/* A curve as tostring shows it (curve_text.h). */
#include <stdio.h>
#include <string.h>
#include "curve_text.h"
#include "fourier.h"
#include "spline.h"

size_t pc_curve_text(const pc_curve *c, const char *kind, char *buf, size_t size) {
    char t0[32], t1[32];
    int n, np, len;
    snprintf(t0, sizeof t0, "%.14g", c->t0 == 0 ? 0.0 : c->t0);
    snprintf(t1, sizeof t1, "%.14g", c->t1 == 0 ? 0.0 : c->t1);
    if (pc_curve_fourier_coefs(c, &n))
        len = snprintf(buf, size, "fourier(%d points, %d-D)", 2 * n, c->dim);
    else if (pc_curve_stroke_pieces(c, &np) && !strcmp(kind, "spline2"))
        len = snprintf(buf, size, "spline2(%d-D)", c->dim);
    else if (np)
        len = snprintf(buf, size, "stroke(%d nodes, %d pieces, %d-D%s)", c->closed ? np : np + 1, np,
                       c->dim, c->closed ? ", closed" : "");
    else if (c->kind == PC_CURVE_FUNC)
        len = snprintf(buf, size, "%s(%d-D, t in [%s, %s])", kind, c->dim, t0, t1);
    else
        len = snprintf(buf, size, "%s(%d-D, degree %d, %d control points, t in [%s, %s])", kind,
                       c->dim, c->degree, c->ncp, t0, t1);
    return len < 0 ? 0 : (size_t)len;
}

pc_field_type pc_curve_field(const pc_curve *c, const char *key, double *v) {
    int np, n;
    pc_field_type type = PC_FIELD_INTEGER;
    if (!strcmp(key, "dim")) *v = c->dim;
    else if (!strcmp(key, "lo") || !strcmp(key, "t0")) *v = c->t0, type = PC_FIELD_NUMBER;
    else if (!strcmp(key, "hi") || !strcmp(key, "t1")) *v = c->t1, type = PC_FIELD_NUMBER;
    else if (!strcmp(key, "closed")) *v = c->closed, type = PC_FIELD_BOOLEAN;
    else if (!strcmp(key, "degree") && c->kind != PC_CURVE_FUNC) *v = c->degree;
    else if (!strcmp(key, "pieces") && pc_curve_stroke_pieces(c, &np)) *v = np;
    else if (!strcmp(key, "pieces")) *v = c->kind == PC_CURVE_BEZIER ? c->nknots - 1 : 1;
    else if (!strcmp(key, "n") && pc_curve_fourier_coefs(c, &n)) *v = n;
    else type = PC_FIELD_NONE;
    return type;
}
