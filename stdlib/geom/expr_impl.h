/* Internal to stdlib/geom/expr*.c: the pool's nodes (not an API). */
#ifndef PC_EXPR_IMPL_H
#define PC_EXPR_IMPL_H

#include "expr.h"

typedef struct {
    unsigned char op;     /* pc_expr_op */
    unsigned char dim;    /* 0: scalar; n: a value of dimension n (n+1 doubles) */
    int a, b;             /* operands (-1: none) */
    int k;                /* PARAM: index; COMP: coordinate; POWI: exponent; SMOOTH: gfun index */
    int c;                /* CONST, VCONST, POWC: offset of its constant(s) in consts, else -1 */
    unsigned pmask;       /* the parameters it depends on */
} pc_expr_node;

struct pc_expr_pool {
    pc_expr_node *nodes;
    int n, cap;
    double *consts;
    int nconsts, cconsts;
    pc_gfun *gfuns;
    int ngfuns, cgfuns;
    int *table;           /* open addressing: node id + 1, 0 empty */
    int tcap;             /* a power of 2 */
    char names[PC_EXPR_MAXPARAM][PC_EXPR_MAXNAME];
    int nparams;
    int param_node[PC_EXPR_MAXPARAM];
};

/* Mark (mark[0..e], 1 = needed) the nodes e needs, e included.  PC_ENOMEM. */
int pc_expr_reach(const pc_expr_pool *p, int e, unsigned char *mark);

/* width of a node's result in doubles */
static inline int pc_expr_width(int dim) { return dim ? dim + 1 : 1; }

/* x^k for an integer k by repeated squaring (exact for small k, as a hand-written product):
 * constant folding (expr.c) and the programs (expr_eval.c) compute powers alike. */
static inline double pcx_ipow(double x, int k) {
    int neg = k < 0;
    unsigned n = neg ? (unsigned)(-k) : (unsigned)k;
    double r = 1, b = x;
    while (n) {
        if (n & 1) r *= b;
        b *= b;
        n >>= 1;
    }
    return neg ? 1 / r : r;
}

#endif
