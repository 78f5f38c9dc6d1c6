/* The coordinates of a polynomial or rational curve expanded as the book prints them. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "status.h"
#include "point.h"
#include "konop_print.h"
#include "curve.h"

typedef struct { char *p; size_t left; int over; } out;

static void put(out *o, const char *s) {
    size_t k = strlen(s);
    if (k >= o->left) { o->over = 1; return; }
    memcpy(o->p, s, k + 1);
    o->p += k, o->left -= k;
}

/* sum c_j var^j, highest power first: "3t^3 - 2t + 1" */
static void poly(out *o, const double *c, int deg, const char *var) {
    double big = 0;
    for (int j = 0; j <= deg; j++) big = fmax(big, fabs(c[j]));
    int first = 1;
    for (int j = deg; j >= 0; j--) {
        double v = c[j];
        if (fabs(v) <= 1e-12 * big || v == 0) continue;
        char num[48];
        put(o, first ? (v < 0 ? "-" : "") : (v < 0 ? " - " : " + "));
        v = fabs(v);
        if (j == 0 || fabs(v - 1) > 1e-12) {
            snprintf(num, sizeof num, "%.6g", v);
            put(o, num);
        }
        if (j > 0) put(o, var);
        if (j > 1) { snprintf(num, sizeof num, "^%d", j); put(o, num); }
        first = 0;
    }
    if (first) put(o, "0");
}

int pc_k_coordinate_text(const double *coef, int dim, int deg, int axis, const char *var,
                         char *buf, size_t n) {
    if (dim < 1 || dim > PC_MAXDIM || axis < 0 || axis >= dim || deg < 0 || deg > 64) return PC_EDIM;
    if (n == 0) return PC_ENOMEM;
    int w = dim + 1;
    double num[65], den[65], big = 0;
    for (int j = 0; j <= deg; j++) {
        num[j] = coef[j * w + axis], den[j] = coef[j * w + dim];
        big = fmax(big, fabs(den[j]));
    }
    if (!(big > 0)) return PC_EDOMAIN;
    int top = 0, constant = 1;              /* the denominator's degree; is it a constant? */
    for (int j = 0; j <= deg; j++)
        if (fabs(den[j]) > 1e-12 * big) top = j;
    for (int j = 1; j <= deg; j++)
        if (fabs(den[j]) > 1e-12 * big) constant = 0;
    double s = den[top];
    for (int j = 0; j <= deg; j++) num[j] /= s, den[j] /= s;
    static const char *names[3] = {"x", "y", "z"};
    char lhs[32];
    if (axis < 3) snprintf(lhs, sizeof lhs, "%s = ", names[axis]);
    else snprintf(lhs, sizeof lhs, "x%d = ", axis + 1);
    out o = {buf, n, 0};
    buf[0] = 0;
    put(&o, lhs);
    if (constant) poly(&o, num, deg, var);
    else {
        put(&o, "(");
        poly(&o, num, deg, var);
        put(&o, ")/(");
        poly(&o, den, top, var);
        put(&o, ")");
    }
    return o.over ? PC_ENOMEM : PC_OK;
}

int pc_k_curve_text(const pc_curve *c, int axis, const char *var, char *buf, size_t n) {
    double coef[(PC_CURVE_MAXDEG + 1) * (PC_MAXDIM + 1)];
    int deg, st = pc_curve_monomial(c, 0, coef, &deg);
    return st ? st : pc_k_coordinate_text(coef, c->dim, deg, axis, var, buf, n);
}
