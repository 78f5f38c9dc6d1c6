/* Binding of Korotky's shells of 2015 (stdlib/books/korotky/pencils4.h, conic_shells.h,
 * conic_props.h), added to the table `korotky` by pcl_open_korotky:
 *   korotky.two_pencils{omega = {g1, g2, g3}, delta = {g1, g2, g3}}  -> 4-D surface (Fig. 1b)
 *   korotky.conic_revolve{A =, B =, nA =, nB =, ridge =}             -> surface (Fig. 3b)
 *   korotky.ridge_shell{U =, R =, V =, T1 =, T2 =, P =, H =, Q =}    -> surface (Fig. 3d)
 *   korotky.conic_elements(arc | {a, b, c, d, e, f})  -> the table of c:conic() (Fig. 2c:
 *                                                         kind, coef, center, axes, semi, ...)
 * A pencil's spanning point g is a 4-D curve or a fixed 4-D point (a vector: the point at
 * infinity of its direction, as the basis point Z of the z axis). */
#include <math.h>
#include <string.h>
#include "pcl_args.h"
#include "pcl_curve.h"
#include "pcl_point.h"
#include "pencils4.h"
#include "conic_shells.h"
#include "conic_props.h"
#include "quadratic.h"
#include "pcl_books.h"

/* A guide of dimension a->dim: a curve (out->obj), or a fixed point or vector (out->v, the
 * weight snapped by the one rule) when a->lo is 1. */
static int read_guide(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    pc_curve *c = pcl_tocurve(L, idx);
    out->obj = c;
    if (c) return c->dim == a->dim;
    pcl_value *v = a->lo ? pcl_tovalue(L, idx) : NULL;
    if (!v || v->n != a->dim) return 0;
    memcpy(out->v, v->h, sizeof(double) * (size_t)(a->dim + 1));
    return pcl_snap_weight(a->dim, out->v) != PC_KIND_WEIGHTED;
}

/* A new reference to the guide as a curve (a fixed value: a constant curve). */
static pc_curve *guide_curve(lua_State *L, const pcl_val *g, int dim) {
    if (g->obj) return pc_curve_retain(g->obj);
    double cp[2 * (PC_MAXDIM + 1)];
    memcpy(cp, g->v, sizeof(double) * (size_t)(dim + 1));
    memcpy(cp + dim + 1, g->v, sizeof(double) * (size_t)(dim + 1));
    int st;
    pc_curve *c = pc_curve_bezier(dim, 2, cp, &st);
    if (!c) pcl_statuserror(L, pcl_name(L), st, NULL);
    return c;
}

static const char *meet_why(int st) {
    return st == PC_ESAME_LINE ? "the planes share a line (a plane of one pencil holds the other's basis points)"
           : st == PC_ESKEW    ? "the flats do not meet (a pencil's points span only a line)"
                               : pc_strerror(st);
}

/* ---- the key construction in 4-D --------------------------------------------------------- */

/* a pencil: three 4-D points, vectors or curves (the table in the argument keeps them alive) */
static int read_pencil(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    (void)a;
    if (!lua_istable(L, idx) || luaL_len(L, idx) != 3) return 0;
    pc_pencil_point *g = (pc_pencil_point *)out->list;
    static const pcl_arg g4 = {.kind = PCL_ANY, .dim = 4, .lo = 1};
    for (int i = 0; i < 3; i++) {
        pcl_val v = {0};
        lua_geti(L, idx, i + 1);
        if (!read_guide(L, lua_gettop(L), &g4, &v))
            pcl_keyfail(L, a->name, "[%d] must be a 4-D point, vector or curve, got %s", i + 1, pcl_shown(L, lua_gettop(L)));
        lua_pop(L, 1);
        g[i].c = v.obj;
        if (!v.obj) memcpy(g[i].h, v.v, sizeof g[i].h);
    }
    return 1;
}
#define PENCIL(nm) {.name = nm, .kind = PCL_ANY, .flags = PCL_REQ, .read = read_pencil, .shown = "{g1, g2, g3}", \
                    .expect = "a list of three 4-D points, vectors or curves"}
static const pcl_arg pencil_keys[] = {PENCIL("omega"), PENCIL("delta"), PCL_END};
static const pcl_arg pencils_args[] = {{.name = "pencils", .kind = PCL_OPTIONS, .flags = PCL_CALLTABLE, .keys = pencil_keys}, PCL_END};

static int l_two_pencils(lua_State *L) {
    pc_pencil_point om[3], de[3];
    pcl_val a[3] = {{0}, {.list = (double *)om}, {.list = (double *)de}};
    PCL_READ(L, a);
    int st;
    pc_surface *s = pc_surface_two_pencils(om, de, &st);
    if (!s) return pcl_statuserror(L, pcl_name(L), st, NULL);
    /* a surface whose every meet fails is a mistake in the data: say so now */
    double out[5];
    st = s->fn(s->ud, .5, .5, 0, out);
    if (st != PC_OK) {
        pc_surface_release(s);
        return pcl_fail(L, "no single meet at u = v = 0.5: %s", meet_why(st));
    }
    pcl_pushsurface(L, s, "korotky.two_pencils");
    return 1;
}

/* ---- the rotational sweep and the ridge shell ---------------------------------------------- */

static const pcl_arg revolve_keys[] = {{.name = "A", .kind = PCL_POINT, .flags = PCL_REQ, .dim = 3},
                                       {.name = "B", .kind = PCL_POINT, .flags = PCL_REQ, .dim = 3},
                                       {.name = "nA", .kind = PCL_VECTOR, .flags = PCL_REQ, .dim = 3},
                                       {.name = "nB", .kind = PCL_VECTOR, .flags = PCL_REQ, .dim = 3},
                                       {.name = "ridge", .kind = PCL_CURVE, .flags = PCL_REQ, .dim = 3}, PCL_END};
static const pcl_arg revolve_args[] = {{.name = "data", .kind = PCL_OPTIONS, .flags = PCL_CALLTABLE, .keys = revolve_keys}, PCL_END};

static int l_conic_revolve(lua_State *L) {
    pcl_val a[6] = {0};
    PCL_READ(L, a);
    int st;
    double u = 0;
    pc_surface *s = pc_surface_conic_revolve(a[1].v, a[2].v, a[3].v, a[4].v, a[5].obj, &u, &st);
    if (!s) {
        const char *why = st == PC_ECOLLINEAR ? "the ridge point lies on the axis AB"
                          : st == PC_EDOMAIN  ? "no conic through A, B and the ridge point with those tangent planes"
                          : st == PC_ECOINCIDENT ? "A and B coincide"
                          : st == PC_EZERO    ? "a tangent plane's normal is the zero vector"
                                              : pc_strerror(st);
        if (st == PC_ECOLLINEAR || st == PC_EDOMAIN) return pcl_fail(L, "%s at u = %s", why, pcl_pushnum(L, u));
        return pcl_fail(L, "%s", why);
    }
    pcl_pushsurface(L, s, "korotky.conic_revolve");
    return 1;
}

#define GUIDE(nm) {.name = nm, .kind = PCL_ANY, .flags = PCL_REQ, .read = read_guide, .dim = 3, .lo = 1, \
                   .expect = "a 3-D curve, point or vector"}
static const pcl_arg ridge_keys[] = {GUIDE("U"), GUIDE("R"), GUIDE("V"), GUIDE("T1"), GUIDE("T2"), GUIDE("P"),
                                     GUIDE("H"), GUIDE("Q"), PCL_END};
static const pcl_arg ridge_args[] = {{.name = "guides", .kind = PCL_OPTIONS, .flags = PCL_CALLTABLE, .keys = ridge_keys}, PCL_END};

static int l_ridge_shell(lua_State *L) {
    pcl_val a[9] = {0};
    PCL_READ(L, a);   /* every guide checked before the first curve is made: an error leaks none */
    pc_curve *c[8];
    for (int i = 0; i < 8; i++) c[i] = guide_curve(L, &a[i + 1], 3);
    pc_ridge_shell g = {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]};
    int st;
    double u = 0;
    pc_surface *s = pc_surface_ridge_shell(&g, &u, &st);
    for (int i = 0; i < 8; i++) pc_curve_release(c[i]);
    if (!s && (st == PC_EDOMAIN || st == PC_ESKEW || st == PC_ECOINCIDENT || st == PC_EZERO))
        return pcl_fail(L, "no conic arc of the profile at u = %s (%s)", pcl_pushnum(L, u),
                        st == PC_EDOMAIN ? "a T must lie between the tangent lines" : pc_strerror(st));
    if (!s) return pcl_statuserror(L, pcl_name(L), st, NULL);
    pcl_pushsurface(L, s, "korotky.ridge_shell");
    return 1;
}

/* ---- the conic's centre, axes and asymptotes ---------------------------------------------- */

/* a 2-D conic arc (a rational quadratic Bezier curve, out->obj) or six finite numbers (out->v) */
static int read_conic(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    (void)a;
    pc_curve *c = pcl_tocurve(L, idx);
    out->obj = c;
    /* an arc, or the line pair of korotky.conic_arc with T = W (two quadratic pieces, told
     * apart in l_conic_elements) */
    if (c) return c->dim == 2 && c->kind == PC_CURVE_BEZIER && c->degree == 2 && (c->ncp == 3 || c->ncp == 5);
    if (!lua_istable(L, idx) || luaL_len(L, idx) != 6) return 0;
    for (int i = 0; i < 6; i++) {
        lua_geti(L, idx, i + 1);
        out->v[i] = lua_tonumber(L, -1);
        if (lua_type(L, -1) != LUA_TNUMBER || !isfinite(out->v[i]))
            pcl_argfail(L, 1, "[%d] must be a finite number, got %s", i + 1, pcl_shown(L, lua_gettop(L)));
        lua_pop(L, 1);
    }
    return 1;
}
static const pcl_arg elements_args[] = {{.name = "arc | {a, b, c, d, e, f}", .kind = PCL_ANY, .read = read_conic,
                                         .expect = "a 2-D conic arc (a rational quadratic Bezier curve) or the coefficients {a, b, c, d, e, f}"},
                                        PCL_END};

static int l_conic_elements(lua_State *L) {
    pcl_val a[1] = {0};
    PCL_READ(L, a);
    /* the kernel's conic (geom/quadratic.h): an arc by its homogeneous control points, its
     * weights as they are; the same table as c:conic() */
    pc_conic_info o;
    const pc_curve *c = a[0].obj;
    if (c && c->ncp == 5) {   /* the degenerate section AOD of Fig. 3c: no centre, no axes */
        double q[5][2];
        for (int i = 0; i < 5; i++) {
            double w = c->cp[3 * i + 2];
            q[i][0] = w != 0 ? c->cp[3 * i] / w : NAN;
            q[i][1] = w != 0 ? c->cp[3 * i + 1] / w : NAN;
        }
        /* both pieces straight: U, its midpoint, W and W, its midpoint, V */
        int pair = 1;
        for (int k = 0; k < 2 && pair; k++) {
            const double *a = q[2 * k], *m = q[2 * k + 1], *b = q[2 * k + 2];
            double cr = (m[0] - a[0]) * (b[1] - a[1]) - (m[1] - a[1]) * (b[0] - a[0]);
            pair = isfinite(cr) && fabs(cr) <= 1e-12 * (1 + hypot(b[0] - a[0], b[1] - a[1]) * hypot(m[0] - a[0], m[1] - a[1]));
        }
        if (!pair)
            return pcl_argfail(L, 1, "must be a 2-D conic arc (one rational quadratic piece) or the coefficients {a, b, c, d, e, f}, got a curve of two pieces");
        return pcl_fail(L, "the line pair U W V (T = W, the weight infinite) is a degenerate conic: its lines meet at W = P(%f, %f)",
                        q[2][0], q[2][1]);
    }
    int st = c ? pc_conic_info_rquad(((pc_curve *)a[0].obj)->cp, &o) : pc_conic_info_coef(a[0].v, &o);
    if (st == PC_ECOLLINEAR) return pcl_fail(L, "the arc is a straight segment (weight 0): no conic");
    if (st == PC_EDOMAIN) return pcl_fail(L, "a degenerate conic (a line pair, or no real points)");
    if (st != PC_OK) return pcl_statuserror(L, pcl_name(L), st, "argument #1");
    pcl_push_conic_info(L, &o);
    return 1;
}

static const pcl_fn fns[] = {
    PCL_FN("korotky.conic_elements", l_conic_elements, elements_args, "{kind, coef, center, axes, semi, foci, e, p, asymptotes, ...}", "The conic of a 2-D conic arc with any weights (or of a x^2 + b xy + c y^2 + d x + e y + f = 0): the table of c:conic(): kind, coefficients, centre (a parabola's vertex), unit principal axes (major or transverse first), semi-axes, foci, e, p, a hyperbola's unit asymptote directions, and for an arc mu, w and the engineering discriminant k."),
    PCL_FN("korotky.two_pencils", l_two_pencils, pencils_args, "s", "The 4-D key construction: S(u, v) is the meet of the 2-plane through omega's three points at u and delta's at v (each a 4-D curve or a fixed 4-D point; a vector is a point at infinity). Draw it through a 4-D -> 2-D map (map.matrix of 3 x 5)."),
    PCL_FN("korotky.conic_revolve", l_conic_revolve, revolve_args, "s", "A conic turned about AB: for each point T of the ridge (a 3-D curve) the arc from A to B through T tangent to the planes with normals nA at A and nB at B."),
    PCL_FN("korotky.ridge_shell", l_ridge_shell, ridge_args, "s", "A shell whose profiles are two conic arcs, U to R through T1 and R to V through T2, tangent towards P at U, along H at the ridge R and towards Q at V (3-D curves, points or vectors): G1 along the ridge; v in [0, 2]."),
    PCL_END};

/* Called by pcl_open_korotky with the korotky table on top of the stack. */
void pcl_korotky_shells(lua_State *L) { pcl_register(L, -1, fns, 0); }
