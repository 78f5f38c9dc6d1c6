/* Point equations as text, in the book's notation (expr.h): A*bar(t)^2 + 2*B*t*bar(t) + C*t^2,
 * (A - C)*cos(f) + (B - C)*sin(f) + C.  Points print as P(x, y) unless the caller names them;
 * 1 - t prints as bar(t) (the book's t with a bar); parentheses only where Lua's precedence
 * needs them. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "expr_impl.h"

enum { L_SUM = 1, L_PROD, L_UNARY, L_POW, L_ATOM };
#define MAXDEPTH 200

typedef struct {
    const pc_expr_pool *p;
    pc_expr_namer namer;
    void *ud;
    char *buf;
    size_t len, pos;
} out_t;

static void put(out_t *o, const char *s) {
    size_t n = strlen(s);
    for (size_t i = 0; i < n; i++, o->pos++)
        if (o->pos + 1 < o->len) o->buf[o->pos] = s[i];
    if (o->len) o->buf[o->pos + 1 < o->len ? o->pos : o->len - 1] = 0;
}

static void putnum(out_t *o, double x) {
    char s[40];
    if (x == 0) x = 0;
    snprintf(s, sizeof s, "%.14g", x);
    put(o, s);
}

static const pc_expr_node *N(const out_t *o, int e) { return &o->p->nodes[e]; }
static const double *C(const out_t *o, int e) { return o->p->consts + N(o, e)->c; }

/* 1 - t of a parameter: the book's t̄, printed bar(t) */
static int is_bar(const out_t *o, int e) {
    const pc_expr_node *nd = N(o, e);
    return nd->op == PC_EX_SUB && N(o, nd->a)->op == PC_EX_CONST && C(o, nd->a)[0] == 1 &&
           N(o, nd->b)->op == PC_EX_PARAM;
}

static const char *name_of(out_t *o, int dim, const double *h) {
    return o->namer ? o->namer(o->ud, dim, h) : NULL;
}

/* P(x, y) / V(x, y) with coordinates h[0..dim-1] */
static void put_coords(out_t *o, const char *f, int dim, const double *h, double div) {
    put(o, f);
    put(o, "(");
    for (int i = 0; i < dim; i++) {
        if (i) put(o, ", ");
        putnum(o, h[i] / div);
    }
    put(o, ")");
}

static int level(const out_t *o, int e) {
    const pc_expr_node *nd = N(o, e);
    switch ((pc_expr_op)nd->op) {
    case PC_EX_CONST: return C(o, e)[0] < 0 ? L_UNARY : L_ATOM;
    case PC_EX_VCONST: {
        double w = C(o, e)[nd->dim];
        if (name_of((out_t *)o, nd->dim, C(o, e))) return L_ATOM;
        return pc_kind_of(w) == PC_KIND_WEIGHTED ? L_PROD : L_ATOM;
    }
    case PC_EX_ADD: return L_SUM;
    case PC_EX_SUB: return is_bar(o, e) ? L_ATOM : L_SUM;
    case PC_EX_NEG: return L_SUM;
    case PC_EX_MUL: case PC_EX_SCALE: case PC_EX_RECIP: return L_PROD;
    case PC_EX_POWI: case PC_EX_POWC: return L_POW;
    default: return L_ATOM;
    }
}

static void expr(out_t *o, int e, int need, int depth);

static void vconst(out_t *o, int e) {
    const pc_expr_node *nd = N(o, e);
    const double *h = C(o, e);
    int dim = nd->dim;
    const char *nm = name_of(o, dim, h);
    if (nm) { put(o, nm); return; }
    double w = h[dim];
    switch (pc_kind_of(w)) {
    case PC_KIND_POINT: put_coords(o, "P", dim, h, w); return;
    case PC_KIND_VECTOR: put_coords(o, "V", dim, h, 1); return;
    default: {
        double q[PC_MAXDIM + 1];
        for (int i = 0; i <= dim; i++) q[i] = h[i] / w;
        putnum(o, w);
        put(o, "*");
        nm = name_of(o, dim, q);
        if (nm) put(o, nm);
        else put_coords(o, "P", dim, h, w);
    }
    }
}

static const char *fname(pc_expr_op op) {
    switch (op) {
    case PC_EX_SIN: return "sin";
    case PC_EX_COS: return "cos";
    case PC_EX_TAN: return "tan";
    case PC_EX_EXP: return "exp";
    case PC_EX_LOG: return "log";
    case PC_EX_SQRT: return "sqrt";
    case PC_EX_ABS: return "abs";
    default: return "?";
    }
}

/* a*b, a/b for MUL and SCALE: the scalar constant first, a reciprocal as a division */
static void product(out_t *o, int a, int b, int depth) {
    if (N(o, a)->dim == 0 && N(o, b)->op == PC_EX_CONST) { int t = a; a = b; b = t; }
    if (N(o, b)->op == PC_EX_RECIP) {
        expr(o, a, L_PROD, depth);
        put(o, "/");
        expr(o, N(o, b)->a, L_POW, depth);
        return;
    }
    expr(o, a, L_PROD, depth);
    put(o, "*");
    expr(o, b, L_UNARY + (N(o, b)->op == PC_EX_CONST && C(o, b)[0] < 0), depth);
}

static void body(out_t *o, int e, int depth) {
    const pc_expr_node *nd = N(o, e);
    switch ((pc_expr_op)nd->op) {
    case PC_EX_CONST: putnum(o, C(o, e)[0]); return;
    case PC_EX_VCONST: vconst(o, e); return;
    case PC_EX_PARAM: put(o, pc_expr_param_name(o->p, nd->k)); return;
    case PC_EX_ADD: {
        int b = nd->b;
        expr(o, nd->a, L_SUM, depth);
        if (N(o, b)->op == PC_EX_NEG) {
            put(o, " - ");
            expr(o, N(o, b)->a, L_PROD, depth);
        } else if (N(o, b)->op == PC_EX_CONST && C(o, b)[0] < 0) {
            put(o, " - ");
            putnum(o, -C(o, b)[0]);
        } else {
            put(o, " + ");
            expr(o, b, L_SUM, depth);
        }
        return;
    }
    case PC_EX_SUB:
        if (is_bar(o, e)) {
            put(o, "bar(");
            put(o, pc_expr_param_name(o->p, N(o, nd->b)->k));
            put(o, ")");
            return;
        }
        expr(o, nd->a, L_SUM, depth);
        put(o, " - ");
        expr(o, nd->b, L_PROD, depth);
        return;
    case PC_EX_NEG: put(o, "-"); expr(o, nd->a, L_PROD, depth); return;
    case PC_EX_MUL: case PC_EX_SCALE: product(o, nd->a, nd->b, depth); return;
    case PC_EX_RECIP: put(o, "1/"); expr(o, nd->a, L_POW, depth); return;
    case PC_EX_POWI: {
        char s[16];
        expr(o, nd->a, L_ATOM, depth);
        snprintf(s, sizeof s, nd->k < 0 ? "^(%d)" : "^%d", nd->k);
        put(o, s);
        return;
    }
    case PC_EX_POWC: {
        double c = o->p->consts[nd->c];
        expr(o, nd->a, L_ATOM, depth);
        put(o, c < 0 ? "^(" : "^");
        putnum(o, c);
        if (c < 0) put(o, ")");
        return;
    }
    case PC_EX_DOT:
        put(o, "dot(");
        expr(o, nd->a, L_SUM, depth);
        put(o, ", ");
        expr(o, nd->b, L_SUM, depth);
        put(o, ")");
        return;
    case PC_EX_COMP: {
        static const char *xyz[] = {".x", ".y", ".z"};
        if (nd->k == N(o, nd->a)->dim) {
            put(o, "weight(");
            expr(o, nd->a, L_SUM, depth);
            put(o, ")");
            return;
        }
        expr(o, nd->a, L_ATOM, depth);
        if (nd->k < 3) put(o, xyz[nd->k]);
        else {
            char s[16];
            snprintf(s, sizeof s, "[%d]", nd->k + 1);
            put(o, s);
        }
        return;
    }
    case PC_EX_SMOOTH: {
        const pc_gfun *g = &o->p->gfuns[nd->k];
        if (g->kind == PC_G_SINE) put(o, "smooth.sine(");
        else if (g->kind == PC_G_CUBIC) put(o, "smooth.cubic(");
        else {
            put(o, "smooth.half(");
            putnum(o, g->h.n);
            put(o, ", ");
            putnum(o, g->h.m);
            put(o, ", ");
            putnum(o, g->h.t0);
            put(o, ", ");
        }
        expr(o, nd->a, L_SUM, depth);
        put(o, ")");
        return;
    }
    default:
        put(o, fname((pc_expr_op)nd->op));
        put(o, "(");
        expr(o, nd->a, L_SUM, depth);
        put(o, ")");
        return;
    }
}

static void expr(out_t *o, int e, int need, int depth) {
    if (depth > MAXDEPTH) { put(o, "..."); return; }
    int paren = level(o, e) < need;
    if (paren) put(o, "(");
    body(o, e, depth + 1);
    if (paren) put(o, ")");
}

int pc_expr_print(const pc_expr_pool *p, int e, pc_expr_namer namer, void *ud, char *buf,
                  size_t len) {
    out_t o = {p, namer, ud, buf, len, 0};
    if (len) buf[0] = 0;
    expr(&o, e, 0, 0);
    return (int)o.pos;
}
