/* The print look's bindings: figure{...} (on the declared argument layer, docs/bindings.md),
 * and the physical and named pens and label options that pen() and label() of l_draw.c read
 * (kept here in one piece until l_draw.c moves to the layer). */
#include <string.h>
#include <lauxlib.h>
#include "pcl_args.h"
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

/* A length option: a string with its unit ("12cm"), in pt. */
static int read_length(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    if (lua_type(L, idx) != LUA_TSTRING) return 0;
    char err[200];
    if (pc_parse_length(lua_tostring(L, idx), "", &out->x, err, sizeof err) != PC_OK)
        return pcl_keyfail(L, a->name, "%s", err + 2);   /* the parser's words, after ": " */
    return 1;
}

/* A text size: pt as a number, or a length ("9pt"); 1..200 pt. */
static int read_size(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    if (lua_type(L, idx) == LUA_TNUMBER) out->x = lua_tonumber(L, idx);
    else if (!read_length(L, idx, a, out)) return 0;
    if (!(out->x >= 1 && out->x <= 200))
        return pcl_keyfail(L, a->name, "must be 1 to 200 pt, got %s pt", pcl_pushnum(L, out->x));
    return 1;
}

#define LENGTH "a length with its unit such as \"12cm\" or \"0.5mm\""
static const pcl_arg figure_keys[] = {
    {.name = "width", .kind = PCL_ANY, .read = read_length, .expect = LENGTH, .shown = "\"12cm\""},
    {.name = "height", .kind = PCL_ANY, .read = read_length, .expect = LENGTH, .shown = "\"8cm\""},
    {.name = "dpi", .kind = PCL_NUMBER, .flags = PCL_RANGE, .lo = 10, .hi = 2400, .shown = "300"},
    {.name = "font", .kind = PCL_STRING, .shown = "\"serif\"|\"sans\"|\"mono\""},
    {.name = "size", .kind = PCL_ANY, .read = read_size, .expect = "a size in pt (1 to 200)", .shown = "10"},
    PCL_END};
static const pcl_arg figure_args[] = {
    {.name = "options", .kind = PCL_OPTIONS, .flags = PCL_OPT | PCL_CALLTABLE, .keys = figure_keys},
    PCL_END};

/* figure{width = "12cm", height = "8cm", dpi = 300, font = "serif", size = 10}: the print
 * look for every output, at that size; a width alone keeps the window's aspect. */
static int l_figure(lua_State *L) {
    pcl_val a[6] = {0};   /* options, width, height, dpi, font, size */
    PCL_READ(L, a);
    pc_canvas *c = pcl_canvas(L);
    pc_figure f = c->figure;
    if (a[1].present || a[2].present) {
        f.width = a[1].present ? a[1].x : 0;
        f.height = a[2].present ? a[2].x : 0;
    }
    if (a[3].present) f.dpi = a[3].x;
    if (a[4].present) {
        if (strlen(a[4].s) >= sizeof f.font) return pcl_keyfail(L, "font", "is too long");
        strcpy(f.font, a[4].s);
    }
    if (a[5].present) f.size = a[5].x;
    if (pc_figure_set(c, &f) != PC_OK) {   /* the core's message, its "figure: " once */
        const char *m = pc_canvas_error(c);
        return pcl_fail(L, "%s", strncmp(m, "figure: ", 8) ? m : m + 8);
    }
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

static const pcl_fn fns[] = {
    PCL_FN("figure", l_figure, figure_args, NULL,
           "The print look for every output (PDF, EPS and PS always have it): the canvas at that size (a width alone keeps the window's aspect), PNG at dpi, labels in the font at size pt."),
    PCL_END};

void pcl_open_figure(lua_State *L) { pcl_register(L, -1, fns, 0); }
