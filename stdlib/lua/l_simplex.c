/* Binding of simplices (stdlib/geom/simplex.h): simplex(C, A, B, ...), S(p, q), its methods, S[i]
 * (vertex i, 1 the initial point) and #S (the number of vertices). */
#include "pcl_args.h"
#include "pcl_point.h"
#include "pcl_core.h"
#include "simplex.h"

static const char REGKEY[] = "pointcalc.simplex";   /* the metatable in the registry */

/* A genuine simplex's block is exactly pc_simplex_size(n, k) (pcl.h: forged userdata). */
static void *tosimplex(lua_State *L, int idx) {
    pc_simplex *s = luaL_testudata(L, idx, REGKEY);
    size_t len = s ? lua_rawlen(L, idx) : 0;
    int ok = s && len >= sizeof(pc_simplex) && s->n >= 1 && s->n <= PC_MAXDIM && s->k >= 1 &&
             s->k <= s->n && len == pc_simplex_size(s->n, s->k);
    return pcl_genuine(L, idx, s, ok, "simplex");
}

/* simplex(C, A, B, ...): the vertices after C are read one by one in C's dimension */
static const pcl_arg simplex_args[] = {A_SAMEPOINT("C"), A_SAMEPOINT("A"), PCL_END};

PCL_BODY(l_simplex, a) {
    int m = lua_gettop(L), k = m - 1, n = a[0].n;
    double v[(PC_MAXDIM + 1) * PC_MAXDIM];
    char msg[160];
    if (k > n && pc_simplex_init_text(PC_EDIM, n, k, NULL, msg, sizeof msg)) return pcl_fail(L, "%s", msg);
    static const pcl_arg vertex = {.kind = PCL_POINT, .flags = PCL_SAMEDIM};
    for (int i = 1; i <= m; i++) {
        pcl_val p = i < 3 ? a[i - 1] : (pcl_val){0};
        if (i > 2) pcl_readone(L, i, i, 0, &vertex, n, &p);
        memcpy(v + (i - 1) * n, p.v, sizeof(double) * (size_t)n);
    }
    pc_simplex *s = lua_newuserdatauv(L, pc_simplex_size(n, k), 0);
    int st = pc_simplex_init(s, n, k, v);
    if (st != PC_OK && pc_simplex_init_text(st, n, k, v, msg, sizeof msg)) return pcl_fail(L, "%s", msg);
    luaL_setmetatable(L, REGKEY);
    return 1;
}

/* S(p, q, ...): the point by its natural parameters.  One more number may follow and is
 * ignored, so that S(S:params(M)) works (params returns the residual last); with
 * coefficients summing to 1 it is also the initial point's barycentric coefficient, which
 * the natural parameters already imply.  S:bary(p, q, ..., r), the same body: coefficients
 * of vertices 2..k+1, then of the initial point. */
PCL_METHOD(l_call, pc_simplex *s, a) {
    int m = lua_gettop(L) - 1, k = s->k, bary = !strcmp(pcl_running(L)->d->name, "S:bary");
    if (bary && m != k + 1) return pcl_fail(L, "a %d-simplex takes %d barycentric parameters, got %d", k, k + 1, m);
    if (!bary && m != k && m != k + 1)
        return pcl_fail(L, "a %d-simplex takes %d natural parameters, got %d (for barycentric parameters use S:bary)", k, k, m);
    double p[PC_MAXDIM + 1];
    for (int i = 0; i < m; i++) {
        p[i] = lua_tonumber(L, i + 2);
        if (lua_type(L, i + 2) == LUA_TNUMBER && isfinite(p[i])) continue;
        char what[24];                              /* the label only on the error path */
        snprintf(what, sizeof what, "parameter %d", i + 1);
        pcl_arg num = {.kind = PCL_NUMBER, .name = bary ? NULL : what};
        pcl_val v;
        pcl_readone(L, i + 2, i + 1, 0, &num, 0, &v);   /* the message */
    }
    pcl_value *r = pcl_newvalue(L, s->n);
    r->h[s->n] = 1.0;                               /* S(p, q): a point; bary writes its weight */
    if (bary) pc_simplex_bary(s, p, r->h);
    else pc_simplex_eval(s, p, r->h);
    return 1;
}

static const pcl_arg params_args[] = {A_POINT("M", 0), PCL_END};

PCL_METHOD(l_params, pc_simplex *s, a) {
    double p[PC_MAXDIM + 1];   /* the parameters, then the residual */
    if (a[0].n != s->n)
        return pcl_fail(L, "argument #1 (M) is %d-D, but the simplex is in %d-D: dimensions cannot be mixed", a[0].n, s->n);
    pc_simplex_params(s, a[0].v, p, &p[s->k]);
    return pcl_push_packed(L, s->k + 1, "x", p);   /* k + 1 <= LUA_MINSTACK */
}

PCL_METHOD(l_measure, pc_simplex *s, a) {
    return pcl_push_results(L, 0, "n", pc_simplex_measure(s));
}

PCL_METHOD(l_ratio, pc_simplex *s, a) {
    int k = s->k, n = s->n, m = lua_gettop(L) - 1;
    if (m != k + 1) return pcl_fail(L, "a %d-simplex compares with %d points, got %d", k, k + 1, m);
    double pts[(PC_MAXDIM + 1) * PC_MAXDIM], res;
    static const pcl_arg pt = {.kind = PCL_POINT};
    for (int i = 0; i <= k; i++) {
        pcl_val v;
        pcl_readone(L, i + 2, i + 1, 0, &pt, 0, &v);
        if (v.n != n) return pcl_fail(L, "argument #%d is %d-D, but the simplex is in %d-D: dimensions cannot be mixed", i + 1, v.n, n);
        memcpy(pts + i * n, v.v, sizeof(double) * (size_t)n);
    }
    double ratio = pc_simplex_ratio(s, pts, &res);
    return pcl_push_results(L, 0, "n n", ratio, res);
}

static int l_index(lua_State *L) {
    pc_simplex *s = pcl_meta_self(L, tosimplex(L, 1), "index: not a simplex");
    lua_Integer i = lua_type(L, 2) == LUA_TNUMBER ? lua_tointeger(L, 2) : 0;   /* 0: not integral */
    if (i >= 1 && i <= s->k + 1) pcl_pushpoint(L, s->n, PC_SIMPLEX_V(s) + (i - 1) * s->n);
    else lua_rawget(L, lua_upvalueindex(1));                /* a method, or nil: key on the top */
    return 1;
}

static int l_len(lua_State *L) {
    pc_simplex *s = pcl_meta_self(L, tosimplex(L, 1), "#: not a simplex");
    return pcl_push_results(L, 0, "i", s->k + 1);
}

static int l_tostring(lua_State *L) {
    pc_simplex *s = pcl_meta_self(L, tosimplex(L, 1), "tostring: not a simplex");
    char buf[(PC_MAXDIM + 1) * (PC_MAXDIM * 24 + 40)];
    pc_simplex_text(s, buf, sizeof buf);
    return pcl_push_results(L, 0, "s", buf);
}

#define METHOD(nm, f, a, forms, text) {.name = nm, .fn = f, .args = a, .sig = forms, .help = text, \
                                      .self = tosimplex, .selftype = "simplex"}
static const pcl_fn methods[] = {
    METHOD("S:bary", l_call, NULL, "S:bary(p, q, ..., r) -> value", "Ap + Bq + ... + Cr: barycentric coefficients, the initial point's last (weighted when they do not sum to 1)."),
    METHOD("S:params", l_params, params_args, "S:params(M) -> p, q, ..., residual", "The natural parameters of M (least squares off the simplex's flat) and M's distance from that flat."),
    METHOD("S:measure", l_measure, NULL, "S:measure() -> number", "Length, area, volume...: signed when the simplex is full-dimensional."),
    METHOD("S:ratio", l_ratio, NULL, "S:ratio(P1, P2, ...) -> ratio, residual", "The S-/V-theorem: the signed ratio of the measure of P1P2... to the simplex's own."),
    PCL_END};
static const pcl_fn call[] = {{.name = "S", .fn = l_call, .self = tosimplex, .selftype = "simplex", .key = "__call",
                               .topic = "S(p, q)", .callname = 1, .sig = "S(p, q, ...) -> point", .help = "The point of simplex S with natural parameters p, q, ..."}, PCL_END};
static const pcl_fn ctor[] = {{.name = "simplex", .fn = l_simplex, .args = simplex_args, .sig = "simplex(C, A, B, ...) -> S", .help = "A simplex with initial point C (the book's simplex CAB): S(p, q) = (A - C)p + (B - C)q + C."}, PCL_END};

void pcl_open_simplex(lua_State *L) {
    int module = lua_gettop(L);
    static const luaL_Reg meta[] = {{"__len", l_len}, {"__tostring", l_tostring}, {NULL, NULL}};
    pcl_open_type(L, REGKEY, meta, call, methods, l_index);
    lua_pushliteral(L, "simplex");
    lua_setfield(L, -2, "__metatable");
    pcl_register(L, module, ctor, 0);
    lua_settop(L, module);
}
