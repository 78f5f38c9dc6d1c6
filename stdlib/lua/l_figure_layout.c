/* Binding of the figure layout and its furniture (stdlib/draw/layout.h, furniture.h):
 *   placed_labels()                      where the labels go when the picture is written
 *   mark(P [, style [, size [, colour]]])   dot, open, cross, plus, square
 *   arrow(A, B [, heads [, colour]])  vector(A, v [, colour])
 *   dimension(A, B [, offset [, text [, colour]]]) -> length
 *   angle_mark(A, O, B [, text [, radius [, colour]]]) -> angle (radians)
 *   ticks(A, B [, n [, colour]])  hatch(points [, spacing [, angle [, colour]]])
 *   centre_line(A, B [, extend [, colour]])
 * Points are 2-D, or n-D through the camera; sizes are screen pixels. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "pcl.h"
#include "pcl_qbscreen.h"
#include "layout.h"
#include "furniture.h"

/* A core failure as the house error: the caller's name, the core's message without its own. */
static int check(lua_State *L, pc_canvas *c, int rc) {
    if (rc == PC_OK) return 0;
    const char *msg = c->error, *colon = strstr(msg, ": ");
    if (colon && strspn(msg, "abcdefghijklmnopqrstuvwxyz_") == (size_t)(colon - msg)) msg = colon + 2;
    return pcl_error(L, "%s: %s", pcl_fname(L), msg);
}

static int option(lua_State *L, int arg, const char *what, const char *const names[], int dflt) {
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
                         pcl_arg_shown(L, arg), what, lua_tostring(L, -1), s);
    return pcl_argerror(L, arg, what, lua_tostring(L, -1));
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
    pc_box2 *b;
    int *side;
    size_t n;
    if (pc_layout_labels(c, &b, &side, &n) != PC_OK) return pcl_error(L, "placed_labels: out of memory");
    static const char *const names[] = {"c", "n", "ne", "e", "se", "s", "sw", "w", "nw"};
    lua_createtable(L, (int)n, 0);
    size_t k = 0;
    for (size_t i = 0; i < c->nops; i++) {
        const pc_op *op = &c->ops[i];
        if (op->kind != PC_OP_TEXT) continue;
        lua_createtable(L, 0, 7);
        lua_pushlstring(L, c->text + op->first, op->count);
        lua_setfield(L, -2, "text");
        lua_pushnumber(L, b[k].x0); lua_setfield(L, -2, "x");
        lua_pushnumber(L, b[k].y0); lua_setfield(L, -2, "y");
        lua_pushnumber(L, b[k].x1 - b[k].x0); lua_setfield(L, -2, "w");
        lua_pushnumber(L, b[k].y1 - b[k].y0); lua_setfield(L, -2, "h");
        lua_pushstring(L, names[side[k] >= 0 && side[k] <= 8 ? side[k] : 0]); lua_setfield(L, -2, "side");
        lua_pushboolean(L, (op->flags & PC_TEXT_AUTO) != 0); lua_setfield(L, -2, "auto");
        lua_rawseti(L, -2, (lua_Integer)++k);
    }
    free(b);
    free(side);
    return 1;
}

static int l_mark(lua_State *L) {
    static const char *const styles[] = {"dot", "open", "cross", "plus", "square", NULL};
    pc_canvas *c = pcl_active_canvas(L);
    int arg = 1;
    double x, y;
    pcl_checkxy(L, &arg, &x, &y, "");
    int style = option(L, arg, "style", styles, PC_MARK_DOT);
    double size = optnum(L, arg + 1, "size", 5);
    return check(L, c, pc_mark(c, x, y, style, size, pcl_optcolor(L, arg + 2, c)));
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

void pcl_open_figure_layout(lua_State *L) {
    static const luaL_Reg fns[] = {
        {"placed_labels", l_placed_labels}, {"mark", l_mark}, {"arrow", l_arrow},
        {"vector", l_vector}, {"dimension", l_dimension}, {"angle_mark", l_angle_mark},
        {"ticks", l_ticks}, {"hatch", l_hatch}, {"centre_line", l_centre_line}, {NULL, NULL}};
    luaL_setfuncs(L, fns, 0);
}
