/* A point equation's coordinates as the book prints them (konop_expanded.h). */
#include "konop_expanded.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "konop_print.h"

int pc_k_expanded(const pc_expr_pool *pool, int e, char *texts, size_t each, char *why, size_t size) {
    int in[PC_EXPR_MAXPARAM], n = pc_expr_param_list(pool, e, in), dim = pc_expr_dim(pool, e);
    if (n != 1) {
        char names[PC_EXPR_MAXPARAM * (PC_EXPR_MAXNAME + 2)];
        pc_expr_param_names(pool, n, in, names, sizeof names);
        if (n) snprintf(why, size, "the equation has the parameters %s: fix all but one with M:with{...} first", names);
        else snprintf(why, size, "the equation has no parameter: it is a constant");
        return -1;
    }
    int rows = dim ? dim + 1 : 2, axes = dim ? dim : 1, deg;
    double *coef = malloc(sizeof(double) * (size_t)(PC_CURVE_MAXDEG + 1) * (size_t)rows);
    int st = coef ? pc_expr_power_basis(pool, e, in[0], PC_CURVE_MAXDEG, coef, &deg) : PC_ENOMEM;
    if (st == PC_EDOMAIN)
        snprintf(why, size, "only an equation rational in its parameter expands in its powers (built by + - * /, "
                 "integer powers, dot, lerp, bar; no sin, exp, sqrt, smoothsteps or real powers) of degree up to %d",
                 PC_CURVE_MAXDEG);
    const char *var = pc_expr_param_name(pool, in[0]);
    for (int x = 0; x < axes && st == PC_OK; x++) {
        char *buf = texts + (size_t)x * each;
        st = pc_k_coordinate_text(coef, axes, deg, x, var, buf, each);
        if (st == PC_EDOMAIN) snprintf(why, size, "the equation's weight (its denominator) is identically 0");
        if (st == PC_OK && !dim) memmove(buf, buf + 4, strlen(buf + 4) + 1);   /* a scalar: no "x = " */
    }
    free(coef);
    if (st != PC_OK && st != PC_EDOMAIN) snprintf(why, size, "%s", pc_strerror(st));
    return st == PC_OK ? axes : -1;
}
