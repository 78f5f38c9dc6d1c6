/* Calling the core from a binding: statuses explained (why.h), results pushed by a spec, the
 * Lua functions the core calls back. */
#ifndef PCL_CORE_H
#define PCL_CORE_H

#include "pcl_curve.h"
#include "why.h"

/* st unless it fails: then raise the table's row for the running function's name and st,
 * "NAME: argument #K (WHAT) TEXT" (TEXT's %s the argument's value), "NAME: option 'KEY' TEXT"
 * or "NAME: TEXT" (with arg -K: TEXT's %s the value of argument #K); a status the table does
 * not explain raises as pcl_raise_status. */
int pcl_check(lua_State *L, int st, const pc_why *table);
/* pcl_push_made, with the status of a curve not made explained by the table. */
int pcl_made(lua_State *L, pc_curve *c, const int *st, const pc_why *table);

/* Push results by spec, space-separated tokens: p a point (const double *, dim coordinates),
 * v a vector, h a homogeneous row (dim + 1: a point, or a vector where its weight is 0), n a
 * number (double), o a number left out when NaN (in a table; -0 as 0), i an integer (int), b a
 * boolean (int), s a string, N a list of numbers (int n, const double *), P a list of points
 * (int n, const double * rows of dim), V a list of vectors (the same), x the dim numbers of a
 * row as as many results (const double *; not in a table).  Tokens NAME=x go into one table
 * by name (1 pushed); else each is pushed in turn.  Returns the count pushed. */
int pcl_push_results(lua_State *L, int dim, const char *spec, ...);
/* The same for values packed in order in v (p, v and x: dim numbers, h: dim + 1, n: one). */
int pcl_push_packed(lua_State *L, int dim, const char *spec, const double *v);

/* pcl_register into the table t[name] of the table t at index t (nothing when it is no table). */
void pcl_register_into(lua_State *L, int t, const char *name, const pcl_fn *fns);

/* References to the Lua functions at stack indices idx[0..n-1] (at most 16) the core calls,
 * the callback state set; freed by pcl_luafn_free.  failed: the calls that raised; nargs: the
 * numbers pcl_luafn_point passes (1 when made). */
typedef struct {
    int n, nargs, failed, ref[16];
    int stack;              /* pcl_luafn_at: the function's stack index, else 0 */
    const char *fname;      /* the declaration's name, for the messages */
} pcl_luafn;
pcl_luafn *pcl_luafn_new(lua_State *L, int n, const int *idx);
/* The function at stack index idx for calls while the binding runs (nothing to free). */
pcl_luafn pcl_luafn_at(lua_State *L, int idx);
void pcl_luafn_free(void *f);
/* Call function `which` (item > 0: element [item] of that table) with the nargs numbers x:
 * a number, or NaN with the error kept; what names it in a message (NULL: "the function"). */
double pcl_luafn_call(pcl_luafn *f, int which, int item, const char *what, int nargs, const double *x);
/* The callback shapes of the core: the first function of x or of the point x[0..n-1]; the
 * function `which` (NaN past the last). */
double pcl_luafn_of(double x, void *f);
double pcl_luafn_blend(void *f, double x);
double pcl_luafn_which(void *f, int which, double x);
double pcl_luafn_point(void *f, const double *x);

#endif
