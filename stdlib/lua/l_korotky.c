/* Binding of Korotky's nature-like curves and conic surfaces (stdlib/books/korotky/ferguson.h,
 * elastic.h, conic_surface.h), in the table `korotky`:
 *   korotky.poly_spline(points [, {ends =, s0 =, s1 =}])      -> curve, coefficients
 *   korotky.ferguson(points, tangents, moduli)                 -> curve
 *   korotky.ferguson_lambda(points, {TA =, TE =, wA =, wE =, lambda =})  -> curve
 *   korotky.ferguson_tangents(points, tangents [, {wA =, wE =, start =}]) -> curve, moduli
 *   korotky.ferguson_substitution(points, tangents, wA, z1 [, "min"|"max"])
 *                                                              -> curve, moduli, quadratics
 *   korotky.elastic(points [, {ends =, pieces =}])             -> curve, energy (C2 spline)
 *   korotky.deviation(c1, c2 [, samples])  korotky.joint_jumps(c)  korotky.energy(c)
 *   korotky.conic_arc(U, tU, V, tV, T)                         -> curve, w, kind
 *   korotky.conic_sweep{U =, V =, T =, P =, Q =}               -> surface
 *   korotky.dome_rect(a0, b0, c0 [, origin])  korotky.dome_tri(A, B, C, h | D) -> surface
 *   korotky.graphical_slope(samples, x [, window])             -> slope, angle in degrees
 * A tangent is a slope tg(delta) (the direction (cos delta, sin delta), x growing) or a 2-D
 * vector.  Errors of the solvers name the knot (#1 is the first point). */
#include <math.h>
#include <string.h>
#include "pcl_curve.h"
#include "ferguson.h"
#include "elastic.h"
#include "conic_surface.h"
#include "graphdiff.h"

#define MAXPTS PC_FERGUSON_MAXN

void pcl_korotky_shells(lua_State *L);   /* the shells of 2015 (l_korotky_shells.c) */

/* The list of 2-D points at arg: n (>= 2, <= max) rows into p. */
static int read_points(lua_State *L, const char *fn, int arg, double *p, int max) {
    if (!lua_istable(L, arg)) return pcl_argerror_full(L, fn, arg, arg, "points", "a list of 2-D points");
    int n = (int)luaL_len(L, arg);
    if (n < 2 || n > max)
        return pcl_error(L, "%s: argument #%d (points) must hold 2 to %d points, got %d", fn, arg, max, n);
    for (int i = 1; i <= n; i++) {
        lua_geti(L, arg, i);
        pcl_value *v = pcl_tovalue(L, -1);
        if (!v || v->n != 2 || v->h[2] != 1)
            return pcl_error(L, "%s: argument #%d (points) [%d] must be a 2-D point, got %s", fn, arg,
                             i, pcl_shown(L, lua_gettop(L)));
        p[2 * i - 2] = v->h[0];
        p[2 * i - 1] = v->h[1];
        lua_pop(L, 1);
    }
    return n;
}

/* A tangent at the stack index idx: a slope or a 2-D vector, into t (2). */
static int read_tangent(lua_State *L, int idx, double *t) {
    if (lua_type(L, idx) == LUA_TNUMBER) {
        double s = lua_tonumber(L, idx);
        if (!isfinite(s)) return 0;
        double d = atan(s);
        t[0] = cos(d);
        t[1] = sin(d);
        return 1;
    }
    pcl_value *v = pcl_tovalue(L, idx);
    if (!v || v->n != 2 || v->h[2] != 0 || !isfinite(v->h[0]) || !isfinite(v->h[1])) return 0;
    t[0] = v->h[0];
    t[1] = v->h[1];
    return 1;
}

/* The list of n tangents at arg into T. */
static void read_tangents(lua_State *L, const char *fn, int arg, int n, double *T) {
    if (!lua_istable(L, arg)) {
        pcl_argerror_full(L, fn, arg, arg, "tangents", "a list of slopes or 2-D vectors");
        return;
    }
    int m = (int)luaL_len(L, arg);
    if (m != n)
        pcl_error(L, "%s: argument #%d (tangents) must hold one tangent per point (%d), got %d", fn,
                  arg, n, m);
    for (int i = 1; i <= n; i++) {
        lua_geti(L, arg, i);
        if (!read_tangent(L, -1, T + 2 * i - 2))
            pcl_error(L, "%s: argument #%d (tangents) [%d] must be a slope or a 2-D vector, got %s",
                      fn, arg, i, pcl_shown(L, lua_gettop(L)));
        lua_pop(L, 1);
    }
}

/* A list of exactly n numbers at the stack index idx (named what) into out. */
static void read_list(lua_State *L, const char *fn, int idx, const char *what, int n, double *out) {
    if (!lua_istable(L, idx))
        pcl_error(L, "%s: %s must be a list of %d numbers, got %s", fn, what, n, pcl_shown(L, idx));
    int m = (int)luaL_len(L, idx);
    if (m != n) pcl_error(L, "%s: %s must hold %d numbers, got %d", fn, what, n, m);
    for (int i = 1; i <= n; i++) {
        lua_geti(L, idx, i);
        if (lua_type(L, -1) != LUA_TNUMBER || !isfinite(lua_tonumber(L, -1)))
            pcl_error(L, "%s: %s [%d] must be a finite number, got %s", fn, what, i, pcl_shown(L, lua_gettop(L)));
        out[i - 1] = lua_tonumber(L, -1);
        lua_pop(L, 1);
    }
}

static void push_list(lua_State *L, int n, const double *v) {
    lua_createtable(L, n, 0);
    for (int i = 0; i < n; i++) {
        lua_pushnumber(L, v[i]);
        lua_rawseti(L, -2, i + 1);
    }
}

/* An optional number field of the options table at opts. */
static double opt_field(lua_State *L, const char *fn, int opts, const char *field, double dflt) {
    if (!opts) return dflt;
    lua_getfield(L, opts, field);
    double x = dflt;
    if (!lua_isnil(L, -1)) {
        if (lua_type(L, -1) != LUA_TNUMBER || !isfinite(lua_tonumber(L, -1)))
            pcl_error(L, "%s: option %s must be a finite number, got %s", fn, field, pcl_shown(L, lua_gettop(L)));
        x = lua_tonumber(L, -1);
    }
    lua_pop(L, 1);
    return x;
}

static int opt_table(lua_State *L, const char *fn, int arg) {
    if (lua_isnoneornil(L, arg)) return 0;
    if (!lua_istable(L, arg)) return pcl_argerror_full(L, fn, arg, arg, "options", "a table");
    return arg;
}

/* A solver's failure at knot bad (0-based). */
static int knot_error(lua_State *L, const char *fn, int st, int bad) {
    const char *why = st == PC_EDOMAIN      ? "no positive derivative moduli"
                      : st == PC_ENOCONVERGE ? "Newton's method does not converge"
                      : st == PC_ESINGULAR   ? "the system is singular"
                      : st == PC_EZERO       ? "the tangent is the zero vector"
                      : st == PC_ECOINCIDENT ? "the point repeats the one before"
                                             : pc_strerror(st);
    if (bad >= 0) return pcl_error(L, "%s: %s at knot #%d", fn, why, bad + 1);
    return pcl_statuserror(L, fn, st, NULL);
}

static void push_new_curve(lua_State *L, const char *fn, pc_curve *c, int st, const char *kind) {
    if (!c) pcl_statuserror(L, fn, st, NULL);
    pcl_pushcurve(L, c, kind);
}

/* ---- polynomial spline -------------------------------------------------------------------- */

static int l_poly_spline(lua_State *L) {
    const char *fn = "korotky.poly_spline";
    double p[2 * MAXPTS], x[MAXPTS], y[MAXPTS], coef[4 * MAXPTS];
    int n = read_points(L, fn, 1, p, MAXPTS), opts = opt_table(L, fn, 2);
    for (int i = 0; i < n; i++) x[i] = p[2 * i], y[i] = p[2 * i + 1];
    pc_end_kind ends = PC_END_NATURAL;
    if (opts && lua_getfield(L, opts, "ends") != LUA_TNIL) {
        const char *e = lua_tostring(L, -1);
        if (lua_type(L, -1) == LUA_TSTRING && !strcmp(e, "clamped")) ends = PC_END_CLAMPED;
        else if (!(lua_type(L, -1) == LUA_TSTRING && !strcmp(e, "natural")))
            return pcl_error(L, "%s: option ends must be \"natural\" or \"clamped\", got %s", fn,
                             pcl_shown(L, lua_gettop(L)));
    }
    double s0 = 0, s1 = 0;
    if (ends == PC_END_CLAMPED) {
        lua_getfield(L, opts, "s0");
        lua_getfield(L, opts, "s1");
        if (lua_type(L, -2) != LUA_TNUMBER || lua_type(L, -1) != LUA_TNUMBER)
            return pcl_error(L, "%s: clamped ends need the end slopes s0 and s1 (numbers)", fn);
        s0 = lua_tonumber(L, -2);
        s1 = lua_tonumber(L, -1);
    }
    int bad = -1, st = pc_poly_spline(n, x, y, ends, s0, s1, coef, &bad);
    if (st == PC_EDOMAIN)
        return pcl_error(L, "%s: argument #1 (points) [%d] must lie right of the point before (x must increase)",
                         fn, bad + 1);
    if (st != PC_OK) return knot_error(L, fn, st, bad);
    pc_curve *c = pc_poly_spline_curve(n, x, coef, &st);
    push_new_curve(L, fn, c, st, "korotky.poly_spline");
    lua_createtable(L, n - 1, 0);
    for (int i = 0; i < n - 1; i++) {
        push_list(L, 4, coef + 4 * i);
        lua_rawseti(L, -2, i + 1);
    }
    return 2;
}

/* ---- Ferguson splines --------------------------------------------------------------------- */

static int l_ferguson(lua_State *L) {
    const char *fn = "korotky.ferguson";
    double p[2 * MAXPTS], T[2 * MAXPTS], mags[2 * MAXPTS];
    int n = read_points(L, fn, 1, p, MAXPTS);
    read_tangents(L, fn, 2, n, T);
    if (!lua_istable(L, 3)) return pcl_argerror_full(L, fn, 3, 3, "moduli", "a list of numbers");
    read_list(L, fn, 3, "argument #3 (moduli)", 2 * n - 2, mags);
    int st;
    pc_curve *c = pc_ferguson_curve(n, p, T, mags, &st);
    if (!c) return pcl_statuserror(L, fn, st, "argument #2 (tangents)");
    pcl_pushcurve(L, c, "korotky.ferguson");
    return 1;
}

static int l_ferguson_lambda(lua_State *L) {
    const char *fn = "korotky.ferguson_lambda";
    double p[2 * MAXPTS], lam[MAXPTS], dout[2 * MAXPTS], din[2 * MAXPTS], TA[2], TE[2];
    int n = read_points(L, fn, 1, p, MAXPTS);
    if (!lua_istable(L, 2)) return pcl_argerror_full(L, fn, 2, 2, "options", "a table {TA =, TE =, lambda =}");
    lua_getfield(L, 2, "TA");
    if (!read_tangent(L, -1, TA))
        return pcl_error(L, "%s: option TA (the tangent at the first point) must be a slope or a 2-D vector, got %s",
                         fn, pcl_shown(L, lua_gettop(L)));
    lua_getfield(L, 2, "TE");
    if (!read_tangent(L, -1, TE))
        return pcl_error(L, "%s: option TE (the tangent at the last point) must be a slope or a 2-D vector, got %s",
                         fn, pcl_shown(L, lua_gettop(L)));
    double lA = hypot(TA[0], TA[1]), lE = hypot(TE[0], TE[1]);
    if (!(lA > 0) || !(lE > 0)) return pcl_error(L, "%s: the end tangents must not be zero vectors", fn);
    double wA = opt_field(L, fn, 2, "wA", 1), wE = opt_field(L, fn, 2, "wE", 1);
    for (int k = 0; k < 2; k++) TA[k] *= wA / lA, TE[k] *= wE / lE;
    lua_getfield(L, 2, "lambda");
    if (n > 2) read_list(L, fn, lua_gettop(L), "option lambda", n - 2, lam);
    int bad = -1, st = pc_ferguson_lambda(2, n, p, TA, TE, lam, dout, din, &bad);
    if (st == PC_EDOMAIN)
        return pcl_error(L, "%s: option lambda [%d] (at knot #%d) must be positive", fn, bad, bad + 1);
    if (st != PC_OK) return knot_error(L, fn, st, bad);
    pc_curve *c = pc_curve_hermite(2, n, p, dout, din, NULL, 0, &st);
    push_new_curve(L, fn, c, st, "korotky.ferguson_lambda");
    return 1;
}

static int l_ferguson_tangents(lua_State *L) {
    const char *fn = "korotky.ferguson_tangents";
    double p[2 * MAXPTS], T[2 * MAXPTS], mags[2 * MAXPTS];
    int n = read_points(L, fn, 1, p, MAXPTS);
    read_tangents(L, fn, 2, n, T);
    int opts = opt_table(L, fn, 3), start = 0;
    mags[0] = opt_field(L, fn, opts, "wA", 1);
    mags[2 * n - 3] = opt_field(L, fn, opts, "wE", 1);
    if (opts && lua_getfield(L, opts, "start") != LUA_TNIL) {
        read_list(L, fn, lua_gettop(L), "option start", 2 * n - 4, mags + 1);
        start = 1;
    }
    int bad = -1, st = pc_ferguson_tangents(n, p, T, mags, start, &bad);
    if (st != PC_OK) return knot_error(L, fn, st, bad);
    pc_curve *c = pc_ferguson_curve(n, p, T, mags, &st);
    push_new_curve(L, fn, c, st, "korotky.ferguson");
    push_list(L, 2 * n - 2, mags);
    return 2;
}

static int l_ferguson_substitution(lua_State *L) {
    const char *fn = "korotky.ferguson_substitution";
    double p[2 * MAXPTS], T[2 * MAXPTS], mags[2 * MAXPTS], quad[3 * MAXPTS];
    int n = read_points(L, fn, 1, p, MAXPTS);
    read_tangents(L, fn, 2, n, T);
    mags[0] = pcl_checknum(L, fn, 3, "wA");
    mags[1] = pcl_checknum(L, fn, 4, "z1");
    if (!(mags[1] > 0)) return pcl_argerror_full(L, fn, 4, 4, "z1", "a positive number");
    int root_max = 0;
    if (!lua_isnoneornil(L, 5)) {
        const char *r = lua_tostring(L, 5);
        if (lua_type(L, 5) == LUA_TSTRING && !strcmp(r, "max")) root_max = 1;
        else if (!(lua_type(L, 5) == LUA_TSTRING && !strcmp(r, "min")))
            return pcl_argerror_full(L, fn, 5, 5, "root", "\"min\" or \"max\"");
    }
    int bad = -1, st = pc_ferguson_substitution(n, p, T, mags, root_max, quad, &bad);
    if (st != PC_OK) return knot_error(L, fn, st, bad);
    pc_curve *c = pc_ferguson_curve(n, p, T, mags, &st);
    push_new_curve(L, fn, c, st, "korotky.ferguson");
    push_list(L, 2 * n - 2, mags);
    lua_createtable(L, n - 2, 0);
    for (int i = 0; i < n - 2; i++) {
        push_list(L, 3, quad + 3 * i);
        lua_rawseti(L, -2, i + 1);
    }
    return 3;
}

/* ---- the elastic reference and the measures ------------------------------------------------ */

static int l_elastic(lua_State *L) {
    const char *fn = "korotky.elastic";
    double p[2 * PC_ELASTIC_MAXN];
    int n = read_points(L, fn, 1, p, PC_ELASTIC_MAXN), opts = opt_table(L, fn, 2);
    int pieces = 0;   /* as many as the points allow (4 up to 10 points) */
    if (opts && lua_getfield(L, opts, "pieces") != LUA_TNIL) {
        double k = lua_tonumber(L, -1);
        if (lua_type(L, -1) != LUA_TNUMBER || !(k >= 1 && k <= 4 && k == (int)k))
            return pcl_error(L, "%s: option pieces must be 1 to 4, got %s", fn, pcl_shown(L, lua_gettop(L)));
        pieces = (int)k;
        lua_pop(L, 1);
    }
    double angles[2], *ends = NULL;
    if (opts && lua_getfield(L, opts, "ends") != LUA_TNIL) {
        int e = lua_gettop(L);
        double t[2];
        if (!lua_istable(L, e) || luaL_len(L, e) != 2)
            return pcl_error(L, "%s: option ends must be {tangent at the first point, tangent at the last}, got %s",
                             fn, pcl_shown(L, e));
        for (int i = 0; i < 2; i++) {
            lua_geti(L, e, i + 1);
            if (!read_tangent(L, -1, t) || !(hypot(t[0], t[1]) > 0))
                return pcl_error(L, "%s: option ends [%d] must be a slope or a non-zero 2-D vector, got %s",
                                 fn, i + 1, pcl_shown(L, lua_gettop(L)));
            angles[i] = atan2(t[1], t[0]);
            lua_pop(L, 1);
        }
        ends = angles;
    }
    double E;
    int st;
    pc_curve *c = pc_elastic(n, p, pieces, ends, &E, &st);
    if (!c && st == PC_ECOINCIDENT) return pcl_error(L, "%s: two consecutive points coincide", fn);
    if (!c && st == PC_EDIM)
        return pcl_error(L, "%s: %d points with %d pieces per span are too many unknowns; use fewer pieces",
                         fn, n, pieces);
    push_new_curve(L, fn, c, st, "korotky.elastic");
    lua_pushnumber(L, E);
    return 2;
}

static pc_curve *check_curve(lua_State *L, const char *fn, int arg, const char *what) {
    pc_curve *c = pcl_tocurve(L, arg);
    if (!c) pcl_argerror_full(L, fn, arg, arg, what, "a curve");
    return c;
}

static int l_deviation(lua_State *L) {
    const char *fn = "korotky.deviation";
    pc_curve *a = check_curve(L, fn, 1, "model"), *b = check_curve(L, fn, 2, "reference");
    double s = pcl_optnum(L, fn, 3, "samples", 64);
    if (!(s >= 8 && s <= 4096)) return pcl_argerror_full(L, fn, 3, 3, "samples", "8 to 4096");
    if (a->dim != b->dim)
        return pcl_error(L, "%s: argument #2 (reference) is %d-D, but argument #1 is %d-D (mixed dimensions)",
                         fn, b->dim, a->dim);
    pcl_callback_state(L);
    double d;
    int st = pc_curve_hausdorff(a, b, (int)s, &d);
    if (st != PC_OK) return pcl_raise_status(L, fn, st);
    lua_pushnumber(L, d);
    return 1;
}

static int l_joint_jumps(lua_State *L) {
    const char *fn = "korotky.joint_jumps";
    pc_curve *c = check_curve(L, fn, 1, "curve");
    double dk, da;
    int at;
    int st = pc_curve_joint_jumps(c, &dk, &da, &at);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, "at a joint");
    lua_pushnumber(L, dk);
    lua_pushnumber(L, da);
    lua_pushinteger(L, at + 1);
    return 3;
}

static int l_energy(lua_State *L) {
    const char *fn = "korotky.energy";
    pc_curve *c = check_curve(L, fn, 1, "curve");
    pcl_callback_state(L);
    double E;
    int st = pc_curve_bending_energy(c, &E);
    if (st != PC_OK) return pcl_raise_status(L, fn, st);
    lua_pushnumber(L, E);
    return 1;
}

/* Graphical differentiation: the slope at x of a curve known by samples (2-D points, x
 * increasing), the way the article measured the ruler's slopes (Tables A2-A5). */
static int l_graphical_slope(lua_State *L) {
    const char *fn = "korotky.graphical_slope";
    if (!lua_istable(L, 1)) return pcl_argerror_full(L, fn, 1, 1, "samples", "a list of 2-D points");
    int n = (int)luaL_len(L, 1);
    if (n < 3) return pcl_error(L, "%s: argument #1 (samples) must hold at least 3 points, got %d", fn, n);
    double x = pcl_checknum(L, fn, 2, "x");
    double wn = pcl_optnum(L, fn, 3, "window", n >= 7 ? 7 : n % 2 ? n : n - 1);
    if (!(wn >= 3 && wn <= n && wn == (int)wn))
        return pcl_error(L, "%s: argument #3 (window) must be an integer 3 to %d, got %s", fn, n, pcl_pushnum(L, wn));
    double *xy = lua_newuserdatauv(L, sizeof(double) * 2 * (size_t)n, 0);
    for (int i = 1; i <= n; i++) {
        lua_geti(L, 1, i);
        pcl_value *v = pcl_tovalue(L, -1);
        if (!v || v->n != 2 || v->h[2] != 1)
            return pcl_error(L, "%s: argument #1 (samples) [%d] must be a 2-D point, got %s", fn, i,
                             pcl_shown(L, lua_gettop(L)));
        xy[2 * i - 2] = v->h[0];
        xy[2 * i - 1] = v->h[1];
        lua_pop(L, 1);
        if (i > 1 && !(xy[2 * i - 2] > xy[2 * i - 4]))
            return pcl_error(L, "%s: argument #1 (samples) [%d] must lie right of the sample before (x must increase)",
                             fn, i);
    }
    double m;
    int st = pc_graphical_slope(n, xy, x, (int)wn, &m);
    if (st == PC_EDOMAIN)
        return pcl_error(L, "%s: argument #2 (x) must lie within the samples [%s, %s], got %s", fn,
                         pcl_pushnum(L, xy[0]), pcl_pushnum(L, xy[2 * n - 2]), pcl_pushnum(L, x));
    if (st != PC_OK) return pcl_statuserror(L, fn, st, "argument #1 (samples)");
    lua_pushnumber(L, m);
    lua_pushnumber(L, atan(m) * 180 / M_PI);
    return 2;
}

/* ---- conics and conic surfaces ------------------------------------------------------------ */

static int l_conic_arc(lua_State *L) {
    const char *fn = "korotky.conic_arc";
    double U[PC_MAXDIM], V[PC_MAXDIM], T[PC_MAXDIM], tU[PC_MAXDIM], tV[PC_MAXDIM];
    int d = pcl_checkloc(L, 1, "U", 0, 0, U);
    pcl_checkvec(L, 2, "tangent at U", d, 1, tU);
    pcl_checkloc(L, 3, "V", d, 1, V);
    pcl_checkvec(L, 4, "tangent at V", d, 1, tV);
    pcl_checkloc(L, 5, "T", d, 1, T);
    if (d < 2) return pcl_error(L, "%s: the points must be 2-D or more", fn);
    double w;
    int st;
    pc_curve *c = pc_conic_arc(d, U, tU, V, tV, T, &w, &st);
    if (!c) {
        const char *why = st == PC_ESKEW      ? "the tangents must lie in the plane of U, V and T"
                          : st == PC_EDOMAIN  ? "T must lie between the tangent lines, on an arc from U to V that stays finite"
                          : st == PC_ECOINCIDENT ? "U and V coincide"
                          : st == PC_EZERO    ? "a tangent is the zero vector"
                                              : pc_strerror(st);
        return pcl_error(L, "%s: %s", fn, why);
    }
    pcl_pushcurve(L, c, "korotky.conic_arc");
    lua_pushnumber(L, w);
    lua_pushstring(L, pc_conic_kind(w));
    return 3;
}

static int l_conic_sweep(lua_State *L) {
    const char *fn = "korotky.conic_sweep";
    if (!lua_istable(L, 1)) return pcl_argerror_full(L, fn, 1, 1, "guides", "a table {U =, V =, T =, P =, Q =}");
    static const char *names[5] = {"U", "V", "T", "P", "Q"};
    pc_curve *c[5];
    for (int i = 0; i < 5; i++) {
        lua_getfield(L, 1, names[i]);
        c[i] = pcl_tocurve(L, -1);
        if (!c[i]) return pcl_error(L, "%s: field %s must be a 3-D curve, got %s", fn, names[i], pcl_shown(L, lua_gettop(L)));
        if (c[i]->dim != 3)
            return pcl_error(L, "%s: field %s must be a 3-D curve, got a %d-D one", fn, names[i], c[i]->dim);
    }
    int st;
    double u = 0;
    pc_surface *s = pc_surface_conic_sweep(c[0], c[1], c[2], c[3], c[4], &u, &st);
    if (!s && (st == PC_EDOMAIN || st == PC_ESKEW || st == PC_ECOINCIDENT || st == PC_EZERO))
        return pcl_error(L, "%s: no conic through U, V, T with the tangents towards P and Q at u = %s (%s)",
                         fn, pcl_pushnum(L, u),
                         st == PC_EDOMAIN ? "T must lie between the tangent lines" : pc_strerror(st));
    if (!s) return pcl_statuserror(L, fn, st, NULL);
    pcl_pushsurface(L, s, "korotky.conic_sweep");
    return 1;
}

static int l_dome_rect(lua_State *L) {
    const char *fn = "korotky.dome_rect";
    double a = pcl_checknum(L, fn, 1, "a0"), b = pcl_checknum(L, fn, 2, "b0"), c = pcl_checknum(L, fn, 3, "c0");
    if (!(a > 0)) return pcl_argerror_full(L, fn, 1, 1, "a0", "a positive number");
    if (!(b > 0)) return pcl_argerror_full(L, fn, 2, 2, "b0", "a positive number");
    if (!(c > 0)) return pcl_argerror_full(L, fn, 3, 3, "c0", "a positive number");
    double o[3], *origin = NULL;
    if (!lua_isnoneornil(L, 4)) {
        pcl_checkloc(L, 4, "origin", 3, 4, o);
        origin = o;
    }
    int st;
    pc_surface *s = pc_surface_dome_rect(a, b, c, origin, &st);
    if (!s) return pcl_statuserror(L, fn, st, NULL);
    pcl_pushsurface(L, s, "korotky.dome_rect");
    return 1;
}

/* A corner of the triangle: a 2-D point (z = 0) or a 3-D one. */
static void corner(lua_State *L, const char *fn, int arg, const char *what, double *out) {
    pcl_value *v = pcl_tovalue(L, arg);
    if (!v || (v->n != 2 && v->n != 3)) {
        pcl_argerror_full(L, fn, arg, arg, what, "a 2-D or 3-D point");
        return;
    }
    out[2] = 0;
    pcl_checkloc(L, arg, what, v->n, arg, out);
}

static int l_dome_tri(lua_State *L) {
    const char *fn = "korotky.dome_tri";
    double A[3], B[3], C[3], h;
    corner(L, fn, 1, "A", A);
    corner(L, fn, 2, "B", B);
    corner(L, fn, 3, "C", C);
    if (lua_type(L, 4) == LUA_TNUMBER) {
        h = pcl_checknum(L, fn, 4, "height");
        if (!(h > 0)) return pcl_argerror_full(L, fn, 4, 4, "height", "a positive number");
    } else {
        double D[3];
        pcl_value *v = pcl_tovalue(L, 4);
        if (!v || v->n != 3) return pcl_argerror_full(L, fn, 4, 4, "height", "a positive number or the 3-D apex D");
        pcl_checkloc(L, 4, "apex", 3, 4, D);
        int st = pc_dome_tri_height_through(A, B, C, D, &h);
        if (st == PC_EDOMAIN)
            return pcl_error(L, "%s: argument #4 (apex) must stand above the inside of the triangle, got %s",
                             fn, pcl_shown(L, 4));
        if (st != PC_OK) return pcl_statuserror(L, fn, st, "the triangle");
    }
    int st;
    pc_surface *s = pc_surface_dome_tri(A, B, C, h, &st);
    if (!s && st == PC_ECOLLINEAR) return pcl_error(L, "%s: the triangle ABC is flat in plan", fn);
    if (!s) return pcl_statuserror(L, fn, st, NULL);
    pcl_pushsurface(L, s, "korotky.dome_tri");
    return 1;
}

void pcl_open_korotky(lua_State *L) {
    static const luaL_Reg fns[] = {
        {"poly_spline", l_poly_spline},
        {"ferguson", l_ferguson},
        {"ferguson_lambda", l_ferguson_lambda},
        {"ferguson_tangents", l_ferguson_tangents},
        {"ferguson_substitution", l_ferguson_substitution},
        {"elastic", l_elastic},
        {"deviation", l_deviation},
        {"joint_jumps", l_joint_jumps},
        {"energy", l_energy},
        {"conic_arc", l_conic_arc},
        {"conic_sweep", l_conic_sweep},
        {"dome_rect", l_dome_rect},
        {"dome_tri", l_dome_tri},
        {"graphical_slope", l_graphical_slope},
        {NULL, NULL}};
    luaL_newlib(L, fns);
    pcl_korotky_shells(L);
    lua_setfield(L, -2, "korotky");
}
