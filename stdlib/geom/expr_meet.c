/* The meet of two lines of point equations (expr.h pc_expr_meet): an equation built from the
 * pool's own operations, so it is compiled with exact derivatives like any other (issue 23:
 * "meet of point equations", a scheme of meets written as the book writes it). */
#include "expr.h"

/* r = op(a, b), or the failure passed on */
#define TRY(r, call)        \
    do {                    \
        (r) = (call);       \
        if ((r) < 0) return -1; \
    } while (0)

int pc_expr_meet(pc_expr_pool *pool, int a1, int a2, int b1, int b2, int *lambda, int *mu,
                 int *status) {
    int d1, d2, r, D11, D12, D22, R1, R2, t1, t2, num, den, lam, m, k, step;
    /* A1 + lambda (A2 - A1) = B1 + mu (B2 - B1): the normal equations of lambda d1 - mu d2 = r,
     * [d1.d1 -d1.d2; -d1.d2 d2.d2] (lambda, mu) = (d1.r, -d2.r), exact where the lines meet */
    TRY(d1, pc_expr_sub(pool, a2, a1, status));
    TRY(d2, pc_expr_sub(pool, b2, b1, status));
    TRY(r, pc_expr_sub(pool, b1, a1, status));
    TRY(D11, pc_expr_dot(pool, d1, d1, status));
    TRY(D12, pc_expr_dot(pool, d1, d2, status));
    TRY(D22, pc_expr_dot(pool, d2, d2, status));
    TRY(R1, pc_expr_dot(pool, d1, r, status));
    TRY(R2, pc_expr_dot(pool, d2, r, status));
    TRY(t1, pc_expr_mul(pool, R1, D22, status));
    TRY(t2, pc_expr_mul(pool, R2, D12, status));
    TRY(num, pc_expr_sub(pool, t1, t2, status));
    TRY(t1, pc_expr_mul(pool, D11, D22, status));
    TRY(t2, pc_expr_mul(pool, D12, D12, status));
    TRY(den, pc_expr_sub(pool, t1, t2, status));
    TRY(lam, pc_expr_div(pool, num, den, status));
    TRY(step, pc_expr_mul(pool, d1, lam, status));
    TRY(k, pc_expr_add(pool, a1, step, status));
    if (lambda) *lambda = lam;
    if (mu) {
        TRY(t1, pc_expr_mul(pool, R1, D12, status));
        TRY(t2, pc_expr_mul(pool, R2, D11, status));
        TRY(num, pc_expr_sub(pool, t1, t2, status));
        TRY(m, pc_expr_div(pool, num, den, status));
        *mu = m;
    }
    return k;
}
