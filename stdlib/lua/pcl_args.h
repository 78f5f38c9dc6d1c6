/* The declared argument layer: a binding declares each function once and the layer reads its
 * arguments, words every message and gives :help and docs/api.md.  docs/bindings.md is the
 * guide (the kinds, the messages, registration); l_korotky.c a model. */
#ifndef PCL_ARGS_H
#define PCL_ARGS_H

#include "pcl.h"
#include "names.h"
#include "point.h"

typedef enum {
    PCL_NONE,      /* ends an argument list ({0}) */
    PCL_NUMBER,    /* a finite number; PCL_RANGE: lo..hi, PCL_POS: > 0 */
    PCL_INTEGER,   /* an integral number; PCL_RANGE: lo..hi */
    PCL_BOOLEAN,
    PCL_STRING,
    PCL_ENUM,      /* one of the strings choices[] (NULL-ended); v.n is its index */
    PCL_POINT,     /* weight 1: v.v the Cartesian coordinates, v.n the dimension */
    PCL_VECTOR,    /* weight 0: v.v the components */
    PCL_LOC,       /* a point or a vector (a direction): v.v homogeneous (n + 1), weight 0 or 1 */
    PCL_VALUE,     /* any point, vector or weighted value: v.v homogeneous, the weight as given */
    PCL_POINTS,    /* a list of points (lo..hi of them; dim or one dimension): v.list rows */
    PCL_NUMBERS,   /* a list of finite numbers (lo..hi of them): v.list */
    PCL_VALUES,    /* a list of values of any weight (w*P, vectors at infinity): homogeneous rows */
    PCL_VECTORS,   /* a list of vectors: rows of their components */
    PCL_CURVE,     /* v.obj a pc_curve (dim: its dimension must be dim) */
    PCL_SURFACE,   /* v.obj a pc_surface */
    PCL_MAP,       /* v.obj a pc_map */
    PCL_FUNCTION,  /* v.idx its stack index */
    PCL_CALLABLE,  /* a function or a value with __call (v.idx) */
    PCL_TABLE,     /* any table (v.idx): the body reads it */
    PCL_OPTIONS,   /* a table of the keys[] (each with its own kind); unknown keys are errors */
    PCL_ANY,       /* anything (v.idx); with read: the binding's own reader */
} pcl_kind;

/* flags of an argument (or of an option key) */
#define PCL_OPT     0x01u  /* an argument that may be nil or absent (v.present = 0, v.x = dflt) */
#define PCL_REQ     0x02u  /* an option key that must be given (keys are optional otherwise) */
#define PCL_RANGE   0x04u  /* numbers, integers: lo <= x <= hi */
#define PCL_POS     0x08u  /* numbers: x > 0 */
#define PCL_SAMEDIM 0x10u  /* points, vectors, locations, lists, curves: the dimension of the first one */
#define PCL_CALLTABLE 0x20u /* the only argument, an options table: shown as NAME{...} */
#define PCL_PAIR    0x40u  /* numbers: x of a pair x, y (the next argument) that may be one point */
#define PCL_INF     0x80u  /* numbers: +-inf accepted (NaN is not) */

typedef struct pcl_val pcl_val;
typedef struct pcl_arg pcl_arg;
/* A binding's own reader (PCL_ANY): 1 if the value at idx fits (filled into out), 0 if not. */
typedef int (*pcl_reader)(lua_State *L, int idx, const pcl_arg *a, pcl_val *out);

struct pcl_arg {
    const char *name;         /* as messages and the signature show it */
    pcl_kind kind;
    unsigned flags;
    double lo, hi;            /* range of a number or integer; count bounds of a list */
    int dim;                  /* points, vectors, curves, surfaces: the dimension (0 any) */
    const char *const *choices;  /* PCL_ENUM */
    const pcl_arg *keys;      /* PCL_OPTIONS: the known keys, ended by {0} */
    double dflt;              /* the value when absent (numbers, integers, booleans, enums) */
    const char *shown;        /* how the signature shows the default or the value ("1"), or NULL */
    const char *expect;       /* EXPECTED text (PCL_ANY with read; overrides the kind's) */
    pcl_reader read;
};

struct pcl_val {
    int present;              /* given (not nil) */
    int n;                    /* dimension; count of a list; index of an enum's choice */
    double x;                 /* number, integer, boolean (0/1) */
    const char *s;            /* string, enum choice */
    double v[PC_MAXDIM + 1];  /* point, vector, location, value; a reader's scratch */
    double *list;             /* lists: rows of dim numbers (preset with cap: the caller's buffer) */
    int cap;                  /* capacity of a preset list in doubles */
    int dim;                  /* dimension of a list of points */
    void *obj;                /* curve, surface, map */
    int idx;                  /* stack index of the argument (0: an option key) */
};

/* One function: registered with pcl_register, read with PCL_READ. */
typedef struct pcl_fn {
    const char *name;         /* as the user writes it: "korotky.ferguson", "f:xy", "S" (a __call) */
    lua_CFunction fn;
    const pcl_arg *args;      /* ended by {0}; NULL: no arguments */
    const char *result;       /* "curve, coef", or NULL */
    const char *help;         /* the one-line description (:help, docs/api.md) */
    const char *sig;          /* NULL: the signature is made from args; else the forms, one per line */
    void *(*self)(lua_State *L, int idx);  /* methods and __call: the receiver's recogniser */
    const char *selftype;     /* "map": "NAME: must be called on a map, as f:xy(...)" */
    const char *key;          /* the field set (NULL: the name's last part; "__call" for f(p)) */
    const char *topic;        /* the help entry (NULL: the name; "f(p)" for a __call) */
    int callname;             /* a __call: messages name the called variable when Lua knows it */
} pcl_fn;

/* Set table[the last part of each name] = a closure of fn with its declaration as upvalue 1
 * and the nup values on the stack top as upvalues 2.. (popped); record each for :help. */
void pcl_register(lua_State *L, int table, const pcl_fn *fns, int nup);
/* The same, not recorded for :help: the toolkit functions of _tk. */
void pcl_register_private(lua_State *L, int table, const pcl_fn *fns);
/* Push one declared function (upvalues as pcl_register), not recorded: a closure made at run time. */
void pcl_pushfn(lua_State *L, const pcl_fn *d, int nup);
/* Upvalue k of a registered function (k = 1: the first of the nup shared values). */
#define PCL_UPVALUE(k) lua_upvalueindex((k) + 1)

/* Read the running function's declared arguments into v (one value per argument, then one per
 * key of each option table); the receiver of a method, or NULL.  Lists without a preset buffer
 * get one above the arguments on the stack. */
void *pcl_read(lua_State *L, pcl_val *v, int n);
#define PCL_READ(L, v) pcl_read((L), (v), (int)(sizeof(v) / sizeof((v)[0])))
/* Upvalue 1 of a declared function: its declaration with the counts a call needs, made once. */
typedef struct {
    PCL_SELF;                 /* a block of another type there is refused (pcl.h) */
    const pcl_fn *d;
    int nargs, nvalues;       /* the declared arguments; the values PCL_READ fills */
    int first_pair;           /* pcl_read_pairs: the argument (from 1) that starts the first pair */
} pcl_decl;
/* The running function's declaration, checked; pcl_read into its nvalues values of v, cleared
 * first, with Lua callbacks armed (PCL_BODY: the declaration found once per call). */
const pcl_decl *pcl_running(lua_State *L);
void *pcl_read_decl(lua_State *L, const pcl_decl *b, pcl_val *v);
/* A binding's body, its declared arguments read into a and Lua callbacks armed:
 *     PCL_BODY(l_bezier, a) { ... a[0].list ... return pcl_push_made(L, c, &st, NULL); }
 *     PCL_METHOD(c_length, lcurve *u, a) { ... }     the receiver of a method as u
 * The function defined is l_bezier (a lua_CFunction, registered as any other). */
#define PCL_CALL_BODY(f, ...) \
    static int f(lua_State *L) { \
        const pcl_decl *f##_d = pcl_running(L); \
        pcl_val f##_v[f##_d->nvalues > 0 ? f##_d->nvalues : 1]; \
        PCL_UNUSED void *f##_self = pcl_read_decl(L, f##_d, f##_v); \
        return f##_body(L, __VA_ARGS__); \
    }
#define PCL_BODY(f, a) \
    static int f##_body(lua_State *L, pcl_val *a); \
    PCL_CALL_BODY(f, f##_v) \
    static int f##_body(lua_State *L, PCL_UNUSED pcl_val *a)
#define PCL_METHOD(f, self, a) \
    static int f##_body(lua_State *L, self, pcl_val *a); \
    PCL_CALL_BODY(f, f##_self, f##_v) \
    static int f##_body(lua_State *L, self, PCL_UNUSED pcl_val *a)
#define PCL_UNUSED __attribute__((unused))
/* The values the running function's declaration fills (at least 1: PCL_BODY's block). */
int pcl_nvalues(lua_State *L);

/* Read the value at idx as the argument a shown as argument #shown (its element [item] when
 * item > 0: variadic functions); dimdef: the dimension PCL_SAMEDIM refers to. */
void pcl_readone(lua_State *L, int idx, int shown, int item, const pcl_arg *a, int dimdef, pcl_val *out);

/* PCL_READ for a plain function whose coordinate pairs (x flagged PCL_PAIR, y after it) may
 * each be one point (pcl_topoint2): each argument is read and shown by the slot it falls on, a
 * last option table may trail; v need not be initialised (no preset buffers). */
void pcl_read_pairs(lua_State *L, pcl_val *v, int n);
#define PCL_READ_PAIRS(L, v) pcl_read_pairs((L), (v), (int)(sizeof(v) / sizeof((v)[0])))
/* Inside a reader: raise "NAME: WHERE must be EXPECTED, got VALUE" for the value at idx. */
int pcl_readfail(lua_State *L, int idx, const char *expected);
/* The drawing colour (l_draw.c): an attribute or "#rrggbb" into out->x. */
int pcl_read_color(lua_State *L, int idx, const pcl_arg *a, pcl_val *out);
/* The print look (l_figure.c): a length with its unit ("0.5mm") in pt into out->x; the label
 * options {font =, size =, halo =}, applied to a label once drawn. */
int pcl_read_length(lua_State *L, int idx, const pcl_arg *a, pcl_val *out);
extern const pcl_arg pcl_label_keys[];
void pcl_label_style(lua_State *L, pc_canvas *c, const pcl_val *keys);
/* Read the option table at idx as the argument a, shown as #shown, its keys into v: screen{...}. */
void pcl_read_options(lua_State *L, int idx, int shown, const pcl_arg *a, pcl_val *v);
#define A_X(nm) {.name = nm, .kind = PCL_NUMBER, .flags = PCL_PAIR}

/* The running function's declared name (a __call's: the variable called, when Lua knows it). */
const char *pcl_name(lua_State *L);
/* 1 if the running C function is a declared one (pcl_name may be asked). */
int pcl_declared(lua_State *L);
/* "NAME: MESSAGE" at the user's line. */
int pcl_fail(lua_State *L, const char *fmt, ...);
/* "NAME: argument #K (WHAT) EXPECTED_TEXT": a body's own condition on a declared argument, e.g.
 * pcl_argfail(L, 1, "[%d] must lie right of the point before", i).  k counts from 1. */
int pcl_argfail(lua_State *L, int k, const char *fmt, ...);
/* "NAME: option 'KEY' MESSAGE". */
int pcl_keyfail(lua_State *L, const char *key, const char *fmt, ...);

/* The coordinates of k declared points a[0..k-1] of dimension n into out, rows of n. */
void pcl_point_rows(const pcl_val *a, int k, int n, double *out);
/* Argument #k, a matrix of 1..PC_MAXDIM + 1 rows of finite numbers, into m row by row: *nr
 * rows, *nc columns (ncols, or with ncols 0 the length of row [1], 2..PC_MAXDIM + 1). */
void pcl_read_rows(lua_State *L, int k, int ncols, double *m, int *nr, int *nc);

/* The nearest of the string keys of the table at idx to name, or NULL (names.h: pc_nearest_name). */
const char *pcl_nearest_key(lua_State *L, const char *name, int idx);

/* 1 if the value at idx can be called: a function, or a value whose metatable has __call. */
int pcl_callable(lua_State *L, int idx);
/* The receiver's recogniser (pcl_fn.self) of a callable table's __call: any table. */
void *pcl_self_table(lua_State *L, int idx);
/* Push a list {x[0], ..., x[n-1]}. */
void pcl_push_numbers(lua_State *L, int n, const double *x);
/* Push a list of n points from rows of dim, or (homogeneous) of values from rows of dim + 1. */
void pcl_push_values(lua_State *L, int n, int dim, const double *rows, int homogeneous);

/* Make and leave the metatable tname: metamethods meta, a declared __call, and __index: a
 * closure of index over the table of the declared methods (index NULL: that table). */
void pcl_open_type(lua_State *L, const char *tname, const luaL_Reg *meta, const pcl_fn *call,
                   const pcl_fn *methods, lua_CFunction index);
/* module[name] = a new table of the declared functions fns; with call, the table is callable
 * through a declared __call in its metatable (oneratio(A, B, C) is oneratio.simplex). */
void pcl_new_table(lua_State *L, int module, const char *name, const pcl_fn *fns, const pcl_fn *call);

/* Refuse debug.setupvalue(f, 1, x) of a declared function (upvalue 1, which the layer trusts). */
void pcl_guard_upvalues(lua_State *L);
/* The registry's declarations, name -> {sig = TEXT | {FORMS}, desc = TEXT}: pointcalc._decl. */
#define PCL_DECL_KEY "pointcalc.decl"
/* Push and return "(did you mean 'label'?)" for a message about a misspelt global, else NULL. */
const char *pcl_global_hint(lua_State *L, const char *msg);

/* Shorthands for declarations (designated initialisers work as well). */
#define PCL_FN(nm, f, a, res, text) {.name = nm, .fn = f, .args = a, .result = res, .help = text}
#define PCL_END {0}
#define A_NUM(nm) {.name = nm, .kind = PCL_NUMBER}
#define A_NUMOPT(nm, d, txt) {.name = nm, .kind = PCL_NUMBER, .flags = PCL_OPT, .dflt = d, .shown = txt}
#define A_POSNUM(nm) {.name = nm, .kind = PCL_NUMBER, .flags = PCL_POS}
#define A_NUMIN(nm, a, b) {.name = nm, .kind = PCL_NUMBER, .flags = PCL_RANGE, .lo = a, .hi = b}
#define A_INT(nm, a, b) {.name = nm, .kind = PCL_INTEGER, .flags = PCL_RANGE, .lo = a, .hi = b}
#define A_ENUM(nm, ch) {.name = nm, .kind = PCL_ENUM, .choices = ch}
#define A_POINT(nm, d) {.name = nm, .kind = PCL_POINT, .dim = d}
#define A_VECTOR(nm, d) {.name = nm, .kind = PCL_VECTOR, .dim = d}
#define A_SAMEPOINT(nm) {.name = nm, .kind = PCL_POINT, .flags = PCL_SAMEDIM}
#define A_SAMEVECTOR(nm) {.name = nm, .kind = PCL_VECTOR, .flags = PCL_SAMEDIM}
#define A_POINTS(nm, d, a, b) {.name = nm, .kind = PCL_POINTS, .dim = d, .lo = a, .hi = b}
#define A_NUMBERS(nm, a, b) {.name = nm, .kind = PCL_NUMBERS, .lo = a, .hi = b}
#define A_VALUES(nm, a, b) {.name = nm, .kind = PCL_VALUES, .lo = a, .hi = b}
#define A_VECTORS(nm) {.name = nm, .kind = PCL_VECTORS, .flags = PCL_SAMEDIM}
#define A_CURVE(nm, d) {.name = nm, .kind = PCL_CURVE, .dim = d}
#define A_MAP(nm) {.name = nm, .kind = PCL_MAP}
#define A_FUNCTION(nm) {.name = nm, .kind = PCL_FUNCTION}
#define A_OPTIONS(nm, k) {.name = nm, .kind = PCL_OPTIONS, .flags = PCL_OPT, .keys = k}
#define A_ANY(nm, rd, exp) {.name = nm, .kind = PCL_ANY, .read = rd, .expect = exp}

#endif
