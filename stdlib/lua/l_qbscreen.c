/* Binding of QBasic's screen (stdlib/draw/qbscreen.h): what QBasic programs do on a graphics
 * screen beyond the drawing statements, for the QBasic runtime and for scripts.
 *
 *   print_at(row, col, text [, fg [, bg]])   text in character cells (code page 437 bytes)
 *   scroll_text(top, bottom [, bg])           the text rows top..bottom up by one
 *   get_block(x1, y1, x2, y2) -> block        GET; block.w, block.h, block.bytes
 *   put_block(x, y, block [, action])         PUT; "xor" (default), "pset", "preset", "and", "or"
 *   draw(commands)                            DRAW's macro language
 *   pages(active [, visual])                  SCREEN , , apage, vpage
 *   pcopy(from, to)                           PCOPY
 *   pmap(value, fn)                           PMAP: fn 0/1 world -> view pixels, 2/3 back
 *   mode_info(mode) -> table                  width height colors pages cols rows cell aspect
 *   paint_tile(x, y, tile [, border])         PAINT with a tile string, as the mode reads it */
#include <math.h>
#include <string.h>
#include "pcl_qbscreen.h"

#define BLOCK_MT "pointcalc.Block"
static const char BLOCK_TAG = 'b';   /* its address tags the type (PCL_SELF_TAG) */

/* A core call failed: its message, under the binding's name (given: through a pcall the
 * caller's name is unknown). */
static int check(lua_State *L, pc_canvas *c, int rc, const char *name) {
    if (rc == PC_OK) return 0;
    const char *msg = c->error, *colon = strstr(msg, ": ");
    if (colon && colon > msg && strspn(msg, "abcdefghijklmnopqrstuvwxyz_") == (size_t)(colon - msg))
        msg = colon + 2;   /* the binding's name replaces the core's */
    return pcl_error(L, "%s: %s", name, msg);
}

/* The mode of the screen (its size and colours), or 0 for a canvas of another size. */
static int screen_mode(const pc_canvas *c, pc_mode_info *out) {
    static const int modes[] = {1, 2, 7, 8, 9, 12, 13};
    for (size_t i = 0; i < sizeof modes / sizeof *modes; i++) {
        pc_mode_info_of(modes[i], out);
        if (out->width == c->width && out->height == c->height && out->ncolors == c->ncolors)
            return modes[i];
    }
    return 0;
}

/* The character cell height of the screen: its mode's (8, 14, 16), or 16 for other sizes. */
static int cell_height(const pc_canvas *c) {
    pc_mode_info m;
    return screen_mode(c, &m) ? m.cell_h : 16;
}

static int opt_attr(lua_State *L, int arg, pc_canvas *c, const char *what) {
    if (lua_isnoneornil(L, arg)) return -1;
    int isint;
    lua_Integer v = lua_tointegerx(L, arg, &isint);
    if (!isint || v < 0 || v >= c->ncolors) {
        char expected[48];
        snprintf(expected, sizeof expected, "a colour number 0..%d", c->ncolors - 1);
        return pcl_argerror(L, arg, what, expected);
    }
    return (int)v;
}

static int check_int(lua_State *L, int arg, const char *what, lua_Integer lo, lua_Integer hi) {
    int isint;
    lua_Integer v = lua_tointegerx(L, arg, &isint);
    if (!isint || v < lo || v > hi) {
        char expected[64];
        snprintf(expected, sizeof expected, "an integer %lld..%lld", (long long)lo, (long long)hi);
        return pcl_argerror(L, arg, what, expected);
    }
    return (int)v;
}

static int l_print_at(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    int h = cell_height(c);
    int row = check_int(L, 1, "row", 1, c->height / h + 1);
    int col = check_int(L, 2, "column", 1, c->width / 8);
    size_t n;
    const char *s = lua_tolstring(L, 3, &n);
    if (!s || lua_type(L, 3) != LUA_TSTRING) return pcl_argerror(L, 3, "text", "a string");
    int fg = opt_attr(L, 4, c, "colour"), bg = opt_attr(L, 5, c, "background colour");
    return check(L, c, pc_text_cells(c, row, col, s, n, h, fg, bg), "print_at");
}

static int l_scroll_text(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    int h = cell_height(c), rows = (c->height + h - 1) / h;
    int top = check_int(L, 1, "top row", 1, rows);
    int bottom = check_int(L, 2, "bottom row", top, rows);
    return check(L, c, pc_text_scroll(c, top, bottom, h, opt_attr(L, 3, c, "background colour")), "scroll_text");
}

/* ---- blocks ------------------------------------------------------------------------------ */

typedef struct { PCL_SELF; pc_block *b; long bytes; } block_box;   /* self: pcl.h */

/* The block at idx or NULL; one given the metatable by the debug library is refused. */
static block_box *toblock(lua_State *L, int idx) {
    block_box *bb = luaL_testudata(L, idx, BLOCK_MT);
    int ok = !bb || (lua_rawlen(L, idx) == sizeof *bb && bb->self == PCL_SELF_TAG(bb, &BLOCK_TAG));
    return pcl_genuine(L, idx, bb, ok, "block");
}

static block_box *checkblock(lua_State *L, const char *fn) {
    block_box *bb = toblock(L, 1);
    if (!bb) pcl_argerror_full(L, fn, 1, 0, NULL, "a block from get_block");
    return bb;
}

static int block_gc(lua_State *L) {
    block_box *bb = luaL_testudata(L, 1, BLOCK_MT);
    if (!bb || lua_rawlen(L, 1) != sizeof *bb || bb->self != PCL_SELF_TAG(bb, &BLOCK_TAG))
        return 0;   /* never a forged one */
    pc_block_free(bb->b);
    bb->b = NULL;
    return 0;
}

static int block_index(lua_State *L) {
    block_box *bb = checkblock(L, "block.field");
    const char *k = lua_tostring(L, 2);
    if (bb->b && k && !strcmp(k, "w")) lua_pushinteger(L, bb->b->w);
    else if (bb->b && k && !strcmp(k, "h")) lua_pushinteger(L, bb->b->h);
    else if (bb->b && k && !strcmp(k, "bytes")) lua_pushinteger(L, bb->bytes);
    else lua_pushnil(L);
    return 1;
}

static int block_tostring(lua_State *L) {
    block_box *bb = checkblock(L, "tostring");
    lua_pushfstring(L, "block(%d x %d)", bb->b ? bb->b->w : 0, bb->b ? bb->b->h : 0);
    return 1;
}

static int l_get_block(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    int arg = 1;
    double x1, y1, x2, y2;
    pcl_checkxy(L, &arg, &x1, &y1, "first corner");
    pcl_checkxy(L, &arg, &x2, &y2, "second corner");
    block_box *bb = lua_newuserdatauv(L, sizeof *bb, 0);
    bb->self = PCL_SELF_TAG(bb, &BLOCK_TAG);
    bb->b = NULL;
    luaL_setmetatable(L, BLOCK_MT);
    check(L, c, pc_get_block(c, x1, y1, x2, y2, &bb->b), "get_block");
    bb->bytes = pc_block_bytes(c, bb->b->w, bb->b->h);
    return 1;
}

static int l_put_block(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    int arg = 1;
    double x, y;
    pcl_checkxy(L, &arg, &x, &y, "corner");
    block_box *bb = toblock(L, arg);
    if (!bb || !bb->b) return pcl_argerror(L, arg, "block", "a block from get_block");
    static const char *const actions[] = {"pset", "preset", "and", "or", "xor", NULL};
    int action = PC_PUT_XOR;
    if (!lua_isnoneornil(L, arg + 1)) {
        const char *a = lua_tostring(L, arg + 1);
        action = -1;
        for (int i = 0; a && actions[i]; i++)
            if (!strcmp(a, actions[i])) action = i;
        if (action < 0 || lua_type(L, arg + 1) != LUA_TSTRING)
            return pcl_argerror(L, arg + 1, "action", "\"pset\", \"preset\", \"and\", \"or\" or \"xor\"");
    }
    return check(L, c, pc_put_block(c, x, y, bb->b, action), "put_block");
}

/* ---- DRAW, pages, PMAP ------------------------------------------------------------------- */

static int l_draw(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    size_t n;
    const char *s = lua_tolstring(L, 1, &n);
    if (!s || lua_type(L, 1) != LUA_TSTRING) return pcl_argerror(L, 1, "commands", "a string");
    if (strlen(s) != n) return pcl_argerror(L, 1, "commands", "a string without zero bytes");
    pc_draw_state *st = pcl_draw_state(L);
    pc_mode_info m;   /* turns keep a figure's size on a 4:3 monitor (SCREEN 1, 2...) */
    st->aspect = screen_mode(c, &m) ? m.aspect : 1;
    return check(L, c, pc_draw_macro(c, st, s), "draw");
}

/* paint_tile(x, y, tile [, border]): PAINT with a tile string (qbscreen.h) */
static int l_paint_tile(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    int arg = 1;
    double x, y;
    pcl_checkxy(L, &arg, &x, &y, "point");
    size_t n;
    const char *s = lua_type(L, arg) == LUA_TSTRING ? lua_tolstring(L, arg, &n) : NULL;
    if (!s || n < 1 || n > 64) return pcl_argerror(L, arg, "tile", "a string of 1..64 bytes");
    int border = opt_attr(L, arg + 1, c, "border");
    pc_tile t;
    check(L, c, pc_tile_from_bytes(c, (const unsigned char *)s, n, &t), "paint_tile");
    return check(L, c, pc_paint_tile(c, x, y, &t, border), "paint_tile");
}

static int l_pages(lua_State *L) {
    int n = pcl_npages(L);
    int active = check_int(L, 1, "active page", 0, n - 1);
    int visual = lua_isnoneornil(L, 2) ? active : check_int(L, 2, "visual page", 0, n - 1);
    pcl_set_pages(L, active, visual);
    return 0;
}

static int l_pcopy(lua_State *L) {
    int n = pcl_npages(L);
    int from = check_int(L, 1, "source page", 0, n - 1);
    int to = check_int(L, 2, "destination page", 0, n - 1);
    pc_canvas *src = pcl_page(L, from), *dst = pcl_page(L, to);
    return check(L, dst, pc_canvas_copy_picture(dst, src), "pcopy");
}

static int l_pmap(lua_State *L) {
    pc_canvas *c = pcl_active_canvas(L);
    int isnum;
    double v = lua_tonumberx(L, 1, &isnum);
    if (!isnum || !isfinite(v)) return pcl_argerror(L, 1, "value", "a finite number");
    int fn = check_int(L, 2, "function", 0, 3);
    /* physical coordinates count from the view's corner, unless VIEW SCREEN */
    double ox = c->view_screen ? 0 : c->view.x0, oy = c->view_screen ? 0 : c->view.y0;
    double sx, sy, wx, wy;
    switch (fn) {
    case 0: pc_world_to_screen(c, v, 0, &sx, &sy); lua_pushinteger(L, (lua_Integer)lrint(sx - ox)); break;
    case 1: pc_world_to_screen(c, 0, v, &sx, &sy); lua_pushinteger(L, (lua_Integer)lrint(sy - oy)); break;
    case 2: pc_screen_to_world(c, v + ox, oy, &wx, &wy); lua_pushnumber(L, wx); break;
    default: pc_screen_to_world(c, ox, v + oy, &wx, &wy); lua_pushnumber(L, wy); break;
    }
    return 1;
}

static int l_mode_info(lua_State *L) {
    int isint;
    lua_Integer mode = lua_tointegerx(L, 1, &isint);
    pc_mode_info m;
    if (!isint || mode < 0 || mode > 13 || pc_mode_info_of((int)mode, &m) != PC_OK)
        return pcl_argerror(L, 1, "mode", "a screen mode 1, 2, 7, 8, 9, 12 or 13");
    lua_createtable(L, 0, 8);
    lua_pushinteger(L, m.width); lua_setfield(L, -2, "width");
    lua_pushinteger(L, m.height); lua_setfield(L, -2, "height");
    lua_pushinteger(L, m.ncolors); lua_setfield(L, -2, "colors");
    lua_pushinteger(L, m.pages); lua_setfield(L, -2, "pages");
    lua_pushinteger(L, m.cols); lua_setfield(L, -2, "cols");
    lua_pushinteger(L, m.rows); lua_setfield(L, -2, "rows");
    lua_pushinteger(L, m.cell_h); lua_setfield(L, -2, "cell");
    lua_pushnumber(L, m.aspect); lua_setfield(L, -2, "aspect");
    return 1;
}

static const luaL_Reg qbscreen_functions[] = {
    {"print_at", l_print_at}, {"scroll_text", l_scroll_text}, {"get_block", l_get_block},
    {"put_block", l_put_block}, {"draw", l_draw},            {"pages", l_pages},
    {"pcopy", l_pcopy},       {"pmap", l_pmap},              {"mode_info", l_mode_info},
    {"paint_tile", l_paint_tile},
    {NULL, NULL}};

void pcl_open_qbscreen(lua_State *L) {
    if (luaL_newmetatable(L, BLOCK_MT)) {
        lua_pushcfunction(L, block_gc);
        lua_setfield(L, -2, "__gc");
        lua_pushcfunction(L, block_index);
        lua_setfield(L, -2, "__index");
        lua_pushcfunction(L, block_tostring);
        lua_setfield(L, -2, "__tostring");
    }
    lua_pop(L, 1);
    luaL_setfuncs(L, qbscreen_functions, 0);
}
