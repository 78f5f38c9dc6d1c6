/* Binding of the figure layout and its furniture (stdlib/draw/layout.h, furniture.h):
 *   placed_labels()                      where the labels go when the picture is written
 *   mark(P [, style [, size [, colour]]])   dot, open, cross, plus, square
 *   arrow(A, B [, heads [, colour]])  vector(A, v [, colour])
 *   dimension(A, B [, offset [, text [, colour]]]) -> length
 *   angle_mark(A, O, B [, text [, radius [, colour]]]) -> angle (radians)
 *   ticks(A, B [, n [, colour]])  hatch(points [, spacing [, angle [, colour]]])
 *   centre_line(A, B [, extend [, colour]])
 * Points are 2-D, or n-D through the camera; sizes are screen pixels.  And the 3-D scene
 * (pcl_scene.h): the strokes of a camera with hidden lines, resolved when the picture is
 * written. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "pcl.h"
#include "pcl_qbscreen.h"
#include "layout.h"
#include "furniture.h"
#include "pcl_curve.h"
#include "pcl_scene.h"
#include "view.h"
#include "axes.h"

/* A core failure as the house error: the caller's name, the core's message without its own. */
static int check(lua_State *L, pc_canvas *c, int rc) {
    if (rc == PC_OK) return 0;
    const char *msg = c->error, *colon = strstr(msg, ": ");
    if (colon && strspn(msg, "abcdefghijklmnopqrstuvwxyz_") == (size_t)(colon - msg)) msg = colon + 2;
    return pcl_error(L, "%s: %s", pcl_fname(L), msg);
}

/* A string among names at stack index idx (nil: dflt), shown as argument `shown` in errors. */
static int option_at(lua_State *L, int idx, int shown, const char *what, const char *const names[],
                     int dflt) {
    int arg = idx;
    if (lua_isnoneornil(L, arg)) return dflt;
    const char *s = lua_type(L, arg) == LUA_TSTRING ? lua_tostring(L, arg) : NULL;
    for (int k = 0; s && names[k]; k++)
        if (!strcmp(s, names[k])) return k;
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    for (int k = 0; names[k]; k++) {
        luaL_addstring(&b, k ? " \"" : "one of \"");
        luaL_addstring(&b, names[k]);
        luaL_addchar(&b, '"');
    }
    luaL_pushresult(&b);
    if (s)   /* the string itself says best what is wrong */
        return pcl_error(L, "%s: argument #%d (%s) must be %s, got \"%s\"", pcl_fname(L),
                         shown, what, lua_tostring(L, -1), s);
    return pcl_argerror_full(L, pcl_fname(L), arg, shown, what, lua_tostring(L, -1));
}

static int option(lua_State *L, int arg, const char *what, const char *const names[], int dflt) {
    return option_at(L, arg, pcl_arg_shown(L, arg), what, names, dflt);
}

static double optnum(lua_State *L, int arg, const char *what, double dflt) {
    return pcl_optnum(L, pcl_fname(L), arg, what, dflt);
}

static const char *opttext(lua_State *L, int arg) {
    if (lua_isnoneornil(L, arg)) return NULL;
    int t = lua_type(L, arg);
    if (t != LUA_TSTRING && t != LUA_TNUMBER) pcl_argerror(L, arg, "text", "a string");
    return lua_tostring(L, arg);
}

static int l_placed_labels(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    const pc_canvas *r = pc_layout_resolve(c);   /* as a writer gets it: placed, scene drawn */
    pc_box2 *b;
    int *side;
    size_t n;
    if (!r || pc_layout_labels(r, &b, &side, &n) != PC_OK) {
        pc_layout_release(c, r);
        return pcl_error(L, "placed_labels: out of memory");
    }
    static const char *const names[] = {"c", "n", "ne", "e", "se", "s", "sw", "w", "nw"};
    lua_createtable(L, (int)n, 0);
    size_t k = 0;
    for (size_t i = 0; i < r->nops && k < n; i++) {
        const pc_op *op = &r->ops[i];
        if (op->kind != PC_OP_TEXT) continue;
        lua_createtable(L, 0, 7);
        lua_pushlstring(L, r->text + op->first, op->count);
        lua_setfield(L, -2, "text");
        lua_pushnumber(L, b[k].x0); lua_setfield(L, -2, "x");
        lua_pushnumber(L, b[k].y0); lua_setfield(L, -2, "y");
        lua_pushnumber(L, b[k].x1 - b[k].x0); lua_setfield(L, -2, "w");
        lua_pushnumber(L, b[k].y1 - b[k].y0); lua_setfield(L, -2, "h");
        lua_pushstring(L, names[side[k] >= 0 && side[k] <= 8 ? side[k] : 0]); lua_setfield(L, -2, "side");
        lua_pushboolean(L, (op->flags & (PC_TEXT_AUTO | PC_TEXT_PLACED)) != 0); lua_setfield(L, -2, "auto");
        lua_rawseti(L, -2, (lua_Integer)++k);
    }
    free(b);
    free(side);
    pc_layout_release(c, r);
    return 1;
}

/* ---- the 3-D scene ----------------------------------------------------------------------- */

#define HIDDEN_KEY "pointcalc.hidden"

/* The scenes of a canvas: a new one each time the camera's screen map or mode changes. */
typedef struct {
    pc_scene **sc;
    int *mode;
    pc_map *map;
    size_t n, cap;
} scene_set;

static int set_resolve(void *p, pc_canvas *copy) {
    scene_set *set = p;
    int st = PC_OK;
    for (size_t i = 0; i < set->n && st == PC_OK; i++) st = pc_scene_draw(set->sc[i], copy, set->mode[i]);
    return st;
}

static void set_drop(void *p) {
    scene_set *set = p;
    for (size_t i = 0; i < set->n; i++) pc_scene_free(set->sc[i]);
    free(set->sc);
    free(set->mode);
    free(set->map);
    free(set);
}

void pcl_set_hidden_mode(lua_State *L, int mode) {
    lua_pushinteger(L, mode);
    lua_setfield(L, LUA_REGISTRYINDEX, HIDDEN_KEY);
}

pc_scene *pcl_scene(lua_State *L) {
    lua_getfield(L, LUA_REGISTRYINDEX, HIDDEN_KEY);
    int mode = lua_isinteger(L, -1) ? (int)lua_tointeger(L, -1) : -1;
    lua_pop(L, 1);
    pc_map *f = pcl_camera(L);
    if (mode < 0 || !f || f->nin != 3) return NULL;
    pc_map scr;
    pcl_screen_map(L, f, &scr);
    pc_canvas *c = pcl_active_canvas(L);
    scene_set *set = c->attach_resolve == set_resolve ? c->attach : NULL;
    if (!set) {
        if (c->attach) return NULL;   /* something else is attached: draw as usual */
        if (!(set = calloc(1, sizeof *set))) pcl_error(L, "%s: out of memory", pcl_fname(L));
        c->attach = set;
        c->attach_resolve = set_resolve;
        c->attach_drop = set_drop;
    }
    size_t n = set->n;
    if (n && set->mode[n - 1] == mode && !memcmp(&set->map[n - 1], &scr, sizeof scr)) return set->sc[n - 1];
    if (n == set->cap) {
        size_t cap = set->cap ? 2 * set->cap : 4;
        pc_scene **a = realloc(set->sc, cap * sizeof *a);
        if (a) set->sc = a;
        int *m = realloc(set->mode, cap * sizeof *m);
        if (m) set->mode = m;
        pc_map *mp = realloc(set->map, cap * sizeof *mp);
        if (mp) set->map = mp;
        if (!a || !m || !mp) pcl_error(L, "%s: out of memory", pcl_fname(L));
        set->cap = cap;
    }
    int st;
    pc_scene *sc = pc_scene_new(&scr, &st);
    if (!sc) return pcl_raise_status(L, pcl_fname(L), st), NULL;
    set->sc[n] = sc;
    set->mode[n] = mode;
    set->map[n] = scr;
    set->n++;
    return sc;
}

int pcl_scene_curve(lua_State *L, pc_scene *sc, const pc_curve *c, int n, int color) {
    double *xyz = lua_newuserdatauv(L, sizeof(double) * 3 * (size_t)(n + 1), 0);
    uint8_t *brk = lua_newuserdatauv(L, (size_t)n + 1, 0);
    size_t m = 0;
    int gap = 1;
    for (int k = 0; k <= n; k++) {
        double x[PC_MAXDIM];
        if (pc_curve_eval(c, c->t0 + (c->t1 - c->t0) * k / n, x) != PC_OK) {
            gap = 1;   /* a point at infinity: the curve breaks there */
            continue;
        }
        memcpy(xyz + 3 * m, x, 3 * sizeof *x);
        brk[m++] = (uint8_t)gap;
        gap = 0;
    }
    int st = pc_scene_add_polyline(sc, m, xyz, brk, color, pcl_active_canvas(L)->pen);
    lua_pop(L, 2);
    return st;
}

/* A 3-D point at stack index idx, or 0. */
static int point3(lua_State *L, int idx, double x[3]) {
    pcl_value *p = pcl_tovalue(L, idx);
    if (!p || p->n != 3 || fabs(p->h[3] - 1) > 1e-9) return 0;
    for (int k = 0; k < 3; k++) x[k] = p->h[k] / p->h[3];
    return 1;
}

int pcl_scene_line(lua_State *L) {
    double ab[6];
    pc_scene *sc;
    if (!point3(L, 1, ab) || !point3(L, 2, ab + 3) || !(sc = pcl_scene(L))) return 0;
    pc_canvas *c = pcl_active_canvas(L);
    int st = pc_scene_add_polyline(sc, 2, ab, NULL, pcl_optcolor(L, 3, c), c->pen);
    if (st != PC_OK) pcl_raise_status(L, pcl_fname(L), st);
    return 1;
}

static int l_mark(lua_State *L) {
    static const char *const styles[] = {"dot", "open", "cross", "plus", "square", NULL};
    pc_canvas *c = pcl_active_canvas(L);
    int arg = 1;
    double x, y, p3[3];
    pc_scene *sc = point3(L, 1, p3) ? pcl_scene(L) : NULL;
    if (sc) arg = 2;
    else pcl_checkxy(L, &arg, &x, &y, "");
    int style = option(L, arg, "style", styles, PC_MARK_DOT);
    double size = optnum(L, arg + 1, "size", 5);
    int color = pcl_optcolor(L, arg + 2, c);
    if (!(size >= 1 && size <= 200)) return pcl_argerror(L, arg + 1, "size", "a number 1..200 (pixels)");
    if (sc) {
        int st = pc_scene_add_mark(sc, p3, style, size, color);
        return st == PC_OK ? 0 : pcl_raise_status(L, "mark", st);
    }
    return check(L, c, pc_mark(c, x, y, style, size, color));
}

static int l_arrow(lua_State *L) {
    static const char *const heads[] = {"none", "end", "start", "both", NULL};
    pc_canvas *c = pcl_active_canvas(L);
    int arg = 1;
    double x1, y1, x2, y2;
    pcl_checkxy(L, &arg, &x1, &y1, "start");
    pcl_checkxy(L, &arg, &x2, &y2, "end");
    int h = option(L, arg, "heads", heads, PC_ARROW_END);
    return check(L, c, pc_arrow(c, x1, y1, x2, y2, h, 9, pcl_optcolor(L, arg + 1, c)));
}

/* vector(A, v [, colour]): the arrow from A to A + v (the sum taken as a script would). */
static int l_vector(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    int arg = 1;
    double x1, y1, x2, y2;
    lua_settop(L, 3);
    pcl_checkxy(L, &arg, &x1, &y1, "start");
    lua_pushvalue(L, 1);
    lua_pushvalue(L, 2);
    lua_arith(L, LUA_OPADD);
    lua_replace(L, 2);
    pcl_checkxy(L, &arg, &x2, &y2, "vector");
    return check(L, c, pc_arrow(c, x1, y1, x2, y2, PC_ARROW_END, 9, pcl_optcolor(L, 3, c)));
}

static int l_dimension(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    int arg = 1;
    double ax, ay, bx, by, len = 0;
    pcl_checkxy(L, &arg, &ax, &ay, "A");
    pcl_checkxy(L, &arg, &bx, &by, "B");
    double off = optnum(L, arg, "offset", 20);
    const char *text = opttext(L, arg + 1);
    check(L, c, pc_dimension(c, ax, ay, bx, by, off, text, pcl_optcolor(L, arg + 2, c), &len));
    lua_pushnumber(L, len);
    return 1;
}

static int l_angle_mark(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    int arg = 1;
    double ax, ay, ox, oy, bx, by, th = 0;
    pcl_checkxy(L, &arg, &ax, &ay, "A");
    pcl_checkxy(L, &arg, &ox, &oy, "O");
    pcl_checkxy(L, &arg, &bx, &by, "B");
    const char *text = opttext(L, arg);
    double r = optnum(L, arg + 1, "radius", 24);
    check(L, c, pc_angle_mark(c, ax, ay, ox, oy, bx, by, r, text, pcl_optcolor(L, arg + 2, c), &th));
    lua_pushnumber(L, th);
    return 1;
}

static int l_ticks(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    int arg = 1;
    double ax, ay, bx, by;
    pcl_checkxy(L, &arg, &ax, &ay, "A");
    pcl_checkxy(L, &arg, &bx, &by, "B");
    lua_Integer n = 1;
    if (!lua_isnoneornil(L, arg)) {
        int isint;
        n = lua_tointegerx(L, arg, &isint);
        if (!isint || n < 1 || n > 5) return pcl_argerror(L, arg, "n", "an integer 1..5");
    }
    return check(L, c, pc_ticks(c, ax, ay, bx, by, (int)n, 8, pcl_optcolor(L, arg + 1, c)));
}

static int l_hatch(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    if (!lua_istable(L, 1)) return pcl_argerror(L, 1, "points", "a list of at least 3 points");
    lua_Integer n = luaL_len(L, 1);
    if (n < 3 || n > 1000000) return pcl_argerror(L, 1, "points", "a list of at least 3 points");
    double spacing = optnum(L, 2, "spacing", 8), angle = optnum(L, 3, "angle", 45);
    int color = pcl_optcolor(L, 4, c);
    double *xy = lua_newuserdatauv(L, sizeof(double) * 2 * (size_t)n, 0);
    for (lua_Integer i = 1; i <= n; i++) {
        lua_geti(L, 1, i);
        int top = lua_gettop(L), a = top;
        pcl_checkxy(L, &a, &xy[2 * i - 2], &xy[2 * i - 1], "point");
        lua_settop(L, top - 1);
    }
    size_t lines;
    return check(L, c, pc_hatch(c, (size_t)n, xy, spacing, angle, color, &lines));
}

static int l_centre_line(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    int arg = 1;
    double ax, ay, bx, by;
    pcl_checkxy(L, &arg, &ax, &ay, "A");
    pcl_checkxy(L, &arg, &bx, &by, "B");
    double ext = optnum(L, arg, "extend", 10);
    return check(L, c, pc_centre_line(c, ax, ay, bx, by, ext, pcl_optcolor(L, arg + 1, c)));
}

int pcl_scene_label(lua_State *L) {
    static const char *const dirs[] = {"c", "n", "ne", "e", "se", "s", "sw", "w", "nw", NULL};
    double x[3];
    pc_scene *sc;
    if (!point3(L, 2, x) || !(sc = pcl_scene(L))) return 0;
    pc_canvas *c = pcl_active_canvas(L);
    const char *s = opttext(L, 1);
    if (!s) return pcl_argerror(L, 1, "text", "a string");
    int anchor = option(L, 3, "direction", dirs, PC_ANCHOR_AUTO);
    int color = pcl_optcolor(L, 4, c);
    lua_Integer scale = luaL_optinteger(L, 5, 1);
    if (scale < 1 || scale > 8) return pcl_argerror(L, 5, "scale", "an integer 1..8");
    int st = pc_scene_add_label(sc, x, s, anchor, (int)scale, color);
    if (st != PC_OK) pcl_raise_status(L, pcl_fname(L), st);
    return 1;
}

/* ---- framing, captions, device-unit text -------------------------------------------------- */

/* fit{margin = px, aspect = "equal"|"fill"}: frame what is drawn (layout.h). */
static int l_fit(lua_State *L) {
    static const char *const aspects[] = {"equal", "fill", NULL};
    pc_canvas *c = pcl_active_canvas(L);
    double margin = 10;
    int aspect = PC_FIT_EQUAL;
    if (!lua_isnoneornil(L, 1)) {
        if (!lua_istable(L, 1)) return pcl_argerror(L, 1, "options", "a table {margin =, aspect =}");
        lua_getfield(L, 1, "margin");
        margin = optnum(L, lua_gettop(L), "margin", 10);
        lua_getfield(L, 1, "aspect");
        aspect = option_at(L, lua_gettop(L), 1, "aspect", aspects, PC_FIT_EQUAL);
        lua_settop(L, 1);
    }
    return check(L, c, pc_fit(c, margin, aspect));
}

/* Text at a screen point given in device pixels, whatever the window. */
static int device_text(lua_State *L, pc_canvas *c, double x, double y, const char *s, int anchor,
                       double gap, int scale, int color) {
    double wx, wy;
    pc_screen_to_world(c, x, y, &wx, &wy);
    return check(L, c, pc_text(c, wx, wy, s, anchor, gap, scale, color));
}

/* caption(text [, "bottom"|"top" [, colour]]): centred at the picture's edge, in device units. */
static int l_caption(lua_State *L) {
    static const char *const where[] = {"bottom", "top", NULL};
    pc_canvas *c = pcl_active_canvas(L);
    const char *s = opttext(L, 1);
    if (!s) return pcl_argerror(L, 1, "text", "a string");
    int top = option(L, 2, "where", where, 0);
    int color = pcl_optcolor(L, 3, c);
    pc_rect v = c->view;
    int vs = c->view_screen;   /* the whole screen, not the VIEW: a caption is the figure's */
    c->view = (pc_rect){0, 0, c->width - 1, c->height - 1};
    c->view_screen = 1;
    double wx, wy;
    pc_screen_to_world(c, c->width / 2.0, top ? 0 : c->height - 1, &wx, &wy);
    int st = pc_text(c, wx, wy, s, top ? PC_ANCHOR_S : PC_ANCHOR_N, 3, 1, color);
    c->view = v;
    c->view_screen = vs;
    return check(L, c, st);
}

/* text{x =, y =, text =, units = "device"|"world", color =, scale =}; the positional form goes
 * to the drawing binding's text (the upvalue). */
static int l_text_table(lua_State *L) {
    if (!lua_istable(L, 1)) {
        lua_pushvalue(L, lua_upvalueindex(1));
        lua_insert(L, 1);
        lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
        return lua_gettop(L);
    }
    static const char *const units[] = {"world", "device", NULL};
    pc_canvas *c = pcl_active_canvas(L);
    lua_settop(L, 1);
    lua_getfield(L, 1, "x");   /* 2 */
    lua_getfield(L, 1, "y");   /* 3 */
    lua_getfield(L, 1, "text");   /* 4 */
    lua_getfield(L, 1, "units");   /* 5 */
    lua_getfield(L, 1, "color");   /* 6 */
    lua_getfield(L, 1, "scale");   /* 7 */
    double x = pcl_checknum(L, "text", 2, "x"), y = pcl_checknum(L, "text", 3, "y");
    const char *s = opttext(L, 4);
    if (!s) return pcl_error(L, "text: the table needs text = \"...\"");
    int device = option_at(L, 5, 1, "units", units, 0);
    int color = pcl_optcolor(L, 6, c);
    lua_Integer scale = luaL_optinteger(L, 7, 1);
    if (scale < 1 || scale > 8) return pcl_error(L, "text: scale must be an integer 1..8");
    if (!device) return check(L, c, pc_text(c, x, y, s, PC_ANCHOR_SE, 0, (int)scale, color));
    return device_text(L, c, x, y, s, PC_ANCHOR_SE, 0, (int)scale, color);
}

/* ---- axes, graphs, legends ------------------------------------------------------------------ */

/* A {lo, hi} range field of the options table at 1. */
static int range_field(lua_State *L, const char *key, double *lo, double *hi) {
    if (lua_getfield(L, 1, key) == LUA_TNIL) {
        lua_pop(L, 1);
        return 0;
    }
    int ok = lua_istable(L, -1) && lua_geti(L, -1, 1) == LUA_TNUMBER && lua_geti(L, -2, 2) == LUA_TNUMBER;
    if (ok) {
        *lo = lua_tonumber(L, -2);
        *hi = lua_tonumber(L, -1);
    }
    if (!ok || !(*lo < *hi)) pcl_error(L, "axes: %s must be {lo, hi} with lo < hi", key);
    lua_settop(L, 1);
    return 1;
}

/* axes{x = {a, b}, y = {c, d}, origin = P, ticks = 5, labels = true, arrows = true,
 * grid = false, color =, grid_color =} -> the number of ticks */
static int l_axes(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    if (lua_isnoneornil(L, 1)) lua_newtable(L), lua_replace(L, 1);
    if (!lua_istable(L, 1)) return pcl_argerror(L, 1, "options", "a table {x =, y =, ...}");
    lua_settop(L, 1);
    pc_axes_spec a = {0, 0, 0, 0, 0, 0, 5, 1, 1, 0, -1};
    double wx0, wy0, wx1, wy1;   /* default: the window's (or the screen's) extent */
    pc_screen_to_world(c, c->view.x0, c->view.y1, &wx0, &wy0);
    pc_screen_to_world(c, c->view.x1, c->view.y0, &wx1, &wy1);
    a.x0 = fmin(wx0, wx1); a.x1 = fmax(wx0, wx1); a.y0 = fmin(wy0, wy1); a.y1 = fmax(wy0, wy1);
    range_field(L, "x", &a.x0, &a.x1);
    range_field(L, "y", &a.y0, &a.y1);
    if (lua_getfield(L, 1, "origin") != LUA_TNIL) {
        int arg = 2;
        pcl_checkxy(L, &arg, &a.ox, &a.oy, "origin");
    }
    lua_settop(L, 1);
    lua_getfield(L, 1, "ticks");
    a.ticks = (int)luaL_optinteger(L, -1, 5);
    if (a.ticks < 0 || a.ticks > 100) return pcl_error(L, "axes: ticks must be 0..100");
    static const char *const flags[] = {"labels", "arrows", "grid"};
    int *fv[] = {&a.labels, &a.arrows, &a.grid};
    for (int k = 0; k < 3; k++) {
        if (lua_getfield(L, 1, flags[k]) != LUA_TNIL) *fv[k] = lua_toboolean(L, -1);
        lua_pop(L, 1);
    }
    lua_getfield(L, 1, "color");
    int color = pcl_optcolor(L, lua_gettop(L), c);
    lua_getfield(L, 1, "grid_color");
    a.grid_color = pcl_optcolor(L, lua_gettop(L), c);
    int n = 0;
    check(L, c, pc_axes(c, &a, color, &n));
    lua_pushinteger(L, n);
    return 1;
}

/* graph(f, a, b [, {color =, n = 400}]): y = f(x) for x in a..b, broken where f gives no
 * finite number. */
static int l_graph(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    luaL_checktype(L, 1, LUA_TFUNCTION);
    double a = pcl_checknum(L, "graph", 2, "a"), b = pcl_checknum(L, "graph", 3, "b");
    if (!(a < b)) {
        const char *sa = pcl_pushnum(L, a), *sb = pcl_pushnum(L, b);
        return pcl_error(L, "graph: the range must have a < b, got %s..%s", sa, sb);
    }
    int color = -1;
    lua_Integer n = 400;
    if (!lua_isnoneornil(L, 4)) {
        if (!lua_istable(L, 4)) return pcl_argerror(L, 4, "options", "a table {color =, n =}");
        lua_getfield(L, 4, "color");
        color = pcl_optcolor(L, lua_gettop(L), c);
        lua_getfield(L, 4, "n");
        n = luaL_optinteger(L, -1, 400);
        if (n < 1 || n > 1000000) return pcl_error(L, "graph: n must be 1..1000000");
    }
    lua_settop(L, 3);
    double *xy = lua_newuserdatauv(L, sizeof(double) * 2 * (size_t)(n + 1), 0);
    uint8_t *verbs = lua_newuserdatauv(L, (size_t)n + 1, 0);
    size_t m = 0, start = 0;
    int st = PC_OK;
    for (lua_Integer k = 0; k <= n && st == PC_OK; k++) {
        double x = a + (b - a) * (double)k / (double)n;
        lua_pushvalue(L, 1);
        lua_pushnumber(L, x);
        lua_call(L, 1, 1);
        int isnum;
        double y = lua_tonumberx(L, -1, &isnum);
        lua_pop(L, 1);
        if (!isnum || !isfinite(y)) {   /* a gap: what came before is one piece */
            if (m - start == 1) m = start;   /* a lone point draws nothing */
            start = m;
            continue;
        }
        xy[2 * m] = x;
        xy[2 * m + 1] = y;
        verbs[m] = m == start ? PC_PATH_MOVE : PC_PATH_LINE;
        m++;
    }
    if (m - start == 1) m = start;
    if (m) check(L, c, pc_path(c, m, xy, verbs, m, 0, color));
    return 0;
}

/* legend({{name, colour}, ...} [, "ne"|"nw"|"se"|"sw" [, colour]]) */
static int l_legend(lua_State *L) {
    static const char *const corners[] = {"ne", "nw", "se", "sw", NULL};
    static const int corner_of[] = {PC_ANCHOR_NE, PC_ANCHOR_NW, PC_ANCHOR_SE, PC_ANCHOR_SW};
    pc_canvas *c = pcl_active_canvas(L);
    if (!lua_istable(L, 1)) return pcl_argerror(L, 1, "entries", "a list of {name, colour}");
    lua_Integer n = luaL_len(L, 1);
    if (n < 1 || n > 100) return pcl_argerror(L, 1, "entries", "a list of 1..100 {name, colour}");
    int corner = corner_of[option(L, 2, "corner", corners, 0)];
    int color = pcl_optcolor(L, 3, c);
    luaL_checkstack(L, 2 * (int)n + 8, "legend: too many entries");
    const char **names = lua_newuserdatauv(L, sizeof *names * (size_t)n, 0);
    int *colors = lua_newuserdatauv(L, sizeof *colors * (size_t)n, 0);
    for (lua_Integer i = 1; i <= n; i++) {
        if (lua_geti(L, 1, i) != LUA_TTABLE) return pcl_error(L, "legend: entry %d must be {name, colour}", (int)i);
        lua_geti(L, -1, 1);
        if (!lua_isstring(L, -1)) return pcl_error(L, "legend: entry %d must be {name, colour}", (int)i);
        names[i - 1] = lua_tostring(L, -1);
        lua_geti(L, -2, 2);
        colors[i - 1] = pcl_optcolor(L, lua_gettop(L), c);
        lua_pop(L, 1);   /* the name stays on the stack, referenced by the list */
    }
    return check(L, c, pc_legend(c, (int)n, names, colors, corner, color));
}

/* ---- map.view ------------------------------------------------------------------------------ */

/* A 3-D field of the options table at 1: a point (weight 1) or a vector (weight 0). */
static int field3(lua_State *L, const char *key, int weight, double out[3]) {
    if (lua_getfield(L, 1, key) == LUA_TNIL) {
        lua_pop(L, 1);
        return 0;
    }
    pcl_value *p = pcl_tovalue(L, -1);
    if (!p || p->n != 3 || fabs(p->h[3] - weight) > 1e-9)
        pcl_error(L, "map.view: %s must be a 3-D %s, got %s", key, weight ? "point" : "vector",
                  pcl_shown(L, -1));
    for (int k = 0; k < 3; k++) out[k] = weight ? p->h[k] / p->h[3] : p->h[k];
    lua_pop(L, 1);
    return 1;
}

static double fieldnum(lua_State *L, const char *key, double dflt) {
    lua_getfield(L, 1, key);
    int isnum;
    double v = lua_isnil(L, -1) ? dflt : lua_tonumberx(L, -1, &isnum);
    if (!lua_isnil(L, -1) && (!isnum || !isfinite(v)))
        pcl_error(L, "map.view: %s must be a finite number, got %s", key, pcl_shown(L, -1));
    lua_pop(L, 1);
    return v;
}

/* map.view{from = P, to = P [, up = V] [, perspective = true]} or
 * map.view{azimuth =, elevation = [, distance =] [, to =] [, perspective =]}: z up. */
static int l_view(lua_State *L) {
    if (!lua_istable(L, 1)) return pcl_argerror(L, 1, "options", "a table {from =, to =, up =} or {azimuth =, elevation =}");
    double from[3], to[3] = {0, 0, 0}, up[3];
    int has_from = field3(L, "from", 1, from), has_to = field3(L, "to", 1, to);
    int has_up = field3(L, "up", 0, up);
    lua_getfield(L, 1, "perspective");
    int persp = lua_toboolean(L, -1);
    lua_pop(L, 1);
    pc_map f;
    int st;
    if (has_from) {
        if (!has_to) return pcl_error(L, "map.view: from needs to (the point looked at)");
        st = pc_map_view(&f, from, to, has_up ? up : NULL, persp);
    } else {
        lua_getfield(L, 1, "azimuth");
        int has_az = !lua_isnil(L, -1);
        lua_pop(L, 1);
        if (!has_az) return pcl_error(L, "map.view: give from and to, or azimuth and elevation");
        st = pc_map_view_azel(&f, to, fieldnum(L, "azimuth", 0), fieldnum(L, "elevation", 30),
                              fieldnum(L, "distance", 10), persp);
    }
    switch (st) {
    case PC_OK: break;
    case PC_ECOINCIDENT: return pcl_error(L, "map.view: from and to coincide (or distance is not positive): no line of sight");
    case PC_EZERO: return pcl_error(L, "map.view: up is the zero vector");
    case PC_ECOLLINEAR: return pcl_error(L, "map.view: up is along the line of sight; give another up");
    default: return pcl_error(L, "map.view: %s", pc_strerror(st));
    }
    *pcl_newmap(L) = f;
    return 1;
}

void pcl_open_figure_layout(lua_State *L) {
    static const luaL_Reg fns[] = {
        {"placed_labels", l_placed_labels}, {"mark", l_mark}, {"arrow", l_arrow},
        {"vector", l_vector}, {"dimension", l_dimension}, {"angle_mark", l_angle_mark},
        {"ticks", l_ticks}, {"hatch", l_hatch}, {"centre_line", l_centre_line},
        {"axes", l_axes}, {"graph", l_graph}, {"legend", l_legend}, {NULL, NULL}};
    luaL_setfuncs(L, fns, 0);
    lua_pushcfunction(L, l_fit);
    lua_setfield(L, -2, "fit");
    lua_pushcfunction(L, l_caption);
    lua_setfield(L, -2, "caption");
    lua_getfield(L, -1, "text");   /* text{...} in front of the positional text(x, y, s) */
    lua_pushcclosure(L, l_text_table, 1);
    lua_setfield(L, -2, "text");
    if (lua_getfield(L, -1, "map") == LUA_TTABLE) {
        lua_pushcfunction(L, l_view);
        lua_setfield(L, -2, "view");
    }
    lua_pop(L, 1);
}
