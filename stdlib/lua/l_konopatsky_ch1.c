/* Konopatsky's chapter 1 in Lua (books/konopatsky/konop_ch1.h): the table konopatsky, declared
 * on the argument layer. */
#include "pcl_args.h"
#include "pcl_core.h"
#include "pcl_curve.h"
#include "konop_ch1.h"
#include "konop_print.h"
#include "konop_why.h"

#define CHECK(st) pcl_check(L, (st), pc_konop_why)

PCL_BODY(k_area_k, a) {
    double k;
    CHECK(pc_k_area_k(a[0].x, a[1].x, a[2].x, &k));
    return pcl_push_results(L, 0, "n", k);
}

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
    double m[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)];
    int d, cols;
    pcl_read_rows(L, 1, 0, m, &d, &cols);
    if (d != cols || d < 2 || d > 9)
        return pcl_argfail(L, 1, "must hold 2 to 9 rows of as many numbers (a square matrix), got %d rows of %d", d,
                           cols);
    double r;
    CHECK(pc_k_simplex_ratio(d - 1, m, &r));
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

PCL_BODY(k_polar, a) {   /* also konopatsky.rotate(C, A, B, phi), declared without rho: rho = |CA| */
    int n = a[0].n, rotate = pcl_nvalues(L) == 4;
    double m[PC_MAXDIM], rho = rotate ? pc_dist(n, a[0].v, a[1].v) : a[3].x;
    CHECK(pc_k_polar(n, a[0].v, a[1].v, a[2].v, rho, a[rotate ? 3 : 4].x, m));
    return pcl_push_results(L, n, "p", m);
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

#define SAMEPT(nm) {.name = nm, .kind = PCL_POINT, .flags = PCL_SAMEDIM}
static const pcl_arg lambdas[] = {A_NUM("l1"), A_NUM("l2"), A_NUM("l3"), PCL_END};
static const pcl_arg six[] = {SAMEPT("A1"), SAMEPT("A2"), SAMEPT("A3"), SAMEPT("B1"), SAMEPT("B2"), SAMEPT("B3"), PCL_END};
static const pcl_arg o_args[] = {{.name = "polygon", .kind = PCL_POINTS, .flags = PCL_SAMEDIM, .lo = 3, .hi = 64},
                                 SAMEPT("D1"), SAMEPT("D2"), PCL_END};
static const pcl_arg rows_args[] = {
    {.name = "rows", .kind = PCL_TABLE, .expect = "a list of k + 1 rows of barycentric parameters"}, PCL_END};
static const pcl_arg lp_args[] = {SAMEPT("A1"), SAMEPT("A2"), SAMEPT("P1"), SAMEPT("P2"), SAMEPT("P3"), PCL_END};
static const pcl_arg polar_args[] = {SAMEPT("C"), SAMEPT("A"), SAMEPT("B"), A_NUM("rho"), A_NUM("phi"), PCL_END};
static const pcl_arg rotate_args[] = {SAMEPT("C"), SAMEPT("A"), SAMEPT("B"), A_NUM("phi"), PCL_END};
static const pcl_arg eq_args[] = {A_CURVE("c", 0), {.name = "var", .kind = PCL_STRING, .flags = PCL_OPT, .shown = "\"t\""}, PCL_END};
static const pcl_arg ms_args[] = {A_CURVE("NA", 0), A_CURVE("NB", 0), A_CURVE("NC", 0), A_CURVE("gen", 0), PCL_END};

static const pcl_fn fns[] = {
    PCL_FN("konopatsky.area_k", k_area_k, lambdas, "k", "(1.2) The theorem on triangle areas: k = (1 + l1 l2 l3)/((1 + l1)(1 + l2)(1 + l3)) = S_B1B2B3/S_A1A2A3."),
    PCL_FN("konopatsky.area_theorem", k_area_theorem, six, "{k, lambda, a, b, c, collinear}", "(1.2) for B1 on A1A2, B2 on A2A3, B3 on A3A1, any dimension: the signed area ratio k, lambda_i = (AiA(i+1)Bi), the proof's a = (B1A1A2) = -1/(1 + l1), b, c; collinear is corollary 1 (k = 0, Menelaus l1 l2 l3 = -1). B3 = A3 gives k = ab (corollary 2), B1 = A1 and B3 = A3 give k = -b (corollary 3)."),
    PCL_FN("konopatsky.o_theorem", k_o_theorem, o_args, "product, ratios, B", "(1.4) The O-theorem: Bi = AiA(i+1) x D1D2 (B at infinity for a side parallel to d), ratios (AiA(i+1)Bi) and their product, (-1)^m with the closing factor (A_m A_1 B_m) the print omits."),
    {.name = "konopatsky.simplex_ratio", .fn = k_simplex_ratio, .args = rows_args, .result = "ratio", .sig = "konopatsky.simplex_ratio({{p1, q1, r1}, {p2, q2, r2}, {p3, q3, r3}}) -> ratio", .help = "The S-theorem (and with 4 rows the V-theorem, any k + 1 rows): the measure of the simplex of the points with these barycentric parameters over the simplex's own is their determinant (the printed V-theorem's det/det is corrected)."},
    PCL_FN("konopatsky.meet_line_plane", k_meet_line_plane, lp_args, "K, lambda, p, q", "§1.3.5 The meet of line A1A2 and plane P1P2P3 by the V-theorem, in 3-D and n-D: K = (A2 - A1) lambda + A1 = (P1 - P3) p + (P2 - P3) q + P3. A point at infinity (a vector) and lambda = inf when they are parallel; an error when the line lies in the plane or (n > 3) they do not meet."),
    PCL_FN("konopatsky.polar", k_polar, polar_args, "M", "(2.117)/(2.118) The point at distance rho from C at the angle phi from ray CA towards CB: M = (A - C) rho sin(gamma - phi)/(b sin gamma) + (B - C) rho sin phi/(a sin gamma) + C, any dimension."),
    PCL_FN("konopatsky.rotate", k_polar, rotate_args, "Q", "(2.138) A rotated about C by phi towards B in the plane CAB (polar with rho = |CA|)."),
    PCL_FN("konopatsky.moving_simplex", k_moving_simplex, ms_args, "surface", "Fig. 1.2 The moving-simplex surface M(u, v) = (NA - NC) p(v) + (NB - NC) q(v) + NC on three guide curves of one domain (the book's are lines N = (P' - P)(phi(u) - phi(0))/(phi(1) - phi(0)) + P), the generator a 2-D curve gen(v) = (p, q) in the natural parameters of the moving simplex (a conic of ch. 2 gives conic sections)."),
    PCL_FN("konopatsky.equation", k_equation, eq_args, "x, y, ...", "The coordinates of a polynomial or rational curve (its first piece) as the book prints them: x = (a_n t^n + ... + a_0)/(t^m + ... + d_0), expanded in powers of var (\"t\"), the denominator monic; a polynomial curve gives polynomials (the ch. 4-5 coefficients of c:monomial)."),
    PCL_END};

void pcl_open_konopatsky_ch1(lua_State *L) {
    lua_newtable(L);
    pcl_register(L, -1, fns, 0);
    lua_setfield(L, -2, "konopatsky");
}
