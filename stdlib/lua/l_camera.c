/* Binding of 3-D drawing: the current projection and the drawing of curves as paths.
 *   camera(f)      set the current projection (a map from n-D to 2-D); with one set, every
 *                  drawing call takes n-D points and draws their images
 *   camera(f, {hidden = "dashed"|"hide"|"show"})  and 3-D curves, lines, markers and
 *                  wireframes form a scene whose hidden lines are resolved at write
 *   camera(nil)    back to plain 2-D drawing;  camera() -> the current map or nil
 * and, for stdlib/lua/curves.lua, _tk.draw_curve(c, colour, tol [, map]): the curve flattened
 * through the projection, WINDOW and VIEW to within tol pixels and drawn as one path. */
#include <math.h>
#include <string.h>
#include "pcl_curve.h"
#include "pcl_scene.h"

#define CAMERA_KEY "pointcalc.camera"

pc_map *pcl_camera(lua_State *L) {
    lua_getfield(L, LUA_REGISTRYINDEX, CAMERA_KEY);
    pc_map *f = pcl_tomap(L, -1);
    lua_pop(L, 1);   /* the registry keeps the map alive */
    return f;
}

static int l_camera(lua_State *L) {
    if (lua_isnone(L, 1)) {
        lua_getfield(L, LUA_REGISTRYINDEX, CAMERA_KEY);
        return 1;
    }
    if (!lua_isnil(L, 1)) {
        pc_map *f = pcl_tomap(L, 1);
        if (!f) return pcl_argerror(L, 1, "projection", "a map to the plane (or nil)");
        if (f->nout != 2)
            return pcl_error(L, "camera: argument #1 (projection) must map to 2-D points, but it "
                                "maps to %d-D", f->nout);
    }
    /* {hidden = ...}: the 3-D strokes from now on form a scene resolved at write (pcl_scene.h) */
    int mode = -1;
    if (!lua_isnoneornil(L, 2)) {
        static const char *const modes[] = {"show", "dashed", "hide", NULL};
        if (!lua_istable(L, 2)) return pcl_argerror(L, 2, "options", "a table {hidden =}");
        if (lua_getfield(L, 2, "hidden") != LUA_TNIL) {
            const char *m = lua_tostring(L, -1);
            for (mode = 0; modes[mode] && !(lua_type(L, -1) == LUA_TSTRING && !strcmp(m, modes[mode])); mode++) {}
            if (!modes[mode])
                return pcl_error(L, "camera: argument #2 (hidden) must be \"dashed\", \"hide\" or "
                                    "\"show\", got %s%s%s", m ? "\"" : "", m ? m : pcl_shown(L, -1),
                                 m ? "\"" : "");
        }
    }
    pcl_set_hidden_mode(L, mode);
    lua_settop(L, 1);
    lua_setfield(L, LUA_REGISTRYINDEX, CAMERA_KEY);
    return 0;
}

int pcl_project(lua_State *L, int n, const double *h, double *x, double *y) {
    pc_map *f = pcl_camera(L);
    if (!f || f->nin != n) return PC_EDIM;
    double o[3];
    pc_map_apply(f, h, o);
    if (o[2] == 0) return PC_IMPROPER;
    *x = o[0] / o[2];
    *y = o[1] / o[2];
    return isfinite(*x) && isfinite(*y) ? PC_OK : PC_ENONFINITE;
}

/* ---- flattening through the projection and the window ---------------------------------------- */

void pcl_screen_map(lua_State *L, const pc_map *f, pc_map *out) {
    pc_canvas *cv = pcl_canvas(L);
    double o[2], ex[2], ey[2];
    pc_world_to_screen(cv, 0, 0, &o[0], &o[1]);
    pc_world_to_screen(cv, 1, 0, &ex[0], &ex[1]);
    pc_world_to_screen(cv, 0, 1, &ey[0], &ey[1]);
    pc_map w;
    pc_map_identity(&w, 2);
    for (int r = 0; r < 2; r++) {
        PC_MAP_AT(&w, r, 0) = ex[r] - o[r];
        PC_MAP_AT(&w, r, 1) = ey[r] - o[r];
        PC_MAP_AT(&w, r, 2) = o[r];
    }
    if (f) pc_map_compose(&w, f, out);
    else *out = w;
}

int pcl_flatten(lua_State *L, pc_curve *c, double a, double b, int pieces, const pc_map *f,
                int screen, double tol, pc_polyline *out) {
    pc_map scr;
    if (screen) {
        pcl_screen_map(L, f, &scr);
        f = &scr;
    }
    pcl_callback_state(L);
    if (!f && c->dim != 2) return PC_EDIM;
    if (pieces < 1) pieces = 1;
    for (int i = 0; i < pieces; i++) {
        double lo = a + (b - a) * i / pieces, hi = i == pieces - 1 ? b : a + (b - a) * (i + 1) / pieces;
        size_t before = out->n;
        int st = pc_curve_flatten_map(c, lo, hi, f, tol, out);
        if (st != PC_OK) return st;
        /* the next part starts where this one ended: keep one vertex, no break */
        if (before > 0 && out->n > before && out->xy[2 * before] == out->xy[2 * before - 2] &&
            out->xy[2 * before + 1] == out->xy[2 * before - 1]) {
            memmove(out->xy + 2 * before, out->xy + 2 * (before + 1),
                    sizeof(double) * 2 * (out->n - before - 1));
            memmove(out->move + before, out->move + before + 1, out->n - before - 1);
            out->n--;
        }
    }
    return PC_OK;
}

const pc_map *pcl_drawing_map(lua_State *L, int idx, int dim, const char *fname) {
    if (idx && !lua_isnoneornil(L, idx)) {
        pc_map *f = pcl_tomap(L, idx);
        if (!f || f->nout != 2 || f->nin != dim)
            pcl_error(L, "%s: map must be a map from %d-D to 2-D", fname, dim);
        return f;
    }
    pc_map *f = pcl_camera(L);
    if (dim == 2) return f && f->nin == 2 ? f : NULL;   /* a 3-D camera leaves 2-D drawing alone */
    if (!f)
        pcl_error(L, "%s: a %d-D object needs a projection: set one with camera(f) or give "
                     "map = f", fname, dim);
    if (f->nin != dim)
        pcl_error(L, "%s: the camera takes %d-D points, but this is %d-D", fname, f->nin, dim);
    return f;
}

/* Draw a screen-space polyline as one path (world coordinates for the canvas).  Returns the
 * canvas status (its message in the canvas's error) rather than raising, so that the caller
 * can free the polyline first. */
int pcl_draw_polyline(lua_State *L, const pc_polyline *pl, int color, int closed) {
    pc_canvas *cv = pcl_canvas(L);
    if (pl->n == 0) return PC_OK;
    double *xy = lua_newuserdatauv(L, sizeof(double) * 2 * pl->n, 0);
    uint8_t *verbs = lua_newuserdatauv(L, pl->n, 0);
    for (size_t i = 0; i < pl->n; i++) {
        pc_screen_to_world(cv, pl->xy[2 * i], pl->xy[2 * i + 1], &xy[2 * i], &xy[2 * i + 1]);
        verbs[i] = (i == 0 || pl->move[i]) ? PC_PATH_MOVE : PC_PATH_LINE;
    }
    int rc = pc_path(cv, pl->n, xy, verbs, pl->n, closed, color);
    lua_pop(L, 2);
    return rc;   /* the message is in the canvas */
}

/* _tk.draw_curve(c, colour, tol [, map [, pieces]]) */
static int l_draw_curve(lua_State *L) {
    pc_curve *c = pcl_tocurve(L, 1);
    if (!c) return pcl_argerror(L, 1, "curve", "a curve");
    pc_canvas *cv = pcl_canvas(L);
    int color = pcl_optcolor(L, 2, cv);
    double tol = luaL_optnumber(L, 3, 0.25);
    if (!(tol > 0)) return pcl_error(L, "c:draw: tol must be a positive number of pixels");
    const pc_map *f = pcl_drawing_map(L, 4, c->dim, "c:draw");
    int pieces = (int)luaL_optinteger(L, 5, 1);
    pc_polyline pl = {0};
    /* what can be seen: the canvas and a margin as wide as it (a wide pen, a dash pattern
     * leaving and coming back keep their look) */
    double m = cv->width > cv->height ? cv->width : cv->height;
    double clip[4] = {-m, -m, cv->width + m, cv->height + m};
    pl.clip = clip;
    int st = pcl_flatten(L, c, c->t0, c->t1, pieces, f, 1, tol, &pl);
    if (st != PC_OK) {
        int capped = st == PC_ENOMEM && pl.n >= PC_POLYLINE_MAX;
        pc_polyline_free(&pl);
        if (capped) {
            char t[32];
            snprintf(t, sizeof t, "%g", tol);
            return pcl_error(L, "c:draw: the curve needs more than %d vertices at tol = %s px; "
                             "draw it with a larger tol", (int)PC_POLYLINE_MAX, t);
        }
        return pcl_raise_status(L, "c:draw", st);
    }
    pc_scene *sc = c->dim == 3 && lua_isnoneornil(L, 4) ? pcl_scene(L) : NULL;
    if (sc) {   /* into the scene, sampled as densely as the flattened path */
        int n = (int)fmin(8192, fmax(64, 4.0 * (double)pl.n));
        pc_polyline_free(&pl);
        st = pcl_scene_curve(L, sc, c, n, color);
        return st == PC_OK ? 0 : pcl_raise_status(L, "c:draw", st);
    }
    /* a closed curve whose polyline is unbroken closes exactly */
    int unbroken = 1;
    for (size_t i = 1; i < pl.n; i++) unbroken &= !pl.move[i];
    st = pcl_draw_polyline(L, &pl, color, c->closed && unbroken);
    pc_polyline_free(&pl);
    if (st != PC_OK) return pcl_error(L, "c:draw: %s", cv->error);
    return 0;
}

void pcl_open_camera(lua_State *L) {
    int module = lua_gettop(L);
    lua_pushcfunction(L, l_camera);
    lua_setfield(L, module, "camera");
    pcl_private(L, module);
    lua_pushcfunction(L, l_draw_curve);
    lua_setfield(L, -2, "draw_curve");
    lua_settop(L, module);
}
