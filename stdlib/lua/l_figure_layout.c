/* Binding of the figure layout and its furniture (stdlib/draw/layout.h, furniture.h, axes.h),
 * on the declared argument layer (pcl_args.h, docs/bindings.md): placed_labels, mark, arrow,
 * vector, dimension, angle_mark, ticks, hatch, centre_line, fit, caption, axes, graph, legend
 * and map.view.  Points are 2-D, or n-D through the camera; sizes are screen pixels. */
#include "pcl_draw.h"
#include "layout.h"
#include "furniture.h"
#include "axes.h"
#include "view.h"

/* ---- the readers: a place (a 2-D point, or n-D through the camera), a colour ------------- */

/* v[0], v[1]: the 2-D place; a 3-D point also keeps its coordinates in v[2..4] (n = 3). */
static int read_xy(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    pcl_value *p = pcl_tovalue(L, idx);
    if (!p || fabs(p->h[p->n] - 1) > PC_WEIGHT_TOL) return 0;
    out->n = p->n;
    for (int k = 0; k < 3 && p->n == 3; k++) out->v[2 + k] = p->h[k] / p->h[3];
    return pc_place_xy(pcl_camera(L), p->n, p->h, &out->v[0], &out->v[1]) == PC_OK;
}
#define A_XY(nm) {.name = nm, .kind = PCL_ANY, .read = read_xy, .expect = PCL_PLACE_TEXT}

/* a colour, true colours (256..) included */
#define A_COLOR(nm) {.name = nm, .kind = PCL_ANY, .flags = PCL_OPT, .read = pcl_read_color, .dflt = -1, .dim = 1}

#define A_OPTNUM(nm, a, b, d, txt) {.name = nm, .kind = PCL_NUMBER, .flags = PCL_OPT | PCL_RANGE, \
                                    .lo = a, .hi = b, .dflt = d, .shown = txt}
#define A_OPTENUM(nm, ch, d) {.name = nm, .kind = PCL_ENUM, .flags = PCL_OPT, .choices = ch, .dflt = d}
#define A_OPTSTR(nm) {.name = nm, .kind = PCL_STRING, .flags = PCL_OPT}

/* ---- placed labels ---------------------------------------------------------------------- */

static int l_placed_labels(lua_State *L) {
    size_t n;
    pc_placed *p = pc_placed_labels(pcl_active_canvas(L), &n);
    if (!p) return pcl_fail(L, "out of memory");
    lua_createtable(L, (int)n, 0);
    for (size_t k = 0; k < n; k++) {
        const pc_box2 *b = &p[k].box;
        pcl_push_results(L, 0, "text=s x=n y=n w=n h=n side=s auto=b", p[k].text, b->x0, b->y0, b->x1 - b->x0,
                         b->y1 - b->y0, p[k].side, p[k].autoplaced);
        lua_rawseti(L, -2, (lua_Integer)k + 1);
    }
    free(p);
    return 1;
}

/* ---- markers, arrows, furniture -------------------------------------------------------------- */

static const char *const STYLES[] = {"dot", "open", "cross", "plus", "square", NULL};
static const pcl_arg mark_args[] = {A_XY("P"), A_OPTENUM("style", STYLES, 0),
                                    A_OPTNUM("size", 1, 200, 5, "5"), A_COLOR("colour"), PCL_END};
PCL_BODY(l_mark, a) {
    pc_scene *sc = a[0].n == 3 ? pcl_scene(L) : NULL;
    if (sc) return pcl_check(L, pc_scene_add_mark(sc, a[0].v + 2, a[1].n, a[2].x, (int)a[3].x), NULL);
    return pcl_drawn(L, pc_mark(pcl_active_canvas(L), a[0].v[0], a[0].v[1], a[1].n, a[2].x, (int)a[3].x));
}

/* vector(A, v [, colour]): the arrow from A to A + v (the sum taken as a script would). */
static const pcl_arg vector_args[] = {A_XY("A"), {.name = "v", .kind = PCL_VECTOR}, A_COLOR("colour"), PCL_END};
PCL_BODY(l_vector, a) {
    pcl_val end = {0};
    lua_pushvalue(L, 1);
    lua_pushvalue(L, 2);
    lua_arith(L, LUA_OPADD);
    if (!read_xy(L, lua_gettop(L), NULL, &end)) return pcl_argfail(L, 2, "must have A's dimension");
    return pcl_drawn(L, pc_arrow(pcl_active_canvas(L), a[0].v[0], a[0].v[1], end.v[0], end.v[1], PC_ARROW_END, 9,
                                 (int)a[2].x));
}

static const pcl_arg hatch_args[] = {A_POINTS("points", 0, 3, 0), A_OPTNUM("spacing", 1, 1e4, 8, "8"),
                                     A_OPTNUM("angle", -1e6, 1e6, 45, "45"), A_COLOR("colour"), PCL_END};
PCL_BODY(l_hatch, a) {
    const double *xy = pcl_places(L, &a[0], "argument #1 (points)");
    size_t lines;
    return pcl_drawn(L, pc_hatch(pcl_active_canvas(L), (size_t)a[0].n, xy, a[1].x, a[2].x, (int)a[3].x, &lines));
}

static const char *const HEADS[] = {"none", "end", "start", "both", NULL};
static const pcl_arg arrow_args[] = {A_XY("A"), A_XY("B"), A_OPTENUM("heads", HEADS, 1), A_COLOR("colour"), PCL_END};
static const pcl_arg dim_args[] = {A_XY("A"), A_XY("B"), A_OPTNUM("offset", -1e5, 1e5, 20, "20"),
                                   A_OPTSTR("text"), A_COLOR("colour"), PCL_END};
static const pcl_arg angle_args[] = {A_XY("A"), A_XY("O"), A_XY("B"), A_OPTSTR("text"),
                                     A_OPTNUM("radius", 2, 1000, 24, "24"), A_COLOR("colour"), PCL_END};
static const pcl_arg ticks_args[] = {A_XY("A"), A_XY("B"),
                                     {.name = "n", .kind = PCL_INTEGER, .flags = PCL_OPT | PCL_RANGE, .lo = 1, .hi = 5, .dflt = 1, .shown = "1"},
                                     A_COLOR("colour"), PCL_END};
static const pcl_arg centre_args[] = {A_XY("A"), A_XY("B"), A_OPTNUM("extend", 0, 1e5, 10, "10"),
                                      A_COLOR("colour"), PCL_END};
/* arrow, dimension, angle_mark, ticks, centre_line: one body, the kind by the name called; the
 * slots of the declared size, text (-1: none) and colour after the points */
static const struct { int points, size, text, color; } FURNITURE[] = {
    [PC_FURN_ARROW] = {2, 2, -1, 3}, [PC_FURN_DIMENSION] = {2, 2, 3, 4}, [PC_FURN_ANGLE] = {3, 4, 3, 5},
    [PC_FURN_TICKS] = {2, 2, -1, 3}, [PC_FURN_CENTRE] = {2, 2, -1, 3}};
PCL_BODY(l_furniture, a) {
    pc_furniture_kind kind = pc_furniture_kind_of(pcl_name(L));
    int size = FURNITURE[kind].size, text = FURNITURE[kind].text;
    double xy[6], measure;
    for (int i = 0; i < FURNITURE[kind].points; i++) memcpy(xy + 2 * i, a[i].v, 2 * sizeof *xy);
    pcl_drawn(L, pc_furniture(pcl_active_canvas(L), kind, xy, kind == PC_FURN_ARROW ? a[size].n : a[size].x,
                              text < 0 ? NULL : a[text].s, (int)a[FURNITURE[kind].color].x, &measure));
    return text < 0 ? 0 : pcl_push_results(L, 0, "n", measure);
}

/* ---- framing, captions, device-unit text -------------------------------------------------- */

static const char *const ASPECTS[] = {"equal", "fill", NULL};
static const pcl_arg fit_keys[] = {A_OPTNUM("margin", 0, 1e5, 10, "10"), A_OPTENUM("aspect", ASPECTS, 0),
                                   {.name = "around", .kind = PCL_POINTS, .flags = PCL_OPT, .lo = 1},
                                   A_OPTNUM("pad", 0, 1e300, 0, "0"), A_OPTNUM("band", 0, 1e5, 0, "0"), PCL_END};
static const pcl_arg fit_args[] = {{.name = "options", .kind = PCL_OPTIONS, .flags = PCL_OPT | PCL_CALLTABLE, .keys = fit_keys}, PCL_END};
PCL_BODY(l_fit, a) {   /* options; margin, aspect, around, pad, band */
    const double *xy = pcl_places(L, &a[3], "option 'around'");
    pc_fit_opts o = {a[1].present, a[4].present, a[5].present, a[3].present, a[2].n,
                     a[1].x, a[4].x, a[5].x, (size_t)a[3].n, xy};
    return pcl_drawn(L, pc_fit_options(pcl_active_canvas(L), &o));
}

static const char *const EDGES[] = {"bottom", "top", NULL};
static const pcl_arg caption_args[] = {{.name = "text", .kind = PCL_STRING}, A_OPTENUM("where", EDGES, 0),
                                       A_COLOR("colour"), PCL_END};
PCL_BODY(l_caption, a) {
    return pcl_drawn(L, pc_caption(pcl_active_canvas(L), a[0].s, a[1].n, (int)a[2].x));
}

/* ---- axes, graphs, legends ------------------------------------------------------------------ */

static const pcl_arg axes_keys[] = {A_NUMBERS("x", 2, 2), A_NUMBERS("y", 2, 2), A_XY("origin"),
                                    {.name = "ticks", .kind = PCL_INTEGER, .flags = PCL_OPT | PCL_RANGE, .lo = 0, .hi = 100, .dflt = 5},
                                    {.name = "labels", .kind = PCL_BOOLEAN, .dflt = 1}, {.name = "arrows", .kind = PCL_BOOLEAN, .dflt = 1},
                                    {.name = "grid", .kind = PCL_BOOLEAN}, A_COLOR("color"), A_COLOR("grid_color"), PCL_END};
static const pcl_arg axes_args[] = {{.name = "options", .kind = PCL_OPTIONS, .flags = PCL_OPT | PCL_CALLTABLE, .keys = axes_keys}, PCL_END};
PCL_BODY(l_axes, a) {   /* options; x, y, origin, ticks, labels, arrows, grid, color, grid_color */
    pc_axes_opts o = {a[1].list, a[2].list, a[3].present ? a[3].v : NULL, (int)a[4].x, (int)a[5].x, (int)a[6].x,
                      (int)a[7].x, (int)a[9].x};
    int n = 0;
    pcl_drawn(L, pc_axes_options(pcl_active_canvas(L), &o, (int)a[8].x, &n));
    return pcl_push_results(L, 0, "i", n);
}

static const pcl_arg graph_keys[] = {A_COLOR("color"), {.name = "n", .kind = PCL_INTEGER, .flags = PCL_OPT | PCL_RANGE, .lo = 1, .hi = 1e6, .dflt = 400}, PCL_END};
static const pcl_arg graph_args[] = {A_FUNCTION("f"), A_NUM("a"), A_NUM("b"), A_OPTIONS("options", graph_keys), PCL_END};
/* f(x), run protected so that the core frees its buffers: an error stays on the stack */
static int graph_y(void *p, double x, double *y, int *have) {
    pcl_luafn *f = p;
    lua_State *L = pcl_current_state();
    lua_pushvalue(L, f->stack);
    lua_pushnumber(L, x);
    if ((f->failed = lua_pcall(L, 1, 1, 0) != LUA_OK)) return PC_EARG;
    *y = lua_tonumberx(L, -1, have);
    lua_pop(L, 1);
    return PC_OK;
}

PCL_BODY(l_graph, a) {
    pc_canvas *c = pcl_active_canvas(L);
    if (!(a[1].x < a[2].x)) return pcl_argfail(L, 3, "must be greater than a");
    pcl_luafn f = pcl_luafn_at(L, a[0].idx);
    int st = pc_graph(c, a[1].x, a[2].x, (int)a[5].x, graph_y, &f, (int)a[4].x);
    return f.failed ? lua_error(L) : pcl_check_canvas(L, c, st);
}

static const char *const CORNERS[] = {"ne", "nw", "se", "sw", NULL};
static const pcl_arg legend_args[] = {{.name = "entries", .kind = PCL_ANY, .expect = "a list of {name, colour}"},
                                      A_OPTENUM("corner", CORNERS, 0), A_COLOR("colour"), PCL_END};
PCL_BODY(l_legend, a) {
    static const int corner_of[] = {PC_ANCHOR_NE, PC_ANCHOR_NW, PC_ANCHOR_SE, PC_ANCHOR_SW};
    pc_canvas *c = pcl_active_canvas(L);
    lua_Integer n = lua_istable(L, 1) ? luaL_len(L, 1) : 0;
    if (n < 1 || n > 100) return pcl_argfail(L, 1, "must be a list of 1 to 100 {name, colour}, got %s", pcl_shown(L, 1));
    luaL_checkstack(L, 2 * (int)n + 8, "too many entries");
    const char **names = lua_newuserdatauv(L, sizeof *names * (size_t)n, 0);
    int *colors = lua_newuserdatauv(L, sizeof *colors * (size_t)n, 0);
    for (lua_Integer i = 1; i <= n; i++) {   /* each name stays on the stack while it is used */
        if (lua_geti(L, 1, i) != LUA_TTABLE || lua_geti(L, -1, 1) != LUA_TSTRING)
            return pcl_argfail(L, 1, "[%d] must be {name, colour}", (int)i);
        names[i - 1] = lua_tostring(L, -1);
        lua_geti(L, -2, 2);
        colors[i - 1] = lua_isnil(L, -1) ? -1 : pcl_color_at(L, -1, c, 1);
        if (colors[i - 1] == -2)
            return pcl_argfail(L, 1, "[%d] must be {name, colour}: its colour must be a colour number or \"#rrggbb\"", (int)i);
        lua_pop(L, 1);
    }
    return pcl_check_canvas(L, c, pc_legend(c, (int)n, names, colors, corner_of[a[1].n], (int)a[2].x));
}

/* ---- map.view ------------------------------------------------------------------------------ */

static const pcl_arg view_keys[] = {A_POINT("from", 3), A_POINT("to", 3), A_VECTOR("up", 3), {.name = "perspective", .kind = PCL_BOOLEAN},
                                    A_NUM("azimuth"), {.name = "elevation", .kind = PCL_NUMBER, .dflt = 30},
                                    {.name = "distance", .kind = PCL_NUMBER, .flags = PCL_POS, .dflt = 10}, PCL_END};
static const pcl_arg view_args[] = {{.name = "options", .kind = PCL_OPTIONS, .flags = PCL_CALLTABLE, .keys = view_keys}, PCL_END};
static const pc_why view_why[] = {{"map.view", PC_ECOINCIDENT, 0, NULL, "from and to coincide: no line of sight"},
                                  {"map.view", PC_EZERO, 0, "up", "is the zero vector"},
                                  {"map.view", PC_ECOLLINEAR, 0, "up", "is along the line of sight; give another up"},
                                  {0}};
PCL_BODY(l_view, a) {   /* options; from, to (absent: cleared, the origin), up, perspective, ... */
    int persp = (int)a[4].x, st;
    pc_map f;
    if (a[1].present) {
        if (!a[2].present) return pcl_keyfail(L, "to", "must be given with from (the point looked at)");
        st = pc_map_view(&f, a[1].v, a[2].v, a[3].present ? a[3].v : NULL, persp);
    } else {
        if (!a[5].present) return pcl_fail(L, "give from and to, or azimuth and elevation");
        st = pc_map_view_azel(&f, a[2].v, a[5].x, a[6].x, a[7].x, persp);
    }
    pcl_check(L, st, view_why);
    *pcl_newmap(L) = f;
    return 1;
}

/* ---- registration ---------------------------------------------------------------------------- */

static const pcl_fn fns[] = {
    PCL_FN("placed_labels", l_placed_labels, NULL, "{{text =, x =, y =, w =, h =, side =, auto =}, ...}", "Where every label goes when the picture is written: its box in screen pixels and its side; auto for the ones placed automatically."),
    PCL_FN("mark", l_mark, mark_args, NULL, "A marker on a point, size pixels across (default a filled dot of 5); a 3-D point joins the camera's scene."),
    PCL_FN("arrow", l_furniture, arrow_args, NULL, "The segment AB with a filled arrow head (9 px) at B, at A or at both."),
    PCL_FN("vector", l_vector, vector_args, NULL, "The vector v drawn as an arrow from the point A to A + v."),
    PCL_FN("dimension", l_furniture, dim_args, "length", "A dimension line of AB offset pixels to its left (negative: right), with extension lines, two heads and the length |AB| in world units (or text)."),
    PCL_FN("angle_mark", l_furniture, angle_args, "angle", "The angle AOB (the smaller one, in radians, measured in world units) marked by an arc of radius pixels, or the square of a right angle, with its degrees (or text)."),
    PCL_FN("ticks", l_furniture, ticks_args, NULL, "n (1..5) equal-length ticks across the middle of segment AB."),
    PCL_FN("hatch", l_hatch, hatch_args, NULL, "Hatch the closed region through the points (even-odd) with lines at angle degrees (ISO 128: 45) spacing pixels apart."),
    PCL_FN("centre_line", l_furniture, centre_args, NULL, "A centre line through A and B, extend pixels beyond each, long dash and dot (ISO 128 type 04)."),
    PCL_FN("fit", l_fit, fit_args, NULL, "Frame what is drawn: everything moved and scaled into the view, margin pixels in, text cells and room for every automatic label included, the 3-D scene through its camera too, at equal units on both axes (or each axis filling the view); markers keep their size; later drawing follows the new frame. fit{around = points, pad = p}: before drawing, the window round the points (n-D through the camera) with p world units more on each side, at equal units at the view's aspect (or the box itself with aspect = \"fill\"), band = px keeping that many pixels free at the bottom for a caption; what is drawn already stays."),
    PCL_FN("caption", l_caption, caption_args, NULL, "Text centred at the bottom (or top) edge of the picture, in device units, so a window cannot move it off."),
    PCL_FN("axes", l_axes, axes_args, "n", "Both axes in world units (default: the window's extent) with ticks at round numbers (1, 2, 5 x 10^k), their labels, an arrow on each and an optional dotted grid; returns the number of ticks."),
    PCL_FN("graph", l_graph, graph_args, NULL, "The graph y = f(x) for x from a to b as a path of n pieces, broken where f gives no finite number."),
    PCL_FN("legend", l_legend, legend_args, NULL, "A legend in a corner of the picture (device units): a line in each entry's colour and its name."),
    PCL_END};
static const pcl_fn view_fn[] = {{.name = "map.view", .fn = l_view, .args = view_args,
                                  .sig = "map.view{from = P, to = P [, up = V] [, perspective = true]} -> f\nmap.view{azimuth = deg, elevation = deg [, distance = d] [, to = P] [, perspective = true]} -> f",
                                  .help = "The view with z up (docs/maps.md): from a point towards another, the picture's x to the right as seen and y along up (default the z axis), origin at to; parallel unless perspective."}, PCL_END};

void pcl_open_figure_layout(lua_State *L) {
    pcl_register(L, -1, fns, 0);
    pcl_register_into(L, -1, "map", view_fn);
}
