/* Binding of the one surface type (stdlib/geom/surface.h): the table `surface` of constructors,
 * callable as surface(f, u0, u1, v0, v1) for a Lua function or a point equation, and the
 * methods of a surface s (s(u, v), s:iso, s:wireframe, s:shade, ...), declared below. */
#include "wireframe.h"
#include "pcl_draw.h"   /* the layer, the core calls, tagged blocks, the camera's scene */
#include "pcl_expr.h"

#define SURF_MT "surface"
static const char SURF_TAG = 's';   /* its address tags the type (PCL_SELF_TAG) */

typedef struct {
    PCL_SELF;           /* its own address: a forged surface is refused (pcl.h) */
    pc_surface *s;
    const char *kind;
} lsurf;

/* The surface object at idx or NULL; one given the metatable by the debug library is refused. */
static lsurf *tosurf(lua_State *L, int idx) { return pcl_tagged_udata(L, idx, &SURF_TAG, SURF_MT, sizeof(lsurf), 0); }

pc_surface *pcl_tosurface(lua_State *L, int idx) {
    lsurf *u = tosurf(L, idx);
    return u ? u->s : NULL;
}

int pcl_push_made_surface(lua_State *L, pc_surface *s, const int *status, const char *kind) {
    if (!s) pcl_raise_status(L, kind, *status);
    lsurf *u = pcl_tagged_new(L, sizeof *u, &SURF_TAG, SURF_MT);
    *u = (lsurf){u->self, s, kind};
    return 1;
}

/* The receiver of a method: a live surface (the layer arms the callbacks of a Lua surface). */
static void *self_surf(lua_State *L, int idx) {
    lsurf *u = tosurf(L, idx);
    return u && u->s ? u : NULL;
}

static int s_gc(lua_State *L) {
    lsurf *u = pcl_tagged_udata(L, 1, &SURF_TAG, SURF_MT, sizeof *u, PCL_TAG_GC);
    if (u && u->s) {   /* never a forged one */
        pcl_callback_state(L);
        pc_surface_release(u->s);
        u->s = NULL;
    }
    return 0;
}

/* A Lua function as a surface (pcl_luafn, pcl_core.h), whose nargs is the dimension of its points */
static int luasurf_eval(void *ud, double u, double v, int order, double *out) {
    pcl_luafn *f = ud;
    if (order > 0) return PC_EDOMAIN;
    lua_State *L = pcl_current_state();
    int top = lua_gettop(L);
    if (!lua_checkstack(L, f->nargs + 4)) return PC_ENOMEM;
    lua_rawgeti(L, LUA_REGISTRYINDEX, f->ref[0]);
    pcl_push_results(L, 0, "n n", u, v);
    if (lua_pcall(L, 2, 1, 0) != LUA_OK) return pcl_callback_failed(L);
    pcl_value *p = pcl_tovalue(L, -1);
    if (!p || p->n != f->nargs) {
        lua_pushfstring(L, "surface: the function must return a %d-D point, got %s", f->nargs,
                        p ? "another dimension" : luaL_typename(L, -1));
        return pcl_callback_failed(L);
    }
    memcpy(out, p->h, sizeof(double) * (size_t)(f->nargs + 1));
    lua_settop(L, top);
    return PC_OK;
}

/* Push the surface a constructor made, or raise its status as pc_surface_why explains it. */
static int made(lua_State *L, pc_surface *s, const int *st) {
    if (!s) pcl_check(L, *st, pc_surface_why);
    return pcl_push_made_surface(L, s, st, pcl_name(L));
}

static const pcl_arg bilinear_args[] = {A_SAMEPOINT("P00"), A_SAMEPOINT("P10"), A_SAMEPOINT("P01"),
                                        A_SAMEPOINT("P11"), PCL_END};
PCL_BODY(l_bilinear, a) {
    int st;
    return made(L, pc_surface_bilinear(a[0].n, a[0].v, a[1].v, a[2].v, a[3].v, &st), &st);
}

/* A net: a list of nu >= 2 rows of nv >= 2 values (weighted points make it rational), as
 * homogeneous rows in a scratch userdata above the arguments: out->list, out->v = nu, nv, dim. */
static int read_net(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    if (!lua_istable(L, idx)) return 0;
    int m = (int)luaL_len(L, idx), n = 0, d = 0;
    if (m < 2) return pcl_argfail(L, idx, "must have at least 2 rows, got %d", m);
    double *h = NULL;
    for (int i = 1; i <= m; i++) {
        if (lua_geti(L, idx, i) != LUA_TTABLE)
            pcl_argfail(L, idx, "row [%d] must be a list of points, got %s", i, pcl_shown(L, -1));
        int len = (int)luaL_len(L, -1);
        if (i > 1 && len != n) pcl_argfail(L, idx, "row [%d] holds %d points, but row [1] holds %d", i, len, n);
        if ((n = len) < 2) return pcl_argfail(L, idx, "rows must hold at least 2 points");
        if ((long)m * n > 100000) return pcl_argfail(L, idx, "is too large");
        for (int j = 1; j <= n; j++) {
            lua_geti(L, -1, j);
            pcl_value *v = pcl_tovalue(L, -1);
            if (!v) pcl_argfail(L, idx, "[%d][%d] must be a point, got %s", i, j, pcl_shown(L, -1));
            if (!h) {                     /* [1][1] sets the dimension; the buffer goes below row [1] */
                h = lua_newuserdatauv(L, sizeof(double) * (size_t)m * n * ((d = v->n) + 1), 0);
                lua_insert(L, -3);
            }
            if (v->n != d) pcl_argfail(L, idx, "[%d][%d] is %d-D, but [1][1] is %d-D (mixed dimensions)", i, j, v->n, d);
            for (int k = 0; k <= d; k++) {
                if (!isfinite(v->h[k])) pcl_argfail(L, idx, "[%d][%d] has NaN or infinite coordinates", i, j);
                h[((size_t)(i - 1) * n + (j - 1)) * (d + 1) + k] = v->h[k];
            }
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    out->list = h;
    out->v[0] = m, out->v[1] = n, out->v[2] = d;
    return 1;
}

#define NET {.name = "net", .kind = PCL_ANY, .read = read_net, .expect = "a list of rows of points"}
static const pcl_arg bezier_args[] = {NET, PCL_END};
PCL_BODY(l_bezier, a) {
    int st, nu = (int)a[0].v[0], nv = (int)a[0].v[1];
    return made(L, pc_surface_bezier((int)a[0].v[2], nu - 1, nv - 1, a[0].list, &st), &st);
}

static const pcl_arg bspline_args[] = {NET, {.name = "p", .kind = PCL_INTEGER}, {.name = "q", .kind = PCL_INTEGER},
                                       {.name = "uknots", .kind = PCL_ANY, .flags = PCL_OPT},
                                       {.name = "vknots", .kind = PCL_ANY, .flags = PCL_OPT}, PCL_END};
PCL_BODY(l_bspline, a) {
    int nu = (int)a[0].v[0], nv = (int)a[0].v[1], p = (int)a[1].x, q = (int)a[2].x;
    if (p < 1 || p >= nu) return pcl_argfail(L, 2, "must be 1..%d (below the %d rows)", nu - 1, nu);
    if (q < 1 || q >= nv) return pcl_argfail(L, 3, "must be 1..%d (below the %d columns)", nv - 1, nv);
    double *uk, *vk;   /* the knots as bspline reads them (l_curve.c) */
    pc_knot_kind ukind = pcl_checkknots(L, 4, nu, p, &uk), vkind = pcl_checkknots(L, 5, nv, q, &vk);
    int st;
    return made(L, pc_surface_bspline((int)a[0].v[2], p, q, nu, nv, a[0].list, ukind, uk, vkind, vk, &st), &st);
}

/* P: 4 points, Pu, Pv, Puv: 4 vectors of their dimension, at the corners in this order */
#define CORNERS(nm, k, what) {.name = nm, .kind = k, .flags = PCL_REQ | PCL_SAMEDIM, .lo = 4, .hi = 4, \
    .expect = "a list of 4 " what " (corners (0,0), (1,0), (0,1), (1,1))", .shown = "{4}"}
static const pcl_arg hermite_keys[] = {CORNERS("P", PCL_POINTS, "points"), CORNERS("Pu", PCL_VECTORS, "vectors"),
                                       CORNERS("Pv", PCL_VECTORS, "vectors"), CORNERS("Puv", PCL_VECTORS, "vectors"),
                                       PCL_END};
static const pcl_arg hermite_args[] = {{.name = "spec", .kind = PCL_OPTIONS, .flags = PCL_CALLTABLE, .keys = hermite_keys}, PCL_END};
PCL_BODY(l_hermite, a) {   /* spec; P, Pu, Pv, Puv */
    int st;
    return made(L, pc_surface_hermite(a[1].dim, a[1].list, a[2].list, a[3].list, a[4].list, &st), &st);
}

#define A_CURVE_LIKE(nm) {.name = nm, .kind = PCL_CURVE, .flags = PCL_SAMEDIM}   /* of argument #1's dimension */

static const pcl_arg ruled_args[] = {A_CURVE_LIKE("c0"), A_CURVE_LIKE("c1"), PCL_END};
static const pcl_arg coons_args[] = {A_CURVE_LIKE("cu0"), A_CURVE_LIKE("cu1"), A_CURVE_LIKE("c0v"), A_CURVE_LIKE("c1v"),
                                     PCL_END};
/* surface.ruled(c0, c1) and surface.coons(cu0, cu1, c0v, c1v), one body told apart by the declared name */
PCL_BODY(l_curves, a) {
    int st;
    pc_surface *s = strcmp(pcl_name(L), "surface.ruled") ? pc_surface_coons(a[0].obj, a[1].obj, a[2].obj, a[3].obj, &st)
                                                         : pc_surface_ruled(a[0].obj, a[1].obj, &st);
    return made(L, s, &st);
}

static const pcl_arg revolution_args[] = {A_CURVE("profile", 3), A_POINT("A", 3), A_VECTOR("d", 3),
                                          A_NUMOPT("v0", 0, "0"), A_NUMOPT("v1", 2 * M_PI, "2*pi"), PCL_END};
PCL_BODY(l_revolution, a) {
    int st;
    return made(L, pc_surface_revolution(a[0].obj, a[1].v, a[2].v, a[3].x, a[4].x, &st), &st);
}

/* f: a Lua function (u, v) -> point or a compiled point equation (l_expr.c). */
static int read_surface_fn(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, PCL_UNUSED pcl_val *out) {
    return lua_isfunction(L, idx) || pcl_isequation(L, idx);
}

static const pcl_arg func_args[] = {{.name = "f", .kind = PCL_ANY, .read = read_surface_fn,
                                     .expect = "a function (u, v) -> point or an equation"},
                                    A_NUM("u0"), A_NUM("u1"), A_NUM("v0"), A_NUM("v1"), PCL_END};
/* surface(f, u0, u1, v0, v1): the __call of the table (the table itself is argument 1) */
PCL_BODY(l_func, a) {
    lua_settop(L, 6);
    lua_remove(L, 1);
    int st;
    if (!(a[2].x > a[1].x) || !(a[4].x > a[3].x)) return pcl_fail(L, "need u0 < u1 and v0 < v1");
    if (pcl_isequation(L, 1)) {                 /* a compiled point equation (l_expr.c) */
        double lo[2] = {a[1].x, a[3].x}, hi[2] = {a[2].x, a[4].x};
        return made(L, pcl_eq_object(L, 2, lo, hi, &st), &st);
    }
    lua_pushvalue(L, 1);
    pcl_push_results(L, 0, "n n", a[1].x, a[3].x);
    lua_call(L, 2, 1);
    pcl_value *p = pcl_tovalue(L, -1);
    if (!p) return pcl_fail(L, "f(u0, v0) must return a point, got %s", luaL_typename(L, -1));
    pcl_luafn *f = pcl_luafn_new(L, 1, (int[]){1});
    f->nargs = p->n;
    return made(L, pc_surface_func(p->n, a[1].x, a[2].x, a[3].x, a[4].x, luasurf_eval, pcl_luafn_free, f, &st), &st);
}

static const pcl_arg uv_args[] = {A_NUM("u"), A_NUM("v"), PCL_END};
/* s(u, v), s:eval, s:partials and s:normal, one body told apart by the declared name */
PCL_METHOD(s_call, lsurf *u, a) {
    static __typeof__(pc_surface_eval_checked) *const at[] = {pc_surface_eval_checked,
        pc_surface_partials_checked, pc_surface_normal_checked};
    static const char *const spec[] = {"p", "p v v", "v"};
    int i = !strcmp(pcl_name(L), "s:normal") ? 2 : !strcmp(pcl_name(L), "s:partials");
    double out[3 * PC_MAXDIM];
    pc_why_call why;
    pcl_check(L, at[i](pcl_name(L), u->s, a[0].x, a[1].x, out, &why), why.row);
    return pcl_push_packed(L, u->s->dim, spec[i], out);   /* a normal's surface is 3-D */
}

/* s:iso("u", value): the curve u = value (a curve in v); s:iso("v", value) likewise */
static const char *const FAMILIES[] = {"u", "v", NULL};
static const pcl_arg iso_args[] = {{.name = "family", .kind = PCL_ENUM, .choices = FAMILIES,
                                    .expect = "\"u\" (u = const) or \"v\" (v = const)"}, A_NUM("value"), PCL_END};
PCL_METHOD(s_iso, lsurf *u, a) {
    int st;
    return pcl_push_made(L, pc_surface_iso(u->s, a[0].n, a[1].x, &st), &st, "iso-curve");
}

static const pcl_arg map_args[] = {A_MAP("f"), PCL_END};
PCL_METHOD(s_map, lsurf *u, a) {
    pc_map *f = a[0].obj;
    if (f->nin != u->s->dim) return pcl_fail(L, "the map takes %d-D points, but the surface is %d-D", f->nin, u->s->dim);
    int st;
    return pcl_push_made_surface(L, pc_surface_map(u->s, f, &st), &st, u->kind);
}

/* The drawing map option of s:wireframe and s:shade: the map given (from dim-D to 2-D) or the
 * camera, and the map to the screen through it into scr. */
static const pc_map *drawing_map(lua_State *L, const pcl_val *m, int dim, pc_map *scr) {
    const pc_map *f = m->obj;
    if (f && (f->nout != 2 || f->nin != dim)) pcl_keyfail(L, "map", "must be a map from %d-D to 2-D", dim);
    f = f ? f : pcl_drawing_map(L, 0, dim, pcl_name(L));
    pcl_screen_map(L, f, scr);
    return f;
}

/* s:wireframe{...}: the iso-lines drawn by the core (wireframe.h) through the map or the camera */
static const char *const HIDDEN[] = {"show", "hide", "dashed", NULL};   /* 0 every line, 1 hide, 2 dashed */
#define COUNT(nm, top, d) {.name = nm, .kind = PCL_INTEGER, .flags = PCL_RANGE, .lo = 1, .hi = top, .dflt = d, .shown = #d}
#define COUNT0(nm) {.name = nm, .kind = PCL_INTEGER, .flags = PCL_RANGE, .lo = 0, .hi = 1000, .dflt = 10, .shown = "10"}
static const pcl_arg wireframe_keys[] = {
    COUNT0("nu"), COUNT0("nv"), {.name = "color", .kind = PCL_ANY, .read = pcl_read_color, .dflt = -1, .shown = "c"},
    {.name = "tol", .kind = PCL_NUMBER, .flags = PCL_POS, .dflt = 0.25, .shown = "px"}, {.name = "map", .kind = PCL_MAP, .shown = "m"},
    {.name = "hidden", .kind = PCL_ENUM, .choices = HIDDEN}, COUNT("mesh", 1024, 48),
    {.name = "silhouette", .kind = PCL_BOOLEAN, .shown = "false"}, {.name = "boundary", .kind = PCL_BOOLEAN, .shown = "false"}, PCL_END};
static const pcl_arg wireframe_args[] = {A_OPTIONS("opts", wireframe_keys), PCL_END};
PCL_METHOD(s_wireframe, lsurf *u, a) {   /* opts; nu, nv, color, tol, map, hidden, mesh, silhouette, boundary */
    pc_wireframe_opts o = {.nu = (int)a[1].x, .nv = (int)a[2].x, .color = (int)a[3].x, .tol = a[4].x, .hidden = a[6].n,
                           .mesh = (int)a[7].x, .silhouette = (int)a[8].x, .boundary = (int)a[9].x};
    pc_canvas *cv = pcl_canvas(L);
    pc_surface *s = u->s;
    pc_map scr;
    const pc_map *f = drawing_map(L, &a[5], s->dim, &scr);
    if ((o.hidden || o.silhouette) && (s->dim != 3 || !f))
        return pcl_fail(L, "%s a 3-D surface seen through a projection",
                        o.hidden ? "hidden lines need" : "a silhouette needs");
    /* the camera's scene (pcl_draw.h): the surface hides, its lines are hidden, at write */
    pc_scene *sc = !o.hidden && s->dim == 3 && !a[5].present ? pcl_scene(L) : NULL;
    int drawn = PC_OK, st = sc ? pc_scene_wireframe(sc, s, &scr, &o, pcl_active_canvas(L)->pen)
                               : pc_draw_wireframe(cv, s, &scr, &o, &drawn);
    pcl_check_canvas(L, cv, drawn);
    pcl_check(L, st, NULL);
    return 0;
}

/* A colour of s:shade: a true colour's attribute above the screen's colours too (dim 1). */
#define SHADE_COLOR(nm) {.name = nm, .kind = PCL_ANY, .read = pcl_read_color, .dim = 1, .dflt = -1, .shown = "c"}
static const pcl_arg shade_keys[] = {
    COUNT("nu", 1024, 40), COUNT("nv", 1024, 40), SHADE_COLOR("color"),
    {.name = "light", .kind = PCL_VECTOR, .dim = 3, .expect = "a 3-D vector (the direction towards the light)", .shown = "V(...)"},
    {.name = "ambient", .kind = PCL_NUMBER, .flags = PCL_RANGE, .lo = 0, .hi = 1, .shown = "0"},
    SHADE_COLOR("mesh"), {.name = "map", .kind = PCL_MAP, .shown = "m"}, PCL_END};
/* s:shade{...}: the quads drawn by the core (wireframe.h) through the map or the camera; their count */
static const pcl_arg shade_args[] = {A_OPTIONS("opts", shade_keys), PCL_END};
PCL_METHOD(s_shade, lsurf *u, a) {   /* opts; nu, nv, color, light, ambient, mesh, map */
    pc_canvas *cv = pcl_canvas(L);
    pc_shade_opts o = {.nu = (int)a[1].x, .nv = (int)a[2].x, .has_light = a[4].present, .ambient = a[5].x};
    pc_rgb base;
    pc_map scr;
    size_t n;
    memcpy(o.light, a[4].v, sizeof o.light);
    pc_canvas_rgb(cv, a[3].present ? (int)a[3].x : cv->fg, &base);
    if (u->s->dim != 3)
        return pcl_fail(L, "shading needs a 3-D surface seen through a projection, this one is %d-D", u->s->dim);
    drawing_map(L, &a[7], 3, &scr);
    pc_scene *sc = !a[7].present ? pcl_scene(L) : NULL;   /* the camera's (pcl_draw.h) */
    int drawn, st = pc_draw_shaded_surface(cv, sc, u->s, &scr, &o, base, (int)a[6].x, &n, &drawn);
    pcl_check_canvas(L, cv, drawn);   /* (a failing canvas and a failing geometry exclude each other) */
    pcl_check(L, st, pc_surface_why);
    return pcl_push_results(L, 0, "i", (int)n);
}

/* The surface a metamethod is called on (never a script's own call by name). */
static lsurf *meta_self(lua_State *L) {
    lsurf *u = self_surf(L, 1);
    if (!u) pcl_error(L, "surface: a metamethod called on %s, not a surface", pcl_shown(L, 1));
    return u;
}

/* the fields s.dim, s.kind (its constructor's name without "surface."), s.u0 .. s.v1, then the methods */
static int s_index(lua_State *L) {
    static const char *const DOMAIN[] = {"u0", "u1", "v0", "v1", NULL};
    lsurf *u = meta_self(L);
    const char *k = lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : "";
    double domain[4] = {u->s->u0, u->s->u1, u->s->v0, u->s->v1};
    int i = 0;
    while (DOMAIN[i] && strcmp(DOMAIN[i], k)) i++;
    if (!strcmp(k, "dim")) lua_pushinteger(L, u->s->dim);
    else if (!strcmp(k, "kind")) lua_pushstring(L, u->kind + (strncmp(u->kind, "surface.", 8) ? 0 : 8));
    else if (DOMAIN[i]) lua_pushnumber(L, domain[i]);
    else lua_rawget(L, lua_upvalueindex(1));   /* the key at 2, on the top */
    return 1;
}

static int s_tostring(lua_State *L) {
    lsurf *u = meta_self(L);
    pc_surface *s = u->s;
    lua_pushfstring(L, "%s(%d-D, u in [%s, %s], v in [%s, %s])", u->kind, s->dim, pcl_pushnum(L, s->u0),
                    pcl_pushnum(L, s->u1), pcl_pushnum(L, s->v0), pcl_pushnum(L, s->v1));
    return 1;
}

#define METHOD(nm, f, decl, res, text) {.name = nm, .fn = f, .args = decl, .result = res, .help = text, .self = self_surf, .selftype = "surface"}
#define METHOD_SIG(nm, f, decl, forms, text) {.name = nm, .fn = f, .args = decl, .sig = forms, .help = text, .self = self_surf, .selftype = "surface"}
static const pcl_fn methods[] = {
    METHOD("s:eval", s_call, uv_args, "point", "The point of the surface at (u, v), as s(u, v)."),
    METHOD("s:partials", s_call, uv_args, "P, Su, Sv", "The point at (u, v) and the partial derivatives there."),
    METHOD("s:normal", s_call, uv_args, "vector", "The unit normal of a 3-D surface at (u, v): Su x Sv normalized."),
    METHOD_SIG("s:iso", s_iso, iso_args, "s:iso(\"u\"|\"v\", value) -> curve", "The iso-curve u = value (a curve in v) or v = value, exact for tensor-product patches."),
    METHOD("s:map", s_map, map_args, "s", "The image of the surface under a map."),
    METHOD_SIG("s:wireframe", s_wireframe, wireframe_args, "s:wireframe{nu = 10, nv = 10, color = c, tol = px, map = m, hidden = \"hide\"|\"dashed\", mesh = 48, silhouette = false, boundary = false}", "Draw the iso-lines as paths through map or the camera (nu or nv 0: one family only; silhouette: the outline too; boundary: the four edge curves); hidden = \"hide\" leaves out what the surface itself hides, \"dashed\" dashes it; with a camera's hidden mode the surface joins its scene."),
    METHOD_SIG("s:shade", s_shade, shade_args, "s:shade{nu = 40, nv = 40, color = c, light = V(...), ambient = 0, mesh = c, map = m} -> quads", "Draw the 3-D surface through map or the camera as nu x nv quads, each filled with its flat (Lambert) shade of color by the angle between its normal and the light (default: from the viewer), farthest first (the painter's order); with mesh, each quad's outline too, so only the visible mesh shows."),
    PCL_END};
static const pcl_fn call[] = {{.name = "s", .fn = s_call, .args = uv_args, .self = self_surf, .selftype = "surface", .key = "__call", .topic = "s(u, v)", .callname = 1, .sig = "s(u, v) -> point", .help = "The point of a surface at (u, v); s:partials and s:normal give its derivatives and normal."}, PCL_END};
static const pcl_fn func_call[] = {{.name = "surface", .fn = l_func, .args = func_args, .result = "s", .self = pcl_self_table, .selftype = "table", .key = "__call", .help = "A Lua function (u, v) -> point as a surface."}, PCL_END};
static const pcl_fn fns[] = {
    PCL_FN("surface.bilinear", l_bilinear, bilinear_args, "s", "The bilinear patch with these corners at (u, v) = (0,0), (1,0), (0,1), (1,1)."),
    PCL_FN("surface.bezier", l_bezier, bezier_args, "s", "The tensor-product Bezier patch of a net (a list of rows along u of points; weighted points make it rational)."),
    PCL_FN("surface.bspline", l_bspline, bspline_args, "s", "The tensor-product B-spline (NURBS) patch of degrees p, q; knots as for bspline."),
    {.name = "surface.hermite", .fn = l_hermite, .args = hermite_args, .result = "s", .help = "The bicubic Hermite (Coons) patch from corner points, tangents and twists (corners (0,0), (1,0), (0,1), (1,1))."},
    PCL_FN("surface.ruled", l_curves, ruled_args, "s", "The ruled surface (1 - v) c0(u) + v c1(u) between two curves."),
    PCL_FN("surface.coons", l_curves, coons_args, "s", "The linear Coons patch of four boundary curves meeting at the corners: S(u, 0), S(u, 1), S(0, v), S(1, v)."),
    {.name = "surface.revolution", .fn = l_revolution, .args = revolution_args, .sig = "surface.revolution(profile, A, d [, v0, v1]) -> s", .help = "A 3-D profile curve turned about the axis through A with direction d by v in [v0, v1] (default a whole turn)."},
    PCL_END};

void pcl_open_surface(lua_State *L) {
    int module = lua_gettop(L);
    static const luaL_Reg meta[] = {{"__tostring", s_tostring}, {"__gc", s_gc}, {NULL, NULL}};
    pcl_open_type(L, SURF_MT, meta, call, methods, s_index);
    lua_pop(L, 1);
    pcl_new_table(L, module, "surface", fns, func_call);   /* callable as surface(f, u0, u1, v0, v1) */
}
