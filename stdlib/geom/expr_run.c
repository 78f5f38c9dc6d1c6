/* Running a point equation with the reasons it fails worded for the bindings (expr.h): the
 * value at the parameters' values, the samples over an interval, a status's meaning. */
#include <stdio.h>
#include "expr.h"
#include "names.h"

const char *pc_expr_why(int st) {
    return st == PC_ENOMEM ? "out of memory (too many equation nodes)" : pc_strerror(st);
}

int pc_expr_value_at(const pc_expr_pool *pool, pc_expr_prog *p, int n, const int *in, const double *x,
                     double *h, char *why, size_t size) {
    int st = pc_expr_eval(p, 1, x, 0, h, NULL);
    if (st == PC_ENONFINITE) {
        char at[PC_EXPR_MAXPARAM * (PC_EXPR_MAXNAME + 28)];
        pc_expr_param_values(pool, n, in, x, at, sizeof at);
        snprintf(why, size, "the value at %s is not finite (NaN or infinite: outside the domain of a function, "
                 "or a division by zero)", at);
    } else if (st != PC_OK) {
        snprintf(why, size, "%s", pc_expr_why(st));
    }
    return st;
}

int pc_expr_sample_at(const pc_expr_pool *pool, pc_expr_prog *p, int k, double a, double b, long n,
                      double *out, char *why, size_t size) {
    long bad = 0;
    int st = pc_expr_sample(p, a, b, n, out, &bad);
    if (st == PC_ENONFINITE) {
        char num[40];
        double t = n > 1 ? a + (b - a) * (double)bad / (double)(n - 1) : a;
        snprintf(why, size, "the value at %s = %s is not finite", pc_expr_param_name(pool, k),
                 pc_num_text(t, num, sizeof num));
    } else if (st != PC_OK) {
        snprintf(why, size, "%s", pc_expr_why(st));
    }
    return st;
}
