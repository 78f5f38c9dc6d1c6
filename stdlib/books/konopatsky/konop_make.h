/* The constructions of the monograph that take only points and numbers, by kind: one entry for
 * callers that hold the points as rows (pts: pc_konop_npoints(kind) rows of dim) and the
 * numbers in order (x), as the bindings of conic.*, oneratio.* and interp.* do. */
#ifndef PC_KONOP_MAKE_H
#define PC_KONOP_MAKE_H

#include "curve.h"

typedef enum {
    PC_KM_ED,          /* A, B, C; k: the engineering-discriminant arc (2.97), pc_conic_ed */
    PC_KM_CEVA,        /* A1, A2, A3; k: Ceva's parametrisation (2.104) */
    PC_KM_PARABOLA,    /* A1, A3, A2; tC: the parabola (2.58), or with tC not NaN (2.62) */
    PC_KM_ED3,         /* A, K, B; k: the conic through A, K, B of §4.1 (pc_conic_ed3) */
    PC_KM_TETRA,       /* A, B, C, D: (3.2) */
    PC_KM_BEZIER3,     /* A, C1, C2, B: (3.4) */
    PC_KM_SMOOTH,      /* A, B, C; n: the contour arc of smoothness order n, §3.6 */
    PC_KM_DESARGUES,   /* A, B, C, D: (3.6) */
    PC_KM_CONES,       /* A, B, C, D; fP, fQ, n: the space cubic of two cones, §2.6 (pc_cubic_cones) */
    PC_KM_TRIPLES,     /* A1 .. A5; t0, t1: the system of triples (b), §2.2 (pc_triples_conic) */
    PC_KM_CLOSED,      /* A, B, C; kP, kQ, scheme: the closed curve of §3.5 (pc_oneratio_closed) */
    PC_KM_ED_K,        /* A, B, C, K: the discriminant k of (2.97) through K (pc_conic_ed_k) */
    PC_KM_CIRCLE_K,    /* A, B, C: k of the circular arc (2.107) */
    PC_KM_CEVA_K,      /* A1, A2, A3, K: Ceva's k (2.100) */
    PC_KM_CEVA_TO_ED,  /* no points; k: the engineering discriminant of Ceva's k (pc_ceva_to_ed) */
    PC_KM_ED_TO_CEVA,  /* no points; k: Ceva's k of the engineering discriminant (pc_ed_to_ceva) */
    PC_KM_AREA_K,      /* no points; l1, l2, l3: the area ratio k of (1.2) (pc_k_area_k) */
    PC_KM_CONES_EXCLUDED,   /* no points; fP, fQ: the u the cubic of two cones avoids (pc_cones_excluded) */
    PC_KM_CHEBYSHEV    /* no points; N, a, b: the N Chebyshev nodes on [a, b] (pc_chebyshev_nodes) */
} pc_konop_kind;

/* How many points the construction takes. */
int pc_konop_npoints(pc_konop_kind kind);
/* The kind of the construction the API calls name ("conic.ed", "oneratio.tetra", ...), or -1. */
int pc_konop_kind_of(const char *name);
/* The curve of a construction PC_KM_ED .. PC_KM_CLOSED of the points and the numbers x (as many
 * as the kind takes), or NULL with *status set (the status of the construction's own function;
 * PC_EDOMAIN for another kind). */
pc_curve *pc_konop_make(pc_konop_kind kind, int dim, const double *pts, const double *x, int *status);
/* The number of a construction PC_KM_ED_K .. PC_KM_AREA_K of the points and the numbers x
 * into *out: the status of its own function (PC_EDOMAIN for another kind). */
int pc_konop_number(pc_konop_kind kind, int dim, const double *pts, const double *x, double *out);
/* The list of a construction PC_KM_CONES_EXCLUDED .. PC_KM_CHEBYSHEV of the numbers x into out
 * (at most 64), their count in *n: the status of its own function (PC_EDOMAIN for another kind). */
int pc_konop_list(pc_konop_kind kind, const double *x, double *out, int *n);

/* The schemes whose points figures label, by kind: pc_konop_scheme fills out with the points
 * in order, then the numbers (rows of dim + 1 homogeneous where a point may be at infinity,
 * of dim where not). */
typedef enum {
    PC_KS_ED,          /* A, B, C; k, u -> T1, K, T, N, P, Q, M (homogeneous): §2.1.6 */
    PC_KS_FIVE,        /* A, B, C, D, E; u -> S, U, V, M, U_B, U_D, R, U_E (homogeneous): §2.1.4 */
    PC_KS_CEVA,        /* A1, A2, A3; k, t -> M3, M (rows of dim), t3, r: (2.105) */
    PC_KS_SIMPLEX,     /* A, B, C; t -> N, M (rows of dim): Fig. 3.1 */
    PC_KS_DESARGUES,   /* A, B, C, D; t -> T, S, R, N, J, Q, M (homogeneous), pJ, qJ: Fig. 3.12 */
    PC_KS_FOCI,        /* C, A, B; 0 ellipse or 1 hyperbola -> F1, F2 (rows of dim), e, p */
    PC_KS_FOCAL,       /* C, A, B; phi, 0 ellipse or 1 hyperbola -> M, F (rows of dim), pa, pb */
    PC_KS_POLAR,       /* C, A, B; rho, phi -> M (a row of dim): (2.117), pc_k_polar */
    PC_KS_ROTATE       /* C, A, B; phi -> A rotated about C towards B: pc_k_polar with rho = |CA| */
} pc_konop_scheme_kind;

/* How many points the scheme takes. */
int pc_konop_scheme_npoints(pc_konop_scheme_kind kind);
/* The kind of the scheme the API calls name ("conic.ed_scheme", "conic.foci", ...), or -1, and
 * in *fields its results in the order of pc_konop_scheme's out, a pcl_push_packed spec
 * ("T1=h K=h ...": NAME= a field of one table, h a homogeneous row, p a point, n a number). */
int pc_konop_scheme_of(const char *name, const char **fields);
/* The scheme's points and numbers into out (at most 8 (PC_MAXDIM + 1) doubles): the status of
 * the scheme's own function; PC_EARG for a zero k of PC_KS_ED (the arc collapses to C). */
int pc_konop_scheme(pc_konop_scheme_kind kind, int dim, const double *pts, const double *x, double *out);

#endif
