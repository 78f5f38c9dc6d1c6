/* Binding of the curve builders (stdlib/geom/spline.h, fourier.h):
 *   spline2(A, a, B, b [, g])   the two-point curve with prescribed directions (example 5)
 *   fourier(points)             the closed Fourier curve through 2n points (example 12)
 *   sphdir(u1, u2)              the unit vector of longitude u1 and latitude u2 (example 33)
 * and the raw constructor _tk.stroke used by stroke{...} (stdlib/lua/curves.lua).
 *
 * All three kinds are one userdata type "curve": c(t) is a point, c:xy(t) its coordinates;
 * strokes also have c:piece(i, t), c:piece_xy(i, t), c:controls(i).  The methods table is
 * _tk.curve_methods, so the Lua helpers add c:each{...} and c:draw{...}. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "pcl_tk.h"
#include "spline.h"
#include "fourier.h"

#define CURVE_MT "curve"
#define METHODS lua_upvalueindex(1)

enum { KIND_SPLINE2, KIND_STROKE, KIND_FOURIER };
static const char *const kind_names[] = {"spline2", "stroke", "fourier"};

typedef struct {
    int kind, d, np, closed, n;
    int lua_g;          /* the smoothstep is the Lua callable in user value 1 */
    double lo, hi;      /* the natural parameter range of one piece */
    double data[];      /* pieces (pc_piece[np]) or Fourier coefficients */
} curve;

static pc_piece *pieces(curve *c) { return (pc_piece *)c->data; }

static curve *newcurve(lua_State *L, int kind, int d, int np, size_t extra) {
    curve *c = lua_newuserdatauv(L, sizeof(curve) + extra, 1);
    memset(c, 0, sizeof *c);
    c->kind = kind;
    c->d = d;
    c->np = np;
    c->lo = 0;
    c->hi = 1;
    luaL_setmetatable(L, CURVE_MT);
    return c;
}

static curve *checkcurve(lua_State *L, int idx, const char *fname) {
    curve *c = luaL_testudata(L, idx, CURVE_MT);
    if (!c) tk_argerror(L, fname, idx, "self", "a curve");
    return c;
}

/* The smoothstep at idx: nil (the default kind dflt), smooth.sine, smooth.cubic, a half-spline
 * object, or any other callable (then *lua is set and the caller stores it). */
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
    if (lua_isfunction(L, idx) || luaL_getmetafield(L, idx, "__call") != LUA_TNIL) {
        if (!lua_isfunction(L, idx)) lua_pop(L, 1);
        *lua = 1;
        return;
    }
    tk_argerror(L, fname, idx, "g", "a smoothstep (a function of t)");
}

/* g(t) through the user's Lua function (user value 1 of the curve at idx 1) */
static double lua_g(lua_State *L, double t) {
    lua_getiuservalue(L, 1, 1);
    lua_pushnumber(L, t);
    lua_call(L, 1, 1);
    int isnum;
    double g = lua_tonumberx(L, -1, &isnum);
    if (!isnum) pcl_error(L, "curve: the smoothstep g must return a number, got %s",
                           luaL_typename(L, -1));
    if (!isfinite(g)) {
        const char *tt = tk_pushnum(L, t), *tg = tk_pushnum(L, g);
        pcl_error(L, "curve: the smoothstep g must return a finite number, got g(%s) = %s", tt, tg);
    }
    lua_pop(L, 1);
    return g;
}

/* Evaluate piece i (0-based) at its own t; the curve is at stack index 1.  A half-spline of
 * fractional degree has no value before its start (t < 0) or past its end (t > 1): the
 * argument at idx (shown as #shown, whose value is the global parameter s) is then wrong,
 * and must lie in [lo, hi]. */
static void eval_piece(lua_State *L, curve *c, int i, double t, double *out, const char *fname,
                       int idx, int shown, double lo, double hi) {
    pc_piece *pc = &pieces(c)[i];
    if (c->lua_g) {
        pc_qspline(c->d, pc->a, pc->p, pc->q, pc->b, t, lua_g(L, t), out);
        return;
    }
    if (pc_gfun_check(&pc->g, t) != PC_OK) {
        int low = t < 0;
        const char *deg = tk_pushnum(L, low ? pc->g.h.n : pc->g.h.m);
        const char *bound = tk_pushnum(L, low ? lo : hi);
        lua_pushfstring(L, "%s %s (piece %d's half-spline has the fractional degree %s = %s and "
                        "does not extrapolate)", low ? "at least" : "at most", bound, i + 1,
                        low ? "n" : "m", deg);
        tk_argerror_at(L, fname, idx, shown, "t", lua_tostring(L, -1));
    }
    pc_piece_eval(c->d, pc, t, out);
}

/* Evaluate at the global parameter: a stroke's s in [0, pieces] (piece floor(s), the first
 * and last pieces extrapolate), a spline2's t, a Fourier curve's u. */
static void eval_global(lua_State *L, curve *c, double s, double *out, const char *fname) {
    if (c->kind == KIND_FOURIER) {
        int m = c->n + 1;
        for (int k = 0; k < c->d; k++)
            out[k] = pc_fourier_eval(c->n, c->data + 2 * k * m, c->data + (2 * k + 1) * m, s);
        return;
    }
    double f = floor(s);
    int i = f < 0 ? 0 : (f > c->np - 1 ? c->np - 1 : (int)f);
    eval_piece(L, c, i, s - i, out, fname, 2, 1, 0, c->np);
}

static int push_coords(lua_State *L, int d, const double *x) {
    for (int k = 0; k < d; k++) lua_pushnumber(L, x[k]);
    return d;
}

static int c_call(lua_State *L) {
    curve *c = checkcurve(L, 1, "curve");
    double x[PC_CURVE_MAXDIM];
    eval_global(L, c, tk_checknum_m(L, kind_names[c->kind], 2, "t"), x, kind_names[c->kind]);
    tk_pushpoint(L, c->d, x);
    return 1;
}

static int c_xy(lua_State *L) {
    curve *c = checkcurve(L, 1, "c:xy");
    double x[PC_CURVE_MAXDIM];
    eval_global(L, c, tk_checknum_m(L, "c:xy", 2, "t"), x, "c:xy");
    return push_coords(L, c->d, x);
}

static int check_piece(lua_State *L, curve *c, const char *fname, int arg) {
    if (c->kind == KIND_FOURIER) pcl_error(L, "%s: a Fourier curve has no pieces", fname);
    int isint;
    lua_Integer i = lua_tointegerx(L, arg, &isint);
    if (!isint || i < 1 || i > c->np) {
        char expected[48];
        snprintf(expected, sizeof expected, "a piece number 1..%d", c->np);
        tk_argerror_at(L, fname, arg, arg - 1, "i", expected);
    }
    return (int)i - 1;
}

static int c_piece(lua_State *L) {
    curve *c = checkcurve(L, 1, "c:piece");
    int i = check_piece(L, c, "c:piece", 2);
    double x[PC_CURVE_MAXDIM];
    eval_piece(L, c, i, tk_checknum_m(L, "c:piece", 3, "t"), x, "c:piece", 3, 2, 0, 1);
    tk_pushpoint(L, c->d, x);
    return 1;
}

static int c_piece_xy(lua_State *L) {
    curve *c = checkcurve(L, 1, "c:piece_xy");
    int i = check_piece(L, c, "c:piece_xy", 2);
    double x[PC_CURVE_MAXDIM];
    eval_piece(L, c, i, tk_checknum_m(L, "c:piece_xy", 3, "t"), x, "c:piece_xy", 3, 2, 0, 1);
    return push_coords(L, c->d, x);
}

/* c:controls(i) -> A, P, Q, B: the quadrilateral of piece i */
static int c_controls(lua_State *L) {
    curve *c = checkcurve(L, 1, "c:controls");
    if (c->kind == KIND_FOURIER) return pcl_error(L, "c:controls: a Fourier curve has no pieces");
    int i = c->np == 1 && lua_isnoneornil(L, 2) ? 0 : check_piece(L, c, "c:controls", 2);
    pc_piece *pc = &pieces(c)[i];
    tk_pushpoint(L, c->d, pc->a);
    tk_pushpoint(L, c->d, pc->p);
    tk_pushpoint(L, c->d, pc->q);
    tk_pushpoint(L, c->d, pc->b);
    return 4;
}

static int c_index(lua_State *L) {
    curve *c = checkcurve(L, 1, "curve");
    const char *k = lua_tostring(L, 2);
    if (k) {
        if (!strcmp(k, "pieces")) { lua_pushinteger(L, c->kind == KIND_FOURIER ? 1 : c->np); return 1; }
        if (!strcmp(k, "dim")) { lua_pushinteger(L, c->d); return 1; }
        if (!strcmp(k, "closed")) { lua_pushboolean(L, c->closed || c->kind == KIND_FOURIER); return 1; }
        if (!strcmp(k, "kind")) { lua_pushstring(L, kind_names[c->kind]); return 1; }
        if (!strcmp(k, "lo")) { lua_pushnumber(L, c->lo); return 1; }
        if (!strcmp(k, "hi")) { lua_pushnumber(L, c->hi); return 1; }
        if (!strcmp(k, "n") && c->kind == KIND_FOURIER) { lua_pushinteger(L, c->n); return 1; }
    }
    lua_pushvalue(L, 2);
    lua_rawget(L, METHODS);
    return 1;
}

static int c_tostring(lua_State *L) {
    curve *c = checkcurve(L, 1, "curve");
    if (c->kind == KIND_FOURIER)
        lua_pushfstring(L, "fourier(%d points, %d-D)", 2 * c->n, c->d);
    else if (c->kind == KIND_SPLINE2)
        lua_pushfstring(L, "spline2(%d-D)", c->d);
    else
        lua_pushfstring(L, "stroke(%d nodes, %d pieces, %d-D%s)",
                        c->closed ? c->np : c->np + 1, c->np, c->d, c->closed ? ", closed" : "");
    return 1;
}

/* ---- constructors --------------------------------------------------------------------------- */

static int l_spline2(lua_State *L) {
    const char *fn = "spline2";
    double A[PC_MAXDIM], a[PC_MAXDIM], B[PC_MAXDIM], b[PC_MAXDIM];
    int d = pcl_checkloc(L, 1, "A", 0, 0, A);
    if (d > PC_CURVE_MAXDIM)
        return pcl_error(L, "%s: argument #1 (A) must be a point of dimension 1..4, got %d-D", fn, d);
    pcl_checkvec(L, 2, "a", d, 1, a);
    pcl_checkloc(L, 3, "B", d, 1, B);
    pcl_checkvec(L, 4, "b", d, 1, b);
    pc_gfun g;
    int lua;
    check_g(L, fn, 5, PC_G_CUBIC, &g, &lua);
    curve *c = newcurve(L, KIND_SPLINE2, d, 1, sizeof(pc_piece));
    pc_piece *pc = pieces(c);
    memset(pc, 0, sizeof *pc);
    for (int k = 0; k < d; k++) {
        pc->a[k] = A[k];
        pc->p[k] = A[k] + a[k];
        pc->q[k] = B[k] - b[k];
        pc->b[k] = B[k];
    }
    pc->g = g;
    if (lua) {
        c->lua_g = 1;
        lua_pushvalue(L, 5);
        lua_setiuservalue(L, -2, 1);
    }
    return 1;
}

/* a flat array of numbers from table arg (nil allowed when optional): count entries */
static double *read_numbers(lua_State *L, int arg, int count, double *buf, int optional) {
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
 * nil, status, bad node (1-based).  Arrays are flat (nodes, ein, eout: k rows of d) with NaN
 * for "default"; ein, eout, rin, rout may be nil. */
static int l_stroke_raw(lua_State *L) {
    lua_settop(L, 11);
    int d = (int)luaL_checkinteger(L, 1);
    int closed = lua_toboolean(L, 2);
    luaL_checktype(L, 3, LUA_TTABLE);
    int k = (int)(luaL_len(L, 3) / (d > 0 ? d : 1));
    if (d < 1 || d > PC_CURVE_MAXDIM || k < 2) pcl_error(L, "_tk.stroke: bad dimension or count");
    size_t sz = (size_t)k * (size_t)d;
    /* scratch space on the Lua heap (freed by the GC) */
    double *buf = lua_newuserdatauv(L, sizeof(double) * (sz * 3 + (size_t)k * 5), 0);
    int scratch = lua_gettop(L);
    double *nodes = read_numbers(L, 3, (int)sz, buf, 0);
    double *ein = read_numbers(L, 4, (int)sz, buf + sz, 1);
    double *eout = read_numbers(L, 5, (int)sz, buf + 2 * sz, 1);
    double *rin = read_numbers(L, 6, k, buf + 3 * sz, 1);
    double *rout = read_numbers(L, 7, k, buf + 3 * sz + k, 1);
    double *n = read_numbers(L, 8, k, buf + 3 * sz + 2 * k, 1);
    double *m = read_numbers(L, 9, k, buf + 3 * sz + 3 * k, 1);
    double *t0 = read_numbers(L, 10, k, buf + 3 * sz + 4 * k, 1);
    pc_gfun g;
    int lua;
    check_g(L, "stroke", 11, PC_G_HALF, &g, &lua);
    int np = pc_stroke_npieces(k, closed);
    pc_stroke_spec spec = {.d = d, .nnodes = k, .closed = closed, .nodes = nodes, .ein = ein,
                           .eout = eout, .rin = rin, .rout = rout, .n = n, .m = m, .t0 = t0};
    curve *c = newcurve(L, KIND_STROKE, d, np, sizeof(pc_piece) * (size_t)np);
    c->closed = closed;
    int bad;
    int st = pc_stroke_build(&spec, pieces(c), &bad);
    if (st != PC_OK) {
        lua_pushnil(L);
        lua_pushinteger(L, st);
        lua_pushinteger(L, bad + 1);
        lua_pushstring(L, pc_strerror(st));
        return 4;
    }
    if (lua || g.kind != PC_G_HALF || !lua_isnoneornil(L, 11)) {
        for (int i = 0; i < np; i++) pieces(c)[i].g = g;
        if (lua) {
            c->lua_g = 1;
            lua_pushvalue(L, 11);
            lua_setiuservalue(L, -2, 1);
        }
    }
    lua_remove(L, scratch);
    return 1;
}

static int l_fourier(lua_State *L) {
    const char *fn = "fourier";
    if (!lua_istable(L, 1)) tk_argerror(L, fn, 1, "points", "a list of 2n points");
    int count = (int)luaL_len(L, 1);
    if (count < 2 || count % 2) {
        lua_pushfstring(L, "a list of an even number (2n >= 2) of points, got %d", count);
        return pcl_error(L, "%s: argument #1 (points) must be %s", fn, lua_tostring(L, -1));
    }
    int n = count / 2, d = 0;
    double *samples = lua_newuserdatauv(L, sizeof(double) * (size_t)count * PC_CURVE_MAXDIM, 0);
    int scratch = lua_gettop(L);
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
                return pcl_error(L, "%s: points must be 1-D to 4-D, got %d-D", fn, d);
        } else if (p->n != d) {
            return pcl_error(L, "%s: points[%d] is %d-D, but points[1] is %d-D: dimensions "
                              "cannot be mixed", fn, i + 1, p->n, d);
        }
        for (int k = 0; k < d; k++) samples[i * PC_CURVE_MAXDIM + k] = loc[k];
        lua_pop(L, 1);
    }
    int m = n + 1;
    curve *c = newcurve(L, KIND_FOURIER, d, 1, sizeof(double) * (size_t)(2 * m * d));
    c->n = n;
    c->lo = 0;
    c->hi = 2 * 3.14159265358979323846;
    for (int k = 0; k < d; k++) {
        int st = pc_fourier_coef(n, samples + k, PC_CURVE_MAXDIM, c->data + 2 * k * m,
                                 c->data + (2 * k + 1) * m);
        if (st != PC_OK) return tk_statuserror(L, fn, st, "points");
    }
    lua_remove(L, scratch);
    return 1;
}

/* c:coef(k) -> a, b: the Fourier coefficient lists of coordinate k (0-based index of a_0) */
static int c_coef(lua_State *L) {
    curve *c = checkcurve(L, 1, "c:coef");
    if (c->kind != KIND_FOURIER) return pcl_error(L, "c:coef: not a Fourier curve");
    int isint = 1;
    lua_Integer k = lua_isnoneornil(L, 2) ? 1 : lua_tointegerx(L, 2, &isint);
    if (!isint || k < 1 || k > c->d) {
        lua_pushfstring(L, "a coordinate number 1..%d", c->d);
        tk_argerror_at(L, "c:coef", 2, 1, "k", lua_tostring(L, -1));
    }
    int m = c->n + 1;
    for (int ab = 0; ab < 2; ab++) {
        lua_createtable(L, m, 0);
        const double *v = c->data + (2 * (k - 1) + ab) * m;
        for (int j = 0; j < m; j++) {
            lua_pushnumber(L, v[j]);
            lua_rawseti(L, -2, j);   /* a[0] .. a[n], as in the article */
        }
    }
    return 2;
}

static int l_sphdir(lua_State *L) {
    double u1 = tk_checknum(L, "sphdir", 1, "u1"), u2 = tk_checknum(L, "sphdir", 2, "u2");
    double e[3];
    pc_dir3(u1, u2, e);
    tk_pushvector(L, 3, e);
    return 1;
}

void pcl_open_curves(lua_State *L) {
    int module = lua_gettop(L);
    tk_private(L, module);
    int tk = lua_gettop(L);
    lua_newtable(L);   /* the methods, shared with the Lua helpers as _tk.curve_methods */
    int methods = lua_gettop(L);
    static const luaL_Reg mfns[] = {{"xy", c_xy},           {"piece", c_piece},
                                    {"piece_xy", c_piece_xy}, {"controls", c_controls},
                                    {"coef", c_coef},       {NULL, NULL}};
    luaL_setfuncs(L, mfns, 0);
    lua_pushvalue(L, methods);
    lua_setfield(L, tk, "curve_methods");

    luaL_newmetatable(L, CURVE_MT);
    lua_pushcfunction(L, c_call);
    lua_setfield(L, -2, "__call");
    lua_pushcfunction(L, c_tostring);
    lua_setfield(L, -2, "__tostring");
    lua_pushvalue(L, methods);
    lua_pushcclosure(L, c_index, 1);
    lua_setfield(L, -2, "__index");
    lua_pop(L, 1);

    lua_pushcfunction(L, l_stroke_raw);
    lua_setfield(L, tk, "stroke");
    static const luaL_Reg fns[] = {
        {"spline2", l_spline2}, {"fourier", l_fourier}, {"sphdir", l_sphdir}, {NULL, NULL}};
    lua_pushvalue(L, module);
    luaL_setfuncs(L, fns, 0);
    lua_settop(L, module);
}
