/* Point equations: the pool of hash-consed nodes and the operations that build them
 * (expr.h).  Compiling and evaluating are in expr_eval.c, the text in expr_print.c. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "expr_impl.h"

#define FAIL(st) do { *status = (st); return -1; } while (0)

pc_expr_pool *pc_expr_pool_new(void) {
    pc_expr_pool *p = calloc(1, sizeof *p);
    if (!p) return NULL;
    p->tcap = 256;
    p->table = calloc((size_t)p->tcap, sizeof *p->table);
    if (!p->table) {
        free(p);
        return NULL;
    }
    return p;
}

void pc_expr_pool_free(pc_expr_pool *p) {
    if (!p) return;
    free(p->nodes);
    free(p->consts);
    free(p->gfuns);
    free(p->table);
    free(p);
}

int pc_expr_pool_size(const pc_expr_pool *p) { return p->n; }
int pc_expr_dim(const pc_expr_pool *p, int e) { return p->nodes[e].dim; }
pc_expr_op pc_expr_opof(const pc_expr_pool *p, int e) { return (pc_expr_op)p->nodes[e].op; }
unsigned pc_expr_params(const pc_expr_pool *p, int e) { return p->nodes[e].pmask; }
int pc_expr_nparams(const pc_expr_pool *p) { return p->nparams; }

const char *pc_expr_param_name(const pc_expr_pool *p, int k) {
    return k >= 0 && k < p->nparams ? p->names[k] : NULL;
}

int pc_expr_param_index(const pc_expr_pool *p, int e) {
    return p->nodes[e].op == PC_EX_PARAM ? p->nodes[e].k : -1;
}

int pc_expr_constant(const pc_expr_pool *p, int e, double *h) {
    const pc_expr_node *nd = &p->nodes[e];
    if (nd->op != PC_EX_CONST && nd->op != PC_EX_VCONST) return PC_EDOMAIN;
    memcpy(h, p->consts + nd->c, sizeof(double) * (size_t)pc_expr_width(nd->dim));
    return PC_OK;
}

/* ---- hash-consing ------------------------------------------------------------------------ */

static uint64_t mix(uint64_t h, uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    return h;
}

static uint64_t dbits(double x) {
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

/* the constants a node carries (n doubles at cs), for hashing and comparing */
static int node_nconst(const pc_expr_node *nd) {
    if (nd->op == PC_EX_CONST || nd->op == PC_EX_POWC) return 1;
    if (nd->op == PC_EX_VCONST) return nd->dim + 1;
    return 0;
}

/* a node's hash: its operation, operands and constants; a smoothstep's by g (its k is only an
 * index into the pool's smoothsteps) */
static uint64_t node_hash(const pc_expr_node *nd, const double *cs, const pc_gfun *g) {
    uint64_t h = mix(nd->op, nd->dim);
    h = mix(h, (uint64_t)(uint32_t)nd->a);
    h = mix(h, (uint64_t)(uint32_t)nd->b);
    if (nd->op == PC_EX_SMOOTH) {
        h = mix(h, (uint64_t)g->kind);
        return mix(mix(mix(h, dbits(g->h.n)), dbits(g->h.m)), dbits(g->h.t0));
    }
    h = mix(h, (uint64_t)(uint32_t)nd->k);
    int nc = node_nconst(nd);
    for (int i = 0; i < nc; i++) h = mix(h, dbits(cs[i]));
    return h;
}

static int gfun_same(const pc_gfun *x, const pc_gfun *y) {
    if (x->kind != y->kind) return 0;
    return x->kind != PC_G_HALF || (x->h.n == y->h.n && x->h.m == y->h.m && x->h.t0 == y->h.t0);
}

static int node_same(const pc_expr_pool *p, const pc_expr_node *x, const double *xc,
                     const pc_gfun *xg, const pc_expr_node *y) {
    if (x->op != y->op || x->dim != y->dim || x->a != y->a || x->b != y->b) return 0;
    if (x->op == PC_EX_SMOOTH) return gfun_same(xg, &p->gfuns[y->k]);
    if (x->k != y->k) return 0;
    int nc = node_nconst(x);
    for (int i = 0; i < nc; i++)
        if (dbits(xc[i]) != dbits(p->consts[y->c + i])) return 0;
    return 1;
}

static int grow_table(pc_expr_pool *p) {
    int cap = p->tcap * 2;
    int *t = calloc((size_t)cap, sizeof *t);
    if (!t) return PC_ENOMEM;
    for (int id = 0; id < p->n; id++) {
        const pc_expr_node *nd = &p->nodes[id];
        uint64_t h = node_hash(nd, nd->c >= 0 ? p->consts + nd->c : NULL,
                               nd->op == PC_EX_SMOOTH ? &p->gfuns[nd->k] : NULL);
        size_t i = (size_t)h & (size_t)(cap - 1);
        while (t[i]) i = (i + 1) & (size_t)(cap - 1);
        t[i] = id + 1;
    }
    free(p->table);
    p->table = t;
    p->tcap = cap;
    return PC_OK;
}

/* The node equal to *nd (its constants cs, its smoothstep g), found or made. */
static int intern(pc_expr_pool *p, pc_expr_node nd, const double *cs, const pc_gfun *g,
                  int *status) {
    uint64_t h = node_hash(&nd, cs, g);
    size_t mask = (size_t)(p->tcap - 1), i = (size_t)h & mask;
    while (p->table[i]) {
        int id = p->table[i] - 1;
        if (node_same(p, &nd, cs, g, &p->nodes[id])) return id;
        i = (i + 1) & mask;
    }
    if (p->n >= PC_EXPR_MAXNODES) FAIL(PC_ENOMEM);
    if (p->n == p->cap) {
        int cap = p->cap ? 2 * p->cap : 64;
        pc_expr_node *nn = realloc(p->nodes, sizeof *nn * (size_t)cap);
        if (!nn) FAIL(PC_ENOMEM);
        p->nodes = nn;
        p->cap = cap;
    }
    int nc = node_nconst(&nd);
    nd.c = -1;
    if (nc) {
        if (p->nconsts + nc > p->cconsts) {
            int cap = p->cconsts ? 2 * p->cconsts : 256;
            while (cap < p->nconsts + nc) cap *= 2;
            double *c = realloc(p->consts, sizeof *c * (size_t)cap);
            if (!c) FAIL(PC_ENOMEM);
            p->consts = c;
            p->cconsts = cap;
        }
        nd.c = p->nconsts;
        memcpy(p->consts + p->nconsts, cs, sizeof(double) * (size_t)nc);
        p->nconsts += nc;
    }
    if (nd.op == PC_EX_SMOOTH) {
        if (p->ngfuns == p->cgfuns) {
            int cap = p->cgfuns ? 2 * p->cgfuns : 8;
            pc_gfun *gg = realloc(p->gfuns, sizeof *gg * (size_t)cap);
            if (!gg) FAIL(PC_ENOMEM);
            p->gfuns = gg;
            p->cgfuns = cap;
        }
        p->gfuns[p->ngfuns] = *g;
        nd.k = p->ngfuns++;
    }
    nd.pmask = (nd.a >= 0 ? p->nodes[nd.a].pmask : 0) | (nd.b >= 0 ? p->nodes[nd.b].pmask : 0) |
               (nd.op == PC_EX_PARAM ? 1u << nd.k : 0);
    int id = p->n++;
    p->nodes[id] = nd;
    p->table[i] = id + 1;
    if (2 * p->n > p->tcap && grow_table(p) != PC_OK) {
        /* the node exists and is found by a linear scan of a full table: keep going */
    }
    return id;
}

static pc_expr_node mk(pc_expr_op op, int dim, int a, int b, int k) {
    pc_expr_node nd = {(unsigned char)op, (unsigned char)dim, a, b, k, -1, 0};
    return nd;
}

/* ---- constants --------------------------------------------------------------------------- */

int pc_expr_const(pc_expr_pool *p, double c, int *status) {
    if (!isfinite(c)) FAIL(PC_ENONFINITE);
    if (c == 0) c = 0;                         /* one zero, not two */
    return intern(p, mk(PC_EX_CONST, 0, -1, -1, 0), &c, NULL, status);
}

int pc_expr_vconst(pc_expr_pool *p, int dim, const double *h, int *status) {
    if (dim < 1 || dim > PC_MAXDIM) FAIL(PC_EDIM);
    double v[PC_MAXDIM + 1];
    for (int i = 0; i <= dim; i++) {
        if (!isfinite(h[i])) FAIL(PC_ENONFINITE);
        v[i] = h[i] == 0 ? 0 : h[i];
    }
    return intern(p, mk(PC_EX_VCONST, dim, -1, -1, 0), v, NULL, status);
}

int pc_expr_param(pc_expr_pool *p, const char *name, int *status) {
    size_t len = strlen(name);
    if (len == 0 || len >= PC_EXPR_MAXNAME) FAIL(PC_EDOMAIN);
    for (int k = 0; k < p->nparams; k++)
        if (!strcmp(p->names[k], name)) return p->param_node[k];
    if (p->nparams == PC_EXPR_MAXPARAM) FAIL(PC_EDOMAIN);
    int k = p->nparams;
    int id = intern(p, mk(PC_EX_PARAM, 0, -1, -1, k), NULL, NULL, status);
    if (id < 0) return -1;
    memcpy(p->names[k], name, len + 1);
    p->param_node[k] = id;
    p->nparams++;
    return id;
}

static int is_const(const pc_expr_pool *p, int e) {
    return p->nodes[e].op == PC_EX_CONST || p->nodes[e].op == PC_EX_VCONST;
}
static double cval(const pc_expr_pool *p, int e) { return p->consts[p->nodes[e].c]; }
static const double *cvec(const pc_expr_pool *p, int e) { return p->consts + p->nodes[e].c; }
static int is_num(const pc_expr_pool *p, int e, double v) {
    return p->nodes[e].op == PC_EX_CONST && cval(p, e) == v;
}
static int is_zero_value(const pc_expr_pool *p, int e) {
    if (p->nodes[e].op != PC_EX_VCONST) return 0;
    for (int i = 0; i <= p->nodes[e].dim; i++)
        if (cvec(p, e)[i] != 0) return 0;
    return 1;
}
static int zero_of(pc_expr_pool *p, int dim, int *status) {
    double z[PC_MAXDIM + 1] = {0};
    return dim ? pc_expr_vconst(p, dim, z, status) : pc_expr_const(p, 0, status);
}
static int const_of(pc_expr_pool *p, int dim, const double *h, int *status) {
    return dim ? pc_expr_vconst(p, dim, h, status) : pc_expr_const(p, h[0], status);
}

/* ---- arithmetic ---------------------------------------------------------------------------- */

int pc_expr_add(pc_expr_pool *p, int a, int b, int *status) {
    int d = p->nodes[a].dim;
    if (p->nodes[b].dim != d) FAIL(PC_EDIM);
    if (is_const(p, a) && is_const(p, b)) {
        double h[PC_MAXDIM + 1];
        for (int i = 0; i < pc_expr_width(d); i++) h[i] = cvec(p, a)[i] + cvec(p, b)[i];
        return const_of(p, d, h, status);
    }
    if (is_num(p, a, 0) || is_zero_value(p, a)) return b;
    if (is_num(p, b, 0) || is_zero_value(p, b)) return a;
    /* a sum keeps its order (it prints as written); products are sorted below */
    return intern(p, mk(PC_EX_ADD, d, a, b, 0), NULL, NULL, status);
}

int pc_expr_neg(pc_expr_pool *p, int a, int *status) {
    int d = p->nodes[a].dim;
    if (is_const(p, a)) {
        double h[PC_MAXDIM + 1];
        for (int i = 0; i < pc_expr_width(d); i++) h[i] = -cvec(p, a)[i];
        return const_of(p, d, h, status);
    }
    if (p->nodes[a].op == PC_EX_NEG) return p->nodes[a].a;
    return intern(p, mk(PC_EX_NEG, d, a, -1, 0), NULL, NULL, status);
}

int pc_expr_sub(pc_expr_pool *p, int a, int b, int *status) {
    int d = p->nodes[a].dim;
    if (p->nodes[b].dim != d) FAIL(PC_EDIM);
    if (a == b) return zero_of(p, d, status);
    if (is_const(p, a) && is_const(p, b)) {
        double h[PC_MAXDIM + 1];
        for (int i = 0; i < pc_expr_width(d); i++) h[i] = cvec(p, a)[i] - cvec(p, b)[i];
        return const_of(p, d, h, status);
    }
    if (is_num(p, b, 0) || is_zero_value(p, b)) return a;
    if (is_num(p, a, 0) || is_zero_value(p, a)) return pc_expr_neg(p, b, status);
    return intern(p, mk(PC_EX_SUB, d, a, b, 0), NULL, NULL, status);
}

int pc_expr_mul(pc_expr_pool *p, int a, int b, int *status) {
    int da = p->nodes[a].dim, db = p->nodes[b].dim;
    if (da && db) FAIL(PC_EDIM);
    if (db) { int t = a; a = b; b = t; da = db; }      /* value first */
    /* now b is a scalar */
    if (is_const(p, a) && is_const(p, b)) {
        double h[PC_MAXDIM + 1], k = cval(p, b);
        for (int i = 0; i < pc_expr_width(da); i++) {
            h[i] = cvec(p, a)[i] * k;
            if (!isfinite(h[i])) FAIL(PC_ENONFINITE);
        }
        return const_of(p, da, h, status);
    }
    if (is_num(p, b, 1)) return a;
    if (!da && is_num(p, a, 1)) return b;
    if (is_num(p, b, 0) || (!da && is_num(p, a, 0)) || is_zero_value(p, a))
        return zero_of(p, da, status);
    if (da) return intern(p, mk(PC_EX_SCALE, da, a, b, 0), NULL, NULL, status);
    if (a > b) { int t = a; a = b; b = t; }    /* a b and b a are one node */
    return intern(p, mk(PC_EX_MUL, 0, a, b, 0), NULL, NULL, status);
}

int pc_expr_div(pc_expr_pool *p, int a, int b, int *status) {
    if (p->nodes[b].dim) FAIL(PC_EDIM);
    if (is_const(p, b)) {
        double k = cval(p, b);
        if (k == 0) FAIL(PC_EDOMAIN);
        if (is_const(p, a)) {
            int d = p->nodes[a].dim;
            double h[PC_MAXDIM + 1];
            for (int i = 0; i < pc_expr_width(d); i++) {
                h[i] = cvec(p, a)[i] / k;              /* as Lua divides */
                if (!isfinite(h[i])) FAIL(PC_ENONFINITE);
            }
            return const_of(p, d, h, status);
        }
        int r = pc_expr_const(p, 1 / k, status);
        if (r < 0) return -1;
        return pc_expr_mul(p, a, r, status);
    }
    int r = pc_expr_fn(p, PC_EX_RECIP, b, status);
    if (r < 0) return -1;
    return pc_expr_mul(p, a, r, status);
}


/* the value of a function at a constant, with its domain */
static int fold_fn(pc_expr_op op, double x, const pc_gfun *g, double c, int k, double *out) {
    double y;
    switch (op) {
    case PC_EX_SIN: y = sin(x); break;
    case PC_EX_COS: y = cos(x); break;
    case PC_EX_TAN: y = tan(x); break;
    case PC_EX_EXP: y = exp(x); break;
    case PC_EX_LOG: if (x <= 0) return PC_EDOMAIN; y = log(x); break;
    case PC_EX_SQRT: if (x < 0) return PC_EDOMAIN; y = sqrt(x); break;
    case PC_EX_ABS: y = fabs(x); break;
    case PC_EX_RECIP: if (x == 0) return PC_EDOMAIN; y = 1 / x; break;
    case PC_EX_POWI: if (x == 0 && k < 0) return PC_EDOMAIN; y = pcx_ipow(x, k); break;
    case PC_EX_POWC: y = pow(x, c); if (isnan(y)) return PC_EDOMAIN; break;
    case PC_EX_SMOOTH:
        if (pc_gfun_check(g, x) != PC_OK) return PC_EDOMAIN;
        y = pc_gfun_eval(g, x);
        break;
    default: return PC_EDOMAIN;
    }
    if (!isfinite(y)) return PC_ENONFINITE;
    *out = y;
    return PC_OK;
}

int pc_expr_fn(pc_expr_pool *p, pc_expr_op op, int a, int *status) {
    if (p->nodes[a].dim) FAIL(PC_EDIM);
    if (!(op >= PC_EX_SIN && op <= PC_EX_ABS) && op != PC_EX_RECIP) FAIL(PC_EDOMAIN);
    if (is_const(p, a)) {
        double y;
        int st = fold_fn(op, cval(p, a), NULL, 0, 0, &y);
        if (st != PC_OK) FAIL(st);
        return pc_expr_const(p, y, status);
    }
    if (op == PC_EX_RECIP && p->nodes[a].op == PC_EX_RECIP) return p->nodes[a].a;
    return intern(p, mk(op, 0, a, -1, 0), NULL, NULL, status);
}

int pc_expr_smooth(pc_expr_pool *p, const pc_gfun *g, int a, int *status) {
    if (p->nodes[a].dim) FAIL(PC_EDIM);
    if (g->kind == PC_G_LINEAR) return a;
    if (is_const(p, a)) {
        double y;
        int st = fold_fn(PC_EX_SMOOTH, cval(p, a), g, 0, 0, &y);
        if (st != PC_OK) FAIL(st);
        return pc_expr_const(p, y, status);
    }
    return intern(p, mk(PC_EX_SMOOTH, 0, a, -1, 0), NULL, g, status);
}

int pc_expr_pow(pc_expr_pool *p, int a, int b, int *status) {
    if (p->nodes[a].dim || p->nodes[b].dim) FAIL(PC_EDIM);
    if (is_const(p, b)) {
        double e = cval(p, b);
        if (e == floor(e) && fabs(e) <= 64) {
            int k = (int)e;
            if (k == 0) return pc_expr_const(p, 1, status);
            if (k == 1) return a;
            if (is_const(p, a)) {
                double y;
                int st = fold_fn(PC_EX_POWI, cval(p, a), NULL, 0, k, &y);
                if (st != PC_OK) FAIL(st);
                return pc_expr_const(p, y, status);
            }
            return intern(p, mk(PC_EX_POWI, 0, a, -1, k), NULL, NULL, status);
        }
        if (is_const(p, a)) {
            double y;
            int st = fold_fn(PC_EX_POWC, cval(p, a), NULL, e, 0, &y);
            if (st != PC_OK) FAIL(st);
            return pc_expr_const(p, y, status);
        }
        if (e == 0.5) return pc_expr_fn(p, PC_EX_SQRT, a, status);
        return intern(p, mk(PC_EX_POWC, 0, a, -1, 0), &e, NULL, status);
    }
    /* a^b = exp(b log a) */
    int l = pc_expr_fn(p, PC_EX_LOG, a, status);
    if (l < 0) return -1;
    int m = pc_expr_mul(p, b, l, status);
    if (m < 0) return -1;
    return pc_expr_fn(p, PC_EX_EXP, m, status);
}

int pc_expr_bar(pc_expr_pool *p, int t, int *status) {
    if (p->nodes[t].dim) FAIL(PC_EDIM);
    int one = pc_expr_const(p, 1, status);
    if (one < 0) return -1;
    return pc_expr_sub(p, one, t, status);
}

/* (B - A) t + A, the segment's equation (Fig. 1.1) */
int pc_expr_lerp(pc_expr_pool *p, int a, int b, int t, int *status) {
    if (p->nodes[t].dim || p->nodes[a].dim != p->nodes[b].dim) FAIL(PC_EDIM);
    int d = pc_expr_sub(p, b, a, status);
    if (d < 0) return -1;
    int m = pc_expr_mul(p, d, t, status);
    if (m < 0) return -1;
    return pc_expr_add(p, m, a, status);
}

int pc_expr_comp(pc_expr_pool *p, int a, int k, int *status) {
    int d = p->nodes[a].dim;
    if (!d || k < 0 || k > d) FAIL(PC_EDIM);
    if (is_const(p, a)) return pc_expr_const(p, cvec(p, a)[k], status);
    return intern(p, mk(PC_EX_COMP, 0, a, -1, k), NULL, NULL, status);
}

int pc_expr_pack(pc_expr_pool *p, int n, const int *x, double weight, int *status) {
    if (n < 1 || n > PC_MAXDIM) FAIL(PC_EDIM);
    double h[PC_MAXDIM + 1] = {0};
    h[n] = weight;
    for (int i = 0; i < n; i++) {
        if (p->nodes[x[i]].dim) FAIL(PC_EDIM);
        if (is_const(p, x[i])) h[i] = cval(p, x[i]);
    }
    int r = pc_expr_vconst(p, n, h, status);
    for (int i = 0; r >= 0 && i < n; i++) {
        if (is_const(p, x[i])) continue;
        double e[PC_MAXDIM + 1] = {0};
        e[i] = 1;
        int ei = pc_expr_vconst(p, n, e, status);
        if (ei < 0) return -1;
        int term = pc_expr_mul(p, ei, x[i], status);
        if (term < 0) return -1;
        r = pc_expr_add(p, r, term, status);
    }
    return r;
}

int pc_expr_dot(pc_expr_pool *p, int a, int b, int *status) {
    int d = p->nodes[a].dim;
    if (!d || p->nodes[b].dim != d) FAIL(PC_EDIM);
    if (is_const(p, a) && is_const(p, b)) return pc_expr_const(p, pc_dot(d, cvec(p, a), cvec(p, b)), status);
    if (a > b) { int t = a; a = b; b = t; }
    return intern(p, mk(PC_EX_DOT, 0, a, b, 0), NULL, NULL, status);
}

/* u.x v.y - u.y v.x of coordinates i, j */
static int cross_part(pc_expr_pool *p, int a, int b, int i, int j, int *status) {
    int ai = pc_expr_comp(p, a, i, status), bj = pc_expr_comp(p, b, j, status);
    if (ai < 0 || bj < 0) return -1;
    int aj = pc_expr_comp(p, a, j, status), bi = pc_expr_comp(p, b, i, status);
    if (aj < 0 || bi < 0) return -1;
    int x = pc_expr_mul(p, ai, bj, status);
    if (x < 0) return -1;
    int y = pc_expr_mul(p, aj, bi, status);
    if (y < 0) return -1;
    return pc_expr_sub(p, x, y, status);
}

int pc_expr_cross(pc_expr_pool *p, int a, int b, int *status) {
    int d = p->nodes[a].dim;
    if (p->nodes[b].dim != d || (d != 2 && d != 3)) FAIL(PC_EDIM);
    if (d == 2) return cross_part(p, a, b, 0, 1, status);
    int c[3];
    c[0] = cross_part(p, a, b, 1, 2, status);
    if (c[0] < 0) return -1;
    c[1] = cross_part(p, a, b, 2, 0, status);
    if (c[1] < 0) return -1;
    c[2] = cross_part(p, a, b, 0, 1, status);
    if (c[2] < 0) return -1;
    return pc_expr_pack(p, 3, c, 0, status);
}

int pc_expr_unit(pc_expr_pool *p, int a, int *status) {
    if (!p->nodes[a].dim) FAIL(PC_EDIM);
    int dd = pc_expr_dot(p, a, a, status);
    if (dd < 0) return -1;
    if (is_const(p, dd) && cval(p, dd) == 0) FAIL(PC_EZERO);
    int len = pc_expr_fn(p, PC_EX_SQRT, dd, status);
    if (len < 0) return -1;
    return pc_expr_div(p, a, len, status);
}

/* ---- substitution -------------------------------------------------------------------------- */

/* Rebuild node nd of the old graph with operands a, b of the new one (folding again). */
static int rebuild(pc_expr_pool *p, const pc_expr_node *nd, int a, int b, int *status) {
    switch ((pc_expr_op)nd->op) {
    case PC_EX_ADD: return pc_expr_add(p, a, b, status);
    case PC_EX_SUB: return pc_expr_sub(p, a, b, status);
    case PC_EX_NEG: return pc_expr_neg(p, a, status);
    case PC_EX_MUL: case PC_EX_SCALE: return pc_expr_mul(p, a, b, status);
    case PC_EX_DOT: return pc_expr_dot(p, a, b, status);
    case PC_EX_COMP: return pc_expr_comp(p, a, nd->k, status);
    case PC_EX_POWI: {
        int k = pc_expr_const(p, nd->k, status);
        return k < 0 ? -1 : pc_expr_pow(p, a, k, status);
    }
    case PC_EX_POWC: {
        int k = pc_expr_const(p, p->consts[nd->c], status);
        return k < 0 ? -1 : pc_expr_pow(p, a, k, status);
    }
    case PC_EX_SMOOTH: {
        pc_gfun g = p->gfuns[nd->k];     /* copied: the array may move */
        return pc_expr_smooth(p, &g, a, status);
    }
    default: return pc_expr_fn(p, (pc_expr_op)nd->op, a, status);
    }
}

int pc_expr_reach(const pc_expr_pool *p, int e, unsigned char *mark) {
    int *stack = malloc(sizeof *stack * (size_t)(e + 1));
    if (!stack) return PC_ENOMEM;
    memset(mark, 0, (size_t)(e + 1));
    int sp = 0;
    stack[sp++] = e;
    mark[e] = 1;
    while (sp) {
        const pc_expr_node *nd = &p->nodes[stack[--sp]];
        if (nd->a >= 0 && !mark[nd->a]) { mark[nd->a] = 1; stack[sp++] = nd->a; }
        if (nd->b >= 0 && !mark[nd->b]) { mark[nd->b] = 1; stack[sp++] = nd->b; }
    }
    free(stack);
    return PC_OK;
}

int pc_expr_subst(pc_expr_pool *p, int e, int k, int r, int *status) {
    if (p->nodes[r].dim) FAIL(PC_EDIM);
    if (k < 0 || k >= p->nparams) FAIL(PC_EDOMAIN);
    unsigned bit = 1u << k;
    if (!(p->nodes[e].pmask & bit)) return e;
    int *map = malloc(sizeof *map * (size_t)(e + 1));
    unsigned char *mark = malloc((size_t)(e + 1));
    if (!map || !mark || pc_expr_reach(p, e, mark) != PC_OK) {
        free(map);
        free(mark);
        FAIL(PC_ENOMEM);
    }
    /* nodes are made after their operands, so ascending ids are a topological order; only the
     * nodes that e needs and that depend on parameter k change */
    int st = PC_OK;
    for (int i = 0; i <= e && st == PC_OK; i++) {
        if (!mark[i]) continue;
        pc_expr_node nd = p->nodes[i];        /* a copy: building may move the array */
        if (!(nd.pmask & bit)) { map[i] = i; continue; }
        if (nd.op == PC_EX_PARAM) { map[i] = r; continue; }
        int a = nd.a >= 0 ? map[nd.a] : -1, b = nd.b >= 0 ? map[nd.b] : -1;
        map[i] = rebuild(p, &nd, a, b, &st);
    }
    int res = st == PC_OK ? map[e] : -1;
    free(map);
    free(mark);
    if (res < 0) FAIL(st);
    return res;
}
