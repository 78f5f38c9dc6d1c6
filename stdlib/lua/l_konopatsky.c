/* Binding of Konopatsky's curves (stdlib/books/konopatsky/conic.h, konop_curves.h, oneratio.h,
 * konop_interp.h, optimize.h): the tables conic, oneratio, interp and approx.  Every curve is
 * the one curve userdata (pcl_pushcurve).  Argument checks only; the constructions are in the
 * core.  Guide: docs/konopatsky.md. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "pcl_curve.h"
#include "pcl_expr.h"
#include "pcl_point.h"
#include "conic.h"
#include "konop_curves.h"
#include "oneratio.h"
#include "konop_interp.h"
#include "approx.h"

/* ---- argument checks with the full name ("conic.ed") ----------------------------------------- */

static int weight_ok(const pcl_value *v) { return fabs(v->h[v->n] - 1) <= PC_WEIGHT_TOL; }

/* The point at arg into out; dim > 0 demands that dimension (of argument dim_arg). */
static int pt(lua_State *L, const char *fn, int arg, const char *what, int dim, int dim_arg,
              double *out) {
    pcl_value *v = pcl_tovalue(L, arg);
    if (!v) return pcl_argerror_full(L, fn, arg, arg, what, "a point");
    if (dim > 0 && v->n != dim)
        pcl_error(L, "%s: argument #%d (%s) is %d-D, but argument #%d is %d-D (mixed dimensions)",
                  fn, arg, what, v->n, dim_arg, dim);
    if (!weight_ok(v))
        pcl_error(L, "%s: argument #%d (%s) must be a point (weight 1), got %s: the coefficients "
                  "of a point equation sum to 1 (membership condition)", fn, arg, what,
                  pcl_shown(L, arg));
    for (int k = 0; k < v->n; k++) {
        out[k] = v->h[k];
        if (!isfinite(out[k]))
            pcl_error(L, "%s: argument #%d (%s) has NaN or infinite coordinates", fn, arg, what);
    }
    return v->n;
}

/* Field `name` of the options table at tbl as a point (dim as above, 0: any). */
static int fpt(lua_State *L, const char *fn, int tbl, const char *name, int dim, double *out) {
    lua_getfield(L, tbl, name);
    pcl_value *v = pcl_tovalue(L, -1);
    if (!v) pcl_error(L, "%s: field %s must be a point, got %s", fn, name, pcl_shown(L, -1));
    if (dim > 0 && v->n != dim)
        pcl_error(L, "%s: field %s is %d-D, but the other points are %d-D (mixed dimensions)",
                  fn, name, v->n, dim);
    if (!weight_ok(v))
        pcl_error(L, "%s: field %s must be a point (weight 1), got %s", fn, name, pcl_shown(L, -1));
    for (int k = 0; k < v->n; k++) out[k] = v->h[k];
    int n = v->n;
    lua_pop(L, 1);
    return n;
}

/* Field `name` as a finite number; dflt when nil (NAN: required). */
static double fnum(lua_State *L, const char *fn, int tbl, const char *name, double dflt) {
    lua_getfield(L, tbl, name);
    if (lua_isnil(L, -1) && !isnan(dflt)) {
        lua_pop(L, 1);
        return dflt;
    }
    int isnum;
    double x = lua_tonumberx(L, -1, &isnum);
    if (!isnum || !isfinite(x))
        pcl_error(L, "%s: field %s must be a finite number, got %s", fn, name, pcl_shown(L, -1));
    lua_pop(L, 1);
    return x;
}

static void checktable(lua_State *L, const char *fn, int arg, const char *what) {
    if (!lua_istable(L, arg)) pcl_argerror_full(L, fn, arg, arg, what, "a table");
}

/* opts.range = {t0, t1}, or NaN NaN */
static void frange(lua_State *L, const char *fn, int tbl, double *t0, double *t1) {
    *t0 = *t1 = NAN;
    if (lua_getfield(L, tbl, "range") == LUA_TNIL) {
        lua_pop(L, 1);
        return;
    }
    if (!lua_istable(L, -1) || luaL_len(L, -1) != 2)
        pcl_error(L, "%s: field range must be a list {t0, t1}, got %s", fn, pcl_shown(L, -1));
    lua_geti(L, -1, 1);
    lua_geti(L, -2, 2);
    int i0, i1;
    *t0 = lua_tonumberx(L, -2, &i0), *t1 = lua_tonumberx(L, -1, &i1);
    if (!i0 || !i1 || !isfinite(*t0) || !isfinite(*t1) || !(*t1 > *t0))
        pcl_error(L, "%s: field range must be two finite numbers t0 < t1", fn);
    lua_pop(L, 3);
}

/* push the curve, or raise the core status (a kept Lua error first) */
static int push(lua_State *L, pc_curve *c, int st, const char *fn) {
    if (!c) return pcl_raise_status(L, fn, st);
    pcl_pushcurve(L, c, fn);
    return 1;
}

static int statuscheck(lua_State *L, const char *fn, int st) {
    if (st) pcl_raise_status(L, fn, st);
    return 0;
}

/* The list of points at arg (Cartesian rows into a scratch userdata left on the stack). */
static double *ptlist(lua_State *L, const char *fn, int arg, const char *what, int min, int max,
                      int *count, int *dim) {
    if (!lua_istable(L, arg)) {
        lua_pushfstring(L, "a list of at least %d points", min);
        pcl_argerror_full(L, fn, arg, arg, what, lua_tostring(L, -1));
    }
    int m = (int)luaL_len(L, arg);
    if (m < min || m > max)
        pcl_error(L, "%s: argument #%d (%s) must hold %d to %d points, got %d", fn, arg, what,
                  min, max, m);
    double *p = NULL;
    int d = 0;
    for (int i = 1; i <= m; i++) {
        lua_geti(L, arg, i);
        pcl_value *v = pcl_tovalue(L, -1);
        if (!v || !weight_ok(v))
            pcl_error(L, "%s: argument #%d (%s) item [%d] must be a point, got %s", fn, arg, what,
                      i, pcl_shown(L, -1));
        if (i == 1) {
            d = v->n;
            p = lua_newuserdatauv(L, sizeof(double) * (size_t)(m * d), 0);
            lua_insert(L, -2);
        } else if (v->n != d) {
            pcl_error(L, "%s: argument #%d (%s) item [%d] is %d-D, but item [1] is %d-D "
                      "(mixed dimensions)", fn, arg, what, i, v->n, d);
        }
        for (int k = 0; k < d; k++) {
            p[(i - 1) * d + k] = v->h[k];
            if (!isfinite(v->h[k]))
                pcl_error(L, "%s: argument #%d (%s) item [%d] has NaN or infinite coordinates",
                          fn, arg, what, i);
        }
        lua_pop(L, 1);
    }
    *count = m;
    *dim = d;
    return p;
}

static double *numlist(lua_State *L, const char *fn, int arg, const char *what, int n) {
    if (!lua_istable(L, arg) || (int)luaL_len(L, arg) != n) {
        lua_pushfstring(L, "a list of %d numbers", n);
        pcl_argerror_full(L, fn, arg, arg, what, lua_tostring(L, -1));
    }
    double *x = lua_newuserdatauv(L, sizeof(double) * (size_t)(n ? n : 1), 0);
    for (int i = 0; i < n; i++) {
        lua_geti(L, arg, i + 1);
        int isnum;
        x[i] = lua_tonumberx(L, -1, &isnum);
        if (!isnum || !isfinite(x[i]))
            pcl_error(L, "%s: argument #%d (%s) item [%d] must be a finite number, got %s", fn,
                      arg, what, i + 1, pcl_shown(L, -1));
        lua_pop(L, 1);
    }
    return x;
}

static void pushnums(lua_State *L, int n, const double *x) {
    lua_createtable(L, n, 0);
    for (int i = 0; i < n; i++) {
        lua_pushnumber(L, x[i]);
        lua_rawseti(L, -2, i + 1);
    }
}

/* ---- Lua functions called by the core ------------------------------------------------------ */

typedef struct { int ref[4]; int nref; const char *fname; } luaref;   /* fname: for messages */

static void luaref_free(void *ud) {
    luaref *r = ud;
    lua_State *L = pcl_current_state();
    if (L)
        for (int i = 0; i < r->nref; i++) luaL_unref(L, LUA_REGISTRYINDEX, r->ref[i]);
    free(r);
}

/* call function r->ref[which] with x; a number, or NaN with the error kept (located at the
 * user's line and naming the function that called it, as every message is) */
static double call1(const luaref *r, int which, double x) {
    lua_State *L = pcl_current_state();
    lua_rawgeti(L, LUA_REGISTRYINDEX, r->ref[which]);
    lua_pushnumber(L, x);
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
        pcl_callback_failed(L);
        return NAN;
    }
    int isnum;
    double y = lua_tonumberx(L, -1, &isnum);
    if (!isnum) {
        const char *got = luaL_typename(L, -1);
        pcl_pushwhere(L);
        lua_pushfstring(L, "%s: the function must return a number, got %s", r->fname, got);
        lua_concat(L, 2);
        pcl_callback_failed(L);
        lua_pop(L, 1);
        return NAN;
    }
    lua_pop(L, 1);
    return y;
}

static double scalar_cb(double x, void *ud) { return call1(ud, 0, x); }
static double blend_cb(void *ud, double v) { return call1(ud, 0, v); }
static double real_cb(void *ud, int which, double t) {
    luaref *r = ud;
    return which < r->nref ? call1(r, which, t) : NAN;
}

static int callable(lua_State *L, int idx) {
    if (lua_isfunction(L, idx)) return 1;
    if (luaL_getmetafield(L, idx, "__call") == LUA_TNIL) return 0;
    lua_pop(L, 1);
    return 1;
}

static luaref *newref(lua_State *L, const char *fname, int n, const int *idx) {
    luaref *r = malloc(sizeof *r);
    if (!r) pcl_error(L, "%s: out of memory", fname);
    r->nref = n;
    r->fname = fname;   /* a static string */
    for (int i = 0; i < n; i++) {
        lua_pushvalue(L, idx[i]);
        r->ref[i] = luaL_ref(L, LUA_REGISTRYINDEX);
    }
    return r;
}

/* ==== conic ================================================================================= */

static int c_ed(lua_State *L) {
    const char *fn = "conic.ed";
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM];
    int d = pt(L, fn, 1, "A", 0, 0, A);
    pt(L, fn, 2, "B", d, 1, B);
    pt(L, fn, 3, "C", d, 1, C);
    double k = pcl_checknum(L, fn, 4, "k");
    if (k == 0) pcl_argerror_full(L, fn, 4, 4, "k", "a non-zero number (k = 0 collapses the arc to C)");
    int st;
    return push(L, pc_conic_ed(d, A, B, C, k, &st), st, fn);
}

static int c_ed_k(lua_State *L) {
    const char *fn = "conic.ed_k";
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM], K[PC_MAXDIM], k;
    int d = pt(L, fn, 1, "A", 0, 0, A);
    pt(L, fn, 2, "B", d, 1, B);
    pt(L, fn, 3, "C", d, 1, C);
    pt(L, fn, 4, "K", d, 1, K);
    int st = pc_conic_ed_k(d, A, B, C, K, &k);
    if (st == PC_ENOTCOLLINEAR)
        pcl_error(L, "%s: argument #4 (K) must lie on the median from C to the midpoint of AB", fn);
    statuscheck(L, fn, st);
    lua_pushnumber(L, k);
    return 1;
}

static int c_circle_k(lua_State *L) {
    const char *fn = "conic.circle_k";
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM], k;
    int d = pt(L, fn, 1, "A", 0, 0, A);
    pt(L, fn, 2, "B", d, 1, B);
    pt(L, fn, 3, "C", d, 1, C);
    int st = pc_conic_ed_circle_k(d, A, B, C, &k);
    if (st == PC_EDOMAIN) pcl_error(L, "%s: |CA| must equal |CB| (tangents from C to a circle)", fn);
    statuscheck(L, fn, st);
    lua_pushnumber(L, k);
    return 1;
}

static int c_ceva(lua_State *L) {
    const char *fn = "conic.ceva";
    double A1[PC_MAXDIM], A2[PC_MAXDIM], A3[PC_MAXDIM];
    int d = pt(L, fn, 1, "A1", 0, 0, A1);
    pt(L, fn, 2, "A2", d, 1, A2);
    pt(L, fn, 3, "A3", d, 1, A3);
    double k = pcl_checknum(L, fn, 4, "k");
    if (k == 0) pcl_argerror_full(L, fn, 4, 4, "k", "a non-zero number");
    int st;
    return push(L, pc_conic_ceva(d, A1, A2, A3, k, &st), st, fn);
}

static int c_ceva_k(lua_State *L) {
    const char *fn = "conic.ceva_k";
    double A1[PC_MAXDIM], A2[PC_MAXDIM], A3[PC_MAXDIM], K[PC_MAXDIM], k;
    int d = pt(L, fn, 1, "A1", 0, 0, A1);
    pt(L, fn, 2, "A2", d, 1, A2);
    pt(L, fn, 3, "A3", d, 1, A3);
    pt(L, fn, 4, "K", d, 1, K);
    int st = pc_conic_ceva_k(d, A1, A2, A3, K, &k);
    if (st == PC_EDOMAIN) pcl_error(L, "%s: the cevians through K must meet the sides A2A3 and A3A1 at finite points other than A3", fn);
    statuscheck(L, fn, st);
    lua_pushnumber(L, k);
    return 1;
}

static int c_parabola(lua_State *L) {
    const char *fn = "conic.parabola";
    double A1[PC_MAXDIM], A3[PC_MAXDIM], A2[PC_MAXDIM];
    int d = pt(L, fn, 1, "A1", 0, 0, A1);
    pt(L, fn, 2, "A3", d, 1, A3);
    pt(L, fn, 3, "A2", d, 1, A2);
    int st;
    if (lua_isnoneornil(L, 4)) return push(L, pc_conic_parabola(d, A1, A3, A2, &st), st, fn);
    double tc = pcl_checknum(L, fn, 4, "tC");
    if (!(tc > 0 && tc < 1)) pcl_argerror_full(L, fn, 4, 4, "tC", "a number in (0, 1)");
    /* (2.62): A, C, B = arguments 1, 2, 3 with C reached at tC */
    return push(L, pc_conic_parabola3(d, A1, A3, A2, tc, &st), st, fn);
}

static const struct { const char *name; pc_kcurve_kind kind; } ellipse_forms[] = {
    {"angle", PC_KC_ELLIPSE_ANGLE}, {"radius", PC_KC_ELLIPSE_RADIUS},
    {"focal", PC_KC_ELLIPSE_FOCAL}, {"compression", PC_KC_ELLIPSE_COMPRESSION},
    {"algebraic", PC_KC_ELLIPSE_ALGEBRAIC}, {NULL, 0}};
static const struct { const char *name; pc_kcurve_kind kind; } hyperbola_forms[] = {
    {"angle", PC_KC_HYPERBOLA_ANGLE}, {"radius", PC_KC_HYPERBOLA_RADIUS},
    {"focal", PC_KC_HYPERBOLA_FOCAL}, {NULL, 0}};

/* The CAB fields, the form `by`, the range: a pc_kcurve. */
static int kcurve_from(lua_State *L, const char *fn, pc_kcurve_kind kind, const double *par,
                       int npar) {
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM], t0, t1;
    int d = fpt(L, fn, 1, "C", 0, C);
    fpt(L, fn, 1, "A", d, A);
    fpt(L, fn, 1, "B", d, B);
    frange(L, fn, 1, &t0, &t1);
    int st;
    pc_curve *c = pc_kcurve(kind, d, C, A, B, par, npar, t0, t1, &st);
    if (!c && st == PC_EDOMAIN) {
        double r0, r1;
        if (pc_kcurve_range(kind, d, C, A, B, par, npar, &r0, &r1) == PC_OK)
            pcl_error(L, "%s: range must lie within the form's real range [%s, %s]", fn,
                      pcl_pushnum(L, r0), pcl_pushnum(L, r1));
        pcl_error(L, "%s: the points or parameters are outside the form's conditions "
                  "(see :help %s)", fn, fn);
    }
    return push(L, c, st, fn);
}

static int c_ellipse(lua_State *L) {
    const char *fn = "conic.ellipse";
    checktable(L, fn, 1, "spec");
    lua_getfield(L, 1, "by");
    const char *by = lua_isnil(L, -1) ? "angle" : lua_tostring(L, -1);
    lua_pop(L, 1);
    if (by && !strcmp(by, "conjugate")) {
        double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM];
        int d = fpt(L, fn, 1, "C", 0, C);
        fpt(L, fn, 1, "A", d, A);
        fpt(L, fn, 1, "B", d, B);
        int st;
        return push(L, pc_conic_conjugate(d, C, A, B, &st), st, fn);
    }
    if (by && !strcmp(by, "diameter")) {
        double K[PC_MAXDIM], A[PC_MAXDIM], B[PC_MAXDIM];
        int d = fpt(L, fn, 1, "K", 0, K);
        fpt(L, fn, 1, "A", d, A);
        fpt(L, fn, 1, "B", d, B);
        double lam = fnum(L, fn, 1, "lambda", NAN);
        if (!(lam > 0 && lam < 1)) pcl_error(L, "%s: field lambda must be in (0, 1), got %s", fn, pcl_pushnum(L, lam));
        int st;
        return push(L, pc_conic_conjugate2(d, K, A, B, lam, &st), st, fn);
    }
    for (int i = 0; ellipse_forms[i].name; i++)
        if (by && !strcmp(by, ellipse_forms[i].name)) {
            double q = fnum(L, fn, 1, "quadrant", 1);
            return kcurve_from(L, fn, ellipse_forms[i].kind, &q, 1);
        }
    return pcl_error(L, "%s: field by must be \"angle\", \"radius\", \"focal\", \"compression\", "
                     "\"algebraic\", \"conjugate\" or \"diameter\", got %s", fn, by ? by : "a non-string");
}

static int c_hyperbola(lua_State *L) {
    const char *fn = "conic.hyperbola";
    checktable(L, fn, 1, "spec");
    lua_getfield(L, 1, "by");
    const char *by = lua_isnil(L, -1) ? "angle" : lua_tostring(L, -1);
    lua_pop(L, 1);
    for (int i = 0; hyperbola_forms[i].name; i++)
        if (by && !strcmp(by, hyperbola_forms[i].name)) {
            double br = fnum(L, fn, 1, "branch", 1);
            if (br != 1 && br != 2) pcl_error(L, "%s: field branch must be 1 (through A) or 2", fn);
            return kcurve_from(L, fn, hyperbola_forms[i].kind, &br, 1);
        }
    return pcl_error(L, "%s: field by must be \"angle\", \"radius\" or \"focal\", got %s", fn,
                     by ? by : "a non-string");
}

static int c_circle(lua_State *L) {
    const char *fn = "conic.circle";
    checktable(L, fn, 1, "spec");
    if (lua_getfield(L, 1, "delta"), !lua_isnil(L, -1)) {
        lua_pop(L, 1);
        double dl = fnum(L, fn, 1, "delta", NAN);
        if (!(dl > 0 && dl < M_PI)) pcl_error(L, "%s: field delta must be an angle in (0, pi), got %s", fn, pcl_pushnum(L, dl));
        return kcurve_from(L, fn, PC_KC_CIRCLE_ANGLE, &dl, 1);
    }
    lua_pop(L, 1);
    if (lua_getfield(L, 1, "R"), !lua_isnil(L, -1)) {
        lua_pop(L, 1);
        double R = fnum(L, fn, 1, "R", NAN);
        if (!(R > 0)) pcl_error(L, "%s: field R must be a positive radius, got %s", fn, pcl_pushnum(L, R));
        return kcurve_from(L, fn, PC_KC_CIRCLE_RADIUS, &R, 1);
    }
    lua_pop(L, 1);
    /* §2.1.8.1: the arc AB with tangents meeting at C, by the engineering discriminant */
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM], k;
    int d = fpt(L, fn, 1, "A", 0, A);
    fpt(L, fn, 1, "B", d, B);
    fpt(L, fn, 1, "C", d, C);
    int st = pc_conic_ed_circle_k(d, A, B, C, &k);
    if (st == PC_EDOMAIN) pcl_error(L, "%s: |CA| must equal |CB| for the arc (or give delta or R)", fn);
    statuscheck(L, fn, st);
    return push(L, pc_conic_ed(d, A, B, C, k, &st), st, fn);
}

static int c_tilted(lua_State *L) {
    const char *fn = "conic.tilted";
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM], P[PC_MAXDIM], Q[PC_MAXDIM];
    int d = pt(L, fn, 1, "A", 0, 0, A);
    pt(L, fn, 2, "B", d, 1, B);
    pt(L, fn, 3, "C", d, 1, C);
    double th = pcl_checknum(L, fn, 4, "theta"), m = pcl_checknum(L, fn, 5, "m"),
           n = pcl_checknum(L, fn, 6, "n");
    if (!(m > 0)) pcl_argerror_full(L, fn, 5, 5, "m", "a positive semi-axis");
    if (!(n > 0)) pcl_argerror_full(L, fn, 6, 6, "n", "a positive semi-axis");
    statuscheck(L, fn, pc_ellipse_tilted_axes(d, A, B, C, th, m, n, P, Q));
    int st;
    push(L, pc_kcurve(PC_KC_ELLIPSE_ANGLE, d, C, P, Q, NULL, 0, NAN, NAN, &st), st, fn);
    pcl_pushpoint(L, d, P);
    pcl_pushpoint(L, d, Q);
    return 3;
}

static int c_five_points(lua_State *L) {
    const char *fn = "conic.five_points";
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM], D[PC_MAXDIM], E[PC_MAXDIM], u[5];
    int d = pt(L, fn, 1, "A", 0, 0, A);
    pt(L, fn, 2, "B", d, 1, B);
    pt(L, fn, 3, "C", d, 1, C);
    pt(L, fn, 4, "D", d, 1, D);
    pt(L, fn, 5, "E", d, 1, E);
    int st = pc_conic_five_points_params(d, A, B, C, D, E, u);
    if (st == PC_EDOMAIN)
        pcl_error(L, "%s: the five points must lie in one plane with no three of them collinear", fn);
    if (st == PC_ECOLLINEAR) pcl_error(L, "%s: A, B and C must not be collinear", fn);
    statuscheck(L, fn, st);
    double u0 = 0, u1 = 1;
    /* a point whose U is the point at infinity of CA (ED parallel to CA) has |u| huge, not a
     * range end: it is reached by the whole conic only */
    for (int i = 0; i < 5; i++)
        if (isfinite(u[i]) && fabs(u[i]) < 1e6) u0 = fmin(u0, u[i]), u1 = fmax(u1, u[i]);
    int whole = 0;
    if (!lua_isnoneornil(L, 6)) {
        checktable(L, fn, 6, "opts");
        u0 = fnum(L, fn, 6, "u0", u0);
        u1 = fnum(L, fn, 6, "u1", u1);
        lua_getfield(L, 6, "whole");
        whole = lua_toboolean(L, -1);
        lua_pop(L, 1);
        if (!(u1 > u0)) pcl_error(L, "%s: opts.u1 must be greater than opts.u0", fn);
    }
    push(L, pc_conic_five_points(d, A, B, C, D, E, u0, u1, whole, NULL, &st), st, fn);
    lua_createtable(L, 0, 5);
    static const char *names[5] = {"A", "B", "C", "D", "E"};
    for (int i = 0; i < 5; i++) {
        lua_pushnumber(L, u[i]);
        lua_setfield(L, -2, names[i]);
    }
    return 2;
}

static int c_five_points2(lua_State *L) {
    const char *fn = "conic.five_points2";
    checktable(L, fn, 1, "spec");
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM];
    int d = fpt(L, fn, 1, "C", 0, C);
    fpt(L, fn, 1, "A", d, A);
    fpt(L, fn, 1, "B", d, B);
    double p1 = fnum(L, fn, 1, "p1", NAN), p2 = fnum(L, fn, 1, "p2", NAN),
           q2 = fnum(L, fn, 1, "q2", NAN), q3 = fnum(L, fn, 1, "q3", NAN);
    if (!(p1 > 0 && p1 <= 1 && q3 > 0 && q3 <= 1))
        pcl_error(L, "%s: fields p1 and q3 must be in (0, 1]", fn);
    if (!(p2 > 0 && p2 < 1 && q2 > 0 && q2 < 1))
        pcl_error(L, "%s: fields p2 and q2 must be in (0, 1) (A2 inside the triangle C A1 A3)", fn);
    int st;
    return push(L, pc_conic_five_points2(d, C, A, B, p1, p2, q2, q3, &st), st, fn);
}

static int c_triples(lua_State *L) {
    const char *fn = "conic.triples";
    double P[5][PC_MAXDIM];
    static const char *what[5] = {"A1", "A2", "A3", "A4", "A5"};
    int d = pt(L, fn, 1, what[0], 0, 0, P[0]);
    for (int i = 1; i < 5; i++) pt(L, fn, i + 1, what[i], d, 1, P[i]);
    double t0 = pcl_optnum(L, fn, 6, "t0", 0), t1 = pcl_optnum(L, fn, 7, "t1", 1);
    if (!(t1 > t0)) pcl_argerror_full(L, fn, 7, 7, "t1", "greater than t0");
    int st;
    pc_curve *c = pc_triples_conic(d, P[0], P[1], P[2], P[3], P[4], t0, t1, &st);
    if (!c && st == PC_EDOMAIN) pcl_error(L, "%s: the lines A2A3 and A4A5 must meet", fn);
    return push(L, c, st, fn);
}

static int c_redundant(lua_State *L) {
    const char *fn = "conic.redundant";
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM], K[PC_MAXDIM];
    int d = pt(L, fn, 1, "C", 0, 0, C);
    pt(L, fn, 2, "A", d, 1, A);
    pt(L, fn, 3, "B", d, 1, B);
    if (lua_isnoneornil(L, 4)) {        /* (2.121) u = v = t: the ED arc with k = 2/3 */
        int st;
        return push(L, pc_conic_ed(d, A, B, C, 2.0 / 3, &st), st, fn);
    }
    double u = pcl_checknum(L, fn, 4, "u"), v = pcl_checknum(L, fn, 5, "v");
    int st = pc_redundant_point(d, C, A, B, u, v, K);
    if (st == PC_EPOLE) pcl_error(L, "%s: u = 0 and v = 1 make both lines AB: K is undefined", fn);
    statuscheck(L, fn, st);
    pcl_pushpoint(L, d, K);
    return 1;
}

static int c_reparam(lua_State *L) {
    const char *fn = "conic.reparam";
    checktable(L, fn, 1, "spec");
    lua_getfield(L, 1, "by");
    const char *by = lua_isnil(L, -1) ? "angle" : lua_tostring(L, -1);
    lua_pop(L, 1);
    if (by && !strcmp(by, "angle")) return kcurve_from(L, fn, PC_KC_PARABOLA_ANGLE, NULL, 0);
    if (by && !strcmp(by, "sigma")) {
        double br = fnum(L, fn, 1, "branch", 1);
        if (br != 1 && br != 2) pcl_error(L, "%s: field branch must be 1 (towards A) or 2 (towards B)", fn);
        return kcurve_from(L, fn, PC_KC_PARABOLA_SIGMA, &br, 1);
    }
    return pcl_error(L, "%s: field by must be \"angle\" or \"sigma\"", fn);
}

static int c_sinusoid(lua_State *L) {
    const char *fn = "conic.sinusoid";
    checktable(L, fn, 1, "spec");
    double par[PC_KC_MAXPAR];
    lua_getfield(L, 1, "k");
    if (lua_isnumber(L, -1)) {
        par[0] = 1, par[1] = lua_tonumber(L, -1);
    } else if (lua_istable(L, -1)) {
        int g = (int)luaL_len(L, -1);
        if (g < 1 || g > PC_KC_MAXPAR - 1) pcl_error(L, "%s: field k must list 1 to %d wave numbers", fn, PC_KC_MAXPAR - 1);
        par[0] = g;
        for (int i = 1; i <= g; i++) {
            lua_geti(L, -1, i);
            par[i] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
    } else {
        pcl_error(L, "%s: field k must be a wave number or a list of them (one per generation)", fn);
    }
    lua_pop(L, 1);
    for (int i = 1; i <= (int)par[0]; i++)
        if (!(par[i] > 0) || !isfinite(par[i]))
            pcl_error(L, "%s: field k[%d] must be a positive number", fn, i);
    return kcurve_from(L, fn, PC_KC_SINUSOID, par, (int)par[0] + 1);
}

static int c_cycloid(lua_State *L) {
    const char *fn = "conic.cycloid";
    checktable(L, fn, 1, "spec");
    lua_getfield(L, 1, "concave");
    double cc = lua_toboolean(L, -1) ? 1 : 0;
    lua_pop(L, 1);
    return kcurve_from(L, fn, PC_KC_CYCLOID, &cc, 1);
}

static int c_cones(lua_State *L) {
    const char *fn = "conic.cones";
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM], D[PC_MAXDIM];
    int d = pt(L, fn, 1, "A", 0, 0, A);
    if (d < 3) pcl_error(L, "%s: the points must be 3-D or more (a tetrahedron ABCD), got %d-D", fn, d);
    pt(L, fn, 2, "B", d, 1, B);
    pt(L, fn, 3, "C", d, 1, C);
    pt(L, fn, 4, "D", d, 1, D);
    double fp = pcl_checknum(L, fn, 5, "fP"), fq = pcl_checknum(L, fn, 6, "fQ"),
           n = pcl_checknum(L, fn, 7, "n");
    if (!(fp > 0 && fp < 1)) pcl_argerror_full(L, fn, 5, 5, "fP", "a number in (0, 1)");
    if (!(fq > 0 && fq < 1)) pcl_argerror_full(L, fn, 6, 6, "fQ", "a number in (0, 1)");
    if (n == 0 || n == 1) pcl_argerror_full(L, fn, 7, 7, "n", "a number other than 0 and 1");
    int st;
    pc_curve *c = pc_cubic_cones(d, A, B, C, D, fp, fq, n, &st);
    if (!c && st == PC_ECOLLINEAR) pcl_error(L, "%s: A, B, C, D must span a tetrahedron", fn);
    return push(L, c, st, fn);
}

static int c_contour(lua_State *L) {
    const char *fn = "conic.contour";
    double A1[PC_MAXDIM], A2[PC_MAXDIM], A3[PC_MAXDIM];
    int d = pt(L, fn, 1, "A1", 0, 0, A1);
    pt(L, fn, 2, "A2", d, 1, A2);
    pt(L, fn, 3, "A3", d, 1, A3);
    if (!callable(L, 4)) pcl_argerror_full(L, fn, 4, 4, "u", "a function of t");
    if (!callable(L, 5)) pcl_argerror_full(L, fn, 5, 5, "v", "a function of t");
    int has_d = !lua_isnoneornil(L, 6);
    if (has_d && !callable(L, 6)) pcl_argerror_full(L, fn, 6, 6, "du", "a function of t");
    if (has_d && !callable(L, 7)) pcl_argerror_full(L, fn, 7, 7, "dv", "a function of t");
    int idx[4] = {4, 5, 6, 7};
    luaref *r = newref(L, fn, has_d ? 4 : 2, idx);
    int st;
    pcl_callback_state(L);
    pc_curve *c = pc_contour_arc(d, A1, A2, A3, real_cb, has_d, luaref_free, r, &st);
    if (!c) luaref_free(r);
    return push(L, c, st, fn);
}

/* ==== oneratio ============================================================================== */

static int o_simplex(lua_State *L) {
    const char *fn = "oneratio.simplex";
    int base = lua_istable(L, 1) && !pcl_tovalue(L, 1) ? 2 : 1;   /* oneratio(A, B, C) */
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM];
    int d = pt(L, fn, base, "A", 0, 0, A);
    pt(L, fn, base + 1, "B", d, base, B);
    pt(L, fn, base + 2, "C", d, base, C);
    int st;
    return push(L, pc_oneratio_simplex(d, A, B, C, &st), st, fn);
}

static int o_tetra(lua_State *L) {
    const char *fn = "oneratio.tetra";
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM], D[PC_MAXDIM];
    int d = pt(L, fn, 1, "A", 0, 0, A);
    pt(L, fn, 2, "B", d, 1, B);
    pt(L, fn, 3, "C", d, 1, C);
    pt(L, fn, 4, "D", d, 1, D);
    int st;
    return push(L, pc_oneratio_tetra(d, A, B, C, D, &st), st, fn);
}

static int o_bezier3(lua_State *L) {
    const char *fn = "oneratio.bezier3";
    double P[4][PC_MAXDIM], cp[4 * (PC_MAXDIM + 1)];
    static const char *what[4] = {"A", "C1", "C2", "B"};
    int d = pt(L, fn, 1, what[0], 0, 0, P[0]);
    for (int i = 1; i < 4; i++) pt(L, fn, i + 1, what[i], d, 1, P[i]);
    for (int i = 0; i < 4; i++) {      /* (3.4) with the corrected t' powers */
        memcpy(cp + i * (d + 1), P[i], sizeof(double) * (size_t)d);
        cp[i * (d + 1) + d] = 1;
    }
    int st;
    return push(L, pc_curve_bezier(d, 4, cp, &st), st, fn);
}

static int o_smooth(lua_State *L) {
    const char *fn = "oneratio.smooth";
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM];
    int d = pt(L, fn, 1, "A", 0, 0, A);
    pt(L, fn, 2, "B", d, 1, B);
    pt(L, fn, 3, "C", d, 1, C);
    lua_Integer n = 2;
    if (!lua_isnoneornil(L, 4)) {
        if (!lua_isinteger(L, 4)) pcl_argerror_full(L, fn, 4, 4, "n", "an integer 1..40");
        n = lua_tointeger(L, 4);
    }
    if (n < 1 || n > 40) pcl_argerror_full(L, fn, 4, 4, "n", "an integer 1..40");
    int st;
    return push(L, pc_oneratio_smooth(d, A, B, C, (int)n, &st), st, fn);
}

static int o_desargues(lua_State *L) {
    const char *fn = "oneratio.desargues";
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM], D[PC_MAXDIM];
    int d = pt(L, fn, 1, "A", 0, 0, A);
    pt(L, fn, 2, "B", d, 1, B);
    pt(L, fn, 3, "C", d, 1, C);
    pt(L, fn, 4, "D", d, 1, D);
    int st;
    return push(L, pc_oneratio_desargues(d, A, B, C, D, &st), st, fn);
}

static double const_blend(void *ud, double v) {
    (void)v;
    return *(double *)ud;
}

static int o_double_contact(lua_State *L) {
    const char *fn = "oneratio.double_contact";
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM];
    int d = pt(L, fn, 1, "A", 0, 0, A);
    pt(L, fn, 2, "B", d, 1, B);
    pt(L, fn, 3, "C", d, 1, C);
    double kp = pcl_checknum(L, fn, 4, "kp"), kq = pcl_checknum(L, fn, 5, "kq");
    if (kp == 0) pcl_argerror_full(L, fn, 4, 4, "kp", "a non-zero number");
    if (kq == 0) pcl_argerror_full(L, fn, 5, 5, "kq", "a non-zero number");
    if (kp == kq) pcl_argerror_full(L, fn, 5, 5, "kq", "different from kp (else M is the conic P = Q)");
    int st;
    pc_curve *c;
    pcl_callback_state(L);
    if (lua_isnoneornil(L, 6)) {
        c = pc_oneratio_double_contact(d, A, B, C, kp, kq, NULL, NULL, NULL, &st);
    } else if (lua_type(L, 6) == LUA_TNUMBER) {
        double *f = malloc(sizeof *f);
        if (!f) return pcl_error(L, "%s: out of memory", fn);
        *f = pcl_checknum(L, fn, 6, "f");
        c = pc_oneratio_double_contact(d, A, B, C, kp, kq, const_blend, free, f, &st);
        if (!c) free(f);
    } else {
        if (!callable(L, 6)) pcl_argerror_full(L, fn, 6, 6, "f", "a function of v or a number");
        int idx[1] = {6};
        luaref *r = newref(L, fn, 1, idx);
        c = pc_oneratio_double_contact(d, A, B, C, kp, kq, blend_cb, luaref_free, r, &st);
        if (!c) luaref_free(r);
    }
    return push(L, c, st, fn);
}

static int o_closed(lua_State *L) {
    const char *fn = "oneratio.closed";
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM];
    int d = pt(L, fn, 1, "A", 0, 0, A);
    pt(L, fn, 2, "B", d, 1, B);
    pt(L, fn, 3, "C", d, 1, C);
    double kp = pcl_checknum(L, fn, 4, "kP"), kq = pcl_checknum(L, fn, 5, "kQ");
    if (kp == 0) pcl_argerror_full(L, fn, 4, 4, "kP", "a non-zero number");
    if (kq == 0) pcl_argerror_full(L, fn, 5, 5, "kQ", "a non-zero number");
    double s = pcl_optnum(L, fn, 6, "scheme", 1);
    if (s != 1 && s != 2) pcl_argerror_full(L, fn, 6, 6, "scheme", "1 or 2");
    int st;
    return push(L, pc_oneratio_closed(d, A, B, C, kp, kq, (int)s, &st), st, fn);
}

/* ---- the schemes' intermediate points (for figures that label them) ----------------------- */

/* a homogeneous row: the point, or the direction (a vector) where its weight is 0 */
static void push_h(lua_State *L, int dim, const double *h) {
    double x[PC_MAXDIM];
    int inf = fabs(h[dim]) <= 1e-12;
    for (int k = 0; k < dim; k++) x[k] = inf ? h[k] : h[k] / h[dim];
    if (inf) pcl_pushvector(L, dim, x);
    else pcl_pushpoint(L, dim, x);
}

static int o_simplex_scheme(lua_State *L) {
    const char *fn = "oneratio.simplex_scheme";
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM], N[PC_MAXDIM], M[PC_MAXDIM];
    int d = pt(L, fn, 1, "A", 0, 0, A);
    pt(L, fn, 2, "B", d, 1, B);
    pt(L, fn, 3, "C", d, 1, C);
    double t = pcl_checknum(L, fn, 4, "t");
    statuscheck(L, fn, pc_oneratio_simplex_scheme(d, A, B, C, t, N, M));
    lua_createtable(L, 0, 2);
    pcl_pushpoint(L, d, N);
    lua_setfield(L, -2, "N");
    pcl_pushpoint(L, d, M);
    lua_setfield(L, -2, "M");
    return 1;
}

static int o_levels(lua_State *L) {
    const char *fn = "oneratio.levels";
    lua_settop(L, 2);
    int n, d;
    double *p = ptlist(L, fn, 1, "points", 2, 16, &n, &d);
    double t = pcl_checknum(L, fn, 2, "t"), out[120 * PC_MAXDIM];
    statuscheck(L, fn, pc_decasteljau_levels(d, n, p, t, out));
    lua_createtable(L, n - 1, 0);
    const double *row = out;
    for (int level = 1; level < n; level++) {
        lua_createtable(L, n - level, 0);
        for (int i = 0; i < n - level; i++) {
            pcl_pushpoint(L, d, row + i * d);
            lua_rawseti(L, -2, i + 1);
        }
        lua_rawseti(L, -2, level);
        row += (n - level) * d;
    }
    return 1;
}

static int o_desargues_scheme(lua_State *L) {
    const char *fn = "oneratio.desargues_scheme";
    static const char *names[7] = {"T", "S", "R", "N", "J", "Q", "M"};
    double A[PC_MAXDIM], B[PC_MAXDIM], C[PC_MAXDIM], D[PC_MAXDIM], h[7 * (PC_MAXDIM + 1)], pq[2];
    int d = pt(L, fn, 1, "A", 0, 0, A);
    pt(L, fn, 2, "B", d, 1, B);
    pt(L, fn, 3, "C", d, 1, C);
    pt(L, fn, 4, "D", d, 1, D);
    double t = pcl_checknum(L, fn, 5, "t");
    statuscheck(L, fn, pc_desargues_scheme(d, A, B, C, D, t, h, pq));
    lua_createtable(L, 0, 9);
    for (int i = 0; i < 7; i++) {
        push_h(L, d, h + i * (d + 1));
        lua_setfield(L, -2, names[i]);
    }
    lua_pushnumber(L, pq[0]);
    lua_setfield(L, -2, "pJ");
    lua_pushnumber(L, pq[1]);
    lua_setfield(L, -2, "qJ");
    return 1;
}

/* ==== interp ================================================================================ */

static int i_lagrange(lua_State *L) {
    const char *fn = "interp.lagrange";
    lua_settop(L, 2);
    int n, d;
    double *p = ptlist(L, fn, 1, "points", 2, PC_CURVE_MAXDEG + 1, &n, &d);
    double *u = lua_isnoneornil(L, 2) ? NULL : numlist(L, fn, 2, "params", n);
    int st;
    pc_curve *c = pc_curve_interpolate(d, n, p, u, &st);
    if (!c && st == PC_ECOINCIDENT) pcl_error(L, "%s: argument #2 (params) must be distinct", fn);
    return push(L, c, st, fn);
}

/* interp.weights(n, t): the book's order n (n + 1 weights at the uniform j/n), or the list
 * of node parameters; t a number, or an equation (param "t"): then the weights are equations,
 * the polynomials the Maple program of §4.8 prints */
static int i_weights(lua_State *L) {
    const char *fn = "interp.weights";
    lua_settop(L, 2);
    int n;
    double *u = NULL;
    if (lua_isinteger(L, 1)) {
        lua_Integer order = lua_tointeger(L, 1);
        if (order < 1 || order > PC_CURVE_MAXDEG)
            pcl_argerror_full(L, fn, 1, 1, "n", "the book's order 1..64 (a curve through n + 1 nodes; not the number of nodes)");
        n = (int)order + 1;
    } else if (lua_istable(L, 1)) {
        n = (int)luaL_len(L, 1);
        if (n < 2 || n > PC_CURVE_MAXDEG + 1) pcl_argerror_full(L, fn, 1, 1, "params", "a list of 2..65 parameters");
        u = numlist(L, fn, 1, "params", n);
    } else {
        return pcl_argerror_full(L, fn, 1, 1, "n", "the book's order n or a list of node parameters");
    }
    if (pcl_isequation(L, 2)) {
        double coef[(PC_CURVE_MAXDEG + 1) * (PC_CURVE_MAXDEG + 1)];
        int st = pc_lagrange_weight_coefs(n, u, coef);
        if (st == PC_ECOINCIDENT) pcl_error(L, "%s: argument #1 (params) must be distinct", fn);
        statuscheck(L, fn, st);
        lua_createtable(L, n, 0);
        for (int j = 0; j < n; j++) {
            /* phi_j = c0 + c1 t + c2 t^2 + ..., terms of zero coefficient left out */
            int any = 0;
            for (int i = 0; i < n; i++) {
                double c = coef[(size_t)j * n + i];
                if (c == 0) continue;
                lua_pushnumber(L, c);
                if (i > 0) {
                    lua_pushvalue(L, 2);
                    if (i > 1) {
                        lua_pushinteger(L, i);
                        lua_arith(L, LUA_OPPOW);
                    }
                    lua_arith(L, LUA_OPMUL);
                }
                if (any) lua_arith(L, LUA_OPADD);
                any = 1;
            }
            if (!any) lua_pushnumber(L, 0);
            lua_rawseti(L, -2, j + 1);
        }
        return 1;
    }
    double t = pcl_checknum(L, fn, 2, "t"), w[PC_CURVE_MAXDEG + 1];
    int st = pc_lagrange_weights(n, u, t, w);
    if (st == PC_ECOINCIDENT) pcl_error(L, "%s: argument #1 (params) must be distinct", fn);
    statuscheck(L, fn, st);
    for (int i = 0; i < n; i++)   /* a t far outside the nodes overflows the products */
        if (!isfinite(w[i]))
            pcl_error(L, "%s: the weights are out of range (not finite) for t = %s", fn,
                      pcl_pushnum(L, t));
    pushnums(L, n, w);
    return 1;
}

static int i_controls(lua_State *L) {
    const char *fn = "interp.controls";
    lua_settop(L, 2);
    int n, d;
    double *p = ptlist(L, fn, 1, "points", 2, PC_CURVE_MAXDEG + 1, &n, &d);
    double *u = lua_isnoneornil(L, 2) ? NULL : numlist(L, fn, 2, "params", n);
    int st;
    pc_curve *c = pc_curve_interpolate(d, n, p, u, &st);
    if (!c) return pcl_raise_status(L, fn, st);
    lua_createtable(L, c->ncp, 0);
    for (int i = 0; i < c->ncp; i++) {
        double x[PC_MAXDIM];
        pc_normalize(d, c->cp + i * (d + 1), x);
        pcl_pushpoint(L, d, x);
        lua_rawseti(L, -2, i + 1);
    }
    pc_curve_release(c);
    return 1;
}

static int i_conic(lua_State *L) {
    const char *fn = "interp.conic";
    double A[PC_MAXDIM], K[PC_MAXDIM], B[PC_MAXDIM];
    int d = pt(L, fn, 1, "A", 0, 0, A);
    pt(L, fn, 2, "K", d, 1, K);
    pt(L, fn, 3, "B", d, 1, B);
    double k = pcl_checknum(L, fn, 4, "k");
    if (k == 0 || k == 1) pcl_argerror_full(L, fn, 4, 4, "k", "a number other than 0 and 1");
    int st;
    return push(L, pc_conic_ed3(d, A, K, B, k, &st), st, fn);
}

static int i_arc(lua_State *L) {
    const char *fn = "interp.arc";
    lua_settop(L, 4);
    int n, d;
    double *p = ptlist(L, fn, 1, "points", 2, PC_CURVE_MAXDEG - 2, &n, &d);
    double c2[PC_MAXDIM], cn[PC_MAXDIM];
    pt(L, fn, 2, "C2", d, 1, c2);
    /* interp.arc(points, C2 [, Cn] [, params]) */
    int parg = lua_istable(L, 3) && !pcl_tovalue(L, 3) ? 3 : 4;
    int two = parg == 4 && !lua_isnoneornil(L, 3);
    if (two) pt(L, fn, 3, "Cn", d, 1, cn);
    double *u = lua_isnoneornil(L, parg) ? NULL : numlist(L, fn, parg, "params", n);
    int st;
    pc_curve *c = pc_interp_arc_u(d, n, p, u, c2, two ? cn : NULL, &st);
    if (!c && st == PC_EDOMAIN && u)
        return pcl_error(L, "%s: argument #%d (params) must increase (one parameter per point, in order)", fn, parg);
    return push(L, c, st, fn);
}

static int i_adaptive(lua_State *L) {
    const char *fn = "interp.adaptive";
    lua_settop(L, 2);
    int n, d;
    double *p = ptlist(L, fn, 1, "points", 2, PC_CURVE_MAXDEG + 1, &n, &d);
    lua_Integer axis = 1;
    if (!lua_isnoneornil(L, 2)) {
        if (!lua_isinteger(L, 2) || lua_tointeger(L, 2) < 1 || lua_tointeger(L, 2) > d) {
            lua_pushfstring(L, "an axis number 1..%d", d);
            pcl_argerror_full(L, fn, 2, 2, "axis", lua_tostring(L, -1));
        }
        axis = lua_tointeger(L, 2);
    }
    double v[PC_CURVE_MAXDEG + 1];
    int st = pc_interp_adaptive_params(d, n, p, (int)axis - 1, v);
    if (st == PC_ECOINCIDENT) pcl_error(L, "%s: the first and last nodes have the same coordinate on axis %d", fn, (int)axis);
    if (st == PC_EDOMAIN)
        pcl_error(L, "%s: the nodes must advance along axis %d in their order (the book's "
                  "limitation: the order of the nodes must be the order of the parameters)", fn, (int)axis);
    statuscheck(L, fn, st);
    pushnums(L, n, v);
    return 1;
}

static const struct { const char *name; pc_proto_kind kind; int n, nk; } protos[] = {
    {"desargues", PC_PROTO_DESARGUES, 4, 0}, {"rational", PC_PROTO_RATIONAL, 4, 0},
    {"exp", PC_PROTO_EXP, 3, 3}, {"exp1", PC_PROTO_EXP_AFFINE, 3, 2},
    {"trig", PC_PROTO_TRIG, 3, 0}, {NULL, 0, 0, 0}};

static int i_prototype(lua_State *L) {
    const char *fn = "interp.prototype";
    lua_settop(L, 6);
    const char *name = lua_tostring(L, 1);
    int i = 0;
    while (protos[i].name && (!name || strcmp(name, protos[i].name))) i++;
    if (!protos[i].name)
        return pcl_argerror_full(L, fn, 1, 1, "kind",
                                 "\"desargues\", \"rational\", \"exp\", \"exp1\" or \"trig\"");
    int n, d;
    double *p = ptlist(L, fn, 2, "points", protos[i].n, protos[i].n, &n, &d);
    double k[3] = {0, 0, 0}, t0 = NAN, t1 = NAN;
    int next = 3;
    if (protos[i].nk) {
        double *kk = numlist(L, fn, 3, "k", protos[i].nk);
        memcpy(k, kk, sizeof(double) * (size_t)protos[i].nk);
        next = 4;
    }
    if (!lua_isnoneornil(L, next)) {
        t0 = pcl_checknum(L, fn, next, "t0");
        t1 = pcl_checknum(L, fn, next + 1, "t1");
        if (!(t1 > t0)) pcl_argerror_full(L, fn, next + 1, next + 1, "t1", "greater than t0");
    }
    int st;
    pc_curve *c = pc_interp_prototype(protos[i].kind, d, n, p, k, t0, t1, &st);
    if (!c && st == PC_ESINGULAR) pcl_error(L, "%s: the exponents must be distinct (singular system)", fn);
    return push(L, c, st, fn);
}

/* interp.basis{g1, g2, ...}: Lua prototypes */
typedef struct { int ref; } basisref;

static int basis_cb(void *ud, double t, int n, double *g) {
    lua_State *L = pcl_current_state();
    lua_rawgeti(L, LUA_REGISTRYINDEX, ((basisref *)ud)->ref);
    for (int i = 0; i < n; i++) {
        lua_geti(L, -1 - i, i + 1);
        lua_pushnumber(L, t);
        if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
            int st = pcl_callback_failed(L);
            lua_pop(L, i + 1);
            return st;
        }
        int isnum;
        g[i] = lua_tonumberx(L, -1, &isnum);
        if (!isnum) {
            pcl_pushwhere(L);
            lua_pushfstring(L, "interp.basis: the basis function [%d] must return a number", i + 1);
            lua_concat(L, 2);
            int st = pcl_callback_failed(L);
            lua_pop(L, i + 2);
            return st;
        }
    }
    lua_pop(L, n + 1);
    return PC_OK;
}

static void basisref_free(void *ud) {
    lua_State *L = pcl_current_state();
    if (L) luaL_unref(L, LUA_REGISTRYINDEX, ((basisref *)ud)->ref);
    free(ud);
}

static int i_basis(lua_State *L) {
    const char *fn = "interp.basis";
    lua_settop(L, 5);
    if (!lua_istable(L, 1)) pcl_argerror_full(L, fn, 1, 1, "basis", "a list of functions of t");
    int nb = (int)luaL_len(L, 1);
    if (nb < 1 || nb > 16) pcl_argerror_full(L, fn, 1, 1, "basis", "a list of 1..16 functions");
    for (int i = 1; i <= nb; i++) {
        lua_geti(L, 1, i);
        if (!callable(L, -1)) pcl_error(L, "%s: argument #1 (basis) item [%d] must be a function of t", fn, i);
        lua_pop(L, 1);
    }
    int n, d;
    double *p = ptlist(L, fn, 2, "points", nb, nb, &n, &d);
    double *u = numlist(L, fn, 3, "params", n);
    double t0 = u[0], t1 = u[0];
    for (int i = 1; i < n; i++) t0 = fmin(t0, u[i]), t1 = fmax(t1, u[i]);
    if (!lua_isnoneornil(L, 4)) {
        t0 = pcl_checknum(L, fn, 4, "t0");
        t1 = pcl_checknum(L, fn, 5, "t1");
    }
    if (!(t1 > t0)) pcl_error(L, "%s: the parameter range must not be empty", fn);
    basisref *r = malloc(sizeof *r);
    if (!r) return pcl_error(L, "%s: out of memory", fn);
    lua_pushvalue(L, 1);
    r->ref = luaL_ref(L, LUA_REGISTRYINDEX);
    int st;
    pcl_callback_state(L);
    pc_curve *c = pc_interp_basis(d, n, p, u, basis_cb, basisref_free, r, t0, t1, &st);
    if (!c) {
        basisref_free(r);
        if (st == PC_ESINGULAR) pcl_error(L, "%s: the collocation matrix g_i(t_j) is singular", fn);
    }
    push(L, c, st, fn);
    /* the membership condition: do the weights sum to 1 over [t0, t1]? (the curve owns r) */
    double dev;
    st = pc_interp_basis_membership(n, u, basis_cb, r, t0, t1, 65, &dev);
    if (st) pcl_raise_status(L, fn, st);
    lua_pushboolean(L, dev <= 1e-9);
    lua_pushnumber(L, dev);
    return 3;
}

static int i_rational22(lua_State *L) {
    const char *fn = "interp.rational22";
    lua_settop(L, 1);
    int n, d;
    double *p = ptlist(L, fn, 1, "points", 5, 5, &n, &d), co[5 * PC_MAXDIM];
    int st;
    pc_curve *c = pc_interp_rational22(d, p, co, &st);
    if (!c && st == PC_ESINGULAR) pcl_error(L, "%s: a coordinate has no rational (2,2) fit", fn);
    push(L, c, st, fn);
    lua_createtable(L, d, 0);
    for (int k = 0; k < d; k++) {
        pushnums(L, 5, co + 5 * k);
        lua_rawseti(L, -2, k + 1);
    }
    return 2;
}

/* ==== approx ================================================================================ */

static luaref *checkfn(lua_State *L, const char *fn, int arg) {
    if (!callable(L, arg)) pcl_argerror_full(L, fn, arg, arg, "f", "a function of x");
    int idx[1] = {arg};
    luaref *r = newref(L, fn, 1, idx);
    pcl_callback_state(L);
    return r;
}

static int a_curve(lua_State *L) {
    const char *fn = "approx.curve";
    lua_settop(L, 2);
    if (!callable(L, 1)) pcl_argerror_full(L, fn, 1, 1, "f", "a function of x");
    if (!lua_istable(L, 2)) pcl_argerror_full(L, fn, 2, 2, "nodes", "a list of 2..64 abscissae");
    int n = (int)luaL_len(L, 2);
    if (n < 2 || n > 64) pcl_argerror_full(L, fn, 2, 2, "nodes", "a list of 2..64 abscissae");
    double *x = numlist(L, fn, 2, "nodes", n), p[128];
    for (int j = 0; j < n; j++) {       /* the nodes (x_j, f(x_j)) at uniform t */
        lua_pushvalue(L, 1);
        lua_pushnumber(L, x[j]);
        lua_call(L, 1, 1);
        int isnum;
        p[2 * j] = x[j], p[2 * j + 1] = lua_tonumberx(L, -1, &isnum);
        if (!isnum || !isfinite(p[2 * j + 1]))
            pcl_error(L, "%s: f(%s) must be a finite number", fn, pcl_pushnum(L, x[j]));
        lua_pop(L, 1);
    }
    int st;
    pc_curve *c = pc_curve_interpolate(2, n, p, NULL, &st);
    return push(L, c, st, fn);
}

/* The optional m and {m =, divisor = "m+1"|"m"|"m-1"} from arg on: m as given or dflt, the
 * divisor in *d. */
static lua_Integer mse_opts(lua_State *L, const char *fn, int arg, lua_Integer dflt, lua_Integer lo,
                            lua_Integer hi, pc_mse_divisor *d) {
    lua_Integer m = dflt;
    *d = PC_MSE_DIV_M1;
    int opt = arg;
    if (lua_isinteger(L, arg) || (!lua_isnoneornil(L, arg) && !lua_istable(L, arg))) {
        if (!lua_isinteger(L, arg) || lua_tointeger(L, arg) < lo || lua_tointeger(L, arg) > hi) {
            lua_pushfstring(L, "a number of samples %I..%I", lo, hi);
            pcl_argerror_full(L, fn, arg, arg, "m", lua_tostring(L, -1));
        }
        m = lua_tointeger(L, arg);
        opt = arg + 1;
    }
    if (lua_isnoneornil(L, opt)) return m;
    if (!lua_istable(L, opt)) pcl_argerror_full(L, fn, opt, opt, "options", "a table {m =, divisor =}");
    lua_pushnil(L);
    while (lua_next(L, opt)) {
        const char *k = lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : NULL;
        if (!k || (strcmp(k, "m") && strcmp(k, "divisor")))
            pcl_error(L, "%s: unknown option %s (the options are m and divisor)", fn,
                      k ? k : pcl_shown(L, lua_gettop(L) - 1));
        lua_pop(L, 1);
    }
    lua_getfield(L, opt, "m");
    if (!lua_isnil(L, -1)) {
        if (!lua_isinteger(L, -1) || lua_tointeger(L, -1) < lo || lua_tointeger(L, -1) > hi)
            pcl_error(L, "%s: option m must be a number of samples %d..%d, got %s", fn, (int)lo, (int)hi,
                      pcl_shown(L, lua_gettop(L)));
        m = lua_tointeger(L, -1);
    }
    lua_getfield(L, opt, "divisor");
    if (!lua_isnil(L, -1)) {
        const char *v = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "";
        if (!strcmp(v, "m+1")) *d = PC_MSE_DIV_M1;
        else if (!strcmp(v, "m")) *d = PC_MSE_DIV_M;
        else if (!strcmp(v, "m-1")) *d = PC_MSE_DIV_MMINUS1;
        else pcl_error(L, "%s: option divisor must be \"m+1\" (the book's), \"m\" or \"m-1\", got %s", fn,
                       *v ? lua_pushfstring(L, "\"%s\"", v) : pcl_shown(L, lua_gettop(L)));
    }
    lua_pop(L, 2);
    return m;
}

static int a_mse(lua_State *L) {
    const char *fn = "approx.mse";
    lua_settop(L, 4);
    if (!callable(L, 1)) pcl_argerror_full(L, fn, 1, 1, "f", "a function of x");
    if (!lua_istable(L, 2)) pcl_argerror_full(L, fn, 2, 2, "nodes", "a list of 2..64 abscissae");
    int n = (int)luaL_len(L, 2);
    if (n < 2 || n > 64) pcl_argerror_full(L, fn, 2, 2, "nodes", "a list of 2..64 abscissae");
    double *x = numlist(L, fn, 2, "nodes", n);
    pc_mse_divisor dv;
    lua_Integer m = mse_opts(L, fn, 3, 100, 1, 1000000, &dv);
    luaref *r = checkfn(L, fn, 1);
    double mse;
    int st = pc_approx_mse(scalar_cb, r, n, x, (int)m, &mse);
    luaref_free(r);
    statuscheck(L, fn, st);
    if (pc_approx_rescale(mse, (int)m, dv, &mse) != PC_OK)
        return pcl_error(L, "%s: the divisor m - 1 is 0 for m = 1", fn);
    lua_pushnumber(L, mse);
    return 1;
}

static int a_optimal_nodes(lua_State *L) {
    const char *fn = "approx.optimal_nodes";
    if (!callable(L, 1)) pcl_argerror_full(L, fn, 1, 1, "f", "a function of x");
    double a = pcl_checknum(L, fn, 2, "a"), b = pcl_checknum(L, fn, 3, "b");
    if (!(b > a)) pcl_argerror_full(L, fn, 3, 3, "b", "greater than a");
    if (!lua_isinteger(L, 4) || lua_tointeger(L, 4) < 3 || lua_tointeger(L, 4) > 16)
        pcl_argerror_full(L, fn, 4, 4, "N", "a number of nodes 3..16");
    int N = (int)lua_tointeger(L, 4);
    pc_mse_divisor dv;
    lua_Integer m = mse_opts(L, fn, 5, 100, N, 100000, &dv);
    luaref *r = checkfn(L, fn, 1);
    double x[16], mse;
    int evals;
    int st = pc_approx_optimal_nodes(scalar_cb, r, a, b, N, (int)m, x, &mse, &evals);
    luaref_free(r);
    statuscheck(L, fn, st);
    pc_approx_rescale(mse, (int)m, dv, &mse);   /* m >= N >= 3: the divisor is positive */
    pushnums(L, N, x);
    lua_pushnumber(L, mse);
    lua_pushinteger(L, evals);
    return 3;
}

static int a_chebyshev(lua_State *L) {
    const char *fn = "approx.chebyshev";
    if (!lua_isinteger(L, 1) || lua_tointeger(L, 1) < 1 || lua_tointeger(L, 1) > 64)
        pcl_argerror_full(L, fn, 1, 1, "N", "a number of nodes 1..64");
    int N = (int)lua_tointeger(L, 1);
    double a = pcl_optnum(L, fn, 2, "a", -1), b = pcl_optnum(L, fn, 3, "b", 1), x[64];
    if (!(b > a)) pcl_argerror_full(L, fn, 3, 3, "b", "greater than a");
    pc_chebyshev_nodes(N, a, b, x);
    pushnums(L, N, x);
    return 1;
}

static int a_lagrange_mse(lua_State *L) {
    const char *fn = "approx.lagrange_mse";
    lua_settop(L, 5);
    if (!callable(L, 1)) pcl_argerror_full(L, fn, 1, 1, "f", "a function of x");
    if (!lua_istable(L, 2)) pcl_argerror_full(L, fn, 2, 2, "nodes", "a list of abscissae");
    int n = (int)luaL_len(L, 2);
    if (n < 1 || n > 64) pcl_argerror_full(L, fn, 2, 2, "nodes", "a list of 1..64 abscissae");
    double *x = numlist(L, fn, 2, "nodes", n);
    double a = pcl_checknum(L, fn, 3, "a"), b = pcl_checknum(L, fn, 4, "b");
    lua_Integer M = 101;
    if (!lua_isnoneornil(L, 5)) {
        if (!lua_isinteger(L, 5) || lua_tointeger(L, 5) < 2) pcl_argerror_full(L, fn, 5, 5, "M", "an integer >= 2");
        M = lua_tointeger(L, 5);
    }
    luaref *r = checkfn(L, fn, 1);
    double mse;
    int st = pc_lagrange_mse_x(scalar_cb, r, n, x, a, b, (int)M, &mse);
    luaref_free(r);
    if (st == PC_ECOINCIDENT) pcl_error(L, "%s: argument #2 (nodes) must be distinct", fn);
    statuscheck(L, fn, st);
    lua_pushnumber(L, mse);
    return 1;
}

/* approx.nelder_mead(f, x0 [, step]): f receives the point as numbers */
typedef struct { int ref, n, failed; } nmref;

static double nm_cb(void *ud, const double *x) {
    nmref *r = ud;
    lua_State *L = pcl_current_state();
    lua_rawgeti(L, LUA_REGISTRYINDEX, r->ref);
    for (int i = 0; i < r->n; i++) lua_pushnumber(L, x[i]);
    if (lua_pcall(L, r->n, 1, 0) != LUA_OK) {
        pcl_callback_failed(L);
        r->failed = 1;
        return NAN;
    }
    double y = lua_tonumber(L, -1);
    lua_pop(L, 1);
    return y;
}

static int a_nelder_mead(lua_State *L) {
    const char *fn = "approx.nelder_mead";
    lua_settop(L, 3);
    if (!callable(L, 1)) pcl_argerror_full(L, fn, 1, 1, "f", "a function of n numbers");
    if (!lua_istable(L, 2)) pcl_argerror_full(L, fn, 2, 2, "x0", "a list of 1..32 numbers");
    int n = (int)luaL_len(L, 2);
    if (n < 1 || n > 32) pcl_argerror_full(L, fn, 2, 2, "x0", "a list of 1..32 numbers");
    double *x = numlist(L, fn, 2, "x0", n);
    double step = pcl_optnum(L, fn, 3, "step", 0.1);
    if (!(step > 0)) pcl_argerror_full(L, fn, 3, 3, "step", "a positive number");
    nmref r = {0, n, 0};
    lua_pushvalue(L, 1);
    r.ref = luaL_ref(L, LUA_REGISTRYINDEX);
    pcl_callback_state(L);
    double fx;
    int it;
    int st = pc_nelder_mead(n, nm_cb, &r, x, step, 1e-14, 1e-10, 20000, &fx, &it);
    luaL_unref(L, LUA_REGISTRYINDEX, r.ref);
    if (r.failed) pcl_raise_status(L, fn, PC_EARG);      /* the kept Lua error */
    if (st != PC_OK && st != PC_ENOCONVERGE) pcl_raise_status(L, fn, st);
    pushnums(L, n, x);
    lua_pushnumber(L, fx);
    lua_pushinteger(L, it);
    return 3;
}

/* ==== registration ========================================================================== */

static const luaL_Reg conic_fns[] = {
    {"ed", c_ed}, {"ed_k", c_ed_k}, {"circle_k", c_circle_k}, {"ceva", c_ceva},
    {"ceva_k", c_ceva_k}, {"parabola", c_parabola}, {"ellipse", c_ellipse},
    {"hyperbola", c_hyperbola}, {"circle", c_circle}, {"tilted", c_tilted},
    {"five_points", c_five_points}, {"five_points2", c_five_points2}, {"triples", c_triples},
    {"redundant", c_redundant}, {"reparam", c_reparam}, {"sinusoid", c_sinusoid},
    {"cycloid", c_cycloid}, {"cones", c_cones}, {"contour", c_contour}, {NULL, NULL}};
static const luaL_Reg oneratio_fns[] = {
    {"simplex", o_simplex}, {"tetra", o_tetra}, {"bezier3", o_bezier3}, {"smooth", o_smooth},
    {"desargues", o_desargues}, {"double_contact", o_double_contact}, {"closed", o_closed},
    {"simplex_scheme", o_simplex_scheme}, {"levels", o_levels},
    {"desargues_scheme", o_desargues_scheme}, {NULL, NULL}};
static const luaL_Reg interp_fns[] = {
    {"lagrange", i_lagrange}, {"weights", i_weights}, {"controls", i_controls},
    {"conic", i_conic}, {"arc", i_arc}, {"adaptive", i_adaptive}, {"prototype", i_prototype},
    {"basis", i_basis}, {"rational22", i_rational22}, {NULL, NULL}};
static const luaL_Reg approx_fns[] = {
    {"curve", a_curve}, {"mse", a_mse}, {"optimal_nodes", a_optimal_nodes}, {"chebyshev", a_chebyshev},
    {"lagrange_mse", a_lagrange_mse}, {"nelder_mead", a_nelder_mead}, {NULL, NULL}};

void pcl_open_konopatsky(lua_State *L) {
    luaL_newlib(L, conic_fns);
    lua_setfield(L, -2, "conic");
    luaL_newlib(L, oneratio_fns);
    lua_createtable(L, 0, 1);           /* oneratio(A, B, C) is oneratio.simplex */
    lua_pushcfunction(L, o_simplex);
    lua_setfield(L, -2, "__call");
    lua_setmetatable(L, -2);
    lua_setfield(L, -2, "oneratio");
    luaL_newlib(L, interp_fns);
    lua_setfield(L, -2, "interp");
    luaL_newlib(L, approx_fns);
    lua_setfield(L, -2, "approx");
}
