/* Binding of the one curve type (stdlib/geom/curve.h) and its constructors:
 *   bezier{P0, P1, ...}                 Bezier of any degree; weighted points (w*P) make it
 *                                       rational, vectors are control points at infinity
 *   bspline(points, degree [, knots])   B-spline / NURBS; knots "open" (default), "uniform",
 *                                       "periodic" or a list
 *   hermite(points, tangents [, opts])  piecewise cubic Hermite {tin =, u =, closed =}
 *   cubic_spline(points [, opts])       the C2 spline {ends = "natural"|"clamped"|"periodic",
 *                                       d0 =, d1 =, u =}
 *   interpolate(points [, params])      the polynomial curve through the points
 *   curve(f, t0, t1)                    a Lua function of t as a curve
 *   spline2, stroke (via _tk.stroke), fourier: Stepanov's curves (examples 5, 10, 12)
 * All are one userdata "curve".  c(t) is the point, c:xy(t) its coordinates; the methods are
 * in the table _tk.curve_methods so that stdlib/lua/curves.lua adds draw and each. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pcl_curve.h"
#include "spline.h"
#include "fourier.h"
#include "pcl_expr.h"

#define CURVE_MT "curve"
static const char CURVE_TAG = 'c';   /* its address tags the type (PCL_SELF_TAG) */

enum { TK_NONE, TK_SPLINE2, TK_STROKE, TK_FOURIER };

typedef struct {
    PCL_SELF;           /* its own address: a forged curve is refused (pcl.h) */
    pc_curve *c;
    const char *kind;   /* the constructor's name (a static string) */
    int tk, np, n;      /* Stepanov's kinds: pieces of a stroke, n of a Fourier curve */
    double data[];      /* stroke pieces (pc_piece[np]) or Fourier coefficients */
} lcurve;

static pc_piece *pieces(lcurve *u) { return (pc_piece *)u->data; }

/* ---- Lua functions called from the core ---------------------------------------------------
 * For curve(f, ...) and for strokes whose smoothstep is a Lua function (pcl.h: a Lua error
 * must not unwind through the core's frames, so the callback keeps it). */
typedef struct {
    int ref;            /* the Lua function (registry reference) */
    int dim;
    int np;             /* > 0: a stroke blended by the Lua smoothstep ref */
    pc_piece p[];
} luafn;

static void luafn_free(void *ud) {
    luafn *f = ud;
    lua_State *L = pcl_current_state();
    if (L) luaL_unref(L, LUA_REGISTRYINDEX, f->ref);
    free(f);
}

/* The value a Lua curve function returned (at the top nres results) as homogeneous h. */
static int read_result(lua_State *L, int nres, int dim, double *h) {
    int base = lua_gettop(L) - nres + 1;
    pcl_value *v = nres >= 1 ? pcl_tovalue(L, base) : NULL;
    if (v) {
        if (v->n != dim) {
            lua_pushfstring(L, "curve: the function returned a %d-D value, but the curve is %d-D",
                            v->n, dim);
            return 0;
        }
        memcpy(h, v->h, sizeof(double) * (size_t)(dim + 1));
        return 1;
    }
    if (nres != dim) {
        lua_pushfstring(L, "curve: the function must return a %d-D point or %d numbers, got %s",
                        dim, dim, nres ? luaL_typename(L, base) : "nothing");
        return 0;
    }
    for (int k = 0; k < dim; k++) {
        int isnum;
        h[k] = lua_tonumberx(L, base + k, &isnum);
        if (!isnum) {
            lua_pushfstring(L, "curve: the function must return numbers, got %s",
                            luaL_typename(L, base + k));
            return 0;
        }
    }
    h[dim] = 1;
    return 1;
}

static int luafn_eval(void *ud, double t, int order, double *out) {
    luafn *f = ud;
    lua_State *L = pcl_current_state();
    if (order > 0) return PC_EDOMAIN;            /* the core differences */
    int top = lua_gettop(L);
    if (!lua_checkstack(L, f->dim + 4)) return PC_ENOMEM;
    lua_rawgeti(L, LUA_REGISTRYINDEX, f->ref);
    if (f->np == 0) {
        lua_pushnumber(L, t);
        if (lua_pcall(L, 1, LUA_MULTRET, 0) != LUA_OK) return pcl_callback_failed(L);
        int ok = read_result(L, lua_gettop(L) - top, f->dim, out);
        if (!ok) return pcl_callback_failed(L);
        lua_settop(L, top);
        return PC_OK;
    }
    /* a stroke with a Lua smoothstep: piece floor(t), the ends extrapolating */
    double fl = floor(t);
    int i = fl < 0 ? 0 : (fl > f->np - 1 ? f->np - 1 : (int)fl);
    double s = t - i;
    lua_pushnumber(L, s);
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) return pcl_callback_failed(L);
    int isnum;
    double g = lua_tonumberx(L, -1, &isnum);
    if (!isnum) {
        lua_pushfstring(L, "curve: the smoothstep g must return a number, got %s",
                        luaL_typename(L, -1));
        return pcl_callback_failed(L);
    }
    if (!isfinite(g)) {
        const char *ts = pcl_pushnum(L, s), *gs = pcl_pushnum(L, g);
        lua_pushfstring(L, "curve: the smoothstep g must return a finite number, got g(%s) = %s",
                        ts, gs);
        return pcl_callback_failed(L);
    }
    lua_settop(L, top);
    const pc_piece *p = &f->p[i];
    pc_qspline(f->dim, p->a, p->p, p->q, p->b, s, g, out);
    out[f->dim] = 1;
    return PC_OK;
}

/* ---- the userdata ---------------------------------------------------------------------------- */

static lcurve *newcurve(lua_State *L, pc_curve *c, const char *kind, size_t extra) {
    lcurve *u = lua_newuserdatauv(L, sizeof(lcurve) + extra, 1);   /* uv 1: a Lua smoothstep */
    memset(u, 0, sizeof *u);
    u->self = PCL_SELF_TAG(u, &CURVE_TAG);
    u->c = c;
    u->kind = kind;
    luaL_setmetatable(L, CURVE_MT);
    return u;
}

/* Push a new curve object for c (or raise the core's status when c is NULL). */
static lcurve *pushcurve(lua_State *L, pc_curve *c, int status, const char *kind, size_t extra) {
    if (!c) pcl_raise_status(L, kind, status);
    return newcurve(L, c, kind, extra);
}

static int callable(lua_State *L, int idx) {
    if (lua_isfunction(L, idx)) return 1;
    if (luaL_getmetafield(L, idx, "__call") == LUA_TNIL) return 0;
    lua_pop(L, 1);
    return 1;
}

/* The curve object at idx or NULL; one given the metatable by the debug library is refused. */
static lcurve *tocurve(lua_State *L, int idx) {
    lcurve *u = luaL_testudata(L, idx, CURVE_MT);
    int ok = !u || (lua_rawlen(L, idx) >= sizeof *u && u->self == PCL_SELF_TAG(u, &CURVE_TAG));
    return pcl_genuine(L, idx, u, ok, "curve");
}

pc_curve *pcl_tocurve(lua_State *L, int idx) {
    lcurve *u = tocurve(L, idx);
    return u ? u->c : NULL;
}

void pcl_pushcurve(lua_State *L, pc_curve *c, const char *kind) {
    (void)newcurve(L, c, kind, 0);
}

static lcurve *checkcurve(lua_State *L, int idx, const char *fname) {
    lcurve *u = tocurve(L, idx);
    if (!u || !u->c) pcl_argerror_full(L, fname, idx, idx, "self", "a curve");
    pcl_callback_state(L);
    return u;
}

static int c_gc(lua_State *L) {
    lcurve *u = luaL_testudata(L, 1, CURVE_MT);
    /* never a forged one */
    if (u && lua_rawlen(L, 1) >= sizeof *u && u->self == PCL_SELF_TAG(u, &CURVE_TAG) && u->c) {
        pcl_callback_state(L);
        pc_curve_release(u->c);
        u->c = NULL;
    }
    return 0;
}

/* ---- reading points ------------------------------------------------------------------------- */

/* The values of the list at arg as homogeneous rows (any weight: w*P is a weighted control
 * point, a vector one at infinity) into a new scratch userdata; returns the count. */
static double *read_values(lua_State *L, const char *fn, int arg, const char *what, int min,
                           int *count, int *dim) {
    if (!lua_istable(L, arg)) {
        lua_pushfstring(L, "a list of at least %d points", min);
        pcl_argerror_full(L, fn, arg, arg, what, lua_tostring(L, -1));
    }
    int m = (int)luaL_len(L, arg);
    if (m < min) {
        lua_pushfstring(L, "a list of at least %d points, got %d", min, m);
        pcl_error(L, "%s: argument #%d (%s) must be %s", fn, arg, what, lua_tostring(L, -1));
    }
    if (m > 100000) pcl_error(L, "%s: argument #%d (%s) holds too many points (%d)", fn, arg, what, m);
    int d = 0;
    double *h = NULL;
    for (int i = 1; i <= m; i++) {
        lua_geti(L, arg, i);
        pcl_value *v = pcl_tovalue(L, -1);
        if (!v) pcl_error(L, "%s: argument #%d (%s) item [%d] must be a point, got %s", fn, arg,
                          what, i, luaL_typename(L, -1));
        if (i == 1) {
            d = v->n;
            lua_pop(L, 1);
            h = lua_newuserdatauv(L, sizeof(double) * (size_t)m * (size_t)(d + 1), 0);
            lua_insert(L, -1);
            lua_geti(L, arg, i);
            v = pcl_tovalue(L, -1);
        } else if (v->n != d) {
            pcl_error(L, "%s: argument #%d (%s) item [%d] is %d-D, but item [1] is %d-D: "
                      "dimensions cannot be mixed", fn, arg, what, i, v->n, d);
        }
        for (int k = 0; k <= d; k++) {
            if (!isfinite(v->h[k]))
                pcl_error(L, "%s: argument #%d (%s) item [%d] has NaN or infinite coordinates",
                          fn, arg, what, i);
            h[(size_t)(i - 1) * (d + 1) + k] = v->h[k];
        }
        lua_pop(L, 1);
    }
    *count = m;
    *dim = d;
    return h;   /* the scratch userdata stays on the stack */
}

/* Cartesian rows (weight 1 required, or 0 when vectors is set) from homogeneous ones. */
static void cartesian(lua_State *L, const char *fn, int arg, const char *what, int m, int d,
                      double *h, int vectors) {
    for (int i = 0; i < m; i++) {
        double w = h[(size_t)i * (d + 1) + d];
        if (vectors ? fabs(w) > PC_WEIGHT_TOL : fabs(w - 1) > PC_WEIGHT_TOL)
            pcl_error(L, "%s: argument #%d (%s) item [%d] must be a %s (weight %d), got weight %s",
                      fn, arg, what, i + 1, vectors ? "vector" : "point", vectors ? 0 : 1,
                      pcl_pushnum(L, w));
    }
    /* compact in place: row i of d+1 -> row i of d */
    for (int i = 0; i < m; i++)
        for (int k = 0; k < d; k++) h[(size_t)i * d + k] = h[(size_t)i * (d + 1) + k];
}

/* A list of m finite numbers at arg (or the field of an options table on the stack top). */
static double *read_numbers(lua_State *L, const char *fn, int idx, const char *what, int m) {
    idx = lua_absindex(L, idx);
    if (!lua_istable(L, idx) || (int)luaL_len(L, idx) != m) {
        lua_pushfstring(L, "a list of %d numbers", m);
        pcl_error(L, "%s: %s must be %s", fn, what, lua_tostring(L, -1));
    }
    double *x = lua_newuserdatauv(L, sizeof(double) * (size_t)(m ? m : 1), 0);
    for (int i = 0; i < m; i++) {
        lua_geti(L, idx, i + 1);
        int isnum;
        x[i] = lua_tonumberx(L, -1, &isnum);
        if (!isnum || !isfinite(x[i]))
            pcl_error(L, "%s: %s[%d] must be a finite number, got %s", fn, what, i + 1,
                      isnum ? pcl_pushnum(L, x[i]) : luaL_typename(L, -1));
        lua_pop(L, 1);
    }
    return x;   /* stays on the stack */
}

/* ---- constructors ------------------------------------------------------------------------------ */

static int l_bezier(lua_State *L) {
    int m, d;
    double *h = read_values(L, "bezier", 1, "points", 2, &m, &d);
    int st;
    pc_curve *c = pc_curve_bezier(d, m, h, &st);
    pushcurve(L, c, st, "bezier", 0);
    return 1;
}

pc_knot_kind pcl_checkknots(lua_State *L, const char *fn, int arg, int ncp, int degree,
                            double **knots) {
    *knots = NULL;
    if (lua_isnoneornil(L, arg)) return PC_KNOTS_OPEN;
    if (lua_type(L, arg) == LUA_TSTRING) {
        const char *s = lua_tostring(L, arg);
        if (!strcmp(s, "open")) return PC_KNOTS_OPEN;
        if (!strcmp(s, "uniform")) return PC_KNOTS_UNIFORM;
        if (!strcmp(s, "periodic")) return PC_KNOTS_PERIODIC;
    } else if (lua_istable(L, arg)) {
        int want = ncp + degree + 1, got = (int)luaL_len(L, arg);
        if (got != want)
            pcl_error(L, "%s: argument #%d (knots) must hold points + degree + 1 = %d knots, got %d",
                      fn, arg, want, got);
        *knots = read_numbers(L, fn, arg, "knots", want);
        for (int i = 1; i < want; i++)
            if ((*knots)[i] < (*knots)[i - 1])
                pcl_error(L, "%s: argument #%d (knots) must be non-decreasing, but knot [%d] = %s "
                          "is less than knot [%d] = %s", fn, arg, i + 1, pcl_pushnum(L, (*knots)[i]),
                          i, pcl_pushnum(L, (*knots)[i - 1]));
        return PC_KNOTS_GIVEN;
    }
    return pcl_argerror_full(L, fn, arg, arg, "knots",
                       "\"open\", \"uniform\", \"periodic\" or a list of numbers");
}

static int l_bspline(lua_State *L) {
    const char *fn = "bspline";
    lua_settop(L, 3);
    int m, d;
    double *h = read_values(L, fn, 1, "points", 2, &m, &d);
    if (lua_type(L, 2) != LUA_TNUMBER || !lua_isinteger(L, 2))
        pcl_argerror_full(L, fn, 2, 2, "degree", "an integer");
    lua_Integer p = lua_tointeger(L, 2);
    if (lua_type(L, 3) == LUA_TSTRING && !strcmp(lua_tostring(L, 3), "periodic")) {
        if (p < 1 || p > m) {
            lua_pushfstring(L, "an integer 1..%d (the number of points)", m);
            pcl_argerror_full(L, fn, 2, 2, "degree", lua_tostring(L, -1));
        }
    } else if (p < 1 || p >= m) {
        lua_pushfstring(L, "an integer 1..%d (fewer than the %d points)", m - 1, m);
        pcl_argerror_full(L, fn, 2, 2, "degree", lua_tostring(L, -1));
    }
    if (p > PC_CURVE_MAXDEG) pcl_error(L, "%s: the degree is at most %d", fn, PC_CURVE_MAXDEG);
    double *knots;
    pc_knot_kind kk = pcl_checkknots(L, fn, 3, m, (int)p, &knots);
    int st;
    pc_curve *c = pc_curve_bspline(d, (int)p, m, h, kk, knots, &st);
    pushcurve(L, c, st, "bspline", 0);
    return 1;
}

/* The options table at arg (nil allowed); returns whether there is one. */
static int opts_table(lua_State *L, const char *fn, int arg) {
    if (lua_isnoneornil(L, arg)) return 0;
    if (!lua_istable(L, arg)) pcl_argerror_full(L, fn, arg, arg, "opts", "a table");
    return 1;
}

/* opts.u: a list of n increasing parameters, or NULL */
static double *opt_params(lua_State *L, const char *fn, int opts, const char *field, int n) {
    if (!opts) return NULL;
    if (lua_getfield(L, opts, field) == LUA_TNIL) {
        lua_pop(L, 1);
        return NULL;
    }
    double *u = read_numbers(L, fn, -1, field, n);
    lua_remove(L, -2);
    return u;
}

static int l_hermite(lua_State *L) {
    const char *fn = "hermite";
    lua_settop(L, 3);
    int n, d, nt, dt;
    double *p = read_values(L, fn, 1, "points", 2, &n, &d);
    cartesian(L, fn, 1, "points", n, d, p, 0);
    double *t = read_values(L, fn, 2, "tangents", 1, &nt, &dt);
    if (nt != n || dt != d)
        pcl_error(L, "%s: argument #2 (tangents) must hold %d %d-D vectors, one per point, got %d "
                  "%d-D", fn, n, d, nt, dt);
    cartesian(L, fn, 2, "tangents", n, d, t, 1);
    int opts = opts_table(L, fn, 3) ? 3 : 0;
    double *tin = NULL;
    int closed = 0;
    if (opts) {
        if (lua_getfield(L, opts, "tin") != LUA_TNIL) {
            int ni, di;
            tin = read_values(L, fn, lua_gettop(L), "tin", 1, &ni, &di);
            if (ni != n || di != d)
                pcl_error(L, "%s: opts.tin must hold %d %d-D vectors", fn, n, d);
            cartesian(L, fn, 3, "tin", n, d, tin, 1);
        }
        lua_getfield(L, opts, "closed");
        closed = lua_toboolean(L, -1);
        lua_pop(L, 1);
    }
    double *u = opt_params(L, fn, opts, "u", n);
    int st;
    pc_curve *c = pc_curve_hermite(d, n, p, t, tin, u, closed, &st);
    pushcurve(L, c, st, "hermite", 0);
    return 1;
}

static int l_cubic_spline(lua_State *L) {
    const char *fn = "cubic_spline";
    lua_settop(L, 2);
    int n, d;
    double *p = read_values(L, fn, 1, "points", 2, &n, &d);
    cartesian(L, fn, 1, "points", n, d, p, 0);
    int opts = opts_table(L, fn, 2) ? 2 : 0;
    pc_end_kind ends = PC_END_NATURAL;
    double d0[PC_MAXDIM], d1[PC_MAXDIM];
    if (opts) {
        if (lua_getfield(L, opts, "ends") != LUA_TNIL) {
            const char *s = lua_tostring(L, -1);
            if (s && !strcmp(s, "natural")) ends = PC_END_NATURAL;
            else if (s && !strcmp(s, "clamped")) ends = PC_END_CLAMPED;
            else if (s && !strcmp(s, "periodic")) ends = PC_END_PERIODIC;
            else pcl_error(L, "%s: opts.ends must be \"natural\", \"clamped\" or \"periodic\", got %s",
                           fn, s ? s : luaL_typename(L, -1));
        }
        lua_pop(L, 1);
        if (ends == PC_END_CLAMPED) {
            const char *names[2] = {"d0", "d1"};
            double *dst[2] = {d0, d1};
            for (int e = 0; e < 2; e++) {
                lua_getfield(L, opts, names[e]);
                pcl_value *v = pcl_tovalue(L, -1);
                if (!v || v->n != d || fabs(v->h[d]) > PC_WEIGHT_TOL)
                    pcl_error(L, "%s: opts.%s must be a %d-D vector (the end derivative) for "
                              "clamped ends, got %s", fn, names[e], d,
                              v ? "a point or another dimension" : luaL_typename(L, -1));
                memcpy(dst[e], v->h, sizeof(double) * (size_t)d);
                lua_pop(L, 1);
            }
        }
    }
    double *u = opt_params(L, fn, opts, "u", n);
    int st;
    pc_curve *c = pc_curve_cubic_spline(d, n, p, u, ends, d0, d1, &st);
    pushcurve(L, c, st, "cubic_spline", 0);
    return 1;
}

static int l_interpolate(lua_State *L) {
    const char *fn = "interpolate";
    lua_settop(L, 2);
    int n, d;
    double *p = read_values(L, fn, 1, "points", 2, &n, &d);
    cartesian(L, fn, 1, "points", n, d, p, 0);
    if (n > PC_CURVE_MAXDEG + 1) pcl_error(L, "%s: at most %d points", fn, PC_CURVE_MAXDEG + 1);
    double *u = NULL;
    if (!lua_isnoneornil(L, 2)) u = read_numbers(L, fn, 2, "argument #2 (params)", n);
    int st;
    pc_curve *c = pc_curve_interpolate(d, n, p, u, &st);
    pushcurve(L, c, st, "interpolate", 0);
    return 1;
}

/* curve(f, t0, t1): the dimension is that of f(t0) */
static int l_curve(lua_State *L) {
    const char *fn = "curve";
    if (pcl_isequation(L, 1)) {                 /* a compiled point equation (l_expr.c) */
        int st;
        pc_curve *c = pcl_eq_curve(L, fn, &st);
        pushcurve(L, c, st, "equation", 0);
        return 1;
    }
    if (!callable(L, 1)) pcl_argerror_full(L, fn, 1, 1, "f", "a function of t or an equation");
    double t0 = pcl_checknum(L, fn, 2, "t0"), t1 = pcl_checknum(L, fn, 3, "t1");
    if (!(t1 > t0)) pcl_error(L, "%s: argument #3 (t1) must be greater than t0", fn);
    lua_settop(L, 3);
    lua_pushvalue(L, 1);
    lua_pushnumber(L, t0);
    lua_call(L, 1, LUA_MULTRET);
    int nres = lua_gettop(L) - 3, d;
    pcl_value *v = nres ? pcl_tovalue(L, 4) : NULL;
    d = v ? v->n : nres;
    for (int i = 0; !v && i < nres; i++)
        if (lua_type(L, 4 + i) != LUA_TNUMBER)
            pcl_error(L, "%s: a curve must return a point or numbers, got %s", fn,
                      luaL_typename(L, 4 + i));
    if (d < 1 || d > PC_MAXDIM)
        pcl_error(L, "%s: a curve must return a point or 1..%d numbers, got %s", fn, PC_MAXDIM,
                  nres ? luaL_typename(L, 4) : "nothing");
    lua_settop(L, 3);
    luafn *f = malloc(sizeof *f);
    if (!f) return pcl_error(L, "%s: out of memory", fn);
    f->dim = d;
    f->np = 0;
    lua_pushvalue(L, 1);
    f->ref = luaL_ref(L, LUA_REGISTRYINDEX);
    int st;
    pcl_callback_state(L);
    pc_curve *c = pc_curve_func(d, t0, t1, 0, luafn_eval, luafn_free, f, &st);
    pushcurve(L, c, st, fn, 0);
    return 1;
}

/* ---- Stepanov's curves ------------------------------------------------------------------------- */

/* The smoothstep at idx: nil (the default kind dflt), smooth.sine, smooth.cubic, a half-spline
 * object, or any other callable (then *lua is set). */
static void check_g(lua_State *L, const char *fname, int idx, int dflt, pc_gfun *g, int *lua) {
    *lua = 0;
    memset(g, 0, sizeof *g);
    g->kind = (pc_gkind)dflt;
    if (lua_isnoneornil(L, idx)) return;
    int kind;
    if (lua_iscfunction(L, idx) && pcl_smooth_isfunc(lua_tocfunction(L, idx), &kind)) {
        g->kind = (pc_gkind)kind;
        return;
    }
    pc_hspline *h = pcl_tohspline(L, idx);
    if (h) {
        g->kind = PC_G_HALF;
        g->h = *h;
        return;
    }
    if (callable(L, idx)) {
        *lua = 1;
        return;
    }
    pcl_argerror_full(L, fname, idx, idx, "g", "a smoothstep (a function of t)");
}

/* A stroke (or spline2) of np pieces as a curve: C smoothsteps in the core, a Lua one through
 * the callback. */
static lcurve *push_stroke(lua_State *L, const char *kind, int tk, int d, int np, int closed,
                           const pc_piece *pc, int lua, int gidx) {
    int st;
    pc_curve *c;
    pcl_callback_state(L);
    if (lua) {
        luafn *f = malloc(sizeof *f + sizeof(pc_piece) * (size_t)np);
        if (!f) pcl_error(L, "%s: out of memory", kind);
        f->dim = d;
        f->np = np;
        memcpy(f->p, pc, sizeof(pc_piece) * (size_t)np);
        lua_pushvalue(L, gidx);
        f->ref = luaL_ref(L, LUA_REGISTRYINDEX);
        c = pc_curve_func(d, 0, np, closed, luafn_eval, luafn_free, f, &st);
    } else {
        c = pc_curve_stroke(d, np, pc, closed, &st);
    }
    lcurve *u = pushcurve(L, c, st, kind, sizeof(pc_piece) * (size_t)np);
    u->tk = tk;
    u->np = np;
    memcpy(pieces(u), pc, sizeof(pc_piece) * (size_t)np);
    if (lua) {
        lua_pushvalue(L, gidx);
        lua_setiuservalue(L, -2, 1);
    }
    return u;
}

static int l_spline2(lua_State *L) {
    const char *fn = "spline2";
    double A[PC_MAXDIM], a[PC_MAXDIM], B[PC_MAXDIM], b[PC_MAXDIM];
    int d = pcl_checkloc(L, 1, "A", 0, 0, A);
    if (d > PC_CURVE_MAXDIM)
        return pcl_error(L, "%s: argument #1 (A) must be a point of dimension 1..%d, got %d-D", fn, PC_CURVE_MAXDIM, d);
    pcl_checkvec(L, 2, "a", d, 1, a);
    pcl_checkloc(L, 3, "B", d, 1, B);
    pcl_checkvec(L, 4, "b", d, 1, b);
    pc_gfun g;
    int lua;
    check_g(L, fn, 5, PC_G_CUBIC, &g, &lua);
    pc_piece pc;
    memset(&pc, 0, sizeof pc);
    for (int k = 0; k < d; k++) {
        pc.a[k] = A[k];
        pc.p[k] = A[k] + a[k];
        pc.q[k] = B[k] - b[k];
        pc.b[k] = B[k];
    }
    pc.g = g;
    push_stroke(L, fn, TK_SPLINE2, d, 1, 0, &pc, lua, 5);
    return 1;
}

/* a flat array of numbers from table arg (nil allowed when optional): count entries, NaN for
 * a missing one */
static double *flat_numbers(lua_State *L, int arg, int count, double *buf, int optional) {
    if (lua_isnoneornil(L, arg)) {
        if (optional) return NULL;
        pcl_error(L, "_tk.stroke: argument #%d missing", arg);
    }
    luaL_checktype(L, arg, LUA_TTABLE);
    for (int i = 0; i < count; i++) {
        lua_geti(L, arg, i + 1);
        int isnum;
        buf[i] = lua_tonumberx(L, -1, &isnum);
        if (!isnum) buf[i] = NAN;
        lua_pop(L, 1);
    }
    return buf;
}

/* _tk.stroke(d, closed, nodes, ein, eout, rin, rout, n, m, t0 [, g]) -> curve, or
 * nil, status, bad node (1-based), message.  Arrays are flat (nodes, ein, eout: k rows of d)
 * with NaN for "default"; ein, eout, rin, rout may be nil. */
static int l_stroke_raw(lua_State *L) {
    lua_settop(L, 11);
    int d = (int)luaL_checkinteger(L, 1);
    int closed = lua_toboolean(L, 2);
    luaL_checktype(L, 3, LUA_TTABLE);
    int k = (int)(luaL_len(L, 3) / (d > 0 ? d : 1));
    if (d < 1 || d > PC_CURVE_MAXDIM || k < 2) pcl_error(L, "_tk.stroke: bad dimension or count");
    size_t sz = (size_t)k * (size_t)d;
    double *buf = lua_newuserdatauv(L, sizeof(double) * (sz * 3 + (size_t)k * 5), 0);
    double *nodes = flat_numbers(L, 3, (int)sz, buf, 0);
    double *ein = flat_numbers(L, 4, (int)sz, buf + sz, 1);
    double *eout = flat_numbers(L, 5, (int)sz, buf + 2 * sz, 1);
    double *rin = flat_numbers(L, 6, k, buf + 3 * sz, 1);
    double *rout = flat_numbers(L, 7, k, buf + 3 * sz + k, 1);
    double *n = flat_numbers(L, 8, k, buf + 3 * sz + 2 * k, 1);
    double *m = flat_numbers(L, 9, k, buf + 3 * sz + 3 * k, 1);
    double *t0 = flat_numbers(L, 10, k, buf + 3 * sz + 4 * k, 1);
    pc_gfun g;
    int lua;
    check_g(L, "stroke", 11, PC_G_HALF, &g, &lua);
    int np = pc_stroke_npieces(k, closed);
    pc_stroke_spec spec = {.d = d, .nnodes = k, .closed = closed, .nodes = nodes, .ein = ein,
                           .eout = eout, .rin = rin, .rout = rout, .n = n, .m = m, .t0 = t0};
    pc_piece *pc = lua_newuserdatauv(L, sizeof(pc_piece) * (size_t)np, 0);
    int bad;
    int st = pc_stroke_build(&spec, pc, &bad);
    if (st != PC_OK) {
        lua_pushnil(L);
        lua_pushinteger(L, st);
        lua_pushinteger(L, bad + 1);
        lua_pushstring(L, pc_strerror(st));
        return 4;
    }
    if (lua || !lua_isnoneornil(L, 11))
        for (int i = 0; i < np; i++) pc[i].g = g;
    push_stroke(L, "stroke", TK_STROKE, d, np, closed, pc, lua, 11);
    return 1;
}

static int l_fourier(lua_State *L) {
    const char *fn = "fourier";
    if (!lua_istable(L, 1)) pcl_argerror_full(L, fn, 1, 1, "points", "a list of 2n points");
    int count = (int)luaL_len(L, 1);
    if (count < 2 || count % 2) {
        lua_pushfstring(L, "a list of an even number (2n >= 2) of points, got %d", count);
        return pcl_error(L, "%s: argument #1 (points) must be %s", fn, lua_tostring(L, -1));
    }
    int n = count / 2, d = 0;
    double *samples = NULL;
    for (int i = 0; i < count; i++) {
        lua_geti(L, 1, i + 1);
        pcl_value *p = pcl_tovalue(L, -1);
        double loc[PC_MAXDIM];
        if (!p || pc_loc(p->n, p->h, loc) != PC_OK)
            return pcl_error(L, "%s: points[%d] must be a point, got %s", fn, i + 1,
                              p ? "a vector or weighted value" : luaL_typename(L, -1));
        if (i == 0) {
            d = p->n;
            if (d > PC_CURVE_MAXDIM)
                return pcl_error(L, "%s: points must be 1-D to %d-D, got %d-D", fn, PC_CURVE_MAXDIM, d);
            samples = lua_newuserdatauv(L, sizeof(double) * (size_t)count * (size_t)d, 0);
            lua_insert(L, -2);
        } else if (p->n != d) {
            return pcl_error(L, "%s: points[%d] is %d-D, but points[1] is %d-D: dimensions "
                              "cannot be mixed", fn, i + 1, p->n, d);
        }
        for (int k = 0; k < d; k++) samples[i * d + k] = loc[k];
        lua_pop(L, 1);
    }
    int m = n + 1, st;
    pc_curve *c = pc_curve_fourier(d, n, samples, &st);
    lcurve *u = pushcurve(L, c, st, fn, sizeof(double) * (size_t)(2 * m * d));
    u->tk = TK_FOURIER;
    u->n = n;
    for (int k = 0; k < d; k++) {   /* the coefficients again, for c:coef */
        st = pc_fourier_coef(n, samples + k, d, u->data + 2 * k * m, u->data + (2 * k + 1) * m);
        if (st != PC_OK) return pcl_statuserror(L, fn, st, "points");
    }
    return 1;
}

static int l_sphdir(lua_State *L) {
    double u1 = pcl_checknum(L, "sphdir", 1, "u1"), u2 = pcl_checknum(L, "sphdir", 2, "u2");
    double e[3];
    pc_dir3(u1, u2, e);
    pcl_pushvector(L, 3, e);
    return 1;
}

/* ---- evaluation methods ------------------------------------------------------------------------ */

/* A stroke piece's half-spline of fractional degree has no value past its ends: say which. */
static int domain_error(lua_State *L, lcurve *u, const char *fname, double t) {
    if (u->tk == TK_STROKE || u->tk == TK_SPLINE2) {
        double fl = floor(t);
        int i = fl < 0 ? 0 : (fl > u->np - 1 ? u->np - 1 : (int)fl);
        pc_piece *pc = &pieces(u)[i];
        double s = t - i;
        if (pc->g.kind == PC_G_HALF && pc_gfun_check(&pc->g, s) != PC_OK) {
            int low = s < 0;
            const char *deg = pcl_pushnum(L, low ? pc->g.h.n : pc->g.h.m);
            const char *bound = pcl_pushnum(L, low ? 0 : u->np);
            lua_pushfstring(L, "%s %s (piece %d's half-spline has the fractional degree %s = %s "
                            "and does not extrapolate)", low ? "at least" : "at most", bound,
                            i + 1, low ? "n" : "m", deg);
            return pcl_argerror_full(L, fname, 2, 1, "t", lua_tostring(L, -1));
        }
    }
    return pcl_raise_status(L, fname, PC_EDOMAIN);
}

static void eval_at(lua_State *L, lcurve *u, double t, double *h, const char *fname) {
    int st = pc_curve_eval_h(u->c, t, 0, h);
    if (st == PC_EDOMAIN) domain_error(L, u, fname, t);
    if (st != PC_OK) pcl_raise_status(L, fname, st);
}

/* c(t): the value at t, a point (a vector where the curve is at infinity; a rational curve's
 * value is normalised to weight 1) */
static void push_h(lua_State *L, int d, const double *h) {
    pcl_value *v = pcl_newvalue(L, d);
    double w = h[d];
    if (w != 0) {
        for (int k = 0; k < d; k++) v->h[k] = h[k] / w;
        v->h[d] = 1;
    } else {
        memcpy(v->h, h, sizeof(double) * (size_t)d);
        v->h[d] = 0;
    }
}

static int c_call(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "curve");
    if (lua_type(L, 2) == LUA_TUSERDATA && pcl_eq_curve_apply(L, u->c, 2)) return 1;   /* C(u^2) */
    double h[PC_MAXDIM + 1];
    eval_at(L, u, pcl_checknum_m(L, u->kind, 2, "t"), h, u->kind);
    push_h(L, u->c->dim, h);
    return 1;
}

static int c_xy(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:xy");
    double h[PC_MAXDIM + 1];
    eval_at(L, u, pcl_checknum_m(L, "c:xy", 2, "t"), h, "c:xy");
    int d = u->c->dim;
    if (h[d] == 0)
        return pcl_error(L, "c:xy: the curve is at infinity at t = %s", pcl_pushnum(L, lua_tonumber(L, 2)));
    for (int k = 0; k < d; k++) lua_pushnumber(L, h[k] / h[d]);
    return d;
}

/* c:deriv(t [, order]) -> the derivative vector (order 1 or 2) */
/* c:deriv(t [, order] [, "left"|"right"]): any order; at a joint the right-hand piece unless
 * "left" is asked for */
static int c_deriv(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:deriv");
    double t = pcl_checknum_m(L, "c:deriv", 2, "t");
    int sarg = 3;
    lua_Integer order = 1;
    if (lua_type(L, 3) == LUA_TNUMBER) {
        if (!lua_isinteger(L, 3)) pcl_argerror_full(L, "c:deriv", 3, 2, "order", "a whole number from 1 to 64");
        order = lua_tointeger(L, 3);
        sarg = 4;
    } else if (!lua_isnoneornil(L, 3) && lua_type(L, 3) != LUA_TSTRING) {
        pcl_argerror_full(L, "c:deriv", 3, 2, "order", "a whole number from 1 to 64, or \"left\" / \"right\"");
    }
    if (order < 1 || order > PC_CURVE_MAXDEG) pcl_argerror_full(L, "c:deriv", 3, 2, "order", "a whole number from 1 to 64");
    int side = 0;
    if (!lua_isnoneornil(L, sarg)) {
        const char *sd = lua_tostring(L, sarg);
        if (lua_type(L, sarg) != LUA_TSTRING || (strcmp(sd, "left") && strcmp(sd, "right")))
            pcl_argerror_full(L, "c:deriv", sarg, sarg - 1, "side", "\"left\" or \"right\"");
        side = sd[0] == 'l' ? -1 : 1;
    }
    int d = u->c->dim;
    double out[(PC_CURVE_MAXDEG + 1) * PC_MAXDIM];
    pcl_callback_state(L);
    int st = pc_curve_derivs_n(u->c, t, (int)order, side, out);
    if (st == PC_IMPROPER) return pcl_error(L, "c:deriv: the curve is at infinity at t = %s", pcl_pushnum(L, t));
    if (st == PC_EDOMAIN && u->c->kind == PC_CURVE_FUNC)
        return pcl_error(L, "c:deriv: a function curve gives derivatives up to order 2, not %d", (int)order);
    if (st != PC_OK) return pcl_raise_status(L, "c:deriv", st);
    pcl_pushvector(L, d, out + (size_t)order * d);
    return 1;
}

/* c:monomial([piece]): the power-basis coefficients of a piece in the curve's parameter:
 * {{a0, a1, ...} of x, {...} of y, ...}, and w = {...} for a rational curve */
static int c_monomial(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:monomial");
    const pc_curve *c = u->c;
    lua_Integer piece = 1;
    if (!lua_isnoneornil(L, 2)) {
        if (!lua_isinteger(L, 2)) pcl_argerror_full(L, "c:monomial", 2, 1, "piece", "a whole number");
        piece = lua_tointeger(L, 2);
    }
    if (c->kind == PC_CURVE_FUNC)
        return pcl_error(L, "c:monomial: a function curve has no power-basis coefficients (only Bezier and B-spline curves)");
    int np = c->kind == PC_CURVE_BEZIER ? c->nknots - 1 : 0;
    if (c->kind == PC_CURVE_BSPLINE)
        for (int k = c->degree; k < c->ncp; k++) np += c->knots[k] < c->knots[k + 1];
    if (piece < 1 || piece > np)
        return pcl_error(L, "c:monomial: argument #1 (piece) must be from 1 to %d (the curve's pieces), got %d", np, (int)piece);
    double coef[(PC_CURVE_MAXDEG + 1) * (PC_MAXDIM + 1)];
    int deg, st = pc_curve_monomial(c, (int)piece - 1, coef, &deg);
    if (st != PC_OK) return pcl_raise_status(L, "c:monomial", st);
    int n = c->dim, w = n + 1, rational = 0;
    for (int j = 0; j <= deg; j++)
        if (fabs(coef[j * w + n] - (j == 0)) > 1e-12) rational = 1;
    lua_createtable(L, n, 1);
    for (int x = 0; x <= n; x++) {
        if (x == n && !rational) break;
        lua_createtable(L, deg + 1, 0);
        for (int j = 0; j <= deg; j++) {
            lua_pushnumber(L, coef[j * w + x] + 0.0);
            lua_rawseti(L, -2, j + 1);
        }
        if (x < n) lua_rawseti(L, -2, x + 1);
        else lua_setfield(L, -2, "w");
    }
    return 1;
}

static int c_tangent(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:tangent");
    double t = pcl_checknum_m(L, "c:tangent", 2, "t");
    int d = u->c->dim;
    double out[2 * PC_MAXDIM], e[PC_MAXDIM];
    int st = pc_curve_derivs(u->c, t, 1, out);
    if (st == PC_IMPROPER) return pcl_error(L, "c:tangent: the curve is at infinity at t = %s", pcl_pushnum(L, t));
    if (st != PC_OK) return pcl_raise_status(L, "c:tangent", st);
    if (pc_unit(d, out + d, e) != PC_OK)
        return pcl_error(L, "c:tangent: the derivative is zero at t = %s (a cusp or a stop)", pcl_pushnum(L, t));
    pcl_pushvector(L, d, e);
    return 1;
}

/* c:normal(t): the unit principal normal (in the plane: the tangent turned by +90 degrees) */
static int c_normal(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:normal");
    double t = pcl_checknum_m(L, "c:normal", 2, "t");
    int d = u->c->dim;
    double out[3 * PC_MAXDIM], e[PC_MAXDIM], nrm[PC_MAXDIM];
    int st = pc_curve_derivs(u->c, t, 2, out);
    if (st == PC_IMPROPER) return pcl_error(L, "c:normal: the curve is at infinity at t = %s", pcl_pushnum(L, t));
    if (st != PC_OK) return pcl_raise_status(L, "c:normal", st);
    if (pc_unit(d, out + d, e) != PC_OK)
        return pcl_error(L, "c:normal: the derivative is zero at t = %s", pcl_pushnum(L, t));
    if (d == 2) {
        pc_perp2(e, nrm);
    } else {   /* the part of C'' across the tangent */
        double a = pc_dot(d, out + 2 * d, e);
        for (int k = 0; k < d; k++) nrm[k] = out[2 * d + k] - a * e[k];
        if (pc_unit(d, nrm, nrm) != PC_OK)
            return pcl_error(L, "c:normal: the curve is straight at t = %s (no principal normal)",
                             pcl_pushnum(L, t));
    }
    pcl_pushvector(L, d, nrm);
    return 1;
}

static int c_curvature(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:curvature");
    double t = pcl_checknum_m(L, "c:curvature", 2, "t"), k;
    int st = pc_curve_curvature(u->c, t, &k);
    if (st == PC_IMPROPER) return pcl_error(L, "c:curvature: the curve is at infinity at t = %s", pcl_pushnum(L, t));
    if (st == PC_EZERO)
        return pcl_error(L, "c:curvature: the derivative is zero at t = %s (a cusp or a stop)", pcl_pushnum(L, t));
    if (st != PC_OK) return pcl_raise_status(L, "c:curvature", st);
    lua_pushnumber(L, k);
    return 1;
}

/* ---- operations --------------------------------------------------------------------------------- */

static double inside(lua_State *L, lcurve *u, const char *fname, int idx, const char *what) {
    double t = pcl_checknum_m(L, fname, idx, what);
    if (!(t > u->c->t0 && t < u->c->t1)) {
        lua_pushfstring(L, "inside the domain (%s, %s)", pcl_pushnum(L, u->c->t0), pcl_pushnum(L, u->c->t1));
        pcl_argerror_full(L, fname, idx, idx - 1, what, lua_tostring(L, -1));
    }
    return t;
}

static int c_split(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:split");
    double t = inside(L, u, "c:split", 2, "t");
    pc_curve *a, *b;
    int st = pc_curve_split(u->c, t, &a, &b);
    if (st != PC_OK) return pcl_raise_status(L, "c:split", st);
    pcl_pushcurve(L, a, u->kind);
    pcl_pushcurve(L, b, u->kind);
    return 2;
}

static int c_sub(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:sub");
    double a = pcl_checknum_m(L, "c:sub", 2, "a"), b = pcl_checknum_m(L, "c:sub", 3, "b");
    if (!(a >= u->c->t0 && b <= u->c->t1 && a < b))
        return pcl_error(L, "c:sub: need t0 <= a < b <= t1 in the domain [%s, %s], got a = %s, b = %s",
                         pcl_pushnum(L, u->c->t0), pcl_pushnum(L, u->c->t1), pcl_pushnum(L, a), pcl_pushnum(L, b));
    int st;
    pc_curve *c = pc_curve_sub(u->c, a, b, &st);
    pushcurve(L, c, st, u->kind, 0);
    return 1;
}

static int c_insert_knot(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:insert_knot");
    if (u->c->kind != PC_CURVE_BSPLINE) return pcl_error(L, "c:insert_knot: not a B-spline (a %s)", u->kind);
    double t = inside(L, u, "c:insert_knot", 2, "u");
    int st;
    pc_curve *c = pc_curve_insert_knot(u->c, t, &st);
    pushcurve(L, c, st, u->kind, 0);
    return 1;
}

static int c_length(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:length");
    double a = u->c->t0, b = u->c->t1;
    if (!lua_isnoneornil(L, 2)) {
        a = pcl_checknum_m(L, "c:length", 2, "a");
        b = pcl_checknum_m(L, "c:length", 3, "b");
    }
    double len;
    int st = pc_curve_length(u->c, a, b, 1e-10, &len);
    if (st == PC_IMPROPER) return pcl_error(L, "c:length: the curve passes through infinity: its length is infinite");
    if (st != PC_OK) return pcl_raise_status(L, "c:length", st);
    lua_pushnumber(L, len);
    return 1;
}

static int c_bbox(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:bbox");
    double lo[PC_MAXDIM], hi[PC_MAXDIM];
    int st = pc_curve_bbox(u->c, 1e-9, lo, hi);
    if (st == PC_IMPROPER) return pcl_error(L, "c:bbox: the curve passes through infinity: it has no bounding box");
    if (st != PC_OK) return pcl_raise_status(L, "c:bbox", st);
    pcl_pushpoint(L, u->c->dim, lo);
    pcl_pushpoint(L, u->c->dim, hi);
    return 2;
}

/* c:controls(): the control values (weighted points as given); a stroke's c:controls(i) is
 * its piece's quadrilateral A, P, Q, B as before. */
static int c_controls(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:controls");
    if (u->tk == TK_STROKE || u->tk == TK_SPLINE2) {
        int i = 0;
        if (!(u->np == 1 && lua_isnoneornil(L, 2))) {
            int isint;
            lua_Integer k = lua_tointegerx(L, 2, &isint);
            if (!isint || k < 1 || k > u->np) {
                lua_pushfstring(L, "a piece number 1..%d", u->np);
                pcl_argerror_full(L, "c:controls", 2, 1, "i", lua_tostring(L, -1));
            }
            i = (int)k - 1;
        }
        pc_piece *pc = &pieces(u)[i];
        int d = u->c->dim;
        pcl_pushpoint(L, d, pc->a);
        pcl_pushpoint(L, d, pc->p);
        pcl_pushpoint(L, d, pc->q);
        pcl_pushpoint(L, d, pc->b);
        return 4;
    }
    if (u->tk == TK_FOURIER) return pcl_error(L, "c:controls: a Fourier curve has no pieces");
    if (u->c->kind == PC_CURVE_FUNC) return pcl_error(L, "c:controls: a %s curve has no control points", u->kind);
    int d = u->c->dim;
    lua_createtable(L, u->c->ncp, 0);
    for (int i = 0; i < u->c->ncp; i++) {
        pcl_value *v = pcl_newvalue(L, d);
        memcpy(v->h, u->c->cp + (size_t)i * (d + 1), sizeof(double) * (size_t)(d + 1));
        lua_rawseti(L, -2, i + 1);
    }
    return 1;
}

static int c_knots(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:knots");
    if (u->c->kind == PC_CURVE_FUNC) return pcl_error(L, "c:knots: a %s curve has no knots", u->kind);
    lua_createtable(L, u->c->nknots, 0);
    for (int i = 0; i < u->c->nknots; i++) {
        lua_pushnumber(L, u->c->knots[i]);
        lua_rawseti(L, -2, i + 1);
    }
    return 1;
}

/* c:piece(i, t), c:piece_xy(i, t): a stroke's piece i at its own parameter t (any t: the
 * piece's formula extrapolates, where its smoothstep has values) */
static int piece_at(lua_State *L, const char *fname, double *x) {
    lcurve *u = checkcurve(L, 1, fname);
    if (u->tk != TK_STROKE && u->tk != TK_SPLINE2)
        return pcl_error(L, "%s: a %s curve has no pieces", fname,
                         u->tk == TK_FOURIER ? "Fourier" : u->kind);
    int isint;
    lua_Integer i = lua_tointegerx(L, 2, &isint);
    if (!isint || i < 1 || i > u->np) {
        lua_pushfstring(L, "a piece number 1..%d", u->np);
        pcl_argerror_full(L, fname, 2, 1, "i", lua_tostring(L, -1));
    }
    double t = pcl_checknum_m(L, fname, 3, "t");
    pc_piece *pc = &pieces(u)[i - 1];
    int d = u->c->dim;
    if (lua_getiuservalue(L, 1, 1) != LUA_TNIL) {   /* a Lua smoothstep */
        lua_pushnumber(L, t);
        lua_call(L, 1, 1);
        int isnum;
        double g = lua_tonumberx(L, -1, &isnum);
        if (!isnum || !isfinite(g))
            pcl_error(L, "%s: the smoothstep g must return a finite number, got %s", fname,
                      isnum ? pcl_pushnum(L, g) : luaL_typename(L, -1));
        pc_qspline(d, pc->a, pc->p, pc->q, pc->b, t, g, x);
        return d;
    }
    if (pc_gfun_check(&pc->g, t) != PC_OK) {
        int low = t < 0;
        const char *deg = pcl_pushnum(L, low ? pc->g.h.n : pc->g.h.m);
        lua_pushfstring(L, "%s (piece %d's half-spline has the fractional degree %s = %s and "
                        "does not extrapolate)", low ? "at least 0" : "at most 1", (int)i,
                        low ? "n" : "m", deg);
        pcl_argerror_full(L, fname, 3, 2, "t", lua_tostring(L, -1));
    }
    pc_piece_eval(d, pc, t, x);
    return d;
}

static int c_piece(lua_State *L) {
    double x[PC_MAXDIM];
    int d = piece_at(L, "c:piece", x);
    pcl_pushpoint(L, d, x);
    return 1;
}

static int c_piece_xy(lua_State *L) {
    double x[PC_MAXDIM];
    int d = piece_at(L, "c:piece_xy", x);
    for (int k = 0; k < d; k++) lua_pushnumber(L, x[k]);
    return d;
}

/* c:coef(k) -> a, b: the Fourier coefficient lists of coordinate k (a[0] .. a[n]) */
static int c_coef(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:coef");
    if (u->tk != TK_FOURIER) return pcl_error(L, "c:coef: not a Fourier curve");
    int d = u->c->dim, isint = 1;
    lua_Integer k = lua_isnoneornil(L, 2) ? 1 : lua_tointegerx(L, 2, &isint);
    if (!isint || k < 1 || k > d) {
        lua_pushfstring(L, "a coordinate number 1..%d", d);
        pcl_argerror_full(L, "c:coef", 2, 1, "k", lua_tostring(L, -1));
    }
    int m = u->n + 1;
    for (int ab = 0; ab < 2; ab++) {
        lua_createtable(L, m, 0);
        const double *v = u->data + (2 * (k - 1) + ab) * m;
        for (int j = 0; j < m; j++) {
            lua_pushnumber(L, v[j]);
            lua_rawseti(L, -2, j);
        }
    }
    return 2;
}

/* c:map(f): the image under a map (also f(c)) */
static int c_map(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:map");
    pc_map *f = pcl_tomap(L, 2);
    if (!f) return pcl_argerror_full(L, "c:map", 2, 1, "f", "a map");
    if (f->nin != u->c->dim)
        return pcl_error(L, "c:map: the map takes %d-D points, but the curve is %d-D", f->nin, u->c->dim);
    int st;
    pc_curve *c = pc_curve_map(u->c, f, &st);
    pushcurve(L, c, st, u->kind, 0);
    return 1;
}

/* c:flatten([tol [, map]]) -> a list of polylines (lists of 2-D points) within tol of the
 * curve (default 1e-3 of the curve's size... here: tol in the curve's own units, default
 * 1e-3); map projects a curve of another dimension to the plane. */
static int c_flatten(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "c:flatten");
    double tol = lua_isnoneornil(L, 2) ? 1e-3 : pcl_checknum_m(L, "c:flatten", 2, "tol");
    if (!(tol > 0)) pcl_argerror_full(L, "c:flatten", 2, 1, "tol", "a positive number");
    pc_map *f = NULL;
    if (!lua_isnoneornil(L, 3)) {
        f = pcl_tomap(L, 3);
        if (!f || f->nin != u->c->dim || f->nout != 2) {
            lua_pushfstring(L, "a map from %d-D to 2-D", u->c->dim);
            pcl_argerror_full(L, "c:flatten", 3, 2, "map", lua_tostring(L, -1));
        }
    } else if (u->c->dim != 2) {
        return pcl_error(L, "c:flatten: a %d-D curve needs a map to the plane (argument #2)", u->c->dim);
    }
    pc_polyline pl = {0};
    int st = pcl_flatten(L, u->c, u->c->t0, u->c->t1, 1, f, 0, tol, &pl);
    if (st != PC_OK) {
        pc_polyline_free(&pl);
        return pcl_raise_status(L, "c:flatten", st);
    }
    lua_newtable(L);
    int npl = 0, nv = 0;
    for (size_t i = 0; i < pl.n; i++) {
        if (i == 0 || pl.move[i]) {
            if (i) lua_rawseti(L, -2, ++npl);
            lua_newtable(L);
            nv = 0;
        }
        pcl_pushpoint(L, 2, pl.xy + 2 * i);
        lua_rawseti(L, -2, ++nv);
    }
    if (pl.n) lua_rawseti(L, -2, ++npl);
    pc_polyline_free(&pl);
    return 1;
}

static int c_index(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "curve");
    const char *k = lua_tostring(L, 2);
    if (k) {
        pc_curve *c = u->c;
        if (!strcmp(k, "dim")) { lua_pushinteger(L, c->dim); return 1; }
        if (!strcmp(k, "kind")) { lua_pushstring(L, u->kind); return 1; }
        if (!strcmp(k, "lo") || !strcmp(k, "t0")) { lua_pushnumber(L, c->t0); return 1; }
        if (!strcmp(k, "hi") || !strcmp(k, "t1")) { lua_pushnumber(L, c->t1); return 1; }
        if (!strcmp(k, "closed")) { lua_pushboolean(L, c->closed); return 1; }
        if (!strcmp(k, "degree") && c->kind != PC_CURVE_FUNC) { lua_pushinteger(L, c->degree); return 1; }
        if (!strcmp(k, "pieces")) {
            if (u->tk == TK_STROKE || u->tk == TK_SPLINE2) lua_pushinteger(L, u->np);
            else if (c->kind == PC_CURVE_BEZIER) lua_pushinteger(L, c->nknots - 1);
            else lua_pushinteger(L, 1);
            return 1;
        }
        if (!strcmp(k, "n") && u->tk == TK_FOURIER) { lua_pushinteger(L, u->n); return 1; }
    }
    lua_pushvalue(L, 2);
    lua_rawget(L, lua_upvalueindex(1));
    return 1;
}

static int c_tostring(lua_State *L) {
    lcurve *u = checkcurve(L, 1, "curve");
    pc_curve *c = u->c;
    if (u->tk == TK_FOURIER)
        lua_pushfstring(L, "fourier(%d points, %d-D)", 2 * u->n, c->dim);
    else if (u->tk == TK_SPLINE2)
        lua_pushfstring(L, "spline2(%d-D)", c->dim);
    else if (u->tk == TK_STROKE)
        lua_pushfstring(L, "stroke(%d nodes, %d pieces, %d-D%s)", c->closed ? u->np : u->np + 1,
                        u->np, c->dim, c->closed ? ", closed" : "");
    else if (c->kind == PC_CURVE_FUNC)
        lua_pushfstring(L, "%s(%d-D, t in [%s, %s])", u->kind, c->dim, pcl_pushnum(L, c->t0),
                        pcl_pushnum(L, c->t1));
    else
        lua_pushfstring(L, "%s(%d-D, degree %d, %d control points, t in [%s, %s])", u->kind,
                        c->dim, c->degree, c->ncp, pcl_pushnum(L, c->t0), pcl_pushnum(L, c->t1));
    return 1;
}

void pcl_open_curves(lua_State *L) {
    int module = lua_gettop(L);
    pcl_private(L, module);
    int tk = lua_gettop(L);
    lua_newtable(L);   /* the methods, shared with the Lua helpers as _tk.curve_methods */
    int methods = lua_gettop(L);
    static const luaL_Reg mfns[] = {
        {"xy", c_xy}, {"eval", c_call}, {"deriv", c_deriv}, {"tangent", c_tangent},
        {"normal", c_normal}, {"curvature", c_curvature}, {"split", c_split}, {"sub", c_sub},
        {"insert_knot", c_insert_knot}, {"length", c_length}, {"bbox", c_bbox},
        {"controls", c_controls}, {"knots", c_knots}, {"piece", c_piece},
        {"piece_xy", c_piece_xy}, {"coef", c_coef}, {"monomial", c_monomial}, {"map", c_map}, {"flatten", c_flatten},
        {NULL, NULL}};
    luaL_setfuncs(L, mfns, 0);
    lua_pushvalue(L, methods);
    lua_setfield(L, tk, "curve_methods");

    luaL_newmetatable(L, CURVE_MT);
    static const luaL_Reg meta[] = {{"__call", c_call}, {"__tostring", c_tostring},
                                    {"__gc", c_gc}, {NULL, NULL}};
    luaL_setfuncs(L, meta, 0);
    lua_pushvalue(L, methods);
    lua_pushcclosure(L, c_index, 1);
    lua_setfield(L, -2, "__index");
    lua_pop(L, 1);

    lua_pushcfunction(L, l_stroke_raw);
    lua_setfield(L, tk, "stroke");
    static const luaL_Reg fns[] = {
        {"spline2", l_spline2}, {"fourier", l_fourier}, {"sphdir", l_sphdir},
        {"bezier", l_bezier}, {"bspline", l_bspline}, {"hermite", l_hermite},
        {"cubic_spline", l_cubic_spline}, {"interpolate", l_interpolate}, {"curve", l_curve},
        {NULL, NULL}};
    lua_pushvalue(L, module);
    luaL_setfuncs(L, fns, 0);
    lua_settop(L, module);
}
