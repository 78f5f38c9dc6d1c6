/* A map as text (map.h): the one-line form of tostring(f), the aligned matrix of f:show() with
 * its convention, and the image of a value by the one weight rule (point.h) that the bindings
 * and the camera give back as a point or a direction. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "map.h"

/* Append to buf (size bytes, kept 0-terminated); the length the whole text needs. */
static size_t add(char *buf, size_t size, size_t len, const char *s) {
    if (len < size) snprintf(buf + len, size - len, "%s", s);
    return len + strlen(s);
}

static void num(char *s, size_t size, double x, const char *fmt) {
    snprintf(s, size, fmt, x == 0 ? 0.0 : x);   /* no "-0" */
}

size_t pc_map_text(const pc_map *f, char *buf, size_t size) {
    int affine = pc_map_is_affine(f), rows = affine ? f->nout : f->nout + 1;
    char s[64];
    snprintf(s, sizeof s, "%s map %d-D -> %d-D [", affine ? "affine" : "projective", f->nin, f->nout);
    if (size) buf[0] = 0;
    size_t len = add(buf, size, 0, s);
    for (int i = 0; i < rows; i++) {
        if (i) len = add(buf, size, len, "; ");
        for (int j = 0; j <= f->nin; j++) {
            if (j) len = add(buf, size, len, j == f->nin ? " | " : " ");
            num(s, sizeof s, PC_MAP_AT(f, i, j), "%.14g");
            len = add(buf, size, len, s);
        }
    }
    return add(buf, size, len, "]");
}

size_t pc_map_show(const pc_map *f, int rowvec, char *buf, size_t size) {
    double a[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)];
    pc_map_to_matrix(f, rowvec, a);
    int nr = rowvec ? f->nin + 1 : f->nout + 1, nc = rowvec ? f->nout + 1 : f->nin + 1;
    double big = 0;                               /* rounding noise (cos 90°) prints as 0 */
    for (int i = 0; i < nr * nc; i++) big = fmax(big, fabs(a[i]));
    for (int i = 0; i < nr * nc; i++)
        if (fabs(a[i]) < 1e-14 * big) a[i] = 0;
    int width[PC_MAXDIM + 1] = {0};
    char cell[32], s[96];
    for (int i = 0; i < nr; i++)
        for (int j = 0; j < nc; j++) {
            num(cell, sizeof cell, a[i * nc + j], "%.6g");
            int w = (int)strlen(cell);
            if (w > width[j]) width[j] = w;
        }
    snprintf(s, sizeof s, "%s %d-D -> %d-D, %s:", pc_map_is_affine(f) ? "affine map" : "projective map",
             f->nin, f->nout, rowvec ? "row vectors p' = p T" : "column vectors p' = M p");
    if (size) buf[0] = 0;
    size_t len = add(buf, size, 0, s);
    for (int i = 0; i < nr; i++) {
        len = add(buf, size, len, "\n ");
        for (int j = 0; j < nc; j++) {
            num(cell, sizeof cell, a[i * nc + j], "%.6g");
            snprintf(s, sizeof s, "%s%*s", (j == nc - 1) ? "  | " : "  ", width[j], cell);
            len = add(buf, size, len, s);
        }
    }
    return len;
}

static int image_rule(const pc_map *f, const double *in, double *out) {
    double h[PC_MAXDIM + 1];
    pc_map_apply(f, in, h);
    if (pc_map_is_affine(f) || pc_kind_of(h[f->nout]) != PC_KIND_VECTOR) {
        int st = pc_map_image(f, in, out);
        pc_snap_weight(f->nout, out);
        return st;
    }
    int zero = 1;                 /* the raw weight is within 1e-9 of 0: a direction */
    for (int i = 0; i < f->nout; i++) zero &= h[i] == 0;
    memcpy(out, h, sizeof(double) * (size_t)f->nout);
    out[f->nout] = 0;
    return zero ? PC_EPOLE : in[f->nin] == 0 ? PC_OK : PC_IMPROPER;
}

int pc_map_image_rule(const pc_map *f, const double *in, double *out) {
    int st = image_rule(f, in, out);
    for (int i = 0; st != PC_EPOLE && i <= f->nout; i++)
        if (!isfinite(out[i])) return PC_ENONFINITE;   /* a coordinate overflowed */
    return st;
}
