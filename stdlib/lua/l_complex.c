/* Complex numbers and the Moebius map of the unit disc (examples 15, 16): the arithmetic is the
 * core's pc_cnum_arith and pc_cnum_fn (stdlib/geom/cnum.h), the Moebius map its pc_mobius. */
#include "pcl_args.h"
#include "pcl_tk.h"
#include "pcl_tagged.h"
#include "pcl_core.h"
#include "curvilinear.h"
#include "cnum.h"

#define COMPLEX_MT "complex"
#define MOBIUS_MT "mobius"
static const char COMPLEX_TAG = 'z', MOBIUS_TAG = 'm';   /* PCL_SELF_TAG */

/* self: a file handle has the size of two doubles, so the size alone does not tell (pcl.h) */
typedef struct { PCL_SELF; pc_cnum z; } cnum;
typedef struct { PCL_SELF; pc_cnum z0; double phi; } mobius;

/* The userdata of type tname at idx or NULL; one given the metatable by the debug library has
 * another size or self and is refused (pcl.h: forged userdata). */
static void *totagged(lua_State *L, int idx, const char *tname, size_t size, const char *tag, const char *type) {
    uintptr_t *p = luaL_testudata(L, idx, tname);
    return pcl_genuine(L, idx, p, !p || (lua_rawlen(L, idx) == size && *p == PCL_SELF_TAG(p, tag)), type);
}

static void *tocnum(lua_State *L, int idx) {
    return totagged(L, idx, COMPLEX_MT, sizeof(cnum), &COMPLEX_TAG, "complex number");
}

static void *tomobius(lua_State *L, int idx) {
    return totagged(L, idx, MOBIUS_MT, sizeof(mobius), &MOBIUS_TAG, "Moebius map");
}

/* a new complex number on the stack top: its value unset (newc), or w (pushc: 1, the count) */
static cnum *newc(lua_State *L) { return pcl_tagged_new(L, sizeof(cnum), &COMPLEX_TAG, COMPLEX_MT); }
static int pushc(lua_State *L, pc_cnum w) {
    newc(L)->z = w;
    return 1;
}

/* a complex operand: a complex or a real number (not checked for finiteness) */
static int toc(lua_State *L, int idx, pc_cnum *z) {
    cnum *c = tocnum(L, idx);
    if (c) *z = c->z;
    else if (lua_type(L, idx) == LUA_TNUMBER) *z = (pc_cnum){lua_tonumber(L, idx), 0.0};
    return c || lua_type(L, idx) == LUA_TNUMBER;
}

/* The declared kinds "a complex number or number", re, im into v[0], v[1]: one that is not
 * finite is refused as "a finite number". */
static int read_c(lua_State *L, int idx, PCL_UNUSED const pcl_arg *a, pcl_val *out) {
    pc_cnum z = {0, 0};
    if (!toc(L, idx, &z)) return 0;
    if (!isfinite(z.re) || !isfinite(z.im)) return pcl_readfail(L, idx, "a finite number");
    out->v[0] = z.re, out->v[1] = z.im;
    return 1;
}
#define A_COMPLEX(nm) A_ANY(nm, read_c, "a finite complex number or number")
static pc_cnum cval(const pcl_val *v) { return (pc_cnum){v->v[0], v->v[1]}; }

/* ---- the operators: metamethods, declared for their messages ("complex +: argument #2 ...");
 * one body, the operator the last character of the declared name, the unary minus its key's
 * (Lua calls __unm with (z, z)) */
PCL_BODY(c_arith, a) {
    const pcl_fn *d = pcl_running(L)->d;
    char op = strcmp(d->key, "__unm") ? d->name[strlen(d->name) - 1] : 'u';
    int st = pc_cnum_arith(op, cval(&a[0]), cval(&a[1]), &newc(L)->z);
    if (st == PC_EPOLE)
        return pcl_fail(L, "division by zero%s", op == '^' ? " (zero to a power whose real part is not positive)" : "");
    return st == PC_OK ? 1 : pcl_fail(L, "the result overflows (not finite)");
}

static int c_eq(lua_State *L) {
    pc_cnum a = {0, 0}, b = {0, 0};
    return pcl_push_results(L, 0, "b", toc(L, 1, &a) && toc(L, 2, &b) && a.re == b.re && a.im == b.im);
}

static int c_tostring(lua_State *L) {
    cnum *z = pcl_meta_self(L, tocnum(L, 1), "tostring: not a complex number");
    const char *re = pcl_pushnum(L, z->z.re), *im = pcl_pushnum(L, z->z.im);
    lua_pushfstring(L, "complex(%s, %s)", re, im);
    return 1;
}

/* ---- complex.f(z) and z:f(): one body, the value an argument or the receiver, the function
 * the last part of the declared name (conj, abs, arg, exp: pc_cnum_fn's c, a, g, e; point) */
PCL_METHOD(c_fn, cnum *z, a) {
    const char *name = pcl_running(L)->d->name, *f = name + strcspn(name, ".:") + 1;
    char op = strcmp(f, "arg") ? f[0] : 'g';
    pc_cnum w, in = z ? z->z : cval(&a[0]);
    if (op == 'p') return pcl_push_results(L, 2, "p", (double[]){in.re, in.im});
    if (pc_cnum_fn(op, in, &w) != PC_OK) return pcl_fail(L, "the result overflows (not finite)");
    if (op == 'a' || op == 'g') return pcl_push_results(L, 0, "n", w.re);
    return pushc(L, w);
}

/* __index of both types: z.re, z.im, M.z0, M.phi, then the type's methods (upvalue 1) */
static int l_index(lua_State *L) {
    cnum *z = tocnum(L, 1);
    mobius *m = z ? NULL : tomobius(L, 1);
    const char *k = lua_tostring(L, 2);
    if (!(z || m) || !k) return 0;
    if (z && (!strcmp(k, "re") || !strcmp(k, "im"))) lua_pushnumber(L, k[0] == 'r' ? z->z.re : z->z.im);
    else if (m && !strcmp(k, "z0")) pushc(L, m->z0);
    else if (m && !strcmp(k, "phi")) lua_pushnumber(L, m->phi);
    else lua_getfield(L, lua_upvalueindex(1), k);
    return 1;
}

/* complex(re [, im]), complex(P) or complex(z): the __call of the table complex */
static const pcl_arg new_args[] = {{.name = "re", .kind = PCL_NUMBER, .expect = "a finite number or a 2-D point"},
                                   A_NUMOPT("im", 0, NULL), PCL_END};
static const pcl_arg point_arg = A_POINT("P", 2);

static int c_new(lua_State *L) {
    cnum *z = tocnum(L, 2);
    pcl_val a[2] = {0};
    int point = pcl_tovalue(L, 2) != NULL;
    if (point) pcl_readone(L, 2, 1, 0, &point_arg, 0, &a[0]);
    else if (!z) PCL_READ(L, a);
    return pushc(L, z ? z->z : point ? cval(&a[0]) : (pc_cnum){a[0].x, a[1].x});
}

static const pcl_arg polar_args[] = {A_NUM("r"), A_NUM("u"), PCL_END};
PCL_BODY(c_polar, a) {
    return pushc(L, (pc_cnum){a[0].x * cos(a[1].x), a[0].x * sin(a[1].x)});
}

/* ---- Moebius ------------------------------------------------------------------------------- */

/* M(z), M(x, y), M(P): the form follows the arguments */
static const pcl_arg m_args[] = {A_ANY("z", read_c, "a complex number, a 2-D point or x, y"), PCL_END};
static const pcl_arg coord_x = A_NUM("x"), coord_y = A_NUM("y");

static int m_call(lua_State *L) {
    pcl_val a[2] = {0};
    mobius *m = tomobius(L, 1);      /* a __call; called on another value: the layer's message */
    int xy = lua_type(L, 2) == LUA_TNUMBER && !lua_isnoneornil(L, 3), point = !xy && pcl_tovalue(L, 2);
    if (!m || !(xy || point)) m = PCL_READ(L, a);
    if (xy || point) pcl_readone(L, 2, 1, 0, xy ? &coord_x : &point_arg, 0, &a[0]);
    if (xy) pcl_readone(L, 3, 2, 0, &coord_y, 0, &a[1]);
    double re = xy ? a[0].x : a[0].v[0], im = xy ? a[1].x : a[0].v[1];
    pc_cnum w;
    int st = pc_mobius(m->z0.re, m->z0.im, m->phi, re, im, &w.re, &w.im);
    if (st == PC_EPOLE)
        return pcl_fail(L, "z = complex(%s, %s) is the pole 1/conj(z0) of the map", pcl_pushnum(L, re),
                        pcl_pushnum(L, im));
    if (st != PC_OK) return pcl_fail(L, "%s", pc_strerror(st));
    if (xy || point) return pcl_push_results(L, 2, xy ? "x" : "p", (double[]){w.re, w.im});
    return pushc(L, w);
}

/* a new Moebius map on the stack top, its fields unset */
static mobius *newm(lua_State *L) { return pcl_tagged_new(L, sizeof(mobius), &MOBIUS_TAG, MOBIUS_MT); }

static int m_inverse(lua_State *L) {
    mobius *m = pcl_read(L, NULL, 0), *r = newm(L);
    pc_mobius_inverse(m->z0.re, m->z0.im, m->phi, &r->z0.re, &r->z0.im, &r->phi);
    return 1;
}

static int m_tostring(lua_State *L) {
    mobius *m = pcl_meta_self(L, tomobius(L, 1), "tostring: not a Moebius map");
    const char *re = pcl_pushnum(L, m->z0.re), *im = pcl_pushnum(L, m->z0.im), *phi = pcl_pushnum(L, m->phi);
    lua_pushfstring(L, "mobius(complex(%s, %s), %s)", re, im, phi);
    return 1;
}

static const pcl_arg mobius_args[] = {A_COMPLEX("z0"), A_NUMOPT("phi", 0, NULL), PCL_END};
PCL_BODY(l_mobius, a) {
    if (hypot(a[0].v[0], a[0].v[1]) >= 1)
        return pcl_argfail(L, 1, "must be a point inside the unit disc (|z0| < 1), got %s", luaL_tolstring(L, 1, NULL));
    mobius *m = newm(L);
    *m = (mobius){m->self, cval(&a[0]), a[1].x};
    return 1;
}

static const pcl_arg z_arg[] = {A_COMPLEX("z"), PCL_END};
#define ZMETHOD(nm, res, text) {.name = nm, .fn = c_fn, .result = res, .help = text, .self = tocnum, .selftype = "complex number"}
static const pcl_fn zmethods[] = {
    ZMETHOD("z:conj", "z", "The complex conjugate re - i im."), ZMETHOD("z:abs", "number", "The modulus |z|."),
    ZMETHOD("z:arg", "number", "The argument of z: atan2(im, re), in radians."), ZMETHOD("z:exp", "z", "The complex exponential e^z."),
    ZMETHOD("z:point", "P", "The 2-D point (re, im) of the complex plane."), PCL_END};
#define A_OPERAND(nm) A_ANY(nm, read_c, "a complex number or a number")
static const pcl_arg operands[] = {A_OPERAND("left"), A_OPERAND("right"), PCL_END};
#define OPERATOR(op, mm) {.name = "complex " op, .fn = c_arith, .args = operands, .key = mm}
static const pcl_fn operators[] = {OPERATOR("+", "__add"), OPERATOR("-", "__sub"), OPERATOR("*", "__mul"),
                                   OPERATOR("/", "__div"), OPERATOR("^", "__pow"), OPERATOR("-", "__unm"), PCL_END};
static const pcl_fn cfns[] = {
    PCL_FN("complex.polar", c_polar, polar_args, "z", "The complex number r e^(iu)."),
    PCL_FN("complex.exp", c_fn, z_arg, "z", "The complex exponential."),
    PCL_FN("complex.abs", c_fn, z_arg, "number", "The modulus |z|."),
    PCL_FN("complex.arg", c_fn, z_arg, "number", "The argument of z: atan2(im, re), in radians."),
    PCL_FN("complex.conj", c_fn, z_arg, "z", "The complex conjugate."), PCL_END};
static const pcl_fn cnew[] = {{.name = "complex", .fn = c_new, .args = new_args, .self = pcl_self_table, .selftype = "table", .key = "__call",
                               .sig = "complex(re [, im]) | complex(P) -> z", .help = "A complex number (from a 2-D point, x + iy); + - * / ^ mix with numbers; z.re, z.im, z:conj(), z:abs(), z:arg(), z:exp(), z:point()."}, PCL_END};
static const pcl_fn mfns[] = {PCL_FN("mobius", l_mobius, mobius_args, "M", "The Moebius automorphism w = e^(i phi)(z - z0)/(1 - conj(z0) z) of the unit disc (examples 15, 16): M(z), M(x, y), M(P), M:inverse()."), PCL_END};
static const pcl_fn mcall[] = {{.name = "M", .fn = m_call, .args = m_args, .self = tomobius, .selftype = "Moebius map", .key = "__call", .topic = "M(z)",
                                .callname = 1, .sig = "M(z) -> z\nM(x, y) -> x, y\nM(P) -> P", .help = "The Moebius map applied to a complex number, to coordinates or to a 2-D point."}, PCL_END};
static const pcl_fn mmethods[] = {{.name = "M:inverse", .fn = m_inverse, .result = "M", .self = tomobius, .selftype = "Moebius map",
                                   .help = "The inverse Moebius map (another automorphism of the disc)."}, PCL_END};

void pcl_open_complex(lua_State *L) {
    int module = lua_gettop(L);
    static const luaL_Reg cmeta[] = {{"__eq", c_eq}, {"__tostring", c_tostring}, {NULL, NULL}};
    static const luaL_Reg mmeta[] = {{"__tostring", m_tostring}, {NULL, NULL}};
    pcl_open_type(L, COMPLEX_MT, cmeta, NULL, zmethods, l_index);
    pcl_register_private(L, -1, operators);
    pcl_open_type(L, MOBIUS_MT, mmeta, mcall, mmethods, l_index);
    pcl_new_table(L, module, "complex", cfns, cnew);   /* a table of functions, callable as the constructor */
    lua_getfield(L, module, "complex");
    pushc(L, (pc_cnum){0, 1});
    lua_setfield(L, -2, "i");
    pcl_register(L, module, mfns, 0);
    lua_settop(L, module);
}
