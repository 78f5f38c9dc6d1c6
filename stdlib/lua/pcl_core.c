/* Calling the core from a binding (pcl_core.h). */
#include "pcl_args.h"
#include "pcl_core.h"
#include "pcl_point.h"

int pcl_check(lua_State *L, int st, const pc_why *table) {
    if (st == PC_OK) return st;
    const pc_why *w = pc_why_find(table, pcl_name(L), st);
    if (!w) return pcl_raise_status(L, pcl_name(L), st);
    if (w->arg > 0) return pcl_argfail(L, w->arg, w->text, pcl_shown(L, w->arg));
    if (w->arg < 0) return pcl_fail(L, w->text, pcl_shown(L, -w->arg));
    if (w->key) return pcl_keyfail(L, w->key, "%s", w->text);
    return pcl_fail(L, "%s", w->text);
}

int pcl_made(lua_State *L, pc_curve *c, const int *st, const pc_why *table) {
    if (!c && pc_why_find(table, pcl_name(L), *st)) pcl_check(L, *st, table);
    return pcl_push_made(L, c, st, NULL);
}

/* One value of kind c from x: n a number, p a point, v a vector, h a homogeneous row (the point,
 * or the direction where its weight is 0), w a value of weight as given (w*P, a vector); 1. */
static int push_loc(lua_State *L, int dim, char c, const double *x) {
    double y[PC_MAXDIM];
    int inf = c == 'h' && fabs(x[dim]) <= 1e-12;
    for (int k = 0; c == 'h' && k < dim; k++) y[k] = inf ? x[k] : x[k] / x[dim];
    if (c == 'h') return push_loc(L, dim, inf ? 'v' : 'p', y);
    if (c == 'n') lua_pushnumber(L, *x);
    else if (c == 'w') memcpy(pcl_newvalue(L, dim)->h, x, sizeof(double) * (size_t)(dim + 1));
    else if (c == 'v') pcl_pushvector(L, dim, x);
    else pcl_pushpoint(L, dim, x);
    return 1;
}

/* the numbers a value of kind c takes in packed rows */
static size_t width(int dim, char c) { return c == 'n' ? 1 : c == 'h' || c == 'w' ? (size_t)dim + 1 : (size_t)dim; }

/* a list of n values of kind c from rows */
static void push_list(lua_State *L, int n, int dim, char c, const double *rows) {
    lua_createtable(L, n, 0);
    for (int i = 0; i < n; i++) {
        push_loc(L, dim, c, rows + (size_t)i * width(dim, c));
        lua_rawseti(L, -2, i + 1);
    }
}

void pcl_push_numbers(lua_State *L, int n, const double *x) { push_list(L, n, 0, 'n', x); }

void pcl_push_values(lua_State *L, int n, int dim, const double *rows, int homogeneous) {
    push_list(L, n, dim, homogeneous ? 'w' : 'p', rows);
}

/* push the values of kind c from ap (NULL: from v): their count, 0 when left out (o of NaN) */
static int push_one(lua_State *L, int dim, char c, va_list *ap, const double *v) {
    if (c == 'x') {                       /* the dim numbers of a row as as many results */
        const double *x = ap ? va_arg(*ap, const double *) : v;
        for (int k = 0; k < dim; k++) lua_pushnumber(L, x[k]);
        return dim;
    }
    if (!ap) return push_loc(L, dim, c, v);
    if (c == 'n' || c == 'o') {
        double x = va_arg(*ap, double);
        if (c == 'o' && isnan(x)) return 0;
        lua_pushnumber(L, c == 'o' ? x + 0.0 : x);   /* o: no -0 */
        return 1;
    }
    if (c == 'i') lua_pushinteger(L, va_arg(*ap, int));
    else if (c == 'b') lua_pushboolean(L, va_arg(*ap, int));
    else if (c == 's') lua_pushstring(L, va_arg(*ap, const char *));
    else if (c != 'N' && c != 'P' && c != 'V') push_loc(L, dim, c, va_arg(*ap, const double *));
    else {
        int n = va_arg(*ap, int);   /* the count first: one va_arg at a time */
        push_list(L, n, dim, c == 'N' ? 'n' : c == 'P' ? 'p' : 'v', va_arg(*ap, const double *));
    }
    return 1;
}

/* Both bodies: the values from ap, or (ap NULL) packed in order in v. */
static int push_spec(lua_State *L, int dim, const char *spec, va_list *ap, const double *v) {
    int named = strchr(spec, '=') != NULL, count = 0;
    if (named) lua_newtable(L);
    for (const char *s = spec, *tok = s; *s; tok = s) {
        size_t len = strcspn(s, " ");
        char c = s[len - 1];                    /* the kind letter ends the token */
        s += len + (s[len] == ' ');
        int pushed = push_one(L, dim, c, ap, v);
        if (!ap) v += width(dim, c);
        if (named && pushed) {                  /* NAME=x: into the table by NAME */
            lua_pushlstring(L, tok, strcspn(tok, "="));
            lua_insert(L, -2);
            lua_rawset(L, -3);
        }
        count += pushed;
    }
    return named ? 1 : count;
}

int pcl_push_results(lua_State *L, int dim, const char *spec, ...) {
    va_list ap;
    va_start(ap, spec);
    int count = push_spec(L, dim, spec, &ap, NULL);
    va_end(ap);
    return count;
}

int pcl_push_packed(lua_State *L, int dim, const char *spec, const double *v) {
    return push_spec(L, dim, spec, NULL, v);
}

void pcl_register_into(lua_State *L, int t, const char *name, const pcl_fn *fns) {
    if (lua_getfield(L, t, name) == LUA_TTABLE) pcl_register(L, lua_gettop(L), fns, 0);
    lua_pop(L, 1);
}

pcl_luafn *pcl_luafn_new(lua_State *L, int n, const int *idx) {
    pcl_luafn *f = malloc(sizeof *f);
    if (!f) pcl_fail(L, "out of memory");
    *f = (pcl_luafn){.n = n, .nargs = 1, .fname = pcl_name(L)};   /* fname: a static string */
    for (int i = 0; i < n; i++) {
        lua_pushvalue(L, idx[i]);
        f->ref[i] = luaL_ref(L, LUA_REGISTRYINDEX);
    }
    pcl_callback_state(L);
    return f;
}

pcl_luafn pcl_luafn_at(lua_State *L, int idx) {
    pcl_callback_state(L);
    return (pcl_luafn){.n = 0, .nargs = 1, .stack = lua_absindex(L, idx), .fname = pcl_name(L)};
}

void pcl_luafn_free(void *ud) {
    pcl_luafn *f = ud;
    lua_State *L = pcl_current_state();
    for (int i = 0; L && i < f->n; i++) luaL_unref(L, LUA_REGISTRYINDEX, f->ref[i]);
    free(f);
}

double pcl_luafn_call(pcl_luafn *f, int which, int item, const char *what, int nargs, const double *x) {
    lua_State *L = pcl_current_state();
    if (f->stack) lua_pushvalue(L, f->stack);
    else lua_rawgeti(L, LUA_REGISTRYINDEX, f->ref[which]);
    if (item > 0) {
        lua_geti(L, -1, item);
        lua_remove(L, -2);
    }
    for (int i = 0; i < nargs; i++) lua_pushnumber(L, x[i]);
    int isnum = 0, ok = lua_pcall(L, nargs, 1, 0) == LUA_OK;
    double y = ok ? lua_tonumberx(L, -1, &isnum) : NAN;
    if (ok && !isnum) {   /* kept as the callback's error, raised when the core gives up */
        const char *got = luaL_typename(L, -1);
        pcl_pushwhere(L);
        lua_pushfstring(L, "%s: %s must return a number, got %s", f->fname, what ? what : "the function", got);
        lua_concat(L, 2);
    }
    if (!isnum) {   /* the error kept (popped), Lua's or ours */
        pcl_callback_failed(L);
        f->failed++;
    }
    if (ok) lua_pop(L, 1);   /* the result */
    return isnum ? y : NAN;
}

double pcl_luafn_of(double x, void *f) { return pcl_luafn_call(f, 0, 0, NULL, 1, &x); }

double pcl_luafn_blend(void *f, double x) { return pcl_luafn_call(f, 0, 0, NULL, 1, &x); }

double pcl_luafn_which(void *f, int which, double x) {
    return which < ((pcl_luafn *)f)->n ? pcl_luafn_call(f, which, 0, NULL, 1, &x) : NAN;
}

double pcl_luafn_point(void *f, const double *x) { return pcl_luafn_call(f, 0, 0, NULL, ((pcl_luafn *)f)->nargs, x); }
