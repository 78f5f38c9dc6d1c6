/* The parameters of a point equation (expr.h): which ones it depends on, in order; a name
 * looked up; their names and values as the messages list them; and the weight class of an
 * equation over the unit box of its parameters (the membership condition at build time). */
#include <stdio.h>
#include <string.h>
#include "expr.h"

int pc_expr_param_list(const pc_expr_pool *pool, int e, int *in) {
    unsigned mask = pc_expr_params(pool, e);
    int n = 0;
    for (int k = 0; k < PC_EXPR_MAXPARAM; k++)
        if (mask & (1u << k)) in[n++] = k;
    return n;
}

int pc_expr_find_param(const pc_expr_pool *pool, const char *name) {
    for (int k = 0; name && k < pc_expr_nparams(pool); k++)
        if (!strcmp(pc_expr_param_name(pool, k), name)) return k;
    return -1;
}

/* Append s to buf (size bytes, kept 0-terminated); the length the whole text needs. */
static size_t append(char *buf, size_t size, size_t len, const char *s) {
    size_t add = strlen(s);
    if (len < size) snprintf(buf + len, size - len, "%s", s);
    return len + add;
}

size_t pc_expr_param_names(const pc_expr_pool *pool, int n, const int *in, char *buf, size_t size) {
    size_t len = 0;
    if (size) buf[0] = 0;
    for (int j = 0; j < n; j++) {
        if (j) len = append(buf, size, len, j == n - 1 ? " and " : ", ");
        len = append(buf, size, len, pc_expr_param_name(pool, in[j]));
    }
    return len;
}

size_t pc_expr_param_values(const pc_expr_pool *pool, int n, const int *in, const double *x, char *buf,
                            size_t size) {
    size_t len = 0;
    if (size) buf[0] = 0;
    for (int j = 0; j < n; j++) {
        char one[64];
        snprintf(one, sizeof one, "%s%s = %.14g", j ? ", " : "", pc_expr_param_name(pool, in[j]),
                 x[j] == 0 ? 0.0 : x[j]);   /* no "-0", as points print */
        len = append(buf, size, len, one);
    }
    return len;
}

int pc_expr_weight_class(const pc_expr_pool *pool, int e) {
    int in[PC_EXPR_MAXPARAM], st;
    int n = pc_expr_param_list(pool, e, in);
    pc_expr_prog *prog = pc_expr_compile(pool, e, n, in, &st);
    if (!prog) return -1;
    double lo[PC_EXPR_MAXPARAM] = {0}, hi[PC_EXPR_MAXPARAM];
    for (int j = 0; j < n; j++) hi[j] = 1;
    int kind = pc_expr_prog_weight(prog, lo, hi, NULL, NULL);
    pc_expr_prog_free(prog);
    return kind;
}
