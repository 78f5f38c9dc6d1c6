/* The scheme points of the monograph (books/konopatsky/konop_schemes.h) in Lua:
 *   conic.ed_scheme(A, B, C, k, u) -> {T1, K, T, N, P, Q, M}        §2.1.6, Fig. 2.21
 *   conic.five_scheme(A, B, C, D, E, u) -> {S, U, V, M, U_B, U_D, R, U_E}   §2.1.4, Fig. 2.15
 *   conic.ceva_to_ed(k), conic.ed_to_ceva(k)                        §2.1.7 <-> §2.1.6
 *   conic.ceva_scheme(A1, A2, A3, k, t) -> {M3, M, t3, r}            (2.105)
 *   conic.focal_point(C, A, B, phi [, kind]) -> M, F, pa, pb         (2.17), (2.55)
 *   conic.foci(C, A, B [, "ellipse"|"hyperbola"]) -> F1, F2, e, p
 *   conic.cones_excluded(fP, fQ) -> {u, ...}                        §2.6 (2.148), (2.151), (2.153)
 *   oneratio.smooth_scheme(A, B, C, n, t) -> {P = {...}, Q = {...}, M}  §3.6, Figs. 3.9, 3.10
 * Each a point, or a vector where the scheme's point is at infinity (N at u = 1/2). */
#include <string.h>
#include "pcl.h"
#include "pcl_point.h"
#include "pcl_books.h"
#include "konop_schemes.h"
#include "conic.h"

static void push_rows(lua_State *L, int dim, const double *h, int n, const char *const *names) {
    lua_createtable(L, 0, n);
    for (int i = 0; i < n; i++) {
        const double *r = h + (size_t)(dim + 1) * i;
        if (r[dim] == 0) {
            pcl_pushvector(L, dim, r);
        } else {
            double x[PC_MAXDIM];
            for (int k = 0; k < dim; k++) x[k] = r[k] / r[dim];
            pcl_pushpoint(L, dim, x);
        }
        lua_setfield(L, -2, names[i]);
    }
}

static int scheme_error(lua_State *L, const char *fn, int st, const char *flat) {
    if (st == PC_ECOLLINEAR) return pcl_error(L, "%s: %s", fn, flat);
    if (st == PC_EDOMAIN)
        return pcl_error(L, "%s: a meet of the scheme is undefined at this parameter (its lines coincide)", fn);
    return pcl_statuserror(L, fn, st, NULL);
}

static int l_ed_scheme(lua_State *L) {
    const char *fn = "conic.ed_scheme";
    static const char *nm[3] = {"A", "B", "C"};
    double p[3 * PC_MAXDIM], o[PC_ED_NPTS * (PC_MAXDIM + 1)];
    int n = pclb_points(L, fn, 1, 3, nm, p);
    double k = pcl_checknum(L, fn, 4, "k"), u = pcl_checknum(L, fn, 5, "u");
    if (k == 0) return pcl_error(L, "%s: argument #4 (k) must not be 0 (the arc collapses to C)", fn);
    int st = pc_conic_ed_scheme(n, p, p + n, p + 2 * n, k, u, o);
    if (st != PC_OK) return scheme_error(L, fn, st, "A, B, C are collinear");
    static const char *names[PC_ED_NPTS] = {"T1", "K", "T", "N", "P", "Q", "M"};
    push_rows(L, n, o, PC_ED_NPTS, names);
    return 1;
}

static int l_five_scheme(lua_State *L) {
    const char *fn = "conic.five_scheme";
    static const char *nm[5] = {"A", "B", "C", "D", "E"};
    double p[5 * PC_MAXDIM], o[PC_P5_NPTS * (PC_MAXDIM + 1)];
    int n = pclb_points(L, fn, 1, 5, nm, p);
    double u = pcl_checknum(L, fn, 6, "u");
    int st = pc_conic_five_scheme(n, p, p + n, p + 2 * n, p + 3 * n, p + 4 * n, u, o);
    if (st != PC_OK) return scheme_error(L, fn, st, "A, B, C are collinear");
    static const char *names[PC_P5_NPTS] = {"S", "U", "V", "M", "U_B", "U_D", "R", "U_E"};
    push_rows(L, n, o, PC_P5_NPTS, names);
    return 1;
}

/* oneratio.smooth_scheme(A, B, C, n, t) -> {P = {P1..Pn}, Q = {Q1..Qn}, M} */
static int l_smooth_scheme(lua_State *L) {
    const char *fn = "oneratio.smooth_scheme";
    static const char *nm[3] = {"A", "B", "C"};
    double abc[3 * PC_MAXDIM];
    int d = pclb_points(L, fn, 1, 3, nm, abc);
    if (!lua_isinteger(L, 4) || lua_tointeger(L, 4) < 1 || lua_tointeger(L, 4) > 40)
        return pcl_argerror_full(L, fn, 4, 4, "n", "the smoothness order 1..40");
    int n = (int)lua_tointeger(L, 4);
    double t = pcl_checknum(L, fn, 5, "t");
    double *buf = lua_newuserdatauv(L, sizeof(double) * (size_t)(2 * n + 1) * (size_t)d, 0);
    int scratch = lua_gettop(L);
    double *p = buf, *q = buf + n * d, *m = q + n * d;
    int st = pc_oneratio_smooth_chain(d, abc, abc + d, abc + 2 * d, n, t, p, q, m);
    if (st != PC_OK) return scheme_error(L, fn, st, "A, B, C are collinear");
    lua_createtable(L, 0, 3);
    const char *side[2] = {"P", "Q"};
    for (int s2 = 0; s2 < 2; s2++) {
        lua_createtable(L, n, 0);
        for (int i = 0; i < n; i++) {
            pcl_pushpoint(L, d, (s2 ? q : p) + i * d);
            lua_rawseti(L, -2, i + 1);
        }
        lua_setfield(L, -2, side[s2]);
    }
    pcl_pushpoint(L, d, m);
    lua_setfield(L, -2, "M");
    lua_remove(L, scratch);
    return 1;
}

/* conic.focal_point(C, A, B, phi [, "ellipse"|"hyperbola"]) -> M, F, pa, pb */
static int l_focal_point(lua_State *L) {
    const char *fn = "conic.focal_point";
    static const char *nm[3] = {"C", "A", "B"};
    double p[3 * PC_MAXDIM], o[2 * PC_MAXDIM], pab[2];
    int d = pclb_points(L, fn, 1, 3, nm, p);
    double phi = pcl_checknum(L, fn, 4, "phi");
    const char *kind = luaL_optstring(L, 5, "ellipse");
    int hyp = !strcmp(kind, "hyperbola");
    if (!hyp && strcmp(kind, "ellipse")) return pcl_argerror_full(L, fn, 5, 5, "kind", "\"ellipse\" or \"hyperbola\"");
    int st = pc_conic_focal_point(d, p, p + d, p + 2 * d, hyp, phi, o, pab);
    if (st == PC_EDOMAIN)
        return pcl_error(L, "%s: CA and CB must be perpendicular semi-axes%s", fn, hyp ? "" : ", CA the major one (the foci on it)");
    if (st == PC_EPOLE) return pcl_error(L, "%s: phi = %s is an asymptote's direction (1 - e cos phi = 0)", fn, pcl_pushnum(L, phi));
    if (st != PC_OK) return scheme_error(L, fn, st, "a semi-axis is zero");
    pcl_pushpoint(L, d, o);
    pcl_pushpoint(L, d, o + d);
    lua_pushnumber(L, pab[0]);
    lua_pushnumber(L, pab[1]);
    return 4;
}

/* conic.ceva_scheme(A1, A2, A3, k, t) -> {M3, M, t3, r} */
static int l_ceva_scheme(lua_State *L) {
    const char *fn = "conic.ceva_scheme";
    static const char *nm[3] = {"A1", "A2", "A3"};
    double p[3 * PC_MAXDIM], o[2 * PC_MAXDIM], t3, r;
    int d = pclb_points(L, fn, 1, 3, nm, p);
    double k = pcl_checknum(L, fn, 4, "k"), t = pcl_checknum(L, fn, 5, "t");
    int st = pc_conic_ceva_scheme(d, p, p + d, p + 2 * d, k, t, o, &t3, &r);
    if (st == PC_EDOMAIN) return pcl_error(L, "%s: argument #4 (k) must not be 0", fn);
    if (st == PC_EPOLE) return pcl_error(L, "%s: the arc is at infinity at t = %s", fn, pcl_pushnum(L, t));
    if (st != PC_OK) return scheme_error(L, fn, st, "A1, A2, A3 are collinear");
    lua_createtable(L, 0, 4);
    pcl_pushpoint(L, d, o);
    lua_setfield(L, -2, "M3");
    pcl_pushpoint(L, d, o + d);
    lua_setfield(L, -2, "M");
    lua_pushnumber(L, t3);
    lua_setfield(L, -2, "t3");
    lua_pushnumber(L, r);
    lua_setfield(L, -2, "r");
    return 1;
}

/* conic.foci(C, A, B [, "ellipse"|"hyperbola"]) -> F1, F2, e, p */
static int l_foci(lua_State *L) {
    const char *fn = "conic.foci";
    static const char *nm[3] = {"C", "A", "B"};
    double pts[3 * PC_MAXDIM], f1[PC_MAXDIM], f2[PC_MAXDIM], e, p;
    int d = pclb_points(L, fn, 1, 3, nm, pts);
    const char *kind = luaL_optstring(L, 4, "ellipse");
    int hyp = !strcmp(kind, "hyperbola");
    if (!hyp && strcmp(kind, "ellipse"))
        return pcl_argerror_full(L, fn, 4, 4, "kind", "\"ellipse\" or \"hyperbola\"");
    int st = pc_conic_foci(d, pts, pts + d, pts + 2 * d, hyp, f1, f2, &e, &p);
    if (st == PC_EDOMAIN)
        return pcl_error(L, "%s: CA and CB must be the axes (perpendicular); for conjugate semi-diameters use c:conic()", fn);
    if (st == PC_ECOLLINEAR) return pcl_error(L, "%s: a semi-axis is zero (A or B coincides with C)", fn);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    pcl_pushpoint(L, d, f1);
    pcl_pushpoint(L, d, f2);
    lua_pushnumber(L, e);
    lua_pushnumber(L, p);
    return 4;
}

/* conic.cones_excluded(fP, fQ) -> {u, ...} */
static int l_cones_excluded(lua_State *L) {
    const char *fn = "conic.cones_excluded";
    double fp = pcl_checknum(L, fn, 1, "fP"), fq = pcl_checknum(L, fn, 2, "fQ"), u[5];
    int n, st = pc_cones_excluded(fp, fq, u, &n);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    lua_createtable(L, n, 0);
    for (int i = 0; i < n; i++) {
        lua_pushnumber(L, u[i]);
        lua_rawseti(L, -2, i + 1);
    }
    return 1;
}

/* conic.ceva_to_ed(k), conic.ed_to_ceva(k): the two readings of one arc (§5.7) */
static int conv(lua_State *L, const char *fn, int to_ed) {
    double k = pcl_checknum(L, fn, 1, "k"), r;
    int st = to_ed ? pc_ceva_to_ed(k, &r) : pc_ed_to_ceva(k, &r);
    if (st == PC_EDOMAIN)
        return pcl_error(L, to_ed ? "%s: argument #1 (k) must be a positive Ceva k, got %s"
                                  : "%s: argument #1 (k) must be an engineering discriminant in (0, 1), got %s",
                         fn, pcl_pushnum(L, k));
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    lua_pushnumber(L, r);
    return 1;
}
static int l_ceva_to_ed(lua_State *L) { return conv(L, "conic.ceva_to_ed", 1); }
static int l_ed_to_ceva(lua_State *L) { return conv(L, "conic.ed_to_ceva", 0); }

/* After pcl_open_konopatsky, with the module table on top. */
void pcl_open_konopatsky_schemes(lua_State *L) {
    lua_getfield(L, -1, "conic");
    lua_pushcfunction(L, l_ed_scheme);
    lua_setfield(L, -2, "ed_scheme");
    lua_pushcfunction(L, l_five_scheme);
    lua_setfield(L, -2, "five_scheme");
    lua_pushcfunction(L, l_ceva_to_ed);
    lua_setfield(L, -2, "ceva_to_ed");
    lua_pushcfunction(L, l_cones_excluded);
    lua_setfield(L, -2, "cones_excluded");
    lua_pushcfunction(L, l_foci);
    lua_setfield(L, -2, "foci");
    lua_pushcfunction(L, l_ceva_scheme);
    lua_setfield(L, -2, "ceva_scheme");
    lua_pushcfunction(L, l_focal_point);
    lua_setfield(L, -2, "focal_point");
    lua_pushcfunction(L, l_ed_to_ceva);
    lua_setfield(L, -2, "ed_to_ceva");
    lua_pop(L, 1);
    lua_getfield(L, -1, "oneratio");
    lua_pushcfunction(L, l_smooth_scheme);
    lua_setfield(L, -2, "smooth_scheme");
    lua_pop(L, 1);
}
