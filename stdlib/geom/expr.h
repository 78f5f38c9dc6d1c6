/* Point equations as compiled objects (Konopatsky's point equations, e.g. (2.24)
 * M = (A - C) cos f + (B - C) sin f + C, or the Bezier form A t̄² + 2B t t̄ + C t²).
 *
 * An equation is a node of a DAG kept in a pool.  A node is a scalar (dim 0) or a homogeneous
 * value of dimension n (n+1 doubles, weight last, as in point.h), built from constants,
 * symbolic parameters and a small set of operations.  The pool hash-conses its nodes: building
 * the same operation on the same operands twice gives the same node, so a common
 * subexpression (t̄², a cosine, the difference A - C) exists once and is computed once.
 * Constant operands are folded when a node is made.
 *
 * Compiling a node gives a program: the nodes it needs in order, each with a register, the
 * registers reused once their node is dead.  The program runs over a batch of parameter
 * values at a time, and carries forward-mode derivatives through every operation: with
 * order 1 the partials in each input parameter, with order 2 also the second partials.  So a
 * curve's tangent and curvature, and a surface's normal, are exact, never differenced.
 *
 * Weights follow the point calculus: a constant point has weight 1, a vector 0, k*A weight k,
 * and sums add weights, so an equation whose coefficients sum to 1 (the membership condition)
 * evaluates to weight 1 everywhere; pc_expr_prog_weight checks that numerically.
 *
 * Pools and programs are not thread-safe (a program keeps its workspace).  No function here
 * returns NaN silently: evaluation reports PC_ENONFINITE with the offending sample. */
#ifndef PC_EXPR_H
#define PC_EXPR_H

#include <stddef.h>
#include "point.h"
#include "smooth.h"
#include "curve.h"
#include "surface.h"

#define PC_EXPR_MAXPARAM 8      /* parameters per pool (t, s, u, v, ...) */
#define PC_EXPR_MAXNAME 32      /* a parameter's name, with its terminating 0 */
#define PC_EXPR_MAXNODES (1 << 24)

typedef enum {
    PC_EX_CONST,    /* scalar constant */
    PC_EX_VCONST,   /* constant value (point, vector, weighted point) */
    PC_EX_PARAM,    /* a parameter (scalar) */
    PC_EX_ADD, PC_EX_SUB, PC_EX_NEG,        /* scalars or values of one dimension */
    PC_EX_MUL,      /* scalar * scalar */
    PC_EX_SCALE,    /* value * scalar (weights scale too) */
    PC_EX_DOT,      /* sum of a_i b_i over the coordinates of two values (not the weights) */
    PC_EX_COMP,     /* coordinate k of a value (k = dim: its weight) */
    PC_EX_POWI,     /* scalar ^ integer constant */
    PC_EX_POWC,     /* scalar ^ real constant */
    PC_EX_RECIP,    /* 1 / scalar */
    PC_EX_SIN, PC_EX_COS, PC_EX_TAN, PC_EX_EXP, PC_EX_LOG, PC_EX_SQRT, PC_EX_ABS,
    PC_EX_SMOOTH,   /* a smoothstep (smooth.h: sine, cubic, half-spline) of a scalar */
    PC_EX_NOPS
} pc_expr_op;

typedef struct pc_expr_pool pc_expr_pool;
typedef struct pc_expr_prog pc_expr_prog;

/* --- the pool ----------------------------------------------------------------------------- */
pc_expr_pool *pc_expr_pool_new(void);
void pc_expr_pool_free(pc_expr_pool *pool);         /* programs made from it stay valid */
int pc_expr_pool_size(const pc_expr_pool *pool);    /* nodes made so far */

/* What a node is: its dimension (0 for a scalar), its operation, and the set of parameters it
 * depends on (bit k for parameter k). */
int pc_expr_dim(const pc_expr_pool *pool, int e);
pc_expr_op pc_expr_opof(const pc_expr_pool *pool, int e);
unsigned pc_expr_params(const pc_expr_pool *pool, int e);
/* The constant of a CONST node (h[0]) or VCONST node (dim+1 doubles); PC_EDOMAIN otherwise. */
int pc_expr_constant(const pc_expr_pool *pool, int e, double *h);

/* --- building: each returns a node id (>= 0), or -1 with *status set ----------------------
 * PC_EDIM: operands of different dimensions, or a value where a scalar is needed (the
 * operations say which kinds they take); PC_ENONFINITE: a NaN or infinite constant or a
 * constant fold that overflows; PC_EDOMAIN: a constant fold outside a function's domain
 * (log(-1), 1/0); PC_ENOMEM. */
int pc_expr_const(pc_expr_pool *pool, double c, int *status);
int pc_expr_vconst(pc_expr_pool *pool, int dim, const double *h, int *status);
/* The parameter called name (1..31 characters): the same node for the same name; at most
 * PC_EXPR_MAXPARAM names per pool (PC_EDOMAIN beyond, or for an empty or long name). */
int pc_expr_param(pc_expr_pool *pool, const char *name, int *status);
int pc_expr_nparams(const pc_expr_pool *pool);
const char *pc_expr_param_name(const pc_expr_pool *pool, int k);   /* NULL if none */
int pc_expr_param_index(const pc_expr_pool *pool, int e);         /* k of a PARAM node, else -1 */
/* expr_params.c: the parameters e depends on, in order, into in (PC_EXPR_MAXPARAM): their
 * count; the parameter called name (-1 if none); their names as a list ("t, s and u") and
 * their values ("t = 0.5, s = 1") into buf, returning the length the whole text needs (as
 * snprintf); the weight class of a value over the unit box of its parameters (PC_KIND_POINT,
 * PC_KIND_VECTOR, PC_KIND_WEIGHTED; -1 for a scalar or when it does not compile). */
int pc_expr_param_list(const pc_expr_pool *pool, int e, int *in);
int pc_expr_find_param(const pc_expr_pool *pool, const char *name);
size_t pc_expr_param_names(const pc_expr_pool *pool, int n, const int *in, char *buf, size_t size);
size_t pc_expr_param_values(const pc_expr_pool *pool, int n, const int *in, const double *x, char *buf,
                            size_t size);
int pc_expr_weight_class(const pc_expr_pool *pool, int e);

/* a + b, a - b: two scalars or two values of one dimension; -a. */
int pc_expr_add(pc_expr_pool *pool, int a, int b, int *status);
int pc_expr_sub(pc_expr_pool *pool, int a, int b, int *status);
int pc_expr_neg(pc_expr_pool *pool, int a, int *status);
/* a * b: scalar * scalar, value * scalar or scalar * value (value * value is PC_EDIM). */
int pc_expr_mul(pc_expr_pool *pool, int a, int b, int *status);
/* a / b: scalar / scalar or value / scalar (the weight is divided too). */
int pc_expr_div(pc_expr_pool *pool, int a, int b, int *status);
/* a ^ b of scalars: an integer constant b gives repeated products, a real constant a power
 * function, anything else exp(b log a). */
int pc_expr_pow(pc_expr_pool *pool, int a, int b, int *status);
/* A function of a scalar: op is one of PC_EX_SIN .. PC_EX_ABS or PC_EX_RECIP. */
int pc_expr_fn(pc_expr_pool *pool, pc_expr_op op, int a, int *status);
/* A smoothstep of a scalar (g: sine, cubic, or a half-spline made by pc_hspline_init). */
int pc_expr_smooth(pc_expr_pool *pool, const pc_gfun *g, int a, int *status);
/* (B - A) t + A = A (1 - t) + B t (Fig. 1.1) of two values and a scalar, or of three scalars. */
int pc_expr_lerp(pc_expr_pool *pool, int a, int b, int t, int *status);
/* 1 - t (the book's t̄). */
int pc_expr_bar(pc_expr_pool *pool, int t, int *status);
/* Coordinate k (0-based) of a value; k = dim gives its weight. */
int pc_expr_comp(pc_expr_pool *pool, int a, int k, int *status);
/* A value of dimension n from n scalar coordinates and a constant weight (1: a point). */
int pc_expr_pack(pc_expr_pool *pool, int n, const int *coords, double weight, int *status);
/* The metric operations on values (their coordinates, the weights ignored: the binding
 * checks that they are vectors): dot product; cross product (2-D: the scalar
 * u.x v.y - u.y v.x, 3-D: a vector); unit vector u / |u|. */
int pc_expr_dot(pc_expr_pool *pool, int a, int b, int *status);
int pc_expr_cross(pc_expr_pool *pool, int a, int b, int *status);
int pc_expr_unit(pc_expr_pool *pool, int a, int *status);
/* The meet K = A1 + lambda (A2 - A1) = B1 + mu (B2 - B1) of two lines of values of one
 * dimension (points, equations of points), as an equation: lambda from the normal equations
 * of the two directions (exact where the lines meet; for skew lines in n-D the point of line A
 * nearest line B), so its derivatives are exact.  *lambda, *mu (may be NULL) get their scalar
 * equations.  Parallel lines make the denominator 0 where they are parallel (the evaluation
 * then fails, not a silent value).  expr_meet.c. */
int pc_expr_meet(pc_expr_pool *pool, int a1, int a2, int b1, int b2, int *lambda, int *mu,
                 int *status);
/* The Bezier curve of `degree` with homogeneous control rows cp (degree + 1 rows of dim + 1)
 * over [t0, t1] at the scalar equation t: sum cp_i B_i(s), s = (t - t0)/(t1 - t0), divided
 * by sum w_i B_i(s) when the curve is rational.  expr_curve.c. */
int pc_expr_bezier(pc_expr_pool *pool, int dim, int degree, const double *cp, double t0,
                   double t1, int t, int *status);
/* The curve c applied to the scalar equation t (c(t) of a param): pc_expr_bezier of a
 * single-piece Bezier curve; or -1 with the reason in why (t not scalar, c of another kind or
 * of several pieces, out of memory). */
int pc_expr_curve_at(pc_expr_pool *pool, const pc_curve *c, int t, char *why, size_t size);
/* What a failure st of making or running an equation means: "out of memory (too many equation
 * nodes)", else pc_strerror's text.  expr_run.c. */
const char *pc_expr_why(int st);

/* --- operations with their checks (expr_apply.c) ------------------------------------------
 * The operations of the point calculus on operands that may be equations, each checking its
 * operands as a script's call needs (a scalar where a parameter goes, vectors for dot and
 * cross, points for meet) and wording what is wrong.  The order is that of the binding's hooks
 * (pcl_expr.h), then the operations the bindings call themselves. */
typedef enum {
    PC_EQV_ADD, PC_EQV_SUB, PC_EQV_MUL, PC_EQV_DIV, PC_EQV_NEG,   /* + - * / unary - */
    PC_EQV_LERP, PC_EQV_BAR, PC_EQV_DOT, PC_EQV_CROSS, PC_EQV_UNIT,
    PC_EQV_P, PC_EQV_V,                                         /* P(x, y, ...), V(...) of scalars */
    PC_EQV_MEET,                                                /* K, lambda, mu of meet(A1, A2, B1, B2) */
    PC_EQV_POW,                                                 /* a ^ b */
    PC_EQV_MATH,                                                /* how->fn of x (how->base: log's base) */
    PC_EQV_SMOOTH                                               /* the smoothstep how->g of t */
} pc_expr_verb;

typedef struct {
    pc_expr_op fn;          /* PC_EQV_MATH: PC_EX_SIN .. PC_EX_ABS */
    double base;            /* PC_EQV_MATH with PC_EX_LOG: a base other than e (0: none) */
    const pc_gfun *g;       /* PC_EQV_SMOOTH */
} pc_expr_how;

/* Apply v to the n operand nodes ids (-1: an operand that is no number, value or equation):
 * the result nodes into res (3 for meet, else 1) and their count; or -1 with the message in
 * why: "@k" in it stands for the description of operand k (1-based; its caller knows what the
 * script passed), arguments counted from 1.  The messages of + - * / unary - and ^ are whole
 * ("cannot add ..."), the others follow the name of the function called ("argument #3 (t)
 * must be ..."). */
int pc_expr_apply(pc_expr_pool *pool, pc_expr_verb v, int n, const int *ids, const pc_expr_how *how,
                  int *res, char *why, size_t size);

/* The program of the point equation e for a curve (nwant 1) or a surface (nwant 2) over the box
 * lo..hi of its parameters, the membership condition checked there (pc_expr_prog_weight); or
 * NULL with the reason in why, about "argument #1 (equation)" ("@1" stands for the equation
 * as the caller shows a constant). */
pc_expr_prog *pc_expr_compile_point(const pc_expr_pool *pool, int e, int nwant, const double *lo,
                                    const double *hi, char *why, size_t size);

/* e with parameter k replaced by the node r (a scalar): instantiating a one-parameter family
 * M(t; s) at a value of s, or changing a parameter.  Shared nodes stay shared. */
int pc_expr_subst(pc_expr_pool *pool, int e, int k, int r, int *status);

/* The equation as text in the book's notation: points as P(x, y), vectors as V(x, y), 1 - t as
 * bar(t), sin(f), smoothsteps as smooth.sine(t) ...  namer (may be NULL) may name
 * a constant value (return a name, or NULL to print it).  Returns the length of the whole
 * text (as snprintf: the text is truncated to len - 1 characters). */
typedef const char *(*pc_expr_namer)(void *ud, int dim, const double *h);
int pc_expr_print(const pc_expr_pool *pool, int e, pc_expr_namer namer, void *ud, char *buf,
                  size_t len);

/* e in powers of its parameter k (expr_poly.c), for an equation built by + - * /, integer
 * powers, dot, coordinates and constants (polynomial or rational in k): coef gets (deg + 1)
 * rows, lowest power first; a value's rows are its dim + 1 homogeneous channels over a common
 * denominator that cancels in each coordinate (coordinate i = row i / row dim: the form
 * pc_curve_monomial gives), a scalar's rows are 2: numerator, denominator.  coef holds
 * (maxdeg + 1) * (dim + 1) doubles (2 for a scalar).  PC_EDIM when e depends on another
 * parameter, PC_EDOMAIN for a function that is not rational (sin, exp, sqrt, smoothsteps,
 * real powers) or a degree above maxdeg, PC_ENOMEM. */
int pc_expr_power_basis(const pc_expr_pool *pool, int e, int k, int maxdeg, double *coef, int *deg);

/* --- compiling and evaluating ------------------------------------------------------------- */
/* The program computing e from the parameters inputs[0..nin-1] (indices of parameters,
 * 0 <= nin <= PC_EXPR_MAXPARAM, derivatives are taken with respect to them, in that order).
 * PC_EDOMAIN if e depends on a parameter not among the inputs (*status only; the caller
 * names it with pc_expr_params). */
pc_expr_prog *pc_expr_compile(const pc_expr_pool *pool, int e, int nin, const int *inputs,
                              int *status);
void pc_expr_prog_free(pc_expr_prog *p);
int pc_expr_prog_dim(const pc_expr_prog *p);        /* 0: scalar, n: a value of dimension n */
int pc_expr_prog_nin(const pc_expr_prog *p);
int pc_expr_prog_size(const pc_expr_prog *p);       /* instructions (constants not counted) */
int pc_expr_prog_count(const pc_expr_prog *p, pc_expr_op op);   /* instructions of one kind */
int pc_expr_prog_registers(const pc_expr_prog *p);  /* registers after reuse */

/* Rows of derivatives per sample: 1 for order 0; 1 + nin for order 1; 1 + nin + nin(nin+1)/2
 * for order 2 (second partials in the order (0,0), (0,1), ..., (1,1), ...). */
int pc_expr_jets(int nin, int order);

/* Evaluate at m points x (m rows of nin) up to order (0, 1 or 2): out gets m blocks of
 * pc_expr_jets(nin, order) rows of width (1 for a scalar, dim+1 for a value): for a curve
 * (nin 1, order 2) the value, d/dt and d2/dt2; for a surface (nin 2, order 1) the value,
 * d/du and d/dv.  PC_ENONFINITE if any result is NaN or infinite (*bad, if not NULL, is then
 * the first such sample: its parameters are x[*bad * nin ...]); PC_EDOMAIN for an order
 * outside 0..2; PC_ENONFINITE also for a non-finite x. */
int pc_expr_eval(pc_expr_prog *p, int m, const double *x, int order, double *out, int *bad);
/* n samples of a one-input program at t = a + (b - a) i / (n - 1) (a alone for n = 1),
 * Cartesian: n rows of dim (a value's coordinates divided by its weight; a weight-0 value
 * as it is).  PC_ENONFINITE (with *bad) as pc_expr_eval. */
int pc_expr_sample(pc_expr_prog *p, double a, double b, long n, double *out, long *bad);
/* The same with the reason a call fails worded in why (expr_run.c): the value of p at x, the
 * parameters in[0..n-1] (PC_ENONFINITE: "the value at t = 0.5 is not finite (...)"), and the
 * samples of p in its parameter k ("the value at t = 0.25 is not finite"); the status. */
int pc_expr_value_at(const pc_expr_pool *pool, pc_expr_prog *p, int n, const int *in, const double *x,
                     double *h, char *why, size_t size);
int pc_expr_sample_at(const pc_expr_pool *pool, pc_expr_prog *p, int k, double a, double b, long n,
                      double *out, char *why, size_t size);

/* The weight of a value program over the box lo..hi of its inputs (nin each), probed at a
 * fixed set of points inside it: PC_KIND_POINT if it is 1 throughout, PC_KIND_VECTOR if 0,
 * PC_KIND_WEIGHTED otherwise, with *x_bad (nin) and *w_bad the first probe where it is
 * neither (when not NULL).  -1 for a scalar program.  Probes whose value is not finite are
 * skipped. */
int pc_expr_prog_weight(pc_expr_prog *p, const double *lo, const double *hi, double *x_bad,
                        double *w_bad);

/* The one curve type over [t0, t1] from a one-input value program (it takes p: freed with
 * the curve, or by this function on failure); the callback gives the value and exact first
 * and second derivatives.  PC_EDIM for a scalar or a program of other than one input,
 * PC_EDOMAIN unless t0 < t1. */
pc_curve *pc_expr_curve(pc_expr_prog *p, double t0, double t1, int *status);
/* The surface type over [u0, u1] x [v0, v1] from a two-input value program (taken as for
 * curves), with exact partials. */
pc_surface *pc_expr_surface(pc_expr_prog *p, double u0, double u1, double v0, double v1,
                            int *status);

#endif
