/* Binding of Konopatsky's monograph (stdlib/books/konopatsky/): the tables conic, oneratio,
 * interp, approx and konopatsky (chapter 1), declared on the argument layer (pcl_args.h,
 * docs/bindings.md).  Every curve is the one curve userdata (pcl_pushcurve); the constructions
 * are in the core (docs/konopatsky.md). */
#include "pcl_args.h"
#include "pcl_books.h"
#include "pcl_core.h"
#include "pcl_expr.h"
#include "pcl_point.h"
#include "conic.h"
#include "konop_form.h"
#include "oneratio.h"
#include "konop_interp.h"
#include "approx.h"
#include "konop_why.h"
#include "konop_make.h"
#include "konop_schemes.h"
#include "konop_triples.h"
#include "konop_ch1.h"
#include "konop_print.h"

#define SP(nm) A_SAMEPOINT(nm)
#define REQPT(nm) {.name = nm, .kind = PCL_POINT, .flags = PCL_SAMEDIM | PCL_REQ}   /* an option key */
#define MAXNODES (PC_CURVE_MAXDEG + 1)
#define CHECK(st) pcl_check(L, (st), pc_konop_why)
#define MADE(c) pcl_made(L, (c), &st, pc_konop_why)

/* the params (argument #k), if given: one per point */
static void need_count(lua_State *L, int k, const pcl_val *v, int n) {
    if (v->present && v->n != n)
        pcl_fail(L, "argument #%d (params) must hold %d numbers (one per point), got %d", k, n, v->n);
}

/* A function, or a value with __call (pcl_callable). */
#define A_FN(nm, what, fl) {.name = nm, .kind = PCL_CALLABLE, .flags = fl, .expect = what}
#define A_TRUE(nm) {.name = nm, .kind = PCL_BOOLEAN, .shown = "true"}   /* a boolean key */
#define A_LATER(nm) {.name = nm, .kind = PCL_ANY, .flags = PCL_OPT}   /* read by the body */
/* an optional integer: A_INTOPT(name, lo, hi, default [, .expect = "text"]) */
#define A_INTOPT(nm, l, h, ...) {.name = nm, .kind = PCL_INTEGER, .flags = PCL_OPT | PCL_RANGE, \
    .lo = l, .hi = h, .dflt = __VA_ARGS__}
#define A_PARAMS {.name = "params", .kind = PCL_NUMBERS, .flags = PCL_OPT, .hi = MAXNODES}   /* one per point */

/* ==== conic ================================================================================= */

/* the constructions of made (below) */
static const pcl_arg abck_args[] = {SP("A"), SP("B"), SP("C"), A_NUM("k"), PCL_END};
static const pcl_arg abcK_args[] = {SP("A"), SP("B"), SP("C"), SP("K"), PCL_END};
static const pcl_arg abc_args[] = {SP("A"), SP("B"), SP("C"), PCL_END};
static const pcl_arg ceva_args[] = {SP("A1"), SP("A2"), SP("A3"), A_NUM("k"), PCL_END};
static const pcl_arg cevaK_args[] = {SP("A1"), SP("A2"), SP("A3"), SP("K"), PCL_END};
static const pcl_arg k_args[] = {A_NUM("k"), PCL_END};
static const pcl_arg bezier3_args[] = {SP("A"), SP("C1"), SP("C2"), SP("B"), PCL_END};
static const pcl_arg smooth_args[] = {SP("A"), SP("B"), SP("C"), A_INTOPT("n", 1, 40, 2), PCL_END};
static const pcl_arg akbk_args[] = {SP("A"), SP("K"), SP("B"), A_NUM("k"), PCL_END};
static const pcl_arg parabola_args[] = {SP("A1"), SP("A3"), SP("A2"), A_NUMOPT("tC", NAN, NULL), PCL_END};
static const pcl_arg triples_args[] = {SP("A1"), SP("A2"), SP("A3"), SP("A4"), SP("A5"), A_NUMOPT("t0", 0, NULL),
                                       A_NUMOPT("t1", 1, NULL), PCL_END};
static const pcl_arg cones_args[] = {SP("A"), SP("B"), SP("C"), SP("D"), A_NUM("fP"), A_NUM("fQ"), A_NUM("n"), PCL_END};
static const pcl_arg closed_args[] = {SP("A"), SP("B"), SP("C"), A_NUM("kP"), A_NUM("kQ"),
                                      A_INTOPT("scheme", 1, 2, 1, .expect = "1 or 2"), PCL_END};

/* A construction of pc_konop_make, _number or _list, or a scheme of pc_konop_scheme (pushed by
 * its fields), the kind by the name it is called: the declared points, then the numbers (an
 * enum's choice by its index; from a[0] when there are no points). */
PCL_BODY(made, a) {
    const char *fields = NULL;
    int kind = pc_konop_kind_of(pcl_name(L)), scheme = pc_konop_scheme_of(pcl_name(L), &fields);
    int np = fields ? pc_konop_scheme_npoints(scheme) : pc_konop_npoints(kind), d = a[0].n, st, n;
    double p[5 * PC_MAXDIM], x[3] = {0, 0, 0}, k, u[8 * (PC_MAXDIM + 1)];
    for (int i = 0; i < 3 && np + i < pcl_nvalues(L); i++)
        x[i] = a[np + i].s ? a[np + i].n : a[np + i].x;
    pcl_point_rows(a, np, d, p);
    if (fields) {
        CHECK(pc_konop_scheme(scheme, d, p, x, u));
        return pcl_push_packed(L, d, fields, u);
    }
    if (kind < PC_KM_ED_K) return MADE(pc_konop_make(kind, d, p, x, &st));
    if (kind >= PC_KM_CONES_EXCLUDED) {
        CHECK(pc_konop_list(kind, x, u, &n));
        return pcl_push_results(L, 0, "N", n, u);
    }
    CHECK(pc_konop_number(kind, d, p, x, &k));
    return pcl_push_results(L, 0, "n", k);
}

/* The tables of the book's forms: C, A, B and the range first in each (a[1..4]). */
#define KC_KEYS(req) {.name = "C", .kind = PCL_POINT, .flags = PCL_SAMEDIM | (req)}, REQPT("A"), REQPT("B"), \
    {.name = "range", .kind = PCL_NUMBERS, .lo = 2, .hi = 2, .shown = "{t0, t1}"}
#define SPEC(k) {{.name = "spec", .kind = PCL_OPTIONS, .flags = PCL_CALLTABLE, .keys = k}, PCL_END}
#define BRANCH {.name = "branch", .kind = PCL_INTEGER, .flags = PCL_RANGE, .lo = 1, .hi = 2, .dflt = 1, \
    .shown = "1|2", .expect = "1 or 2"}

/* The form (konop_form.h) of the table read into a[1..4] (C, A, B, range) with its parameters
 * and the point K (or NULL). */
static int kcurve_from(lua_State *L, const pcl_val *a, int form, const double *par, int npar, const pcl_val *K) {
    int st;
    double t0 = a[4].present ? a[4].list[0] : NAN, t1 = a[4].present ? a[4].list[1] : NAN;
    pc_why_call why;
    pc_curve *c = pc_konop_form(pcl_name(L), form, a[2].n, a[1].present ? a[1].v : NULL, a[2].v, a[3].v,
                                K && K->present ? K->v : NULL, par, npar, t0, t1, &st, &why);
    return pcl_made(L, c, &st, why.row);
}

static const char *const HYPERBOLA_BY[] = {"angle", "radius", "focal", NULL};   /* PC_KC_HYPERBOLA_* in order */
static const pcl_arg hyperbola_keys[] = {KC_KEYS(PCL_REQ), A_ENUM("by", HYPERBOLA_BY), BRANCH, PCL_END};
static const pcl_arg hyperbola_args[] = SPEC(hyperbola_keys);
static const char *const REPARAM_BY[] = {"angle", "sigma", NULL};
static const pcl_arg reparam_keys[] = {KC_KEYS(PCL_REQ), A_ENUM("by", REPARAM_BY), BRANCH, PCL_END};
static const pcl_arg reparam_args[] = SPEC(reparam_keys);

/* k: a wave number, or a list of them (one per generation), into out->v = {g, k1, ..., kg} */
static int read_waves(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    int list = lua_istable(L, idx), g = list ? (int)lua_rawlen(L, idx) : 1;   /* raw: no __len inside a reader */
    if (g < 1 || g > PC_KC_MAXPAR - 1) return 0;
    out->v[0] = g;
    for (int i = 1; i <= g; i++) {
        int t = list ? lua_geti(L, idx, i) : lua_type(L, idx);
        out->v[i] = t == LUA_TNUMBER ? lua_tonumber(L, list ? -1 : idx) : NAN;
        lua_pop(L, list);   /* the element, when k is a list */
        if (!(out->v[i] > 0) || !isfinite(out->v[i])) return 0;
    }
    return 1;
}
static const pcl_arg sinusoid_keys[] = {KC_KEYS(PCL_REQ), {.name = "k", .kind = PCL_ANY, .flags = PCL_REQ,
    .read = read_waves, .shown = "{m, n, ...}",
    .expect = "a positive wave number or a list of 1 to 8 of them (one per generation)"}, PCL_END};
static const pcl_arg sinusoid_args[] = SPEC(sinusoid_keys);
static const pcl_arg cycloid_keys[] = {KC_KEYS(PCL_REQ), A_TRUE("concave"), PCL_END};
static const pcl_arg cycloid_args[] = SPEC(cycloid_keys);

/* conic.hyperbola, .reparam, .sinusoid and .cycloid: the table's first form (pc_konop_form_base)
 * offset by 'by' (a[5], an enum where the table has it), the parameter its last key (branch, k,
 * concave; reparam's angle form leaves the branch unread) */
PCL_BODY(c_form, a) {   /* spec; C, A, B, range, [by,] branch | k | concave */
    int form = pc_konop_form_base(pcl_name(L)), last = pcl_nvalues(L) - 1;
    const pcl_val *p = &a[last];
    if (form == PC_KC_SINUSOID) return kcurve_from(L, a, form, p->v, (int)p->v[0] + 1, NULL);
    return kcurve_from(L, a, form + (a[5].s ? a[5].n : 0), &p->x, 1, NULL);
}

/* by: the forms PC_KC_ELLIPSE_ANGLE .. PC_KC_ELLIPSE_ALGEBRAIC in order, then two of conic.h */
static const char *const ELLIPSE_BY[] = {"angle", "radius", "focal", "compression", "algebraic",
                                         "conjugate", "diameter", NULL};
static const pcl_arg ellipse_keys[] = {KC_KEYS(0), A_ENUM("by", ELLIPSE_BY), A_NUMOPT("quadrant", 1, "1"),
                                       SP("K"), A_NUMOPT("lambda", NAN, NULL), PCL_END};
static const pcl_arg ellipse_args[] = SPEC(ellipse_keys);
PCL_BODY(c_ellipse, a) {   /* spec; C, A, B, range, by, quadrant, K, lambda */
    int by = a[5].n, form = by < 5 ? PC_KC_ELLIPSE_ANGLE + by : PC_KF_CONJUGATE + by - 5;
    return kcurve_from(L, a, form, &a[by == 6 ? 8 : 6].x, 1, &a[7]);   /* lambda or quadrant */
}

static const pcl_arg circle_keys[] = {KC_KEYS(PCL_REQ), A_NUM("delta"), A_POSNUM("R"), PCL_END};
static const pcl_arg circle_args[] = SPEC(circle_keys);
PCL_BODY(c_circle, a) {   /* spec; C, A, B, range, delta, R */
    int form = a[5].present ? PC_KC_CIRCLE_ANGLE : a[6].present ? PC_KC_CIRCLE_RADIUS : PC_KF_CIRCLE_ARC;
    return kcurve_from(L, a, form, a[5].present ? &a[5].x : &a[6].x, 1, NULL);
}

static const pcl_arg tilted_args[] = {SP("A"), SP("B"), SP("C"), A_NUM("theta"), A_POSNUM("m"), A_POSNUM("n"), PCL_END};
PCL_BODY(c_tilted, a) {
    int d = a[0].n, st;
    double o[4 * PC_MAXDIM + 2];
    MADE(pc_ellipse_tilted(d, a[0].v, a[1].v, a[2].v, a[3].x, a[4].x, a[5].x, o, &st));
    return 1 + pcl_push_packed(L, d, "p p h p n", o);   /* K: a vector at theta = 0 */
}

static const pcl_arg five_keys[] = {A_NUM("u0"), A_NUM("u1"), A_TRUE("whole"), PCL_END};
static const pcl_arg five_args[] = {SP("A"), SP("B"), SP("C"), SP("D"), SP("E"), A_OPTIONS("opts", five_keys), PCL_END};
PCL_BODY(c_five_points, a) {   /* A..E, opts, u0, u1, whole */
    int st;
    double u[5], u0 = a[6].present ? a[6].x : NAN, u1 = a[7].present ? a[7].x : NAN;
    MADE(pc_conic_five_points(a[0].n, a[0].v, a[1].v, a[2].v, a[3].v, a[4].v, u0, u1, (int)a[8].x, u, &st));
    return 1 + pcl_push_results(L, 0, "A=n B=n C=n D=n E=n", u[0], u[1], u[2], u[3], u[4]);
}

#define REQNUM(nm) {.name = nm, .kind = PCL_NUMBER, .flags = PCL_REQ}
static const pcl_arg five2_keys[] = {REQPT("C"), REQPT("A"), REQPT("B"), REQNUM("p1"), REQNUM("p2"), REQNUM("q2"),
                                     REQNUM("q3"), PCL_END};
static const pcl_arg five2_args[] = SPEC(five2_keys);
PCL_BODY(c_five_points2, a) {   /* spec; C, A, B, p1, p2, q2, q3 */
    int st;
    return MADE(pc_conic_five_points2(a[2].n, a[1].v, a[2].v, a[3].v, a[4].x, a[5].x, a[6].x, a[7].x, &st));
}

static const pcl_arg redundant_args[] = {SP("C"), SP("A"), SP("B"), A_NUMOPT("u", 0, NULL), A_NUMOPT("v", 0, NULL),
                                         PCL_END};
PCL_BODY(c_redundant, a) {
    int d = a[0].n, st;
    if (!a[3].present && !a[4].present)   /* (2.121) u = v = t: the ED arc with k = 2/3 */
        return MADE(pc_conic_ed(d, a[1].v, a[2].v, a[0].v, 2.0 / 3, &st));
    if (!a[3].present || !a[4].present) return pcl_argfail(L, a[3].present ? 5 : 4, "must be a finite number, got nil");
    double K[PC_MAXDIM];
    CHECK(pc_redundant_point(d, a[0].v, a[1].v, a[2].v, a[3].x, a[4].x, K));
    return pcl_push_results(L, d, "p", K);
}

#define T_FN(nm, fl) A_FN(nm, "a function of t", fl)
static const pcl_arg contour_args[] = {SP("A1"), SP("A2"), SP("A3"), T_FN("u", 0), T_FN("v", 0),
                                       T_FN("du", PCL_OPT), T_FN("dv", PCL_OPT), PCL_END};
PCL_BODY(c_contour, a) {
    int has_d = a[5].present, st;
    if (has_d && !a[6].present) return pcl_argfail(L, 7, "must be a function of t (with du), got nil");
    pcl_luafn *r = pcl_luafn_new(L, has_d ? 4 : 2, (int[]){4, 5, 6, 7});
    pc_curve *c = pc_contour_arc(a[0].n, a[0].v, a[1].v, a[2].v, pcl_luafn_which, has_d, pcl_luafn_free, r, &st);
    if (!c) pcl_luafn_free(r);
    return MADE(c);
}

/* ==== oneratio ============================================================================== */

static const pcl_arg abcd_args[] = {SP("A"), SP("B"), SP("C"), SP("D"), PCL_END};
PCL_BODY(o_simplex, a) {   /* also oneratio(A, B, C): the table is the receiver */
    int st;   /* the one kind, however it was called */
    return pcl_push_made(L, pc_oneratio_simplex(a[0].n, a[0].v, a[1].v, a[2].v, &st), &st, "oneratio.simplex");
}

/* f: a function of v or a number */
static int read_blend(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    out->n = lua_type(L, idx) == LUA_TNUMBER;
    out->x = lua_tonumber(L, idx);
    return out->n ? isfinite(out->x) : pcl_callable(L, idx);
}
static const pcl_arg contact_args[] = {SP("A"), SP("B"), SP("C"), A_NUM("kp"), A_NUM("kq"),
    {.name = "f", .kind = PCL_ANY, .flags = PCL_OPT, .read = read_blend, .expect = "a function of v or a number"},
    PCL_END};
PCL_BODY(o_double_contact, a) {   /* f: a function of v, a number, or absent: f(v) = v */
    int st, d = a[0].n, fn = a[5].present && !a[5].n;
    const double *A = a[0].v, *B = a[1].v, *C = a[2].v;
    if (a[5].present && !fn) return MADE(pc_oneratio_double_contact_const(d, A, B, C, a[3].x, a[4].x, a[5].x, &st));
    pcl_luafn *f = fn ? pcl_luafn_new(L, 1, (int[]){6}) : NULL;
    pc_curve *c = pc_oneratio_double_contact(d, A, B, C, a[3].x, a[4].x, fn ? pcl_luafn_blend : NULL,
                                             fn ? pcl_luafn_free : NULL, f, &st);
    if (!c && f) pcl_luafn_free(f);
    return MADE(c);
}

/* ---- the schemes' intermediate points (for figures that label them) ----------------------- */

static const pcl_arg levels_args[] = {A_POINTS("points", 0, 2, 16), A_NUM("t"), PCL_END};
PCL_BODY(o_levels, a) {
    double out[120 * PC_MAXDIM], *row = out;
    int n = a[0].n, d = a[0].dim;
    CHECK(pc_decasteljau_levels(d, n, a[0].list, a[1].x, out));
    lua_createtable(L, n - 1, 0);
    for (int level = 1; level < n; level++) {
        pcl_push_values(L, n - level, d, row, 0);
        lua_rawseti(L, -2, level);
        row += (n - level) * d;
    }
    return 1;
}

/* ==== interp ================================================================================ */

static const pcl_arg lagrange_args[] = {A_POINTS("points", 0, 2, MAXNODES), A_PARAMS, PCL_END};

/* interp.lagrange: the interpolation curve through a[0] at the parameters a[1] (uniform when
 * absent); interp.controls: its control points */
PCL_BODY(i_lagrange, a) {
    int st, d = a[0].dim;
    need_count(L, 2, &a[1], a[0].n);
    pc_curve *c = pc_curve_interpolate(d, a[0].n, a[0].list, a[1].present ? a[1].list : NULL, &st);
    if (!c || !strcmp(pcl_name(L), "interp.lagrange")) return MADE(c);
    pcl_push_values(L, c->ncp, d, c->cp, 1);   /* a polynomial curve: weights 1 */
    pc_curve_release(c);
    return 1;
}

/* the nodes: the book's order n (n + 1 nodes at the uniform j/n), or the list of their
 * parameters (out->list, out->n: the count of nodes) */
static int read_nodes(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    if (lua_istable(L, idx)) {
        static const pcl_arg params = A_NUMBERS("params", 2, MAXNODES);
        pcl_readone(L, idx, 1, 0, &params, 0, out);
        return 1;
    }
    lua_Integer order = lua_isinteger(L, idx) ? lua_tointeger(L, idx) : 0;
    out->n = (int)order + 1, out->list = NULL;
    return order >= 1 && order <= PC_CURVE_MAXDEG;
}
/* t: a finite number, or an equation (out->n = 1) */
static int read_t(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    out->n = pcl_isequation(L, idx);
    out->x = lua_tonumber(L, idx);
    return out->n || (lua_type(L, idx) == LUA_TNUMBER && isfinite(out->x));
}
static const pcl_arg weights_args[] = {{.name = "n", .kind = PCL_ANY, .read = read_nodes,
    .expect = "the book's order 1..64 (a curve through n + 1 nodes; not the number of nodes) or a list of node "
              "parameters"},
    {.name = "t", .kind = PCL_ANY, .read = read_t, .expect = "a finite number or an equation (param \"t\")"}, PCL_END};

/* the weights as equations in t (stack index 2): the polynomials the Maple program of §4.8
 * prints, phi_j = c0 + c1 t + c2 t^2 + ..., terms of zero coefficient left out */
static int weight_equations(lua_State *L, int n, const double *u) {
    double coef[MAXNODES * MAXNODES];
    CHECK(pc_lagrange_weight_coefs(n, u, coef));
    lua_createtable(L, n, 0);
    for (int j = 0; j < n; j++) {
        int terms = 0;
        for (int i = 0; i < n; i++) {
            if (coef[(size_t)j * n + i] == 0) continue;
            lua_pushnumber(L, coef[(size_t)j * n + i]);   /* c t^i: the equations make t^1 t and c t^0 c */
            lua_pushvalue(L, 2);
            lua_pushinteger(L, i);
            lua_arith(L, LUA_OPPOW);
            lua_arith(L, LUA_OPMUL);
            if (terms++) lua_arith(L, LUA_OPADD);
        }
        if (!terms) lua_pushnumber(L, 0);
        lua_rawseti(L, -2, j + 1);
    }
    return 1;
}

PCL_BODY(i_weights, a) {
    int n = a[0].n;
    if (a[1].n) return weight_equations(L, n, a[0].list);
    double w[MAXNODES];
    CHECK(pc_lagrange_weights(n, a[0].list, a[1].x, w));
    return pcl_push_results(L, 0, "N", n, w);
}

/* interp.arc(points, C2 [, Cn] [, params]): argument #3 is Cn (a point) or the params (a list) */
static const pcl_arg arc_args[] = {{.name = "points", .kind = PCL_POINTS, .flags = PCL_SAMEDIM, .lo = 2,
                                    .hi = PC_CURVE_MAXDEG - 2}, SP("C2"), A_LATER("Cn"), A_PARAMS, PCL_END};
PCL_BODY(i_arc, a) {
    static const pcl_arg third[] = {A_NUMBERS("params", 0, MAXNODES), SP("Cn")};
    pcl_val v3 = {0};
    int n = a[0].n, d = a[0].dim, k = lua_istable(L, 3) ? 3 : 4, st;   /* k: the params' argument */
    if (a[2].present) pcl_readone(L, 3, 3, 0, &third[k - 3], d, &v3);
    const pcl_val *u = k == 3 ? &v3 : &a[3];
    need_count(L, k, u, n);
    const double *cn = k == 4 && v3.present ? v3.v : NULL;
    pc_curve *c = pc_interp_arc_u(d, n, a[0].list, u->present ? u->list : NULL, a[1].v, cn, &st);
    if (!c && st == PC_EDOMAIN && u->present)
        return pcl_fail(L, "argument #%d (params) must increase (one parameter per point, in order)", k);
    return MADE(c);
}

static const pcl_arg adaptive_args[] = {A_POINTS("points", 0, 2, MAXNODES),
                                        {.name = "axis", .kind = PCL_INTEGER, .flags = PCL_OPT, .dflt = 1}, PCL_END};
PCL_BODY(i_adaptive, a) {
    double v[MAXNODES];
    pc_why_call why;
    pcl_check(L, pc_interp_adaptive(a[0].dim, a[0].n, a[0].list, (int)a[1].x, v, &why), why.row);
    return pcl_push_results(L, 0, "N", a[0].n, v);
}

static const char *const PROTOS[] = {"desargues", "rational", "exp", "exp1", "trig", NULL};   /* pc_proto_kind */
static const pcl_arg proto_args[] = {A_ENUM("kind", PROTOS), A_LATER("points"), A_LATER("k | t0"),
                                     A_LATER("t0 | t1"), A_LATER("t1"), PCL_END};
PCL_BODY(i_prototype, a) {
    pcl_val p = {0}, k = {0}, t[2] = {{.x = NAN}, {.x = NAN}};   /* t0, t1 NaN when not given */
    int n, nk, st;
    pc_interp_prototype_shape((pc_proto_kind)a[0].n, &n, &nk);
    /* the count of points the prototype takes, whatever came (nil included) */
    if (!lua_istable(L, 2))
        return pcl_argfail(L, 2, "must hold %d points (the \"%s\" prototype), got %s", n, a[0].s, pcl_shown(L, 2));
    pcl_arg pa = A_POINTS("points", 0, n, n), ka = A_NUMBERS("k", nk, nk), ta[2] = {A_NUM("t0"), A_NUM("t1")};
    pcl_readone(L, 2, 2, 0, &pa, 0, &p);
    if (nk) pcl_readone(L, 3, 3, 0, &ka, 0, &k);
    for (int j = 0, at = nk ? 4 : 3; j < 2 && !lua_isnoneornil(L, at); j++)   /* t1 follows t0 */
        pcl_readone(L, at + j, at + j, 0, &ta[j], 0, &t[j]);
    double t0 = t[0].x, t1 = t[1].x, none[3] = {0};
    if (!(t1 > t0) && !isnan(t0)) return pcl_fail(L, "argument #%d (t1) must be greater than t0", nk ? 5 : 4);
    return MADE(pc_interp_prototype((pc_proto_kind)a[0].n, p.dim, n, p.list, nk ? k.list : none, t0, t1, &st));
}

/* interp.basis{g1, g2, ...}: Lua prototypes, the elements of the table (function 0) */
static int basis_cb(void *ud, double t, int n, double *g) {
    pcl_luafn *f = ud;
    for (int i = 0, failed = f->failed; i < n; i++) {
        char what[40];
        snprintf(what, sizeof what, "the basis function [%d]", i + 1);
        g[i] = pcl_luafn_call(f, 0, i + 1, what, 1, &t);
        if (f->failed > failed) return PC_EARG;
    }
    return PC_OK;
}

/* the basis: a list of 1 to 16 functions of t (out->n of them) */
static int read_basis(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    out->n = lua_istable(L, idx) ? (int)lua_rawlen(L, idx) : 0;   /* raw: a __len cannot raise inside the reader */
    if (out->n < 1 || out->n > 16) return 0;
    for (int i = 1; i <= out->n; i++) {
        lua_geti(L, idx, i);
        if (!pcl_callable(L, -1))
            pcl_argfail(L, 1, "[%d] must be a function of t, got %s", i, pcl_shown(L, lua_gettop(L)));
        lua_pop(L, 1);
    }
    return 1;
}
static const pcl_arg basis_args[] = {A_ANY("basis", read_basis, "a list of 1 to 16 functions of t"),
                                     A_POINTS("points", 0, 1, 16), A_NUMBERS("params", 1, 16),
                                     A_NUMOPT("t0", 0, NULL), A_NUMOPT("t1", 0, NULL), PCL_END};
PCL_BODY(i_basis, a) {
    int n = a[0].n, d = a[1].dim, st;
    if (a[1].n != n) return pcl_argfail(L, 2, "must hold %d points (one per basis function), got %d", n, a[1].n);
    need_count(L, 3, &a[2], n);
    if (a[3].present && !a[4].present) return pcl_argfail(L, 5, "must be a finite number (with t0), got nil");
    pcl_luafn *r = pcl_luafn_new(L, 1, (int[]){1});
    pc_curve *c = pc_interp_basis(d, n, a[1].list, a[2].list, basis_cb, pcl_luafn_free, r, a[3].present ? a[3].x : NAN,
                                  a[3].present ? a[4].x : NAN, &st);
    if (!c) pcl_luafn_free(r);
    MADE(c);
    /* the membership condition: do the weights sum to 1 over [t0, t1]? (the curve owns r) */
    double dev;
    CHECK(pc_interp_basis_membership(n, a[2].list, basis_cb, r, c->t0, c->t1, 65, &dev));
    return 1 + pcl_push_results(L, 0, "b n", dev <= 1e-9, dev);
}

static const pcl_arg r22_args[] = {A_POINTS("points", 0, 5, 5), PCL_END};
PCL_BODY(i_rational22, a) {
    int st, d = a[0].dim;
    double co[5 * PC_MAXDIM];
    MADE(pc_interp_rational22(d, a[0].list, co, &st));
    pcl_push_rows(L, d, 5, co);
    return 2;
}

/* ==== approx ================================================================================ */

#define F_OF_X A_FN("f", "a function of x", 0)

static const pcl_arg curve_args[] = {F_OF_X, A_NUMBERS("nodes", 2, 64), PCL_END};
PCL_BODY(a_curve, a) {
    pcl_luafn f = pcl_luafn_at(L, 1);
    int st, bad = 0;
    pc_curve *c = pc_approx_curve(pcl_luafn_of, &f, a[1].n, a[1].list, &bad, &st);
    if (!c && st == PC_ENONFINITE && !f.failed)   /* a kept error of f: raised by MADE */
        return pcl_fail(L, "f(%s) must be a finite number", pcl_pushnum(L, a[1].list[bad]));
    return MADE(c);
}

/* m and the divisor of the MSE: [, m] [, {m =, divisor =}], the table at argument k or k + 1
 * (read_m: an integer or the table); a points to m's value, then the table, then its keys */
static const char *const DIVISORS[] = {"m+1", "m", "m-1", NULL};   /* pc_mse_divisor */
static const pcl_arg mse_keys[] = {{.name = "m", .kind = PCL_INTEGER}, A_ENUM("divisor", DIVISORS), PCL_END};
static const pcl_arg mse_opts = A_OPTIONS("opts", mse_keys);
static int read_m(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    out->x = lua_tonumber(L, idx);
    return lua_istable(L, idx) || (lua_type(L, idx) == LUA_TNUMBER && out->x == floor(out->x) && isfinite(out->x));
}
#define A_M {.name = "m", .kind = PCL_ANY, .flags = PCL_OPT, .read = read_m, \
    .expect = "a number of samples or a table {m =, divisor =}"}

static int samples(lua_State *L, int k, const pcl_val *a, int lo, int hi, pc_mse_divisor *dv) {
    pcl_val t[2] = {0};
    const pcl_val *o = a + 2;
    if (lua_istable(L, k)) pcl_read_options(L, k, k, &mse_opts, t), o = t;
    double m = o[0].present ? o[0].x : a[0].present && !lua_istable(L, k) ? a[0].x : 100;
    if (m < lo || m > hi) {
        if (o[0].present) pcl_keyfail(L, "m", "must be a number of samples %d..%d, got %s", lo, hi, pcl_pushnum(L, m));
        pcl_argfail(L, k, "must be a number of samples %d..%d, got %s", lo, hi, pcl_pushnum(L, m));
    }
    *dv = (pc_mse_divisor)o[1].n;
    return (int)m;
}

static const pcl_arg mse_args[] = {F_OF_X, A_NUMBERS("nodes", 2, 64), A_M, A_OPTIONS("opts", mse_keys), PCL_END};
PCL_BODY(a_mse, a) {   /* f, nodes, m, opts, m =, divisor = */
    pc_mse_divisor dv;
    int m = samples(L, 3, &a[2], 1, 1000000, &dv);
    pcl_luafn f = pcl_luafn_at(L, 1);
    double mse;
    CHECK(pc_approx_mse(pcl_luafn_of, &f, a[1].n, a[1].list, m, &mse));
    if (pc_approx_rescale(mse, m, dv, &mse) != PC_OK) return pcl_fail(L, "the divisor m - 1 is 0 for m = 1");
    return pcl_push_results(L, 0, "n", mse);
}

static const pcl_arg optimal_args[] = {F_OF_X, A_NUM("a"), A_NUM("b"), A_INT("N", 3, 16), A_M,
                                       A_OPTIONS("opts", mse_keys), PCL_END};
PCL_BODY(a_optimal_nodes, a) {   /* f, a, b, N, m, opts, m =, divisor = */
    int N = (int)a[3].x, evals;
    pc_mse_divisor dv;
    int m = samples(L, 5, &a[4], N, 100000, &dv);
    pcl_luafn f = pcl_luafn_at(L, 1);
    double x[16], mse;
    CHECK(pc_approx_optimal_nodes(pcl_luafn_of, &f, a[1].x, a[2].x, N, m, x, &mse, &evals));
    pc_approx_rescale(mse, m, dv, &mse);   /* m >= N >= 3: the divisor is positive */
    return pcl_push_results(L, 0, "N n i", N, x, mse, evals);
}

static const pcl_arg chebyshev_args[] = {A_INT("N", 1, 64), A_NUMOPT("a", -1, NULL), A_NUMOPT("b", 1, NULL), PCL_END};

static const pcl_arg lmse_args[] = {F_OF_X, A_NUMBERS("nodes", 1, 64), A_NUM("a"),
    A_NUM("b"), A_INTOPT("M", 2, 1e9, 101, .expect = "an integer >= 2"), PCL_END};
PCL_BODY(a_lagrange_mse, a) {
    pcl_luafn f = pcl_luafn_at(L, 1);
    double mse;
    CHECK(pc_lagrange_mse_x(pcl_luafn_of, &f, a[1].n, a[1].list, a[2].x, a[3].x, (int)a[4].x, &mse));
    return pcl_push_results(L, 0, "n", mse);
}

/* approx.nelder_mead(f, x0 [, step]): f receives the point as numbers */
static const pcl_arg nm_args[] = {A_FN("f", "a function of n numbers", 0), A_NUMBERS("x0", 1, 32),
    {.name = "step", .kind = PCL_NUMBER, .flags = PCL_OPT | PCL_POS, .dflt = 0.1}, PCL_END};
PCL_BODY(a_nelder_mead, a) {
    double *x = a[1].list, fx;   /* x: the layer's buffer, minimised in place */
    int n = a[1].n, it;
    pcl_luafn f = pcl_luafn_at(L, 1);
    f.nargs = n;
    int st = pc_nelder_mead(n, pcl_luafn_point, &f, x, a[2].x, 1e-14, 1e-10, 20000, &fx, &it);
    if (f.failed) pcl_raise_status(L, pcl_name(L), PC_EARG);      /* the kept Lua error */
    if (st != PC_ENOCONVERGE) CHECK(st);
    return pcl_push_results(L, 0, "N n i", n, x, fx, it);
}

/* ==== the scheme points of the monograph (konop_schemes.h): each a point, or a vector where the
 * scheme's point is at infinity (N at u = 1/2 of conic.ed_scheme) ========================== */

PCL_BODY(l_smooth_scheme, a) {
    int d = a[0].n, n = (int)a[3].x;
    double p[(2 * 40 + 1) * PC_MAXDIM], *q = p + n * d, *m = q + n * d;   /* n <= 40 */
    CHECK(pc_oneratio_smooth_chain(d, a[0].v, a[1].v, a[2].v, n, a[4].x, p, q, m));
    return pcl_push_results(L, d, "P=P Q=P M=p", n, p, n, q, m);
}

static const char *const KINDS[] = {"ellipse", "hyperbola", NULL};

static const pcl_arg ed_scheme_args[] = {SP("A"), SP("B"), SP("C"), A_NUM("k"), A_NUM("u"), PCL_END};
static const pcl_arg five_scheme_args[] = {SP("A"), SP("B"), SP("C"), SP("D"), SP("E"), A_NUM("u"), PCL_END};
static const pcl_arg smooth_scheme_args[] = {SP("A"), SP("B"), SP("C"), A_INT("n", 1, 40), A_NUM("t"), PCL_END};
static const pcl_arg f_args[] = {A_NUM("fP"), A_NUM("fQ"), PCL_END};
#define KIND {.name = "kind", .kind = PCL_ENUM, .flags = PCL_OPT, .choices = KINDS}
static const pcl_arg foci_args[] = {SP("C"), SP("A"), SP("B"), KIND, PCL_END};
static const pcl_arg focal_args[] = {SP("C"), SP("A"), SP("B"), A_NUM("phi"), KIND, PCL_END};
static const pcl_arg ceva_scheme_args[] = {SP("A1"), SP("A2"), SP("A3"), A_NUM("k"), A_NUM("t"), PCL_END};
static const pcl_arg abct_args[] = {SP("A"), SP("B"), SP("C"), A_NUM("t"), PCL_END};
static const pcl_arg abcdt_args[] = {SP("A"), SP("B"), SP("C"), SP("D"), A_NUM("t"), PCL_END};

/* ==== the symbolic method of §2.2 (konop_triples.h): conic.scheme{...} ====================== */

/* the three point names of the list at the stack top (popped) into idx, added to t; 0 if it is
 * no such list */
static int names3(lua_State *L, pc_triples_table *t, int *idx) {
    int top = lua_gettop(L), ok = lua_istable(L, top) && lua_rawlen(L, top) == 3;
    for (int k = 0; ok && k < 3; k++) {
        ok = lua_geti(L, top, k + 1) == LUA_TSTRING;   /* the name stays alive in the table */
        if (ok && pc_triples_index(t, lua_tostring(L, -1), &idx[k]) != PC_OK)
            pcl_fail(L, "at most %d points", PC_TRIPLES_MAXPTS);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return ok;
}

PCL_BODY(l_scheme, a) {   /* the table, then triples, points, current, result, range */
    pc_triples_table t = {0};
    /* the known points first: their names are the keys of points */
    lua_getfield(L, 1, "points");
    lua_pushnil(L);
    while (lua_next(L, -2)) {
        if (lua_type(L, -2) != LUA_TSTRING) return pcl_fail(L, "points must be named (A1 = P(...))");
        const char *s = lua_tostring(L, -2);
        pcl_value *v = pcl_tovalue(L, -1);
        int st = pc_triples_give(&t, s, v ? v->n : 0, v ? v->h : NULL);
        if (st == PC_EDIM)   /* the one weight rule: within 1e-9 of 1 is a point (pc_snap_weight) */
            return pcl_fail(L, "points.%s must be a %s point", s,
                            t.dim ? (t.dim == 2 ? "2-D" : "3-D or more") : "2-D or more");
        if (st != PC_OK) return pcl_fail(L, "at most %d points", PC_TRIPLES_MAXPTS);
        lua_pop(L, 1);
    }
    if (!t.dim) return pcl_fail(L, "field points is empty");
    lua_getfield(L, 1, "triples");
    int it = lua_gettop(L), ntri = (int)lua_rawlen(L, it);
    if (ntri < 1 || ntri > PC_TRIPLES_MAXTRI) return pcl_fail(L, "1 to %d triples, got %d", PC_TRIPLES_MAXTRI, ntri);
    for (int j = 0; j < ntri; j++) {
        lua_geti(L, it, j + 1);
        if (!names3(L, &t, t.tri[j])) return pcl_fail(L, "triples[%d] must be three point names", j + 1);
    }
    lua_getfield(L, 1, "current");
    if (!names3(L, &t, t.cur))
        return pcl_fail(L, "field current must be three point names {\"C\", \"P\", \"Q\"}: C runs as P t' + Q t");
    pc_triples_plan plan;
    int st = pc_triples_table_plan(&t, ntri, a[4].s, &plan);
    if (st == PC_EDOMAIN)
        return pcl_fail(L, "the table does not determine %s (each new point needs two lines of known points)", a[4].s);
    CHECK(st);
    double t0 = a[5].present ? a[5].list[0] : 0, t1 = a[5].present ? a[5].list[1] : 1;
    MADE(pc_triples_curve(&plan, t.dim, t.pts, t0, t1, &st));
    lua_createtable(L, plan.nsteps, 0);
    for (int s = 0; s < plan.nsteps; s++) {
        char text[4 * 64];
        pc_triples_step_text(&plan, s, &t.nm, text, sizeof text);
        lua_pushstring(L, text);
        lua_rawseti(L, -2, s + 1);
    }
    return 2;
}

static const pcl_arg scheme_keys[] = {
    {.name = "triples", .kind = PCL_TABLE, .flags = PCL_REQ, .expect = "a list of {\"X\", \"Y\", \"Z\"}"},
    {.name = "points", .kind = PCL_TABLE, .flags = PCL_REQ, .expect = "a table {A1 = P(...), ...}"},
    {.name = "current", .kind = PCL_ANY, .flags = PCL_REQ, .expect = "{\"C\", \"P\", \"Q\"}"},
    {.name = "result", .kind = PCL_STRING, .flags = PCL_REQ},
    {.name = "range", .kind = PCL_NUMBERS, .lo = 2, .hi = 2}, PCL_END};
static const pcl_arg scheme_args[] = SPEC(scheme_keys);

/* ==== konopatsky: chapter 1 (konop_ch1.h) ================================================== */

PCL_BODY(k_area_theorem, a) {
    int n = a[0].n;
    double p[6 * PC_MAXDIM];
    pcl_point_rows(a, 6, n, p);
    pc_k_areas o;
    CHECK(pc_k_area_theorem(n, p, p + 3 * n, &o));
    return pcl_push_results(L, 0, "k=n lambda=N a=n b=n c=n collinear=b", o.k, 3, o.lambda, o.abc[0], o.abc[1],
                            o.abc[2], o.collinear);
}

PCL_BODY(k_o_theorem, a) {
    int m = a[0].n, n = a[0].dim;
    double *r = lua_newuserdatauv(L, sizeof(double) * (size_t)(m + m * (n + 1)), 0), *b = r + m, prod;
    CHECK(pc_k_o_theorem(n, m, a[0].list, a[1].v, a[2].v, r, b, &prod));
    pcl_push_results(L, 0, "n N", prod, m, r);
    pcl_push_values(L, m, n, b, 1);   /* weight 0: B at infinity */
    return 3;
}

PCL_BODY(k_simplex_ratio, a) {
    double m[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)], r;
    int d, cols;
    pc_why_call why;
    pcl_read_rows(L, 1, 0, m, &d, &cols);
    pcl_check(L, pc_k_simplex_ratio_rows(d, cols, m, &r, &why), why.row);
    return pcl_push_results(L, 0, "n", r);
}

PCL_BODY(k_meet_line_plane, a) {
    int n = a[0].n;
    if (n < 3) return pcl_fail(L, "a line and a plane meet in 3-D or more, got %d-D points", n);
    double k[PC_MAXDIM + 1], lam, pq[2];
    int st = pc_k_meet_line_plane(n, a[0].v, a[1].v, a[2].v, a[3].v, a[4].v, k, &lam, pq);
    if (st == PC_IMPROPER)      /* parallel: the common point at infinity, as meet() gives it */
        return pcl_push_results(L, n, "v n", k, lam);
    CHECK(st);
    return pcl_push_results(L, n, "p n n n", k, lam, pq[0], pq[1]);
}

PCL_BODY(k_moving_simplex, a) {
    int st;
    char why[200];
    pc_surface *s = pc_k_moving_simplex(a[0].obj, a[1].obj, a[2].obj, a[3].obj, &st);
    if (!s && pc_k_moving_simplex_why(st, a[0].obj, a[1].obj, a[2].obj, a[3].obj, why, sizeof why))
        return pcl_fail(L, "%s", why);
    return pcl_push_made_surface(L, s, &st, "konopatsky.moving_simplex");
}

/* The book's printed coordinates of a Bezier (rational or not) or B-spline curve's first piece */
PCL_BODY(k_equation, a) {
    const pc_curve *c = a[0].obj;
    for (int x = 0; x < c->dim; x++) {
        char buf[2048];
        CHECK(pc_k_curve_text(c, x, a[1].present ? a[1].s : "t", buf, sizeof buf));
        lua_pushstring(L, buf);
    }
    return c->dim;
}

static const pcl_arg lambdas[] = {A_NUM("l1"), A_NUM("l2"), A_NUM("l3"), PCL_END};
static const pcl_arg six[] = {SP("A1"), SP("A2"), SP("A3"), SP("B1"), SP("B2"), SP("B3"), PCL_END};
static const pcl_arg o_args[] = {{.name = "polygon", .kind = PCL_POINTS, .flags = PCL_SAMEDIM, .lo = 3, .hi = 64},
                                 SP("D1"), SP("D2"), PCL_END};
static const pcl_arg rows_args[] = {
    {.name = "rows", .kind = PCL_TABLE, .expect = "a list of k + 1 rows of barycentric parameters"}, PCL_END};
static const pcl_arg lp_args[] = {SP("A1"), SP("A2"), SP("P1"), SP("P2"), SP("P3"), PCL_END};
static const pcl_arg polar_args[] = {SP("C"), SP("A"), SP("B"), A_NUM("rho"), A_NUM("phi"), PCL_END};
static const pcl_arg rotate_args[] = {SP("C"), SP("A"), SP("B"), A_NUM("phi"), PCL_END};
static const pcl_arg eq_args[] = {A_CURVE("c", 0),
                                  {.name = "var", .kind = PCL_STRING, .flags = PCL_OPT, .shown = "\"t\""}, PCL_END};
static const pcl_arg ms_args[] = {A_CURVE("NA", 0), A_CURVE("NB", 0), A_CURVE("NC", 0), A_CURVE("gen", 0), PCL_END};

/* ==== registration ========================================================================== */

#define SIG(nm, f, a, forms, text) {.name = nm, .fn = f, .args = a, .sig = forms, .help = text}
static const pcl_fn conic_fns[] = {
    PCL_FN("conic.ed", made, abck_args, "curve", "(2.97) The engineering-discriminant arc A -> B with tangents CA, CB through K = kT1 + (1 - k)C on the median: k < 1/2 hyperbola, 1/2 parabola, > 1/2 ellipse."),
    PCL_FN("conic.ed_k", made, abcK_args, "k", "The discriminant k = CK/CT1 of the arc (2.97) through K on the median from C."),
    PCL_FN("conic.circle_k", made, abc_args, "k", "(2.107) k of the circular arc AB whose tangents meet at C (|CA| = |CB|): 1/2 + 2h^2/c^2."),
    PCL_FN("conic.ceva", made, ceva_args, "curve", "(2.104) Ceva's parametrisation: A2 (t = 0) to A1 (t = 1), tangents through A3; k = 1/4 parabola, < 1/4 hyperbola."),
    PCL_FN("conic.ceva_k", made, cevaK_args, "k", "(2.100) k = v31/v23 of the conic of the pencil through the point K."),
    PCL_FN("conic.ceva_to_ed", made, k_args, "k_ed", "§2.1.7 <-> §2.1.6: the engineering discriminant of Ceva's k, the two readings of one arc: k_ED = 2 sqrt k/(1 + 2 sqrt k) (Ceva's 1/4 is ED's 1/2)."),
    PCL_FN("conic.ed_to_ceva", made, k_args, "k", "The Ceva k of the engineering discriminant k in (0, 1): (k/(2(1 - k)))^2."),
    SIG("conic.parabola", made, parabola_args, "conic.parabola(A1, A3, A2) -> curve\nconic.parabola(A, C, B, tC) -> curve", "(2.58) The parabola of one ratio with tangents meeting at A3; or (2.62) the parabola through A, C (at t = tC), B."),
    SIG("conic.ellipse", c_ellipse, ellipse_args, "conic.ellipse{C =, A =, B = [, by = \"angle\"|\"radius\"|\"focal\"|\"compression\"|\"algebraic\"|\"conjugate\", quadrant = 1, range = {t0, t1}]} -> curve\nconic.ellipse{by = \"diameter\", K =, A =, B =, lambda =} -> curve", "The ellipse of centre C with semi-axes CA, CB in the book's forms (2.11), (2.15), (2.18), (2.24), sqrt, (2.32); by = \"diameter\" with K, A, B, lambda: §2.1.1.6."),
    SIG("conic.hyperbola", c_form, hyperbola_args, "conic.hyperbola{C =, A =, B = [, by = \"angle\"|\"radius\"|\"focal\", branch = 1|2, range = {t0, t1}]} -> curve", "The hyperbola of centre C, vertex A, imaginary semi-axis CB: (2.49), (2.53) with rho >= a, (2.56) with the branch through A by default (corrected ranges)."),
    SIG("conic.circle", c_circle, circle_args, "conic.circle{A =, B =, C = [, delta = | R =]} -> curve", "Circles: the arc AB with tangents through C (§2.1.8.1); delta: the locus angle AMC = delta (2.115); R: centre C, radius R (2.118)."),
    PCL_FN("conic.tilted", c_tilted, tilted_args, "curve, P, Q, K, Arot, tau", "§2.1.1.1 The ellipse of centre C, semi-axes m, n, its major axis at angle theta to AB; P, Q end the semi-axes, K = CP x AB (a vector at theta = 0), Arot is A rotated about C by 3 pi/2 - alpha - theta towards B (Q = (Arot - C) n/b + C), tau = angle ACK = pi - alpha - theta (Fig. 2.5)."),
    PCL_FN("conic.five_points", c_five_points, five_args, "curve, u", "§2.1.4 The conic through five points by Pascal's hexagon with the corrected S = BE x AD; u.A ... u.E are the parameters of the points."),
    SIG("conic.five_points2", c_five_points2, five2_args, "conic.five_points2{C =, A =, B =, p1 =, p2 =, q2 =, q3 =} -> curve", "§2.1.5 The conic A -> B through A1, A2, A3 given by their ratios in simplex CAB (corrected 2.93); p1 = q3 = 1 gives tangents CA, CB."),
    PCL_FN("conic.triples", made, triples_args, "curve", "§2.2 (b) The system of triples without a Pascal line; corrected, its locus is the conic through A1, A3, A4."),
    SIG("conic.redundant", c_redundant, redundant_args, "conic.redundant(C, A, B, u, v) -> point\nconic.redundant(C, A, B) -> curve", "(2.120) The redundant parametrisation of the plane K = AQ x BP; without u, v the curve (2.121) u = v = t."),
    SIG("conic.reparam", c_form, reparam_args, "conic.reparam{C =, A =, B = [, by = \"angle\"|\"sigma\", branch = 1|2, range = {t0, t1}]} -> curve", "§2.4 The one-ratio parabola by the angle MCA, or by sigma = CK + KM (the print's radius |CM| is not what its formula measures)."),
    SIG("conic.sinusoid", c_form, sinusoid_args, "conic.sinusoid{C =, A =, B =, k = {m, n, ...} [, range = {t0, t1}]} -> curve", "(2.145) The sinusoid whose axis is the circle of centre C through A, one wave number per generation."),
    SIG("conic.cycloid", c_form, cycloid_args, "conic.cycloid{C =, A =, B = [, concave = true, range = {t0, t1}]} -> curve", "§2.8 The convex (or concave) cycloid arc from B to A in the simplex CAB; range {0, 2pi} gives the whole arch."),
    PCL_FN("conic.cones", made, cones_args, "curve", "§2.6 The space cubic DP x NQ of two quadric cones over the arcs (2.97) fP, fQ in ABC, N = (D - A)n + A."),
    SIG("conic.contour", c_contour, contour_args, "conic.contour(A1, A2, A3, u, v [, du, dv]) -> curve", "(2.161) The general contour arc A1 -> A2 with tangents through A3, driven by the functions u(t), v(t)."),
    PCL_FN("conic.ed_scheme", made, ed_scheme_args, "{T1, K, T, N, P, Q, M}", "§2.1.6 Fig. 2.21 The points of the engineering-discriminant scheme at u: T1 the chord's midpoint, K = (T1 - C)k + C, T = A u' + B u, N its harmonic conjugate (a vector, at infinity, at u = 1/2), P = AK x CT, Q = BK x CT, M = AQ x BP = (2.97) at u."),
    PCL_FN("conic.five_scheme", made, five_scheme_args, "{S, U, V, M, U_B, U_D, R, U_E}", "§2.1.4 Fig. 2.15 The points of Pascal's hexagon A D M E B C at u (corrected): S = BE x AD, U = (A - C)u + C, V = SU x CB, M = UE x VD, and U_B = BE x CA, U_D = CA x ED, R = CB x ED, U_E = RS x CA, whose positions on CA give the u of B, D, E."),
    PCL_FN("conic.ceva_scheme", made, ceva_scheme_args, "{M3, M, t3, r}", "(2.105) Ceva's arc read by the engineering discriminant: M3 = A1(1 - t3) + A2 t3 on A1A2, M = M3(1 - r) + A3 r, t3 = (1 - t)^2/(k t^2 + (1 - t)^2), r = t(1 - t)/(1 - t(1 - kt)); M is (2.104) at t."),
    PCL_FN("conic.focal_point", made, focal_args, "M, F, pa, pb", "The focal-simplex forms (2.16)/(2.17) and, corrected, (2.54)/(2.55): the point at the focal angle phi written in the simplex A B F, M = (A - F) pa + (B - F) pb + F, F = F2 = C - (A - C)e of the ellipse (CA the major semi-axis) or F1 = C + (A - C)e of the hyperbola; the points of (2.18), (2.56)."),
    PCL_FN("conic.foci", made, foci_args, "F1, F2, e, p", "The foci, eccentricity and focal parameter b^2/a of the ellipse of centre C and semi-axes CA, CB (the foci on the longer), or of the hyperbola of vertex A and imaginary semi-axis CB; any dimension; CA and CB must be perpendicular."),
    PCL_FN("conic.cones_excluded", made, f_args, "{u, ...}", "§2.6 The parameters u the cubic of two cones must avoid, sorted: (2.148)'s pole, (2.151) u = (1 +- 1/sqrt(1 - 2 fP))/2 (the print's sign corrected) for fP < 1/2, and the roots (2.153) of Q's denominator."),
    PCL_FN("conic.scheme", l_scheme, scheme_args, "curve, steps", "§2.2 The symbolic method: a table of collinear triples (each a line of the ruler construction) becomes its construction: the given points, the current point C = P t' + Q t (current = {\"C\", \"P\", \"Q\"}), and every other point the meet of two lines of the table whose other points are known, in the order found (steps, e.g. \"A = A3A2 x A4A5\"); the curve of the result over range (default {0, 1}). Baluba's systems (a) and (b) of Fig. 2.28 are two such tables."),
    PCL_END};

static const pcl_fn oneratio_call[] = {{.name = "oneratio", .fn = o_simplex, .args = abc_args, .result = "curve", .self = pcl_self_table, .selftype = "table", .key = "__call", .help = "The same as oneratio.simplex."}, PCL_END};
static const pcl_fn oneratio_fns[] = {
    PCL_FN("oneratio.simplex", o_simplex, abc_args, "curve", "(3.1) The moving-simplex curve A t'^2 + B t + C t t' (corrected): tangent BC at B."),
    PCL_FN("oneratio.tetra", made, abcd_args, "curve", "(3.2) The arc of one ratio in the simplex DABC; planar, through the centroid at t = 1/2."),
    PCL_FN("oneratio.bezier3", made, bezier3_args, "curve", "(3.4) The cubic Bezier curve of the de Casteljau scheme (corrected powers)."),
    PCL_FN("oneratio.smooth", made, smooth_args, "curve", "§3.6 The contour arc of smoothness order n (2 by default): zero curvature at the ends for n >= 2."),
    PCL_FN("oneratio.desargues", made, abcd_args, "curve", "(3.6) The Desargues arc A -> D with tangents AC and BD, through the centroid."),
    PCL_FN("oneratio.double_contact", o_double_contact, contact_args, "curve", "§3.4 M = P(1 - f(v)) + Q f(v) of the arcs (2.97) kp and kq; f a function of v or a number (default v)."),
    PCL_FN("oneratio.closed", made, closed_args, "curve", "§3.5 The closed curve P u' + Q u through B, scheme 1 or 2 (corrected Q): wing profiles."),
    PCL_FN("oneratio.levels", o_levels, levels_args, "{{P1, ...}, {Q1, ...}, ..., {M}}", "Fig. 3.4 The de Casteljau levels at the one ratio t (for A, C1, C2, B: P1 P2 P3, Q1 Q2, M of (3.4))."),
    PCL_FN("oneratio.simplex_scheme", made, abct_args, "{N =, M =}", "Fig. 3.1 The moving simplex at t: N = A t' + C t on AC and M = N t' + B t on NB (the point of (3.1))."),
    PCL_FN("oneratio.desargues_scheme", made, abcdt_args, "{T =, S =, R =, N =, J =, Q =, M =, pJ =, qJ =}", "Fig. 3.12 The points of the Desargues arc's scheme at t; T, S, R are directions (vectors) at t = 1/2."),
    PCL_FN("oneratio.smooth_scheme", l_smooth_scheme, smooth_scheme_args, "{P = {P1, ..., Pn}, Q = {Q1, ..., Qn}, M}", "§3.6 Figs. 3.9, 3.10 The chain points of M_n at t: P_i = P_(i-1) + t(P_(i+1) - P_(i-1)) on A..C, Q_i likewise on C..B, M = P_n + t(Q1 - P_n) (for n = 2: AP1/AP2 = P1P2/P1C = CQ1/CQ2 = Q1Q2/Q1B = P2M/P2Q1 = t)."),
    PCL_END};

static const pcl_fn interp_fns[] = {
    PCL_FN("interp.lagrange", i_lagrange, lagrange_args, "curve", "§4.2 The book's interpolation curve through the points (uniform t = j/n by default): Lagrange in t, a Bezier curve."),
    SIG("interp.weights", i_weights, weights_args, "interp.weights(n, t) -> {w1, ..., w(n+1)}\ninterp.weights(params, t) -> {w1, ...}", "The weights of the interpolation curve of the book's order n (n + 1 nodes at j/n: (4.10)-(4.28) for n = 2..6), or at the node parameters params; they sum to 1. With t a param the weights are equations, the polynomials the Maple program of §4.8 prints."),
    PCL_FN("interp.controls", i_lagrange, lagrange_args, "{C1, ...}", "The Bezier control points of the interpolation curve ((4.9), C1... of §4.4-4.7)."),
    PCL_FN("interp.conic", made, akbk_args, "curve", "§4.1 The conic arc through A, K (u = 1/2), B with discriminant k (corrected apex C = K/k' - (A + B)k/(2k'))."),
    SIG("interp.arc", i_arc, arc_args, "interp.arc(points, C2 [, Cn] [, params]) -> curve", "§4.9 The curve through the points with the end tangent handles C2 (and Cn): M'(0) = N(C2 - M1); at uniform u, or at the increasing node parameters params (the curve then runs over [params[1], params[#params]])."),
    PCL_FN("interp.adaptive", i_adaptive, adaptive_args, "params", "§4.10 The adaptive parameters v_j = (x_1 - x_j)/(x_1 - x_n) along an axis (1 by default)."),
    SIG("interp.prototype", i_prototype, proto_args, "interp.prototype(\"desargues\"|\"rational\"|\"trig\", points [, t0, t1]) -> curve\ninterp.prototype(\"exp\"|\"exp1\", points, k [, t0, t1]) -> curve", "§4.11 Interpolation on the book's prototypes: (4.35), (4.37), (4.39) with exponents k, its affine variant, (4.40); desargues and rational take 4 points, the others 3."),
    SIG("interp.basis", i_basis, basis_args, "interp.basis({g1, g2, ...}, points, params [, t0, t1]) -> curve, affine, deviation", "§4.11 The simplex-replacement engine on any basis of Lua functions g_i(t), nodes at params; affine: the weights sum to 1 (membership condition) over [t0, t1], deviation the largest |sum - 1|."),
    SIG("interp.rational22", i_rational22, r22_args, "interp.rational22({M1, ..., M5}) -> curve, coef", "(4.38) Per coordinate (a1 t^2 + a2 t + a3)/(a4 t^2 + a5 t + 1) through 5 points at t = j/4."),
    PCL_END};

static const pcl_fn approx_fns[] = {
    PCL_FN("approx.curve", a_curve, curve_args, "curve", "§5.1 The approximation curve through (x_j, f(x_j)) at uniform t."),
    SIG("approx.mse", a_mse, mse_args, "approx.mse(f, nodes [, m] [, {m =, divisor = \"m+1\"|\"m\"|\"m-1\"}]) -> mse", "§5.1 The book's mean-square error: samples t = i/m (m = 100), residual f(x(t)) - y(t), the SSE divided by m + 1 (the book's; divisor = \"m\" or \"m-1\" for comparison: SSE/m gives 0.0000287 for Runge)."),
    SIG("approx.optimal_nodes", a_optimal_nodes, optimal_args, "approx.optimal_nodes(f, a, b, N [, m] [, {m =, divisor =}]) -> nodes, mse, evals", "§5.1 The optimal nodes of the N-node curve on [a, b]: deterministic multi-start Nelder-Mead over ordered nodes."),
    PCL_FN("approx.chebyshev", made, chebyshev_args, "nodes", "The N Chebyshev nodes (roots) on [a, b], increasing."),
    PCL_FN("approx.lagrange_mse", a_lagrange_mse, lmse_args, "mse", "§5.2 The MSE of Lagrange's polynomial on the nodes against f over M = 101 uniform x."),
    PCL_FN("approx.nelder_mead", a_nelder_mead, nm_args, "x, fx, iterations", "Deterministic Nelder-Mead minimisation of f(x1, ..., xn) from the list x0."),
    PCL_END};

static const pcl_fn ch1_fns[] = {
    PCL_FN("konopatsky.area_k", made, lambdas, "k", "(1.2) The theorem on triangle areas: k = (1 + l1 l2 l3)/((1 + l1)(1 + l2)(1 + l3)) = S_B1B2B3/S_A1A2A3."),
    PCL_FN("konopatsky.area_theorem", k_area_theorem, six, "{k, lambda, a, b, c, collinear}", "(1.2) for B1 on A1A2, B2 on A2A3, B3 on A3A1, any dimension: the signed area ratio k, lambda_i = (AiA(i+1)Bi), the proof's a = (B1A1A2) = -1/(1 + l1), b, c; collinear is corollary 1 (k = 0, Menelaus l1 l2 l3 = -1). B3 = A3 gives k = ab (corollary 2), B1 = A1 and B3 = A3 give k = -b (corollary 3)."),
    PCL_FN("konopatsky.o_theorem", k_o_theorem, o_args, "product, ratios, B", "(1.4) The O-theorem: Bi = AiA(i+1) x D1D2 (B at infinity for a side parallel to d), ratios (AiA(i+1)Bi) and their product, (-1)^m with the closing factor (A_m A_1 B_m) the print omits."),
    {.name = "konopatsky.simplex_ratio", .fn = k_simplex_ratio, .args = rows_args, .result = "ratio", .sig = "konopatsky.simplex_ratio({{p1, q1, r1}, {p2, q2, r2}, {p3, q3, r3}}) -> ratio", .help = "The S-theorem (and with 4 rows the V-theorem, any k + 1 rows): the measure of the simplex of the points with these barycentric parameters over the simplex's own is their determinant (the printed V-theorem's det/det is corrected)."},
    PCL_FN("konopatsky.meet_line_plane", k_meet_line_plane, lp_args, "K, lambda, p, q", "§1.3.5 The meet of line A1A2 and plane P1P2P3 by the V-theorem, in 3-D and n-D: K = (A2 - A1) lambda + A1 = (P1 - P3) p + (P2 - P3) q + P3. A point at infinity (a vector) and lambda = inf when they are parallel; an error when the line lies in the plane or (n > 3) they do not meet."),
    PCL_FN("konopatsky.polar", made, polar_args, "M", "(2.117)/(2.118) The point at distance rho from C at the angle phi from ray CA towards CB: M = (A - C) rho sin(gamma - phi)/(b sin gamma) + (B - C) rho sin phi/(a sin gamma) + C, any dimension."),
    PCL_FN("konopatsky.rotate", made, rotate_args, "Q", "(2.138) A rotated about C by phi towards B in the plane CAB (polar with rho = |CA|)."),
    PCL_FN("konopatsky.moving_simplex", k_moving_simplex, ms_args, "surface", "Fig. 1.2 The moving-simplex surface M(u, v) = (NA - NC) p(v) + (NB - NC) q(v) + NC on three guide curves of one domain (the book's are lines N = (P' - P)(phi(u) - phi(0))/(phi(1) - phi(0)) + P), the generator a 2-D curve gen(v) = (p, q) in the natural parameters of the moving simplex (a conic of ch. 2 gives conic sections)."),
    PCL_FN("konopatsky.equation", k_equation, eq_args, "x, y, ...", "The coordinates of a polynomial or rational curve (its first piece) as the book prints them: x = (a_n t^n + ... + a_0)/(t^m + ... + d_0), expanded in powers of var (\"t\"), the denominator monic; a polynomial curve gives polynomials (the ch. 4-5 coefficients of c:monomial)."),
    PCL_END};

/* The tables conic, oneratio, interp, approx and konopatsky, in the order :help lists them;
 * oneratio(A, B, C) is oneratio.simplex. */
void pcl_open_konopatsky(lua_State *L) {
    int module = lua_gettop(L);
    pcl_new_table(L, module, "conic", conic_fns, NULL);
    pcl_new_table(L, module, "oneratio", oneratio_fns, oneratio_call);
    pcl_new_table(L, module, "interp", interp_fns, NULL);
    pcl_new_table(L, module, "approx", approx_fns, NULL);
    pcl_new_table(L, module, "konopatsky", ch1_fns, NULL);
}
