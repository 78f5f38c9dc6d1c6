/* The scheme points of the monograph (books/konopatsky/konop_schemes.h) in Lua, declared on the
 * argument layer: each a point, or a vector where the scheme's point is at infinity (N at
 * u = 1/2 of conic.ed_scheme). */
#include "pcl_args.h"
#include "pcl_core.h"
#include "konop_schemes.h"
#include "konop_why.h"
#include "konop_make.h"
#include "conic.h"

#define CHECK(st) pcl_check(L, (st), pc_konop_why)

/* A scheme of pc_konop_scheme, the kind by the name it is called: the declared points, then the
 * numbers (an enum's choice by its index); its points and numbers pushed by its fields. */
static int scheme(lua_State *L) {
    pcl_val a[7] = {0};
    PCL_READ(L, a);
    const char *fields;
    pc_konop_scheme_kind kind = pc_konop_scheme_of(pcl_name(L), &fields);
    int np = pc_konop_scheme_npoints(kind), d = a[0].n;
    double p[5 * PC_MAXDIM], x[2], o[8 * (PC_MAXDIM + 1)];
    for (int i = 0; i < 2; i++) x[i] = a[np + i].s ? a[np + i].n : a[np + i].x;
    pcl_point_rows(a, np, d, p);
    CHECK(pc_konop_scheme(kind, d, p, x, o));
    return pcl_push_packed(L, d, fields, o);
}

PCL_BODY(l_smooth_scheme, a) {
    int d = a[0].n, n = (int)a[3].x;
    double *buf = lua_newuserdatauv(L, sizeof(double) * (size_t)(2 * n + 1) * (size_t)d, 0);
    double *p = buf, *q = buf + n * d, *m = q + n * d;
    CHECK(pc_oneratio_smooth_chain(d, a[0].v, a[1].v, a[2].v, n, a[4].x, p, q, m));
    return pcl_push_results(L, d, "P=P Q=P M=p", n, p, n, q, m);
}

PCL_BODY(l_cones_excluded, a) {
    double u[5];
    int n;
    CHECK(pc_cones_excluded(a[0].x, a[1].x, u, &n));
    return pcl_push_results(L, 0, "N", n, u);
}

static const char *const KINDS[] = {"ellipse", "hyperbola", NULL};


#define SAMEPT(nm) {.name = nm, .kind = PCL_POINT, .flags = PCL_SAMEDIM}
static const pcl_arg ed_args[] = {SAMEPT("A"), SAMEPT("B"), SAMEPT("C"), A_NUM("k"), A_NUM("u"), PCL_END};
static const pcl_arg five_args[] = {SAMEPT("A"), SAMEPT("B"), SAMEPT("C"), SAMEPT("D"), SAMEPT("E"), A_NUM("u"), PCL_END};
static const pcl_arg smooth_args[] = {SAMEPT("A"), SAMEPT("B"), SAMEPT("C"), A_INT("n", 1, 40), A_NUM("t"), PCL_END};
static const pcl_arg f_args[] = {A_NUM("fP"), A_NUM("fQ"), PCL_END};
#define KIND {.name = "kind", .kind = PCL_ENUM, .flags = PCL_OPT, .choices = KINDS}
static const pcl_arg foci_args[] = {SAMEPT("C"), SAMEPT("A"), SAMEPT("B"), KIND, PCL_END};
static const pcl_arg focal_args[] = {SAMEPT("C"), SAMEPT("A"), SAMEPT("B"), A_NUM("phi"), KIND, PCL_END};
static const pcl_arg ceva_args[] = {SAMEPT("A1"), SAMEPT("A2"), SAMEPT("A3"), A_NUM("k"), A_NUM("t"), PCL_END};
static const pcl_arg abct_args[] = {SAMEPT("A"), SAMEPT("B"), SAMEPT("C"), A_NUM("t"), PCL_END};
static const pcl_arg abcdt_args[] = {SAMEPT("A"), SAMEPT("B"), SAMEPT("C"), SAMEPT("D"), A_NUM("t"), PCL_END};

static const pcl_fn conic_fns[] = {
    PCL_FN("conic.ed_scheme", scheme, ed_args, "{T1, K, T, N, P, Q, M}", "§2.1.6 Fig. 2.21 The points of the engineering-discriminant scheme at u: T1 the chord's midpoint, K = (T1 - C)k + C, T = A u' + B u, N its harmonic conjugate (a vector, at infinity, at u = 1/2), P = AK x CT, Q = BK x CT, M = AQ x BP = (2.97) at u."),
    PCL_FN("conic.five_scheme", scheme, five_args, "{S, U, V, M, U_B, U_D, R, U_E}", "§2.1.4 Fig. 2.15 The points of Pascal's hexagon A D M E B C at u (corrected): S = BE x AD, U = (A - C)u + C, V = SU x CB, M = UE x VD, and U_B = BE x CA, U_D = CA x ED, R = CB x ED, U_E = RS x CA, whose positions on CA give the u of B, D, E."),
    PCL_FN("conic.ceva_scheme", scheme, ceva_args, "{M3, M, t3, r}", "(2.105) Ceva's arc read by the engineering discriminant: M3 = A1(1 - t3) + A2 t3 on A1A2, M = M3(1 - r) + A3 r, t3 = (1 - t)^2/(k t^2 + (1 - t)^2), r = t(1 - t)/(1 - t(1 - kt)); M is (2.104) at t."),
    PCL_FN("conic.focal_point", scheme, focal_args, "M, F, pa, pb", "The focal-simplex forms (2.16)/(2.17) and, corrected, (2.54)/(2.55): the point at the focal angle phi written in the simplex A B F, M = (A - F) pa + (B - F) pb + F, F = F2 = C - (A - C)e of the ellipse (CA the major semi-axis) or F1 = C + (A - C)e of the hyperbola; the points of (2.18), (2.56)."),
    PCL_FN("conic.foci", scheme, foci_args, "F1, F2, e, p", "The foci, eccentricity and focal parameter b^2/a of the ellipse of centre C and semi-axes CA, CB (the foci on the longer), or of the hyperbola of vertex A and imaginary semi-axis CB; any dimension; CA and CB must be perpendicular."),
    PCL_FN("conic.cones_excluded", l_cones_excluded, f_args, "{u, ...}", "§2.6 The parameters u the cubic of two cones must avoid, sorted: (2.148)'s pole, (2.151) u = (1 +- 1/sqrt(1 - 2 fP))/2 (the print's sign corrected) for fP < 1/2, and the roots (2.153) of Q's denominator."),
    PCL_END};
static const pcl_fn oneratio_fns[] = {
    PCL_FN("oneratio.simplex_scheme", scheme, abct_args, "{N =, M =}", "Fig. 3.1 The moving simplex at t: N = A t' + C t on AC and M = N t' + B t on NB (the point of (3.1))."),
    PCL_FN("oneratio.desargues_scheme", scheme, abcdt_args, "{T =, S =, R =, N =, J =, Q =, M =, pJ =, qJ =}", "Fig. 3.12 The points of the Desargues arc's scheme at t; T, S, R are directions (vectors) at t = 1/2."),
    PCL_FN("oneratio.smooth_scheme", l_smooth_scheme, smooth_args, "{P = {P1, ..., Pn}, Q = {Q1, ..., Qn}, M}", "§3.6 Figs. 3.9, 3.10 The chain points of M_n at t: P_i = P_(i-1) + t(P_(i+1) - P_(i-1)) on A..C, Q_i likewise on C..B, M = P_n + t(Q1 - P_n) (for n = 2: AP1/AP2 = P1P2/P1C = CQ1/CQ2 = Q1Q2/Q1B = P2M/P2Q1 = t)."),
    PCL_END};

/* After pcl_open_konopatsky, with the module table on top. */
void pcl_open_konopatsky_schemes(lua_State *L) {
    pcl_register_into(L, lua_gettop(L), "conic", conic_fns);
    pcl_register_into(L, lua_gettop(L), "oneratio", oneratio_fns);
}
