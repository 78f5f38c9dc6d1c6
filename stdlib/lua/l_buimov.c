/* Binding of the textbook's constructions (Buimov; stdlib/books/buimov/plane_curves.h, buimov.h,
 * reconstruct.h), in two tables:
 *   plane.*   ch. 3: circle3 circle2r circle_slopes arc3 classify rotate_conic conic_coef
 *             ellipse parabola hyperbola points
 *   buimov.*  ch. 2.8.6, 4, 5: knots basis bspline bernstein blend hermite hermite_coeffs
 *             spline helix sphere sphere_frame reconstruct calibrate
 * Curves and surfaces are the one curve and surface types, maps the one map type. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "pcl_curve.h"
#include "pcl_point.h"
#include "plane_curves.h"
#include "buimov.h"
#include "reconstruct.h"
#include "linalg.h"

static void push_curve_or_raise(lua_State *L, pc_curve *c, int st, const char *fn, const char *kind) {
    if (!c) pcl_statuserror(L, fn, st, NULL);
    pcl_pushcurve(L, c, kind);
}

/* A list of at least min points at arg, Cartesian rows of one dimension (dim: 0 any, else
 * required), in a scratch userdata left on the stack. */
static double *read_points(lua_State *L, const char *fn, int arg, const char *what, int min,
                           int *count, int *dim) {
    if (!lua_istable(L, arg)) {
        lua_pushfstring(L, "a list of at least %d points", min);
        pcl_argerror_full(L, fn, arg, arg, what, lua_tostring(L, -1));
    }
    int m = (int)luaL_len(L, arg);
    if (m < min) pcl_error(L, "%s: argument #%d (%s) must be a list of at least %d points, got %d",
                           fn, arg, what, min, m);
    if (m > 100000) pcl_error(L, "%s: argument #%d (%s) holds too many points (%d)", fn, arg, what, m);
    int d = *dim;
    double *x = NULL;
    for (int i = 1; i <= m; i++) {
        lua_geti(L, arg, i);
        pcl_value *v = pcl_tovalue(L, -1);
        if (!v) pcl_error(L, "%s: argument #%d (%s) item [%d] must be a point, got %s", fn, arg,
                          what, i, pcl_shown(L, -1));
        if (d == 0) d = v->n;
        if (v->n != d) pcl_error(L, "%s: argument #%d (%s) item [%d] is %d-D, but %s %d-D: "
                                 "dimensions cannot be mixed", fn, arg, what, i, v->n,
                                 *dim ? "it must be" : "item [1] is", d);
        if (fabs(v->h[d] - 1) > PC_WEIGHT_TOL)
            pcl_error(L, "%s: argument #%d (%s) item [%d] must be a point (weight 1), got weight %s",
                      fn, arg, what, i, pcl_pushnum(L, v->h[d]));
        if (!x) {
            lua_pop(L, 1);
            x = lua_newuserdatauv(L, sizeof(double) * (size_t)m * (size_t)d, 0);
            lua_geti(L, arg, i);
            v = pcl_tovalue(L, -1);
        }
        for (int k = 0; k < d; k++) {
            if (!isfinite(v->h[k])) pcl_error(L, "%s: argument #%d (%s) item [%d] has NaN or "
                                              "infinite coordinates", fn, arg, what, i);
            x[(size_t)(i - 1) * d + k] = v->h[k];
        }
        lua_pop(L, 1);
    }
    *count = m;
    *dim = d;
    return x;
}

/* An integer >= lo at arg. */
static int check_int(lua_State *L, const char *fn, int arg, const char *what, int lo, int hi) {
    double x = pcl_checknum(L, fn, arg, what);
    if (x != floor(x) || x < lo || x > hi) {
        lua_pushfstring(L, "an integer from %d to %d", lo, hi);
        pcl_argerror_full(L, fn, arg, arg, what, lua_tostring(L, -1));
    }
    return (int)x;
}

/* A point (weight 1) of dimension dim (0: any) at arg, its coordinates into out; the house
 * error naming fn otherwise.  Returns its dimension. */
static int loc(lua_State *L, const char *fn, int arg, const char *what, int dim, double *out) {
    pcl_value *v = pcl_tovalue(L, arg);
    if (!v) pcl_argerror_full(L, fn, arg, arg, what, "a point");
    if (dim && v->n != dim)
        pcl_error(L, "%s: argument #%d (%s) must be %d-D, got %d-D", fn, arg, what, dim, v->n);
    if (fabs(v->h[v->n] - 1) > PC_WEIGHT_TOL)
        pcl_argerror_full(L, fn, arg, arg, what, "a point (weight 1)");
    for (int k = 0; k < v->n; k++) {
        out[k] = v->h[k];
        if (!isfinite(out[k])) pcl_argerror_full(L, fn, arg, arg, what, "a point with finite coordinates");
    }
    return v->n;
}

/* The same for a vector (weight 0). */
static void vec(lua_State *L, const char *fn, int arg, const char *what, int dim, double *out) {
    pcl_value *v = pcl_tovalue(L, arg);
    if (!v) pcl_argerror_full(L, fn, arg, arg, what, "a vector");
    if (v->n != dim)
        pcl_error(L, "%s: argument #%d (%s) must be %d-D, got %d-D", fn, arg, what, dim, v->n);
    if (v->h[v->n] != 0) pcl_argerror_full(L, fn, arg, arg, what, "a vector (weight 0), e.g. B - A");
    for (int k = 0; k < dim; k++) {
        out[k] = v->h[k];
        if (!isfinite(out[k])) pcl_argerror_full(L, fn, arg, arg, what, "a vector with finite coordinates");
    }
}

/* ==== plane.* ================================================================================ */

/* a circle as a table {centre =, r =, d =, e =, f =, curve =} (curve: the whole circle) */
static void push_circle(lua_State *L, const pc_circle_eq *c, const char *fn) {
    lua_createtable(L, 0, 7);
    pcl_pushpoint(L, 2, c->c);
    lua_setfield(L, -2, "centre");
    lua_pushnumber(L, c->r); lua_setfield(L, -2, "r");
    lua_pushnumber(L, c->d); lua_setfield(L, -2, "d");
    lua_pushnumber(L, c->e); lua_setfield(L, -2, "e");
    lua_pushnumber(L, c->f); lua_setfield(L, -2, "f");
    int st;
    pc_curve *cv = pc_curve_ellipse(c->c, c->r, c->r, 0, 2 * 3.14159265358979323846, &st);
    push_curve_or_raise(L, cv, st, fn, "circle");
    lua_setfield(L, -2, "curve");
}

static void circle_status(lua_State *L, const char *fn, int st) {
    if (st == PC_ECOINCIDENT) pcl_error(L, "%s: two of the points coincide", fn);
    if (st == PC_ECOLLINEAR) pcl_error(L, "%s: the three points lie on one line, so no circle passes through them", fn);
    if (st != PC_OK) pcl_statuserror(L, fn, st, NULL);
}

static int l_circle3(lua_State *L) {
    const char *fn = "plane.circle3";
    double p[3][2];
    static const char *names[3] = {"A", "B", "C"};
    for (int i = 0; i < 3; i++) loc(L, fn, i + 1, names[i], 2, p[i]);
    pc_circle_eq c;
    circle_status(L, fn, pc_circle3(p[0], p[1], p[2], &c));
    push_circle(L, &c, fn);
    int st;
    pc_curve *arc = pc_curve_arc3(p[0], p[1], p[2], &st);
    push_curve_or_raise(L, arc, st, fn, "arc");
    lua_setfield(L, -2, "arc");
    return 1;
}

static int l_arc3(lua_State *L) {
    const char *fn = "plane.arc3";
    double p[3][2];
    static const char *names[3] = {"A", "B", "C"};
    for (int i = 0; i < 3; i++) loc(L, fn, i + 1, names[i], 2, p[i]);
    int st;
    pc_curve *arc = pc_curve_arc3(p[0], p[1], p[2], &st);
    if (!arc) circle_status(L, fn, st);
    pcl_pushcurve(L, arc, "arc");
    return 1;
}

static int l_circle2r(lua_State *L) {
    const char *fn = "plane.circle2r";
    double a[2], b[2];
    loc(L, fn, 1, "A", 2, a);
    loc(L, fn, 2, "B", 2, b);
    double r = pcl_checknum(L, fn, 3, "r");
    if (!(r > 0)) pcl_argerror_full(L, fn, 3, 3, "r", "a positive number");
    pc_circle_eq c[2];
    int st = pc_circle2r(a, b, r, c);
    if (st == PC_ECOINCIDENT) return pcl_error(L, "%s: the points A and B coincide (any circle of radius r through A will do)", fn);
    if (st == PC_EDOMAIN) return pcl_error(L, "%s: the points are %s apart, farther than the diameter 2r = %s", fn,
                                           pcl_pushnum(L, hypot(b[0] - a[0], b[1] - a[1])), pcl_pushnum(L, 2 * r));
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    push_circle(L, &c[0], fn);
    push_circle(L, &c[1], fn);
    return 2;
}

static int l_circle_slopes(lua_State *L) {
    const char *fn = "plane.circle_slopes";
    double a[2];
    loc(L, fn, 1, "A", 2, a);
    double m1 = pcl_checknum(L, fn, 2, "m1"), xe = pcl_checknum(L, fn, 3, "x_end");
    double m2 = pcl_checknum(L, fn, 4, "m2");
    pc_circle_eq c[2];
    double ends[4];
    int n, st = pc_circle_slopes(a, m1, xe, m2, c, ends, &n);
    if (st == PC_EDOMAIN && xe == a[0])
        return pcl_error(L, "%s: argument #3 (x_end) equals the abscissa of A", fn);
    if (st == PC_EDOMAIN) return pcl_error(L, "%s: no circle through A has these slopes", fn);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    double dir[2] = {xe > a[0] ? 1 : -1, xe > a[0] ? m1 : -m1};
    for (int i = 0; i < n; i++) {
        push_circle(L, &c[i], fn);
        pcl_pushpoint(L, 2, ends + 2 * i);
        lua_setfield(L, -2, "finish");
        pc_curve *arc = pc_curve_arc_dir(c[i].c, c[i].r, a, dir, ends + 2 * i, &st);
        push_curve_or_raise(L, arc, st, fn, "arc");
        lua_setfield(L, -2, "arc");
    }
    return n;
}

static const char *conic_names[3] = {"ellipse", "parabola", "hyperbola"};

static int l_classify(lua_State *L) {
    const char *fn = "plane.classify";
    double a = pcl_checknum(L, fn, 1, "a"), b = pcl_checknum(L, fn, 2, "b"), c = pcl_checknum(L, fn, 3, "c");
    pc_conic_class k;
    if (pc_conic_classify(a, b, c, &k) != PC_OK)
        return pcl_error(L, "%s: a = b = c = 0 is a line, not a conic", fn);
    lua_pushstring(L, conic_names[k]);
    lua_pushnumber(L, b * b - 4 * a * c);
    return 2;
}

/* a list {a, b, c, d, e, f} at arg */
static void read_coef(lua_State *L, const char *fn, int arg, double k[6]) {
    if (!lua_istable(L, arg) || luaL_len(L, arg) != 6)
        pcl_argerror_full(L, fn, arg, arg, "coef", "a list {a, b, c, d, e, f}");
    for (int i = 0; i < 6; i++) {
        lua_geti(L, arg, i + 1);
        int ok;
        k[i] = lua_tonumberx(L, -1, &ok);
        if (!ok || !isfinite(k[i]))
            pcl_error(L, "%s: argument #%d (coef) item [%d] must be a finite number, got %s", fn,
                      arg, i + 1, pcl_shown(L, -1));
        lua_pop(L, 1);
    }
}

static void push_coef(lua_State *L, const double k[6]) {
    lua_createtable(L, 6, 0);
    for (int i = 0; i < 6; i++) {
        lua_pushnumber(L, k[i]);
        lua_rawseti(L, -2, i + 1);
    }
}

static int l_rotate_conic(lua_State *L) {
    const char *fn = "plane.rotate_conic";
    double k[6], out[6];
    read_coef(L, fn, 1, k);
    pc_conic_rotate(k, pcl_checknum(L, fn, 2, "alpha"), out);
    push_coef(L, out);
    return 1;
}

static int l_conic_value(lua_State *L) {
    const char *fn = "plane.conic_value";
    double k[6], x[2];
    read_coef(L, fn, 1, k);
    loc(L, fn, 2, "X", 2, x);
    lua_pushnumber(L, pc_conic_value(k, x[0], x[1]));
    return 1;
}

static int l_conic_coef(lua_State *L) {
    const char *fn = "plane.conic_coef";
    static const char *kinds[] = {"ellipse", "hyperbola", "parabola", NULL};
    const char *ks = lua_tostring(L, 1);
    int kind = -1;
    for (int i = 0; ks && kinds[i]; i++) if (!strcmp(ks, kinds[i])) kind = i;
    if (kind < 0) pcl_argerror_full(L, fn, 1, 1, "kind", "\"ellipse\", \"hyperbola\" or \"parabola\"");
    double c[2];
    loc(L, fn, 2, "centre", 2, c);
    double A = pcl_checknum(L, fn, 3, kind == 2 ? "p" : "A");
    double out[6];
    if (kind == 2) pc_conic_parabola_coef(c[0], c[1], A, out);
    else {
        double B = pcl_checknum(L, fn, 4, "B");
        if (!(A > 0) || !(B > 0)) return pcl_error(L, "%s: the semi-axes A and B must be positive", fn);
        (kind ? pc_conic_hyperbola_coef : pc_conic_ellipse_coef)(c[0], c[1], A, B, out);
    }
    push_coef(L, out);
    return 1;
}

static int l_ellipse(lua_State *L) {
    const char *fn = "plane.ellipse";
    double c[2];
    loc(L, fn, 1, "centre", 2, c);
    double A = pcl_checknum(L, fn, 2, "A"), B = pcl_checknum(L, fn, 3, "B");
    double t0 = pcl_optnum(L, fn, 4, "th0", 0), t1 = pcl_optnum(L, fn, 5, "th1", t0 + 2 * 3.14159265358979323846);
    if (!(A > 0) || !(B > 0)) return pcl_error(L, "%s: the semi-axes A and B must be positive", fn);
    if (!(t1 > t0)) return pcl_error(L, "%s: need th0 < th1", fn);
    int st;
    pc_curve *cv = pc_curve_ellipse(c, A, B, t0, t1, &st);
    push_curve_or_raise(L, cv, st, fn, "ellipse");
    return 1;
}

static int l_parabola(lua_State *L) {
    const char *fn = "plane.parabola";
    double p = pcl_checknum(L, fn, 1, "p"), t0 = pcl_checknum(L, fn, 2, "th0"), t1 = pcl_checknum(L, fn, 3, "th1");
    if (!(p > 0)) pcl_argerror_full(L, fn, 1, 1, "p", "a positive number");
    if (!(t1 > t0)) return pcl_error(L, "%s: need th0 < th1", fn);
    int st;
    pc_curve *cv = pc_curve_parabola(p, t0, t1, &st);
    push_curve_or_raise(L, cv, st, fn, "parabola");
    return 1;
}

static int l_hyperbola(lua_State *L) {
    const char *fn = "plane.hyperbola";
    double A = pcl_checknum(L, fn, 1, "A"), B = pcl_checknum(L, fn, 2, "B");
    double t0 = pcl_checknum(L, fn, 3, "t0"), t1 = pcl_checknum(L, fn, 4, "t1");
    if (!(A > 0) || !(B > 0)) return pcl_error(L, "%s: the semi-axes A and B must be positive", fn);
    if (!(t1 > t0)) return pcl_error(L, "%s: need t0 < t1", fn);
    if (fabs(t0) > 300 || fabs(t1) > 300) return pcl_error(L, "%s: |t| beyond 300 overflows ch t", fn);
    int st;
    pc_curve *cv = pc_curve_hyperbola(A, B, t0, t1, &st);
    push_curve_or_raise(L, cv, st, fn, "hyperbola");
    return 1;
}

/* plane.points(kind, {A =, B =, step =, n =, method =}) */
static double opt_field(lua_State *L, const char *fn, const char *field, int required, double dflt) {
    int t = lua_getfield(L, 2, field);
    double x = dflt;
    if (t == LUA_TNIL && required) pcl_error(L, "%s: argument #2 (opts) needs the field %s", fn, field);
    if (t != LUA_TNIL) {
        int ok;
        x = lua_tonumberx(L, -1, &ok);
        if (!ok || !isfinite(x))
            pcl_error(L, "%s: argument #2 (opts) field %s must be a finite number, got %s", fn,
                      field, pcl_shown(L, -1));
    }
    lua_pop(L, 1);
    return x;
}

static int l_points(lua_State *L) {
    const char *fn = "plane.points";
    static const char *kinds[] = {"circle", "ellipse", "parabola", "hyperbola", "hyperbola_ch", NULL};
    static const char *methods[] = {"param", "recurrence", "rational", "explicit", NULL};
    const char *ks = lua_tostring(L, 1);
    int kind = -1, method = 0;
    for (int i = 0; ks && kinds[i]; i++) if (!strcmp(ks, kinds[i])) kind = i;
    if (kind < 0) pcl_argerror_full(L, fn, 1, 1, "kind", "\"circle\", \"ellipse\", \"parabola\", \"hyperbola\" or \"hyperbola_ch\"");
    if (!lua_istable(L, 2)) pcl_argerror_full(L, fn, 2, 2, "opts", "a table {A =, B =, step =, n =, method =}");
    double A = opt_field(L, fn, "A", 1, 0), B = opt_field(L, fn, "B", kind == 1 || kind >= 3, 0);
    double step = opt_field(L, fn, "step", 1, 0), n = opt_field(L, fn, "n", 1, 0);
    if (n != floor(n) || n < 0 || n > 1000000)
        pcl_error(L, "%s: argument #2 (opts) field n must be a whole number of steps, got %s", fn, pcl_pushnum(L, n));
    if (lua_getfield(L, 2, "method") != LUA_TNIL) {
        const char *ms = lua_tostring(L, -1);
        method = -1;
        for (int i = 0; ms && methods[i]; i++) if (!strcmp(ms, methods[i])) method = i;
        if (method < 0) pcl_error(L, "%s: argument #2 (opts) field method must be \"param\", \"recurrence\", \"rational\" or \"explicit\"", fn);
    }
    lua_pop(L, 1);
    if (method >= 2 && kind != 0) pcl_error(L, "%s: the %s method is the circle's only", fn, methods[method]);
    if (!(A > 0) || ((kind == 1 || kind >= 3) && !(B > 0)))
        pcl_error(L, "%s: A (and B) must be positive", fn);
    double *xy = lua_newuserdatauv(L, sizeof(double) * 2 * (size_t)(n + 1), 0);
    int st = pc_conic_points((pc_gen_kind)kind, (pc_gen_method)method, A, B, step, (int)n, xy);
    if (st == PC_EDOMAIN)
        return pcl_error(L, "%s: the steps leave the curve's domain (the explicit circle beyond "
                         "x = -A, the sec form at 90 degrees)", fn);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    lua_createtable(L, (int)n + 1, 0);
    for (int i = 0; i <= (int)n; i++) {
        pcl_pushpoint(L, 2, xy + 2 * i);
        lua_rawseti(L, -2, i + 1);
    }
    return 1;
}

/* ==== buimov.* =============================================================================== */

static int l_knots(lua_State *L) {
    const char *fn = "buimov.knots";
    int m, d = 0;
    double *p = read_points(L, fn, 1, "points", 2, &m, &d);
    int k = check_int(L, fn, 2, "k", 2, m < PC_CURVE_MAXDEG + 1 ? m : PC_CURVE_MAXDEG + 1);
    double *q = lua_newuserdatauv(L, sizeof(double) * (size_t)(m + k), 0);
    pc_book_knots(d, m, p, k, q);
    lua_createtable(L, m + k, 0);
    for (int j = 0; j < m + k; j++) {
        lua_pushinteger(L, (lua_Integer)q[j]);
        lua_rawseti(L, -2, j + 1);
    }
    return 1;
}

static int l_basis(lua_State *L) {
    const char *fn = "buimov.basis";
    int i = check_int(L, fn, 1, "i", 0, 1000000), k = check_int(L, fn, 2, "k", 1, PC_CURVE_MAXDEG + 1);
    double t = pcl_checknum(L, fn, 3, "t");
    if (!lua_istable(L, 4)) pcl_argerror_full(L, fn, 4, 4, "knots", "a list of numbers");
    int nq = (int)luaL_len(L, 4);
    if (nq > 1000000) pcl_error(L, "%s: argument #4 (knots) is too long", fn);
    double *q = lua_newuserdatauv(L, sizeof(double) * (size_t)(nq ? nq : 1), 0);
    for (int j = 0; j < nq; j++) {
        lua_geti(L, 4, j + 1);
        int ok;
        q[j] = lua_tonumberx(L, -1, &ok);
        if (!ok || !isfinite(q[j])) pcl_error(L, "%s: argument #4 (knots) item [%d] must be a finite number, got %s", fn, j + 1, pcl_shown(L, -1));
        if (j > 0 && q[j] < q[j - 1]) pcl_error(L, "%s: argument #4 (knots) must not decrease (item [%d])", fn, j + 1);
        lua_pop(L, 1);
    }
    double N;
    if (pc_book_basis(q, nq, i, k, t, &N) != PC_OK)
        return pcl_error(L, "%s: N(i = %d, k = %d) needs the knots q[i] .. q[i + k]: %d knots given", fn, i, k, nq);
    lua_pushnumber(L, N);
    return 1;
}

static int l_bspline(lua_State *L) {
    const char *fn = "buimov.bspline";
    int m, d = 0;
    double *p = read_points(L, fn, 1, "points", 2, &m, &d);
    int k = check_int(L, fn, 2, "k", 2, m < PC_CURVE_MAXDEG + 1 ? m : PC_CURVE_MAXDEG + 1);
    int st;
    pc_curve *c = pc_curve_book_bspline(d, m, p, k, &st);
    if (!c && st == PC_EDOMAIN)
        return pcl_error(L, "%s: a vertex is repeated so often that the knots leave no span", fn);
    push_curve_or_raise(L, c, st, fn, "bspline");
    return 1;
}

static int l_bernstein(lua_State *L) {
    const char *fn = "buimov.bernstein";
    int n = check_int(L, fn, 1, "n", 0, 1000), i = check_int(L, fn, 2, "i", 0, 1000);
    lua_pushnumber(L, pc_bernstein(n, i, pcl_checknum(L, fn, 3, "t")));
    return 1;
}

static int l_blend(lua_State *L) {
    double F[4];
    pc_hermite_blend(pcl_checknum(L, "buimov.blend", 1, "t"), F);
    for (int i = 0; i < 4; i++) lua_pushnumber(L, F[i]);
    return 4;
}

/* P1, P2 (points), D1, D2 (vectors) [, t]: the data of a Hermite segment */
static int hermite_args(lua_State *L, const char *fn, double *p, double *dv, double *t) {
    int d = loc(L, fn, 1, "P1", 0, p);
    loc(L, fn, 2, "P2", d, p + d);
    vec(L, fn, 3, "D1", d, dv);
    vec(L, fn, 4, "D2", d, dv + d);
    *t = pcl_optnum(L, fn, 5, "t", 1);
    if (!(*t > 0)) pcl_argerror_full(L, fn, 5, 5, "t", "a positive number (the segment's parameter length)");
    return d;
}

static int l_hermite(lua_State *L) {
    const char *fn = "buimov.hermite";
    double p[2 * PC_MAXDIM], dv[2 * PC_MAXDIM], t;
    int d = hermite_args(L, fn, p, dv, &t);
    double u[2] = {0, t};
    int st;
    pc_curve *c = pc_curve_hermite(d, 2, p, dv, NULL, u, 0, &st);
    push_curve_or_raise(L, c, st, fn, "hermite");
    return 1;
}

static int l_hermite_coeffs(lua_State *L) {
    const char *fn = "buimov.hermite_coeffs";
    double p[2 * PC_MAXDIM], dv[2 * PC_MAXDIM], t, B[4 * PC_MAXDIM];
    int d = hermite_args(L, fn, p, dv, &t);
    int st = pc_hermite_coeffs(d, p, p + d, dv, dv + d, t, B);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    pcl_pushpoint(L, d, B);
    for (int i = 1; i < 4; i++) pcl_pushvector(L, d, B + i * d);
    return 4;
}

static int l_spline(lua_State *L) {
    const char *fn = "buimov.spline";
    int n, d = 0;
    double *p = read_points(L, fn, 1, "points", 2, &n, &d);
    int top = lua_gettop(L);               /* the points' scratch userdata is on the stack */
    pc_book_ends ends = PC_BOOK_NATURAL;
    int chord = 0, have_d = 0;
    double d0[PC_MAXDIM], d1[PC_MAXDIM];
    if (!lua_isnoneornil(L, 2)) {
        if (!lua_istable(L, 2)) pcl_argerror_full(L, fn, 2, 2, "opts", "a table {ends =, d0 =, d1 =, param =}");
        if (lua_getfield(L, 2, "ends") != LUA_TNIL) {
            const char *e = lua_tostring(L, -1);
            static const char *names[] = {"clamped", "natural", "cyclic", "anticyclic"};
            int found = -1;
            for (int i = 0; e && i < 4; i++) if (!strcmp(e, names[i])) found = i;
            if (found < 0) pcl_error(L, "%s: argument #2 (opts) field ends must be \"clamped\", \"natural\", \"cyclic\" or \"anticyclic\"", fn);
            ends = (pc_book_ends)found;
        }
        lua_pop(L, 1);
        if (lua_getfield(L, 2, "param") != LUA_TNIL) {
            const char *s = lua_tostring(L, -1);
            if (s && !strcmp(s, "chord")) chord = 1;
            else if (!s || strcmp(s, "uniform"))
                pcl_error(L, "%s: argument #2 (opts) field param must be \"uniform\" or \"chord\"", fn);
        }
        lua_pop(L, 1);
        static const char *dn[2] = {"d0", "d1"};
        for (int i = 0; i < 2; i++) {
            if (lua_getfield(L, 2, dn[i]) != LUA_TNIL) {
                pcl_value *v = pcl_tovalue(L, -1);
                if (!v || v->n != d || v->h[d] != 0)
                    pcl_error(L, "%s: argument #2 (opts) field %s must be a %d-D vector (the end tangent), got %s", fn, dn[i], d, pcl_shown(L, -1));
                memcpy(i ? d1 : d0, v->h, sizeof(double) * (size_t)d);
                have_d++;
            }
            lua_pop(L, 1);
        }
        if (ends == PC_BOOK_NATURAL && have_d == 2 && lua_getfield(L, 2, "ends") == LUA_TNIL)
            ends = PC_BOOK_CLAMPED;            /* tangents given without ends: clamped */
        lua_settop(L, top);
    }
    if (ends == PC_BOOK_CLAMPED && have_d < 2)
        return pcl_error(L, "%s: clamped ends need both end tangents d0 and d1", fn);
    if ((ends == PC_BOOK_CYCLIC || ends == PC_BOOK_ANTICYCLIC) && n < 4)
        return pcl_error(L, "%s: cyclic and anticyclic ends need at least 4 points, got %d", fn, n);
    double *tg = lua_newuserdatauv(L, sizeof(double) * (size_t)n * d, 0);
    int st;
    pc_curve *c = pc_curve_book_spline(d, n, p, chord, ends, d0, d1, tg, &st);
    if (!c && st == PC_ECOINCIDENT)
        return pcl_error(L, "%s: two consecutive points coincide (a chord of length 0)", fn);
    push_curve_or_raise(L, c, st, fn, "spline");
    lua_createtable(L, n, 0);
    for (int i = 0; i < n; i++) {
        pcl_pushvector(L, d, tg + (size_t)i * d);
        lua_rawseti(L, -2, i + 1);
    }
    return 2;
}

static int l_helix(lua_State *L) {
    const char *fn = "buimov.helix";
    double a = pcl_checknum(L, fn, 1, "a"), b = pcl_checknum(L, fn, 2, "b");
    double t0 = pcl_checknum(L, fn, 3, "t0"), t1 = pcl_checknum(L, fn, 4, "t1");
    if (a == 0) pcl_argerror_full(L, fn, 1, 1, "a", "a nonzero radius");
    if (!(t1 > t0)) return pcl_error(L, "%s: need t0 < t1", fn);
    int st;
    pc_curve *c = pc_curve_helix(a, b, t0, t1, &st);
    push_curve_or_raise(L, c, st, fn, "helix");
    return 1;
}

static int l_sphere(lua_State *L) {
    const char *fn = "buimov.sphere";
    const double pi = 3.14159265358979323846;
    double th0 = pcl_optnum(L, fn, 1, "th0", 0), th1 = pcl_optnum(L, fn, 2, "th1", 2 * pi);
    double ph0 = pcl_optnum(L, fn, 3, "ph0", 0), ph1 = pcl_optnum(L, fn, 4, "ph1", pi);
    double c[3] = {0, 0, 0};
    if (!lua_isnoneornil(L, 5)) loc(L, fn, 5, "C", 3, c);
    double r = pcl_optnum(L, fn, 6, "r", 1);
    if (!(r > 0)) pcl_argerror_full(L, fn, 6, 6, "r", "a positive number");
    if (!(th1 > th0) || !(ph1 > ph0)) return pcl_error(L, "%s: need th0 < th1 and ph0 < ph1", fn);
    int st;
    pc_surface *s = pc_surface_sphere(c, r, th0, th1, ph0, ph1, &st);
    if (!s) return pcl_statuserror(L, fn, st, NULL);
    pcl_pushsurface(L, s, "buimov.sphere");
    return 1;
}

static int l_sphere_frame(lua_State *L) {
    const char *fn = "buimov.sphere_frame";
    double f[15];
    pc_sphere_frame(pcl_checknum(L, fn, 1, "th"), pcl_checknum(L, fn, 2, "ph"), f);
    pcl_pushpoint(L, 3, f);
    for (int i = 1; i < 5; i++) pcl_pushvector(L, 3, f + 3 * i);
    return 5;
}

/* buimov.det(rows): the determinant of a square matrix (§1.2; the area factor of §1.7.4) */
static int l_det(lua_State *L) {
    const char *fn = "buimov.det";
    if (!lua_istable(L, 1)) pcl_argerror_full(L, fn, 1, 1, "rows", "a square matrix (a list of rows)");
    int n = (int)luaL_len(L, 1);
    if (n < 1 || n > PC_MAXDIM + 1) return pcl_error(L, "%s: argument #1 (rows) must hold 1 to %d rows, got %d", fn, PC_MAXDIM + 1, n);
    double m[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)];
    for (int i = 0; i < n; i++) {
        if (lua_geti(L, 1, i + 1) != LUA_TTABLE || (int)luaL_len(L, -1) != n)
            pcl_error(L, "%s: argument #1 (rows) row [%d] must be a list of %d numbers", fn, i + 1, n);
        for (int j = 0; j < n; j++) {
            lua_geti(L, -1, j + 1);
            int ok;
            m[i * n + j] = lua_tonumberx(L, -1, &ok);
            if (!ok || !isfinite(m[i * n + j]))
                pcl_error(L, "%s: argument #1 (rows) entry [%d][%d] must be a finite number, got %s", fn, i + 1, j + 1, pcl_shown(L, -1));
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    lua_pushnumber(L, pc_det(n, m));
    return 1;
}

static int l_reconstruct(lua_State *L) {
    const char *fn = "buimov.reconstruct";
    if (!lua_istable(L, 1)) pcl_argerror_full(L, fn, 1, 1, "views", "a list of maps from 3-D to 2-D");
    if (!lua_istable(L, 2)) pcl_argerror_full(L, fn, 2, 2, "images", "a list of 2-D points");
    int n = (int)luaL_len(L, 1);
    if (n < 2 || n > 64) return pcl_error(L, "%s: argument #1 (views) must hold 2 to 64 views, got %d", fn, n);
    if ((int)luaL_len(L, 2) != n) return pcl_error(L, "%s: argument #2 (images) must hold one point per view (%d), got %d", fn, n, (int)luaL_len(L, 2));
    pc_map v[64];
    double xy[128];
    for (int i = 0; i < n; i++) {
        lua_geti(L, 1, i + 1);
        pc_map *f = pcl_tomap(L, -1);
        if (!f || f->nin != 3 || f->nout != 2)
            pcl_error(L, "%s: argument #1 (views) item [%d] must be a map from 3-D to 2-D, got %s", fn, i + 1, pcl_shown(L, -1));
        v[i] = *f;
        lua_geti(L, 2, i + 1);
        pcl_value *p = pcl_tovalue(L, -1);
        if (!p || p->n != 2 || p->h[2] != 1)
            pcl_error(L, "%s: argument #2 (images) item [%d] must be a 2-D point, got %s", fn, i + 1, pcl_shown(L, -1));
        xy[2 * i] = p->h[0];
        xy[2 * i + 1] = p->h[1];
        lua_pop(L, 2);
    }
    double x[3], res;
    int st = pc_reconstruct_point(n, v, xy, x, &res);
    if (st == PC_ESINGULAR) return pcl_error(L, "%s: the views do not fix a point (their lines of sight are parallel)", fn);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    pcl_pushpoint(L, 3, x);
    lua_pushnumber(L, res);
    return 2;
}

static int l_calibrate(lua_State *L) {
    const char *fn = "buimov.calibrate";
    int n, m, d3 = 3, d2 = 2;
    double *xyz = read_points(L, fn, 1, "points", 6, &n, &d3);
    double *xy = read_points(L, fn, 2, "images", 6, &m, &d2);
    if (m != n) return pcl_error(L, "%s: %d points but %d images", fn, n, m);
    pc_map *cam = pcl_newmap(L);
    double rms;
    int st = pc_calibrate_camera(n, xyz, xy, cam, &rms);
    if (st == PC_ESINGULAR)
        return pcl_error(L, "%s: the points do not fix a camera (they lie in one plane, or the "
                         "origin is on the camera's vanishing plane, where T44 = 0)", fn);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    lua_pushnumber(L, rms);
    return 2;
}

void pcl_open_buimov(lua_State *L) {
    int module = lua_gettop(L);
    static const luaL_Reg plane[] = {
        {"circle3", l_circle3},       {"circle2r", l_circle2r},       {"circle_slopes", l_circle_slopes},
        {"arc3", l_arc3},             {"classify", l_classify},       {"rotate_conic", l_rotate_conic},
        {"conic_value", l_conic_value}, {"conic_coef", l_conic_coef}, {"ellipse", l_ellipse},
        {"parabola", l_parabola},     {"hyperbola", l_hyperbola},     {"points", l_points},
        {NULL, NULL}};
    lua_newtable(L);
    luaL_setfuncs(L, plane, 0);
    lua_setfield(L, module, "plane");
    static const luaL_Reg book[] = {
        {"knots", l_knots},           {"basis", l_basis},             {"bspline", l_bspline},
        {"bernstein", l_bernstein},   {"blend", l_blend},             {"hermite", l_hermite},
        {"hermite_coeffs", l_hermite_coeffs}, {"spline", l_spline},   {"helix", l_helix},
        {"sphere", l_sphere},         {"sphere_frame", l_sphere_frame},
        {"det", l_det},               {"reconstruct", l_reconstruct}, {"calibrate", l_calibrate},   {NULL, NULL}};
    lua_newtable(L);
    luaL_setfuncs(L, book, 0);
    lua_setfield(L, module, "buimov");
}
