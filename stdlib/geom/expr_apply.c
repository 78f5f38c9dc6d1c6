/* The operations of point equations with their checks and messages (expr.h, pc_expr_apply). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include "expr.h"

typedef struct {
    pc_expr_pool *p;
    const int *ids;
    char *why;
    size_t size;
} ctx;

static int say(ctx *c, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->why, c->size, fmt, ap);
    va_end(ap);
    return -1;
}

/* the node r, or the failure st of making it (who: the operation a metamethod names) */
static int built(ctx *c, int r, int st, const char *who) {
    if (r >= 0) return r;
    if (st == PC_ENOMEM) return say(c, "%sout of memory (too many equation nodes)", who);
    return say(c, "%s%s", who, pc_strerror(st));
}

static int dim(ctx *c, int id) { return pc_expr_dim(c->p, id); }

/* operand k (1-based) where a number or a scalar equation goes */
static int scalar(ctx *c, int k, const char *what) {
    int id = c->ids[k - 1];
    if (id < 0 || dim(c, id))
        return say(c, "argument #%d (%s) must be a number or a scalar equation, got @%d", k, what, k);
    return id;
}

/* operand k of dot, cross, unit: a vector (weight 0) of dimension d (0: any) */
static int vector(ctx *c, int k, const char *what, int d) {
    int id = c->ids[k - 1], dk = id < 0 ? 0 : dim(c, id);
    if (!dk) return say(c, "argument #%d (%s) must be a vector or a vector equation, got @%d", k, what, k);
    if (d && dk != d)
        return say(c, "argument #%d (%s) is %d-D, but argument #1 (u) is %d-D (mixed dimensions)", k, what, dk, d);
    if (pc_expr_weight_class(c->p, id) != PC_KIND_VECTOR)
        return say(c, "argument #%d (%s) must be a vector (weight 0), got @%d whose weight is not 0; a difference of "
                   "points is a vector, e.g. B - A", k, what, k);
    return id;
}

static const char *const OPNAME[] = {"add", "subtract", "multiply", "divide", "negate"};

static int arith(ctx *c, pc_expr_verb v) {
    int a = c->ids[0], b = v == PC_EQV_NEG ? 0 : c->ids[1], st = PC_OK, r;
    if (a < 0 || b < 0) {
        if (v == PC_EQV_NEG) return say(c, "cannot negate @1");
        return say(c, "cannot %s @1 and @2: equations combine with numbers, points, vectors and equations", OPNAME[v]);
    }
    switch (v) {
    case PC_EQV_ADD: r = pc_expr_add(c->p, a, b, &st); break;
    case PC_EQV_SUB: r = pc_expr_sub(c->p, a, b, &st); break;
    case PC_EQV_MUL: r = pc_expr_mul(c->p, a, b, &st); break;
    case PC_EQV_DIV: r = pc_expr_div(c->p, a, b, &st); break;
    default: r = pc_expr_neg(c->p, a, &st); break;
    }
    if (r >= 0) return r;
    int da = dim(c, a), db = v == PC_EQV_NEG ? 0 : dim(c, b);
    if (st == PC_EDIM) {
        if (da && db && da != db) return say(c, "cannot %s @1 and @2: dimensions cannot be mixed", OPNAME[v]);
        if (v == PC_EQV_MUL)
            return say(c, "cannot multiply @1 by @2: use dot(u, v) or cross(u, v) for products of vectors");
        if (v == PC_EQV_DIV) return say(c, "cannot divide @1 by @2: divide by numbers or scalar equations");
        return say(c, "cannot %s @1 and @2: points and vectors add only to points and vectors; to shift a point "
                   "write A + V(dx, dy)", OPNAME[v]);
    }
    if (st == PC_EDOMAIN && v == PC_EQV_DIV) return say(c, "division of an equation by zero");
    return built(c, -1, st, "equation: ");
}

static int lerp(ctx *c) {
    int t = scalar(c, 3, "t"), a = c->ids[0], b = c->ids[1], st;
    if (t < 0) return -1;
    if (a < 0) return say(c, "argument #1 (A) must be a point, a vector, a number or an equation, got @1");
    if (b < 0) return say(c, "argument #2 (B) must be a point, a vector, a number or an equation, got @2");
    int da = dim(c, a), db = dim(c, b);
    if (da != db && da && db)
        return say(c, "argument #2 (B) is %d-D, but argument #1 (A) is %d-D (mixed dimensions)", db, da);
    if (da != db) return say(c, "A and B must both be points (or vectors) or both numbers, got @1 and @2");
    return built(c, pc_expr_lerp(c->p, a, b, t, &st), st, "");
}

static int products(ctx *c, pc_expr_verb v) {
    int u = vector(c, 1, v == PC_EQV_UNIT ? "v" : "u", 0), w = 0, st = PC_OK, r;
    if (u < 0) return -1;
    if (v == PC_EQV_UNIT) {
        r = pc_expr_unit(c->p, u, &st);
        if (r < 0 && st == PC_EZERO) return say(c, "the zero vector has no direction");
        return built(c, r, st, "");
    }
    if ((w = vector(c, 2, "v", dim(c, u))) < 0) return -1;
    if (v == PC_EQV_CROSS && dim(c, u) != 2 && dim(c, u) != 3)
        return say(c, "vectors must be 2-D or 3-D, got %d-D", dim(c, u));
    r = v == PC_EQV_DOT ? pc_expr_dot(c->p, u, w, &st) : pc_expr_cross(c->p, u, w, &st);
    return built(c, r, st, "");
}

static int pack(ctx *c, int n, double weight) {
    static const char *const xyz[] = {"x", "y", "z"};
    int x[PC_MAXDIM], st;
    if (n < 1 || n > PC_MAXDIM) return say(c, "needs 1 to %d coordinates, got %d", PC_MAXDIM, n);
    for (int i = 0; i < n; i++)
        if ((x[i] = scalar(c, i + 1, i < 3 ? xyz[i] : "coordinate")) < 0) return -1;
    return built(c, pc_expr_pack(c->p, n, x, weight, &st), st, "");
}

/* meet(A1, A2, B1, B2) with equations among the ends: K, lambda, mu */
static int meet(ctx *c, int *res) {
    static const char *const nm[4] = {"A1", "A2", "B1", "B2"};
    int d = 0, st;
    for (int i = 0; i < 4; i++) {
        int id = c->ids[i], di = id < 0 ? 0 : dim(c, id);
        if (!di)
            return say(c, "argument #%d (%s) must be a point or an equation of a point, got @%d", i + 1, nm[i], i + 1);
        if (i == 0) d = di;
        else if (di != d)
            return say(c, "argument #%d (%s) is %d-D, but argument #1 (A1) is %d-D (mixed dimensions)", i + 1, nm[i],
                       di, d);
        if (pc_expr_weight_class(c->p, id) != PC_KIND_POINT)
            return say(c, "argument #%d (%s) must be a point (weight 1), got @%d: the coefficients of a point equation "
                       "sum to 1 (membership condition)", i + 1, nm[i], i + 1);
    }
    if (d < 2) return say(c, "lines meet in 2-D or more, got %d-D points", d);
    res[0] = pc_expr_meet(c->p, c->ids[0], c->ids[1], c->ids[2], c->ids[3], &res[1], &res[2], &st);
    return built(c, res[0], st, "") < 0 ? -1 : 3;
}

static int math(ctx *c, const pc_expr_how *how) {
    int a = scalar(c, 1, "x"), st = PC_OK;
    if (a < 0) return -1;
    int r = pc_expr_fn(c->p, how->fn, a, &st);
    if (r >= 0 && how->fn == PC_EX_LOG && how->base) {   /* log(x, base) */
        int k = pc_expr_const(c->p, 1 / log(how->base), &st);
        r = k < 0 ? -1 : pc_expr_mul(c->p, r, k, &st);
    }
    if (r < 0 && st == PC_EDOMAIN) return say(c, "argument #1 (x) is outside the function's domain");
    return built(c, r, st, "");
}

int pc_expr_apply(pc_expr_pool *pool, pc_expr_verb v, int n, const int *ids, const pc_expr_how *how,
                  int *res, char *why, size_t size) {
    ctx c = {pool, ids, why, size};
    int st, r;
    switch (v) {
    case PC_EQV_ADD: case PC_EQV_SUB: case PC_EQV_MUL: case PC_EQV_DIV: case PC_EQV_NEG:
        r = arith(&c, v);
        break;
    case PC_EQV_POW:
        if (ids[0] < 0 || ids[1] < 0 || dim(&c, ids[0]) || dim(&c, ids[1]))
            return say(&c, "cannot raise @1 to @2: powers are of numbers and scalar equations");
        r = built(&c, pc_expr_pow(pool, ids[0], ids[1], &st), st, "^: ");
        break;
    case PC_EQV_LERP: r = lerp(&c); break;
    case PC_EQV_BAR:
        r = scalar(&c, 1, "t");
        if (r >= 0) r = built(&c, pc_expr_bar(pool, r, &st), st, "");
        break;
    case PC_EQV_DOT: case PC_EQV_CROSS: case PC_EQV_UNIT: r = products(&c, v); break;
    case PC_EQV_P: case PC_EQV_V: r = pack(&c, n, v == PC_EQV_P ? 1.0 : 0.0); break;
    case PC_EQV_MEET: return meet(&c, res);
    case PC_EQV_MATH: r = math(&c, how); break;
    default:
        r = scalar(&c, 1, "t");
        if (r >= 0) r = built(&c, pc_expr_smooth(pool, how->g, r, &st), st, "");
        break;
    }
    if (r < 0) return -1;
    res[0] = r;
    return 1;
}

static const char MEMBERSHIP[] =
    "the coefficients of a point equation must sum to 1 for a point and to 0 for a vector "
    "(the membership condition)";

pc_expr_prog *pc_expr_compile_point(const pc_expr_pool *pool, int e, int nwant, const double *lo,
                                    const double *hi, char *why, size_t size) {
    ctx c = {(pc_expr_pool *)pool, NULL, why, size};
    int in[PC_EXPR_MAXPARAM], n = pc_expr_param_list(pool, e, in), st;
    char names[PC_EXPR_MAXPARAM * (PC_EXPR_MAXNAME + 2)];
    if (!pc_expr_dim(pool, e))
        return say(&c, "argument #1 (equation) must be a point equation, got a scalar equation"), NULL;
    if (n == 0) return say(&c, "argument #1 (equation) has no parameter (it is the constant @1)"), NULL;
    if (n != nwant) {
        pc_expr_param_names(pool, n, in, names, sizeof names);
        return say(&c, "argument #1 (equation) depends on %s, but a %s has %d parameter%s: fix the others with "
                   "M:with{name = value}", names, nwant == 1 ? "curve" : "surface", nwant, nwant == 1 ? "" : "s"), NULL;
    }
    pc_expr_prog *prog = pc_expr_compile(pool, e, n, in, &st);
    if (!prog) return built(&c, -1, st, ""), NULL;
    double xb[PC_EXPR_MAXPARAM], wb;
    int kind = pc_expr_prog_weight(prog, lo, hi, xb, &wb);
    if (kind == PC_KIND_POINT) return prog;
    pc_expr_prog_free(prog);
    if (kind == PC_KIND_VECTOR)
        say(&c, "argument #1 (equation) is a vector equation (weight 0), not a point: %s; to place a vector, add it "
            "to a point, e.g. P(0, 0) + v", MEMBERSHIP);
    else if (kind == -2)
        say(&c, "argument #1 (equation) has no finite value anywhere it was probed in its domain");
    else
        say(&c, "argument #1 (equation) has weight %.14g at %s = %.14g, so it is neither a point (weight 1) nor a "
            "vector (weight 0): %s; write offsets with V(), or divide a rational equation by its total weight",
            wb == 0 ? 0 : wb, pc_expr_param_name(pool, in[0]), xb[0] == 0 ? 0 : xb[0], MEMBERSHIP);
    return NULL;
}
