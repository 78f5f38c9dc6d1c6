/* The constructions by kind (konop_make.h). */
#include <math.h>
#include <stddef.h>
#include "konop_make.h"
#include "conic.h"
#include "oneratio.h"

int pc_konop_npoints(pc_konop_kind kind) {
    switch (kind) {
    case PC_KM_TETRA:
    case PC_KM_BEZIER3:
    case PC_KM_DESARGUES:
    case PC_KM_ED_K:
    case PC_KM_CEVA_K: return 4;
    default: return 3;
    }
}

pc_curve *pc_konop_make(pc_konop_kind kind, int dim, const double *pts, const double *x, int *status) {
    const double *a = pts, *b = pts + dim, *c = pts + 2 * dim, *d = pts + 3 * dim;
    switch (kind) {
    case PC_KM_ED: return pc_conic_ed(dim, a, b, c, x[0], status);
    case PC_KM_CEVA: return pc_conic_ceva(dim, a, b, c, x[0], status);
    case PC_KM_PARABOLA:
        if (isnan(x[0])) return pc_conic_parabola(dim, a, b, c, status);
        return pc_conic_parabola3(dim, a, b, c, x[0], status);   /* A, C, B with C reached at tC */
    case PC_KM_ED3: return pc_conic_ed3(dim, a, b, c, x[0], status);
    case PC_KM_TETRA: return pc_oneratio_tetra(dim, a, b, c, d, status);
    case PC_KM_BEZIER3: return pc_oneratio_bezier3(dim, a, b, c, d, status);
    case PC_KM_SMOOTH: return pc_oneratio_smooth(dim, a, b, c, (int)x[0], status);
    case PC_KM_DESARGUES: return pc_oneratio_desargues(dim, a, b, c, d, status);
    default: break;
    }
    if (status) *status = PC_EDOMAIN;
    return NULL;
}

int pc_konop_number(pc_konop_kind kind, int dim, const double *pts, double *out) {
    const double *a = pts, *b = pts + dim, *c = pts + 2 * dim, *d = pts + 3 * dim;
    switch (kind) {
    case PC_KM_ED_K: return pc_conic_ed_k(dim, a, b, c, d, out);
    case PC_KM_CIRCLE_K: return pc_conic_ed_circle_k(dim, a, b, c, out);
    case PC_KM_CEVA_K: return pc_conic_ceva_k(dim, a, b, c, d, out);
    default: return PC_EDOMAIN;
    }
}
