/* Binding of Korotky's shells of 2015 (stdlib/books/korotky/pencils4.h, conic_shells.h,
 * conic_props.h), added to the table `korotky` by pcl_open_korotky:
 *   korotky.two_pencils{omega = {g1, g2, g3}, delta = {g1, g2, g3}}  -> 4-D surface (Fig. 1b)
 *   korotky.conic_revolve{A =, B =, nA =, nB =, ridge =}             -> surface (Fig. 3b)
 *   korotky.ridge_shell{U =, R =, V =, T1 =, T2 =, P =, H =, Q =}    -> surface (Fig. 3d)
 *   korotky.conic_elements(arc | {a, b, c, d, e, f})  -> {kind, coef, center, axes, semi,
 *                                                         asymptotes} (Fig. 2c)
 * A pencil's spanning point g is a 4-D curve or a fixed 4-D point (a vector: the point at
 * infinity of its direction, as the basis point Z of the z axis). */
#include <math.h>
#include <string.h>
#include "pcl_curve.h"
#include "pcl_point.h"
#include "pencils4.h"
#include "conic_shells.h"
#include "conic_props.h"

/* The field `name` of the table at arg as a curve of dimension dim, or (allow_const) a point
 * or vector made a constant curve: a new reference the caller releases. */
static pc_curve *field_curve(lua_State *L, const char *fn, int arg, const char *name, int dim,
                             int allow_const) {
    lua_getfield(L, arg, name);
    pc_curve *c = pcl_tocurve(L, -1);
    if (c) {
        if (c->dim != dim)
            pcl_error(L, "%s: field %s must be a %d-D curve, got a %d-D one", fn, name, dim, c->dim);
        lua_pop(L, 1);
        return pc_curve_retain(c);
    }
    pcl_value *v = allow_const ? pcl_tovalue(L, -1) : NULL;
    if (!v || v->n != dim || !(v->h[dim] == 0 || v->h[dim] == 1))
        pcl_error(L, "%s: field %s must be a %d-D curve%s, got %s", fn, name, dim,
                  allow_const ? ", point or vector" : "", pcl_shown(L, lua_gettop(L)));
    double cp[2 * (PC_MAXDIM + 1)];
    memcpy(cp, v->h, sizeof(double) * (size_t)(dim + 1));
    memcpy(cp + dim + 1, v->h, sizeof(double) * (size_t)(dim + 1));
    int st;
    c = pc_curve_bezier(dim, 2, cp, &st);
    if (!c) pcl_statuserror(L, fn, st, name);
    lua_pop(L, 1);
    return c;
}

static const char *meet_why(int st) {
    return st == PC_ESAME_LINE ? "the planes share a line (a plane of one pencil holds the other's basis points)"
           : st == PC_ESKEW    ? "the flats do not meet (a pencil's points span only a line)"
                               : pc_strerror(st);
}

/* ---- the key construction in 4-D --------------------------------------------------------- */

static void read_pencil(lua_State *L, const char *fn, const char *name, pc_pencil_point *g) {
    if (lua_getfield(L, 1, name) != LUA_TTABLE || luaL_len(L, -1) != 3)
        pcl_error(L, "%s: field %s must be a list of three 4-D points, vectors or curves, got %s", fn,
                  name, pcl_shown(L, lua_gettop(L)));
    int t = lua_gettop(L);
    for (int i = 0; i < 3; i++) {
        lua_geti(L, t, i + 1);
        pc_curve *c = pcl_tocurve(L, -1);
        pcl_value *v = c ? NULL : pcl_tovalue(L, -1);
        if (c && c->dim == 4) {
            g[i].c = c;
        } else if (v && v->n == 4 && (v->h[4] == 0 || v->h[4] == 1)) {
            g[i].c = NULL;
            memcpy(g[i].h, v->h, sizeof g[i].h);
        } else {
            pcl_error(L, "%s: field %s [%d] must be a 4-D point, vector or curve, got %s", fn, name,
                      i + 1, pcl_shown(L, lua_gettop(L)));
        }
        lua_pop(L, 1);   /* the table in the argument keeps the curve alive */
    }
    lua_pop(L, 1);
}

static int l_two_pencils(lua_State *L) {
    const char *fn = "korotky.two_pencils";
    if (!lua_istable(L, 1))
        return pcl_argerror_full(L, fn, 1, 1, "pencils", "a table {omega = {...}, delta = {...}}");
    pc_pencil_point om[3], de[3];
    read_pencil(L, fn, "omega", om);
    read_pencil(L, fn, "delta", de);
    int st;
    pc_surface *s = pc_surface_two_pencils(om, de, &st);
    if (!s) return pcl_statuserror(L, fn, st, NULL);
    /* a surface whose every meet fails is a mistake in the data: say so now */
    double out[5];
    st = s->fn(s->ud, .5, .5, 0, out);
    if (st != PC_OK) {
        pc_surface_release(s);
        return pcl_error(L, "%s: no single meet at u = v = 0.5: %s", fn, meet_why(st));
    }
    pcl_pushsurface(L, s, "korotky.two_pencils");
    return 1;
}

/* ---- the rotational sweep and the ridge shell ---------------------------------------------- */

static void field_vec3(lua_State *L, const char *fn, const char *name, int want_point, double *out) {
    lua_getfield(L, 1, name);
    pcl_value *v = pcl_tovalue(L, -1);
    if (!v || v->n != 3 || v->h[3] != (want_point ? 1 : 0))
        pcl_error(L, "%s: field %s must be a 3-D %s, got %s", fn, name, want_point ? "point" : "vector",
                  pcl_shown(L, lua_gettop(L)));
    memcpy(out, v->h, 3 * sizeof(double));
    lua_pop(L, 1);
}

static int l_conic_revolve(lua_State *L) {
    const char *fn = "korotky.conic_revolve";
    if (!lua_istable(L, 1))
        return pcl_argerror_full(L, fn, 1, 1, "data", "a table {A =, B =, nA =, nB =, ridge =}");
    double A[3], B[3], nA[3], nB[3];
    field_vec3(L, fn, "A", 1, A);
    field_vec3(L, fn, "B", 1, B);
    field_vec3(L, fn, "nA", 0, nA);
    field_vec3(L, fn, "nB", 0, nB);
    pc_curve *l = field_curve(L, fn, 1, "ridge", 3, 0);
    int st;
    double u = 0;
    pc_surface *s = pc_surface_conic_revolve(A, B, nA, nB, l, &u, &st);
    pc_curve_release(l);
    if (!s) {
        const char *why = st == PC_ECOLLINEAR ? "the ridge point lies on the axis AB"
                          : st == PC_EDOMAIN  ? "no conic through A, B and the ridge point with those tangent planes"
                          : st == PC_ECOINCIDENT ? "A and B coincide"
                          : st == PC_EZERO    ? "a tangent plane's normal is the zero vector"
                                              : pc_strerror(st);
        if (st == PC_ECOLLINEAR || st == PC_EDOMAIN)
            return pcl_error(L, "%s: %s at u = %s", fn, why, pcl_pushnum(L, u));
        return pcl_error(L, "%s: %s", fn, why);
    }
    pcl_pushsurface(L, s, "korotky.conic_revolve");
    return 1;
}

static int l_ridge_shell(lua_State *L) {
    const char *fn = "korotky.ridge_shell";
    if (!lua_istable(L, 1))
        return pcl_argerror_full(L, fn, 1, 1, "guides", "a table {U =, R =, V =, T1 =, T2 =, P =, H =, Q =}");
    static const char *names[8] = {"U", "R", "V", "T1", "T2", "P", "H", "Q"};
    pc_curve *c[8] = {0};
    for (int i = 0; i < 8; i++) {
        /* every field checked before the first curve is made, so that an error leaks none */
        lua_getfield(L, 1, names[i]);
        int ok = pcl_tocurve(L, -1) != NULL;
        pcl_value *v = ok ? NULL : pcl_tovalue(L, -1);
        if (!ok && !(v && v->n == 3 && (v->h[3] == 0 || v->h[3] == 1) && isfinite(v->h[0]) &&
                     isfinite(v->h[1]) && isfinite(v->h[2])))
            return pcl_error(L, "%s: field %s must be a 3-D curve, point or vector, got %s", fn, names[i],
                             pcl_shown(L, lua_gettop(L)));
        if (ok && pcl_tocurve(L, -1)->dim != 3)
            return pcl_error(L, "%s: field %s must be a 3-D curve, got a %d-D one", fn, names[i],
                             pcl_tocurve(L, -1)->dim);
        lua_pop(L, 1);
    }
    for (int i = 0; i < 8; i++) c[i] = field_curve(L, fn, 1, names[i], 3, 1);
    pc_ridge_shell g = {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]};
    int st;
    double u = 0;
    pc_surface *s = pc_surface_ridge_shell(&g, &u, &st);
    for (int i = 0; i < 8; i++) pc_curve_release(c[i]);
    if (!s && (st == PC_EDOMAIN || st == PC_ESKEW || st == PC_ECOINCIDENT || st == PC_EZERO))
        return pcl_error(L, "%s: no conic arc of the profile at u = %s (%s)", fn, pcl_pushnum(L, u),
                         st == PC_EDOMAIN ? "a T must lie between the tangent lines" : pc_strerror(st));
    if (!s) return pcl_statuserror(L, fn, st, NULL);
    pcl_pushsurface(L, s, "korotky.ridge_shell");
    return 1;
}

/* ---- the conic's centre, axes and asymptotes ---------------------------------------------- */

static int l_conic_elements(lua_State *L) {
    const char *fn = "korotky.conic_elements";
    double coef[6];
    pc_curve *c = pcl_tocurve(L, 1);
    if (c) {
        if (c->dim != 2 || c->kind != PC_CURVE_BEZIER || c->degree != 2 || c->ncp != 3)
            return pcl_argerror_full(L, fn, 1, 1, "arc", "a 2-D conic arc (a rational quadratic Bezier curve)");
        int st = pc_conic_from_arc(c->cp, coef);
        if (st == PC_ECOLLINEAR) return pcl_error(L, "%s: the arc is a straight segment (weight 0): no conic", fn);
        if (st != PC_OK) return pcl_statuserror(L, fn, st, "argument #1 (arc)");
    } else if (lua_istable(L, 1) && luaL_len(L, 1) == 6) {
        for (int i = 0; i < 6; i++) {
            lua_geti(L, 1, i + 1);
            if (lua_type(L, -1) != LUA_TNUMBER || !isfinite(lua_tonumber(L, -1)))
                return pcl_error(L, "%s: argument #1 (coefficients) [%d] must be a finite number, got %s", fn,
                                 i + 1, pcl_shown(L, lua_gettop(L)));
            coef[i] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
    } else {
        return pcl_argerror_full(L, fn, 1, 1, "arc", "a 2-D conic arc or the coefficients {a, b, c, d, e, f}");
    }
    pc_conic_elements el;
    int st = pc_conic_elements_of(coef, &el);
    if (st == PC_EDOMAIN) return pcl_error(L, "%s: a degenerate conic (a line pair, or no real points)", fn);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, "argument #1");
    lua_createtable(L, 0, 6);
    static const char *kinds[3] = {"ellipse", "parabola", "hyperbola"};
    lua_pushstring(L, kinds[el.kind]);
    lua_setfield(L, -2, "kind");
    lua_createtable(L, 6, 0);
    for (int i = 0; i < 6; i++) {
        lua_pushnumber(L, coef[i]);
        lua_rawseti(L, -2, i + 1);
    }
    lua_setfield(L, -2, "coef");
    if (el.central) {
        pcl_pushpoint(L, 2, el.center);
        lua_setfield(L, -2, "center");
        lua_createtable(L, 2, 0);
        for (int i = 0; i < 2; i++) {
            lua_pushnumber(L, el.semi[i]);
            lua_rawseti(L, -2, i + 1);
        }
        lua_setfield(L, -2, "semi");
    }
    lua_createtable(L, 2, 0);
    for (int i = 0; i < 2; i++) {
        pcl_pushvector(L, 2, el.axis[i]);
        lua_rawseti(L, -2, i + 1);
    }
    lua_setfield(L, -2, "axes");
    if (el.nasym) {
        lua_createtable(L, 2, 0);
        for (int i = 0; i < 2; i++) {
            pcl_pushvector(L, 2, el.asym[i]);
            lua_rawseti(L, -2, i + 1);
        }
        lua_setfield(L, -2, "asymptotes");
    }
    return 1;
}

/* Called by pcl_open_korotky with the korotky table on top of the stack. */
void pcl_korotky_shells(lua_State *L) {
    static const luaL_Reg fns[] = {
        {"two_pencils", l_two_pencils},
        {"conic_revolve", l_conic_revolve},
        {"ridge_shell", l_ridge_shell},
        {"conic_elements", l_conic_elements},
        {NULL, NULL}};
    luaL_setfuncs(L, fns, 0);
}
