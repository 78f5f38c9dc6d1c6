/* The parts of Korotky's constructions the bindings need (korotky_parts.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "korotky_parts.h"
#include "graphdiff.h"
#include "elastic.h"
#include "conic_surface.h"
#include "names.h"

const char *const pc_poly_spline_ends[] = {"natural", "clamped", NULL};
const char *const pc_ferguson_roots[] = {"min", "max", NULL};

pc_curve *pc_poly_spline_points(int n, const double *p, pc_end_kind ends, double s0, double s1,
                                double *coef, int *bad, int *status) {
    double x[PC_FERGUSON_MAXN], y[PC_FERGUSON_MAXN];
    if (n < 2 || n > PC_FERGUSON_MAXN) {
        *status = PC_EARG;
        return NULL;
    }
    for (int i = 0; i < n; i++) x[i] = p[2 * i], y[i] = p[2 * i + 1];
    *status = pc_poly_spline(n, x, y, ends, s0, s1, coef, bad);
    return *status == PC_OK ? pc_poly_spline_curve(n, x, coef, status) : NULL;
}

/* a constant curve at the homogeneous 3-D point h */
static pc_curve *constant_curve(const double *h, int *status) {
    double cp[8];
    memcpy(cp, h, sizeof(double) * 4);
    memcpy(cp + 4, h, sizeof(double) * 4);
    return pc_curve_bezier(3, 2, cp, status);
}

pc_surface *pc_surface_ridge_shell_of(const pc_pencil_point g[8], double *bad_u, int *status) {
    pc_curve *c[8];
    int ok = 1;
    for (int i = 0; i < 8; i++) {
        c[i] = g[i].c ? pc_curve_retain(g[i].c) : constant_curve(g[i].h, status);
        ok &= c[i] != NULL;
    }
    pc_ridge_shell r = {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]};
    pc_surface *s = ok ? pc_surface_ridge_shell(&r, bad_u, status) : NULL;
    for (int i = 0; i < 8; i++) pc_curve_release(c[i]);
    return s;
}

int pc_conic_line_pair(const double *cp, double w[2]) {
    double q[5][2];
    for (int i = 0; i < 5; i++) {
        double wt = cp[3 * i + 2];
        q[i][0] = wt != 0 ? cp[3 * i] / wt : NAN;
        q[i][1] = wt != 0 ? cp[3 * i + 1] / wt : NAN;
    }
    /* both pieces straight: U, its midpoint, W and W, its midpoint, V */
    for (int k = 0; k < 2; k++) {
        const double *a = q[2 * k], *m = q[2 * k + 1], *b = q[2 * k + 2];
        double cr = (m[0] - a[0]) * (b[1] - a[1]) - (m[1] - a[1]) * (b[0] - a[0]);
        double tol = 1e-12 * (1 + hypot(b[0] - a[0], b[1] - a[1]) * hypot(m[0] - a[0], m[1] - a[1]));
        if (!(isfinite(cr) && fabs(cr) <= tol)) return 0;
    }
    w[0] = q[2][0], w[1] = q[2][1];
    return 1;
}

const char *pc_ferguson_why(int st) {
    return st == PC_EDOMAIN      ? "no positive derivative moduli"
           : st == PC_ENOCONVERGE ? "Newton's method does not converge"
           : st == PC_ESINGULAR   ? "the system is singular"
           : st == PC_EZERO       ? "the tangent is the zero vector"
           : st == PC_ECOINCIDENT ? "the point repeats the one before"
                                  : pc_strerror(st);
}

int pc_ferguson_explain(const char *op, int st, int bad, pc_why_call *w) {
    int poly = !strcmp(op, "korotky.poly_spline"), lambda = !strcmp(op, "korotky.ferguson_lambda");
    if (poly && st == PC_EDOMAIN)
        return pc_why_call_set(w, op, st, 1, NULL, "[%d] must lie right of the point before (x must increase)", bad + 1);
    if (lambda && st == PC_EZERO) return pc_why_call_set(w, op, st, 0, NULL, "the end tangents must not be zero vectors");
    if (lambda && st == PC_EDOMAIN)
        return pc_why_call_set(w, op, st, 0, "lambda", "[%d] (at knot #%d) must be positive", bad, bad + 1);
    if (bad >= 0) return pc_why_call_set(w, op, st, 0, NULL, "%s at knot #%d", pc_ferguson_why(st), bad + 1);
    return pc_why_call_set(w, NULL, st, 0, NULL, "");
}

pc_curve *pc_ferguson_checked(int n, const double *p, const double *T, int nm, const double *mags, int *status,
                              pc_why_call *w) {
    const char *op = "korotky.ferguson";
    pc_curve *c = NULL;
    if (nm != 2 * n - 2)
        *status = pc_why_call_set(w, op, PC_EDIM, 3, NULL, "must hold %d numbers, got %d", 2 * n - 2, nm);
    else if (!(c = pc_ferguson_curve(n, p, T, mags, status)))
        pc_why_call_set(w, op, *status, 0, NULL, "argument #2 (tangents) (%s)", pc_strerror(*status));
    else
        pc_why_call_set(w, NULL, PC_OK, 0, NULL, "");
    return c;
}

pc_curve *pc_poly_spline_checked(int n, const double *p, pc_end_kind ends, int slopes, double s0,
                                 double s1, double *coef, int *status, pc_why_call *w) {
    const char *op = "korotky.poly_spline";
    int bad = -1;
    if (ends == PC_END_CLAMPED && !slopes) {
        *status = pc_why_call_set(w, op, PC_EDOMAIN, 0, NULL,
                                  "clamped ends need the end slopes s0 and s1 (numbers)");
        return NULL;
    }
    pc_curve *c = pc_poly_spline_points(n, p, ends, s0, s1, coef, &bad, status);
    pc_ferguson_explain(op, c ? PC_OK : *status, bad, w);
    return c;
}

pc_curve *pc_ferguson_lambda_checked(int n, const double *p, const double tA[2], const double tE[2],
                                     double wA, double wE, int nl, const double *lambda,
                                     int *status, pc_why_call *w) {
    const char *op = "korotky.ferguson_lambda";
    int bad = -1;
    if (n > 2 && nl != n - 2) {
        if (nl < 0)
            *status = pc_why_call_set(w, op, PC_EDOMAIN, 0, "lambda", "must be a list of %d numbers, got nil", n - 2);
        else
            *status = pc_why_call_set(w, op, PC_EDOMAIN, 0, "lambda", "must hold %d numbers, got %d", n - 2, nl);
        return NULL;
    }
    pc_curve *c = pc_ferguson_lambda_curve(n, p, tA, tE, wA, wE, lambda, &bad, status);
    pc_ferguson_explain(op, c ? PC_OK : *status, bad, w);
    return c;
}

const char *pc_conic_arc_why(int st) {
    return st == PC_ESKEW        ? "the tangents must lie in the plane of U, V and T"
           : st == PC_EDOMAIN     ? "T must lie between the tangent lines, on an arc from U to V that stays finite"
           : st == PC_ECOINCIDENT ? "U and V coincide"
           : st == PC_EZERO       ? "a tangent is the zero vector"
           : st == PC_EDIM        ? "the points must be 2-D or more"
                                  : pc_strerror(st);
}

const char *pc_conic_revolve_why(int st) {
    return st == PC_ECOLLINEAR   ? "the ridge point lies on the axis AB"
           : st == PC_EDOMAIN     ? "no conic through A, B and the ridge point with those tangent planes"
           : st == PC_ECOINCIDENT ? "A and B coincide"
           : st == PC_EZERO       ? "a tangent plane's normal is the zero vector"
                                  : pc_strerror(st);
}

const char *pc_meet_planes4_why(int st, int pencil) {
    if (st == PC_ESAME_LINE)
        return pencil ? "the planes share a line (a plane of one pencil holds the other's basis points)"
                      : "the planes share a line (more than one common point)";
    if (st == PC_ESKEW)
        return pencil ? "the flats do not meet (a pencil's points span only a line)"
                      : "the planes do not meet (a spanning triple is collinear, or they are parallel)";
    return pc_strerror(st);
}

pc_curve *pc_ferguson_lambda_curve(int n, const double *p, const double tA[2], const double tE[2], double wA,
                                   double wE, const double *lambda, int *bad, int *status) {
    double lA = hypot(tA[0], tA[1]), lE = hypot(tE[0], tE[1]), dA[2], dE[2];
    double dout[2 * PC_FERGUSON_MAXN], din[2 * PC_FERGUSON_MAXN];
    if (!(lA > 0) || !(lE > 0)) {
        *status = PC_EZERO;
        return NULL;
    }
    for (int k = 0; k < 2; k++) dA[k] = tA[k] * wA / lA, dE[k] = tE[k] * wE / lE;
    if (n > PC_FERGUSON_MAXN) *status = PC_EDIM;
    else *status = pc_ferguson_lambda(2, n, p, dA, dE, lambda, dout, din, bad);
    return *status == PC_OK ? pc_curve_hermite(2, n, p, dout, din, NULL, 0, status) : NULL;
}

int pc_conic_arc_shaped(const pc_curve *c) {
    return c->dim == 2 && c->kind == PC_CURVE_BEZIER && c->degree == 2 && (c->ncp == 3 || c->ncp == 5);
}

int pc_conic_info_arc(const pc_curve *c, pc_conic_info *out, double w[2]) {
    if (!pc_conic_arc_shaped(c)) return PC_EDIM;
    if (c->ncp == 5) return pc_conic_line_pair(c->cp, w) ? PC_ESAME_LINE : PC_EDIM;
    return pc_conic_info_rquad(c->cp, out);
}

/* x as Lua's %f shows it in a message: %.14g, and ".0" after what looks like an integer */
static const char *lua_num_text(double x, char *buf, size_t size) {
    snprintf(buf, size, "%.14g", x);
    if (buf[strspn(buf, "-0123456789")] == '\0') strncat(buf, ".0", size - strlen(buf) - 1);
    return buf;
}

int pc_conic_elements_checked(const pc_curve *c, const double coef[6], pc_conic_info *out,
                              pc_why_call *w) {
    const char *op = "korotky.conic_elements";
    double at[2];
    char x[40], y[40];
    int st = c ? pc_conic_info_arc(c, out, at) : pc_conic_info_coef(coef, out);
    if (st == PC_ESAME_LINE)   /* the degenerate section AOD of Fig. 3c */
        return pc_why_call_set(w, op, st, 0, NULL, "the line pair U W V (T = W, the weight infinite) is "
                               "a degenerate conic: its lines meet at W = P(%s, %s)",
                               lua_num_text(at[0], x, sizeof x), lua_num_text(at[1], y, sizeof y));
    return pc_why_call_row(w, pc_korotky_why, op, st);
}

pc_curve *pc_elastic_checked(int n, const double *p, int pieces, const double *end_angles,
                             double len, double *energy, int *status, pc_why_call *w) {
    pc_curve *c = pc_elastic_length(n, p, pieces, end_angles, len, energy, status);
    pc_elastic_explain(c ? PC_OK : *status, n, pieces, len, w);
    return c;
}

int pc_elastic_explain(int st, int n, int pieces, double len, pc_why_call *w) {
    const char *op = "korotky.elastic";
    char num[40];
    if (st == PC_ECOINCIDENT) return pc_why_call_set(w, op, st, 0, NULL, "two consecutive points coincide");
    if (st == PC_EDOMAIN)
        return pc_why_call_set(w, op, st, 0, NULL, "length %s is not longer than the polyline through the points",
                               pc_num_text(len, num, sizeof num));
    if (st == PC_EDIM && len > 0 && n == 2 && pieces == 1)
        return pc_why_call_set(w, op, st, 0, NULL, "a length needs a free node: two points with one piece are a segment");
    if (st == PC_EDIM)
        return pc_why_call_set(w, op, st, 0, NULL,
                               "%d points with %d pieces per span are too many unknowns; use fewer pieces", n, pieces);
    return pc_why_call_set(w, NULL, st, 0, NULL, "");
}

int pc_graphical_slope_checked(int n, const double *xy, double x, int window, double *slope, pc_why_call *w) {
    const char *op = "korotky.graphical_slope";
    char lo[40], hi[40], at[40];
    if (window < 3 || window > n)
        return pc_why_call_set(w, op, PC_EDIM, 3, NULL, "must be an integer 3 to %d, got %d", n, window);
    for (int i = 1; i < n; i++)
        if (!(xy[2 * i] > xy[2 * i - 2]))
            return pc_why_call_set(w, op, PC_EDOMAIN, 1, NULL, "[%d] must lie right of the sample before (x must increase)",
                                   i + 1);
    int st = pc_graphical_slope(n, xy, x, window, slope);
    if (st == PC_EDOMAIN)
        return pc_why_call_set(w, op, st, 2, NULL, "must lie within the samples [%s, %s], got %s",
                               pc_num_text(xy[0], lo, sizeof lo), pc_num_text(xy[2 * n - 2], hi, sizeof hi),
                               pc_num_text(x, at, sizeof at));
    return pc_why_call_set(w, op, st, 1, NULL, "(%s)", pc_strerror(st));
}

int pc_curve_hausdorff_checked(const pc_curve *model, const pc_curve *ref, int samples, double *d, pc_why_call *w) {
    if (model->dim != ref->dim)
        return pc_why_call_set(w, "korotky.deviation", PC_EDIM, 0, NULL,
                               "argument #2 (reference) is %d-D, but argument #1 (model) is %d-D (mixed dimensions)",
                               ref->dim, model->dim);
    return pc_why_call_set(w, NULL, pc_curve_hausdorff(model, ref, samples, d), 0, NULL, "");
}

pc_surface *pc_sweep_checked(int ridge, const pc_pencil_point g[8], int *status, pc_why_call *w) {
    double u = 0;
    pc_surface *s = ridge ? pc_surface_ridge_shell_of(g, &u, status)
                          : pc_surface_conic_sweep(g[0].c, g[1].c, g[2].c, g[3].c, g[4].c, &u, status);
    pc_sweep_explain(ridge, s ? PC_OK : *status, u, w);
    return s;
}

int pc_sweep_explain(int ridge, int st, double u, pc_why_call *w) {
    char at[40];
    if (st != PC_EDOMAIN && st != PC_ESKEW && st != PC_ECOINCIDENT && st != PC_EZERO)
        return pc_why_call_set(w, NULL, st, 0, NULL, "");
    const char *why = st != PC_EDOMAIN ? pc_strerror(st) : ridge ? "a T must lie between the tangent lines"
                                                                 : "T must lie between the tangent lines";
    pc_num_text(u, at, sizeof at);
    if (ridge)
        return pc_why_call_set(w, "korotky.ridge_shell", st, 0, NULL, "no conic arc of the profile at u = %s (%s)", at, why);
    return pc_why_call_set(w, "korotky.conic_sweep", st, 0, NULL,
                           "no conic through U, V, T with the tangents towards P and Q at u = %s (%s)", at, why);
}

pc_surface *pc_conic_revolve_explained(const double A[3], const double B[3], const double nA[3], const double nB[3],
                                       pc_curve *ridge, int *status, pc_why_call *w) {
    double u = 0;
    char at[40];
    pc_surface *s = pc_surface_conic_revolve(A, B, nA, nB, ridge, &u, status);
    if (s) return s;
    if (*status == PC_ECOLLINEAR || *status == PC_EDOMAIN)
        pc_why_call_set(w, "korotky.conic_revolve", *status, 0, NULL, "%s at u = %s", pc_conic_revolve_why(*status),
                        pc_num_text(u, at, sizeof at));
    else
        pc_why_call_set(w, "korotky.conic_revolve", *status, 0, NULL, "%s", pc_conic_revolve_why(*status));
    return NULL;
}

int pc_dome_tri_height_checked(const double *A, const double *B, const double *C, const double *D, double *h,
                               pc_why_call *w) {
    int st = pc_dome_tri_height_through(A, B, C, D, h);
    if (st == PC_EDOMAIN)
        return pc_why_call_set(w, "korotky.dome_tri", st, 4, NULL, "must stand above the inside of the triangle, got %%s");
    return pc_why_call_set(w, "korotky.dome_tri", st, 0, NULL, "the triangle (%s)", pc_strerror(st));
}

pc_surface *pc_dome_tri_explained(const double *A, const double *B, const double *C, double h,
                                  const double *D, int *status, pc_why_call *w) {
    if (h == 0 && (*status = pc_dome_tri_height_checked(A, B, C, D, &h, w)) != PC_OK) return NULL;
    pc_surface *s = pc_surface_dome_tri(A, B, C, h, status);
    pc_why_call_row(w, pc_korotky_why, "korotky.dome_tri", *status);
    return s;
}

const pc_why pc_korotky_why[] = {
    {"korotky.dome_tri", PC_ECOLLINEAR, 0, NULL, "the triangle ABC is flat in plan"},
    {"korotky.conic_elements", PC_EDIM, 1, NULL, "must be a 2-D conic arc (one rational quadratic piece) or the "
     "coefficients {a, b, c, d, e, f}, got a curve of two pieces"},
    {"korotky.conic_elements", PC_ECOLLINEAR, 0, NULL, "the arc is a straight segment (weight 0): no conic"},
    {"korotky.conic_elements", PC_EDOMAIN, 0, NULL, "a degenerate conic (a line pair, or no real points)"},
    {"korotky.conic_elements", PC_ENONFINITE, 1, NULL, "must be finite (it holds a NaN or an infinity)"},
    {NULL, 0, 0, NULL, NULL}};
