/* Plane curves of the textbook (Buimov ch. 3): see plane_curves.h. */
#include "plane_curves.h"
#include "linalg.h"
#include <math.h>
#include <stdlib.h>

static const double PI = 3.14159265358979323846;

static int finite2(const double *p) { return isfinite(p[0]) && isfinite(p[1]); }

/* d, e, f from the centre and radius */
static void circle_fill(pc_circle_eq *o, double m, double n, double r) {
    o->c[0] = m;
    o->c[1] = n;
    o->r = r;
    o->d = -2 * m;
    o->e = -2 * n;
    o->f = m * m + n * n - r * r;
}

int pc_circle3(const double p1[2], const double p2[2], const double p3[2], pc_circle_eq *out) {
    if (!finite2(p1) || !finite2(p2) || !finite2(p3)) return PC_ENONFINITE;
    double u[2] = {p2[0] - p1[0], p2[1] - p1[1]}, v[2] = {p3[0] - p1[0], p3[1] - p1[1]};
    double lu = hypot(u[0], u[1]), lv = hypot(v[0], v[1]);
    if (lu == 0 || lv == 0 || (p2[0] == p3[0] && p2[1] == p3[1])) return PC_ECOINCIDENT;
    if (!(fabs(u[0] * v[1] - u[1] * v[0]) > PC_DEGEN_TOL * lu * lv)) return PC_ECOLLINEAR;
    /* The book's system x^2 + y^2 + d x + e y + f = 0 at the three points (§3.2, example 1),
     * written about p1 (so p1 is the origin and large coordinates do not cancel); the
     * coefficients of the original equation follow from the centre and radius. */
    double m[9] = {0, 0, 1, u[0], u[1], 1, v[0], v[1], 1};
    double b[3] = {0, -(u[0] * u[0] + u[1] * u[1]), -(v[0] * v[0] + v[1] * v[1])};
    int st = pc_lu_solve(3, m, b);
    if (st != PC_OK) return PC_ECOLLINEAR;
    double cx = -b[0] / 2, cy = -b[1] / 2;
    circle_fill(out, p1[0] + cx, p1[1] + cy, sqrt(fmax(cx * cx + cy * cy - b[2], 0)));
    return PC_OK;
}

int pc_circle2r(const double p1[2], const double p2[2], double r, pc_circle_eq out[2]) {
    if (!finite2(p1) || !finite2(p2)) return PC_ENONFINITE;
    if (!(r > 0) || !isfinite(r)) return PC_EDOMAIN;
    double u[2] = {p2[0] - p1[0], p2[1] - p1[1]};
    double c = hypot(u[0], u[1]);
    if (c == 0) return PC_ECOINCIDENT;
    double h2 = r * r - c * c / 4;
    if (h2 < -1e-12 * r * r) return PC_EDOMAIN;       /* the chord is longer than 2r */
    double h = sqrt(fmax(h2, 0));
    double nl[2] = {-u[1] / c, u[0] / c};              /* left of p1 -> p2 */
    double mx = (p1[0] + p2[0]) / 2, my = (p1[1] + p2[1]) / 2;
    circle_fill(&out[0], mx - h * nl[0], my - h * nl[1], r);
    circle_fill(&out[1], mx + h * nl[0], my + h * nl[1], r);
    return PC_OK;
}

int pc_circle_slopes(const double p1[2], double m1, double x_end, double m2, pc_circle_eq out[2],
                     double ends[4], int *nsol) {
    *nsol = 0;
    if (!finite2(p1) || !isfinite(m1) || !isfinite(x_end) || !isfinite(m2)) return PC_ENONFINITE;
    if (x_end == p1[0]) return PC_EDOMAIN;
    /* The book (§3.2, example 3) solves for d, e, f from the point, the slope
     * -(2x + d)/(2y + e) = m1 there and the slope m2 at x = x_end.  Geometrically: the centre
     * is C = p1 + s n1 on the normal n1 at p1, and the end point E = C + sigma s n2 (n2 the
     * normal of the slope m2, sigma = +-1, |s| the radius) has the abscissa x_end, which fixes
     * s for each sigma. */
    double k1 = hypot(m1, 1), k2 = hypot(m2, 1);
    double n1[2] = {-m1 / k1, 1 / k1}, n2[2] = {-m2 / k2, 1 / k2};
    int n = 0;
    for (int sigma = 1; sigma >= -1; sigma -= 2) {
        double den = n1[0] + sigma * n2[0];
        if (fabs(den) <= 1e-14) continue;
        double s = (x_end - p1[0]) / den;
        double cx = p1[0] + s * n1[0], cy = p1[1] + s * n1[1];
        double ex = x_end, ey = cy + sigma * s * n2[1];
        if (!isfinite(s) || !isfinite(cy) || !isfinite(ey)) continue;
        circle_fill(&out[n], cx, cy, fabs(s));
        ends[2 * n] = ex;
        ends[2 * n + 1] = ey;
        n++;
    }
    if (n == 2 && out[0].c[0] == out[1].c[0] && out[0].c[1] == out[1].c[1] &&
        ends[1] == ends[3]) n = 1;
    if (n == 0) return PC_EDOMAIN;
    if (n == 2 && ends[3] > ends[1]) {                 /* highest end point first */
        pc_circle_eq t = out[0]; out[0] = out[1]; out[1] = t;
        double ty = ends[1]; ends[1] = ends[3]; ends[3] = ty;
    }
    *nsol = n;
    return PC_OK;
}

/* --- conics --------------------------------------------------------------------------------- */

int pc_conic_classify(double a, double b, double c, pc_conic_class *out) {
    if (!isfinite(a) || !isfinite(b) || !isfinite(c)) return PC_ENONFINITE;
    if (a == 0 && b == 0 && c == 0) return PC_EDOMAIN;
    double disc = b * b - 4 * a * c, scale = fmax(b * b, fabs(4 * a * c));
    if (fabs(disc) <= 1e-12 * scale) *out = PC_CONIC_PARABOLA;
    else *out = disc < 0 ? PC_CONIC_ELLIPSE : PC_CONIC_HYPERBOLA;
    return PC_OK;
}

void pc_conic_rotate(const double in[6], double t, double out[6]) {
    double c = cos(t), s = sin(t);
    double a1 = in[0], b1 = in[1], c1 = in[2], d1 = in[3], e1 = in[4];
    /* x' = x c - y s, y' = x s + y c substituted; with b' = 0 these are the book's
     * a = a'c^2 + c's^2, b = 2(c' - a') c s (corrected), c = a's^2 + c'c^2, d = d'c + e's,
     * e = e'c - d's, f = f' */
    out[0] = a1 * c * c + b1 * c * s + c1 * s * s;
    out[1] = 2 * (c1 - a1) * c * s + b1 * (c * c - s * s);
    out[2] = a1 * s * s - b1 * c * s + c1 * c * c;
    out[3] = d1 * c + e1 * s;
    out[4] = e1 * c - d1 * s;
    out[5] = in[5];
}

double pc_conic_value(const double k[6], double x, double y) {
    return k[0] * x * x + k[1] * x * y + k[2] * y * y + k[3] * x + k[4] * y + k[5];
}

void pc_conic_ellipse_coef(double m, double n, double A, double B, double out[6]) {
    double a2 = A * A, b2 = B * B;           /* §3.3: a' = B^2, c' = A^2, ... */
    out[0] = b2; out[1] = 0; out[2] = a2;
    out[3] = -2 * b2 * m; out[4] = -2 * a2 * n;
    out[5] = b2 * m * m + a2 * n * n - a2 * b2;
}

void pc_conic_hyperbola_coef(double m, double n, double A, double B, double out[6]) {
    double a2 = A * A, b2 = B * B;
    out[0] = b2; out[1] = 0; out[2] = -a2;
    out[3] = -2 * b2 * m; out[4] = 2 * a2 * n;
    out[5] = b2 * m * m - a2 * n * n - a2 * b2;
}

void pc_conic_parabola_coef(double m, double n, double p, double out[6]) {
    /* (x - m)^2 = 4p(y - n): f = m^2 + 4pn (the book prints m^2 - 4pn) */
    out[0] = 1; out[1] = 0; out[2] = 0;
    out[3] = -2 * m; out[4] = -4 * p; out[5] = m * m + 4 * p * n;
}

/* the coefficients of a conic by kind: 0 ellipse, 1 hyperbola (semi-axes A, B), 2 parabola (p = A) */
int pc_conic_coef(int kind, const double c[2], double A, double B, double out[6]) {
    if (kind == 2) {
        pc_conic_parabola_coef(c[0], c[1], A, out);
        return PC_OK;
    }
    if (!(A > 0) || !(B > 0)) return PC_EDOMAIN;
    (kind ? pc_conic_hyperbola_coef : pc_conic_ellipse_coef)(c[0], c[1], A, B, out);
    return PC_OK;
}

/* --- generators ----------------------------------------------------------------------------- */

int pc_conic_points(pc_gen_kind kind, pc_gen_method method, double A, double B, double step,
                    int n, double *xy) {
    if (!isfinite(A) || !isfinite(B) || !isfinite(step)) return PC_ENONFINITE;
    if (n < 0 || !(A > 0)) return PC_EDOMAIN;
    int uses_b = kind == PC_GEN_ELLIPSE || kind == PC_GEN_HYPERBOLA_SEC || kind == PC_GEN_HYPERBOLA_COSH;
    if (uses_b && !(B > 0)) return PC_EDOMAIN;
    if ((method == PC_GEN_RATIONAL || method == PC_GEN_EXPLICIT) && kind != PC_GEN_CIRCLE)
        return PC_EDOMAIN;
    if (kind == PC_GEN_CIRCLE) B = A;
    if (kind == PC_GEN_HYPERBOLA_SEC && !(fabs(n * step) < PI / 2)) return PC_EDOMAIN;
    if (method == PC_GEN_EXPLICIT && A - n * step < -A * (1 + 1e-12)) return PC_EDOMAIN;
    double cd = cos(step), sd = sin(step), td = tan(step), ch = cosh(step), sh = sinh(step);
    for (int i = 0; i <= n; i++) {
        double *o = xy + 2 * i, th = i * step;
        if (method == PC_GEN_PARAM) {
            switch (kind) {
            case PC_GEN_CIRCLE: case PC_GEN_ELLIPSE: o[0] = A * cos(th); o[1] = B * sin(th); break;
            case PC_GEN_PARABOLA: o[0] = A * th * th; o[1] = 2 * A * th; break;
            case PC_GEN_HYPERBOLA_SEC: o[0] = A / cos(th); o[1] = B * tan(th); break;
            case PC_GEN_HYPERBOLA_COSH: o[0] = A * cosh(th); o[1] = B * sinh(th); break;
            }
        } else if (method == PC_GEN_RATIONAL) {
            o[0] = A * (1 - th * th) / (1 + th * th);
            o[1] = 2 * A * th / (1 + th * th);
        } else if (method == PC_GEN_EXPLICIT) {
            o[0] = A - th;
            o[1] = sqrt(fmax(A * A - o[0] * o[0], 0));
        } else if (i == 0) {                            /* the recurrences' starting points */
            o[0] = kind == PC_GEN_PARABOLA ? 0 : A;
            o[1] = 0;
        } else {
            const double x = o[-2], y = o[-1];
            switch (kind) {
            case PC_GEN_CIRCLE: case PC_GEN_ELLIPSE:    /* §3.2, §3.3 */
                o[0] = x * cd - (A / B) * y * sd;
                o[1] = (B / A) * x * sd + y * cd;
                break;
            case PC_GEN_PARABOLA:                        /* §3.4, + y dth (printed - y dth) */
                o[0] = x + y * step + A * step * step;
                o[1] = y + 2 * A * step;
                break;
            case PC_GEN_HYPERBOLA_SEC: {                 /* §3.5, B - y tan (printed B + y tan) */
                double dx = B * cd - y * sd, dy = B - y * td;
                if (!(dx > 0) || !(dy > 0)) return PC_EDOMAIN;
                o[0] = B * x / dx;
                o[1] = B * (y + B * td) / dy;
                break;
            }
            case PC_GEN_HYPERBOLA_COSH:
                o[0] = x * ch + (A / B) * y * sh;
                o[1] = (B / A) * x * sh + y * ch;
                break;
            }
        }
        if (!finite2(o)) return PC_ENONFINITE;
    }
    return PC_OK;
}

/* --- conics as curves ----------------------------------------------------------------------- */

/* A rational quadratic piece into cp (rows 0..2 of 3 doubles; row 0 is shared with the previous
 * piece): the ends and the meeting point of the tangents with the weight w. */
static void put_row(double *row, double x, double y, double w) {
    row[0] = w * x;
    row[1] = w * y;
    row[2] = w;
}

/* ---- the book's parameter on the rational pieces ------------------------------------------
 * A rational quadratic piece of the circle (cos, sin) over [m - h, m + h] with weights
 * (1, cos h, 1) reaches the angle m + x at its own parameter s with tan(x/2) = tan(h/2)(2s - 1);
 * the hyperbola's (ch, sh) piece with weights (1, ch h, 1) likewise with tanh.  The affine image
 * keeps the relation, so evaluating the piece at s(theta) gives the book's point at theta
 * exactly, and the conic stays the rational curve it is (issue 24: before this the piece's
 * parameter was taken for the angle, up to 0.92 degrees off between the quarter turns). */
typedef struct {
    pc_curve *pieces;   /* BEZIER of degree 2, breakpoints = the book's parameter */
    int hyper;          /* 1: tanh, 0: tan */
} reparam;

static void reparam_free(void *ud) {
    reparam *r = ud;
    pc_curve_release(r->pieces);
    free(r);
}

static int reparam_eval(void *ud, double th, int order, double *out) {
    const reparam *r = ud;
    const pc_curve *b = r->pieces;
    int nseg = b->nknots - 1, i = 0;
    while (i < nseg - 1 && th > b->knots[i + 1]) i++;
    double k0 = b->knots[i], k1 = b->knots[i + 1], h = (k1 - k0) / 2, x = th - (k0 + h);
    /* s = (1 + g(x/2)/g(h/2))/2 with g = tan or tanh; s' and s'' from g' = 1 +- g^2 */
    double g = r->hyper ? tanh(x / 2) : tan(x / 2), gh = r->hyper ? tanh(h / 2) : tan(h / 2);
    double dg = r->hyper ? 1 - g * g : 1 + g * g;                  /* d g / d(x/2) */
    double s = (1 + g / gh) / 2, s1 = dg / (4 * gh);
    double s2 = (r->hyper ? -1 : 1) * g * dg / (4 * gh);
    if (!isfinite(s)) return PC_ENONFINITE;
    double tau = k0 + 2 * h * s, t1 = 2 * h * s1, t2 = 2 * h * s2, hb[9];
    int st = pc_curve_eval_h(b, tau, order, hb);
    if (st != PC_OK) return st;
    for (int k = 0; k < 3; k++) {
        out[k] = hb[k];
        if (order >= 1) out[3 + k] = hb[3 + k] * t1;
        if (order >= 2) out[6 + k] = hb[6 + k] * t1 * t1 + hb[3 + k] * t2;
    }
    return PC_OK;
}

/* The FUNC curve over the pieces' breakpoints that evaluates piece i at s(theta); takes pc. */
static pc_curve *reparam_curve(pc_curve *pc, int hyper, int closed, int *status) {
    if (!pc) return NULL;
    reparam *r = malloc(sizeof *r);
    if (!r) {
        pc_curve_release(pc);
        *status = PC_ENOMEM;
        return NULL;
    }
    r->pieces = pc;
    r->hyper = hyper;
    pc_curve *cv = pc_curve_func_breaks(2, pc->t0, pc->t1, closed, pc->nknots - 2, pc->knots + 1,
                                        reparam_eval, reparam_free, r, status);
    if (!cv) reparam_free(r);
    return cv;
}

pc_curve *pc_curve_ellipse(const double c[2], double A, double B, double th0, double th1,
                           int *status) {
    if (!finite2(c) || !isfinite(A) || !isfinite(B) || !isfinite(th0) || !isfinite(th1)) {
        *status = PC_ENONFINITE;
        return NULL;
    }
    if (!(A > 0) || !(B > 0) || !(th1 > th0) || th1 - th0 > 16 * PI) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    int nseg = (int)ceil((th1 - th0) / (PI / 2) - 1e-9);
    if (nseg < 1) nseg = 1;
    double *cp = malloc(sizeof(double) * 3 * (size_t)(2 * nseg + 1));
    double *brk = malloc(sizeof(double) * (size_t)(nseg + 1));
    if (!cp || !brk) {
        free(cp); free(brk);
        *status = PC_ENOMEM;
        return NULL;
    }
    double h = (th1 - th0) / nseg / 2, w = cos(h);
    for (int i = 0; i <= nseg; i++) {
        double a = th0 + 2 * h * i;
        brk[i] = i == nseg ? th1 : a;
        put_row(cp + 6 * i, c[0] + A * cos(brk[i]), c[1] + B * sin(brk[i]), 1);
        if (i < nseg)   /* the tangents at a and a + 2h meet at the mid angle, 1/cos h out */
            put_row(cp + 6 * i + 3, c[0] + A * cos(a + h) / w, c[1] + B * sin(a + h) / w, w);
    }
    pc_curve *cv = pc_curve_bezier_pieces(2, 2, nseg, cp, brk, status);
    free(cp);
    free(brk);
    return reparam_curve(cv, 0, fabs(th1 - th0 - 2 * PI) < 1e-12, status);
}

pc_curve *pc_curve_parabola(double A, double th0, double th1, int *status) {
    if (!isfinite(A) || !isfinite(th0) || !isfinite(th1)) {
        *status = PC_ENONFINITE;
        return NULL;
    }
    if (!(A > 0) || !(th1 > th0)) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    /* (A th^2, 2A th) is a quadratic polynomial: its Bezier points over [th0, th1] */
    double cp[9];
    put_row(cp, A * th0 * th0, 2 * A * th0, 1);
    put_row(cp + 3, A * th0 * th1, A * (th0 + th1), 1);
    put_row(cp + 6, A * th1 * th1, 2 * A * th1, 1);
    double brk[2] = {th0, th1};
    return pc_curve_bezier_pieces(2, 2, 1, cp, brk, status);
}

pc_curve *pc_curve_hyperbola(double A, double B, double t0, double t1, int *status) {
    if (!isfinite(A) || !isfinite(B) || !isfinite(t0) || !isfinite(t1)) {
        *status = PC_ENONFINITE;
        return NULL;
    }
    if (!(A > 0) || !(B > 0) || !(t1 > t0) || fabs(t0) > 300 || fabs(t1) > 300) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    int nseg = (int)ceil(t1 - t0 - 1e-9);
    if (nseg < 1) nseg = 1;
    double *cp = malloc(sizeof(double) * 3 * (size_t)(2 * nseg + 1));
    double *brk = malloc(sizeof(double) * (size_t)(nseg + 1));
    if (!cp || !brk) {
        free(cp); free(brk);
        *status = PC_ENOMEM;
        return NULL;
    }
    /* The symmetric arc of x^2 - y^2 = 1 over [-h, h] has the ends (ch h, -+sh h), the
     * tangents meeting at (1/ch h, 0) and the weight ch h; the hyperbolic rotation by the
     * mid parameter m (a linear map keeping the hyperbola) moves it to [m - h, m + h]. */
    double h = (t1 - t0) / nseg / 2, w = cosh(h);
    for (int i = 0; i <= nseg; i++) {
        brk[i] = i == nseg ? t1 : t0 + 2 * h * i;
        put_row(cp + 6 * i, A * cosh(brk[i]), B * sinh(brk[i]), 1);
        if (i < nseg) {
            double m = t0 + 2 * h * i + h;
            put_row(cp + 6 * i + 3, A * cosh(m) / w, B * sinh(m) / w, w);
        }
    }
    pc_curve *cv = pc_curve_bezier_pieces(2, 2, nseg, cp, brk, status);
    free(cp);
    free(brk);
    return reparam_curve(cv, 1, 0, status);
}

pc_curve *pc_curve_arc3(const double p1[2], const double p2[2], const double p3[2], int *status) {
    pc_circle_eq ce;
    *status = pc_circle3(p1, p2, p3, &ce);
    if (*status != PC_OK) return NULL;
    double a1 = atan2(p1[1] - ce.c[1], p1[0] - ce.c[0]);
    double a2 = atan2(p2[1] - ce.c[1], p2[0] - ce.c[0]);
    double a3 = atan2(p3[1] - ce.c[1], p3[0] - ce.c[0]);
    while (a2 < a1) a2 += 2 * PI;
    while (a3 < a1) a3 += 2 * PI;
    double t0 = a1, t1 = a3;               /* counter-clockwise p1, p2, p3 */
    if (a2 > a3) {                         /* counter-clockwise p3, p2, p1 */
        a3 = atan2(p3[1] - ce.c[1], p3[0] - ce.c[0]);
        while (a1 <= a3) a1 += 2 * PI;
        t0 = a3;
        t1 = a1;
    }
    double k = floor((t0 + PI) / (2 * PI));  /* the start angle in [-pi, pi) */
    return pc_curve_ellipse(ce.c, ce.r, ce.r, t0 - 2 * PI * k, t1 - 2 * PI * k, status);
}

pc_curve *pc_curve_arc_dir(const double c[2], double r, const double a[2], const double dir[2],
                           const double b[2], int *status) {
    if (!finite2(c) || !finite2(a) || !finite2(b) || !finite2(dir) || !isfinite(r)) {
        *status = PC_ENONFINITE;
        return NULL;
    }
    double ra[2] = {a[0] - c[0], a[1] - c[1]}, rb[2] = {b[0] - c[0], b[1] - c[1]};
    double turn = ra[0] * dir[1] - ra[1] * dir[0];      /* > 0: counter-clockwise at a */
    if (!(r > 0) || fabs(hypot(ra[0], ra[1]) - r) > 1e-9 * r || fabs(hypot(rb[0], rb[1]) - r) > 1e-9 * r ||
        !(fabs(turn) > PC_DEGEN_TOL * r * hypot(dir[0], dir[1])) || (a[0] == b[0] && a[1] == b[1])) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    double ta = atan2(ra[1], ra[0]), tb = atan2(rb[1], rb[0]);
    if (turn > 0) {
        while (tb <= ta) tb += 2 * PI;
        return pc_curve_ellipse(c, r, r, ta, tb, status);
    }
    while (ta <= tb) ta += 2 * PI;
    return pc_curve_ellipse(c, r, r, tb, ta, status);
}
