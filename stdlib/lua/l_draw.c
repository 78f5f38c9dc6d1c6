/* Binding of the QBasic drawing layer (stdlib/draw): screen cls color palette pset preset line
 * line_to circle paint point window view save last_point, and beyond QBasic: pen path fill
 * label text.  Every colour argument is an attribute number or a "#rrggbb" string.
 *
 * The canvas lives in a full userdata that every function holds as its first upvalue (a box
 * around a pc_canvas pointer, so SCREEN can replace the canvas in place); the registry keeps
 * it too, for the host.  Coordinate pairs may always be given as one 2-D point. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pcl.h"
#include "pcl_curve.h"   /* pcl_project: 3-D points through the camera */
#include "pcl_qbscreen.h"
#include "pcl_scene.h"
#include "furniture.h"

#define CANVAS_KEY "pointcalc.canvas"
static const char CANVAS_TAG = 'd';   /* its address tags the type (PCL_SELF_TAG) */
#define THEME_KEY "pointcalc.theme"
#define CANVAS_MT "pointcalc.Canvas"

/* c is the page drawn on; pages[] are QBasic's screen pages (pages[0] is the first canvas,
 * the others made on first use), `visual` the one shown and saved by the host. */
typedef struct {
    PCL_SELF;             /* its own address: a forged box is refused (pcl.h) */
    pc_canvas *c;
    pc_canvas *pages[PCL_MAX_PAGES];
    int npages, active, visual;
    pc_draw_state draw;   /* DRAW's colour, scale and angle, kept between statements */
} canvas_box;

/* The box at idx, or NULL: the debug library can put something else in the registry entry
 * or in a drawing function's upvalue (debug.setupvalue), so its size and self are checked. */
static canvas_box *genuine_box(lua_State *L, int idx) {
    canvas_box *b = lua_touserdata(L, idx);
    if (b && lua_type(L, idx) == LUA_TUSERDATA && lua_rawlen(L, idx) == sizeof *b &&
        b->self == PCL_SELF_TAG(b, &CANVAS_TAG))
        return b;
    return NULL;
}

static canvas_box *box_at(lua_State *L, int idx) {
    canvas_box *b = genuine_box(L, idx);
    if (!b) pcl_error(L, "%s: the canvas was replaced (debug.setupvalue)", pcl_fname(L));
    return b;
}

/* the host asks outside any protected call: no error, NULL as for no canvas */
static canvas_box *the_box(lua_State *L) {
    lua_getfield(L, LUA_REGISTRYINDEX, CANVAS_KEY);
    canvas_box *b = genuine_box(L, -1);
    lua_pop(L, 1);
    return b;
}

static pc_canvas *canvas(lua_State *L) { return box_at(L, lua_upvalueindex(1))->c; }

pc_canvas *pcl_canvas(lua_State *L) {
    canvas_box *b = the_box(L);
    if (!b) return NULL;
    return b->pages[b->visual] ? b->pages[b->visual] : b->c;
}

pc_canvas *pcl_active_canvas(lua_State *L) {
    canvas_box *b = the_box(L);
    return b ? b->c : NULL;
}

int pcl_npages(lua_State *L) {
    canvas_box *b = the_box(L);
    return b ? b->npages : 0;
}

pc_canvas *pcl_page(lua_State *L, int page) {
    canvas_box *b = the_box(L);
    if (!b || page < 0 || page >= b->npages) return NULL;
    if (!b->pages[page]) {   /* a page first used: a blank screen like page 0's */
        pc_canvas *p0 = b->pages[0];
        pc_canvas *p = pc_canvas_new(p0->width, p0->height, p0->ncolors);
        if (!p) pcl_error(L, "screen: out of memory for page %d", page);
        memcpy(p->palette, p0->palette, 256 * sizeof *p->palette);
        b->pages[page] = p;
    }
    return b->pages[page];
}

void pcl_set_pages(lua_State *L, int active, int visual) {
    canvas_box *b = the_box(L);
    pc_canvas *a = pcl_page(L, active);
    pcl_page(L, visual);
    b->c = a;
    b->active = active;
    b->visual = visual;
}

pc_draw_state *pcl_draw_state(lua_State *L) {
    canvas_box *b = the_box(L);
    return &b->draw;
}

/* Back to one page, page 0 (SCREEN): the other pages are dropped. */
static void single_page(canvas_box *b) {
    for (int i = 0; i < PCL_MAX_PAGES; i++) {   /* the page drawn on becomes page 0 */
        if (b->pages[i] != b->c) pc_canvas_free(b->pages[i]);
        b->pages[i] = NULL;
    }
    b->pages[0] = b->c;
    b->npages = 1;
    b->active = b->visual = 0;
    pc_draw_state_reset(&b->draw);
}

void pcl_set_theme(lua_State *L, pc_theme theme) {
    lua_pushinteger(L, theme);
    lua_setfield(L, LUA_REGISTRYINDEX, THEME_KEY);
}

pc_theme pcl_theme(lua_State *L) {
    lua_getfield(L, LUA_REGISTRYINDEX, THEME_KEY);
    pc_theme t = (pc_theme)lua_tointeger(L, -1);
    lua_pop(L, 1);
    return t;
}

/* A core call failed: raise its message as a Lua error at the caller's line. */
static int check(lua_State *L, pc_canvas *c, int rc) {
    if (rc == PC_OK) return 0;
    lua_Debug ar;
    const char *name = NULL;
    if (lua_getstack(L, 0, &ar) && lua_getinfo(L, "n", &ar) && ar.name) name = ar.name;
    if (!name) name = pcl_fname(L);   /* called from C: text{...} forwarding, pcall */
    /* a core message may start with the core statement's name ("pset: coordinates ...");
     * the caller's name replaces it, so preset reports as preset and line_to as line_to */
    const char *msg = c->error, *colon = strstr(msg, ": ");
    if (colon && colon > msg && strspn(msg, "abcdefghijklmnopqrstuvwxyz_") == (size_t)(colon - msg))
        msg = colon + 2;
    return pcl_error(L, "%s: %s", name, msg);
}

/* The house argument error for a string value at idx, showing the string itself, for
 * argument arg. */
static int bad_string(lua_State *L, int idx, int arg, const char *what, const char *expected) {
    return pcl_error(L, "%s: argument #%d (%s) must be %s, got \"%s\"", pcl_fname(L),
                     pcl_arg_shown(L, arg), what, expected, lua_tostring(L, idx));
}

/* A colour value at stack index idx, part of argument arg: an attribute number of the screen
 * or a "#rrggbb" string (a true colour, allocated on first use).  `what` names it in errors
 * ("colour", "border colour"). */
static int color_error(lua_State *L, int idx, int arg, pc_canvas *c, const char *what) {
    char expected[64];
    snprintf(expected, sizeof expected, "a colour number 0..%d or \"#rrggbb\"", c->ncolors - 1);
    if (lua_type(L, idx) == LUA_TSTRING)   /* the string itself says best what is wrong */
        return bad_string(L, idx, arg, what, expected);
    return pcl_argerror_full(L, pcl_fname(L), idx, pcl_arg_shown(L, arg), what, expected);
}

static int color_at(lua_State *L, int idx, int arg, pc_canvas *c, const char *what) {
    int isint;
    lua_Integer v = lua_tointegerx(L, idx, &isint);   /* the common case first: pset runs it */
    if (isint && v >= 0 && v < c->ncolors && lua_type(L, idx) == LUA_TNUMBER) return (int)v;
    if (lua_type(L, idx) == LUA_TSTRING) {
        size_t len;
        const char *str = lua_tolstring(L, idx, &len);
        pc_rgb rgb;
        if (pc_rgb_parse(str, len, &rgb) != PC_OK) return color_error(L, idx, arg, c, what);
        int attr = pc_rgb_color(c, rgb);
        if (attr < 0) return pcl_error(L, "%s: %s", pcl_fname(L), c->error);
        return attr;
    }
    return color_error(L, idx, arg, c, what);
}

static int check_color_arg(lua_State *L, int arg, pc_canvas *c, const char *what) {
    return color_at(L, arg, arg, c, what);
}

/* An optional colour: none/nil means the default (-1 for the core). */
static int opt_color(lua_State *L, int arg, pc_canvas *c) {
    if (lua_isnoneornil(L, arg)) return -1;
    return check_color_arg(L, arg, c, "colour");
}

/* An optional number; NaN stands for "not given" in the core, so a NaN passed is refused. */
static double opt_number(lua_State *L, int arg, const char *what, double dflt) {
    if (lua_isnoneornil(L, arg)) return dflt;
    int isnum;
    double v = lua_tonumberx(L, arg, &isnum);
    if (!isnum || isnan(v)) pcl_argerror(L, arg, what, isnum ? "a finite number" : "a number");
    return v;
}

/* ---- the statements ---------------------------------------------------------------------- */

static int l_screen(lua_State *L) {
    canvas_box *b = box_at(L, lua_upvalueindex(1));
    int w, h, colors = 16, pages = 1;
    if (lua_istable(L, 1)) {
        lua_getfield(L, 1, "width");
        lua_getfield(L, 1, "height");
        lua_getfield(L, 1, "colors");
        /* range-checked before narrowing to int, so 2^32 + 640 is not 640 */
        int okw, okh;
        lua_Integer lw = lua_tointegerx(L, -3, &okw), lh = lua_tointegerx(L, -2, &okh);
        if (!okw || lw < 1 || lw > 16384) pcl_argerror(L, 1, "width", "an integer 1..16384");
        if (!okh || lh < 1 || lh > 16384) pcl_argerror(L, 1, "height", "an integer 1..16384");
        w = (int)lw;
        h = (int)lh;
        if (!lua_isnil(L, -1)) {
            lua_Integer lc = lua_tointeger(L, -1);
            if (lc != 2 && lc != 4 && lc != 16 && lc != 256)
                pcl_argerror(L, 1, "colors", "2, 4, 16 or 256");
            colors = (int)lc;
        }
    } else {
        int isint;
        lua_Integer mode = lua_tointegerx(L, 1, &isint);
        pc_mode_info m;
        if (!isint || mode < 0 || mode > 13 || pc_mode_info_of((int)mode, &m) != PC_OK)
            return pcl_argerror(L, 1, "mode",
                                "12 (640x480x16), 13 (320x200x256), 1, 2, 7, 8, 9 or {width=, height=}");
        w = m.width;
        h = m.height;
        colors = m.ncolors;
        pages = m.pages;
    }
    single_page(b);
    int rc = pc_canvas_reset(b->c, w, h, colors);
    if (rc == PC_OK) b->npages = pages;
    return check(L, b->c, rc);
}

static int l_cls(lua_State *L) {
    pc_canvas *c = canvas(L);
    return check(L, c, pc_cls(c));
}

static int l_color(lua_State *L) {
    pc_canvas *c = canvas(L);
    if (lua_isnoneornil(L, 1) && lua_isnoneornil(L, 2)) {   /* query */
        lua_pushinteger(L, c->fg);
        lua_pushinteger(L, c->bg);
        return 2;
    }
    int fg = opt_color(L, 1, c), bg = opt_color(L, 2, c);
    return check(L, c, pc_color(c, fg < 0 ? c->fg : fg, bg));
}

/* PALETTE attr, colour: the colour is QBasic's 65536*blue + 256*green + red with 6-bit
 * components, a "#rrggbb" string, or a table {r, g, b} of 0..255. */
static pc_rgb check_rgb(lua_State *L, int arg) {
    if (lua_type(L, arg) == LUA_TSTRING) {
        size_t len;
        const char *s = lua_tolstring(L, arg, &len);
        pc_rgb rgb;
        if (pc_rgb_parse(s, len, &rgb) == PC_OK) return rgb;
    } else if (lua_istable(L, arg)) {
        int v[3];
        for (int i = 0; i < 3; i++) {
            int isnum = lua_geti(L, arg, i + 1) == LUA_TNUMBER, isint;   /* no "10" */
            lua_Integer x = lua_tointegerx(L, -1, &isint);
            lua_pop(L, 1);
            if (!isnum || !isint || x < 0 || x > 255) goto bad;
            v[i] = (int)x;
        }
        return (pc_rgb){(uint8_t)v[0], (uint8_t)v[1], (uint8_t)v[2]};
    } else if (lua_type(L, arg) == LUA_TNUMBER) {
        int isint;
        lua_Integer q = lua_tointegerx(L, arg, &isint);
        int r = (int)(q & 0xff), g = (int)((q >> 8) & 0xff), b = (int)((q >> 16) & 0xff);
        if (isint && q >= 0 && q <= 0x3f3f3f && r < 64 && g < 64 && b < 64)
            return (pc_rgb){(uint8_t)((r << 2) | (r >> 4)), (uint8_t)((g << 2) | (g >> 4)),
                            (uint8_t)((b << 2) | (b >> 4))};
    }
bad:;
    static const char expected[] = "65536*blue + 256*green + red (each 0..63), \"#rrggbb\" or {r, g, b}";
    if (lua_type(L, arg) == LUA_TSTRING) bad_string(L, arg, arg, "colour", expected);
    pcl_argerror(L, arg, "colour", expected);
    return (pc_rgb){0, 0, 0};
}

static int l_palette(lua_State *L) {
    pc_canvas *c = canvas(L);
    if (lua_isnone(L, 1)) return check(L, c, pc_palette_reset(c));
    int isint;
    lua_Integer attr = lua_tointegerx(L, 1, &isint);
    if (!isint || attr < 0 || attr >= c->ncolors) {
        char expected[40];
        snprintf(expected, sizeof expected, "an attribute 0..%d", c->ncolors - 1);
        return pcl_argerror(L, 1, "attribute", expected);
    }
    pc_rgb rgb = check_rgb(L, 2);
    /* the palette is the video card's: every page shows it */
    canvas_box *b = box_at(L, lua_upvalueindex(1));
    for (int i = 0; i < PCL_MAX_PAGES; i++)
        if (b->pages[i] && b->pages[i] != c) check(L, b->pages[i], pc_palette(b->pages[i], (int)attr, rgb));
    return check(L, c, pc_palette(c, (int)attr, rgb));
}

static int dot(lua_State *L, int (*fn)(pc_canvas *, double, double, int)) {
    pc_canvas *c = canvas(L);
    int arg = 1;
    double x, y;
    pcl_checkxy(L, &arg, &x, &y, "");
    return check(L, c, fn(c, x, y, opt_color(L, arg, c)));
}

static int l_pset(lua_State *L) { return dot(L, pc_pset); }
static int l_preset(lua_State *L) { return dot(L, pc_preset); }

/* The style argument of LINE: nil, "b" (box) or "bf" (filled box), any case. */
static int line_style(lua_State *L, int arg) {
    if (lua_isnoneornil(L, arg)) return 0;
    const char *s = lua_tostring(L, arg);
    if (s && lua_type(L, arg) == LUA_TSTRING) {
        if (!strcmp(s, "b") || !strcmp(s, "B")) return 1;
        if (!strcmp(s, "bf") || !strcmp(s, "BF") || !strcmp(s, "Bf") || !strcmp(s, "bF")) return 2;
    }
    return pcl_argerror(L, arg, "style", "\"b\" (box) or \"bf\" (filled box)");
}

/* QBasic's 16-bit LINE style after the box flag: 0..65535, or a signed INTEGER -32768..-1
 * (&HAAAA is -21846 in QBasic); -1 when not given. */
static long line_pattern(lua_State *L, int arg) {
    if (lua_isnoneornil(L, arg)) return -1;
    int isint;
    lua_Integer v = lua_tointegerx(L, arg, &isint);
    if (!isint || v < -32768 || v > 65535)
        return pcl_argerror(L, arg, "line style", "a 16-bit pattern -32768..65535");
    return (long)(v & 0xffff);
}

static int draw_line(lua_State *L, pc_canvas *c, double x1, double y1, int arg) {
    double x2, y2;
    pcl_checkxy(L, &arg, &x2, &y2, "end");
    int color = opt_color(L, arg, c);
    int box = line_style(L, arg + 1);
    long pattern = line_pattern(L, arg + 2);
    if (pattern >= 0 && box != 2)   /* QBasic ignores the style of a filled box */
        return check(L, c, pc_line_styled(c, x1, y1, x2, y2, color, box, (unsigned)pattern));
    if (box == 0) return check(L, c, pc_line(c, x1, y1, x2, y2, color));
    return check(L, c, pc_box(c, x1, y1, x2, y2, color, box == 2));
}

/* ---- beyond QBasic: pen, path, label, text ------------------------------------------------ */

/* A field of an options table that must be a number in lo..hi (the value at the stack top). */
static double field_number(lua_State *L, int arg, const char *what, double lo, double hi,
                           const char *expected) {
    int isnum;
    double v = lua_tonumberx(L, -1, &isnum);
    if (!isnum || !(v >= lo && v <= hi))
        pcl_argerror_full(L, pcl_fname(L), lua_gettop(L), pcl_arg_shown(L, arg), what, expected);
    return v;
}

/* pen{width = w, dash = {on, off, ...}} sets the pen; pen() restores the default. */
static int l_pen(lua_State *L) {
    pc_canvas *c = canvas(L);
    if (lua_isnoneornil(L, 1)) {
        pc_pen_reset(c);
        return 0;
    }
    if (pcl_pen_print(L, c)) return 0;   /* a named pen, or lengths with units */
    if (!lua_istable(L, 1))
        return pcl_argerror(L, 1, "pen", "a table {width =, dash =} or a pen's name (\"main\", "
                                         "\"thin\", \"hidden\", \"centre\")");
    double width = 1, dash[PC_PEN_MAXDASH];
    int ndash = 0;
    if (lua_getfield(L, 1, "width") != LUA_TNIL)
        width = field_number(L, 1, "width", 1, PC_PEN_MAXWIDTH, "a number 1..256 (pixels)");
    lua_pop(L, 1);
    if (lua_getfield(L, 1, "dash") != LUA_TNIL) {
        int t = lua_gettop(L);
        lua_Integer n = lua_istable(L, t) ? luaL_len(L, t) : -1;
        if (n < 0 || n > PC_PEN_MAXDASH || n % 2)
            return pcl_argerror_full(L, pcl_fname(L), t, pcl_arg_shown(L, 1), "dash",
                                     "a list of on, off lengths (an even number, at most 16)");
        for (int i = 0; i < n; i++) {
            lua_geti(L, t, i + 1);
            dash[i] = field_number(L, 1, "dash length", 1e-6, 1e6, "a positive number (pixels)");
            lua_pop(L, 1);
        }
        ndash = (int)n;
    }
    lua_pop(L, 1);
    return check(L, c, pc_pen(c, width, dash, ndash));
}

/* The point at the stack top, element `where` ("index 3", "index [2][3]") of argument arg:
 * a 2-D point, or an n-D one with a camera for n-D points set. */
static void list_point(lua_State *L, int arg, const char *where, const char *expected,
                       double *x, double *y) {
    pcl_value *p = pcl_tovalue(L, -1);
    if (p && p->n != 2) {
        int st = pcl_project(L, p->n, p->h, x, y);
        if (st == PC_OK) return;
        const char *text = luaL_tolstring(L, -1, NULL);
        if (st == PC_IMPROPER)
            pcl_error(L, "%s: argument #%d (points) at %s: %s projects to infinity (it lies in the "
                         "camera's vanishing plane)", pcl_fname(L), pcl_arg_shown(L, arg), where, text);
        if (st != PC_EDIM)
            pcl_error(L, "%s: argument #%d (points) at %s: the image of %s is not finite",
                      pcl_fname(L), pcl_arg_shown(L, arg), where, text);
        pcl_error(L, "%s: argument #%d (points) must be %s, got the %d-D %s at %s (3-D points "
                     "need a camera)", pcl_fname(L), pcl_arg_shown(L, arg), expected, p->n, text, where);
    }
    double loc[2];
    if (p && pc_loc(2, p->h, loc) != PC_OK) {   /* a vector or a weighted value */
        const char *text = luaL_tolstring(L, -1, NULL);
        const char *w = pcl_pushnum(L, p->h[2]);
        pcl_error(L, "%s: argument #%d (points) at %s: %s has weight %s, not 1: a location must "
                     "be a point (the membership condition; normalize(p) for a projective point)",
                  pcl_fname(L), pcl_arg_shown(L, arg), where, text, w);
    }
    if (!pcl_topoint2(L, -1, x, y))
        pcl_error(L, "%s: argument #%d (points) must be %s, got %s at %s", pcl_fname(L),
                  pcl_arg_shown(L, arg), expected, luaL_typename(L, -1), where);
}

/* The points argument at arg of path and fill: a list of 2-D points (one subpath) or a list
 * of such lists (one subpath each).  The coordinates and the verbs (a move at the start of
 * each subpath, lines after) go to scratch userdata left on the stack; returns the number of
 * points. */
static size_t read_subpaths(lua_State *L, int arg, double **xy, uint8_t **verbs) {
    static const char expected[] = "a list of 2-D points or a list of such lists";
    if (!lua_istable(L, arg)) return (size_t)pcl_argerror(L, arg, "points", "a list of 2-D points");
    lua_Integer m = luaL_len(L, arg);
    if (m < 1) return (size_t)pcl_argerror(L, arg, "points", "a list of at least one point");
    lua_geti(L, arg, 1);
    int nested = lua_type(L, -1) == LUA_TTABLE;
    lua_pop(L, 1);
    size_t n = 0;
    for (lua_Integer k = 1; nested && k <= m; k++) {   /* count the points of the subpaths */
        if (lua_geti(L, arg, k) != LUA_TTABLE)
            pcl_error(L, "%s: argument #%d (points) must be %s, got %s at index %d", pcl_fname(L),
                      pcl_arg_shown(L, arg), expected, luaL_typename(L, -1), (int)k);
        lua_Integer len = luaL_len(L, -1);
        if (len < 1)
            pcl_error(L, "%s: argument #%d (points) must be %s, got an empty list at index %d",
                      pcl_fname(L), pcl_arg_shown(L, arg), expected, (int)k);
        n += (size_t)len;
        lua_pop(L, 1);
    }
    if (!nested) n = (size_t)m;
    if (n > 100000000) pcl_error(L, "%s: argument #%d (points) holds too many points", pcl_fname(L), pcl_arg_shown(L, arg));
    *xy = lua_newuserdatauv(L, n * 2 * sizeof **xy, 0);   /* freed by the GC */
    *verbs = lua_newuserdatauv(L, n, 0);
    size_t i = 0;
    for (lua_Integer k = 1; k <= (nested ? m : 1); k++) {
        int list = arg;
        if (nested) {
            lua_geti(L, arg, k);
            list = lua_gettop(L);
        }
        lua_Integer len = luaL_len(L, list);
        for (lua_Integer j = 1; j <= len; j++, i++) {
            char where[48];
            if (nested) snprintf(where, sizeof where, "index [%d][%d]", (int)k, (int)j);
            else snprintf(where, sizeof where, "index %d", (int)j);
            lua_geti(L, list, j);
            list_point(L, arg, where, nested ? expected : "a list of 2-D points",
                       &(*xy)[2 * i], &(*xy)[2 * i + 1]);
            (*verbs)[i] = j == 1 ? PC_PATH_MOVE : PC_PATH_LINE;
            lua_pop(L, 1);
        }
        if (nested) lua_pop(L, 1);
    }
    return n;
}

/* A fill rule at stack index idx, part of argument arg: "evenodd" (the default) or
 * "nonzero". */
static int rule_at(lua_State *L, int idx, int arg, const char *what) {
    static const char expected[] = "\"evenodd\" or \"nonzero\"";
    if (lua_isnoneornil(L, idx)) return PC_FILL_EVENODD;
    if (lua_type(L, idx) == LUA_TSTRING) {
        const char *r = lua_tostring(L, idx);
        if (!strcmp(r, "evenodd")) return PC_FILL_EVENODD;
        if (!strcmp(r, "nonzero")) return PC_FILL_NONZERO;
        return bad_string(L, idx, arg, what, expected);
    }
    return pcl_argerror_full(L, pcl_fname(L), idx, pcl_arg_shown(L, arg), what, expected);
}

/* The arrow option of path's table (argument 2): "end", "start", "both" or absent. */
static int path_heads(lua_State *L) {
    static const char *const heads[] = {"none", "end", "start", "both", NULL};
    if (!lua_istable(L, 2) || lua_getfield(L, 2, "arrow") == LUA_TNIL) {
        lua_settop(L, 2);
        return 0;
    }
    const char *h = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "";
    for (int k = 0; heads[k]; k++)
        if (!strcmp(h, heads[k])) {
            lua_settop(L, 2);
            return k;
        }
    return bad_string(L, lua_gettop(L), 2, "options.arrow", "\"end\", \"start\", \"both\" or \"none\"");
}

/* path(points [, {closed =, color =, fill =, rule =, arrow =}]): the polyline through a list of 2-D
 * points (or several, one subpath each).  With fill, the closed path is filled in that
 * colour, and its outline drawn on top only when color is given too. */
static int l_path(lua_State *L) {
    pc_canvas *c = canvas(L);
    lua_settop(L, 2);
    int closed = 0, color = -1, fill = -2, rule = PC_FILL_EVENODD;
    if (!lua_isnil(L, 2)) {
        if (!lua_istable(L, 2))
            return pcl_argerror(L, 2, "options", "a table {closed =, color =, fill =, rule =}");
        lua_getfield(L, 2, "closed");
        closed = lua_toboolean(L, -1);
        if (lua_getfield(L, 2, "color") != LUA_TNIL)
            color = color_at(L, lua_gettop(L), 2, c, "options.color");
        if (lua_getfield(L, 2, "fill") != LUA_TNIL)
            fill = color_at(L, lua_gettop(L), 2, c, "options.fill");
        lua_getfield(L, 2, "rule");
        rule = rule_at(L, lua_gettop(L), 2, "options.rule");
        lua_pop(L, 4);
    }
    int heads = path_heads(L);
    double *xy;
    uint8_t *verbs;
    size_t n = read_subpaths(L, 1, &xy, &verbs);
    if (fill == -2) {
        check(L, c, pc_path(c, n, xy, verbs, n, closed, color));
        /* arrow heads (furniture.h) on the first and last segments */
        if ((heads & PC_ARROW_END) && n >= 2)
            check(L, c, pc_arrow_head(c, xy[2 * n - 4], xy[2 * n - 3], xy[2 * n - 2], xy[2 * n - 1], 9, color));
        if ((heads & PC_ARROW_START) && n >= 2)
            check(L, c, pc_arrow_head(c, xy[2], xy[3], xy[0], xy[1], 9, color));
        return 0;
    }
    check(L, c, pc_fill_path(c, n, xy, verbs, n, rule, fill));
    if (color < 0) return 0;
    return check(L, c, pc_path(c, n, xy, verbs, n, 1, color));
}

/* fill(points [, colour [, rule]]): the closed path through the points (or several, one
 * subpath each) filled; rule "evenodd" (default: a subpath inside another makes a hole) or
 * "nonzero". */
static int l_fill(lua_State *L) {
    pc_canvas *c = canvas(L);
    lua_settop(L, 3);
    int color = opt_color(L, 2, c);
    int rule = rule_at(L, 3, 3, "rule");
    double *xy;
    uint8_t *verbs;
    size_t n = read_subpaths(L, 1, &xy, &verbs);
    return check(L, c, pc_fill_path(c, n, xy, verbs, n, rule, color));
}

static const char *const directions[] = {"c", "n", "ne", "e", "se", "s", "sw", "w", "nw", NULL};

/* The text argument: a string (or a number, shown as Lua shows it). */
static const char *check_text(lua_State *L, int arg) {
    int t = lua_type(L, arg);
    if (t != LUA_TSTRING && t != LUA_TNUMBER) pcl_argerror(L, arg, "text", "a string");
    size_t len;
    const char *s = lua_tolstring(L, arg, &len);
    /* the writers take C strings: a NUL would cut the label short in every one of them */
    if (strlen(s) != len) pcl_argerror(L, arg, "text", "a string without NUL bytes");
    return s;
}

static int opt_scale(lua_State *L, int arg) {
    if (lua_isnoneornil(L, arg)) return 1;
    int isint;
    lua_Integer v = lua_tointegerx(L, arg, &isint);
    if (!isint || v < 1 || v > 8) return pcl_argerror(L, arg, "scale", "an integer 1..8");
    return (int)v;
}

/* label(text, P [, direction [, colour [, scale]]]): text beside a point, 3 px off it; without
 * a direction it is placed when the picture is written (stdlib/draw/layout.h). */
static int l_label(lua_State *L) {
    if (pcl_scene_label(L)) return 0;   /* a 3-D point in the camera's scene (pcl_scene.h) */
    pc_canvas *c = canvas(L);
    /* a trailing options table {font =, size =, halo =}, read first and then dropped */
    int opts = lua_gettop(L) > 2 && lua_type(L, lua_gettop(L)) == LUA_TTABLE ? lua_gettop(L) : 0;
    pcl_label_opts o;
    if (opts) {
        pcl_label_options(L, opts, &o);
        lua_settop(L, opts - 1);
    }
    const char *str = check_text(L, 1);
    int arg = 2;
    double x, y;
    pcl_checkxy(L, &arg, &x, &y, "");
    int anchor = PC_ANCHOR_AUTO;
    if (!lua_isnoneornil(L, arg)) {
        static const char expected[] = "one of \"n\" \"ne\" \"e\" \"se\" \"s\" \"sw\" \"w\" \"nw\" \"c\"";
        if (lua_type(L, arg) != LUA_TSTRING) return pcl_argerror(L, arg, "direction", expected);
        const char *d = lua_tostring(L, arg);
        int k = 0;
        while (directions[k] && strcmp(directions[k], d)) k++;
        if (!directions[k]) return bad_string(L, arg, arg, "direction", expected);
        anchor = k;
    }
    int color = opt_color(L, arg + 1, c);
    int scale = opt_scale(L, arg + 2);
    check(L, c, pc_text(c, x, y, str, anchor, 3, scale, color));
    if (opts) pcl_label_style(L, c, &o);
    return 0;
}

/* text(x, y, string [, colour [, scale]]): the text cell's top-left corner at the point. */
static int l_text(lua_State *L) {
    pc_canvas *c = canvas(L);
    int arg = 1;
    double x, y;
    pcl_checkxy(L, &arg, &x, &y, "");
    const char *str = check_text(L, arg);
    int color = opt_color(L, arg + 1, c);
    int scale = opt_scale(L, arg + 2);
    return check(L, c, pc_text(c, x, y, str, PC_ANCHOR_SE, 0, scale, color));
}

static int l_line(lua_State *L) {
    if (pcl_scene_line(L)) return 0;   /* 3-D points into the camera's scene (pcl_scene.h) */
    pc_canvas *c = canvas(L);
    int arg = 1;
    double x1, y1;
    pcl_checkxy(L, &arg, &x1, &y1, "start");
    return draw_line(L, c, x1, y1, arg);
}

/* LINE -(x, y): from the graphics cursor (the last point referenced). */
static int l_line_to(lua_State *L) {
    pc_canvas *c = canvas(L);
    return draw_line(L, c, c->last_x, c->last_y, 1);
}

static int l_last_point(lua_State *L) {
    pc_canvas *c = canvas(L);
    lua_pushnumber(L, c->last_x);
    lua_pushnumber(L, c->last_y);
    return 2;
}

static int l_circle(lua_State *L) {
    pc_canvas *c = canvas(L);
    int arg = 1;
    double x, y;
    pcl_checkxy(L, &arg, &x, &y, "centre");
    int isnum;
    double r = lua_tonumberx(L, arg, &isnum);
    if (!isnum || !(r >= 0) || !isfinite(r))
        return pcl_argerror(L, arg, "radius", "a non-negative number");
    int color = opt_color(L, arg + 1, c);
    double start = opt_number(L, arg + 2, "start angle", NAN);
    double end = opt_number(L, arg + 3, "end angle", NAN);
    double aspect = opt_number(L, arg + 4, "aspect", NAN);
    if (!isnan(aspect) && !(aspect > 0 && isfinite(aspect)))
        return pcl_argerror(L, arg + 4, "aspect", "a positive number");
    if (!isnan(start) && !(fabs(start) <= 2 * M_PI + 1e-6))
        return pcl_argerror(L, arg + 2, "start angle", "between -2*pi and 2*pi");
    if (!isnan(end) && !(fabs(end) <= 2 * M_PI + 1e-6))
        return pcl_argerror(L, arg + 3, "end angle", "between -2*pi and 2*pi");
    return check(L, c, pc_circle(c, x, y, r, color, start, end, aspect));
}

static int l_paint(lua_State *L) {
    pc_canvas *c = canvas(L);
    int arg = 1;
    double x, y;
    pcl_checkxy(L, &arg, &x, &y, "");
    int color = opt_color(L, arg, c);
    int border = -1;
    if (!lua_isnoneornil(L, arg + 1)) border = check_color_arg(L, arg + 1, c, "border colour");
    return check(L, c, pc_paint(c, x, y, color, border));
}

static int l_point(lua_State *L) {
    pc_canvas *c = canvas(L);
    int arg = 1;
    double x, y;
    pcl_checkxy(L, &arg, &x, &y, "");
    lua_pushinteger(L, pc_point(c, x, y));
    return 1;
}

/* A number as the core's messages print it (%g). */
static const char *num(lua_State *L, double v) {
    char b[32];
    snprintf(b, sizeof b, "%g", v);
    return lua_pushstring(L, b);
}

/* "screen" (string) or true as the last argument of WINDOW/VIEW means QBasic's SCREEN form. */
static int screen_flag(lua_State *L, int arg) {
    if (lua_isnoneornil(L, arg)) return 0;
    if (lua_isboolean(L, arg)) return lua_toboolean(L, arg);
    if (lua_type(L, arg) == LUA_TSTRING && !strcmp(lua_tostring(L, arg), "screen")) return 1;
    return pcl_argerror(L, arg, "mode", "\"screen\", a boolean or nil");
}

static int l_window(lua_State *L) {
    pc_canvas *c = canvas(L);
    if (lua_isnone(L, 1)) {
        pc_window_reset(c);
        return 0;
    }
    int arg = 1;
    double x1, y1, x2, y2;
    pcl_checkxy(L, &arg, &x1, &y1, "first corner");
    pcl_checkxy(L, &arg, &x2, &y2, "second corner");
    return check(L, c, pc_window(c, x1, y1, x2, y2, screen_flag(L, arg)));
}

static int l_view(lua_State *L) {
    pc_canvas *c = canvas(L);
    if (lua_isnone(L, 1)) return check(L, c, pc_view_reset(c));
    int arg = 1;
    double x1, y1, x2, y2;
    pcl_checkxy(L, &arg, &x1, &y1, "first corner");
    pcl_checkxy(L, &arg, &x2, &y2, "second corner");
    int fill = opt_color(L, arg, c), border = opt_color(L, arg + 1, c);
    int screen = screen_flag(L, arg + 2);
    /* the core takes whole pixels: corners beyond any screen are refused here, before the
     * conversion to int could wrap them onto it */
    const double lim = 1e6;
    if (!(fabs(x1) <= lim && fabs(y1) <= lim && fabs(x2) <= lim && fabs(y2) <= lim))
        return pcl_error(L, "view: view (%s, %s)-(%s, %s) is not inside the %dx%d screen",
                         num(L, x1), num(L, y1), num(L, x2), num(L, y2), c->width, c->height);
    return check(L, c, pc_view(c, (int)lrint(x1), (int)lrint(y1), (int)lrint(x2), (int)lrint(y2),
                               fill, border, screen));
}

/* save(path [, theme]): the format follows the extension; theme "paper" or "screen". */
static int l_save(lua_State *L) {
    pc_canvas *c = canvas(L);
    if (lua_type(L, 1) != LUA_TSTRING) return pcl_argerror(L, 1, "path", "a file name");
    const char *path = lua_tostring(L, 1);
    pc_theme theme = pcl_theme(L);
    if (!lua_isnoneornil(L, 2)) {
        const char *t = lua_tostring(L, 2);
        if (t && !strcmp(t, "paper")) theme = PC_THEME_PAPER;
        else if (t && !strcmp(t, "screen")) theme = PC_THEME_SCREEN;
        else return pcl_argerror(L, 2, "theme", "\"paper\" or \"screen\"");
    }
    if (pc_format_from_path(path) == PC_FMT_UNKNOWN)
        return pcl_argerror(L, 1, "path", "a file name ending in .png, .svg, .ppm, .pdf, .eps or .ps");
    char err[512];
    if (pc_write_file(c, path, theme, err, sizeof err) != PC_OK)
        return pcl_error(L, "save: %s", err);
    pc_canvas_mark_saved(c);
    return 0;
}

/* size() -> width, height, colours of the current screen */
static int l_size(lua_State *L) {
    pc_canvas *c = canvas(L);
    lua_pushinteger(L, c->width);
    lua_pushinteger(L, c->height);
    lua_pushinteger(L, c->ncolors);
    return 3;
}

static int canvas_gc(lua_State *L) {
    canvas_box *b = genuine_box(L, 1);
    if (!b) return 0;   /* never a forged one */
    for (int i = 0; i < PCL_MAX_PAGES; i++)
        if (b->pages[i] != b->c) pc_canvas_free(b->pages[i]);
    pc_canvas_free(b->c);
    memset(b, 0, sizeof *b);
    return 0;
}

static const luaL_Reg draw_functions[] = {
    {"screen", l_screen}, {"cls", l_cls},       {"color", l_color},   {"palette", l_palette},
    {"pset", l_pset},     {"preset", l_preset}, {"line", l_line},     {"line_to", l_line_to},
    {"circle", l_circle}, {"paint", l_paint},   {"point", l_point},   {"window", l_window},
    {"view", l_view},     {"save", l_save},     {"size", l_size},     {"last_point", l_last_point},
    {"pen", l_pen},       {"path", l_path},     {"label", l_label},   {"text", l_text},
    {"fill", l_fill},     {NULL, NULL}};

void pcl_open_draw(lua_State *L) {
    /* one canvas per Lua state: reuse it if the module is opened twice */
    lua_getfield(L, LUA_REGISTRYINDEX, CANVAS_KEY);
    if (lua_isnil(L, -1)) {
        lua_pop(L, 1);
        canvas_box *b = lua_newuserdatauv(L, sizeof *b, 0);
        memset(b, 0, sizeof *b);
        b->self = PCL_SELF_TAG(b, &CANVAS_TAG);
        luaL_newmetatable(L, CANVAS_MT);
        lua_pushcfunction(L, canvas_gc);
        lua_setfield(L, -2, "__gc");
        lua_setmetatable(L, -2);
        b->c = pc_canvas_new_mode(12);
        if (!b->c) pcl_error(L, "pointcalc: out of memory for the canvas");
        b->pages[0] = b->c;
        b->npages = 1;
        pc_draw_state_reset(&b->draw);
        lua_pushvalue(L, -1);
        lua_setfield(L, LUA_REGISTRYINDEX, CANVAS_KEY);
    }
    luaL_setfuncs(L, draw_functions, 1);
}

/* The colour argument at arg for other bindings (curves, surfaces): nil for the default. */
int pcl_optcolor(lua_State *L, int arg, pc_canvas *c) { return opt_color(L, lua_absindex(L, arg), c); }
