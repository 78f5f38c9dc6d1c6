/* The constructions by kind (konop_make.h). */
#include <math.h>
#include <stddef.h>
#include <string.h>
#include "konop_make.h"
#include "conic.h"
#include "oneratio.h"
#include "konop_schemes.h"
#include "konop_curves.h"
#include "konop_ch1.h"
#include "approx.h"
#include "point.h"

int pc_konop_npoints(pc_konop_kind kind) {
    switch (kind) {
    case PC_KM_TRIPLES: return 5;
    case PC_KM_TETRA:
    case PC_KM_CONES:
    case PC_KM_BEZIER3:
    case PC_KM_DESARGUES:
    case PC_KM_ED_K:
    case PC_KM_CEVA_K: return 4;
    case PC_KM_CEVA_TO_ED:
    case PC_KM_ED_TO_CEVA:
    case PC_KM_AREA_K:
    case PC_KM_CONES_EXCLUDED:
    case PC_KM_CHEBYSHEV: return 0;
    default: return 3;
    }
}

static const struct { const char *name; pc_konop_kind kind; } names[] = {
    {"conic.ed", PC_KM_ED}, {"conic.ed_k", PC_KM_ED_K}, {"conic.circle_k", PC_KM_CIRCLE_K},
    {"conic.ceva", PC_KM_CEVA}, {"conic.ceva_k", PC_KM_CEVA_K}, {"conic.parabola", PC_KM_PARABOLA},
    {"oneratio.tetra", PC_KM_TETRA}, {"oneratio.bezier3", PC_KM_BEZIER3}, {"oneratio.smooth", PC_KM_SMOOTH},
    {"oneratio.desargues", PC_KM_DESARGUES}, {"conic.cones", PC_KM_CONES}, {"conic.triples", PC_KM_TRIPLES},
    {"oneratio.closed", PC_KM_CLOSED}, {"interp.conic", PC_KM_ED3}, {"conic.ceva_to_ed", PC_KM_CEVA_TO_ED},
    {"conic.ed_to_ceva", PC_KM_ED_TO_CEVA}, {"konopatsky.area_k", PC_KM_AREA_K},
    {"conic.cones_excluded", PC_KM_CONES_EXCLUDED}, {"approx.chebyshev", PC_KM_CHEBYSHEV}};

int pc_konop_kind_of(const char *name) {
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (strcmp(names[i].name, name) == 0) return (int)names[i].kind;
    return -1;
}

pc_curve *pc_konop_make(pc_konop_kind kind, int dim, const double *pts, const double *x, int *status) {
    const double *a = pts, *b = pts + dim, *c = pts + 2 * dim, *d = pts + 3 * dim, *e = pts + 4 * dim;
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
    case PC_KM_CONES: return pc_cubic_cones(dim, a, b, c, d, x[0], x[1], x[2], status);
    case PC_KM_TRIPLES: return pc_triples_conic(dim, a, b, c, d, e, x[0], x[1], status);
    case PC_KM_CLOSED: return pc_oneratio_closed(dim, a, b, c, x[0], x[1], (int)x[2], status);
    default: break;
    }
    if (status) *status = PC_EDOMAIN;
    return NULL;
}

int pc_konop_number(pc_konop_kind kind, int dim, const double *pts, const double *x, double *out) {
    const double *a = pts, *b = pts + dim, *c = pts + 2 * dim, *d = pts + 3 * dim;
    switch (kind) {
    case PC_KM_ED_K: return pc_conic_ed_k(dim, a, b, c, d, out);
    case PC_KM_CIRCLE_K: return pc_conic_ed_circle_k(dim, a, b, c, out);
    case PC_KM_CEVA_K: return pc_conic_ceva_k(dim, a, b, c, d, out);
    case PC_KM_CEVA_TO_ED: return pc_ceva_to_ed(x[0], out);
    case PC_KM_ED_TO_CEVA: return pc_ed_to_ceva(x[0], out);
    case PC_KM_AREA_K: return pc_k_area_k(x[0], x[1], x[2], out);
    default: return PC_EDOMAIN;
    }
}

int pc_konop_list(pc_konop_kind kind, const double *x, double *out, int *n) {
    switch (kind) {
    case PC_KM_CONES_EXCLUDED: return pc_cones_excluded(x[0], x[1], out, n);
    case PC_KM_CHEBYSHEV:
        *n = (int)x[0];
        return *n <= 64 ? pc_chebyshev_nodes(*n, x[1], x[2], out) : PC_EDOMAIN;
    default: return PC_EDOMAIN;
    }
}

int pc_konop_scheme_npoints(pc_konop_scheme_kind kind) {
    return kind == PC_KS_FIVE ? 5 : kind == PC_KS_DESARGUES ? 4 : 3;
}

static const struct { const char *name; pc_konop_scheme_kind kind; const char *fields; } schemes[] = {
    {"conic.ed_scheme", PC_KS_ED, "T1=h K=h T=h N=h P=h Q=h M=h"},
    {"conic.five_scheme", PC_KS_FIVE, "S=h U=h V=h M=h U_B=h U_D=h R=h U_E=h"},
    {"conic.ceva_scheme", PC_KS_CEVA, "M3=p M=p t3=n r=n"},
    {"oneratio.simplex_scheme", PC_KS_SIMPLEX, "N=p M=p"},
    {"conic.foci", PC_KS_FOCI, "p p n n"},
    {"oneratio.desargues_scheme", PC_KS_DESARGUES, "T=h S=h R=h N=h J=h Q=h M=h pJ=n qJ=n"},
    {"conic.focal_point", PC_KS_FOCAL, "p p n n"}, {"konopatsky.polar", PC_KS_POLAR, "p"},
    {"konopatsky.rotate", PC_KS_ROTATE, "p"}};

int pc_konop_scheme_of(const char *name, const char **fields) {
    for (size_t i = 0; i < sizeof schemes / sizeof schemes[0]; i++) {
        if (strcmp(schemes[i].name, name) == 0) {
            *fields = schemes[i].fields;
            return (int)schemes[i].kind;
        }
    }
    return -1;
}

int pc_konop_scheme(pc_konop_scheme_kind kind, int dim, const double *pts, const double *x, double *out) {
    const double *a = pts, *b = pts + dim, *c = pts + 2 * dim, *d = pts + 3 * dim, *e = pts + 4 * dim;
    switch (kind) {
    case PC_KS_ED:
        if (x[0] == 0) return PC_EARG;
        return pc_conic_ed_scheme(dim, a, b, c, x[0], x[1], out);
    case PC_KS_FIVE: return pc_conic_five_scheme(dim, a, b, c, d, e, x[0], out);
    case PC_KS_CEVA: return pc_conic_ceva_scheme(dim, a, b, c, x[0], x[1], out, out + 2 * dim, out + 2 * dim + 1);
    case PC_KS_SIMPLEX: return pc_oneratio_simplex_scheme(dim, a, b, c, x[0], out, out + dim);
    case PC_KS_DESARGUES: return pc_desargues_scheme(dim, a, b, c, d, x[0], out, out + 7 * (dim + 1));
    case PC_KS_FOCI: return pc_conic_foci(dim, a, b, c, x[0] == 1, out, out + dim, out + 2 * dim, out + 2 * dim + 1);
    case PC_KS_FOCAL: return pc_conic_focal_point(dim, a, b, c, x[1] == 1, x[0], out, out + 2 * dim);
    case PC_KS_POLAR: return pc_k_polar(dim, a, b, c, x[0], x[1], out);
    case PC_KS_ROTATE: return pc_k_polar(dim, a, b, c, pc_dist(dim, a, b), x[0], out);
    }
    return PC_EDOMAIN;
}
