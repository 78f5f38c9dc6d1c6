/* Binding of the textbook's constructions (Buimov; stdlib/books/buimov/), in the tables plane
 * (ch. 3) and buimov (ch. 1.2, 2.8.6, 4, 5).  Curves and surfaces are the one curve and surface
 * types, maps the one map type. */
#include "pcl_args.h"
#include "pcl_core.h"
#include "pcl_point.h"
#include "plane_curves.h"
#include "buimov.h"
#include "reconstruct.h"
#include "linalg.h"
#include "buimov_parts.h"
#include "pcl_books.h"
#include "buimov_why.h"

#define WHY pc_buimov_why

/* the curve a construction made (kind: its name), or its status explained by the why-table */
static int made(lua_State *L, pc_curve *c, const int *st, const char *kind) {
    if (!c) pcl_check(L, *st, WHY);
    return pcl_push_made(L, c, st, kind);
}

/* ==== plane.* ================================================================================ */

/* a circle as a table {centre =, r =, d =, e =, f =, curve =} (curve: the whole circle) */
static void push_circle(lua_State *L, const pc_circle_eq *c) {
    int st;
    pcl_push_results(L, 2, "centre=p r=n d=n e=n f=n", c->c, c->r, c->d, c->e, c->f);
    made(L, pc_curve_ellipse(c->c, c->r, c->r, 0, 2 * M_PI, &st), &st, "circle");
    lua_setfield(L, -2, "curve");
}

/* plane.circle3 and plane.arc3, one body told apart by the declared name: the arc through A,
 * B and C, alone or as the field arc of their circle */
static const pcl_arg abc_args[] = {A_POINT("A", 2), A_POINT("B", 2), A_POINT("C", 2), PCL_END};
PCL_BODY(l_circle3, a) {
    pc_circle_eq c;
    int st, circle = !strcmp(pcl_name(L), "plane.circle3");
    if (circle) {
        pcl_check(L, pc_circle3(a[0].v, a[1].v, a[2].v, &c), WHY);
        push_circle(L, &c);
    }
    made(L, pc_curve_arc3(a[0].v, a[1].v, a[2].v, &st), &st, "arc");
    if (circle) lua_setfield(L, -2, "arc");
    return 1;
}

static const pcl_arg circle2r_args[] = {A_POINT("A", 2), A_POINT("B", 2), A_POSNUM("r"), PCL_END};
PCL_BODY(l_circle2r, a) {
    pc_circle_eq c[2];
    pc_why_call why;
    pcl_check(L, pc_circle2r_checked(a[0].v, a[1].v, a[2].x, c, &why), why.row);
    for (int i = 0; i < 2; i++) push_circle(L, &c[i]);
    return 2;
}

static const pcl_arg slopes_args[] = {A_POINT("A", 2), A_NUM("m1"), A_NUM("x_end"), A_NUM("m2"), PCL_END};
PCL_BODY(l_circle_slopes, a) {
    double *A = a[0].v, m1 = a[1].x, xe = a[2].x, ends[4];
    pc_circle_eq c[2];
    pc_why_call why;
    int n, st;
    pcl_check(L, pc_circle_slopes_checked(A, m1, xe, a[3].x, c, ends, &n, &why), why.row);
    double dir[2] = {xe > A[0] ? 1 : -1, xe > A[0] ? m1 : -m1};
    for (int i = 0; i < n; i++) {
        push_circle(L, &c[i]);
        pcl_pushpoint(L, 2, ends + 2 * i);
        lua_setfield(L, -2, "finish");
        made(L, pc_curve_arc_dir(c[i].c, c[i].r, A, dir, ends + 2 * i, &st), &st, "arc");
        lua_setfield(L, -2, "arc");
    }
    return n;
}

static const pcl_arg classify_args[] = {A_NUM("a"), A_NUM("b"), A_NUM("c"), PCL_END};
PCL_BODY(l_classify, a) {
    pc_conic_class k;
    pcl_check(L, pc_conic_classify(a[0].x, a[1].x, a[2].x, &k), WHY);
    return pcl_push_results(L, 0, "s n", pc_conic_names[k], a[1].x * a[1].x - 4 * a[0].x * a[2].x);
}

#define COEF {.name = "coef", .kind = PCL_NUMBERS, .lo = 6, .hi = 6}
static const pcl_arg rotate_args[] = {COEF, A_NUM("alpha"), PCL_END};
PCL_BODY(l_rotate_conic, a) {
    double out[6];
    pc_conic_rotate(a[0].list, a[1].x, out);
    return pcl_push_results(L, 0, "N", 6, out);
}

static const pcl_arg value_args[] = {COEF, A_POINT("X", 2), PCL_END};
PCL_BODY(l_conic_value, a) {
    return pcl_push_results(L, 0, "n", pc_conic_value(a[0].list, a[1].v[0], a[1].v[1]));
}

static const pcl_arg coef_args[] = {A_ENUM("kind", pc_conic_coef_kinds), A_POINT("centre", 2), A_NUM("A"),
                                    {.name = "B", .kind = PCL_NUMBER, .flags = PCL_OPT}, PCL_END};
PCL_BODY(l_conic_coef, a) {
    double out[6];
    pc_why_call why;
    pcl_check(L, pc_conic_coef_checked(a[0].n, a[1].v, a[2].x, a[3].present, a[3].x, out, &why), why.row);
    return pcl_push_results(L, 0, "N", 6, out);
}

static const pcl_arg ellipse_args[] = {A_POINT("centre", 2), A_POSNUM("A"), A_POSNUM("B"), A_NUMOPT("th0", 0, "0"),
                                       A_NUMOPT("th1", 0, NULL), PCL_END};
static const pcl_arg parabola_args[] = {A_POSNUM("p"), A_NUM("th0"), A_NUM("th1"), PCL_END};
static const pcl_arg hyperbola_args[] = {A_POSNUM("A"), A_POSNUM("B"), A_NUMIN("t0", -300, 300),
                                         A_NUMIN("t1", -300, 300), PCL_END};

/* plane.ellipse, plane.parabola and plane.hyperbola, one body told apart by the declared name,
 * whose last part is the curve's kind (the ellipse whole unless th1 is given) */
PCL_BODY(l_conic_curve, a) {
    const char *kind = pcl_name(L) + strlen("plane.");
    int st;
    pc_curve *c;
    if (!strcmp(kind, "ellipse"))
        c = pc_curve_ellipse(a[0].v, a[1].x, a[2].x, a[3].x, a[4].present ? a[4].x : a[3].x + 2 * M_PI, &st);
    else if (!strcmp(kind, "parabola")) c = pc_curve_parabola(a[0].x, a[1].x, a[2].x, &st);
    else c = pc_curve_hyperbola(a[0].x, a[1].x, a[2].x, a[3].x, &st);
    return made(L, c, &st, kind);
}

static const pcl_arg points_keys[] = {{.name = "A", .kind = PCL_NUMBER, .flags = PCL_REQ | PCL_POS}, A_POSNUM("B"),
                                      {.name = "step", .kind = PCL_NUMBER, .flags = PCL_REQ},
                                      {.name = "n", .kind = PCL_INTEGER, .flags = PCL_REQ | PCL_RANGE, .hi = 1000000},
                                      A_ENUM("method", pc_gen_method_names), PCL_END};
static const pcl_arg points_args[] = {A_ENUM("kind", pc_gen_kind_names),
                                      {.name = "opts", .kind = PCL_OPTIONS, .keys = points_keys}, PCL_END};
PCL_BODY(l_points, a) {
    int n = (int)a[5].x;
    double *xy = lua_newuserdatauv(L, sizeof(double) * 2 * (size_t)(n + 1), 0);
    pc_why_call why;
    pcl_check(L, pc_conic_points_checked(a[0].n, a[6].n, a[2].x, a[3].present, a[3].x, a[4].x, n, xy, &why), why.row);
    return pcl_push_results(L, 2, "P", n + 1, xy);
}

/* ==== buimov.* =============================================================================== */

/* buimov.knots and buimov.bspline, one body told apart by the declared name: the book's knots
 * of order k for m vertices, or the B-spline on them; k is 2 .. min(m, the largest degree + 1) */
static const pcl_arg knots_args[] = {A_POINTS("points", 0, 2, 0), A_INT("k", 2, PC_CURVE_MAXDEG + 1), PCL_END};
PCL_BODY(l_knots, a) {
    int m = a[0].n, k = (int)a[1].x, hi = m < PC_CURVE_MAXDEG + 1 ? m : PC_CURVE_MAXDEG + 1, st;
    if (k > hi) pcl_argfail(L, 2, "must be an integer from 2 to %d (at most the number of points), got %d", hi, k);
    if (!strcmp(pcl_name(L), "buimov.bspline"))
        return made(L, pc_curve_book_bspline(a[0].dim, m, a[0].list, k, &st), &st, "bspline");
    double *q = lua_newuserdatauv(L, sizeof(double) * (size_t)(m + k), 0);
    pc_book_knots(a[0].dim, m, a[0].list, k, q);
    lua_createtable(L, m + k, 0);
    for (int j = 0; j < m + k; j++) {
        lua_pushinteger(L, (lua_Integer)q[j]);
        lua_rawseti(L, -2, j + 1);
    }
    return 1;
}

static const pcl_arg basis_args[] = {A_INT("i", 0, 1000000), A_INT("k", 1, PC_CURVE_MAXDEG + 1), A_NUM("t"),
                                     A_NUMBERS("knots", 0, 1000000), PCL_END};
PCL_BODY(l_basis, a) {
    double N;
    pc_why_call why;
    pcl_check(L, pc_book_basis_checked(a[3].list, a[3].n, (int)a[0].x, (int)a[1].x, a[2].x, &N, &why), why.row);
    return pcl_push_results(L, 0, "n", N);
}

static const pcl_arg bernstein_args[] = {A_INT("n", 0, 1000), A_INT("i", 0, 1000), A_NUM("t"), PCL_END};
PCL_BODY(l_bernstein, a) {
    return pcl_push_results(L, 0, "n", pc_bernstein((int)a[0].x, (int)a[1].x, a[2].x));
}

static const pcl_arg t_arg[] = {A_NUM("t"), PCL_END};
PCL_BODY(l_blend, a) {
    double F[4];
    pc_hermite_blend(a[0].x, F);
    return pcl_push_results(L, 0, "n n n n", F[0], F[1], F[2], F[3]);
}

static const pcl_arg hermite_args[] = {A_SAMEPOINT("P1"), A_SAMEPOINT("P2"), A_SAMEVECTOR("D1"), A_SAMEVECTOR("D2"),
                                       A_POSOPT("t", 1), PCL_END};
/* buimov.hermite and buimov.hermite_coeffs, one body told apart by the declared name: the
 * segment, or its coefficients */
PCL_BODY(l_hermite, a) {
    double p[4 * PC_MAXDIM], u[2] = {0, a[4].x}, B[4 * PC_MAXDIM];
    int d = a[0].n, st;
    pcl_point_rows(a, 4, d, p);   /* the rows P1, P2, D1, D2 */
    if (!strcmp(pcl_name(L), "buimov.hermite"))
        return made(L, pc_curve_hermite(d, 2, p, p + 2 * d, NULL, u, 0, &st), &st, "hermite");
    pcl_check(L, pc_hermite_coeffs(d, p, p + d, p + 2 * d, p + 3 * d, a[4].x, B), WHY);
    return pcl_push_results(L, d, "p v v v", B, B + d, B + 2 * d, B + 3 * d);
}

static const pcl_arg spline_keys[] = {{.name = "ends", .kind = PCL_ENUM, .dflt = PC_BOOK_NATURAL,
                                       .choices = pc_book_ends_names}, A_SAMEVECTOR("d0"),
                                      A_SAMEVECTOR("d1"), A_ENUM("param", pc_book_param_names),
                                      {.name = "lengths", .kind = PCL_NUMBERS, .lo = 1}, PCL_END};
static const pcl_arg spline_args[] = {{.name = "points", .kind = PCL_POINTS, .flags = PCL_SAMEDIM, .lo = 2},
                                      A_OPTIONS("opts", spline_keys), PCL_END};
PCL_BODY(l_spline, a) {
    int n = a[0].n, d = a[0].dim, st;
    pc_book_ends ends = (pc_book_ends)a[2].n;
    pc_why_call why;
    pcl_check(L, pc_book_spline_check(n, &ends, a[2].present, a[3].present + a[4].present, a[5].present,
                                      a[6].present ? a[6].n : -1, a[6].list, &why), why.row);
    double *tg = lua_newuserdatauv(L, sizeof(double) * (size_t)n * d, 0);
    pc_curve *c = a[6].present ? pc_curve_book_spline_tl(d, n, a[0].list, a[6].list, ends, a[3].v, a[4].v, tg, &st)
                               : pc_curve_book_spline(d, n, a[0].list, a[5].n, ends, a[3].v, a[4].v, tg, &st);
    made(L, c, &st, "spline");
    return 1 + pcl_push_results(L, d, "V", n, tg);
}

static const pcl_arg helix_args[] = {A_NUM("a"), A_NUM("b"), A_NUM("t0"), A_NUM("t1"), PCL_END};
PCL_BODY(l_helix, a) {
    if (a[0].x == 0) return pcl_argfail(L, 1, "must be a nonzero radius, got 0");
    int st;
    return made(L, pc_curve_helix(a[0].x, a[1].x, a[2].x, a[3].x, &st), &st, "helix");
}

static const pcl_arg sphere_args[] = {A_NUMOPT("th0", 0, "0"), A_NUMOPT("th1", 2 * M_PI, "2pi"), A_NUMOPT("ph0", 0, "0"),
                                      A_NUMOPT("ph1", M_PI, "pi"), A_POINTOPT("C", 3), A_POSOPT("r", 1), PCL_END};
PCL_BODY(l_sphere, a) {
    int st;   /* C absent: its cleared value, the origin */
    pc_surface *s = pc_surface_sphere(a[4].v, a[5].x, a[0].x, a[1].x, a[2].x, a[3].x, &st);
    if (!s) pcl_check(L, st, WHY);
    return pcl_push_made_surface(L, s, &st, "buimov.sphere");
}

static const pcl_arg frame_args[] = {A_NUM("th"), A_NUM("ph"), A_POINTOPT("C", 3), A_POSOPT("r", 1), PCL_END};
PCL_BODY(l_sphere_frame, a) {
    double f[15];
    pc_sphere_frame_at(a[2].v, a[3].x, a[0].x, a[1].x, f);   /* the unit sphere at the origin by default */
    return pcl_push_results(L, 3, "p v v v v", f, f + 3, f + 6, f + 9, f + 12);
}

static const pcl_arg det_args[] = {{.name = "rows", .kind = PCL_TABLE, .expect = "a square matrix (a list of rows)"},
                                   PCL_END};
PCL_BODY(l_det, a) {
    int n = (int)luaL_len(L, 1), nc;
    double m[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)];
    pcl_read_rows(L, 1, n, m, &n, &nc);   /* square: as many numbers a row as rows */
    return pcl_push_results(L, 0, "n", pc_det(n, m));
}

#define VIEWS "a list of maps from 3-D to 2-D"
static const pcl_arg reconstruct_args[] = {{.name = "views", .kind = PCL_TABLE, .expect = VIEWS},
                                           A_POINTS("images", 2, 2, 64), PCL_END};
PCL_BODY(l_reconstruct, a) {
    int n = (int)luaL_len(L, 1);
    if (n < 2 || n > 64) return pcl_argfail(L, 1, "must hold 2 to 64 views, got %d", n);
    if (a[1].n != n) return pcl_argfail(L, 2, "must hold one point per view (%d), got %d", n, a[1].n);
    pc_map v[64];
    for (int i = 0; i < n; i++) {
        lua_geti(L, 1, i + 1);
        pc_map *f = pcl_tomap(L, -1);
        if (!f || f->nin != 3 || f->nout != 2)
            pcl_argfail(L, 1, "[%d] must be a map from 3-D to 2-D, got %s", i + 1, pcl_shown(L, lua_gettop(L)));
        v[i] = *f;
        lua_pop(L, 1);
    }
    double x[3], res;
    pcl_check(L, pc_reconstruct_point(n, v, a[1].list, x, &res), WHY);
    return pcl_push_results(L, 3, "p n", x, res);
}

static const pcl_arg calibrate_args[] = {A_POINTS("points", 3, 6, 0), A_POINTS("images", 2, 6, 0), PCL_END};
PCL_BODY(l_calibrate, a) {
    pc_map *cam = pcl_newmap(L);
    double rms;
    pc_why_call w;
    pcl_check(L, pc_calibrate_checked(a[0].n, a[0].list, a[1].n, a[1].list, cam, &rms, &w), w.row);
    return 1 + pcl_push_results(L, 0, "n", rms);
}

/* §4.3 the G1 joint of Bezier curves */
static const pcl_arg g1_args[] = {A_CURVE("P", 0), A_INT("m", 1, PC_CURVE_MAXDEG),
                                  {.name = "g", .kind = PCL_NUMBER, .flags = PCL_OPT | PCL_POS, .dflt = 1, .shown = "1",
                                   .expect = "a positive number (the tangents keep their direction)"}, PCL_END};
PCL_BODY(l_g1_next, a) {
    double q0[PC_MAXDIM], q1[PC_MAXDIM];
    pc_why_call why;
    pcl_check(L, pc_bezier_g1_next_of(a[0].obj, (int)a[1].x, a[2].x, q0, q1, &why), why.row);
    return pcl_push_results(L, a[0].n, "p p", q0, q1);   /* n: the curve's dimension */
}

static const pcl_arg joint_args[] = {A_CURVE("P", 0), A_CURVE("Q", 0), PCL_END};
PCL_BODY(l_joint, a) {
    double g;
    int kind;
    pc_why_call why;
    pcl_check(L, pc_bezier_joint_of(a[0].obj, a[1].obj, &kind, &g, &why), why.row);
    lua_pushstring(L, pc_bezier_joint_name(kind));
    if (isnan(g)) lua_pushnil(L);
    else lua_pushnumber(L, g);
    return 2;
}

static const pcl_fn plane[] = {
    PCL_FN("plane.circle3", l_circle3, abc_args, "circle", "The circle through three points (§3.2): a table {centre =, r =, d =, e =, f =, curve =, arc =} with x^2 + y^2 + d x + e y + f = 0, the whole circle and the arc through the points."),
    PCL_FN("plane.circle2r", l_circle2r, circle2r_args, "circle1, circle2", "The two circles of radius r through A and B (§3.2): first the centre on the right of A -> B (the book's), then the left."),
    PCL_FN("plane.circle_slopes", l_circle_slopes, slopes_args, "circle [, circle2]", "The circle through A with slope m1 there and slope m2 at x = x_end (§3.2, Fig 3.1); each with finish (its end point) and arc (from A to it)."),
    PCL_FN("plane.arc3", l_circle3, abc_args, "curve", "The arc of the circle through A, B, C that passes through B, counter-clockwise; the parameter is the angle at the centre from +x (rational quadratic pieces inside)."),
    PCL_FN("plane.classify", l_classify, classify_args, "\"ellipse\"|\"parabola\"|\"hyperbola\", discriminant", "The kind of the conic a x^2 + b xy + c y^2 + d x + e y + f = 0 by b^2 - 4ac (§3.1)."),
    {.name = "plane.rotate_conic", .fn = l_rotate_conic, .args = rotate_args, .sig = "plane.rotate_conic({a, b, c, d, e, f}, alpha) -> coef", .help = "The coefficients after x' = x cos alpha - y sin alpha, y' = x sin alpha + y cos alpha (§3.3, b corrected to 2(c' - a') cos sin)."},
    PCL_FN("plane.conic_value", l_conic_value, value_args, "number", "The left-hand side a x^2 + b xy + c y^2 + d x + e y + f at the point X."),
    {.name = "plane.conic_coef", .fn = l_conic_coef, .args = coef_args, .help = "The general-form coefficients of an axis-parallel ellipse, hyperbola, or parabola (x - m)^2 = 4p(y - n) (§3.3-§3.5; f = m^2 + 4pn corrected).", .sig = "plane.conic_coef(\"ellipse\"|\"hyperbola\", centre, A, B) | plane.conic_coef(\"parabola\", vertex, p) -> coef"},
    PCL_FN("plane.ellipse", l_conic_curve, ellipse_args, "curve", "The ellipse centre + (A cos th, B sin th), the parameter th the book's angle exactly (rational quadratic pieces of at most 90 degrees inside, each evaluated at the piece parameter of th); A = B is a circle."),
    PCL_FN("plane.parabola", l_conic_curve, parabola_args, "curve", "The parabola y^2 = 4px as (p th^2, 2p th) (§3.4; the book writes 2px), the book's parameter exactly."),
    PCL_FN("plane.hyperbola", l_conic_curve, hyperbola_args, "curve", "The hyperbola branch (A ch t, B sh t) (§3.5), the parameter t the book's exactly (rational quadratic pieces inside)."),
    PCL_FN("plane.points", l_points, points_args, "points", "n + 1 points of a \"circle\", \"ellipse\", \"parabola\", \"hyperbola\" (sec/tan) or \"hyperbola_ch\" by the book's forms and incremental recurrences (§3.2-§3.5, corrected)."),
    PCL_END};

static const pcl_fn book[] = {
    PCL_FN("buimov.knots", l_knots, knots_args, "knots", "The book's integer knot vector of order k (§4.4): n + k + 1 knots, a repeated knot for each multiple vertex."),
    PCL_FN("buimov.basis", l_basis, basis_args, "number", "The B-spline basis N_i,k(t) by the Cox-de Boor recursion (0/0 = 0, closed at t_max; i from 0 as in the book)."),
    PCL_FN("buimov.bspline", l_knots, knots_args, "curve", "The B-spline of order k (degree k - 1) on the book's knots, over [0, t_max]; a repeated vertex pulls the curve to it."),
    PCL_FN("buimov.bernstein", l_bernstein, bernstein_args, "number", "The Bernstein polynomial J_n,i(t) = C(n, i) t^i (1 - t)^(n - i) (§4.3)."),
    PCL_FN("buimov.blend", l_blend, t_arg, "F1, F2, F3, F4", "The Hermite blending functions of a normalised segment (§5.5)."),
    PCL_FN("buimov.hermite", l_hermite, hermite_args, "curve", "The cubic segment from P1 to P2 with the derivatives D1, D2 over the book's parameter [0, t] (§4.2; t = 1 by default)."),
    PCL_FN("buimov.hermite_coeffs", l_hermite, hermite_args, "B1, B2, B3, B4", "The coefficients of P(t) = B1 + B2 t + B3 t^2 + B4 t^3 of that segment (§4.2, B4 corrected)."),
    PCL_FN("buimov.spline", l_spline, spline_args, "curve, tangents", "The C2 cubic spline by the book's tridiagonal system of the joints (§4.2); natural ends by default, clamped when d0 and d1 are given; the segments' parameter lengths uniform, by chords, or the user's lengths."),
    PCL_FN("buimov.helix", l_helix, helix_args, "curve", "The helix (a cos t, a sin t, b t) (§4.1)."),
    {.name = "buimov.sphere", .fn = l_sphere, .args = sphere_args, .sig = "buimov.sphere([th0, th1, ph0, ph1 [, C, r]]) -> s", .help = "The sphere patch C + r (cos th sin ph, sin th sin ph, cos ph) (§5.1, y corrected); u = th, v = ph; the whole unit sphere by default."},
    PCL_FN("buimov.sphere_frame", l_sphere_frame, frame_args, "S, S_th, S_ph, twist, N", "The sphere's point, tangent, twist and normal vectors at (th, ph) (§5.1, corrected; N = S_th x S_ph points inwards): the unit sphere at the origin, or centre C and radius r (the vectors times r, N times r^2)."),
    PCL_FN("buimov.det", l_det, det_args, "number", "The determinant of a square matrix (§1.2): the area factor of a 2x2 map (§1.7.4)."),
    {.name = "buimov.reconstruct", .fn = l_reconstruct, .args = reconstruct_args, .sig = "buimov.reconstruct({T1, T2, ...}, {X1, X2, ...}) -> point, residual", .help = "The point of space whose images under the views (maps from 3-D to 2-D) are X1, X2, ... by least squares (§2.8.6)."},
    PCL_FN("buimov.calibrate", l_calibrate, calibrate_args, "map, rms", "The camera (a map from 3-D to 2-D) sending six or more points of space to their images, by least squares with T44 = 1 (§2.8.6)."),
    PCL_FN("buimov.g1_next", l_g1_next, g1_args, "Q0, Q1", "§4.3 The first two control points of the next Bezier curve of degree m joined to P with G1: Q0 = P_n, n (P_n - P_(n-1)) = g m (Q1 - Q0) (g = 1: C1)."),
    PCL_FN("buimov.joint", l_joint, joint_args, "\"none\"|\"C0\"|\"G1\"|\"C1\", g", "§4.3 The kind of joint of two polynomial Bezier curves and the g of n (P_n - P_(n-1)) = g m (Q1 - Q0)."),
    PCL_END};

void pcl_open_buimov(lua_State *L) {
    pcl_new_table(L, -1, "plane", plane, NULL);
    pcl_new_table(L, -1, "buimov", book, NULL);
}
