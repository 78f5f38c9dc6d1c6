/* Binding of the one surface type (stdlib/geom/surface.h), in the table `surface`:
 *   surface.bilinear(P00, P10, P01, P11)      surface.bezier(net)
 *   surface.bspline(net, p, q [, uknots [, vknots]])
 *   surface.hermite{P = {4}, Pu = {4}, Pv = {4}, Puv = {4}}   corners (0,0), (1,0), (0,1), (1,1)
 *   surface.ruled(c0, c1)    surface.coons(cu0, cu1, c0v, c1v)
 *   surface.revolution(profile, A, d [, v0, v1])
 *   surface(f, u0, u1, v0, v1)                a Lua function (u, v) -> point
 * net: a list of rows, row i (along u) a list of points (weighted points make it rational).
 * s(u, v) is the point; s:partials(u, v), s:normal(u, v), s:iso("u"|"v", value) -> curve,
 * s:wireframe{nu =, nv =, color =, map =}, s:shade{nu =, nv =, color =, light =, mesh =, map =},
 * s:map(f). */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pcl_curve.h"
#include "hidden.h"
#include "view.h"
#include "pcl_scene.h"
#include "shaded.h"
#include "pcl_expr.h"

#define SURF_MT "surface"
static const char SURF_TAG = 's';   /* its address tags the type (PCL_SELF_TAG) */

typedef struct {
    PCL_SELF;           /* its own address: a forged surface is refused (pcl.h) */
    pc_surface *s;
    const char *kind;
} lsurf;

/* The surface object at idx or NULL; one given the metatable by the debug library is refused. */
static lsurf *tosurf(lua_State *L, int idx) {
    lsurf *u = luaL_testudata(L, idx, SURF_MT);
    int ok = !u || (lua_rawlen(L, idx) == sizeof *u && u->self == PCL_SELF_TAG(u, &SURF_TAG));
    return pcl_genuine(L, idx, u, ok, "surface");
}

pc_surface *pcl_tosurface(lua_State *L, int idx) {
    lsurf *u = tosurf(L, idx);
    return u ? u->s : NULL;
}

static lsurf *pushsurf(lua_State *L, pc_surface *s, int status, const char *kind) {
    if (!s) pcl_raise_status(L, kind, status);
    lsurf *u = lua_newuserdatauv(L, sizeof *u, 0);
    u->self = PCL_SELF_TAG(u, &SURF_TAG);
    u->s = s;
    u->kind = kind;
    luaL_setmetatable(L, SURF_MT);
    return u;
}

void pcl_pushsurface(lua_State *L, pc_surface *s, const char *kind) {
    (void)pushsurf(L, s, PC_OK, kind);
}

static lsurf *checksurf(lua_State *L, int idx, const char *fname) {
    lsurf *u = tosurf(L, idx);
    if (!u || !u->s) pcl_argerror_full(L, fname, idx, idx, "self", "a surface");
    pcl_callback_state(L);
    return u;
}

static int s_gc(lua_State *L) {
    lsurf *u = luaL_testudata(L, 1, SURF_MT);
    /* never a forged one */
    if (u && lua_rawlen(L, 1) == sizeof *u && u->self == PCL_SELF_TAG(u, &SURF_TAG) && u->s) {
        pcl_callback_state(L);
        pc_surface_release(u->s);
        u->s = NULL;
    }
    return 0;
}

/* ---- a Lua function as a surface ------------------------------------------------------------- */

typedef struct { int ref, dim; } luasurf;

static void luasurf_free(void *ud) {
    luasurf *f = ud;
    lua_State *L = pcl_current_state();
    if (L) luaL_unref(L, LUA_REGISTRYINDEX, f->ref);
    free(f);
}

static int luasurf_eval(void *ud, double u, double v, int order, double *out) {
    luasurf *f = ud;
    if (order > 0) return PC_EDOMAIN;
    lua_State *L = pcl_current_state();
    int top = lua_gettop(L);
    if (!lua_checkstack(L, f->dim + 4)) return PC_ENOMEM;
    lua_rawgeti(L, LUA_REGISTRYINDEX, f->ref);
    lua_pushnumber(L, u);
    lua_pushnumber(L, v);
    if (lua_pcall(L, 2, 1, 0) != LUA_OK) return pcl_callback_failed(L);
    pcl_value *p = pcl_tovalue(L, -1);
    if (!p || p->n != f->dim) {
        lua_pushfstring(L, "surface: the function must return a %d-D point, got %s", f->dim,
                        p ? "another dimension" : luaL_typename(L, -1));
        return pcl_callback_failed(L);
    }
    memcpy(out, p->h, sizeof(double) * (size_t)(f->dim + 1));
    lua_settop(L, top);
    return PC_OK;
}

/* ---- constructors ------------------------------------------------------------------------------ */

static void loc_arg(lua_State *L, int arg, const char *what, int *dim, double *out) {
    *dim = pcl_checkloc(L, arg, what, *dim, *dim ? 1 : 0, out);
}

static int l_bilinear(lua_State *L) {
    double p[4][PC_MAXDIM];
    int d = 0;
    static const char *names[4] = {"P00", "P10", "P01", "P11"};
    for (int i = 0; i < 4; i++) loc_arg(L, i + 1, names[i], &d, p[i]);
    int st;
    pc_surface *s = pc_surface_bilinear(d, p[0], p[1], p[2], p[3], &st);
    pushsurf(L, s, st, "surface.bilinear");
    return 1;
}

/* The size of row [i] of the net at arg (a list of points). */
static int row_len(lua_State *L, const char *fn, int arg, int i) {
    if (lua_geti(L, arg, i) != LUA_TTABLE)
        pcl_error(L, "%s: argument #%d (net) row [%d] must be a list of points, got %s", fn, arg,
                  i, luaL_typename(L, -1));
    int n = (int)luaL_len(L, -1);
    lua_pop(L, 1);
    return n;
}

/* The net at arg: a list of nu rows of nv values, as homogeneous rows in a scratch userdata
 * left on the stack. */
static double *read_net(lua_State *L, const char *fn, int arg, int *nu, int *nv, int *dim) {
    if (!lua_istable(L, arg)) pcl_argerror_full(L, fn, arg, arg, "net", "a list of rows of points");
    int m = (int)luaL_len(L, arg);
    if (m < 2) pcl_error(L, "%s: argument #%d (net) must have at least 2 rows, got %d", fn, arg, m);
    int n = row_len(L, fn, arg, 1);
    if (n < 2) pcl_error(L, "%s: argument #%d (net) rows must hold at least 2 points", fn, arg);
    if ((long)m * n > 100000) pcl_error(L, "%s: argument #%d (net) is too large", fn, arg);
    lua_geti(L, arg, 1);
    lua_geti(L, -1, 1);
    pcl_value *first = pcl_tovalue(L, -1);
    if (!first) pcl_error(L, "%s: argument #%d (net) [1][1] must be a point, got %s", fn, arg,
                          luaL_typename(L, -1));
    int d = first->n;
    lua_pop(L, 2);
    double *h = lua_newuserdatauv(L, sizeof(double) * (size_t)m * n * (d + 1), 0);
    for (int i = 1; i <= m; i++) {
        int len = row_len(L, fn, arg, i);
        if (len != n)
            pcl_error(L, "%s: argument #%d (net) row [%d] holds %d points, but row [1] holds %d",
                      fn, arg, i, len, n);
        lua_geti(L, arg, i);
        for (int j = 1; j <= n; j++) {
            lua_geti(L, -1, j);
            pcl_value *v = pcl_tovalue(L, -1);
            if (!v) pcl_error(L, "%s: argument #%d (net) [%d][%d] must be a point, got %s", fn,
                              arg, i, j, luaL_typename(L, -1));
            if (v->n != d)
                pcl_error(L, "%s: argument #%d (net) [%d][%d] is %d-D, but [1][1] is %d-D: "
                          "dimensions cannot be mixed", fn, arg, i, j, v->n, d);
            for (int k = 0; k <= d; k++) {
                if (!isfinite(v->h[k]))
                    pcl_error(L, "%s: argument #%d (net) [%d][%d] has NaN or infinite "
                              "coordinates", fn, arg, i, j);
                h[((size_t)(i - 1) * n + (j - 1)) * (d + 1) + k] = v->h[k];
            }
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    *nu = m;
    *nv = n;
    *dim = d;
    return h;
}

static int l_bezier(lua_State *L) {
    int nu, nv, d;
    double *h = read_net(L, "surface.bezier", 1, &nu, &nv, &d);
    int st;
    pc_surface *s = pc_surface_bezier(d, nu - 1, nv - 1, h, &st);
    pushsurf(L, s, st, "surface.bezier");
    return 1;
}

static int l_bspline(lua_State *L) {
    const char *fn = "surface.bspline";
    lua_settop(L, 5);
    int nu, nv, d;
    double *h = read_net(L, fn, 1, &nu, &nv, &d);
    int p = (int)pcl_checknum(L, fn, 2, "p"), q = (int)pcl_checknum(L, fn, 3, "q");
    if (p < 1 || p >= nu) pcl_error(L, "%s: argument #2 (p) must be 1..%d (below the %d rows)", fn, nu - 1, nu);
    if (q < 1 || q >= nv) pcl_error(L, "%s: argument #3 (q) must be 1..%d (below the %d columns)", fn, nv - 1, nv);
    double *uk, *vk;
    pc_knot_kind ukind = pcl_checkknots(L, fn, 4, nu, p, &uk), vkind = pcl_checkknots(L, fn, 5, nv, q, &vk);
    int st;
    pc_surface *s = pc_surface_bspline(d, p, q, nu, nv, h, ukind, uk, vkind, vk, &st);
    pushsurf(L, s, st, fn);
    return 1;
}

static int l_hermite(lua_State *L) {
    const char *fn = "surface.hermite";
    if (!lua_istable(L, 1)) pcl_argerror_full(L, fn, 1, 1, "spec", "a table {P =, Pu =, Pv =, Puv =}");
    static const char *fields[4] = {"P", "Pu", "Pv", "Puv"};
    double rows[4][4 * PC_MAXDIM];
    int d = 0;
    for (int f = 0; f < 4; f++) {
        if (lua_getfield(L, 1, fields[f]) != LUA_TTABLE || luaL_len(L, -1) != 4)
            pcl_error(L, "%s: %s must be a list of 4 %s (corners (0,0), (1,0), (0,1), (1,1))", fn,
                      fields[f], f ? "vectors" : "points");
        for (int i = 0; i < 4; i++) {
            lua_geti(L, -1, i + 1);
            pcl_value *v = pcl_tovalue(L, -1);
            double want = f ? 0 : 1;
            if (!v || fabs(v->h[v->n] - want) > PC_WEIGHT_TOL || (d && v->n != d))
                pcl_error(L, "%s: %s[%d] must be a %s%s", fn, fields[f], i + 1, f ? "vector" : "point",
                          d ? " of the corners' dimension" : "");
            d = v->n;
            memcpy(rows[f] + i * d, v->h, sizeof(double) * (size_t)d);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    int st;
    pc_surface *s = pc_surface_hermite(d, rows[0], rows[1], rows[2], rows[3], &st);
    pushsurf(L, s, st, fn);
    return 1;
}

static pc_curve *curve_arg(lua_State *L, const char *fn, int arg, const char *what) {
    pc_curve *c = pcl_tocurve(L, arg);
    if (!c) pcl_argerror_full(L, fn, arg, arg, what, "a curve");
    return c;
}

static int l_ruled(lua_State *L) {
    const char *fn = "surface.ruled";
    pc_curve *a = curve_arg(L, fn, 1, "c0"), *b = curve_arg(L, fn, 2, "c1");
    if (a->dim != b->dim) pcl_error(L, "%s: the curves are %d-D and %d-D: dimensions cannot be mixed", fn, a->dim, b->dim);
    int st;
    pc_surface *s = pc_surface_ruled(a, b, &st);
    pushsurf(L, s, st, fn);
    return 1;
}

static int l_coons(lua_State *L) {
    const char *fn = "surface.coons";
    pc_curve *c[4];
    static const char *names[4] = {"cu0", "cu1", "c0v", "c1v"};
    for (int i = 0; i < 4; i++) {
        c[i] = curve_arg(L, fn, i + 1, names[i]);
        if (c[i]->dim != c[0]->dim) pcl_error(L, "%s: the curves must have one dimension", fn);
    }
    int st;
    pc_surface *s = pc_surface_coons(c[0], c[1], c[2], c[3], &st);
    if (!s && st == PC_EDOMAIN)
        return pcl_error(L, "%s: the boundary curves do not meet at the corners (cu0 and c0v "
                            "must start together, cu0 must end where c1v starts, ...)", fn);
    pushsurf(L, s, st, fn);
    return 1;
}

static int l_revolution(lua_State *L) {
    const char *fn = "surface.revolution";
    pc_curve *c = curve_arg(L, fn, 1, "profile");
    if (c->dim != 3) pcl_error(L, "%s: argument #1 (profile) must be a 3-D curve, got %d-D", fn, c->dim);
    double a[3], d[3];
    pcl_checkloc(L, 2, "A", 3, 0, a);
    pcl_checkvec(L, 3, "d", 3, 0, d);
    double v0 = pcl_optnum(L, fn, 4, "v0", 0), v1 = pcl_optnum(L, fn, 5, "v1", 2 * M_PI);
    int st;
    pc_surface *s = pc_surface_revolution(c, a, d, v0, v1, &st);
    if (!s && st == PC_EZERO) return pcl_error(L, "%s: argument #3 (d) must be a nonzero vector (the axis)", fn);
    pushsurf(L, s, st, fn);
    return 1;
}

/* surface(f, u0, u1, v0, v1): the __call of the table (the table itself is argument 1) */
static int l_func(lua_State *L) {
    const char *fn = "surface";
    lua_remove(L, 1);
    if (pcl_isequation(L, 1)) {                 /* a compiled point equation (l_expr.c) */
        int st;
        pc_surface *s = pcl_eq_surface(L, fn, &st);
        pushsurf(L, s, st, fn);
        return 1;
    }
    if (!lua_isfunction(L, 1)) pcl_argerror_full(L, fn, 1, 1, "f", "a function (u, v) -> point or an equation");
    double r[4];
    static const char *names[4] = {"u0", "u1", "v0", "v1"};
    for (int i = 0; i < 4; i++) r[i] = pcl_checknum(L, fn, i + 2, names[i]);
    if (!(r[1] > r[0]) || !(r[3] > r[2])) pcl_error(L, "%s: need u0 < u1 and v0 < v1", fn);
    lua_settop(L, 5);
    lua_pushvalue(L, 1);
    lua_pushnumber(L, r[0]);
    lua_pushnumber(L, r[2]);
    lua_call(L, 2, 1);
    pcl_value *p = pcl_tovalue(L, -1);
    if (!p) pcl_error(L, "%s: f(u0, v0) must return a point, got %s", fn, luaL_typename(L, -1));
    int d = p->n;
    lua_pop(L, 1);
    luasurf *f = malloc(sizeof *f);
    if (!f) return pcl_error(L, "%s: out of memory", fn);
    f->dim = d;
    lua_pushvalue(L, 1);
    f->ref = luaL_ref(L, LUA_REGISTRYINDEX);
    pcl_callback_state(L);
    int st;
    pc_surface *s = pc_surface_func(d, r[0], r[1], r[2], r[3], luasurf_eval, luasurf_free, f, &st);
    pushsurf(L, s, st, fn);
    return 1;
}

/* ---- methods --------------------------------------------------------------------------------- */

static void uv_args(lua_State *L, const char *fn, double *u, double *v) {
    *u = pcl_checknum_m(L, fn, 2, "u");
    *v = pcl_checknum_m(L, fn, 3, "v");
}

static int s_call(lua_State *L) {
    lsurf *u = checksurf(L, 1, "surface");
    double a, b, out[PC_MAXDIM];
    uv_args(L, "surface", &a, &b);
    int st = pc_surface_eval(u->s, a, b, out);
    if (st == PC_IMPROPER) return pcl_error(L, "surface: the point at (%s, %s) is at infinity", pcl_pushnum(L, a), pcl_pushnum(L, b));
    if (st != PC_OK) return pcl_raise_status(L, "surface", st);
    pcl_pushpoint(L, u->s->dim, out);
    return 1;
}

static int s_partials(lua_State *L) {
    lsurf *u = checksurf(L, 1, "s:partials");
    double a, b, out[3 * PC_MAXDIM];
    uv_args(L, "s:partials", &a, &b);
    int st = pc_surface_partials(u->s, a, b, out);
    if (st != PC_OK) return pcl_raise_status(L, "s:partials", st);
    int d = u->s->dim;
    pcl_pushpoint(L, d, out);
    pcl_pushvector(L, d, out + d);
    pcl_pushvector(L, d, out + 2 * d);
    return 3;
}

static int s_normal(lua_State *L) {
    lsurf *u = checksurf(L, 1, "s:normal");
    double a, b, n[3];
    uv_args(L, "s:normal", &a, &b);
    if (u->s->dim != 3) return pcl_error(L, "s:normal: a normal needs a 3-D surface, this one is %d-D", u->s->dim);
    int st = pc_surface_normal(u->s, a, b, n);
    if (st == PC_EZERO) return pcl_error(L, "s:normal: the surface is singular at (%s, %s): its partial derivatives are parallel", pcl_pushnum(L, a), pcl_pushnum(L, b));
    if (st != PC_OK) return pcl_raise_status(L, "s:normal", st);
    pcl_pushvector(L, 3, n);
    return 1;
}

static int iso_dir(lua_State *L, const char *fn, int idx) {
    const char *s = lua_tostring(L, idx);
    if (lua_type(L, idx) == LUA_TSTRING && !strcmp(s, "u")) return 0;
    if (lua_type(L, idx) == LUA_TSTRING && !strcmp(s, "v")) return 1;
    return pcl_argerror_full(L, fn, idx, idx - 1, "family", "\"u\" (u = const) or \"v\" (v = const)");
}

/* s:iso("u", value): the curve u = value (a curve in v); s:iso("v", value) likewise */
static int s_iso(lua_State *L) {
    lsurf *u = checksurf(L, 1, "s:iso");
    int dir = iso_dir(L, "s:iso", 2);
    double val = pcl_checknum_m(L, "s:iso", 3, "value");
    int st;
    pc_curve *c = pc_surface_iso(u->s, dir, val, &st);
    if (!c) return pcl_raise_status(L, "s:iso", st);
    pcl_pushcurve(L, c, "iso-curve");
    return 1;
}

static int s_map(lua_State *L) {
    lsurf *u = checksurf(L, 1, "s:map");
    pc_map *f = pcl_tomap(L, 2);
    if (!f) return pcl_argerror_full(L, "s:map", 2, 1, "f", "a map");
    if (f->nin != u->s->dim)
        return pcl_error(L, "s:map: the map takes %d-D points, but the surface is %d-D", f->nin, u->s->dim);
    int st;
    pc_surface *s = pc_surface_map(u->s, f, &st);
    pushsurf(L, s, st, u->kind);
    return 1;
}


typedef struct {
    const pc_occluder *occ;
    pc_map scr;
    pc_polyline seen, hidden;
} hidden_ctx;

/* the screen point of the iso-curve at t and whether it is seen; 0 if it has no image */
static int sample(hidden_ctx *h, const pc_curve *c, double t, double xy[2], int *vis) {
    double x[PC_MAXDIM], hx[4], s[3];
    if (pc_curve_eval(c, t, x) != PC_OK) return 0;
    hx[0] = x[0], hx[1] = x[1], hx[2] = x[2], hx[3] = 1;
    pc_map_apply(&h->scr, hx, s);
    if (s[2] == 0) return 0;
    xy[0] = s[0] / s[2];
    xy[1] = s[1] / s[2];
    if (!isfinite(xy[0]) || !isfinite(xy[1])) return 0;
    *vis = pc_occluder_visible(h->occ, x);
    return 1;
}

/* Split the iso-curve c into its seen and hidden runs (samples at least as dense as the
 * flattened path, each change of visibility located by bisection). */
static int split_visibility(hidden_ctx *h, const pc_curve *c, int n) {
    double prev_t = c->t0;
    int prev_ok = 0, prev_vis = 1, st = PC_OK;
    for (int k = 0; k <= n && st == PC_OK; k++) {
        double t = c->t0 + (c->t1 - c->t0) * k / n, xy[2];
        int vis, ok = sample(h, c, t, xy, &vis);
        if (ok && prev_ok && vis != prev_vis) {
            double lo = prev_t, hi = t, mxy[2] = {xy[0], xy[1]};
            for (int i = 0; i < 30; i++) {   /* where the visibility changes */
                double mid = (lo + hi) / 2, m[2];
                int mv;
                if (!sample(h, c, mid, m, &mv)) break;
                if (mv == prev_vis) lo = mid; else { hi = mid; mxy[0] = m[0]; mxy[1] = m[1]; }
            }
            pc_polyline *from = prev_vis ? &h->seen : &h->hidden, *to = vis ? &h->seen : &h->hidden;
            st = pc_polyline_push(from, mxy[0], mxy[1], 0);
            if (st == PC_OK) st = pc_polyline_push(to, mxy[0], mxy[1], 1);
        }
        if (ok && st == PC_OK)   /* a run starts after a gap; a change started one above */
            st = pc_polyline_push(vis ? &h->seen : &h->hidden, xy[0], xy[1], !prev_ok);
        prev_t = t;
        prev_ok = ok;
        if (ok) prev_vis = vis;
    }
    return st;
}

static int opt_count(lua_State *L, int opts, const char *field, int dflt, int min, int max) {
    lua_getfield(L, opts, field);
    int isint = 1;
    lua_Integer n = lua_isnil(L, -1) ? dflt : lua_tointegerx(L, -1, &isint);
    if (!isint || n < min || n > max)
        pcl_error(L, "s:wireframe: %s must be an integer %d..%d, got %s", field, min, max,
                  pcl_shown(L, -1));
    lua_pop(L, 1);
    return (int)n;
}

/* The wireframe in the camera's scene: the surface as an occluder, its iso-lines (and its
 * silhouette) as 3-D strokes, all resolved against every surface of the figure at write. */
static int scene_wireframe(lua_State *L, pc_scene *sc, pc_surface *s, int nu, int nv, int mesh,
                           int outline, int color) {
    const char *fn = "s:wireframe";
    int st = pc_scene_add_surface(sc, s, mesh), boundary = outline & 2;
    outline &= 1;
    for (int dir = 0; dir < 2 && st == PC_OK; dir++) {
        int n = dir == 0 ? nu : nv;
        if (n == 0 && boundary) n = 1;   /* the two edges of this family */
        double lo = dir == 0 ? s->u0 : s->v0, hi = dir == 0 ? s->u1 : s->v1;
        for (int i = 0; n > 0 && i <= n && st == PC_OK; i++) {
            pc_curve *c = pc_surface_iso(s, dir, lo + (hi - lo) * i / n, &st);
            if (!c) break;
            st = pcl_scene_curve(L, sc, c, 256, color);
            pc_curve_release(c);
        }
    }
    if (outline && st == PC_OK) {
        double *seg;
        size_t nseg;
        pc_map scr;
        pcl_screen_map(L, pcl_camera(L), &scr);
        st = pc_surface_silhouette(s, &scr, 4 * mesh, 4 * mesh, &seg, &nseg);
        for (size_t i = 0; st == PC_OK && i < nseg; i++)
            st = pc_scene_add_polyline(sc, 2, seg + 6 * i, NULL, color, pcl_canvas(L)->pen);
        if (st == PC_OK || nseg) free(seg);
    }
    return st == PC_OK ? 0 : pcl_raise_status(L, fn, st);
}

/* s:wireframe{nu = 10, nv = 10, color = c, tol = px, map = f, hidden = "hide"|"dashed",
 * mesh = 48}: the iso-lines u = u0 + i (u1 - u0)/nu and v = v0 + j (v1 - v0)/nv, each
 * flattened and drawn as a path through the map or the camera.  With hidden, the parts the
 * surface itself hides (depth test against a mesh of mesh x mesh quads, hidden.h) are left
 * out or drawn dashed. */
static int s_wireframe(lua_State *L) {
    const char *fn = "s:wireframe";
    lsurf *u = checksurf(L, 1, fn);
    if (lua_isnoneornil(L, 2)) {
        lua_settop(L, 1);
        lua_newtable(L);
    }
    if (!lua_istable(L, 2)) return pcl_argerror_full(L, fn, 2, 1, "opts", "a table");
    int nu = opt_count(L, 2, "nu", 10, 0, 1000), nv = opt_count(L, 2, "nv", 10, 0, 1000);
    int mesh = opt_count(L, 2, "mesh", 48, 1, 1024);
    lua_getfield(L, 2, "silhouette");
    int outline = lua_toboolean(L, -1);
    lua_getfield(L, 2, "boundary");
    int boundary = lua_toboolean(L, -1);
    lua_pop(L, 2);
    lua_getfield(L, 2, "color");
    pc_canvas *cv = pcl_canvas(L);
    int color = pcl_optcolor(L, -1, cv);
    lua_getfield(L, 2, "tol");
    double tol = luaL_optnumber(L, -1, 0.25);
    if (!(tol > 0)) return pcl_error(L, "%s: tol must be a positive number of pixels", fn);
    int mode = 0;   /* 0 every line, 1 hide, 2 dashed */
    if (lua_getfield(L, 2, "hidden") != LUA_TNIL) {
        const char *m = lua_tostring(L, -1);
        if (lua_type(L, -1) == LUA_TSTRING && !strcmp(m, "hide")) mode = 1;
        else if (lua_type(L, -1) == LUA_TSTRING && !strcmp(m, "dashed")) mode = 2;
        else if (!(lua_type(L, -1) == LUA_TSTRING && !strcmp(m, "show")))
            return pcl_error(L, "%s: hidden must be \"hide\", \"dashed\" or \"show\", got %s", fn,
                             pcl_shown(L, -1));
    }
    lua_getfield(L, 2, "map");
    pc_surface *s = u->s;
    const pc_map *f = pcl_drawing_map(L, lua_gettop(L), s->dim, fn);
    if (mode && (s->dim != 3 || !f))
        return pcl_error(L, "%s: hidden lines need a 3-D surface seen through a projection", fn);
    if (outline && (s->dim != 3 || !f))
        return pcl_error(L, "%s: a silhouette needs a 3-D surface seen through a projection", fn);
    /* the camera's scene (pcl_scene.h): the surface hides, its lines are hidden, at write */
    pc_scene *sc = !mode && s->dim == 3 && lua_isnil(L, -1) ? pcl_scene(L) : NULL;
    if (sc) return scene_wireframe(L, sc, s, nu, nv, mesh, outline | boundary << 1, color);
    hidden_ctx h = {0};
    pc_occluder *occ = NULL;
    if (mode) {
        int st;
        pcl_screen_map(L, f, &h.scr);
        occ = pc_occluder_new(s, &h.scr, mesh, mesh, &st);
        if (!occ) return pcl_raise_status(L, fn, st);
        h.occ = occ;
    }
    pc_stroke pen = cv->pens[cv->pen];   /* to restore after the dashed hidden parts */
    int st = PC_OK, drawn = PC_OK;
    for (int dir = 0; dir < 2 && st == PC_OK && drawn == PC_OK; dir++) {
        int n = dir == 0 ? nu : nv;
        double lo = dir == 0 ? s->u0 : s->v0, hi = dir == 0 ? s->u1 : s->v1;
        if (n == 0 && boundary) n = 1;   /* the two edges of this family */
        for (int i = 0; n > 0 && i <= n && st == PC_OK && drawn == PC_OK; i++) {
            pc_curve *c = pc_surface_iso(s, dir, lo + (hi - lo) * i / n, &st);
            if (!c) break;
            pc_polyline pl = {0};
            st = pcl_flatten(L, c, c->t0, c->t1, 1, f, 1, tol, &pl);
            if (st == PC_OK && !mode) drawn = pcl_draw_polyline(L, &pl, color, 0);
            if (st == PC_OK && mode) {
                int samples = (int)fmin(8192, fmax(64, 4.0 * (double)pl.n));
                st = split_visibility(&h, c, samples);
                if (st == PC_OK) drawn = pcl_draw_polyline(L, &h.seen, color, 0);
                if (st == PC_OK && drawn == PC_OK && mode == 2 && h.hidden.n) {
                    double dash[2] = {3, 3};
                    pc_pen(cv, pen.width, dash, 2);
                    drawn = pcl_draw_polyline(L, &h.hidden, color, 0);
                    pc_pen(cv, pen.width, pen.dash, pen.ndash);
                }
                h.seen.n = h.hidden.n = 0;
            }
            pc_polyline_free(&pl);
            pc_curve_release(c);
        }
    }
    if (outline && st == PC_OK && drawn == PC_OK) {   /* the silhouette, hidden by the surface too */
        double *seg;
        size_t nseg;
        pcl_screen_map(L, f, &h.scr);
        st = pc_surface_silhouette(s, &h.scr, 4 * mesh, 4 * mesh, &seg, &nseg);
        for (size_t i = 0; st == PC_OK && drawn == PC_OK && i < nseg; i++) {
            double xy[4];
            for (int e = 0; e < 2; e++) {
                double hx[4] = {seg[6 * i + 3 * e], seg[6 * i + 3 * e + 1], seg[6 * i + 3 * e + 2], 1}, o[3];
                pc_map_apply(&h.scr, hx, o);
                pc_screen_to_world(cv, o[0] / o[2], o[1] / o[2], &xy[2 * e], &xy[2 * e + 1]);
            }
            drawn = pc_path(cv, 2, xy, NULL, 0, 0, color);
        }
        if (st == PC_OK) free(seg);
    }
    pc_polyline_free(&h.seen);
    pc_polyline_free(&h.hidden);
    pc_occluder_free(occ);
    if (drawn != PC_OK) return pcl_error(L, "%s: %s", fn, cv->error);
    if (st != PC_OK) return pcl_raise_status(L, fn, st);
    return 0;
}

/* ---- shading ----------------------------------------------------------------------------- */

/* The house error for a field of the options table of s:shade (argument #1 of the method);
 * the value at the stack top. */
static int shade_field_error(lua_State *L, const char *field, const char *expected) {
    const char *what = lua_pushfstring(L, "opts.%s", field);
    return pcl_argerror_full(L, "s:shade", lua_gettop(L) - 1, 1, what, expected);
}

/* opts.field (at the stack top) as a colour: an attribute of the screen or "#rrggbb"; its
 * rgb into *rgb and its attribute (a true colour allocated for a string) returned. */
static int shade_color(lua_State *L, pc_canvas *cv, const char *field, pc_rgb *rgb) {
    char expected[64];
    snprintf(expected, sizeof expected, "a colour number 0..%d or \"#rrggbb\"", cv->ncolors - 1);
    if (lua_type(L, -1) == LUA_TSTRING) {
        size_t len;
        const char *h = lua_tolstring(L, -1, &len);
        unsigned v[3];
        int ok = len == 7 && h[0] == '#';
        for (size_t k = 1; ok && k < 7; k++) ok = isxdigit((unsigned char)h[k]) != 0;
        if (!ok || sscanf(h + 1, "%2x%2x%2x", &v[0], &v[1], &v[2]) != 3)
            return pcl_error(L, "s:shade: argument #1 (opts.%s) must be %s, got \"%s\"", field,
                             expected, h);
        *rgb = (pc_rgb){(uint8_t)v[0], (uint8_t)v[1], (uint8_t)v[2]};
        int attr = pc_rgb_color(cv, *rgb);
        if (attr < 0) return pcl_error(L, "s:shade: %s", cv->error);
        return attr;
    }
    int isint;
    lua_Integer a = lua_tointegerx(L, -1, &isint);
    if (lua_type(L, -1) != LUA_TNUMBER || !isint || a < 0 || a > PC_MAX_ATTR ||
        pc_canvas_rgb(cv, (int)a, rgb) != PC_OK)
        return shade_field_error(L, field, expected);
    return (int)a;
}

/* s:shade{nu = 40, nv = 40, color = c, light = V(...), ambient = 0, mesh = c, map = f}: the
 * surface as nu x nv quads through the map or the camera, each filled with its Lambert shade
 * of the base colour (stdlib/geom/shade.h) in painter's order, each outline drawn over its
 * fill in the mesh colour when mesh is given.  Returns the number of quads drawn. */
static int s_shade(lua_State *L) {
    const char *fn = "s:shade";
    lsurf *u = checksurf(L, 1, fn);
    if (lua_isnoneornil(L, 2)) {
        lua_settop(L, 1);
        lua_newtable(L);
    }
    if (!lua_istable(L, 2)) return pcl_argerror_full(L, fn, 2, 1, "opts", "a table");
    lua_settop(L, 2);
    pc_canvas *cv = pcl_canvas(L);
    pc_shade_opts o = {.nu = 40, .nv = 40};
    static const char *const counts[2] = {"nu", "nv"};
    for (int k = 0; k < 2; k++) {
        if (lua_getfield(L, 2, counts[k]) != LUA_TNIL) {
            int isint;
            lua_Integer v = lua_tointegerx(L, -1, &isint);
            if (lua_type(L, -1) != LUA_TNUMBER || !isint || v < 1 || v > 1024)
                shade_field_error(L, counts[k], "an integer 1..1024");
            *(k ? &o.nv : &o.nu) = (int)v;
        }
        lua_pop(L, 1);
    }
    pc_rgb base;
    if (lua_getfield(L, 2, "color") != LUA_TNIL) shade_color(L, cv, "color", &base);
    else pc_canvas_rgb(cv, cv->fg, &base);
    lua_pop(L, 1);
    int mesh = -1;
    pc_rgb ignored;
    if (lua_getfield(L, 2, "mesh") != LUA_TNIL) mesh = shade_color(L, cv, "mesh", &ignored);
    lua_pop(L, 1);
    if (lua_getfield(L, 2, "light") != LUA_TNIL) {
        pcl_value *v = pcl_tovalue(L, -1);
        if (!v || v->n != 3 || v->h[3] != 0)
            shade_field_error(L, "light", "a 3-D vector (the direction towards the light)");
        for (int k = 0; k < 3; k++) o.light[k] = v->h[k];
        if (o.light[0] == 0 && o.light[1] == 0 && o.light[2] == 0)
            shade_field_error(L, "light", "a nonzero vector (the direction towards the light)");
        o.has_light = 1;
    }
    lua_pop(L, 1);
    if (lua_getfield(L, 2, "ambient") != LUA_TNIL) {
        o.ambient = lua_tonumber(L, -1);
        if (lua_type(L, -1) != LUA_TNUMBER || !(o.ambient >= 0 && o.ambient <= 1))
            shade_field_error(L, "ambient", "a number 0..1");
    }
    lua_pop(L, 1);
    pc_surface *s = u->s;
    if (s->dim != 3)
        return pcl_error(L, "%s: shading needs a 3-D surface seen through a projection, this one "
                            "is %d-D", fn, s->dim);
    lua_getfield(L, 2, "map");
    const pc_map *f = pcl_drawing_map(L, lua_gettop(L), 3, fn);
    pc_map scr;
    pcl_screen_map(L, f, &scr);
    pcl_callback_state(L);
    pc_shade_quad *q;
    size_t n;
    int st = pc_shade_quads(s, &scr, &o, &q, &n);
    if (st == PC_ESINGULAR)
        return pcl_error(L, "%s: the projection is singular (it flattens space onto a line)", fn);
    if (st != PC_OK) return pcl_raise_status(L, fn, st);
    int drawn = pc_draw_shaded(cv, q, n, base, mesh);
    free(q);
    if (drawn != PC_OK) return pcl_error(L, "%s: %s", fn, cv->error);
    lua_pushinteger(L, (lua_Integer)n);
    return 1;
}

static int s_index(lua_State *L) {
    lsurf *u = checksurf(L, 1, "surface");
    const char *k = lua_tostring(L, 2);
    if (k) {
        pc_surface *s = u->s;
        if (!strcmp(k, "dim")) { lua_pushinteger(L, s->dim); return 1; }
        if (!strcmp(k, "kind")) { lua_pushstring(L, u->kind + (strncmp(u->kind, "surface.", 8) ? 0 : 8)); return 1; }
        if (!strcmp(k, "u0")) { lua_pushnumber(L, s->u0); return 1; }
        if (!strcmp(k, "u1")) { lua_pushnumber(L, s->u1); return 1; }
        if (!strcmp(k, "v0")) { lua_pushnumber(L, s->v0); return 1; }
        if (!strcmp(k, "v1")) { lua_pushnumber(L, s->v1); return 1; }
    }
    lua_pushvalue(L, 2);
    lua_rawget(L, lua_upvalueindex(1));
    return 1;
}

static int s_tostring(lua_State *L) {
    lsurf *u = checksurf(L, 1, "surface");
    pc_surface *s = u->s;
    lua_pushfstring(L, "%s(%d-D, u in [%s, %s], v in [%s, %s])", u->kind, s->dim,
                    pcl_pushnum(L, s->u0), pcl_pushnum(L, s->u1), pcl_pushnum(L, s->v0),
                    pcl_pushnum(L, s->v1));
    return 1;
}

void pcl_open_surface(lua_State *L) {
    int module = lua_gettop(L);
    lua_newtable(L);
    int methods = lua_gettop(L);
    static const luaL_Reg mfns[] = {{"eval", s_call}, {"partials", s_partials},
                                    {"normal", s_normal}, {"iso", s_iso}, {"map", s_map},
                                    {"wireframe", s_wireframe}, {"shade", s_shade},
                                    {NULL, NULL}};
    luaL_setfuncs(L, mfns, 0);
    luaL_newmetatable(L, SURF_MT);
    static const luaL_Reg meta[] = {{"__call", s_call}, {"__tostring", s_tostring},
                                    {"__gc", s_gc}, {NULL, NULL}};
    luaL_setfuncs(L, meta, 0);
    lua_pushvalue(L, methods);
    lua_pushcclosure(L, s_index, 1);
    lua_setfield(L, -2, "__index");
    lua_pop(L, 2);

    lua_newtable(L);   /* the table `surface`, callable as surface(f, u0, u1, v0, v1) */
    static const luaL_Reg fns[] = {{"bilinear", l_bilinear}, {"bezier", l_bezier},
                                   {"bspline", l_bspline},   {"hermite", l_hermite},
                                   {"ruled", l_ruled},       {"coons", l_coons},
                                   {"revolution", l_revolution}, {NULL, NULL}};
    luaL_setfuncs(L, fns, 0);
    lua_newtable(L);
    lua_pushcfunction(L, l_func);
    lua_setfield(L, -2, "__call");
    lua_setmetatable(L, -2);
    lua_setfield(L, module, "surface");
    lua_settop(L, module);
}
