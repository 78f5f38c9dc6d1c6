/* Conics that know what they are (geom/quadratic.h) in Lua: c:conic(), conic.elements and
 * plane.conic_slope.  pcl_push_conic_info is shared with korotky.conic_elements, pcl_push_rows
 * with the books and the maps (pcl_books.h). */
#include "pcl_args.h"
#include "pcl_books.h"
#include "pcl_core.h"
#include "pcl_point.h"
#include "quadratic_given.h"
#include "quadratic_on.h"
#include "konop_why.h"

/* The fields of every conic, then those of a central one or of a parabola. */
#define COMMON "kind=s circle=b discriminant=o coef=N axes=V foci=P e=o p=o mu=o w=o k=o k_ceva=o"
#define COMMON_OF(o) pc_ckind_names[o->kind], o->circle, o->disc, 6, coef, 2, &o->axis[0][0], \
    o->nfoci, &o->focus[0][0], o->ecc, o->param, o->mu, o->w, o->k_ed, o->k_ceva

int pcl_push_conic_info(lua_State *L, const pc_conic_info *o) {
    double coef[6];
    for (int i = 0; i < 6; i++) coef[i] = o->coef[i] + 0.0;   /* no -0 in the listing */
    if (o->central)
        pcl_push_results(L, 2, COMMON " center=p semi=N a=o b=o", COMMON_OF(o), o->center, 2, o->semi, o->semi[0],
                         o->semi[1]);
    else
        pcl_push_results(L, 2, COMMON " vertex=p", COMMON_OF(o), o->vertex);
    if (o->nasym) {
        pcl_push_results(L, 2, "V", 2, &o->asym[0][0]);
        lua_setfield(L, -2, "asymptotes");
    }
    return 1;
}

void pcl_push_rows(lua_State *L, int nr, int nc, const double *m) {
    lua_createtable(L, nr, 0);
    for (int i = 0; i < nr; i++) {
        pcl_push_numbers(L, nc, m + (size_t)i * nc);
        lua_rawseti(L, -2, i + 1);
    }
}

/* The elements of the curve c, or the message for the status of pc_curve_conic. */
static int conic_of_curve(lua_State *L, pc_curve *c) {
    pc_conic_info o;
    pcl_callback_state(L);
    int st = pc_curve_conic(c, &o);
    if (st == PC_EDIM)
        return pcl_fail(L, "the curve is %d-D; a conic's elements are those of a plane (2-D) curve",
                        c->dim);
    pcl_check(L, st, pc_konop_why);
    return pcl_push_conic_info(L, &o);
}

static int c_conic(lua_State *L) { return conic_of_curve(L, pcl_read(L, NULL, 0)); }

/* A tangent condition {P, V}: a 2-D point and a 2-D vector (the one weight rule) into
 * out->v[0..3]. */
static int read_tangent(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    if (!lua_istable(L, idx)) return 0;
    int ok = 1;
    for (int i = 0; i < 2; i++) {
        lua_geti(L, idx, i + 1);
        pcl_value *p = pcl_tovalue(L, -1);
        double h[3];
        if (p && p->n == 2) memcpy(h, p->h, sizeof h);
        ok = ok && p && p->n == 2 && pc_snap_weight(2, h) == (i ? PC_KIND_VECTOR : PC_KIND_POINT);
        if (ok) out->v[2 * i] = h[0], out->v[2 * i + 1] = h[1];
        lua_pop(L, 1);
    }
    return ok;
}

static const pcl_arg tangent_item = A_ANY("tangents", read_tangent, "{a 2-D point, a 2-D vector}");
static const pcl_arg condition_keys[] = {A_POINTS("points", 2, 0, 5), {.name = "tangents", .kind = PCL_TABLE}, PCL_END};
static const pcl_arg condition_table = {.name = "conic", .kind = PCL_OPTIONS, .keys = condition_keys};

/* {points = {P, ...}, tangents = {{P, V}, ...}} at 1: five conditions, a tangent at a point
 * given among the points or not (quadratic_given.h). */
static int conditions(lua_State *L, pc_conic_info *o) {
    double pts[10], tangents[20];
    pcl_val k[2] = {{.list = pts, .cap = 10}};
    pcl_read_options(L, 1, 1, &condition_table, k);
    lua_getfield(L, 1, "tangents");
    int tg = lua_gettop(L), np = k[0].n, nt = k[1].present ? (int)lua_rawlen(L, tg) : 0;
    if (np + nt != 5)
        return pcl_fail(L, "five conditions fix a conic, got %d points and %d tangents", np, nt);
    for (int i = 0; i < nt; i++) {
        pcl_val t = {0};
        lua_geti(L, tg, i + 1);
        pcl_readone(L, tg + 1, 1, i + 1, &tangent_item, 2, &t);
        memcpy(tangents + 4 * i, t.v, sizeof(double) * 4);
        lua_pop(L, 1);
    }
    return pc_conic_info_given(np, pts, nt, tangents, o);
}

static const pcl_arg slope_args[] = {A_NUMBERS("coef", 6, 6), A_POINT("X", 2), PCL_END};
PCL_BODY(l_slope, a) {
    double sl;
    pc_why_call why;
    pcl_check(L, pc_conic_slope_checked(a[0].list, a[1].v, &sl, &why), why.row);
    return pcl_push_results(L, 0, "n", sl);   /* math.huge: a vertical tangent */
}

static const pcl_fn plane_fns[] = {
    PCL_FN("plane.conic_slope", l_slope, slope_args, "slope", "The slope dy/dx = -(2ax + by + d)/(bx + 2cy + e) of the implicit conic {a, b, c, d, e, f} at its point X (math.huge for a vertical tangent; an error off the curve or at a singular point)."),
    PCL_END};

PCL_BODY(l_elements, a) {
    pc_curve *c = pcl_tocurve(L, 1);
    if (c) return conic_of_curve(L, c);
    pc_conic_info o;
    int st, has_points = lua_istable(L, 1) && lua_getfield(L, 1, "points") != LUA_TNIL;   /* left on the stack */
    if (has_points) {
        st = conditions(L, &o);
    } else if (lua_istable(L, 1)) {
        static const pcl_arg coef_arg = A_NUMBERS("conic", 6, 6);
        pcl_val v = {.list = o.coef, .cap = 6};   /* pc_conic_info_coef may read its own out->coef */
        if (lua_rawlen(L, 1) != 6) return pcl_argfail(L, 1, "must be a list of 6 numbers {a, b, c, d, e, f}");
        pcl_readone(L, 1, 1, 0, &coef_arg, 0, &v);
        st = pc_conic_info_coef(o.coef, &o);
    } else if (pcl_tovalue(L, 1)) {
        /* five points, each read by the one point rule */
        static const pcl_arg pts_arg[5] = {A_POINT("A", 2), A_POINT("B", 2), A_POINT("C", 2), A_POINT("D", 2), A_POINT("E", 2)};
        pcl_val v[5] = {0};
        double pts[10];
        for (int i = 0; i < 5; i++) pcl_readone(L, i + 1, i + 1, 0, &pts_arg[i], 2, &v[i]);
        pcl_point_rows(v, 5, 2, pts);
        st = pc_conic_info_five(pts, &o);
    } else {
        return pcl_argfail(L, 1, "must be a 2-D curve, five points, the coefficients {a, b, c, d, e, f} or {points =, tangents =}, got %s",
                           pcl_shown(L, 1));
    }
    pcl_check(L, st, pc_konop_why);   /* pc_conic_info_given, _coef or _five */
    return pcl_push_conic_info(L, &o);
}

static void *self_curve(lua_State *L, int idx) { return pcl_tocurve(L, idx); }
#define LATER(nm) {.name = nm, .kind = PCL_ANY, .flags = PCL_OPT}   /* read by the body */
static const pcl_arg el_args[] = {{.name = "conic", .kind = PCL_ANY}, LATER("B"), LATER("C"), LATER("D"), LATER("E"),
                                  PCL_END};
static const pcl_fn conic_fns[] = {
    {.name = "conic.elements", .fn = l_elements, .args = el_args, .sig = "conic.elements(c) -> elements\nconic.elements(A, B, C, D, E) -> elements\nconic.elements({a, b, c, d, e, f}) -> elements\nconic.elements{points = {...}, tangents = {{P, V}, ...}} -> elements", .help = "What a conic is: the table of c:conic() for a curve, for the conic through five points, for the coefficients of a x^2 + b xy + c y^2 + d x + e y + f = 0, or for five general conditions (points, and tangent directions at points) (kind, centre or vertex, axes, semi-axes, foci, e, p, asymptotes, the implicit equation)."},
    PCL_END};
static const pcl_fn method_fns[] = {
    {.name = "c:conic", .fn = c_conic, .self = self_curve, .selftype = "curve", .result = "{kind, circle, discriminant, coef, center | vertex, axes, semi, a, b, foci, e, p, asymptotes, mu, w, k, k_ceva}", .help = "The conic a 2-D curve lies on: a rational quadratic arc with any weights (signs and points at infinity included) by its control points, any other curve by five of its points checked at eleven more. kind is \"ellipse\", \"parabola\" or \"hyperbola\" (circle = true for equal semi-axes); coef {a, b, c, d, e, f} of a x^2 + b xy + c y^2 + d x + e y + f = 0; axes[1] the major, transverse or parabola axis (into the curve); foci, eccentricity e and focal parameter p = b^2/a; for an arc with finite control points also mu = w1^2/(w0 w2), the normalised middle weight w, the engineering discriminant k = 1/(1 + w) of (2.97) and Ceva's k_ceva = 1/(4 mu) of (2.104). An error when the curve is not on one conic."},
    PCL_END};

/* After pcl_open_curves and pcl_open_konopatsky, with the module table on top. */
void pcl_open_conic_elements(lua_State *L) {
    int module = lua_gettop(L);
    pcl_private(L, module);
    pcl_register_into(L, module + 1, "curve_methods", method_fns);
    lua_settop(L, module);
    pcl_register_into(L, module, "conic", conic_fns);
    pcl_register_into(L, module, "plane", plane_fns);
}
