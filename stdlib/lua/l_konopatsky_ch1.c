/* Konopatsky's chapter 1 in Lua (books/konopatsky/konop_ch1.h), the table konopatsky:
 *   area_k(l1, l2, l3) -> k                          (1.2)
 *   area_theorem(A1, A2, A3, B1, B2, B3) -> {k, lambda, a, b, c, collinear}
 *   o_theorem({A1, ..., Am}, D1, D2) -> product, ratios, B   (1.4), B homogeneous points
 *   simplex_ratio({{p1, q1, r1}, ...}) -> det          S- and V-theorems
 *   meet_line_plane(A1, A2, P1, P2, P3) -> K, lambda, p, q   (§1.3.5 by the V-theorem)
 *   polar(C, A, B, rho, phi) -> M                     (2.117)/(2.118)
 *   rotate(C, A, B, phi) -> Q                         (2.138)
 *   moving_simplex(NA, NB, NC, gen) -> surface        Fig. 1.2 */
#include <math.h>
#include "pcl.h"
#include "pcl_curve.h"
#include "pcl_point.h"
#include "pcl_books.h"
#include "konop_ch1.h"

int pclb_point(lua_State *L, const char *fn, int arg, const char *what, int dim, int dim_arg,
               const char *dim_name, double *out) {
    pcl_value *v = pcl_tovalue(L, arg);
    if (!v) return pcl_argerror_full(L, fn, arg, arg, what, "a point");
    if (dim > 0 && v->n != dim && (dim_arg <= 0 || dim_arg == arg))
        return pcl_error(L, "%s: argument #%d (%s) must be %d-D, got %d-D", fn, arg, what, dim, v->n);
    if (dim > 0 && v->n != dim)
        return pcl_error(L, "%s: argument #%d (%s) is %d-D, but argument #%d (%s) is %d-D: dimensions cannot be mixed",
                         fn, arg, what, v->n, dim_arg, dim_name, dim);
    if (fabs(v->h[v->n] - 1) > PC_WEIGHT_TOL)
        return pcl_error(L, "%s: argument #%d (%s) must be a point (weight 1), got %s: the coefficients "
                         "of a point equation sum to 1 (membership condition); V() makes a vector", fn, arg, what,
                         pcl_shown(L, arg));
    for (int k = 0; k < v->n; k++) {
        out[k] = v->h[k];
        if (!isfinite(out[k]))
            return pcl_error(L, "%s: argument #%d (%s) has NaN or infinite coordinates", fn, arg, what);
    }
    return v->n;
}

int pclb_points(lua_State *L, const char *fn, int first, int count, const char *const *names,
                double *out) {
    int n = pclb_point(L, fn, first, names[0], 0, 0, NULL, out);
    for (int i = 1; i < count; i++) pclb_point(L, fn, first + i, names[i], n, first, names[0], out + n * i);
    return n;
}

static int k_area_k(lua_State *L) {
    const char *fn = "konopatsky.area_k";
    double l[3], k;
    static const char *nm[3] = {"l1", "l2", "l3"};
    for (int i = 0; i < 3; i++) l[i] = pcl_checknum(L, fn, i + 1, nm[i]);
    if (pc_k_area_k(l[0], l[1], l[2], &k) != PC_OK)
        return pcl_error(L, "%s: a lambda is -1 (its point is at infinity): k is undefined", fn);
    lua_pushnumber(L, k);
    return 1;
}

static int k_area_theorem(lua_State *L) {
    const char *fn = "konopatsky.area_theorem";
    static const char *nm[6] = {"A1", "A2", "A3", "B1", "B2", "B3"};
    double p[6 * PC_MAXDIM];
    int n = pclb_points(L, fn, 1, 6, nm, p);
    pc_k_areas o;
    int st = pc_k_area_theorem(n, p, p + 3 * n, &o);
    if (st == PC_ECOLLINEAR) return pcl_error(L, "%s: the triangle A1A2A3 is flat", fn);
    if (st == PC_ENOTCOLLINEAR)
        return pcl_error(L, "%s: each Bi must lie on its side line (B1 on A1A2, B2 on A2A3, B3 on A3A1)", fn);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    lua_createtable(L, 0, 6);
    lua_pushnumber(L, o.k);
    lua_setfield(L, -2, "k");
    lua_createtable(L, 3, 0);
    for (int i = 0; i < 3; i++) {
        lua_pushnumber(L, o.lambda[i]);
        lua_rawseti(L, -2, i + 1);
    }
    lua_setfield(L, -2, "lambda");
    static const char *abc[3] = {"a", "b", "c"};
    for (int i = 0; i < 3; i++) {
        lua_pushnumber(L, o.abc[i]);
        lua_setfield(L, -2, abc[i]);
    }
    lua_pushboolean(L, o.collinear);
    lua_setfield(L, -2, "collinear");
    return 1;
}

static int k_o_theorem(lua_State *L) {
    const char *fn = "konopatsky.o_theorem";
    if (!lua_istable(L, 1)) return pcl_argerror_full(L, fn, 1, 1, "polygon", "a list of at least 3 points");
    int m = (int)luaL_len(L, 1);
    if (m < 3 || m > 64) return pcl_argerror_full(L, fn, 1, 1, "polygon", "a list of 3 to 64 points");
    double d[2 * PC_MAXDIM];
    static const char *dn[2] = {"D1", "D2"};
    int n = pclb_points(L, fn, 2, 2, dn, d);
    double *poly = lua_newuserdatauv(L, sizeof(double) * (size_t)(m * n + m + m * (n + 1)), 0);
    double *ratios = poly + m * n, *b = ratios + m;
    int scratch = lua_gettop(L);
    for (int i = 0; i < m; i++) {
        lua_geti(L, 1, i + 1);
        pcl_value *v = pcl_tovalue(L, -1);
        if (!v || v->n != n || fabs(v->h[n] - 1) > 1e-9)
            return pcl_error(L, "%s: argument #1 (polygon) [%d] must be a %d-D point, got %s", fn, i + 1, n,
                             pcl_shown(L, lua_gettop(L)));
        for (int j = 0; j < n; j++) poly[n * i + j] = v->h[j] / v->h[n];
        lua_pop(L, 1);
    }
    double prod;
    int st = pc_k_o_theorem(n, m, poly, d, d + n, ratios, b, &prod);
    if (st == PC_EDOMAIN) return pcl_error(L, "%s: the line D1D2 passes through a vertex", fn);
    if (st == PC_ESKEW || st == PC_ESAME_LINE)
        return pcl_error(L, "%s: the line D1D2 must lie in the polygon's plane and be no side line", fn);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    lua_pushnumber(L, prod);
    lua_createtable(L, m, 0);
    for (int i = 0; i < m; i++) {
        lua_pushnumber(L, ratios[i]);
        lua_rawseti(L, -2, i + 1);
    }
    lua_createtable(L, m, 0);
    for (int i = 0; i < m; i++) {
        const double *h = b + (size_t)(n + 1) * i;
        if (h[n] == 0) pcl_pushvector(L, n, h);
        else pcl_pushpoint(L, n, h);
        lua_rawseti(L, -2, i + 1);
    }
    lua_remove(L, scratch);
    return 3;
}

static int k_simplex_ratio(lua_State *L) {
    const char *fn = "konopatsky.simplex_ratio";
    if (!lua_istable(L, 1)) return pcl_argerror_full(L, fn, 1, 1, "rows", "a list of k + 1 rows of barycentric parameters");
    int d = (int)luaL_len(L, 1);
    if (d < 2 || d > 9) return pcl_argerror_full(L, fn, 1, 1, "rows", "2 to 9 rows");
    double rows[81];
    for (int i = 0; i < d; i++) {
        lua_geti(L, 1, i + 1);
        if (!lua_istable(L, -1) || luaL_len(L, -1) != d)
            return pcl_error(L, "%s: argument #1 (rows) [%d] must be a list of %d numbers (a square matrix)", fn, i + 1, d);
        for (int j = 0; j < d; j++) {
            lua_geti(L, -1, j + 1);
            if (lua_type(L, -1) != LUA_TNUMBER)
                return pcl_error(L, "%s: argument #1 (rows) [%d][%d] must be a number, got %s", fn, i + 1, j + 1,
                                 pcl_shown(L, lua_gettop(L)));
            rows[d * i + j] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    double r;
    int st = pc_k_simplex_ratio(d - 1, rows, &r);
    if (st == PC_EDOMAIN) return pcl_error(L, "%s: each row's parameters must sum to 1 (the membership condition)", fn);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    lua_pushnumber(L, r);
    return 1;
}

static int k_meet_line_plane(lua_State *L) {
    const char *fn = "konopatsky.meet_line_plane";
    static const char *nm[5] = {"A1", "A2", "P1", "P2", "P3"};
    double p[5 * PC_MAXDIM], k[PC_MAXDIM + 1], lam, pq[2];
    int n = pclb_points(L, fn, 1, 5, nm, p);
    if (n < 3) return pcl_error(L, "%s: a line and a plane meet in 3-D or more, got %d-D points", fn, n);
    int st = pc_k_meet_line_plane(n, p, p + n, p + 2 * n, p + 3 * n, p + 4 * n, k, &lam, pq);
    switch (st) {
    case PC_OK:
        pcl_pushpoint(L, n, k);
        lua_pushnumber(L, lam);
        lua_pushnumber(L, pq[0]);
        lua_pushnumber(L, pq[1]);
        return 4;
    case PC_IMPROPER:      /* parallel: the common point at infinity, as meet() gives it */
        pcl_pushvector(L, n, k);
        lua_pushnumber(L, lam);
        return 2;
    case PC_ESAME_LINE: return pcl_error(L, "%s: the line A1A2 lies in the plane P1P2P3: no single meet", fn);
    case PC_ESKEW: return pcl_error(L, "%s: the line A1A2 and the plane P1P2P3 do not meet (they span more than 3-D)", fn);
    case PC_ECOINCIDENT: return pcl_error(L, "%s: A1 and A2 coincide: no line", fn);
    case PC_ECOLLINEAR: return pcl_error(L, "%s: P1, P2, P3 are collinear: no plane", fn);
    default: return pcl_statuserror(L, fn, st, NULL);
    }
}

static int polar_common(lua_State *L, const char *fn, int rotate) {
    static const char *nm[3] = {"C", "A", "B"};
    double p[3 * PC_MAXDIM], m[PC_MAXDIM];
    int n = pclb_points(L, fn, 1, 3, nm, p);
    double rho = rotate ? pc_dist(n, p, p + n) : pcl_checknum(L, fn, 4, "rho");
    double phi = pcl_checknum(L, fn, rotate ? 4 : 5, "phi");
    int st = pc_k_polar(n, p, p + n, p + 2 * n, rho, phi, m);
    if (st == PC_ECOLLINEAR) return pcl_error(L, "%s: C, A, B are collinear (or coincide): no plane, no angle", fn);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    pcl_pushpoint(L, n, m);
    return 1;
}

static int k_polar(lua_State *L) { return polar_common(L, "konopatsky.polar", 0); }
static int k_rotate(lua_State *L) { return polar_common(L, "konopatsky.rotate", 1); }

static int k_moving_simplex(lua_State *L) {
    const char *fn = "konopatsky.moving_simplex";
    static const char *nm[4] = {"NA", "NB", "NC", "gen"};
    pc_curve *c[4];
    for (int i = 0; i < 4; i++) {
        c[i] = pcl_tocurve(L, i + 1);
        if (!c[i]) return pcl_argerror_full(L, fn, i + 1, i + 1, nm[i], i < 3 ? "a curve (a guide)" : "a 2-D curve (p(v), q(v))");
    }
    int st;
    pc_surface *s = pc_k_moving_simplex(c[0], c[1], c[2], c[3], &st);
    if (!s && st == PC_EDIM)
        return pcl_error(L, "%s: the guides must have one dimension (%d-D, %d-D, %d-D) and the generator gen must be 2-D (its coordinates are p and q), got %d-D",
                         fn, c[0]->dim, c[1]->dim, c[2]->dim, c[3]->dim);
    if (!s && st == PC_EDOMAIN)
        return pcl_error(L, "%s: the guides must run over one domain of u (NA over [%s, %s])", fn,
                         pcl_pushnum(L, c[0]->t0), pcl_pushnum(L, c[0]->t1));
    if (!s) return pcl_statuserror(L, fn, st, NULL);
    pcl_pushsurface(L, s, fn);
    return 1;
}

void pcl_open_konopatsky_ch1(lua_State *L) {
    static const luaL_Reg fns[] = {
        {"area_k", k_area_k}, {"area_theorem", k_area_theorem}, {"o_theorem", k_o_theorem},
        {"simplex_ratio", k_simplex_ratio}, {"meet_line_plane", k_meet_line_plane},
        {"polar", k_polar}, {"rotate", k_rotate}, {"moving_simplex", k_moving_simplex},
        {NULL, NULL}};
    luaL_newlib(L, fns);
    lua_setfield(L, -2, "konopatsky");
}
