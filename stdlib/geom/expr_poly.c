/* An equation in powers of its parameter (expr.h: pc_expr_power_basis): the book prints a
 * point equation's coordinates expanded, x = 4t(9t + 0,8)/(70t^2 - 75t + 44,2) (Fig. 2.17),
 * ch. 4-5's interpolants as polynomials.  Each node of the DAG becomes a rational function of
 * the parameter: numerator polynomials, one per channel (a value's homogeneous coordinates
 * and weight, or a scalar), over one scalar denominator polynomial.  A value's cartesian
 * coordinate is channel i over the weight channel, where that denominator cancels. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "expr_impl.h"

typedef struct {
    int w, dn, dd;     /* channels; degrees of the numerators and of the denominator */
    double *n, *d;     /* n: w rows of dn + 1 coefficients (low power first); d: dd + 1 */
} rat;

static int alloc(rat *r, int w, int dn, int dd) {
    r->w = w, r->dn = dn, r->dd = dd;
    r->n = calloc((size_t)w * (size_t)(dn + 1), sizeof(double));
    r->d = calloc((size_t)(dd + 1), sizeof(double));
    return r->n && r->d ? PC_OK : PC_ENOMEM;
}

/* c = a * b of polynomials of degrees da, db (c has da + db + 1 slots, zeroed) */
static void pmul(const double *a, int da, const double *b, int db, double *c) {
    for (int i = 0; i <= da; i++)
        for (int j = 0; j <= db; j++) c[i + j] += a[i] * b[j];
}

/* drop exactly-zero top coefficients; a constant denominator is divided into the numerators
 * so that polynomial equations stay polynomials of their own degree */
static void tidy(rat *r) {
    while (r->dd > 0 && r->d[r->dd] == 0) r->dd--;
    for (;;) {
        int top = 0;
        for (int c = 0; c < r->w; c++)
            if (r->n[c * (r->dn + 1) + r->dn] != 0) top = 1;
        if (top || r->dn == 0) break;
        for (int c = 1; c < r->w; c++)   /* rows shrink by one: pack them */
            memmove(r->n + c * r->dn, r->n + c * (r->dn + 1), sizeof(double) * (size_t)r->dn);
        r->dn--;
    }
    if (r->dd == 0 && r->d[0] != 1) {
        for (int i = 0; i < r->w * (r->dn + 1); i++) r->n[i] /= r->d[0];
        r->d[0] = 1;
    }
}

/* a +- b (sign = 1 or -1), channel by channel, over the product of the denominators (or the
 * common one when they are equal constants 1) */
/* c when b's denominator is c times a's (to 1e-12 of its largest coefficient), else 0: the
 * book's coordinates share a denominator up to a factor (Fig. 2.17: 14t^2 - 15t + 8,84 is a
 * fifth of 70t^2 - 75t + 44,2), which then stays of its own degree instead of squaring */
static double proportional(const rat *a, const rat *b) {
    if (a->dd != b->dd || a->dd == 0) return 0;
    double c = b->d[a->dd] / a->d[a->dd], big = 0;
    for (int i = 0; i <= a->dd; i++) big = fmax(big, fabs(b->d[i]));
    for (int i = 0; i <= a->dd; i++)
        if (fabs(b->d[i] - c * a->d[i]) > 1e-12 * big) return 0;
    return c;
}

static int add(const rat *a, const rat *b, double sign, int maxdeg, rat *z) {
    double c = proportional(a, b);
    if (c != 0) {   /* a/Da + b/(c Da) = (c a + b)/Db */
        int dn = a->dn > b->dn ? a->dn : b->dn, st = alloc(z, a->w, dn, b->dd);
        if (st != PC_OK) return st;
        for (int ch = 0; ch < a->w; ch++) {
            double *zc = z->n + ch * (dn + 1);
            for (int i = 0; i <= a->dn; i++) zc[i] += c * a->n[ch * (a->dn + 1) + i];
            for (int i = 0; i <= b->dn; i++) zc[i] += sign * b->n[ch * (b->dn + 1) + i];
        }
        memcpy(z->d, b->d, sizeof(double) * (size_t)(b->dd + 1));
        return PC_OK;
    }
    int one = a->dd == 0 && b->dd == 0;   /* tidy made both 1 */
    int dn = one ? (a->dn > b->dn ? a->dn : b->dn)
                 : (a->dn + b->dd > b->dn + a->dd ? a->dn + b->dd : b->dn + a->dd);
    int dd = one ? 0 : a->dd + b->dd;
    if (dn > maxdeg || dd > maxdeg) return PC_EDOMAIN;
    int st = alloc(z, a->w, dn, dd);
    if (st != PC_OK) return st;
    double *tmp = calloc((size_t)dn + 1, sizeof(double));
    if (!tmp) return PC_ENOMEM;
    for (int c = 0; c < a->w; c++) {
        double *zc = z->n + c * (dn + 1);
        const double *ac = a->n + c * (a->dn + 1), *bc = b->n + c * (b->dn + 1);
        if (one) {
            for (int i = 0; i <= a->dn; i++) zc[i] += ac[i];
            for (int i = 0; i <= b->dn; i++) zc[i] += sign * bc[i];
            continue;
        }
        pmul(ac, a->dn, b->d, b->dd, zc);
        memset(tmp, 0, sizeof(double) * ((size_t)dn + 1));
        pmul(bc, b->dn, a->d, a->dd, tmp);
        for (int i = 0; i <= dn; i++) zc[i] += sign * tmp[i];
    }
    free(tmp);
    if (one) z->d[0] = 1;
    else pmul(a->d, a->dd, b->d, b->dd, z->d);
    return PC_OK;
}

/* every channel of a times the scalar s (s->w == 1) */
static int scale(const rat *a, const rat *s, int maxdeg, rat *z) {
    if (a->dn + s->dn > maxdeg || a->dd + s->dd > maxdeg) return PC_EDOMAIN;
    int st = alloc(z, a->w, a->dn + s->dn, a->dd + s->dd);
    if (st != PC_OK) return st;
    for (int c = 0; c < a->w; c++) pmul(a->n + c * (a->dn + 1), a->dn, s->n, s->dn, z->n + c * (z->dn + 1));
    pmul(a->d, a->dd, s->d, s->dd, z->d);
    return PC_OK;
}

static int copy(const rat *a, rat *z) {
    int st = alloc(z, a->w, a->dn, a->dd);
    if (st != PC_OK) return st;
    memcpy(z->n, a->n, sizeof(double) * (size_t)(a->w * (a->dn + 1)));
    memcpy(z->d, a->d, sizeof(double) * (size_t)(a->dd + 1));
    return PC_OK;
}

static void release(rat *r) { free(r->n), free(r->d), r->n = r->d = NULL; }

static int node(const pc_expr_pool *p, int id, int k, int maxdeg, rat *R) {
    const pc_expr_node *nd = &p->nodes[id];
    const rat *a = nd->a >= 0 ? &R[nd->a] : NULL, *b = nd->b >= 0 ? &R[nd->b] : NULL;
    rat *z = &R[id];
    int st = PC_OK, w = pc_expr_width(nd->dim);
    switch ((pc_expr_op)nd->op) {
    case PC_EX_CONST: case PC_EX_VCONST:
        if ((st = alloc(z, w, 0, 0)) != PC_OK) return st;
        memcpy(z->n, p->consts + nd->c, sizeof(double) * (size_t)w);
        z->d[0] = 1;
        return PC_OK;
    case PC_EX_PARAM:
        if (nd->k != k) return PC_EDIM;   /* another parameter: not in powers of this one */
        if ((st = alloc(z, 1, 1, 0)) != PC_OK) return st;
        z->n[1] = 1, z->d[0] = 1;
        return PC_OK;
    case PC_EX_ADD: return add(a, b, 1, maxdeg, z);
    case PC_EX_SUB: return add(a, b, -1, maxdeg, z);
    case PC_EX_NEG:
        if ((st = copy(a, z)) != PC_OK) return st;
        for (int i = 0; i < z->w * (z->dn + 1); i++) z->n[i] = -z->n[i];
        return PC_OK;
    case PC_EX_MUL: return scale(a, b, maxdeg, z);
    case PC_EX_SCALE: return b->w == 1 ? scale(a, b, maxdeg, z) : scale(b, a, maxdeg, z);
    case PC_EX_COMP:
        if ((st = alloc(z, 1, a->dn, a->dd)) != PC_OK) return st;
        memcpy(z->n, a->n + nd->k * (a->dn + 1), sizeof(double) * (size_t)(a->dn + 1));
        memcpy(z->d, a->d, sizeof(double) * (size_t)(a->dd + 1));
        return PC_OK;
    case PC_EX_DOT: {   /* sum over the coordinates, not the weights, as expr_eval.c */
        if (a->dn + b->dn > maxdeg || a->dd + b->dd > maxdeg) return PC_EDOMAIN;
        if ((st = alloc(z, 1, a->dn + b->dn, a->dd + b->dd)) != PC_OK) return st;
        for (int c = 0; c < a->w - 1; c++) pmul(a->n + c * (a->dn + 1), a->dn, b->n + c * (b->dn + 1), b->dn, z->n);
        pmul(a->d, a->dd, b->d, b->dd, z->d);
        return PC_OK;
    }
    case PC_EX_RECIP:   /* the denominator and the numerator swap */
        if ((st = alloc(z, 1, a->dd, a->dn)) != PC_OK) return st;
        memcpy(z->n, a->d, sizeof(double) * (size_t)(a->dd + 1));
        memcpy(z->d, a->n, sizeof(double) * (size_t)(a->dn + 1));
        return PC_OK;
    case PC_EX_POWI: {
        int e = abs(nd->k);
        rat acc = {0};
        if ((st = alloc(&acc, 1, 0, 0)) != PC_OK) { release(&acc); return st; }
        acc.n[0] = acc.d[0] = 1;
        for (int i = 0; i < e; i++) {
            rat t = {0};
            st = scale(&acc, a, maxdeg, &t);
            release(&acc);
            acc = t;
            if (st != PC_OK) { release(&acc); return st; }
            tidy(&acc);
        }
        if (nd->k < 0) {   /* 1 / a^e */
            double *n = acc.n; int dn = acc.dn;
            acc.n = acc.d, acc.dn = acc.dd, acc.d = n, acc.dd = dn;
        }
        *z = acc;
        return PC_OK;
    }
    default: return PC_EDOMAIN;   /* sin, exp, sqrt, a smoothstep, x^real: not rational in t */
    }
}

int pc_expr_power_basis(const pc_expr_pool *p, int e, int k, int maxdeg, double *coef, int *deg) {
    if (!p || e < 0 || e >= p->n || k < 0 || k >= p->nparams || maxdeg < 0) return PC_EDIM;
    if (p->nodes[e].pmask & ~(1u << k)) return PC_EDIM;
    unsigned char *mark = calloc((size_t)e + 1, 1);
    rat *R = calloc((size_t)e + 1, sizeof *R);
    int st = mark && R ? pc_expr_reach(p, e, mark) : PC_ENOMEM;
    for (int i = 0; i <= e && st == PC_OK; i++) {
        if (!mark[i]) continue;
        st = node(p, i, k, maxdeg, R);
        if (st == PC_OK) tidy(&R[i]);
    }
    if (st == PC_OK) {
        const rat *r = &R[e];
        int rows = p->nodes[e].dim ? r->w : 2;
        /* a value: its channels (the denominator cancels in every coordinate); a scalar:
         * numerator and denominator, as a 1-D point's coordinate and weight */
        int top = p->nodes[e].dim ? r->dn : (r->dn > r->dd ? r->dn : r->dd);
        if (top > maxdeg) st = PC_EDOMAIN;
        else {
            memset(coef, 0, sizeof(double) * (size_t)((top + 1) * rows));
            for (int j = 0; j <= top; j++) {
                if (p->nodes[e].dim)
                    for (int c = 0; c < r->w; c++) coef[j * rows + c] = r->n[c * (r->dn + 1) + j];
                else {
                    coef[j * 2] = j <= r->dn ? r->n[j] : 0;
                    coef[j * 2 + 1] = j <= r->dd ? r->d[j] : 0;
                }
            }
            for (int j = 0; j < (top + 1) * rows; j++)
                if (!isfinite(coef[j])) st = PC_ENONFINITE;
            *deg = top;
        }
    }
    if (R)
        for (int i = 0; i <= e; i++) release(&R[i]);
    free(R), free(mark);
    return st;
}
