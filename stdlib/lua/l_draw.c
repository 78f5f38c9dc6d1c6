/* Binding of the QBasic drawing layer (stdlib/draw) and beyond QBasic: pen path fill label text.
 * The canvas lives in a full userdata that every function holds as its first upvalue (a box
 * around QBasic's pages, so SCREEN can replace the canvas in place); the registry keeps it
 * too, for the host. */
#include "pcl_draw.h"
#include "print.h"       /* named pens, the print pen's width */
#include "furniture.h"
#include "math_label.h"

#define CANVAS_KEY "pointcalc.canvas"
static const char CANVAS_TAG = 'd';   /* its address tags the type (PCL_SELF_TAG) */
#define THEME_KEY "pointcalc.theme"
#define CANVAS_MT "pointcalc.Canvas"

typedef struct {
    PCL_SELF;             /* its own address: a forged box is refused (pcl.h) */
    pc_pages p;           /* QBasic's pages, the one drawn on, DRAW's state (qbscreen.h) */
} canvas_box;

/* The box at idx, or NULL: the debug library can put something else in the registry entry
 * or in a drawing function's upvalue (debug.setupvalue), so its size and self are checked. */
static canvas_box *genuine_box(lua_State *L, int idx) { return pcl_tagged(L, idx, sizeof(canvas_box), &CANVAS_TAG); }

static canvas_box *box_at(lua_State *L, int idx) {
    canvas_box *b = genuine_box(L, idx);
    if (!b) pcl_error(L, "%s: the canvas was replaced (debug.setupvalue)", pcl_fname(L));
    return b;
}

/* the host asks outside any protected call: no error, NULL as for no canvas */
pc_pages *pcl_pages(lua_State *L) {
    lua_getfield(L, LUA_REGISTRYINDEX, CANVAS_KEY);
    canvas_box *b = genuine_box(L, -1);
    lua_pop(L, 1);
    return b ? &b->p : NULL;
}

static pc_canvas *canvas(lua_State *L) { return box_at(L, PCL_UPVALUE(1))->p.c; }

pc_canvas *pcl_canvas(lua_State *L) {
    pc_pages *p = pcl_pages(L);
    return p ? pc_pages_shown(p) : NULL;
}

pc_canvas *pcl_active_canvas(lua_State *L) {
    pc_pages *p = pcl_pages(L);
    return p ? p->c : NULL;
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

int pcl_check_canvas(lua_State *L, pc_canvas *c, int rc) {
    return rc == PC_OK ? 0 : pcl_fail(L, "%s", pc_canvas_message(c));
}

int pcl_drawn(lua_State *L, int rc) { return pcl_check_canvas(L, pcl_active_canvas(L), rc); }

/* ---- the kinds of the drawing layer ------------------------------------------------------ */

int pcl_color_at(lua_State *L, int idx, pc_canvas *c, int truecolors) {
    int isint;
    lua_Integer v = lua_tointegerx(L, idx, &isint);   /* the common case first: pset runs it */
    if (isint && v >= 0 && v < c->ncolors && lua_type(L, idx) == LUA_TNUMBER) return (int)v;
    if (truecolors && isint && v >= 256 && v < 256 + c->ntrue && lua_type(L, idx) == LUA_TNUMBER) return (int)v;
    size_t len;
    const char *s = lua_type(L, idx) == LUA_TSTRING ? lua_tolstring(L, idx, &len) : NULL;
    pc_rgb rgb;
    if (!s || pc_rgb_parse(s, len, &rgb) != PC_OK) return -2;
    int attr = pc_rgb_color(c, rgb);
    if (attr < 0) pcl_error(L, "%s: %s", pcl_fname(L), c->error);
    return attr;
}

/* The colour at idx on canvas c into out->x, or the reader's message naming c's range. */
static int read_color_on(lua_State *L, int idx, pc_canvas *c, int truecolors, pcl_val *out) {
    if ((out->x = pcl_color_at(L, idx, c, truecolors)) >= 0) return 1;
    return pcl_readfail(L, idx, lua_pushfstring(L, "a colour number 0..%d or \"#rrggbb\"", c->ncolors - 1));
}

int pcl_read_color(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    return read_color_on(L, idx, pcl_active_canvas(L), a->dim == 1, out);
}

/* The colour of this file's statements, read on their upvalue's canvas (no registry look-up),
 * that canvas left in out->obj: pset finds it once per call (stmt_canvas). */
static int stmt_color(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    pc_canvas *c = canvas(L);
    out->obj = c;
    return read_color_on(L, idx, c, 0, out);
}

/* The canvas of a statement: the one its colour was read on, else the upvalue's. */
static pc_canvas *stmt_canvas(lua_State *L, const pcl_val *color) {
    return color->present ? color->obj : canvas(L);
}

/* PALETTE's colour: QBasic's 65536*blue + 256*green + red with 6-bit components, a "#rrggbb"
 * string, or a table {r, g, b} of 0..255; into out->v[0..2]. */
static int read_rgb(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    if (lua_istable(L, idx)) {
        for (int i = 0; i < 3; i++) {
            int isnum = lua_geti(L, idx, i + 1) == LUA_TNUMBER, isint;   /* no "10" */
            lua_Integer x = lua_tointegerx(L, -1, &isint);
            lua_pop(L, 1);
            if (!isnum || !isint || x < 0 || x > 255) return 0;
            out->v[i] = (double)x;
        }
        return 1;
    }
    pc_rgb rgb;
    size_t len = 0;
    int isint = 0, t = lua_type(L, idx);
    const char *s = t == LUA_TSTRING ? lua_tolstring(L, idx, &len) : NULL;
    lua_Integer q = t == LUA_TNUMBER ? lua_tointegerx(L, idx, &isint) : 0;
    if (s ? pc_rgb_parse(s, len, &rgb) != PC_OK : !isint || pc_rgb_qbasic(q, &rgb) != PC_OK) return 0;
    out->v[0] = rgb.r, out->v[1] = rgb.g, out->v[2] = rgb.b;
    return 1;
}

/* "screen" or a boolean as the last argument of WINDOW/VIEW: QBasic's SCREEN form. */
static int read_screen_flag(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    if (lua_isboolean(L, idx)) return (out->x = lua_toboolean(L, idx)), 1;
    return lua_type(L, idx) == LUA_TSTRING && !strcmp(lua_tostring(L, idx), "screen") && (out->x = 1);
}

#define COLOR(nm) {.name = nm, .kind = PCL_ANY, .flags = PCL_OPT, .read = stmt_color, .dflt = -1}
#define OPTNUM(nm, flag, l, h, exp) {.name = nm, .kind = PCL_NUMBER, .flags = PCL_OPT | (flag), .lo = l, .hi = h, .dflt = NAN, .expect = exp}
#define SCALE {.name = "scale", .kind = PCL_INTEGER, .flags = PCL_OPT | PCL_RANGE, .lo = 1, .hi = 8, .dflt = 1}
#define SCREEN_FLAG {.name = "mode", .kind = PCL_ANY, .flags = PCL_OPT, .read = read_screen_flag, .expect = "\"screen\", a boolean or nil"}
#define TEXT {.name = "text", .kind = PCL_ANY, .read = pcl_read_bytes, .dim = 1, .expect = "a string"}

/* ---- the statements ---------------------------------------------------------------------- */

static const pcl_arg screen_keys[] = {
    {.name = "width", .kind = PCL_INTEGER, .flags = PCL_REQ | PCL_RANGE, .lo = 1, .hi = 16384},
    {.name = "height", .kind = PCL_INTEGER, .flags = PCL_REQ | PCL_RANGE, .lo = 1, .hi = 16384},
    {.name = "colors", .kind = PCL_INTEGER, .flags = PCL_RANGE, .lo = 2, .hi = 256, .dflt = 16,
     .expect = "2, 4, 16 or 256"}, PCL_END};
static const pcl_arg screen_table = {.name = "mode", .kind = PCL_OPTIONS, .keys = screen_keys};
static const pcl_arg screen_args[] = {
    {.name = "mode", .kind = PCL_ANY, .expect = "12 (640x480x16), 13 (320x200x256), 1, 2, 7, 8, 9 or {width=, height=}"},
    PCL_END};

static int l_screen(lua_State *L) {
    pcl_val a[4] = {0};   /* mode; the table's width, height, colors */
    PCL_READ(L, a);
    canvas_box *b = box_at(L, PCL_UPVALUE(1));
    pc_mode_info m = {.pages = 1};
    if (lua_istable(L, 1)) {
        pcl_read_options(L, 1, 1, &screen_table, a + 1);
        m.width = (int)a[1].x, m.height = (int)a[2].x, m.ncolors = (int)a[3].x;
        if (m.ncolors != 2 && m.ncolors != 4 && m.ncolors != 16 && m.ncolors != 256)
            return pcl_keyfail(L, "colors", "must be 2, 4, 16 or 256, got %d", m.ncolors);
    } else {
        int isint;
        lua_Integer mode = lua_tointegerx(L, 1, &isint);
        if (!isint || mode < 0 || mode > 13 || pc_mode_info_of((int)mode, &m) != PC_OK)
            return pcl_argfail(L, 1, "must be %s, got %s", screen_args[0].expect, pcl_shown(L, 1));
    }
    return pcl_check_canvas(L, b->p.c, pc_pages_screen(&b->p, &m));
}

static int l_cls(lua_State *L) { return pcl_drawn(L, pc_cls(canvas(L))); }

static const pcl_arg color_args[] = {COLOR("fg"), COLOR("bg"), PCL_END};
PCL_BODY(l_color, a) {
    pc_canvas *c = canvas(L);
    if (!a[0].present && !a[1].present) return pcl_push_results(L, 0, "i i", c->fg, c->bg);   /* query */
    return pcl_check_canvas(L, c, pc_color(c, a[0].present ? (int)a[0].x : c->fg, (int)a[1].x));
}

static const pcl_arg palette_args[] = {
    {.name = "attribute", .kind = PCL_ANY, .read = pcl_read_attr, .dim = 1, .expect = "an attribute of the screen"},
    A_ANY("colour", read_rgb, "65536*blue + 256*green + red (each 0..63), \"#rrggbb\" or {r, g, b}"), PCL_END};
static int l_palette(lua_State *L) {
    pc_canvas *c = canvas(L);
    if (lua_isnone(L, 1)) return pcl_check_canvas(L, c, pc_palette_reset(c));
    pcl_val a[2] = {0};
    PCL_READ(L, a);
    pc_rgb rgb = {(uint8_t)a[1].v[0], (uint8_t)a[1].v[1], (uint8_t)a[1].v[2]};
    return pcl_check_canvas(L, c, pc_pages_palette(&box_at(L, PCL_UPVALUE(1))->p, (int)a[0].x, rgb));
}

static const pcl_arg dot_args[] = {A_X("x"), A_NUM("y"), COLOR("colour"), PCL_END};
static int dot(lua_State *L, int (*fn)(pc_canvas *, double, double, int)) {
    pcl_val a[3];   /* PCL_READ_PAIRS sets what it reads: no 576 bytes zeroed per pixel */
    PCL_READ_PAIRS(L, a);
    pc_canvas *c = stmt_canvas(L, &a[2]);
    return pcl_check_canvas(L, c, fn(c, a[0].x, a[1].x, (int)a[2].x));
}

/* LINE's style: "b" (box) or "bf" (filled box), any case; then QBasic's 16-bit pattern,
 * 0..65535 or a signed INTEGER -32768..-1 (&HAAAA is -21846 in QBasic). */
static const char *const BOX[] = {"b", "B", "bf", "BF", "Bf", "bF", NULL};
#define LINE_TAIL COLOR("colour"), \
    {.name = "style", .kind = PCL_ENUM, .flags = PCL_OPT, .choices = BOX, .expect = "\"b\" (box) or \"bf\" (filled box)"}, \
    {.name = "line style", .kind = PCL_INTEGER, .flags = PCL_OPT | PCL_RANGE, .lo = -32768, .hi = 65535, \
     .expect = "a 16-bit pattern -32768..65535"}, PCL_END
static const pcl_arg line_args[] = {A_X("start x"), A_NUM("start y"), A_X("end x"), A_NUM("end y"), LINE_TAIL};
static const pcl_arg line_to_args[] = {A_X("end x"), A_NUM("end y"), LINE_TAIL};

/* ---- 3-D points into the camera's scene (pcl_draw.h): hidden behind its surfaces at write -- */

/* A 3-D point at stack index idx, or 0. */
static int point3(lua_State *L, int idx, double x[3]) {
    pcl_value *p = pcl_tovalue(L, idx);
    if (!p || p->n != 3 || fabs(p->h[3] - 1) > PC_WEIGHT_TOL) return 0;
    for (int k = 0; k < 3; k++) x[k] = p->h[k] / p->h[3];
    return 1;
}

/* The colour argument #k of a statement with 3-D points, read as its declaration a says. */
static int scene_color(lua_State *L, int k, const pcl_arg *a) {
    pcl_val v = {0};
    pcl_readone(L, k, k, 0, a, 0, &v);
    return (int)v.x;
}

/* pset(P [, colour]) with a 3-D point and a scene: the dot joins the scene. */
static int l_pset(lua_State *L) {
    double x[3];
    pc_scene *sc = lua_type(L, 1) != LUA_TNUMBER && point3(L, 1, x) ? pcl_scene(L) : NULL;
    if (sc) return pcl_check(L, pc_scene_add_dot(sc, x, scene_color(L, 2, &dot_args[2])), NULL);
    return dot(L, pc_pset);
}

static int l_preset(lua_State *L) { return dot(L, pc_preset); }

static int draw_line(lua_State *L, pc_canvas *c, double x1, double y1, const pcl_val *a) {
    int box = !a[3].present ? 0 : a[3].n < 2 ? 1 : 2;
    long pattern = a[4].present ? (long)a[4].x & 0xffff : -1;
    return pcl_check_canvas(L, c, pc_line_stmt(c, x1, y1, a[0].x, a[1].x, (int)a[2].x, box, pattern));
}

/* line(A, B [, colour]) with 3-D points and a scene: the segment joins the scene. */
static int l_line(lua_State *L) {
    double ab[6];
    pc_scene *sc = point3(L, 1, ab) && point3(L, 2, ab + 3) ? pcl_scene(L) : NULL;
    if (sc)
        return pcl_check(L, pc_scene_add_polyline(sc, 2, ab, NULL, scene_color(L, 3, &line_args[4]),
                                                  pcl_active_canvas(L)->pen), NULL);
    pcl_val a[7];
    PCL_READ_PAIRS(L, a);
    return draw_line(L, stmt_canvas(L, &a[4]), a[0].x, a[1].x, a + 2);
}

/* LINE -(x, y): from the graphics cursor (the last point referenced). */
PCL_PAIRS_BODY(l_line_to, a) {
    pc_canvas *c = stmt_canvas(L, &a[2]);
    return draw_line(L, c, c->last_x, c->last_y, a);
}

static int l_last_point(lua_State *L) {
    pc_canvas *c = canvas(L);
    return pcl_push_results(L, 0, "n n", c->last_x, c->last_y);
}

#define ANGLE(nm) OPTNUM(nm, PCL_RANGE, -2 * M_PI - 1e-6, 2 * M_PI + 1e-6, "a number between -2*pi and 2*pi")
static const pcl_arg circle_args[] = {A_X("x"), A_NUM("y"),
    {.name = "radius", .kind = PCL_NUMBER, .flags = PCL_RANGE, .lo = 0, .hi = HUGE_VAL, .expect = "a non-negative number"},
    COLOR("colour"), ANGLE("start angle"), ANGLE("end angle"), OPTNUM("aspect", PCL_POS, 0, 0, NULL), PCL_END};
PCL_PAIRS_BODY(l_circle, a) {
    pc_canvas *c = stmt_canvas(L, &a[3]);
    return pcl_check_canvas(L, c, pc_circle(c, a[0].x, a[1].x, a[2].x, (int)a[3].x, a[4].x, a[5].x, a[6].x));
}

static const pcl_arg paint_args[] = {A_X("x"), A_NUM("y"), COLOR("colour"), COLOR("border colour"), PCL_END};
PCL_PAIRS_BODY(l_paint, a) {
    return pcl_drawn(L, pc_paint(canvas(L), a[0].x, a[1].x, (int)a[2].x, (int)a[3].x));
}

static const pcl_arg point_args[] = {A_X("x"), A_NUM("y"), PCL_END};
PCL_PAIRS_BODY(l_point, a) {
    return pcl_push_results(L, 0, "i", pc_point(canvas(L), a[0].x, a[1].x));
}

static const pcl_arg window_args[] = {A_X("first corner x"), A_NUM("first corner y"), A_X("second corner x"),
                                      A_NUM("second corner y"), SCREEN_FLAG, PCL_END};
static const pcl_arg view_args[] = {A_X("first corner x"), A_NUM("first corner y"), A_X("second corner x"),
                                    A_NUM("second corner y"), COLOR("fill"), COLOR("border"), SCREEN_FLAG, PCL_END};
/* window and view, by the name called; no argument resets */
static int l_window(lua_State *L) {
    pc_canvas *c = canvas(L);
    int view = pcl_name(L)[0] == 'v';
    if (lua_isnone(L, 1)) return view ? pcl_check_canvas(L, c, pc_view_reset(c)) : (pc_window_reset(c), 0);
    pcl_val a[7];   /* PCL_READ_PAIRS sets what it reads */
    PCL_READ_PAIRS(L, a);
    if (!view) return pcl_check_canvas(L, c, pc_window(c, a[0].x, a[1].x, a[2].x, a[3].x, (int)a[4].x));
    return pcl_check_canvas(L, c, pc_view_at(c, a[0].x, a[1].x, a[2].x, a[3].x, (int)a[4].x, (int)a[5].x, (int)a[6].x));
}

static const char *const THEMES[] = {"paper", "screen", NULL};
static const pcl_arg save_args[] = {{.name = "path", .kind = PCL_STRING, .expect = "a file name"},
                                    {.name = "theme", .kind = PCL_ENUM, .flags = PCL_OPT, .choices = THEMES}, PCL_END};
PCL_BODY(l_save, a) {
    pc_canvas *c = canvas(L);
    pc_theme theme = !a[1].present ? pcl_theme(L) : a[1].n == 0 ? PC_THEME_PAPER : PC_THEME_SCREEN;
    if (pc_format_from_path(a[0].s) == PC_FMT_UNKNOWN)
        return pcl_argfail(L, 1, "must be a file name ending in .png, .svg, .ppm, .pdf, .eps or .ps, got \"%s\"", a[0].s);
    char err[512];
    if (pc_write_file(c, a[0].s, theme, err, sizeof err) != PC_OK) return pcl_fail(L, "%s", err);
    pc_canvas_mark_saved(c);
    return 0;
}

static int l_size(lua_State *L) {
    pc_canvas *c = canvas(L);
    return pcl_push_results(L, 0, "i i i", c->width, c->height, c->ncolors);
}

/* ---- beyond QBasic: pen, path, label, text ------------------------------------------------ */

/* A pen's width: pixels 1..256, or a length with its unit (out->n = 1: the print pen). */
static int read_pen_width(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    if (lua_type(L, idx) == LUA_TSTRING) return (out->n = 1), pcl_read_length(L, idx, a, out);
    out->x = lua_tonumber(L, idx);
    return lua_type(L, idx) == LUA_TNUMBER && out->x >= 1 && out->x <= PC_PEN_MAXWIDTH;
}

/* A dash pattern: on, off lengths (an even number, at most 16), pixels or lengths with units
 * (out->n = 1), into out->v; out->dim the count. */
static int read_dash(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    lua_Integer n = lua_istable(L, idx) ? luaL_len(L, idx) : -1;
    if (n < 0 || n > PC_PEN_MAXDASH || n % 2) return 0;
    out->dim = (int)n;
    for (int i = 0; i < n; i++) {
        int t = lua_geti(L, idx, i + 1);
        pcl_val len = {0};
        if (i == 0) out->n = t == LUA_TSTRING;
        if (out->n ? !pcl_read_length(L, lua_gettop(L), a, &len) : (len.x = lua_tonumber(L, -1),
            t != LUA_TNUMBER || !(len.x >= 1e-6 && len.x <= 1e6)))
            return pcl_readfail(L, lua_gettop(L), out->n ? "a length with its unit such as \"3mm\""
                                                         : "a positive number (pixels)");
        out->v[i] = len.x;
        lua_pop(L, 1);
    }
    return 1;
}

static const pcl_arg pen_keys[] = {
    {.name = "width", .kind = PCL_ANY, .read = read_pen_width, .expect = "a number 1..256 (pixels) or a length such as \"0.5mm\""},
    {.name = "dash", .kind = PCL_ANY, .read = read_dash, .expect = "a list of on, off lengths (an even number, at most 16)"},
    PCL_END};
static const pcl_arg pen_table = {.name = "pen", .kind = PCL_OPTIONS, .keys = pen_keys};
static const pcl_arg pen_args[] = {
    {.name = "pen", .kind = PCL_ANY, .flags = PCL_OPT,
     .expect = "a table {width =, dash =} or a pen's name (\"main\", \"thin\", \"hidden\", \"centre\")"}, PCL_END};

static int l_pen(lua_State *L) {
    pcl_val a[3] = {0};   /* pen; the table's width, dash */
    PCL_READ(L, a);
    pc_canvas *c = canvas(L);
    if (!a[0].present) return pc_pen_reset(c), 0;
    if (lua_type(L, 1) == LUA_TSTRING) return pcl_check_canvas(L, c, pc_pen_named(c, lua_tostring(L, 1)));
    if (!lua_istable(L, 1)) return pcl_argfail(L, 1, "must be %s, got %s", pen_args[0].expect, pcl_shown(L, 1));
    pcl_read_options(L, 1, 1, &pen_table, a + 1);
    pc_pen_opts o = {a[1].present, a[1].present && a[1].n, a[2].present, a[2].present && a[2].n, a[2].dim,
                     a[1].x, a[2].v};
    return pcl_check_canvas(L, c, pc_pen_options(c, &o));
}

/* The point at the stack top, element [j] (k > 0: [k][j]) of the points argument at idx: a
 * 2-D point, or an n-D one with a camera for n-D points set. */
static void list_point(lua_State *L, int idx, int k, int j, double *xy) {
    pcl_value *p = pcl_tovalue(L, -1);
    char why[200];
    int value = lua_gettop(L), placed = !p || pc_place_why(pcl_camera(L), p->n, p->h, xy, why, sizeof why) == PC_OK;
    if (placed && pcl_topoint2(L, value, xy, xy + 1)) return;
    const char *where = k ? lua_pushfstring(L, "[%d][%d]", k, j) : lua_pushfstring(L, "[%d]", j);
    if (!placed)
        pcl_fail(L, "argument #%d (points) %s%s", idx, where, lua_pushfstring(L, why, luaL_tolstring(L, value, NULL)));
    pcl_fail(L, "argument #%d (points) %s must be a 2-D point, got %s", idx, where, pcl_shown(L, value));
}

/* Subpath k of the points at idx pushed (nested: a list of lists), or the list itself: its
 * stack index. */
static int subpath(lua_State *L, int idx, lua_Integer k, int nested) {
    static const char nested_text[] = "a list of 2-D points or a list of such lists";
    if (!nested)
        lua_pushvalue(L, idx);
    else if (lua_geti(L, idx, k) != LUA_TTABLE)
        pcl_fail(L, "argument #%d (points) [%d] must be %s, got %s", idx, (int)k, nested_text, pcl_shown(L, -1));
    else if (luaL_len(L, -1) < 1)
        pcl_fail(L, "argument #%d (points) [%d] must be %s, got an empty list", idx, (int)k, nested_text);
    return lua_gettop(L);
}

/* The points of path and fill: a list of 2-D points (one subpath) or a list of such lists
 * (one subpath each).  The coordinates (out->list) and the verbs (out->obj: a move at the start
 * of each subpath, lines after) go to scratch userdata above the arguments; out->n points.  One
 * path of 3-D points (out->dim 1) has their xyz after the places, for the scene (l_path). */
static int read_subpaths(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    if (!lua_istable(L, idx)) return 0;
    lua_Integer m = luaL_len(L, idx);
    if (m < 1) return pcl_readfail(L, idx, "a list of at least one point");
    int nested = lua_geti(L, idx, 1) == LUA_TTABLE;
    lua_pop(L, 1);
    size_t n = 0;
    for (lua_Integer k = 1; k <= (nested ? m : 1); k++) {   /* count the points of the subpaths */
        n += (size_t)luaL_len(L, subpath(L, idx, k, nested));
        lua_pop(L, 1);
    }
    if (n > 100000000) pcl_fail(L, "argument #%d (points) holds too many points", idx);
    double *xy = lua_newuserdatauv(L, n * 5 * sizeof *xy, 0);   /* freed by the GC */
    uint8_t *verbs = lua_newuserdatauv(L, n, 0);
    size_t i = 0;
    int all3 = !nested;   /* one path of 3-D points: also their xyz after the places (scenes) */
    for (lua_Integer k = 1; k <= (nested ? m : 1); k++) {
        int list = subpath(L, idx, k, nested);
        for (lua_Integer j = 1, len = luaL_len(L, list); j <= len; j++, i++) {
            lua_geti(L, list, j);
            list_point(L, idx, nested ? (int)k : 0, (int)j, &xy[2 * i]);
            all3 = all3 && point3(L, -1, &xy[2 * n + 3 * i]);
            verbs[i] = j == 1 ? PC_PATH_MOVE : PC_PATH_LINE;
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    out->list = xy, out->obj = verbs, out->n = (int)n, out->dim = all3;
    return 1;
}

static const char *const RULES[] = {"evenodd", "nonzero", NULL};
#define POINTS {.name = "points", .kind = PCL_ANY, .read = read_subpaths, .expect = "a list of 2-D points"}
#define RULE(nm) {.name = nm, .kind = PCL_ENUM, .flags = PCL_OPT, .choices = RULES}
static const char *const HEADS[] = {"none", "end", "start", "both", NULL};   /* PC_ARROW_* bits */
static const pcl_arg path_keys[] = {{.name = "closed", .kind = PCL_BOOLEAN}, COLOR("color"), COLOR("fill"),
                                    RULE("rule"), {.name = "arrow", .kind = PCL_ENUM, .choices = HEADS}, PCL_END};
static const pcl_arg path_args[] = {POINTS, A_OPTIONS("options", path_keys), PCL_END};

/* path(points, ...): with 3-D points of one path, no fill and a scene, the polyline and its
 * heads (PC_ARROW_* bits) join the scene. */
PCL_BODY(l_path, a) {   /* points, options; closed, color, fill, rule, arrow */
    int closed = (int)a[2].x, color = (int)a[3].x, heads = a[6].n;
    size_t n = (size_t)a[0].n;
    pc_scene *sc = a[0].dim && !a[4].present ? pcl_scene(L) : NULL;
    pc_canvas *c = canvas(L);
    if (sc) return pcl_check(L, pc_scene_add_path(sc, n, a[0].list + 2 * n, closed, heads, color, c->pen), NULL);
    int rule = a[5].n ? PC_FILL_NONZERO : PC_FILL_EVENODD;
    return pcl_check_canvas(L, c, pc_path_stmt(c, n, a[0].list, a[0].obj, closed, color, heads,
                                               a[4].present, (int)a[4].x, rule));
}

static const pcl_arg fill_args[] = {POINTS, COLOR("colour"), RULE("rule"), PCL_END};
PCL_BODY(l_fill, a) {
    size_t n = (size_t)a[0].n;
    int rule = a[2].n ? PC_FILL_NONZERO : PC_FILL_EVENODD;
    return pcl_drawn(L, pc_fill_path(canvas(L), n, a[0].list, a[0].obj, n, rule, (int)a[1].x));
}

static const char *const DIRECTIONS[] = {"c", "n", "ne", "e", "se", "s", "sw", "w", "nw", NULL};
static const pcl_arg label_args[] = {TEXT, A_X("x"), A_NUM("y"),
    {.name = "direction", .kind = PCL_ENUM, .flags = PCL_OPT, .choices = DIRECTIONS, .dflt = PC_ANCHOR_NE,
     .expect = "one of \"n\" \"ne\" \"e\" \"se\" \"s\" \"sw\" \"w\" \"nw\" \"c\""},
    COLOR("colour"), SCALE, A_OPTIONS("options", pcl_label_keys), PCL_END};
/* label(text, P, ...) with a 3-D point and a scene: the label joins the scene, its markup
 * checked now, as a 2-D label's is, and shown only where its point is seen. */
PCL_PAIRS_BODY(l_label, a) {   /* text, x, y, direction, colour, scale, options; font, size, halo */
    int anchor = a[3].present ? a[3].n : PC_ANCHOR_AUTO;
    double x[3];
    pc_scene *sc = point3(L, 2, x) ? pcl_scene(L) : NULL;
    if (sc) {
        char err[200];
        if (pc_math_check(a[0].s, err, sizeof err) != PC_OK) return pcl_fail(L, "%s", err);
        int st = pc_scene_add_label(sc, x, a[0].s, anchor, (int)a[5].x, (int)a[4].x);
        if (st == PC_OK && a[6].present)   /* {font, size, halo}: kept with the label till it is drawn */
            st = pc_scene_style_label(sc, a[7].s, a[8].x, a[9].present ? (int)a[9].x : -1);
        return pcl_check(L, st, NULL);
    }
    pc_canvas *c = canvas(L);
    pcl_check_canvas(L, c, pc_text(c, a[1].x, a[2].x, a[0].s, anchor, 3, (int)a[5].x, (int)a[4].x));
    if (a[6].present) pcl_label_style(L, c, a + 7);
    return 0;
}

/* text(x, y, s ...), or text{x =, y =, text =, units =, color =, scale =}: (x, y) in screen
 * pixels with units = "device", whatever the window. */
static const char *const UNITS[] = {"world", "device", NULL};
static const pcl_arg text_keys[] = {
    {.name = "x", .kind = PCL_NUMBER, .flags = PCL_REQ}, {.name = "y", .kind = PCL_NUMBER, .flags = PCL_REQ},
    {.name = "text", .kind = PCL_STRING, .flags = PCL_REQ},
    {.name = "color", .kind = PCL_ANY, .flags = PCL_OPT, .read = pcl_read_color, .dflt = -1, .dim = 1}, SCALE,
    {.name = "units", .kind = PCL_ENUM, .choices = UNITS}, PCL_END};
static const pcl_arg text_table = {.name = "options", .kind = PCL_OPTIONS, .keys = text_keys};
static const pcl_arg text_args[] = {A_X("x"), A_NUM("y"), TEXT, COLOR("colour"), SCALE, PCL_END};
static int l_text(lua_State *L) {
    pc_canvas *c = canvas(L);
    pcl_val a[6] = {0};   /* x, y, text, colour, scale; the table's units */
    if (lua_istable(L, 1)) pcl_read_options(L, 1, 1, &text_table, a);
    else PCL_READ_PAIRS(L, a);
    if (a[5].n == 1) return pcl_check_canvas(L, c, pc_text_device(c, a[0].x, a[1].x, a[2].s, (int)a[4].x, (int)a[3].x));
    return pcl_check_canvas(L, c, pc_text(c, a[0].x, a[1].x, a[2].s, PC_ANCHOR_SE, 0, (int)a[4].x, (int)a[3].x));
}

static int canvas_gc(lua_State *L) {
    canvas_box *b = genuine_box(L, 1);
    if (!b) return 0;   /* never a forged one */
    pc_pages_free(&b->p);
    memset(b, 0, sizeof *b);
    return 0;
}

static const pcl_fn fns[] = {
    {.name = "screen", .fn = l_screen, .args = screen_args, .sig = "screen(12) | screen(13) | screen(1|2|7|9)\nscreen{width=W, height=H [, colors=2|4|16|256]}", .help = "A new blank canvas: 640x480x16 (12), 320x200x256 (13), QBasic's other modes (mode_info) or any size."},
    {.name = "cls", .fn = l_cls, .args = NULL, .sig = "cls()", .help = "Clear the view to the background colour."},
    {.name = "color", .fn = l_color, .args = color_args, .sig = "color(fg [, bg])\ncolor() -> fg, bg", .help = "Set the drawing colour (and the background used by cls), or read both."},
    {.name = "palette", .fn = l_palette, .args = palette_args, .sig = "palette(attr, colour)\npalette()", .help = "Change what a colour number looks like (65536*b + 256*g + r in 0..63, \"#rrggbb\" or {r, g, b}); no argument restores the default."},
    {.name = "pset", .fn = l_pset, .args = dot_args, .sig = "pset(x, y [, c]) | pset(A [, c])", .help = "Plot one pixel in colour c (default: the drawing colour)."},
    {.name = "preset", .fn = l_preset, .args = dot_args, .sig = "preset(x, y [, c]) | preset(A [, c])", .help = "Plot one pixel in colour c (default: the background: erases)."},
    {.name = "line", .fn = l_line, .args = line_args, .sig = "line(x1, y1, x2, y2 [, c [, \"b\"|\"bf\"]]) | line(A, B [, c [, style]])", .help = "A segment, or with \"b\" the outline of a box, with \"bf\" a filled box."},
    {.name = "line_to", .fn = l_line_to, .args = line_to_args, .sig = "line_to(x, y [, c [, \"b\"|\"bf\"]]) | line_to(B [, c [, style]])", .help = "A segment from the last point referenced to (x, y): QBasic's LINE -(x, y)."},
    {.name = "circle", .fn = l_circle, .args = circle_args, .sig = "circle(x, y, r [, c [, start, end [, aspect]]]) | circle(A, r, ...)", .help = "A circle, an ellipse (aspect) or an arc (angles in radians; a negative angle also draws that radius)."},
    {.name = "paint", .fn = l_paint, .args = paint_args, .sig = "paint(x, y [, c [, border]]) | paint(A [, c [, border]])", .help = "Flood-fill from (x, y) up to pixels of the border colour (default: the paint colour)."},
    {.name = "point", .fn = l_point, .args = point_args, .sig = "point(x, y) -> colour | point(A) -> colour", .help = "The colour number at (x, y), or -1 outside the view."},
    {.name = "window", .fn = l_window, .args = window_args, .sig = "window(x1, y1, x2, y2 [, \"screen\"])\nwindow()", .help = "World coordinates: (x1, y1)-(x2, y2) fill the view, y up (y down with \"screen\"); no argument: pixels again."},
    {.name = "view", .fn = l_window, .args = view_args, .sig = "view(x1, y1, x2, y2 [, fill [, border [, \"screen\"]]])\nview()", .help = "A viewport in pixels: drawing is clipped to it and, without \"screen\", relative to it."},
    {.name = "save", .fn = l_save, .args = save_args, .sig = "save(path [, \"paper\"|\"screen\"])", .help = "Write the canvas: PNG, SVG, PPM, PDF, EPS or PS by the extension, atomically; \"paper\" prints dark ink on white; PDF, EPS and PS (and PNG, SVG after figure{}) in the print look."},
    {.name = "size", .fn = l_size, .args = NULL, .sig = "size() -> width, height, colours", .help = "The size of the canvas and its number of colours."},
    {.name = "last_point", .fn = l_last_point, .args = NULL, .sig = "last_point() -> x, y", .help = "The graphics cursor: the last point referenced, in world coordinates."},
    {.name = "pen", .fn = l_pen, .args = pen_args, .sig = "pen{width = w, dash = {on, off, ...}}\npen{width = \"0.5mm\", dash = {\"3mm\", \"1.5mm\"}}\npen \"main\"|\"thin\"|\"hidden\"|\"centre\"\npen()", .help = "The pen of lines, boxes, circles and paths: width in pixels or a length with its unit (cm, mm, in, pt, px) and a dash pattern, or a named engineering pen (main 0.5 mm, thin 0.25 mm, hidden dashed, centre chain); pen() restores the default."},
    {.name = "path", .fn = l_path, .args = path_args, .sig = "path(points [, {closed = false, color = c, fill = c, rule = \"evenodd\"|\"nonzero\", arrow = \"end\"|\"start\"|\"both\"}])", .help = "A polyline through the points (or a list of lists: one subpath each) as one path (SVG keeps it a <path>); with fill, the closed path filled, its outline drawn on top only if color is given; arrow puts filled heads on its last and/or first segment."},
    {.name = "fill", .fn = l_fill, .args = fill_args, .sig = "fill(points [, colour [, \"evenodd\"|\"nonzero\"]])", .help = "Fill the closed path through the points (or a list of lists: subpaths; even-odd by default, so a subpath inside another is a hole): the pixels whose centres are inside, shared edges covered once; a filled <path> in SVG."},
    {.name = "label", .fn = l_label, .args = label_args, .sig = "label(text, P | x, y [, direction [, colour [, scale]]] [, {font =, size =, halo =}])", .help = "Text beside a point: direction \"n\", \"ne\", \"e\", \"se\", \"s\", \"sw\", \"w\", \"nw\" or \"c\", 3 px away; without one (or nil) it is placed when the picture is written, clear of other labels, lines and the edge; $...$ is math ($A_1$, $\\varphi$, $\\bar{t}$); the VGA 8x16 font in the VGA look, the figure's font (size in pt, a halo unless halo = false) in the print look."},
    {.name = "text", .fn = l_text, .args = text_args, .sig = "text(x, y, string [, colour [, scale]])\ntext{x =, y =, text =, units = \"world\"|\"device\", color =, scale =}", .help = "Text with the top-left corner of its first 8x16 cell at (x, y); units = \"device\" takes (x, y) in screen pixels whatever the window."},
    PCL_END};

void pcl_open_draw(lua_State *L) {
    /* one canvas per Lua state: reuse it if the module is opened twice */
    lua_getfield(L, LUA_REGISTRYINDEX, CANVAS_KEY);
    if (lua_isnil(L, -1)) {
        lua_pop(L, 1);
        luaL_newmetatable(L, CANVAS_MT);
        luaL_setfuncs(L, (const luaL_Reg[]){{"__gc", canvas_gc}, {NULL, NULL}}, 0);
        lua_pop(L, 1);
        canvas_box *b = pcl_tagged_new(L, sizeof *b, &CANVAS_TAG, CANVAS_MT);   /* __gc-safe */
        if (pc_pages_init(&b->p) != PC_OK) pcl_error(L, "pointcalc: out of memory for the canvas");
        lua_pushvalue(L, -1);
        lua_setfield(L, LUA_REGISTRYINDEX, CANVAS_KEY);
    }
    pcl_register(L, -2, fns, 1);
}
