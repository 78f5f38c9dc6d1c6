/* The parts of the textbook's constructions the bindings need (buimov_parts.h). */
#include "buimov_parts.h"
#include <math.h>
#include "names.h"
#include "reconstruct.h"
#include "buimov_why.h"

int pc_bezier_points(const pc_curve *c, double *out) {
    int ok = c->kind == PC_CURVE_BEZIER && c->nknots == 2;
    for (int i = 0; ok && i < c->ncp; i++) ok = c->cp[i * (c->dim + 1) + c->dim] == 1;
    if (!ok) return -1;
    for (int i = 0; i < c->ncp; i++)
        for (int j = 0; j < c->dim; j++) out[i * c->dim + j] = c->cp[i * (c->dim + 1) + j];
    return c->degree;
}

const char *pc_bezier_joint_name(int kind) {
    static const char *names[4] = {"none", "C0", "G1", "C1"};
    return kind >= 0 && kind < 4 ? names[kind] : "none";
}

#define NOT_POLY "must be a polynomial Bezier curve (bezier{P0, ..., Pn}), not a rational or piecewise one"

int pc_bezier_g1_next_of(const pc_curve *P, int m, double g, double *q0, double *q1, pc_why_call *w) {
    double p[(PC_CURVE_MAXDEG + 1) * PC_MAXDIM];
    int n = pc_bezier_points(P, p);
    if (n < 0) return pc_why_call_set(w, "buimov.g1_next", PC_EARG, 1, NULL, NOT_POLY);
    return pc_why_call_set(w, NULL, pc_bezier_g1_next(P->dim, n, p, m, g, q0, q1), 0, NULL, "");
}

int pc_bezier_joint_of(const pc_curve *P, const pc_curve *Q, int *kind, double *g, pc_why_call *w) {
    const char *op = "buimov.joint";
    double p[(PC_CURVE_MAXDEG + 1) * PC_MAXDIM], q[(PC_CURVE_MAXDEG + 1) * PC_MAXDIM];
    int n = pc_bezier_points(P, p), m = pc_bezier_points(Q, q);
    if (n < 0 || m < 0) return pc_why_call_set(w, op, PC_EARG, n < 0 ? 1 : 2, NULL, NOT_POLY);
    if (P->dim != Q->dim)
        return pc_why_call_set(w, op, PC_EDIM, 0, NULL,
                               "argument #2 (Q) is %d-D, but argument #1 (P) is %d-D (mixed dimensions)", Q->dim, P->dim);
    return pc_why_call_set(w, NULL, pc_bezier_joint(P->dim, n, p, m, q, kind, g), 0, NULL, "");
}

int pc_book_spline_check(int n, pc_book_ends *ends, int ends_given, int nd, int param_given, int nlen,
                         const double *len, pc_why_call *w) {
    const char *op = "buimov.spline";
    char num[40];
    if (!ends_given && nd == 2) *ends = PC_BOOK_CLAMPED;
    if (*ends == PC_BOOK_CLAMPED && nd < 2)
        return pc_why_call_set(w, op, PC_EDOMAIN, 0, NULL, "clamped ends need both end tangents d0 and d1");
    if ((*ends == PC_BOOK_CYCLIC || *ends == PC_BOOK_ANTICYCLIC) && n < 4)
        return pc_why_call_set(w, op, PC_EDOMAIN, 0, NULL, "cyclic and anticyclic ends need at least 4 points, got %d", n);
    if (nlen >= 0 && param_given)
        return pc_why_call_set(w, op, PC_EDOMAIN, 0, NULL, "give the parameter as param or as lengths, not both");
    if (nlen >= 0 && nlen != n - 1)
        return pc_why_call_set(w, op, PC_EDOMAIN, 0, "lengths", "must hold %d segment lengths (one per segment), got %d",
                               n - 1, nlen);
    for (int i = 0; i < nlen; i++)
        if (!(len[i] > 0))
            return pc_why_call_set(w, op, PC_EDOMAIN, 0, "lengths", "[%d] must be a positive length, got %s", i + 1,
                                   pc_num_text(len[i], num, sizeof num));
    return pc_why_call_set(w, op, PC_OK, 0, NULL, "");
}

int pc_book_basis_checked(const double *q, int nq, int i, int k, double t, double *out, pc_why_call *w) {
    const char *op = "buimov.basis";
    for (int j = 1; j < nq; j++)
        if (q[j] < q[j - 1]) return pc_why_call_set(w, op, PC_EDOMAIN, 4, NULL, "must not decrease ([%d])", j + 1);
    int st = pc_book_basis(q, nq, i, k, t, out);
    return pc_why_call_set(w, op, st, 0, NULL, "N(i = %d, k = %d) needs the knots q[i] .. q[i + k]: %d knots given",
                           i, k, nq);
}

const char *const pc_gen_kind_names[] = {"circle", "ellipse", "parabola", "hyperbola", "hyperbola_ch", NULL};
const char *const pc_gen_method_names[] = {"param", "recurrence", "rational", "explicit", NULL};
const char *const pc_conic_coef_kinds[] = {"ellipse", "hyperbola", "parabola", NULL};
const char *const pc_conic_names[] = {"ellipse", "parabola", "hyperbola", NULL};
const char *const pc_book_ends_names[] = {"clamped", "natural", "cyclic", "anticyclic", NULL};
const char *const pc_book_param_names[] = {"uniform", "chord", NULL};

int pc_circle2r_checked(const double p1[2], const double p2[2], double r, pc_circle_eq out[2], pc_why_call *w) {
    const char *op = "plane.circle2r";
    char d[40], r2[40];
    int st = pc_circle2r(p1, p2, r, out);
    if (st == PC_ECOINCIDENT)
        return pc_why_call_set(w, op, st, 0, NULL, "the points A and B coincide (any circle of radius r through A will do)");
    if (st == PC_EDOMAIN)
        return pc_why_call_set(w, op, st, 0, NULL, "the points are %s apart, farther than the diameter 2r = %s",
                               pc_num_text(hypot(p2[0] - p1[0], p2[1] - p1[1]), d, sizeof d), pc_num_text(2 * r, r2, sizeof r2));
    return pc_why_call_set(w, NULL, st, 0, NULL, "");
}

int pc_circle_slopes_checked(const double p1[2], double m1, double x_end, double m2, pc_circle_eq out[2],
                             double ends[4], int *nsol, pc_why_call *w) {
    const char *op = "plane.circle_slopes";
    int st = pc_circle_slopes(p1, m1, x_end, m2, out, ends, nsol);
    if (st == PC_EDOMAIN && x_end == p1[0]) return pc_why_call_set(w, op, st, 3, NULL, "equals the abscissa of A");
    if (st == PC_EDOMAIN) return pc_why_call_set(w, op, st, 0, NULL, "no circle through A has these slopes");
    return pc_why_call_set(w, NULL, st, 0, NULL, "");
}

int pc_conic_coef_checked(int kind, const double c[2], double A, int has_B, double B, double out[6], pc_why_call *w) {
    const char *op = "plane.conic_coef";
    if (kind != 2 && !has_B)
        return pc_why_call_set(w, op, PC_EDOMAIN, 4, NULL, "must be a finite number (the %s's second semi-axis), got nil",
                               pc_conic_coef_kinds[kind]);
    int st = pc_conic_coef(kind, c, A, B, out);
    return pc_why_call_set(w, op, st, 0, NULL, "the semi-axes A and B must be positive");
}

int pc_conic_points_checked(pc_gen_kind kind, pc_gen_method method, double A, int has_B, double B, double step,
                            int n, double *xy, pc_why_call *w) {
    const char *op = "plane.points";
    if ((kind == PC_GEN_ELLIPSE || kind >= PC_GEN_HYPERBOLA_SEC) && !has_B)
        return pc_why_call_set(w, op, PC_EDOMAIN, 0, "B", "must be a positive number (the %s's), got nil",
                               pc_gen_kind_names[kind]);
    if (method >= PC_GEN_RATIONAL && kind != PC_GEN_CIRCLE)
        return pc_why_call_set(w, op, PC_EDOMAIN, 0, NULL, "the %s method is the circle's only", pc_gen_method_names[method]);
    int st = pc_conic_points(kind, method, A, B, step, n, xy);
    return pc_why_call_set(w, st == PC_EDOMAIN ? op : NULL, st, 0, NULL,
                           "the steps leave the curve's domain (the explicit circle beyond x = -A, the sec form at 90 degrees)");
}

int pc_calibrate_checked(int n, const double *xyz, int m, const double *xy, pc_map *cam, double *rms,
                         pc_why_call *w) {
    if (m != n) return pc_why_call_set(w, "buimov.calibrate", PC_EDIM, 0, NULL, "%d points but %d images", n, m);
    return pc_why_call_row(w, pc_buimov_why, "buimov.calibrate", pc_calibrate_camera(n, xyz, xy, cam, rms));
}
