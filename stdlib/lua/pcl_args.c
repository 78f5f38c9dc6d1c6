/* The declared argument layer (pcl_args.h): registration, the one reader of declared
 * arguments, one wording of every message, and the registry of declarations :help reads. */
#include "pcl_args.h"
#include "pcl_curve.h"
#include "pcl_point.h"

#define MAXLIST 100000                 /* no list of a binding is longer */

/* ---- the running declaration ------------------------------------------------------------- */

static const char BOX_TAG = 'd';
#define BOX_MT "pointcalc.declaration"
/* The declaration block at idx, or NULL: its size and its tag, which a script cannot forge. */
static const pcl_decl *to_box(lua_State *L, int idx) {
    const pcl_decl *b = lua_touserdata(L, idx);
    int ok = b && lua_type(L, idx) == LUA_TUSERDATA && lua_rawlen(L, idx) == sizeof *b;
    return ok && b->self == PCL_SELF_TAG(b, &BOX_TAG) ? b : NULL;
}

/* The declaration of the running C function (the guard below keeps debug.setupvalue off it). */
const pcl_decl *pcl_running(lua_State *L) {
    const pcl_decl *b = to_box(L, lua_upvalueindex(1));
    if (!b) luaL_error(L, "pointcalc: a declared function without its declaration (forged upvalue)");
    return b;
}
static const pcl_fn *current(lua_State *L) { return pcl_running(L)->d; }

int pcl_declared(lua_State *L) { return to_box(L, lua_upvalueindex(1)) != NULL; }

/* debug.setupvalue(f, 1, x) of a declared function is refused, so that no call asks Lua which
 * function runs; Lua's own function is kept where no script reaches it (not an upvalue). */
static lua_CFunction lua_setupvalue_fn;
static int setupvalue_guard(lua_State *L) {
    if (lua_iscfunction(L, 1) && lua_tointegerx(L, 2, NULL) == 1 && lua_getupvalue(L, 1, 1)) {
        int declared = to_box(L, -1) != NULL;
        lua_pop(L, 1);
        if (declared)
            return luaL_error(L, "debug.setupvalue: upvalue 1 of a declared function is its declaration, "
                              "which cannot be replaced (forged upvalue)");
    }
    return lua_setupvalue_fn(L);
}

void pcl_guard_upvalues(lua_State *L) {
    int top = lua_gettop(L);
    if (lua_getglobal(L, "debug") == LUA_TTABLE && lua_getfield(L, -1, "setupvalue") == LUA_TFUNCTION &&
        lua_tocfunction(L, -1) && lua_tocfunction(L, -1) != setupvalue_guard) {
        lua_setupvalue_fn = lua_tocfunction(L, -1);   /* the debug library's, one per process */
        lua_pushcfunction(L, setupvalue_guard);
        lua_setfield(L, -3, "setupvalue");
    }
    lua_settop(L, top);
}

/* The declared name; for a __call (callname) the variable the script called, when known:
 * "iso: argument #1 is 2-D, ..." for iso(P(1, 2)). */
const char *pcl_name(lua_State *L) {
    const pcl_fn *d = current(L);
    lua_Debug ar;
    if (d->callname && lua_getstack(L, 0, &ar) && lua_getinfo(L, "n", &ar) && ar.name &&
        ar.namewhat[0] && strcmp(ar.namewhat, "method") != 0)
        return ar.name;
    return d->name;
}

int pcl_fail(lua_State *L, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    return pcl_verror(L, lua_pushfstring(L, "%s: ", pcl_name(L)), fmt, ap);
}

/* A plain function called with a colon (p:dist(B), a value's method table holds it): the
 * receiver is "self" and the arguments count after it, as the user wrote them. */
static int colon_call(lua_State *L) { return !current(L)->self && pcl_arg_shown(L, 1) == 0; }

static const char *arg_label(lua_State *L, int shown, const char *name) {
    int self = colon_call(L) && --shown == 0;
    const char *arg = self ? "self" : lua_pushfstring(L, "argument #%d", shown);
    return name ? lua_pushfstring(L, "%s (%s)", arg, name) : arg;
}

/* The name of declared argument #k, or NULL past the declared ones (or none declared). */
static const char *arg_name(lua_State *L, int k) {
    const pcl_decl *b = pcl_running(L);
    return k >= 1 && k <= b->nargs ? b->d->args[k - 1].name : NULL;
}

int pcl_argfail(lua_State *L, int k, const char *fmt, ...) {
    const char *name = arg_name(L, k);
    va_list ap;
    va_start(ap, fmt);
    return pcl_verror(L, lua_pushfstring(L, "%s: %s ", pcl_name(L), arg_label(L, k, name)), fmt, ap);
}

int pcl_keyfail(lua_State *L, const char *key, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    return pcl_verror(L, lua_pushfstring(L, "%s: option '%s' ", pcl_name(L), key), fmt, ap);
}

void pcl_point_rows(const pcl_val *a, int k, int n, double *out) {
    for (int i = 0; i < k; i++) memcpy(out + i * n, a[i].v, sizeof(double) * (size_t)n);
}

void pcl_read_rows(lua_State *L, int k, int ncols, double *m, int *nr, int *nc) {
    int idx = k + (current(L)->self ? 1 : 0), max = PC_MAXDIM + 1;
    int rows = (int)luaL_len(L, idx), cols = ncols;
    if (rows < 1 || rows > max) pcl_argfail(L, k, "must hold 1 to %d rows, got %d", max, rows);
    for (int i = 1; i <= rows; i++) {
        int t = lua_geti(L, idx, i), len = t == LUA_TTABLE ? (int)luaL_len(L, -1) : -1;
        if (ncols && len != ncols)
            pcl_argfail(L, k, "row [%d] must be a list of %d numbers, got %s", i, ncols, pcl_shown(L, lua_gettop(L)));
        if (len < 0) pcl_argfail(L, k, "row [%d] must be a table of numbers, got %s", i, pcl_shown(L, lua_gettop(L)));
        if (i == 1 && !ncols && (len < 2 || len > max))
            pcl_argfail(L, k, "row [1] holds %d numbers; a matrix here has 2..%d columns", len, max);
        if (i == 1) cols = len;
        if (len != cols)
            pcl_argfail(L, k, "row [%d] holds %d numbers, row [1] %d: the rows must be of one length", i, len, cols);
        for (int j = 1; j <= cols; j++) {
            lua_geti(L, -1, j);
            double v = lua_tonumber(L, -1);
            if (lua_type(L, -1) != LUA_TNUMBER || !isfinite(v))
                pcl_argfail(L, k, "entry [%d][%d] must be a finite number, got %s", i, j, pcl_shown(L, lua_gettop(L)));
            m[(i - 1) * cols + (j - 1)] = v;
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    *nr = rows;
    *nc = cols;
}

/* ---- nearest names (names.c) ---------------------------------------------------------------- */

const char *pcl_nearest_key(lua_State *L, const char *name, int idx) {
    idx = lua_absindex(L, idx);
    const char *best = NULL;
    int bestd = 99;
    lua_pushnil(L);
    while (lua_next(L, idx)) {
        lua_pop(L, 1);
        if (lua_type(L, -1) == LUA_TSTRING) pc_nearer_name(name, lua_tostring(L, -1), &best, &bestd);
    }
    return best;   /* a key of the table, which keeps the string alive */
}

/* ---- callables ------------------------------------------------------------------------------ */

int pcl_callable(lua_State *L, int idx) {
    if (lua_isfunction(L, idx)) return 1;
    if (luaL_getmetafield(L, idx, "__call") == LUA_TNIL) return 0;
    lua_pop(L, 1);
    return 1;
}

void *pcl_self_table(lua_State *L, int idx) { return lua_istable(L, idx) ? (void *)1 : NULL; }

/* ---- reading one value ------------------------------------------------------------------- */

/* Where a value sits, for its messages: argument #shown (name), or option 'key'; item > 0: an
 * element of that list. */
typedef struct dimref dimref;
typedef struct {
    const char *fname;
    int shown;
    const char *name, *key;
    int item;
    dimref *dim;            /* the dimension PCL_SAMEDIM refers to */
} ctx;
struct dimref {
    int n;                  /* 0: not yet set */
    ctx who;                /* the value that set it */
};

static const char *where(lua_State *L, const ctx *c) {
    const char *w = c->key ? lua_pushfstring(L, "option '%s'", c->key) : arg_label(L, c->shown, c->name);
    if (c->item) w = lua_pushfstring(L, "%s [%d]", w, c->item);
    return w;
}

/* The value as messages show it: a string in quotes (shortened), else as pcl_shown. */
static const char *shown(lua_State *L, int idx) {
    if (lua_type(L, idx) != LUA_TSTRING) return pcl_shown(L, idx);
    size_t len;
    const char *s = lua_tolstring(L, idx, &len);
    if (len > 40) return lua_pushfstring(L, "\"%s...\"", lua_pushlstring(L, s, 37));
    return lua_pushfstring(L, "\"%s\"", s);
}

/* "NAME: WHERE must be EXPECTED, got VALUE[; HINT]" */
static int mismatch_hint(lua_State *L, const ctx *c, int idx, const char *expected, const char *hint) {
    return pcl_error(L, "%s: %s must be %s, got %s%s%s", c->fname, where(L, c), expected, shown(L, idx),
                     hint ? "; " : "", hint ? hint : "");
}
#define mismatch(L, c, idx, expected) mismatch_hint((L), (c), (idx), (expected), NULL)

/* Push the strings items[] (NULL-ended), each as fmt shows it, joined by sep, the last by last:
 * "a", "b" or "c". */
static const char *push_list(lua_State *L, const char *const *items, const char *fmt, const char *sep,
                             const char *last) {
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    for (int i = 0; items[i]; i++) {
        if (i) luaL_addstring(&b, items[i + 1] ? sep : last);
        lua_pushfstring(L, fmt, items[i]);
        luaL_addvalue(&b);
    }
    luaL_pushresult(&b);
    return lua_tostring(L, -1);
}

/* The names of the keys of an option table into names (NULL-ended); their count. */
static int key_names(const pcl_arg *keys, const char **names, int max) {
    int n = 0;
    for (; keys[n].name && n < max - 1; n++) names[n] = keys[n].name;
    names[n] = NULL;
    return n;
}

/* The expected text of each kind; %s: "2-D " for a kind with a dimension. */
static const char *const EXPECTED[] = {
    [PCL_NUMBER] = "a finite number", [PCL_INTEGER] = "an integer", [PCL_BOOLEAN] = "a boolean",
    [PCL_STRING] = "a string", [PCL_POINT] = "a %spoint", [PCL_VECTOR] = "a %svector",
    [PCL_LOC] = "a %spoint or vector", [PCL_VALUE] = "a %spoint, vector or weighted point",
    [PCL_POINTS] = "a list of %spoints", [PCL_NUMBERS] = "a list of numbers",
    [PCL_VALUES] = "a list of points", [PCL_VECTORS] = "a list of vectors",
    [PCL_CURVE] = "a %scurve", [PCL_SURFACE] = "a %ssurface", [PCL_MAP] = "a map",
    [PCL_FUNCTION] = "a function", [PCL_CALLABLE] = "a function", [PCL_TABLE] = "a table",
    [PCL_ANY] = "a value"};

/* The expected text of a kind (what the messages say after "must be"). */
static const char *expected(lua_State *L, const pcl_arg *a) {
    const char *names[64];
    int number = a->kind == PCL_NUMBER;
    if (a->expect) return a->expect;
    if ((number || a->kind == PCL_INTEGER) && (a->flags & PCL_RANGE))
        return lua_pushfstring(L, "%s from %s to %s", number ? "a number" : "an integer",
                               pcl_pushnum(L, a->lo), pcl_pushnum(L, a->hi));
    if (number && (a->flags & (PCL_INF | PCL_POS)))
        return a->flags & PCL_INF ? "a number other than NaN" : "a positive number";
    if (a->kind == PCL_ENUM) return push_list(L, a->choices, "\"%s\"", ", ", " or ");
    if (a->kind == PCL_OPTIONS) {                       /* a table {k1 =, k2 =} */
        key_names(a->keys, names, 64);
        return lua_pushfstring(L, "a table {%s}", push_list(L, names, "%s =", ", ", ", "));
    }
    if (a->kind <= PCL_NONE || a->kind > PCL_ANY) return "a value";
    const char *dim = a->dim > 0 ? lua_pushfstring(L, "%d-D ", a->dim) : "";
    return lua_pushfstring(L, EXPECTED[a->kind], dim);
}

/* The dimension rule: a fixed dimension, or (PCL_SAMEDIM) the first located value's. */
static void check_dim(lua_State *L, const ctx *c, const pcl_arg *a, int idx, int n) {
    if (a->dim > 0 && n != a->dim) mismatch(L, c, idx, expected(L, a));
    if (!(a->flags & PCL_SAMEDIM) || !c->dim) return;
    if (c->dim->n == 0) {
        c->dim->n = n;
        c->dim->who = *c;
        c->dim->who.dim = NULL;
    } else if (n != c->dim->n) {
        const ctx *who = &c->dim->who;
        const char *other = who->item && who->shown == c->shown && who->key == c->key
                            ? lua_pushfstring(L, "[%d]", who->item) : where(L, who);   /* in one list */
        pcl_error(L, "%s: %s is %d-D, but %s is %d-D (mixed dimensions)", c->fname, where(L, c), n,
                  other, c->dim->n);
    }
}

/* A point, vector, location or value at idx into out->v (the weight rule). */
static void read_loc(lua_State *L, const ctx *c, const pcl_arg *a, int idx, pcl_val *out) {
    pcl_value *p = pcl_tovalue(L, idx);
    if (!p) mismatch(L, c, idx, expected(L, a));
    int n = p->n;
    check_dim(L, c, a, idx, n);
    out->n = n;
    memcpy(out->v, p->h, sizeof(double) * (size_t)(n + 1));
    if (a->kind == PCL_VALUE) return;
    static const char *const HINT[PC_KIND_WEIGHTED + 1] = {   /* given a point; given a vector */
        [PC_KIND_POINT] = "a vector has weight 0: a difference of points is a vector, e.g. B - A",
        [PC_KIND_VECTOR] = "a point has weight 1: to place a vector, add it to a point, "
                           "e.g. P(0, 0) + v"};
    int k = pc_snap_weight(n, out->v);
    int want = a->kind == PCL_POINT ? PC_KIND_POINT : a->kind == PCL_VECTOR ? PC_KIND_VECTOR : k;
    if (k == PC_KIND_WEIGHTED)
        mismatch_hint(L, c, idx, expected(L, a), lua_pushfstring(L, "its weight is %s, and a point "
                      "equation's coefficients sum to 1 for a point, 0 for a vector (the "
                      "membership condition)", pcl_pushnum(L, p->h[n])));
    if (k != want) mismatch_hint(L, c, idx, expected(L, a), HINT[k]);
    for (int i = 0; i < n; i++)
        if (!isfinite(out->v[i])) mismatch(L, c, idx, "a value with finite coordinates");
}

/* The fast path of the common kinds: a number or integer that fits its declaration is read
 * here with a type test and the range tests, no message made; anything else (absent, of
 * another kind, out of range) goes to read_value, which reads it or words the message.  Only
 * read_value (general) takes an infinite number for PCL_INF: the fast path tests isfinite alone. */
static inline int read_scalar(lua_State *L, const pcl_arg *a, int idx, pcl_val *out, int general) {
    if ((a->kind != PCL_NUMBER && a->kind != PCL_INTEGER) || lua_type(L, idx) != LUA_TNUMBER) return 0;
    double x = lua_tonumber(L, idx);
    if (!isfinite(x) && !(general && (a->flags & PCL_INF) && !isnan(x))) return 0;
    if (a->kind == PCL_INTEGER && x != floor(x)) return 0;
    if ((a->flags & PCL_RANGE) && !(x >= a->lo && x <= a->hi)) return 0;
    if ((a->flags & PCL_POS) && !(x > 0)) return 0;
    out->present = 1;
    out->x = x;
    out->idx = idx;
    out->n = 0;
    out->s = NULL;
    out->obj = NULL;
    return 1;
}

static double *list_buffer(lua_State *L, pcl_val *out, size_t need) {
    if (out->list && (size_t)out->cap >= need) return out->list;
    if (out->list) return NULL;                       /* a caller's buffer too small */
    return lua_newuserdatauv(L, sizeof(double) * (need ? need : 1), 0);   /* above the arguments */
}

static void count_error(lua_State *L, const ctx *c, const pcl_arg *a, int m, const char *unit) {
    int lo = (int)a->lo, hi = (int)a->hi;
    const char *count = hi <= 0 ? lua_pushfstring(L, "at least %d", lo)
                        : lo == hi ? lua_pushfstring(L, "%d", lo) : lua_pushfstring(L, "%d to %d", lo, hi);
    pcl_error(L, "%s: %s must hold %s %s, got %d", c->fname, where(L, c), count, unit, m);
}

/* A list of points or numbers at idx. */
static void read_list(lua_State *L, const ctx *c, const pcl_arg *a, int idx, pcl_val *out) {
    if (!lua_istable(L, idx)) mismatch(L, c, idx, expected(L, a));
    lua_len(L, idx);                       /* a __len may say anything: clamp before int */
    int isint;
    lua_Integer len = lua_tointegerx(L, -1, &isint);
    lua_pop(L, 1);
    if (!isint) mismatch(L, c, idx, expected(L, a));   /* not Lua's unlocated length error */
    int m = len < 0 ? -1 : len > MAXLIST ? MAXLIST + 1 : (int)len;
    int hi = a->hi > 0 ? (int)a->hi : MAXLIST;
    const char *unit = a->kind == PCL_NUMBERS ? "numbers" : a->kind == PCL_VECTORS ? "vectors" : "points";
    if (m < (int)a->lo || m > hi || m < 0) count_error(L, c, a, m, unit);
    out->n = m;
    /* each element as one value: a number, or a point, value or vector of the declared
     * dimension (vectors: or the one PCL_SAMEDIM knows, "[2] must be a 2-D vector"), else the
     * first one's for all; values keep their weights (rows of d + 1) */
    static const pcl_kind item_kind[] = {[PCL_POINTS] = PCL_POINT, [PCL_VALUES] = PCL_VALUE,
                                         [PCL_VECTORS] = PCL_VECTOR, [PCL_NUMBERS] = PCL_NUMBER};
    int numbers = a->kind == PCL_NUMBERS;
    int known = a->dim ? a->dim : a->kind == PCL_VECTORS && (a->flags & PCL_SAMEDIM) && c->dim ? c->dim->n : 0;
    pcl_arg pt = {.name = a->name, .kind = item_kind[a->kind], .dim = known,
                  .expect = a->kind == PCL_VALUES ? "a point" : numbers ? "a finite number" : NULL};
    ctx e = *c;
    dimref inner = {0};
    double *x = numbers ? list_buffer(L, out, (size_t)m) : NULL;
    int d = known, w = 1;
    for (int i = 1; i <= m; i++) {
        lua_geti(L, idx, i);
        int top = lua_gettop(L);
        e.item = i;
        if (!known && !numbers) pt.flags = PCL_SAMEDIM, e.dim = &inner;
        pcl_val one;
        if (numbers && !read_scalar(L, &pt, top, &one, 0)) mismatch(L, &e, top, pt.expect);
        if (numbers) one.v[0] = one.x;
        else read_loc(L, &e, &pt, top, &one);
        for (int j = 0; a->kind == PCL_VALUES && j <= one.n; j++)
            if (!isfinite(one.v[j])) mismatch(L, &e, top, "a value with finite coordinates");
        lua_pop(L, 1);
        if (i == 1 && !numbers) {
            d = one.n;
            w = d + (a->kind == PCL_VALUES);
            pcl_arg whole = *a;
            whole.dim = 0;                     /* the list's dimension against the others' */
            check_dim(L, c, &whole, idx, d);
            x = list_buffer(L, out, (size_t)m * (size_t)w);
        }
        if (!x) luaL_error(L, "%s: %d %s do not fit the binding's buffer", c->fname, m, unit);
        memcpy(x + (size_t)(i - 1) * w, one.v, sizeof(double) * (size_t)w);
    }
    if (!x) x = list_buffer(L, out, 1);
    out->list = x;
    if (!numbers) out->dim = d;
}

static const ctx *reading;   /* the value a binding's reader is reading (pcl_readfail) */

/* The kinds that are a Lua type. */
static const int LUA_TYPE_OF[] = {[PCL_BOOLEAN] = LUA_TBOOLEAN, [PCL_STRING] = LUA_TSTRING,
                                  [PCL_FUNCTION] = LUA_TFUNCTION, [PCL_TABLE] = LUA_TTABLE};

/* One value at idx as the argument (or option key) a describes. */
static void read_value(lua_State *L, const ctx *c, const pcl_arg *a, int idx, pcl_val *out) {
    int t = lua_type(L, idx);
    out->idx = c->key ? 0 : idx;
    out->present = t != LUA_TNIL && t != LUA_TNONE;
    out->x = a->dflt;
    out->n = a->kind == PCL_ENUM ? (int)a->dflt : 0;
    out->s = a->kind == PCL_ENUM ? a->choices[(int)a->dflt] : NULL;
    out->obj = NULL;
    if (!out->present) {
        int optional = c->key ? !(a->flags & PCL_REQ) : (a->flags & PCL_OPT) != 0;
        if (!optional) mismatch(L, c, idx, expected(L, a));
        return;
    }
    switch (a->kind) {
    case PCL_NUMBER: case PCL_INTEGER:
        if (!read_scalar(L, a, idx, out, 1)) break;
        out->idx = c->key ? 0 : idx;
        return;
    case PCL_BOOLEAN: case PCL_STRING: case PCL_FUNCTION: case PCL_TABLE: case PCL_CALLABLE:
        if (a->kind == PCL_CALLABLE ? !pcl_callable(L, idx) : t != LUA_TYPE_OF[a->kind]) break;
        if (a->kind == PCL_BOOLEAN) out->x = lua_toboolean(L, idx);
        if (a->kind == PCL_STRING) out->s = lua_tostring(L, idx);
        return;
    case PCL_ENUM:
        if (t == LUA_TSTRING)
            for (int i = 0; a->choices[i]; i++)
                if (!strcmp(lua_tostring(L, idx), a->choices[i])) {
                    out->n = i, out->s = a->choices[i];
                    return;
                }
        break;
    case PCL_POINT: case PCL_VECTOR: case PCL_LOC: case PCL_VALUE:
        read_loc(L, c, a, idx, out);
        return;
    case PCL_POINTS: case PCL_NUMBERS: case PCL_VALUES: case PCL_VECTORS:
        read_list(L, c, a, idx, out);
        return;
    case PCL_CURVE: case PCL_SURFACE: {
        pc_curve *cv = a->kind == PCL_CURVE ? pcl_tocurve(L, idx) : NULL;
        pc_surface *sf = a->kind == PCL_SURFACE ? pcl_tosurface(L, idx) : NULL;
        int dim = cv ? cv->dim : sf ? sf->dim : 0;
        if (!dim) break;
        if (a->dim && dim != a->dim)
            pcl_error(L, "%s: %s must be %s, got a %d-D one", c->fname, where(L, c), expected(L, a), dim);
        check_dim(L, c, a, idx, dim);
        out->obj = cv ? (void *)cv : (void *)sf;
        out->n = dim;
        return;
    }
    case PCL_MAP:
        if (!(out->obj = pcl_tomap(L, idx))) break;
        return;
    case PCL_ANY: {
        const ctx *outer = reading;
        reading = c;                            /* for pcl_readfail */
        int ok = !a->read || a->read(L, idx, a, out);
        reading = outer;
        if (!ok) break;
        return;
    }
    default:
        luaL_error(L, "%s: an option table inside an option table is not supported", c->fname);
    }
    mismatch(L, c, idx, expected(L, a));   /* a case that breaks: not of its kind */
}

/* Every key of the option table at idx must be one of known (nk of them): else "unknown option". */
static void check_keys(lua_State *L, const ctx *c, int idx, const char *const *known, int nk) {
    lua_pushnil(L);
    while (lua_next(L, idx)) {
        lua_pop(L, 1);
        if (lua_type(L, -1) != LUA_TSTRING)
            pcl_error(L, "%s: %s holds [%s]; its options are named (key = value)", c->fname, where(L, c),
                      pcl_shown(L, lua_gettop(L)));
        const char *key = lua_tostring(L, -1);
        int found = 0;
        for (int k = 0; k < nk && !found; k++)   /* colour = is the docs' spelling of color = */
            found = !strcmp(key, known[k]) || (!strcmp(key, "colour") && !strcmp(known[k], "color"));
        if (found) continue;
        const char *near = pc_nearest_name(key, known);
        if (near) pcl_error(L, "%s: unknown option '%s' (did you mean '%s'?)", c->fname, key, near);
        pcl_error(L, "%s: unknown option '%s' (the options are %s)", c->fname, key,
                  push_list(L, known, "%s", ", ", ", "));
    }
}

/* The keys of an options table at idx into v (one per key); unknown keys are errors.  Absent
 * (nil, when optional), each key takes its default and a required one fails. */
static void read_options(lua_State *L, ctx *c, const pcl_arg *a, int idx, pcl_val *v) {
    const char *known[64];
    int nk = key_names(a->keys, known, 64), table = lua_istable(L, idx);
    if (!table && (!lua_isnoneornil(L, idx) || !(a->flags & PCL_OPT))) mismatch(L, c, idx, expected(L, a));
    if (table) check_keys(L, c, idx, known, nk);
    for (int k = 0; k < nk; k++) {
        ctx kc = *c;
        kc.key = known[k];
        int t = table ? lua_getfield(L, idx, kc.key) : LUA_TNIL;
        if (!table) lua_pushnil(L);
        if (table && !strcmp(kc.key, "color")) {      /* colour = is the same option */
            int given = lua_getfield(L, idx, "colour") != LUA_TNIL;
            if (given && t != LUA_TNIL)
                pcl_error(L, "%s: options 'color' and 'colour' are one option: give one", c->fname);
            if (given) kc.key = "colour";
            lua_remove(L, given ? -2 : -1);
        }
        int top = lua_gettop(L);
        read_value(L, &kc, &a->keys[k], top, &v[k]);
        lua_remove(L, top);   /* the value lives on in the table; a list's buffer stays above */
    }
}

/* The running declaration, whose values must fit the caller's n. */
static const pcl_decl *counted_box(lua_State *L, int n) {
    const pcl_decl *b = pcl_running(L);
    if (n < b->nvalues) luaL_error(L, "%s: the binding reads %d values into %d", b->d->name, b->nvalues, n);
    return b;
}

/* The declared arguments from stack slot first on into v, argument k + 1 shown as #k + 1;
 * pairs: pcl_read_pairs (pcl_args.h). */
static inline __attribute__((always_inline))   /* one copy per reader: pairs a constant */
void read_args(lua_State *L, const pcl_decl *b, pcl_val *v, int first, int pairs) {
    const pcl_fn *d = b->d;
    int nargs = b->nargs, top = lua_gettop(L), opts = 0;
    if (pairs && nargs && d->args[nargs - 1].kind == PCL_OPTIONS && top > b->first_pair && lua_istable(L, top))
        opts = top;                             /* a trailing option table */
    int limit = opts ? opts - 1 : top, keys = nargs, room = 0, y = 0;
    const char *fname = NULL;
    dimref dim = {0};
    for (int k = 0, slot = first; k < nargs; k++, slot++) {
        const pcl_arg *a = &d->args[k];
        int given = !pairs || slot <= limit;    /* pcl_read made room for every argument */
        int idx = given ? slot : lua_gettop(L) + 1;   /* beyond the values: none */
        if (given && read_scalar(L, a, idx, &v[k], 0)) {
            y = (a->flags & PCL_PAIR) != 0;
            continue;
        }
        if (!fname) fname = d->callname ? pcl_name(L) : d->name;   /* the general reader */
        if (a->kind != PCL_ANY && !room) {   /* lists and options push; a reader pushes little */
            luaL_checkstack(L, 24, NULL);
            room = 1;
        }
        if (a->kind == PCL_OPTIONS) {
            int at = pairs ? opts : idx;
            ctx c = {fname, (at ? at : idx) - first + 1, a->name, NULL, 0, &dim};
            v[k].idx = at;
            v[k].present = at && lua_istable(L, at);
            read_options(L, &c, a, at ? at : idx, v + keys);
            for (const pcl_arg *kk = a->keys; kk->name; kk++) keys++;
            continue;
        }
        if (pairs && (a->flags & PCL_PAIR) && k + 1 < nargs && slot <= limit &&
            lua_type(L, idx) != LUA_TNUMBER && pcl_tovalue(L, idx)) {
            pcl_topoint2(L, idx, &v[k].x, &v[k + 1].x);   /* one point: the pair in one slot */
            v[k].present = v[k + 1].present = 1;
            v[k].idx = v[k + 1].idx = idx;
            k++;
            continue;
        }
        int coord = pairs && ((a->flags & PCL_PAIR) || y);
        y = (a->flags & PCL_PAIR) != 0;         /* the next argument is this pair's y */
        pcl_arg one;
        if (coord && lua_type(L, idx) != LUA_TNUMBER) {
            one = *a;
            one.expect = "a number or a point";
            a = &one;
        }
        ctx c = {fname, slot - first + 1, a->name, NULL, 0, &dim};
        read_value(L, &c, a, idx, &v[k]);
    }
}

/* The receiver of a method (checked), then the declared arguments into v. */
static void *read_self(lua_State *L, const pcl_decl *b, pcl_val *v) {
    const pcl_fn *d = b->d;
    void *self = d->self ? d->self(L, 1) : NULL;
    if (d->self && !self)
        pcl_error(L, "%s: must be called on %s %s, as %s(...)", d->name,
                  strchr("aeiou", d->selftype[0]) ? "an" : "a", d->selftype, d->topic ? d->topic : d->name);
    int first = self ? 2 : 1;
    if (lua_gettop(L) < first - 1 + b->nargs) lua_settop(L, first - 1 + b->nargs);   /* buffers above */
    read_args(L, b, v, first, 0);
    return self;
}

void *pcl_read(lua_State *L, pcl_val *v, int n) { return read_self(L, counted_box(L, n), v); }

int pcl_nvalues(lua_State *L) {
    int n = pcl_running(L)->nvalues;
    return n > 0 ? n : 1;
}

void *pcl_read_decl(lua_State *L, const pcl_decl *b, pcl_val *v) {
    memset(v, 0, sizeof *v * (size_t)b->nvalues);
    pcl_callback_state(L);
    return read_self(L, b, v);
}

void pcl_readone(lua_State *L, int idx, int shown, int item, const pcl_arg *a, int dimdef, pcl_val *out) {
    const char *name = a->name ? a->name : arg_name(L, shown);
    dimref dim = {dimdef, {pcl_name(L), item ? shown : 1, item ? name : NULL, NULL, item ? 1 : 0, NULL}};
    ctx c = {dim.who.fname, shown, name, NULL, item, &dim};
    read_value(L, &c, a, idx, out);
}

int pcl_readfail(lua_State *L, int idx, const char *expected) {
    const ctx *c = reading;
    reading = NULL;
    if (!c) return pcl_fail(L, "must be %s, got %s", expected, shown(L, idx));
    return mismatch(L, c, idx, expected);
}

void pcl_read_options(lua_State *L, int idx, int shown, const pcl_arg *a, pcl_val *v) {
    ctx c = {pcl_name(L), shown, a->name, NULL, 0, NULL};
    read_options(L, &c, a, lua_absindex(L, idx), v);
}

void pcl_read_pairs(lua_State *L, pcl_val *v, int n) {
    const pcl_decl *b = counted_box(L, n);
    memset(v, 0, sizeof *v * (size_t)n);   /* the caller's array need not be zeroed (pcl_args.h) */
    read_args(L, b, v, 1, 1);
}

/* ---- registration and signatures ----------------------------------------------------------- */

/* The text of one argument in a signature: its name, an enum's choices, an option table's keys. */
static void add_arg(luaL_Buffer *b, lua_State *L, const pcl_arg *a) {
    if (a->kind != PCL_OPTIONS) {
        if (a->kind == PCL_ENUM) push_list(L, a->choices, "\"%s\"", "|", "|");
        else lua_pushstring(L, a->name);
        luaL_addvalue(b);
        return;
    }
    luaL_addchar(b, '{');
    for (const pcl_arg *k = a->keys; k->name; k++) {
        lua_pushfstring(L, "%s%s =%s", k == a->keys ? "" : ", ", k->name, k->kind == PCL_ENUM || k->shown ? " " : "");
        luaL_addvalue(b);
        if (k->kind == PCL_ENUM) add_arg(b, L, k);
        else if (k->shown) luaL_addstring(b, k->shown);
    }
    luaL_addchar(b, '}');
}

/* Push the signature made from the declaration: NAME(a, b [, c [, d]]) -> RESULT. */
static void push_signature(lua_State *L, const pcl_fn *d) {
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    luaL_addstring(&b, d->name);
    const pcl_arg *a = d->args;
    int calltable = a && a->kind == PCL_OPTIONS && (a->flags & PCL_CALLTABLE), open = 0;
    if (!calltable) luaL_addchar(&b, '(');
    for (int k = 0; a && a->kind; a++, k++) {
        int opt = !calltable && (a->flags & PCL_OPT);
        luaL_addstring(&b, opt ? (k ? " [, " : "[") : k ? ", " : "");
        open += opt;
        add_arg(&b, L, a);
    }
    while (open--) luaL_addchar(&b, ']');
    if (!calltable) luaL_addchar(&b, ')');
    luaL_addstring(&b, d->result ? " -> " : "");
    luaL_addstring(&b, d->result ? d->result : "");
    luaL_pushresult(&b);
}

static void record(lua_State *L, const pcl_fn *d) {
    luaL_getsubtable(L, LUA_REGISTRYINDEX, PCL_DECL_KEY);
    lua_createtable(L, 0, 3);
    if (d->sig) lua_newtable(L);                     /* forms, one per line */
    else push_signature(L, d);
    for (const char *s = d->sig; s && *s;) {
        size_t len = strcspn(s, "\n");
        lua_pushlstring(L, s, len);
        lua_rawseti(L, -2, (lua_Integer)lua_rawlen(L, -2) + 1);
        s += len + (s[len] == '\n');
    }
    lua_setfield(L, -2, "sig");
    lua_pushstring(L, d->help ? d->help : "");
    lua_setfield(L, -2, "desc");
    lua_setfield(L, -2, d->topic ? d->topic : d->name);
    lua_pop(L, 1);
}

void pcl_pushfn(lua_State *L, const pcl_fn *d, int nup) {
    pcl_decl *b = lua_newuserdatauv(L, sizeof *b, 0);
    *b = (pcl_decl){.self = PCL_SELF_TAG(b, &BOX_TAG), .d = d};
    for (const pcl_arg *a = d->args; a && a->kind; a++) {
        b->nargs++;
        b->nvalues++;                        /* one value, and one per key of an option table */
        for (const pcl_arg *k = a->kind == PCL_OPTIONS ? a->keys : NULL; k && k->name; k++) b->nvalues++;
        if ((a->flags & PCL_PAIR) && !b->first_pair) b->first_pair = b->nargs;
    }
    if (luaL_newmetatable(L, BOX_MT)) {      /* getmetatable(d) says "declaration" and no more */
        lua_pushliteral(L, "declaration");
        lua_setfield(L, -2, "__metatable");
    }
    lua_setmetatable(L, -2);
    lua_insert(L, -1 - nup);                 /* the declaration is upvalue 1 */
    lua_pushcclosure(L, d->fn, nup + 1);
}

static void register_all(lua_State *L, int table, const pcl_fn *fns, int nup, int documented) {
    table = lua_absindex(L, table);
    int ups = lua_gettop(L) - nup + 1;
    for (const pcl_fn *d = fns; d->name; d++) {
        const char *key = d->key ? d->key : d->name;    /* else the name's last part */
        for (const char *p = key; !d->key && (p = strpbrk(p, ".:")); ) key = ++p;
        for (int i = 0; i < nup; i++) lua_pushvalue(L, ups + i);
        pcl_pushfn(L, d, nup);
        lua_setfield(L, table, key);
        if (documented) record(L, d);
    }
    lua_pop(L, nup);
}

void pcl_register(lua_State *L, int table, const pcl_fn *fns, int nup) { register_all(L, table, fns, nup, 1); }
void pcl_register_private(lua_State *L, int table, const pcl_fn *fns) { register_all(L, table, fns, 0, 0); }

void pcl_open_type(lua_State *L, const char *tname, const luaL_Reg *meta, const pcl_fn *call,
                   const pcl_fn *methods, lua_CFunction index) {
    luaL_newmetatable(L, tname);
    if (meta) luaL_setfuncs(L, meta, 0);
    if (call) pcl_register(L, -1, call, 0);
    if (!methods && !index) return;
    lua_newtable(L);
    if (methods) pcl_register(L, -1, methods, 0);
    if (index) lua_pushcclosure(L, index, 1);
    lua_setfield(L, -2, "__index");
}

void pcl_new_table(lua_State *L, int module, const char *name, const pcl_fn *fns, const pcl_fn *call) {
    module = lua_absindex(L, module);
    lua_newtable(L);
    pcl_register(L, -1, fns, 0);
    if (call) {
        lua_newtable(L);
        pcl_register(L, -1, call, 0);
        lua_setmetatable(L, -2);
    }
    lua_setfield(L, module, name);
}

/* ---- misspelt globals ----------------------------------------------------------------------- */

/* One place for scripts, -e chunks and the REPL; NULL: nothing pushed. */
const char *pcl_global_hint(lua_State *L, const char *msg) {
    const char *p = msg ? strstr(msg, "a nil value (global '") : NULL;
    if (!p) return NULL;
    p += strlen("a nil value (global '");
    const char *e = strchr(p, '\'');
    if (!e || e - p > 40) return NULL;
    lua_pushglobaltable(L);
    const char *best = pcl_nearest_key(L, lua_pushlstring(L, p, (size_t)(e - p)), -2);
    const char *h = best ? lua_pushfstring(L, "(did you mean '%s'?)", best) : NULL;
    lua_rotate(L, -2 - (h != NULL), h != NULL);   /* the hint (if any) below the table and name */
    lua_pop(L, 2);
    return h;
}
