/* Point equations compiled (expr.h): a program of instructions over registers, each register
 * holding a batch of BATCH samples of a node's value and its derivatives ("jets"), so that
 * every instruction is a short loop the compiler vectorises.  Derivatives are forward mode:
 * linear operations act on every jet row alike, products follow Leibniz's rule and functions
 * the chain rule, up to second order:
 *   (xy)_i = x_i y + x y_i,   (xy)_ij = x_ij y + x_i y_j + x_j y_i + x y_ij,
 *   f(x)_i = f'(x) x_i,       f(x)_ij = f'(x) x_ij + f''(x) x_i x_j. */
#if defined(__GNUC__) && !defined(__clang__) && !defined(__OPTIMIZE_SIZE__)
#pragma GCC optimize("O3")     /* the lane loops are written to be vectorised */
#endif
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "expr_impl.h"

#define BATCH 256
#define PI 3.14159265358979323846

typedef struct {
    unsigned char op, w, aw;  /* operation, width of the result, width of operand a */
    int k;                    /* COMP: coordinate; POWI: exponent; SIN, COS: 1 when the
                                 instruction also computes the other one into b (sincos) */
    double c;                 /* POWC: exponent */
    pc_gfun g;                /* SMOOTH */
    size_t dst, a, b;         /* register offsets in the workspace */
} ins_t;

struct pc_expr_prog {
    int nin, dim, width;
    int jmax;                 /* jet rows a register holds */
    int maxorder;             /* 2 for up to two inputs, else 1 */
    int nins, nregs;
    ins_t *ins;
    size_t root;              /* the result's register */
    size_t in_off[PC_EXPR_MAXPARAM];
    int in_used[PC_EXPR_MAXPARAM];
    double *ws;
    int counts[PC_EX_NOPS];
};

int pc_expr_jets(int nin, int order) {
    if (order <= 0) return 1;
    if (order == 1) return 1 + nin;
    return 1 + nin + nin * (nin + 1) / 2;
}

/* the row of the second partial (d1, d2), d1 <= d2 */
static int sidx(int nd, int d1, int d2) { return 1 + nd + d1 * nd - d1 * (d1 - 1) / 2 + (d2 - d1); }

int pc_expr_prog_dim(const pc_expr_prog *p) { return p->dim; }
int pc_expr_prog_nin(const pc_expr_prog *p) { return p->nin; }
int pc_expr_prog_size(const pc_expr_prog *p) { return p->nins; }
int pc_expr_prog_registers(const pc_expr_prog *p) { return p->nregs; }
int pc_expr_prog_count(const pc_expr_prog *p, pc_expr_op op) {
    return op >= 0 && op < PC_EX_NOPS ? p->counts[op] : 0;
}

void pc_expr_prog_free(pc_expr_prog *p) {
    if (!p) return;
    free(p->ins);
    free(p->ws);
    free(p);
}

/* ---- compiling ----------------------------------------------------------------------------- */

typedef struct { size_t off; int w; } reg_t;

typedef struct {
    reg_t *regs;
    int nregs, cregs;
    int *freel[PC_MAXDIM + 2];     /* free registers by width */
    int nfree[PC_MAXDIM + 2], cfree[PC_MAXDIM + 2];
    size_t top;                    /* doubles allocated so far */
    size_t per;                    /* doubles per unit of width: jmax * BATCH */
} alloc_t;

static int reg_new(alloc_t *a, int w) {
    if (a->nfree[w]) return a->freel[w][--a->nfree[w]];
    if (a->nregs == a->cregs) {
        int cap = a->cregs ? 2 * a->cregs : 32;
        reg_t *r = realloc(a->regs, sizeof *r * (size_t)cap);
        if (!r) return -1;
        a->regs = r;
        a->cregs = cap;
    }
    a->regs[a->nregs].off = a->top;
    a->regs[a->nregs].w = w;
    a->top += (size_t)w * a->per;
    return a->nregs++;
}

static int reg_free(alloc_t *a, int r) {
    int w = a->regs[r].w;
    if (a->nfree[w] == a->cfree[w]) {
        int cap = a->cfree[w] ? 2 * a->cfree[w] : 8;
        int *f = realloc(a->freel[w], sizeof *f * (size_t)cap);
        if (!f) return PC_ENOMEM;
        a->freel[w] = f;
        a->cfree[w] = cap;
    }
    a->freel[w][a->nfree[w]++] = r;
    return PC_OK;
}

static int is_leaf(int op) { return op == PC_EX_CONST || op == PC_EX_VCONST || op == PC_EX_PARAM; }

pc_expr_prog *pc_expr_compile(const pc_expr_pool *pool, int e, int nin, const int *inputs,
                              int *status) {
    if (nin < 0 || nin > PC_EXPR_MAXPARAM || e < 0 || e >= pool->n) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    unsigned have = 0;
    for (int j = 0; j < nin; j++) {
        if (inputs[j] < 0 || inputs[j] >= pool->nparams || (have & (1u << inputs[j]))) {
            *status = PC_EDOMAIN;
            return NULL;
        }
        have |= 1u << inputs[j];
    }
    if (pool->nodes[e].pmask & ~have) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    pc_expr_prog *p = calloc(1, sizeof *p);
    unsigned char *mark = malloc((size_t)e + 1);
    int *last = malloc(sizeof *last * ((size_t)e + 1));
    int *reg = malloc(sizeof *reg * ((size_t)e + 1));
    /* sin x and cos x of one x are computed together (one sincos, as a C compiler would):
     * partner[i] = the other node + 1 for the first of the two, -(first + 1) for the second */
    int *partner = calloc((size_t)e + 1, sizeof *partner);
    int *sin_of = malloc(sizeof *sin_of * ((size_t)e + 1));
    alloc_t al;
    memset(&al, 0, sizeof al);
    int st = PC_ENOMEM;
    if (!p || !mark || !last || !reg || !partner || !sin_of || pc_expr_reach(pool, e, mark) != PC_OK)
        goto fail;
    for (int i = 0; i <= e; i++) sin_of[i] = -1;
    for (int i = 0; i <= e; i++)
        if (mark[i] && pool->nodes[i].op == PC_EX_SIN) sin_of[pool->nodes[i].a] = i;
    for (int i = 0; i <= e; i++) {
        if (!mark[i] || pool->nodes[i].op != PC_EX_COS || sin_of[pool->nodes[i].a] < 0) continue;
        int j = sin_of[pool->nodes[i].a], first = j < i ? j : i, second = j < i ? i : j;
        partner[first] = second + 1;
        partner[second] = -(first + 1);
    }
    p->nin = nin;
    p->dim = pool->nodes[e].dim;
    p->width = pc_expr_width(p->dim);
    p->maxorder = nin <= 2 ? 2 : 1;
    p->jmax = pc_expr_jets(nin, p->maxorder);
    al.per = (size_t)p->jmax * BATCH;

    /* the last instruction (node id) that reads each node */
    int ninstr = 0;
    for (int i = 0; i <= e; i++) {
        last[i] = -1;
        if (!mark[i]) continue;
        const pc_expr_node *nd = &pool->nodes[i];
        if (!is_leaf(nd->op)) ninstr++;
        if (nd->a >= 0) last[nd->a] = i;
        if (nd->b >= 0) last[nd->b] = i;
    }
    p->ins = malloc(sizeof *p->ins * (size_t)(ninstr ? ninstr : 1));
    if (!p->ins) goto fail;

    /* leaves first (their registers are permanent), then the instructions in order, each
     * operand's register freed after its last reader */
    for (int i = 0; i <= e; i++) {
        if (!mark[i] || !is_leaf(pool->nodes[i].op)) continue;
        if ((reg[i] = reg_new(&al, pc_expr_width(pool->nodes[i].dim))) < 0) goto fail;
    }
    for (int i = 0; i <= e; i++) {
        if (!mark[i]) continue;
        const pc_expr_node *nd = &pool->nodes[i];
        if (is_leaf(nd->op)) continue;
        if (partner[i] < 0) {                /* computed with its partner: only free operands */
            if (nd->a >= 0 && !is_leaf(pool->nodes[nd->a].op) && last[nd->a] == i &&
                reg_free(&al, reg[nd->a]) != PC_OK)
                goto fail;
            p->counts[nd->op]++;
            continue;
        }
        int r = reg_new(&al, pc_expr_width(nd->dim));
        if (r < 0) goto fail;
        reg[i] = r;
        if (partner[i] > 0 && (reg[partner[i] - 1] = reg_new(&al, 1)) < 0) goto fail;
        ins_t *in = &p->ins[p->nins++];
        memset(in, 0, sizeof *in);
        in->op = nd->op;
        in->w = (unsigned char)pc_expr_width(nd->dim);
        in->aw = (unsigned char)pc_expr_width(pool->nodes[nd->a].dim);
        in->k = partner[i] > 0 ? 1 : nd->k;
        if (nd->op == PC_EX_POWC) in->c = pool->consts[nd->c];
        if (nd->op == PC_EX_SMOOTH) in->g = pool->gfuns[nd->k];
        p->counts[nd->op]++;
        int ops[2] = {nd->a, nd->b};
        for (int j = 0; j < 2; j++) {
            int x = ops[j];
            if (x < 0 || is_leaf(pool->nodes[x].op) || last[x] != i) continue;
            if (j == 1 && x == nd->a) continue;            /* x op x: free once */
            if (reg_free(&al, reg[x]) != PC_OK) goto fail;
        }
    }
    /* offsets are known now: fill in the instructions' registers */
    {
        int n = 0;
        for (int i = 0; i <= e; i++) {
            if (!mark[i] || is_leaf(pool->nodes[i].op) || partner[i] < 0) continue;
            const pc_expr_node *nd = &pool->nodes[i];
            ins_t *in = &p->ins[n++];
            in->dst = al.regs[reg[i]].off;
            in->a = al.regs[reg[nd->a]].off;
            in->b = nd->b >= 0 ? al.regs[reg[nd->b]].off : 0;
            if (partner[i] > 0) in->b = al.regs[reg[partner[i] - 1]].off;
        }
    }
    p->nregs = al.nregs;
    p->root = al.regs[reg[e]].off;
    p->ws = calloc(al.top ? al.top : 1, sizeof *p->ws);
    if (!p->ws) goto fail;
    /* constants (value row, every lane; the derivative rows stay 0) and the inputs' seeds */
    for (int i = 0; i <= e; i++) {
        if (!mark[i]) continue;
        const pc_expr_node *nd = &pool->nodes[i];
        double *r = p->ws + al.regs[reg[i]].off;
        if (nd->op == PC_EX_CONST || nd->op == PC_EX_VCONST) {
            int w = pc_expr_width(nd->dim);
            for (int c = 0; c < w; c++)
                for (int k = 0; k < BATCH; k++) r[(size_t)c * BATCH + k] = pool->consts[nd->c + c];
        } else if (nd->op == PC_EX_PARAM) {
            int j = 0;
            while (inputs[j] != nd->k) j++;
            p->in_off[j] = al.regs[reg[i]].off;
            p->in_used[j] = 1;
            for (int k = 0; k < BATCH; k++) r[(size_t)(1 + j) * BATCH + k] = 1;   /* d x_j / d x_j */
        }
    }
    st = PC_OK;
fail:
    for (int w = 0; w < PC_MAXDIM + 2; w++) free(al.freel[w]);
    free(al.regs);
    free(mark);
    free(last);
    free(reg);
    free(partner);
    free(sin_of);
    if (st != PC_OK) {
        pc_expr_prog_free(p);
        *status = st;
        return NULL;
    }
    *status = PC_OK;
    return p;
}

/* ---- evaluating ------------------------------------------------------------------------------ */

/* row c, channel i of a register of width w */
#define ROW(base, w, c, i) ((base) + ((size_t)(c) * (w) + (i)) * BATCH)


/* f, f', f'' of a unary operation at the lanes of x (f1, f2 only as order asks) */
static void unary(const ins_t *in, const double *x, int m, int order, double *f0, double *f1,
                  double *f2) {
    int k;
    switch ((pc_expr_op)in->op) {
    case PC_EX_SIN:
        for (k = 0; k < m; k++) f0[k] = sin(x[k]);
        if (order) for (k = 0; k < m; k++) { f1[k] = cos(x[k]); f2[k] = -f0[k]; }
        break;
    case PC_EX_COS:
        for (k = 0; k < m; k++) f0[k] = cos(x[k]);
        if (order) for (k = 0; k < m; k++) { f1[k] = -sin(x[k]); f2[k] = -f0[k]; }
        break;
    case PC_EX_TAN:
        for (k = 0; k < m; k++) f0[k] = tan(x[k]);
        if (order) for (k = 0; k < m; k++) { f1[k] = 1 + f0[k] * f0[k]; f2[k] = 2 * f0[k] * f1[k]; }
        break;
    case PC_EX_EXP:
        for (k = 0; k < m; k++) f0[k] = exp(x[k]);
        if (order) for (k = 0; k < m; k++) f1[k] = f2[k] = f0[k];
        break;
    case PC_EX_LOG:
        for (k = 0; k < m; k++) f0[k] = log(x[k]);
        if (order) for (k = 0; k < m; k++) { f1[k] = 1 / x[k]; f2[k] = -f1[k] * f1[k]; }
        break;
    case PC_EX_SQRT:
        for (k = 0; k < m; k++) f0[k] = sqrt(x[k]);
        if (order) for (k = 0; k < m; k++) { f1[k] = 0.5 / f0[k]; f2[k] = -0.25 / (f0[k] * x[k]); }
        break;
    case PC_EX_ABS:
        for (k = 0; k < m; k++) f0[k] = fabs(x[k]);
        if (order) for (k = 0; k < m; k++) { f1[k] = (x[k] > 0) - (x[k] < 0); f2[k] = 0; }
        break;
    case PC_EX_RECIP:
        for (k = 0; k < m; k++) f0[k] = 1 / x[k];
        if (order) for (k = 0; k < m; k++) { f1[k] = -f0[k] * f0[k]; f2[k] = -2 * f1[k] * f0[k]; }
        break;
    case PC_EX_POWI: {
        int n = in->k;
        /* the value is the same at every order (a curve's point must not depend on how many
         * derivatives were asked for) */
        if (n == 2) {
            for (k = 0; k < m; k++) f0[k] = x[k] * x[k];
            if (order) for (k = 0; k < m; k++) { f1[k] = 2 * x[k]; f2[k] = 2; }
        } else if (n > 2 && n <= 8) {     /* small powers: products over the lanes */
            for (k = 0; k < m; k++) f0[k] = x[k] * x[k];
            for (int j = 2; j < n; j++)
                for (k = 0; k < m; k++) f0[k] *= x[k];
            if (order)
                for (k = 0; k < m; k++) {
                    f1[k] = n * pcx_ipow(x[k], n - 1);
                    f2[k] = (double)n * (n - 1) * pcx_ipow(x[k], n - 2);
                }
        } else {
            for (k = 0; k < m; k++) f0[k] = pcx_ipow(x[k], n);
            if (order)
                for (k = 0; k < m; k++) {
                    f1[k] = n * pcx_ipow(x[k], n - 1);
                    f2[k] = (double)n * (n - 1) * pcx_ipow(x[k], n - 2);
                }
        }
        break;
    }
    case PC_EX_POWC: {
        double c = in->c;
        for (k = 0; k < m; k++) f0[k] = pow(x[k], c);
        if (order)
            for (k = 0; k < m; k++) {
                f1[k] = c * pow(x[k], c - 1);
                f2[k] = c * (c - 1) * pow(x[k], c - 2);
            }
        break;
    }
    case PC_EX_SMOOTH: {
        const pc_gfun *g = &in->g;
        if (g->kind == PC_G_SINE) {        /* (1 - cos(pi t))/2 */
            for (k = 0; k < m; k++) f0[k] = pc_smooth_sine(x[k]);
            if (order)
                for (k = 0; k < m; k++) {
                    f1[k] = PI / 2 * sin(PI * x[k]);
                    f2[k] = PI * PI / 2 * cos(PI * x[k]);
                }
        } else if (g->kind == PC_G_CUBIC) {   /* 3t^2 - 2t^3 */
            for (k = 0; k < m; k++) f0[k] = pc_smooth_cubic(x[k]);
            if (order) for (k = 0; k < m; k++) { f1[k] = 6 * x[k] * (1 - x[k]); f2[k] = 6 - 12 * x[k]; }
        } else {                              /* half-spline: c1 t^n | 1 - c2 (1 - t)^m */
            const pc_hspline *h = &g->h;
            for (k = 0; k < m; k++) {
                double t = x[k];
                if (pc_hspline_check(h, t) != PC_OK) { f0[k] = f1[k] = f2[k] = NAN; continue; }
                f0[k] = pc_hspline_eval(h, t);
                if (!order) continue;
                f1[k] = pc_hspline_deriv(h, t);
                f2[k] = t < h->t0 ? h->n * (h->n - 1) * h->c1 * pow(t, h->n - 2)
                                  : -h->m * (h->m - 1) * h->c2 * pow(1 - t, h->m - 2);
            }
        }
        break;
    }
    default:
        for (k = 0; k < m; k++) f0[k] = NAN;
    }
}

/* z = x * y (elementwise over w channels; y of width 1 is broadcast) with Leibniz's rule */
static void product(double *z, const double *x, const double *y, int w, int yw, int m, int nd,
                    int order) {
    for (int i = 0; i < w; i++) {
        int iy = yw == 1 ? 0 : i;
        const double *x0 = ROW(x, w, 0, i), *y0 = ROW(y, yw, 0, iy);
        double *z0 = ROW(z, w, 0, i);
        for (int k = 0; k < m; k++) z0[k] = x0[k] * y0[k];
        if (order < 1) continue;
        for (int d = 0; d < nd; d++) {
            const double *xd = ROW(x, w, 1 + d, i), *yd = ROW(y, yw, 1 + d, iy);
            double *zd = ROW(z, w, 1 + d, i);
            for (int k = 0; k < m; k++) zd[k] = xd[k] * y0[k] + x0[k] * yd[k];
        }
        if (order < 2) continue;
        for (int d1 = 0; d1 < nd; d1++)
            for (int d2 = d1; d2 < nd; d2++) {
                int s = sidx(nd, d1, d2);
                const double *xa = ROW(x, w, 1 + d1, i), *xb = ROW(x, w, 1 + d2, i);
                const double *ya = ROW(y, yw, 1 + d1, iy), *yb = ROW(y, yw, 1 + d2, iy);
                const double *xs = ROW(x, w, s, i), *ys = ROW(y, yw, s, iy);
                double *zs = ROW(z, w, s, i);
                for (int k = 0; k < m; k++)
                    zs[k] = xs[k] * y0[k] + xa[k] * yb[k] + xb[k] * ya[k] + x0[k] * ys[k];
            }
    }
}

/* z = f(x) by the chain rule from f, f', f'' at the lanes */
static void chain(double *z, const double *x, const double *f0, const double *f1,
                  const double *f2, int m, int nd, int order) {
    int k;
    if (z != f0)
        for (k = 0; k < m; k++) z[k] = f0[k];
    if (order < 1) return;
    for (int d = 0; d < nd; d++)
        for (k = 0; k < m; k++) z[(1 + d) * BATCH + k] = f1[k] * x[(1 + d) * BATCH + k];
    if (order < 2) return;
    for (int d1 = 0; d1 < nd; d1++)
        for (int d2 = d1; d2 < nd; d2++) {
            int s = sidx(nd, d1, d2);
            for (k = 0; k < m; k++)
                z[s * BATCH + k] = f1[k] * x[s * BATCH + k] +
                                   f2[k] * x[(1 + d1) * BATCH + k] * x[(1 + d2) * BATCH + k];
        }
}

/* sin x into zs and cos x into zc, together */
static void sincos_pair(double *zs, double *zc, const double *x, int m, int nd, int order) {
    double s[BATCH], c[BATCH], ms[BATCH], mc[BATCH];
    for (int k = 0; k < m; k++) {
        s[k] = sin(x[k]);
        c[k] = cos(x[k]);
    }
    if (order)
        for (int k = 0; k < m; k++) { ms[k] = -s[k]; mc[k] = -c[k]; }
    chain(zs, x, s, c, ms, m, nd, order);
    chain(zc, x, c, ms, mc, m, nd, order);
}

static void exec(pc_expr_prog *p, const ins_t *in, int m, int order) {
    double *ws = p->ws, *z = ws + in->dst;
    const double *x = ws + in->a, *y = ws + in->b;
    int w = in->w, nd = p->nin, J = pc_expr_jets(nd, order), k;
    switch ((pc_expr_op)in->op) {
    case PC_EX_ADD:
        for (int c = 0; c < J * w; c++)
            for (k = 0; k < m; k++) z[c * BATCH + k] = x[c * BATCH + k] + y[c * BATCH + k];
        return;
    case PC_EX_SUB:
        for (int c = 0; c < J * w; c++)
            for (k = 0; k < m; k++) z[c * BATCH + k] = x[c * BATCH + k] - y[c * BATCH + k];
        return;
    case PC_EX_NEG:
        for (int c = 0; c < J * w; c++)
            for (k = 0; k < m; k++) z[c * BATCH + k] = -x[c * BATCH + k];
        return;
    case PC_EX_COMP:
        for (int c = 0; c < J; c++) {
            const double *xc = ROW(x, in->aw, c, in->k);
            for (k = 0; k < m; k++) z[c * BATCH + k] = xc[k];
        }
        return;
    case PC_EX_MUL: product(z, x, y, 1, 1, m, nd, order); return;
    case PC_EX_SCALE: product(z, x, y, w, 1, m, nd, order); return;
    case PC_EX_DOT: {
        double tmp[6 * BATCH];            /* at most jets(2, 2) = 6 rows */
        for (int c = 0; c < J; c++)
            for (k = 0; k < m; k++) z[c * BATCH + k] = 0;
        int n = in->aw - 1;
        for (int i = 0; i < n; i++) {
            /* the product of channel i of x and of y, as a scalar register */
            double xi[6 * BATCH], yi[6 * BATCH];
            if (J > 6) {
                /* three or more inputs carry first derivatives only: accumulate directly */
                const double *x0 = ROW(x, in->aw, 0, i), *y0 = ROW(y, in->aw, 0, i);
                for (k = 0; k < m; k++) z[k] += x0[k] * y0[k];
                for (int d = 0; d < nd && order; d++) {
                    const double *xd = ROW(x, in->aw, 1 + d, i), *yd = ROW(y, in->aw, 1 + d, i);
                    for (k = 0; k < m; k++) z[(1 + d) * BATCH + k] += xd[k] * y0[k] + x0[k] * yd[k];
                }
                continue;
            }
            for (int c = 0; c < J; c++) {
                memcpy(xi + c * BATCH, ROW(x, in->aw, c, i), sizeof(double) * (size_t)m);
                memcpy(yi + c * BATCH, ROW(y, in->aw, c, i), sizeof(double) * (size_t)m);
            }
            product(tmp, xi, yi, 1, 1, m, nd, order);
            for (int c = 0; c < J; c++)
                for (k = 0; k < m; k++) z[c * BATCH + k] += tmp[c * BATCH + k];
        }
        return;
    }
    default: {                       /* a function of a scalar: the chain rule */
        if ((in->op == PC_EX_SIN || in->op == PC_EX_COS) && in->k) {
            double *other = ws + in->b;
            if (in->op == PC_EX_SIN) sincos_pair(z, other, x, m, nd, order);
            else sincos_pair(other, z, x, m, nd, order);
            return;
        }
        double f1[BATCH], f2[BATCH];
        unary(in, x, m, order, z, f1, f2);        /* f into the value row directly */
        chain(z, x, z, f1, f2, m, nd, order);
    }
    }
}

/* one batch: the inputs' value rows from x (m rows of nin), then every instruction */
static void run_batch(pc_expr_prog *p, const double *x, int m, int order) {
    for (int j = 0; j < p->nin; j++) {
        if (!p->in_used[j]) continue;
        double *r = p->ws + p->in_off[j];
        for (int k = 0; k < m; k++) r[k] = x[(size_t)k * p->nin + j];
    }
    for (int i = 0; i < p->nins; i++) exec(p, &p->ins[i], m, order);
}

int pc_expr_eval(pc_expr_prog *p, int m, const double *x, int order, double *out, int *bad) {
    if (order < 0 || order > p->maxorder) return PC_EDOMAIN;
    int J = pc_expr_jets(p->nin, order), w = p->width;
    for (int k = 0; k < m * p->nin; k++)
        if (!isfinite(x[k])) {
            if (bad) *bad = k / p->nin;
            return PC_ENONFINITE;
        }
    for (int s = 0; s < m; s += BATCH) {
        int mm = m - s < BATCH ? m - s : BATCH;
        run_batch(p, x + (size_t)s * p->nin, mm, order);
        const double *r = p->ws + p->root;
        for (int k = 0; k < mm; k++) {
            double *o = out + (size_t)(s + k) * J * w;
            for (int c = 0; c < J; c++)
                for (int i = 0; i < w; i++) {
                    double v = ROW(r, w, c, i)[k];
                    if (!isfinite(v)) {
                        if (bad) *bad = s + k;
                        return PC_ENONFINITE;
                    }
                    o[c * w + i] = v;
                }
        }
    }
    return PC_OK;
}

int pc_expr_sample(pc_expr_prog *p, double a, double b, long n, double *out, long *bad) {
    if (p->nin != 1 || n < 1) return PC_EDOMAIN;
    if (!isfinite(a) || !isfinite(b)) return PC_ENONFINITE;
    int dim = p->dim, w = p->width;
    double t[BATCH], step = n > 1 ? (b - a) / (double)(n - 1) : 0;
    for (long s = 0; s < n; s += BATCH) {
        int mm = n - s < BATCH ? (int)(n - s) : BATCH;
        for (int k = 0; k < mm; k++) t[k] = s + k == n - 1 && n > 1 ? b : a + step * (double)(s + k);
        run_batch(p, t, mm, 0);
        const double *r = p->ws + p->root;
        if (!dim) {
            for (int k = 0; k < mm; k++) out[s + k] = r[k];
        } else {
            const double *wt = ROW(r, w, 0, dim);
            for (int i = 0; i < dim; i++) {
                const double *ri = ROW(r, w, 0, i);
                for (int k = 0; k < mm; k++)
                    out[(size_t)(s + k) * dim + i] = wt[k] != 0 ? ri[k] / wt[k] : ri[k];
            }
        }
        for (int k = 0; k < mm * (dim ? dim : 1); k++)
            if (!isfinite(out[(size_t)s * (dim ? dim : 1) + k])) {
                if (bad) *bad = s + k / (dim ? dim : 1);
                return PC_ENONFINITE;
            }
    }
    return PC_OK;
}

int pc_expr_prog_weight(pc_expr_prog *p, const double *lo, const double *hi, double *x_bad,
                        double *w_bad) {
    if (!p->dim) return -1;
    enum { NPROBE = 9 };
    static const double frac[NPROBE] = {0.5, 0, 1, 0.137, 0.863, 0.291, 0.709, 0.419, 0.581};
    double x[NPROBE * PC_EXPR_MAXPARAM], out[NPROBE * (PC_MAXDIM + 1)];
    int nin = p->nin, w = p->width, seen = 0, kind = -1;
    for (int i = 0; i < NPROBE; i++)
        for (int j = 0; j < nin; j++)
            x[i * nin + j] = lo[j] + (hi[j] - lo[j]) * frac[(i + 2 * j) % NPROBE];
    int odd = -1;              /* the first probe whose weight is neither 0 nor 1 */
    int other = -1;            /* the first probe of another kind than the first one */
    for (int i = 0; i < NPROBE; i++) {
        /* one probe at a time: a probe outside the equation's domain is skipped */
        if (pc_expr_eval(p, 1, x + i * nin, 0, out + i * w, NULL) != PC_OK) continue;
        int kd = pc_kind_of(out[i * w + p->dim]);
        if (!seen) kind = kd;
        seen = 1;
        if (kd == PC_KIND_WEIGHTED && odd < 0) odd = i;
        if (kd != kind && other < 0) other = i;
    }
    int bad = odd >= 0 ? odd : other;
    if (bad >= 0) {
        if (x_bad) memcpy(x_bad, x + bad * nin, sizeof(double) * (size_t)nin);
        if (w_bad) *w_bad = out[bad * w + p->dim];
        return PC_KIND_WEIGHTED;
    }
    return seen ? kind : -2;
}

/* ---- the one curve and surface types ---------------------------------------------------------- */

static int curve_cb(void *ud, double t, int order, double *out) {
    return pc_expr_eval(ud, 1, &t, order, out, NULL);
}

static int surface_cb(void *ud, double u, double v, int order, double *out) {
    double x[2] = {u, v};
    return pc_expr_eval(ud, 1, x, order, out, NULL);
}

static void prog_free_cb(void *ud) { pc_expr_prog_free(ud); }

pc_curve *pc_expr_curve(pc_expr_prog *p, double t0, double t1, int *status) {
    if (!p->dim || p->nin != 1) {
        pc_expr_prog_free(p);
        *status = PC_EDIM;
        return NULL;
    }
    if (!isfinite(t0) || !isfinite(t1) || !(t0 < t1)) {
        pc_expr_prog_free(p);
        *status = isfinite(t0) && isfinite(t1) ? PC_EDOMAIN : PC_ENONFINITE;
        return NULL;
    }
    /* closed when it ends where it starts (an oval over a whole turn) */
    double a[PC_MAXDIM + 1], b[PC_MAXDIM + 1];
    int closed = 0;
    if (pc_expr_eval(p, 1, &t0, 0, a, NULL) == PC_OK && pc_expr_eval(p, 1, &t1, 0, b, NULL) == PC_OK) {
        double scale = 1, d = 0;
        for (int i = 0; i <= p->dim; i++) {
            scale = fmax(scale, fmax(fabs(a[i]), fabs(b[i])));
            d = fmax(d, fabs(a[i] - b[i]));
        }
        closed = d <= 1e-12 * scale;
    }
    pc_curve *c = pc_curve_func(p->dim, t0, t1, closed, curve_cb, prog_free_cb, p, status);
    if (!c) pc_expr_prog_free(p);
    return c;
}

pc_surface *pc_expr_surface(pc_expr_prog *p, double u0, double u1, double v0, double v1,
                            int *status) {
    if (!p->dim || p->nin != 2) {
        pc_expr_prog_free(p);
        *status = PC_EDIM;
        return NULL;
    }
    pc_surface *s = pc_surface_func(p->dim, u0, u1, v0, v1, surface_cb, prog_free_cb, p, status);
    if (!s) pc_expr_prog_free(p);
    return s;
}
