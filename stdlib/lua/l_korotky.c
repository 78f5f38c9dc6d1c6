/* Binding of Korotky's nature-like curves, conic surfaces and shells of 2015 (stdlib/books/
 * korotky/), in the table `korotky`.  A tangent is a slope tg(delta) (the direction
 * (cos delta, sin delta), x growing) or a 2-D vector.  Errors of the solvers name the knot (#1
 * is the first point).  A guide or a pencil's spanning point is a curve or a fixed point (a
 * vector: the point at infinity of its direction, as the basis point Z of the z axis). */
#include "pcl_args.h"
#include "pcl_core.h"
#include "ferguson.h"
#include "elastic.h"
#include "conic_surface.h"
#include "korotky_parts.h"
#include "pcl_point.h"
#include "pcl_books.h"

#define MAXPTS PC_FERGUSON_MAXN

/* A tangent: a slope tg(delta) (the direction (cos delta, sin delta)) or a 2-D vector. */
static int tangent_at(lua_State *L, int idx, double *t) {
    if (lua_type(L, idx) == LUA_TNUMBER && isfinite(lua_tonumber(L, idx))) {
        double d = atan(lua_tonumber(L, idx));
        t[0] = cos(d), t[1] = sin(d);
        return 1;
    }
    pcl_value *v = pcl_tovalue(L, idx);
    int ok = v && v->n == 2 && pc_kind_of(v->h[2]) == PC_KIND_VECTOR && isfinite(v->h[0]) && isfinite(v->h[1]);
    if (ok) t[0] = v->h[0], t[1] = v->h[1];
    return ok;
}
static int read_tangent(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    return tangent_at(L, idx, out->v);
}
#define TANGENT "a slope or a 2-D vector"
#define TANGENTS {.name = "tangents", .kind = PCL_TABLE, .expect = "a list of slopes or 2-D vectors"}

/* The n tangents of argument #k (a list, one per point) into T. */
static void tangents(lua_State *L, int k, const pcl_val *v, int n, double *T) {
    int m = (int)luaL_len(L, v->idx);
    if (m != n) pcl_argfail(L, k, "must hold one tangent per point (%d), got %d", n, m);
    for (int i = 1; i <= n; i++) {
        lua_geti(L, v->idx, i);
        if (!tangent_at(L, -1, T + 2 * i - 2))
            pcl_argfail(L, k, "[%d] must be " TANGENT ", got %s", i, pcl_shown(L, lua_gettop(L)));
        lua_pop(L, 1);
    }
}

/* ---- polynomial spline -------------------------------------------------------------------- */

static const pcl_arg poly_keys[] = {A_ENUM("ends", pc_poly_spline_ends), A_NUM("s0"), A_NUM("s1"),
                                    PCL_END};
static const pcl_arg poly_args[] = {A_POINTS("points", 2, 2, MAXPTS), A_OPTIONS("opts", poly_keys), PCL_END};
PCL_BODY(l_poly_spline, a) {
    double coef[4 * MAXPTS];
    int st, slopes = a[3].present && a[4].present;   /* a[2].n: the ends, a pc_end_kind */
    pc_why_call why;
    pc_curve *c = pc_poly_spline_checked(a[0].n, a[0].list, a[2].n, slopes, a[3].x, a[4].x, coef,
                                         &st, &why);
    pcl_made(L, c, &st, why.row);
    pcl_push_rows(L, a[0].n - 1, 4, coef);
    return 2;
}

/* ---- Ferguson splines --------------------------------------------------------------------- */

#define END_TANGENT(nm, at) {.name = nm, .kind = PCL_ANY, .flags = PCL_REQ, .read = read_tangent, \
                           .expect = TANGENT " (the tangent at the " at " point)"}
#define A_LIST(nm, n) {.name = nm, .kind = PCL_NUMBERS, .hi = n, .shown = "{...}"}   /* an optional key */
static const pcl_arg lambda_keys[] = {END_TANGENT("TA", "first"), END_TANGENT("TE", "last"), A_NUMOPT("wA", 1, "1"),
                                      A_NUMOPT("wE", 1, "1"), A_LIST("lambda", MAXPTS), PCL_END};
static const pcl_arg lambda_args[] = {A_POINTS("points", 2, 2, MAXPTS),
                                      {.name = "opts", .kind = PCL_OPTIONS, .keys = lambda_keys}, PCL_END};
PCL_BODY(l_ferguson_lambda, a) {
    int st, nl = a[6].present ? a[6].n : -1;   /* the ratios lambda given */
    pc_why_call why;
    pc_curve *c = pc_ferguson_lambda_checked(a[0].n, a[0].list, a[2].v, a[3].v, a[4].x, a[5].x, nl,
                                             a[6].list, &st, &why);
    return pcl_made(L, c, &st, why.row);
}

static const pcl_arg ferguson_args[] = {A_POINTS("points", 2, 2, MAXPTS), TANGENTS,
                                        A_NUMBERS("moduli", 2, 2 * MAXPTS - 2), PCL_END};
static const pcl_arg tangents_keys[] = {A_NUMOPT("wA", 1, "1"), A_NUMOPT("wE", 1, "1"), A_LIST("start", 2 * MAXPTS),
                                        PCL_END};
static const pcl_arg tangents_args[] = {A_POINTS("points", 2, 2, MAXPTS), TANGENTS,
                                        A_OPTIONS("opts", tangents_keys), PCL_END};
static const pcl_arg subst_args[] = {A_POINTS("points", 2, 2, MAXPTS), TANGENTS, A_NUM("wA"),
                                     A_POSNUM("z1"), {.name = "root", .kind = PCL_ENUM,
                                     .flags = PCL_OPT, .choices = pc_ferguson_roots}, PCL_END};

/* korotky.ferguson, korotky.ferguson_tangents and korotky.ferguson_substitution, one body told
 * apart by the declared name: the spline with a given tangent at every point, its moduli given
 * or solved for (then pushed, with the substitution's quadratics) */
PCL_BODY(l_ferguson, a) {
    double *p = a[0].list, T[2 * MAXPTS], mags[2 * MAXPTS], quad[3 * MAXPTS];
    const char *name = pcl_name(L);
    int n = a[0].n, subst = !strcmp(name, "korotky.ferguson_substitution"), bad = -1, st;
    pc_why_call w;   /* the failure explained */
    tangents(L, 2, &a[1], n, T);
    if (!strcmp(name, "korotky.ferguson"))
        return pcl_made(L, pc_ferguson_checked(n, p, T, a[2].n, a[2].list, &st, &w), &st, w.row);
    if (subst) {
        mags[0] = a[2].x;
        mags[1] = a[3].x;
        st = pc_ferguson_substitution(n, p, T, mags, a[4].n, quad, &bad);
    } else {
        if (a[5].present && a[5].n != 2 * n - 4)   /* the unknown moduli's start */
            pcl_keyfail(L, "start", "must hold %d numbers, got %d", 2 * n - 4, a[5].n);
        mags[0] = a[3].x;
        mags[2 * n - 3] = a[4].x;
        if (a[5].present) memcpy(mags + 1, a[5].list, sizeof(double) * (size_t)(2 * n - 4));
        st = pc_ferguson_tangents(n, p, T, mags, a[5].present, &bad);
    }
    pcl_check(L, pc_ferguson_explain(name, st, bad, &w), w.row);
    pcl_push_made(L, pc_ferguson_curve(n, p, T, mags, &st), &st, "korotky.ferguson");
    pcl_push_numbers(L, 2 * n - 2, mags);
    if (subst) pcl_push_rows(L, n - 2, 3, quad);
    return 2 + subst;
}

/* ---- the elastic reference and the measures ------------------------------------------------ */

/* ends = {tangent at the first point, tangent at the last}: their angles into out->v */
static int read_ends(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    if (!lua_istable(L, idx) || luaL_len(L, idx) != 2) return 0;
    for (int i = 0; i < 2; i++) {
        double t[2];
        lua_geti(L, idx, i + 1);
        int ok = tangent_at(L, -1, t) && hypot(t[0], t[1]) > 0;
        lua_pop(L, 1);
        if (!ok) return 0;
        out->v[i] = atan2(t[1], t[0]);
    }
    return 1;
}
static const pcl_arg elastic_keys[] = {
    {.name = "ends", .kind = PCL_ANY, .read = read_ends, .shown = "{tA, tE}",
     .expect = "{tangent at the first point, tangent at the last} (slopes or non-zero 2-D vectors)"},
    {.name = "pieces", .kind = PCL_INTEGER, .flags = PCL_RANGE, .lo = 1, .hi = 4, .shown = "4"},
    {.name = "length", .kind = PCL_NUMBER, .flags = PCL_POS, .shown = "free"}, PCL_END};
static const pcl_arg elastic_args[] = {A_POINTS("points", 2, 2, PC_ELASTIC_MAXN), A_OPTIONS("opts", elastic_keys),
                                       PCL_END};
PCL_BODY(l_elastic, a) {
    double E;
    int st;   /* pieces absent: 0, as many as the points allow; length absent: 0, free */
    pc_why_call why;
    pc_curve *c = pc_elastic_checked(a[0].n, a[0].list, (int)a[3].x, a[2].present ? a[2].v : NULL,
                                     a[4].x, &E, &st, &why);
    pcl_made(L, c, &st, why.row);
    return 1 + pcl_push_results(L, 0, "n", E);
}

static const pcl_arg deviation_args[] = {A_CURVE("model", 0), A_CURVE("reference", 0),
                                         {.name = "samples", .kind = PCL_INTEGER, .flags = PCL_OPT | PCL_RANGE,
                                          .lo = 8, .hi = 4096, .dflt = 64}, PCL_END};
PCL_BODY(l_deviation, a) {
    double d;
    pc_why_call why;
    pcl_check(L, pc_curve_hausdorff_checked(a[0].obj, a[1].obj, (int)a[2].x, &d, &why), why.row);
    return pcl_push_results(L, 0, "n", d);
}

/* korotky.joint_jumps and korotky.energy, one body told apart by the declared name: the jumps
 * at the joints (dk, da, the knot), or the bending energy (dk) */
static const pcl_arg curve_arg[] = {A_CURVE("curve", 0), PCL_END};
PCL_BODY(l_joints, a) {
    double dk, da;
    int at, jumps = !strcmp(pcl_name(L), "korotky.joint_jumps");
    int st = jumps ? pc_curve_joint_jumps(a[0].obj, &dk, &da, &at) : pc_curve_bending_energy(a[0].obj, &dk);
    if (st != PC_OK && jumps) return pcl_statuserror(L, pcl_name(L), st, "at a joint");
    if (st != PC_OK) return pcl_raise_status(L, pcl_name(L), st);
    return jumps ? pcl_push_results(L, 0, "n n i", dk, da, at + 1) : pcl_push_results(L, 0, "n", dk);
}

/* Graphical differentiation: the slope at x of a curve known by samples (2-D points, x
 * increasing), the way the article measured the ruler's slopes (Tables A2-A5). */
static const pcl_arg slope_args[] = {A_POINTS("samples", 2, 3, 0), A_NUM("x"),
                                     {.name = "window", .kind = PCL_INTEGER, .flags = PCL_OPT}, PCL_END};
PCL_BODY(l_graphical_slope, a) {
    int n = a[0].n, wn = a[2].present ? (int)a[2].x : n >= 7 ? 7 : n % 2 ? n : n - 1;
    double m;
    pc_why_call why;
    pcl_check(L, pc_graphical_slope_checked(n, a[0].list, a[1].x, wn, &m, &why), why.row);
    return pcl_push_results(L, 0, "n n", m, atan(m) * 180 / M_PI);
}

/* ---- conics and conic surfaces ------------------------------------------------------------ */

static const pcl_arg arc_args[] = {A_SAMEPOINT("U"), A_SAMEVECTOR("tU"), A_SAMEPOINT("V"), A_SAMEVECTOR("tV"),
                                   A_SAMEPOINT("T"), PCL_END};
PCL_BODY(l_conic_arc, a) {
    int d = a[0].n, st;   /* 1-D: PC_EDIM */
    double w;
    pc_curve *c = pc_conic_arc(d, a[0].v, a[1].v, a[2].v, a[3].v, a[4].v, &w, &st);
    if (!c) return pcl_fail(L, "%s", pc_conic_arc_why(st));
    pcl_pushcurve(L, c, "korotky.conic_arc");
    return 1 + pcl_push_results(L, 0, "n s", w, pc_conic_kind(w));
}

#define REQ3(nm, k) {.name = nm, .kind = k, .flags = PCL_REQ, .dim = 3}   /* a required 3-D key */
static const pcl_arg sweep_keys[] = {REQ3("U", PCL_CURVE), REQ3("V", PCL_CURVE), REQ3("T", PCL_CURVE),
                                     REQ3("P", PCL_CURVE), REQ3("Q", PCL_CURVE), PCL_END};
#define CALLTABLE(nm, k) {.name = nm, .kind = PCL_OPTIONS, .flags = PCL_CALLTABLE, .keys = k}   /* korotky.x{...} */
static const pcl_arg sweep_args[] = {CALLTABLE("guides", sweep_keys), PCL_END};

static const pcl_arg rect_args[] = {A_POSNUM("a0"), A_POSNUM("b0"), A_POSNUM("c0"), A_POINTOPT("origin", 3), PCL_END};
PCL_BODY(l_dome_rect, a) {
    int st;
    pc_surface *s = pc_surface_dome_rect(a[0].x, a[1].x, a[2].x, a[3].present ? a[3].v : NULL, &st);
    return pcl_push_made_surface(L, s, &st, "korotky.dome_rect");
}

/* A corner of the triangle: a 2-D point (z = 0) or a 3-D one. */
static int read_corner(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    pcl_value *v = pcl_tovalue(L, idx);
    out->v[2] = 0;
    return v && (v->n == 2 || v->n == 3) && pc_loc(v->n, v->h, out->v) == PC_OK;
}
/* The height h, or (h 0) the apex D (a 3-D point) the dome passes through. */
static int read_height(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    pcl_value *v = pcl_tovalue(L, idx);
    out->x = lua_tonumber(L, idx);
    if (lua_type(L, idx) == LUA_TNUMBER) return isfinite(out->x) && out->x > 0;
    return v && v->n == 3 && pc_loc(3, v->h, out->v) == PC_OK;
}
#define CORNER(nm) A_ANY(nm, read_corner, "a 2-D or 3-D point")
static const pcl_arg tri_args[] = {CORNER("A"), CORNER("B"), CORNER("C"),
                                   A_ANY("h | D", read_height, "a positive number or the 3-D apex D"), PCL_END};
PCL_BODY(l_dome_tri, a) {
    int st;
    pc_why_call why;
    pc_surface *s = pc_dome_tri_explained(a[0].v, a[1].v, a[2].v, a[3].x, a[3].v, &st, &why);
    if (!s) pcl_check(L, st, why.row);
    return pcl_push_made_surface(L, s, &st, "korotky.dome_tri");
}

/* ---- the shells of 2015 -------------------------------------------------------------------- */

/* A guide of dimension a->dim: a curve (out->obj), or a fixed point or vector (out->v, the
 * weight snapped by the one rule). */
static int read_guide(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    pc_curve *c = pcl_tocurve(L, idx);
    out->obj = c;
    if (c) return c->dim == a->dim;
    pcl_value *v = pcl_tovalue(L, idx);
    if (!v || v->n != a->dim) return 0;
    memcpy(out->v, v->h, sizeof(double) * (size_t)(a->dim + 1));
    return pc_snap_weight(a->dim, out->v) != PC_KIND_WEIGHTED;
}

/* ---- the key construction in 4-D --------------------------------------------------------- */

/* a pencil: three 4-D points, vectors or curves into a new buffer, out->obj (the table in the
 * argument keeps them alive) */
static int read_pencil(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    if (!lua_istable(L, idx) || luaL_len(L, idx) != 3) return 0;
    pc_pencil_point *g = lua_newuserdatauv(L, 3 * sizeof *g, 0);
    out->obj = g;
    static const pcl_arg g4 = {.kind = PCL_ANY, .dim = 4};
    for (int i = 0; i < 3; i++) {
        pcl_val v = {0};
        lua_geti(L, idx, i + 1);
        if (!read_guide(L, lua_gettop(L), &g4, &v))
            pcl_keyfail(L, a->name, "[%d] must be a 4-D point, vector or curve, got %s", i + 1,
                        pcl_shown(L, lua_gettop(L)));
        lua_pop(L, 1);
        g[i].c = v.obj;
        if (!v.obj) memcpy(g[i].h, v.v, sizeof g[i].h);
    }
    return 1;
}
#define PENCIL(nm) {.name = nm, .kind = PCL_ANY, .flags = PCL_REQ, .read = read_pencil, .shown = "{g1, g2, g3}", \
                    .expect = "a list of three 4-D points, vectors or curves"}
static const pcl_arg pencil_keys[] = {PENCIL("omega"), PENCIL("delta"), PCL_END};
static const pcl_arg pencils_args[] = {CALLTABLE("pencils", pencil_keys), PCL_END};
PCL_BODY(l_two_pencils, a) {
    int st, meet;
    pc_surface *s = pc_surface_two_pencils_checked(a[1].obj, a[2].obj, &st, &meet);
    if (meet != PC_OK) return pcl_fail(L, "no single meet at u = v = 0.5: %s", pc_meet_planes4_why(meet, 1));
    if (!s) return pcl_statuserror(L, pcl_name(L), st, NULL);
    return pcl_push_made_surface(L, s, &st, "korotky.two_pencils");
}

/* ---- the rotational sweep and the ridge shell ---------------------------------------------- */

static const pcl_arg revolve_keys[] = {REQ3("A", PCL_POINT), REQ3("B", PCL_POINT), REQ3("nA", PCL_VECTOR),
                                       REQ3("nB", PCL_VECTOR), REQ3("ridge", PCL_CURVE), PCL_END};
static const pcl_arg revolve_args[] = {CALLTABLE("data", revolve_keys), PCL_END};
PCL_BODY(l_conic_revolve, a) {
    int st;
    pc_why_call why;
    pc_surface *s = pc_conic_revolve_explained(a[1].v, a[2].v, a[3].v, a[4].v, a[5].obj, &st, &why);
    if (!s) pcl_check(L, st, why.row);
    return pcl_push_made_surface(L, s, &st, "korotky.conic_revolve");
}

#define GUIDE(nm) {.name = nm, .kind = PCL_ANY, .flags = PCL_REQ, .read = read_guide, .dim = 3, \
                   .expect = "a 3-D curve, point or vector"}
static const pcl_arg ridge_keys[] = {GUIDE("U"), GUIDE("R"), GUIDE("V"), GUIDE("T1"), GUIDE("T2"), GUIDE("P"),
                                     GUIDE("H"), GUIDE("Q"), PCL_END};
static const pcl_arg ridge_args[] = {CALLTABLE("guides", ridge_keys), PCL_END};

/* korotky.conic_sweep and korotky.ridge_shell, one body told apart by the declared name: the
 * surface of the conics the guides span (the sweep's five curves, the ridge shell's eight) */
PCL_BODY(l_sweep, a) {
    int ridge = !strcmp(pcl_name(L), "korotky.ridge_shell"), st;
    pc_pencil_point g[8];
    for (int i = 0; i < (ridge ? 8 : 5); i++) {
        g[i].c = a[i + 1].obj;
        memcpy(g[i].h, a[i + 1].v, sizeof(double) * 4);
    }
    pc_why_call why;
    pc_surface *s = pc_sweep_checked(ridge, g, &st, &why);
    if (!s) pcl_check(L, st, why.row);
    return pcl_push_made_surface(L, s, &st, pcl_name(L));
}

/* ---- the conic's centre, axes and asymptotes ---------------------------------------------- */

/* a 2-D conic arc (a rational quadratic Bezier curve, out->obj) or six finite numbers (out->v) */
static int read_conic(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    pc_curve *c = pcl_tocurve(L, idx);
    out->obj = c;
    if (c) return pc_conic_arc_shaped(c);   /* an arc, or korotky.conic_arc's line pair (T = W) */
    if (!lua_istable(L, idx) || luaL_len(L, idx) != 6) return 0;
    pcl_val coef = {.list = out->v, .cap = 6};
    pcl_readone(L, idx, 1, 0, &(const pcl_arg){.name = a->name, .kind = PCL_NUMBERS, .lo = 6, .hi = 6}, 0, &coef);
    return 1;
}
#define CONIC "a 2-D conic arc (a rational quadratic Bezier curve) or the coefficients {a, b, c, d, e, f}"
static const pcl_arg elements_args[] = {A_ANY("arc | {a, b, c, d, e, f}", read_conic, CONIC), PCL_END};
PCL_BODY(l_conic_elements, a) {
    /* the kernel's conic (geom/quadratic.h): an arc by its homogeneous control points, its
     * weights as they are; the same table as c:conic() */
    pc_conic_info o;
    pc_why_call why;
    pcl_check(L, pc_conic_elements_checked(a[0].obj, a[0].v, &o, &why), why.row);
    return pcl_push_conic_info(L, &o);
}

PCL_BODY(l_plane_meet, a) {
    double pq[6][5], out[5];   /* P1, P2, P3, then Q1, Q2, Q3 */
    pcl_point_rows(a, 6, 5, pq[0]);
    int st = pc_meet_planes4(pq, pq + 3, out);
    if (st != PC_OK) return pcl_fail(L, "%s", pc_meet_planes4_why(st, 0));
    pc_snap_weight(4, out);
    return pcl_push_results(L, 4, "w", out);
}

#define A_LOC4(nm) {.name = nm, .kind = PCL_LOC, .dim = 4}
static const pcl_arg meet_args[] = {A_LOC4("P1"), A_LOC4("P2"), A_LOC4("P3"),
                                    A_LOC4("Q1"), A_LOC4("Q2"), A_LOC4("Q3"), PCL_END};
static const pcl_fn fns[] = {
    PCL_FN("korotky.poly_spline", l_poly_spline, poly_args, "curve, coef", "The cubic spline y = S(x) through points with increasing x (eqs (1)-(9)); coef[i] = {a, b, c, d} of segment i, local origin x_i; the curve's parameter is x."),
    PCL_FN("korotky.ferguson", l_ferguson, ferguson_args, "curve", "The Ferguson spline (eq. (10) per segment, t in [0, 1]) with derivative moduli {w_A, z1, ..., w_E}, two per segment."),
    PCL_FN("korotky.ferguson_lambda", l_ferguson_lambda, lambda_args, "curve", "Ferguson spline with fixed ratios lambda at the interior knots (system (22), tridiagonal): curvature continuous at the joints."),
    PCL_FN("korotky.ferguson_tangents", l_ferguson, tangents_args, "curve, moduli", "Ferguson spline with a given tangent at every knot: Newton's method on system (23) from the chord lengths (Example 3 gives (28))."),
    PCL_FN("korotky.ferguson_substitution", l_ferguson, subst_args, "curve, moduli, quadratics", "The authors' sequential substitution (24)-(26) in closed form: one quadratic per knot; w_E is an output (Example 4 gives (29))."),
    PCL_FN("korotky.elastic", l_elastic, elastic_args, "curve, energy", "The elastic reference: the curve of least bending energy (integral of kappa^2 ds) through the points, free length unless length is given (a clamped ruler keeps its length), as a C2 cubic spline with pieces - 1 free nodes per span (curvature continuous at the pins, kappa = 0 at free ends); free ends unless ends are given."),
    PCL_FN("korotky.graphical_slope", l_graphical_slope, slope_args, "slope, degrees", "Graphical differentiation: the slope tg(delta) at x of a curve known by samples (2-D points, x increasing) from the parabola through the window (7) nearest samples, one-sided at the ends; and delta in degrees."),
    PCL_FN("korotky.deviation", l_deviation, deviation_args, "number", "The largest distance between two curves (two-sided Hausdorff distance)."),
    PCL_FN("korotky.joint_jumps", l_joints, curve_arg, "dkappa, dangle, knot", "The largest curvature jump and tangent angle jump (radians) at the joints of a piecewise curve, and the knot of the largest curvature jump."),
    PCL_FN("korotky.energy", l_joints, curve_arg, "number", "The bending energy, the integral of kappa^2 ds over the curve."),
    PCL_FN("korotky.conic_arc", l_conic_arc, arc_args, "curve, w, kind", "The conic arc from U to V through T tangent to tU at U and tV at V, as a rational quadratic Bezier curve; w its weight, kind \"ellipse\", \"parabola\", \"hyperbola\" or \"segment\"."),
    PCL_FN("korotky.conic_sweep", l_sweep, sweep_args, "s", "The surface swept by the conics through U(u), V(u), T(u) tangent to the lines U(u)P(u) and V(u)Q(u) (3-D curves, u in [0, 1])."),
    PCL_FN("korotky.dome_rect", l_dome_rect, rect_args, "s", "The elliptic dome over the rectangle 2 a0 x 2 b0 with height c0: an exact rational biquadratic patch whose iso-lines are semi-ellipses."),
    PCL_FN("korotky.dome_tri", l_dome_tri, tri_args, "s", "The triangular elliptic dome z^2 = 27 h^2 l1 l2 l3 over triangle ABC (height h over the centroid, or through the apex D) over (u, v) in [0, 1]^2 with the plan point A + (B - A) u(1 - v) + (C - A) uv: u-isolines are the ellipses parallel to BC."),
    PCL_FN("korotky.conic_elements", l_conic_elements, elements_args, "{kind, coef, center, axes, semi, foci, e, p, asymptotes, ...}", "The conic of a 2-D conic arc with any weights (or of a x^2 + b xy + c y^2 + d x + e y + f = 0): the table of c:conic(): kind, coefficients, centre (a parabola's vertex), unit principal axes (major or transverse first), semi-axes, foci, e, p, a hyperbola's unit asymptote directions, and for an arc mu, w and the engineering discriminant k."),
    PCL_FN("korotky.two_pencils", l_two_pencils, pencils_args, "s", "The 4-D key construction: S(u, v) is the meet of the 2-plane through omega's three points at u and delta's at v (each a 4-D curve or a fixed 4-D point; a vector is a point at infinity). Draw it through a 4-D -> 2-D map (map.matrix of 3 x 5)."),
    PCL_FN("korotky.conic_revolve", l_conic_revolve, revolve_args, "s", "A conic turned about AB: for each point T of the ridge (a 3-D curve) the arc from A to B through T tangent to the planes with normals nA at A and nB at B."),
    PCL_FN("korotky.ridge_shell", l_sweep, ridge_args, "s", "A shell whose profiles are two conic arcs, U to R through T1 and R to V through T2, tangent towards P at U, along H at the ridge R and towards Q at V (3-D curves, points or vectors): G1 along the ridge; v in [0, 2]."),
    PCL_FN("korotky.plane_meet", l_plane_meet, meet_args, "K", "The meet of the 2-plane through P1, P2, P3 and the one through Q1, Q2, Q3 in 4-space (B.4, the step of the key construction): one point in general, a vector when it is at infinity; a vector among the six is a point at infinity."),
    PCL_END};

void pcl_open_korotky(lua_State *L) { pcl_new_table(L, -1, "korotky", fns, NULL); }
