/* The textbook's Bezier joints in Lua (books/buimov/buimov.h), declared on the argument layer,
 * in the table buimov: the G1 joint of §4.3. */
#include <math.h>
#include "pcl_args.h"
#include "pcl_point.h"
#include "buimov.h"

/* The Cartesian control points of the polynomial single-piece Bezier curve c (argument #k). */
static int bez_points(lua_State *L, int k, const pc_curve *c, double *out) {
    int ok = c->kind == PC_CURVE_BEZIER && c->nknots == 2;
    for (int i = 0; ok && i < c->ncp; i++) ok = c->cp[i * (c->dim + 1) + c->dim] == 1;
    if (!ok) return pcl_argfail(L, k, "must be a polynomial Bezier curve (bezier{P0, ..., Pn}), not a rational or piecewise one");
    for (int i = 0; i < c->ncp; i++)
        for (int j = 0; j < c->dim; j++) out[i * c->dim + j] = c->cp[i * (c->dim + 1) + j];
    return c->degree;
}

static int l_g1_next(lua_State *L) {
    pcl_val a[3] = {0};
    PCL_READ(L, a);
    const pc_curve *c = a[0].obj;
    double p[(PC_CURVE_MAXDEG + 1) * PC_MAXDIM], q0[PC_MAXDIM], q1[PC_MAXDIM];
    int n = bez_points(L, 1, c, p);
    if (!(a[2].x > 0)) return pcl_argfail(L, 3, "must be positive (the tangents keep their direction)");
    int st = pc_bezier_g1_next(c->dim, n, p, (int)a[1].x, a[2].x, q0, q1);
    if (st != PC_OK) return pcl_fail(L, "%s", pc_strerror(st));
    pcl_pushpoint(L, c->dim, q0);
    pcl_pushpoint(L, c->dim, q1);
    return 2;
}

static int l_joint(lua_State *L) {
    pcl_val a[2] = {0};
    PCL_READ(L, a);
    const pc_curve *P = a[0].obj, *Q = a[1].obj;
    double p[(PC_CURVE_MAXDEG + 1) * PC_MAXDIM], q[(PC_CURVE_MAXDEG + 1) * PC_MAXDIM], g;
    int n = bez_points(L, 1, P, p), m = bez_points(L, 2, Q, q), kind;
    if (P->dim != Q->dim)
        return pcl_fail(L, "argument #2 (Q) is %d-D, but argument #1 (P) is %d-D (mixed dimensions)", Q->dim, P->dim);
    int st = pc_bezier_joint(P->dim, n, p, m, q, &kind, &g);
    if (st != PC_OK) return pcl_fail(L, "%s", pc_strerror(st));
    static const char *names[4] = {"none", "C0", "G1", "C1"};
    lua_pushstring(L, names[kind]);
    if (isnan(g)) lua_pushnil(L);
    else lua_pushnumber(L, g);
    return 2;
}

static const pcl_arg g1_args[] = {A_CURVE("P", 0), A_INT("m", 1, PC_CURVE_MAXDEG),
                                  A_NUMOPT("g", 1, "1"), PCL_END};
static const pcl_arg joint_args[] = {A_CURVE("P", 0), A_CURVE("Q", 0), PCL_END};

static const pcl_fn fns[] = {
    PCL_FN("buimov.g1_next", l_g1_next, g1_args, "Q0, Q1",
           "§4.3 The first two control points of the next Bezier curve of degree m joined to P with G1: Q0 = P_n, n (P_n - P_(n-1)) = g m (Q1 - Q0) (g = 1: C1)."),
    PCL_FN("buimov.joint", l_joint, joint_args, "\"none\"|\"C0\"|\"G1\"|\"C1\", g",
           "§4.3 The kind of joint of two polynomial Bezier curves and the g of n (P_n - P_(n-1)) = g m (Q1 - Q0)."),
    PCL_END};

/* After pcl_open_buimov, with the module table on top. */
void pcl_open_buimov_more(lua_State *L) {
    lua_getfield(L, -1, "buimov");
    pcl_register(L, lua_gettop(L), fns, 0);
    lua_pop(L, 1);
}
