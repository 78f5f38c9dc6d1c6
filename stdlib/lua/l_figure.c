/* The print look's bindings: figure{...}, physical and named pens, label options.  Kept apart
 * from l_draw.c so they move to the declared argument layer in one piece. */
#include <string.h>
#include <lauxlib.h>
#include "pcl.h"
#include "print.h"

/* Every key of options table t is one of keys (NULL-terminated): an unknown option is an
 * error, never silently ignored. */
static void known_keys(lua_State *L, int t, const char *fname, const char *const *keys,
                       const char *list) {
    lua_pushnil(L);
    while (lua_next(L, t)) {
        lua_pop(L, 1);
        int ok = 0;
        if (lua_type(L, -1) == LUA_TSTRING)
            for (int i = 0; keys[i]; i++) ok |= !strcmp(keys[i], lua_tostring(L, -1));
        if (!ok)
            pcl_error(L, "%s: unknown option %s (the options are %s)", fname,
                      lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : luaL_typename(L, -1), list);
    }
}

/* A length option at the stack top: a string with its unit. */
static double length_field(lua_State *L, const char *fname, const char *key) {
    char what[64], err[200];
    snprintf(what, sizeof what, "%s: %s", fname, key);
    if (lua_type(L, -1) != LUA_TSTRING)
        pcl_error(L, "%s must be a length with its unit such as \"12cm\" or \"0.5mm\", got %s",
                  what, pcl_shown(L, -1));
    double pt;
    if (pc_parse_length(lua_tostring(L, -1), what, &pt, err, sizeof err) != PC_OK)
        pcl_error(L, "%s", err);
    return pt;
}

static double number_field(lua_State *L, const char *fname, const char *key) {
    int isnum;
    double v = lua_tonumberx(L, -1, &isnum);
    if (!isnum) pcl_error(L, "%s: %s must be a number, got %s", fname, key, pcl_shown(L, -1));
    return v;
}

/* figure{width = "12cm", height = "8cm", dpi = 300, font = "serif", size = 10}: the print
 * look for every output, at that size. */
static int l_figure(lua_State *L) {
    static const char *const keys[] = {"width", "height", "dpi", "font", "size", NULL};
    pc_canvas *c = pcl_canvas(L);
    pc_figure f = c->figure;
    if (!lua_isnoneornil(L, 1)) {
        if (!lua_istable(L, 1))
            return pcl_argerror(L, 1, "options", "a table {width =, height =, dpi =, font =, size =}");
        known_keys(L, 1, "figure", keys, "width, height, dpi, font and size");
        if (lua_getfield(L, 1, "width") != LUA_TNIL) f.width = length_field(L, "figure", "width");
        if (lua_getfield(L, 1, "height") != LUA_TNIL) f.height = length_field(L, "figure", "height");
        if (lua_getfield(L, 1, "dpi") != LUA_TNIL) {
            f.dpi = number_field(L, "figure", "dpi");
            if (!(f.dpi >= 10 && f.dpi <= 2400))
                return pcl_error(L, "figure: dpi must be 10..2400, got %f", f.dpi);
        }
        if (lua_getfield(L, 1, "size") != LUA_TNIL) {
            f.size = lua_type(L, -1) == LUA_TSTRING ? length_field(L, "figure", "size")
                                                     : number_field(L, "figure", "size");
            if (!(f.size >= 1 && f.size <= 200))
                return pcl_error(L, "figure: size must be 1..200 pt, got %f", f.size);
        }
        if (lua_getfield(L, 1, "font") != LUA_TNIL) {
            if (lua_type(L, -1) != LUA_TSTRING || lua_rawlen(L, -1) >= sizeof f.font)
                return pcl_error(L, "figure: font must be a font name such as \"serif\", \"sans\" "
                                    "or \"mono\", got %s", pcl_shown(L, -1));
            strcpy(f.font, lua_tostring(L, -1));
        }
        lua_pop(L, 5);
        /* a width alone keeps the window's aspect, a height alone likewise */
        lua_getfield(L, 1, "height");
        if (lua_isnil(L, -1) && lua_getfield(L, 1, "width") != LUA_TNIL) f.height = 0;
        lua_settop(L, 1);
        lua_getfield(L, 1, "width");
        if (lua_isnil(L, -1) && lua_getfield(L, 1, "height") != LUA_TNIL) f.width = 0;
        lua_settop(L, 1);
    }
    if (pc_figure_set(c, &f) != PC_OK) return pcl_error(L, "%s", pc_canvas_error(c));
    return 0;
}

/* pen "main" / pen{width = "0.5mm", dash = {"3mm", "1.5mm"}}: called by pen() (l_draw.c)
 * when the pen is named or a length has a unit.  Returns 1 when it set the pen. */
int pcl_pen_print(lua_State *L, pc_canvas *c) {
    if (lua_type(L, 1) == LUA_TSTRING) {
        if (pc_pen_named(c, lua_tostring(L, 1)) != PC_OK) return pcl_error(L, "%s", pc_canvas_error(c));
        return 1;
    }
    if (!lua_istable(L, 1)) return 0;
    int physical = lua_getfield(L, 1, "width") == LUA_TSTRING;
    lua_pop(L, 1);
    if (lua_getfield(L, 1, "dash") == LUA_TTABLE) {
        lua_geti(L, -1, 1);
        physical |= lua_type(L, -1) == LUA_TSTRING;
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (!physical) return 0;
    double width = PC_PRINT_PEN_PT, dash[PC_PEN_MAXDASH];
    int ndash = 0;
    if (lua_getfield(L, 1, "width") != LUA_TNIL) width = length_field(L, "pen", "width");
    lua_pop(L, 1);
    if (lua_getfield(L, 1, "dash") != LUA_TNIL) {
        int t = lua_gettop(L);
        lua_Integer n = lua_istable(L, t) ? luaL_len(L, t) : -1;
        if (n < 0 || n > PC_PEN_MAXDASH || n % 2)
            return pcl_error(L, "pen: dash must be a list of on, off lengths (an even number, at most 16)");
        for (int i = 0; i < n; i++) {
            lua_geti(L, t, i + 1);
            dash[i] = length_field(L, "pen", "dash length");
            lua_pop(L, 1);
        }
        ndash = (int)n;
    }
    lua_pop(L, 1);
    if (pc_pen_physical(c, width, dash, ndash) != PC_OK) return pcl_error(L, "%s", pc_canvas_error(c));
    return 1;
}

/* label(..., {font =, size =, halo =}): read the options table at idx (checked now, applied by
 * pcl_label_style to the label once drawn). */
void pcl_label_options(lua_State *L, int idx, pcl_label_opts *o) {
    static const char *const keys[] = {"font", "size", "halo", NULL};
    known_keys(L, idx, pcl_fname(L), keys, "font, size and halo");
    memset(o, 0, sizeof *o);
    o->halo = -1;
    if (lua_getfield(L, idx, "font") != LUA_TNIL) {
        if (lua_type(L, -1) != LUA_TSTRING || lua_rawlen(L, -1) >= sizeof o->font)
            pcl_error(L, "%s: font must be a font name, got %s", pcl_fname(L), pcl_shown(L, -1));
        const char *font = lua_tostring(L, -1);
        strcpy(o->font, font);
        const char *family;
        char err[200];
        if (pc_font_family(font, &family, err, sizeof err) != PC_OK)
            pcl_error(L, "%s: %s", pcl_fname(L), err);
    }
    if (lua_getfield(L, idx, "size") != LUA_TNIL) {
        o->size = lua_type(L, -1) == LUA_TSTRING ? length_field(L, pcl_fname(L), "size")
                                                  : number_field(L, pcl_fname(L), "size");
        if (!(o->size >= 1 && o->size <= 200))
            pcl_error(L, "%s: size must be 1..200 pt, got %f", pcl_fname(L), o->size);
    }
    if (lua_getfield(L, idx, "halo") != LUA_TNIL) {
        if (!lua_isboolean(L, -1))
            pcl_error(L, "%s: halo must be true or false, got %s", pcl_fname(L), pcl_shown(L, -1));
        o->halo = lua_toboolean(L, -1);
    }
    lua_pop(L, 3);
}

void pcl_label_style(lua_State *L, pc_canvas *c, const pcl_label_opts *o) {
    if (pc_text_style(c, o->font, o->size, o->halo) != PC_OK) {
        const char *m = pc_canvas_error(c), *colon = strstr(m, ": ");
        pcl_error(L, "%s: %s", pcl_fname(L), colon ? colon + 2 : m);
    }
}

void pcl_open_figure(lua_State *L) {
    lua_pushcfunction(L, l_figure);
    lua_setfield(L, -2, "figure");
}
