/* Binding of 3-D drawing: camera(f), the current projection and its scene of hidden lines
 * (pcl_draw.h), and curves drawn as one path (c:draw; _tk.draw_curve for plot and curvilinear.lua)
 * through the camera (or a map), WINDOW and VIEW to the canvas (curve_path.h). */
#include "pcl_draw.h"

#define CAMERA_KEY "pointcalc.camera"
#define HIDDEN_KEY "pointcalc.hidden"   /* the camera's hidden-line mode: -1 none, else a pc_hidden_mode */

pc_map *pcl_camera(lua_State *L) {
    lua_getfield(L, LUA_REGISTRYINDEX, CAMERA_KEY);
    pc_map *f = pcl_tomap(L, -1);
    lua_pop(L, 1);   /* the registry keeps the map alive */
    return f;
}

/* camera(f [, {hidden =}]), camera(nil), camera() */
static int l_camera(lua_State *L) {
    int given = !lua_isnone(L, 1);   /* asked before reading, which may fill the stack */
    pcl_val a[3] = {{0}};   /* projection, opts, hidden */
    PCL_READ(L, a);
    if (!given) {
        lua_getfield(L, LUA_REGISTRYINDEX, CAMERA_KEY);
        return 1;
    }
    pc_map *f = a[0].obj;
    if (f && f->nout != 2) return pcl_argfail(L, 1, "must map to 2-D points, but it maps to %d-D", f->nout);
    /* {hidden = ...}: the 3-D strokes from now on form a scene resolved at write (pcl_draw.h) */
    lua_pushinteger(L, a[2].present ? a[2].n : -1);
    lua_setfield(L, LUA_REGISTRYINDEX, HIDDEN_KEY);
    lua_settop(L, 1);
    lua_setfield(L, LUA_REGISTRYINDEX, CAMERA_KEY);
    return 0;
}

pc_scene *pcl_scene(lua_State *L) {
    lua_getfield(L, LUA_REGISTRYINDEX, HIDDEN_KEY);
    int mode = lua_isinteger(L, -1) ? (int)lua_tointeger(L, -1) : -1, st;
    lua_pop(L, 1);
    pc_map *f = pcl_camera(L), scr;
    if (mode < 0 || !f || f->nin != 3) return NULL;
    pcl_screen_map(L, f, &scr);
    pc_scene *sc = pc_canvas_scene(pcl_active_canvas(L), &scr, mode, &st);
    if (st != PC_OK) pcl_raise_status(L, pcl_fname(L), st);
    return sc;
}

int pcl_project(lua_State *L, int n, const double *h, double *x, double *y) {
    return pc_map_image_xy(pcl_camera(L), n, h, x, y);
}

/* ---- flattening through the projection and the window (stdlib/draw/curve_path.h) ---------- */

void pcl_screen_map(lua_State *L, const pc_map *f, pc_map *out) {
    pc_screen_map(pcl_canvas(L), f, out);
}

const pc_map *pcl_drawing_map(lua_State *L, int idx, int dim, const char *fname) {
    char why[160];
    int given = idx && !lua_isnoneornil(L, idx);
    const pc_map *f = pc_drawing_map(given ? pcl_tomap(L, idx) : NULL, given, pcl_camera(L), dim, why, sizeof why);
    if (*why) pcl_error(L, "%s: %s", fname, why);
    return f;
}

void pcl_draw_curve(lua_State *L, pc_curve *c, const pc_map *f, int pieces, double tol,
                    int color, int closed, const char *fname) {
    char why[200];
    pc_scene *sc = c->dim == 3 && f == pcl_camera(L) ? pcl_scene(L) : NULL;
    pcl_callback_state(L);
    int st = pc_curve_draw(pcl_canvas(L), sc, pcl_active_canvas(L)->pen, c, f, pieces, tol, color, closed, why,
                           sizeof why);
    if (st != PC_OK && *why) pcl_error(L, "%s: %s", fname, why);
    if (st != PC_OK) pcl_raise_status(L, fname, st);
}

static void *self_curve(lua_State *L, int idx) { return pcl_tocurve(L, idx); }

enum { O_TABLE, O_COLOR, O_TOL, O_MAP, O_CLOSED, O_T, O_BRUSH, O_DOTS, O_QB, O_N };
static const pcl_arg draw_keys[] = {
    {.name = "color", .kind = PCL_ANY, .read = pcl_read_color, .dflt = -1},
    {.name = "tol", .kind = PCL_NUMBER, .flags = PCL_POS, .dflt = 0.25, .shown = "0.25"},
    {.name = "map", .kind = PCL_ANY}, {.name = "closed", .kind = PCL_BOOLEAN},
    {.name = "t", .kind = PCL_ANY}, {.name = "brush", .kind = PCL_ANY},
    {.name = "dots", .kind = PCL_BOOLEAN}, {.name = "qb", .kind = PCL_BOOLEAN}, PCL_END};
static const pcl_arg draw_args[] = {A_OPTIONS("opts", draw_keys), PCL_END};

/* c:draw{...}: a path through the C path above; dots (t, brush, dots, qb) and maps that are
 * plain functions go to the Lua walkers of curves.lua (_tk.draw_dots, _tk.draw_mapped). */
PCL_METHOD(c_draw, pc_curve *c, o) {
    const char *via = o[O_T].present || o[O_BRUSH].present || o[O_DOTS].x || o[O_QB].x ? "draw_dots" : NULL;
    const pc_map *f = NULL;
    if (o[O_MAP].present) {
        lua_getfield(L, 2, "map");
        if (!(f = pcl_tomap(L, -1))) via = via ? via : "draw_mapped";
        else if (f->nout != 2 || f->nin != c->dim)
            pcl_keyfail(L, "map", "must be a map from %d-D to 2-D", c->dim);
    }
    if (via) {   /* the Lua walkers, with the options as given */
        lua_getfield(L, PCL_UPVALUE(1), via);
        lua_pushvalue(L, 1);
        if (o[O_TABLE].present) lua_pushvalue(L, 2);
        else lua_newtable(L);
        lua_call(L, 2, 0);
        return 0;
    }
    if (!f) f = pcl_drawing_map(L, 0, c->dim, pcl_name(L));
    pcl_draw_curve(L, c, f, 1, o[O_TOL].x, (int)o[O_COLOR].x, (int)o[O_CLOSED].x, pcl_name(L));
    return 0;
}

/* _tk.draw_curve(c, colour, tol, map, pieces, fname): the C path for the Lua helpers (plot,
 * C:draw), which have checked their options; errors name fname. */
static int tk_draw_curve(lua_State *L) {
    const char *fname = luaL_optstring(L, 6, "c:draw");
    pc_curve *c = pcl_meta_self(L, pcl_tocurve(L, 1), lua_pushfstring(L, "%s: not a curve", fname));
    pc_canvas *cv = pcl_canvas(L);
    int color = lua_isnoneornil(L, 2) ? -1 : pcl_color_at(L, 2, cv, 0);
    if (color == -2)
        return pcl_error(L, "%s: option 'color' must be a colour number 0..%d or \"#rrggbb\", got %s", fname,
                         cv->ncolors - 1, pcl_shown(L, 2));
    double tol = luaL_optnumber(L, 3, 0.25);
    if (!(tol > 0)) return pcl_error(L, "%s: option 'tol' must be a positive number, got %s", fname, pcl_shown(L, 3));
    const pc_map *f = pcl_drawing_map(L, 4, c->dim, fname);
    pcl_draw_curve(L, c, f, (int)luaL_optinteger(L, 5, 1), tol, color, 0, fname);
    return 0;
}

/* _tk.nearest(name, set) -> the key of the table set nearest to name (pcl_nearest_key), or nil:
 * curves.lua checks the option keys of its Lua-written calls with it */
static int tk_nearest(lua_State *L) {
    const char *near = pcl_nearest_key(L, luaL_checkstring(L, 1), 2);
    return near ? pcl_push_results(L, 0, "s", near) : 0;
}

static const char *const HIDDEN[] = {"show", "dashed", "hide", NULL};   /* a pc_hidden_mode */
static const pcl_arg camera_keys[] = {A_ENUM("hidden", HIDDEN), PCL_END};
static const pcl_arg camera_args[] = {{.name = "projection", .kind = PCL_MAP, .flags = PCL_OPT,
                                       .expect = "a map to the plane (or nil)"},
                                      A_OPTIONS("opts", camera_keys), PCL_END};
static const pcl_fn fns[] = {
    {.name = "camera", .fn = l_camera, .args = camera_args, .sig = "camera(f [, {hidden = \"dashed\"|\"hide\"|\"show\"}])\ncamera(nil)\ncamera() -> f", .help = "The current projection (a map to 2-D): with one set, drawing calls take its points (3-D) and draw their images; with hidden, 3-D lines, curves, marks and wireframes form a scene whose hidden parts are resolved when the picture is written, whatever the drawing order."},
    PCL_END};
static const pcl_fn methods[] = {
    {.name = "c:draw", .fn = c_draw, .args = draw_args, .self = self_curve, .selftype = "curve", .sig = "c:draw{color = c, tol = px, map = m, closed = false}\nc:draw{t = {a, b, step}, brush = \"pset\"|\"dot\"|fn, dots = true, qb = false, ...}", .help = "Draw the curve as one path, flattened to within tol pixels (default 1/4) through map or the camera; with t or a brush, dots as the listings draw them."},
    PCL_END};

void pcl_open_camera(lua_State *L) {
    int module = lua_gettop(L);
    pcl_register(L, module, fns, 0);
    static const luaL_Reg tk[] = {{"draw_curve", tk_draw_curve}, {"nearest", tk_nearest}, {NULL, NULL}};
    pcl_private(L, module);
    luaL_setfuncs(L, tk, 0);
    lua_getfield(L, -1, "curve_methods");
    lua_pushvalue(L, -2);                      /* c:draw's upvalue: _tk, for the Lua walkers */
    pcl_register(L, -2, methods, 1);
    lua_settop(L, module);
}
