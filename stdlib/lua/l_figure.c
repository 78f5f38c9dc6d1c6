/* The print look's bindings on the declared argument layer (docs/bindings.md): figure{...},
 * and the kinds pen() and label() of l_draw.c declare: lengths with units and the label
 * options {font =, size =, halo =}. */
#include "pcl_draw.h"
#include "print.h"

/* A length option: a string with its unit ("12cm"), in pt. */
int pcl_read_length(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    if (lua_type(L, idx) != LUA_TSTRING) return 0;
    char err[200];
    return pc_parse_length(lua_tostring(L, idx), "", &out->x, err, sizeof err) == PC_OK
           || pcl_keyfail(L, a->name, "%s", err + 2);   /* the parser's words, after ": " */
}

/* A text size: pt as a number, or a length ("9pt"); 1..200 pt. */
static int read_size(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    if (lua_type(L, idx) == LUA_TNUMBER) out->x = lua_tonumber(L, idx);
    else if (!pcl_read_length(L, idx, a, out)) return 0;
    return (out->x >= 1 && out->x <= 200)
           || pcl_keyfail(L, a->name, "must be 1 to 200 pt, got %s pt", pcl_pushnum(L, out->x));
}

#define LENGTH "a length with its unit such as \"12cm\" or \"0.5mm\""
static const pcl_arg figure_keys[] = {
    {.name = "width", .kind = PCL_ANY, .read = pcl_read_length, .expect = LENGTH, .shown = "\"12cm\""},
    {.name = "height", .kind = PCL_ANY, .read = pcl_read_length, .expect = LENGTH, .shown = "\"8cm\""},
    {.name = "dpi", .kind = PCL_NUMBER, .flags = PCL_RANGE, .lo = 10, .hi = 2400, .shown = "300"},
    {.name = "font", .kind = PCL_STRING, .shown = "\"serif\"|\"sans\"|\"mono\""},
    {.name = "size", .kind = PCL_ANY, .read = read_size, .expect = "a size in pt (1 to 200)", .shown = "10"}, PCL_END};
static const pcl_arg figure_args[] = {
    {.name = "options", .kind = PCL_OPTIONS, .flags = PCL_OPT | PCL_CALLTABLE, .keys = figure_keys}, PCL_END};

/* figure{width = "12cm", height = "8cm", dpi = 300, font = "serif", size = 10}: the print
 * look for every output, at that size; a width alone keeps the window's aspect. */
PCL_BODY(l_figure, a) {   /* options, width, height, dpi, font, size */
    pc_canvas *c = pcl_canvas(L);
    pc_figure_opts o = {a[1].present, a[2].present, a[3].present, a[5].present, a[1].x, a[2].x, a[3].x, a[5].x, a[4].s};
    return pcl_check_canvas(L, c, pc_figure_options(c, &o));   /* the core's message, its "figure: " once */
}

/* A font the print look can set: a name fontconfig knows. */
static int read_font(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    if (lua_type(L, idx) != LUA_TSTRING || lua_rawlen(L, idx) >= 64) return 0;
    out->s = lua_tostring(L, idx);
    const char *family;
    char err[200];
    return pc_font_family(out->s, &family, err, sizeof err) == PC_OK || pcl_fail(L, "%s", err);
}

const pcl_arg pcl_label_keys[] = {{.name = "font", .kind = PCL_ANY, .read = read_font, .expect = "a font name"},
    {.name = "size", .kind = PCL_ANY, .read = read_size, .expect = "a size in pt (1 to 200)"},
    {.name = "halo", .kind = PCL_BOOLEAN}, PCL_END};

void pcl_label_style(lua_State *L, pc_canvas *c, const pcl_val *k) {
    pcl_check_canvas(L, c, pc_text_style(c, k[0].s, k[1].x, k[2].present ? (int)k[2].x : -1));
}

static const pcl_fn fns[] = {
    PCL_FN("figure", l_figure, figure_args, NULL, "The print look for every output (PDF, EPS and PS always have it): the canvas at that size (a width alone keeps the window's aspect), PNG at dpi, labels in the font at size pt. Without a window or a screen() the coordinates are world units with y up and the figure is framed to what is drawn, at true shape."),
    PCL_END};

void pcl_open_figure(lua_State *L) { pcl_register(L, -1, fns, 0); }
