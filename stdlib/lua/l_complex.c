/* Complex numbers and the Moebius map of the unit disc (stdlib/geom/cnum.h, curvilinear.h; examples 15, 16):
 *   complex(re [, im]) / complex(P)   a complex number (from a 2-D point: x + i y)
 *   complex.polar(r, u)  complex.exp(z)  complex.i
 *   z + w, z - w, z * w, z / w, -z, z ^ k (numbers mix in), z == w, tostring(z)
 *   z.re z.im, z:conj(), z:abs(), z:arg(), z:exp(), z:point()
 *   mobius(z0 [, phi])   w = e^(i phi) (z - z0) / (1 - conj(z0) z); the map M is called as
 *                        M(z) -> complex, M(x, y) -> x, y, M(P) -> P; M:inverse(); M.z0, M.phi
 * The arithmetic is the core's pc_cnum_arith, the Moebius map its pc_mobius. */
#include <complex.h>
#include <math.h>
#include <string.h>
#include "pcl_args.h"
#include "pcl_tk.h"
#include "curvilinear.h"
#include "cnum.h"

#define COMPLEX_MT "complex"
#define MOBIUS_MT "mobius"
static const char COMPLEX_TAG = 'z', MOBIUS_TAG = 'm';   /* PCL_SELF_TAG */

/* self: a file handle has the size of two doubles, so the size alone does not tell (pcl.h) */
typedef struct { PCL_SELF; double re, im; } cnum;
typedef struct { PCL_SELF; double z0re, z0im, phi; } mobius;   /* self: as cnum's */

static cnum *pushc(lua_State *L, double re, double im) {
    cnum *z = lua_newuserdatauv(L, sizeof *z, 0);
    z->self = PCL_SELF_TAG(z, &COMPLEX_TAG);
    z->re = re;
    z->im = im;
    luaL_setmetatable(L, COMPLEX_MT);
    return z;
}

static void pushcc(lua_State *L, double complex z) { pushc(L, creal(z), cimag(z)); }

/* The complex number at idx or NULL; a userdata given its metatable by the debug library has
 * another size and is refused (pcl.h: forged userdata). */
static cnum *tocnum(lua_State *L, int idx) {
    cnum *c = luaL_testudata(L, idx, COMPLEX_MT);
    int ok = !c || (lua_rawlen(L, idx) == sizeof *c &&
                    c->self == PCL_SELF_TAG(c, &COMPLEX_TAG));
    return pcl_genuine(L, idx, c, ok, "complex number");
}
static void *self_cnum(lua_State *L, int idx) { return tocnum(L, idx); }

static mobius *tomobius(lua_State *L, int idx) {
    mobius *m = luaL_testudata(L, idx, MOBIUS_MT);
    int ok = !m || (lua_rawlen(L, idx) == sizeof *m && m->self == PCL_SELF_TAG(m, &MOBIUS_TAG));
    return pcl_genuine(L, idx, m, ok, "Moebius map");
}
static void *self_mobius(lua_State *L, int idx) { return tomobius(L, idx); }

/* a complex operand: a complex or a real number (not checked for finiteness) */
static int toc(lua_State *L, int idx, double complex *z) {
    cnum *c = tocnum(L, idx);
    if (c) *z = CMPLX(c->re, c->im);
    else if (lua_type(L, idx) == LUA_TNUMBER) *z = CMPLX(lua_tonumber(L, idx), 0.0);
    return c || lua_type(L, idx) == LUA_TNUMBER;
}

/* The declared kind "a finite complex number or number": re, im into v[0], v[1]. */
static int read_c(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    (void)a;
    double complex z = 0;
    if (!toc(L, idx, &z) || !isfinite(creal(z)) || !isfinite(cimag(z))) return 0;
    out->v[0] = creal(z), out->v[1] = cimag(z);
    return 1;
}
#define A_COMPLEX(nm) A_ANY(nm, read_c, "a finite complex number or number")

/* ---- the operators (metamethods: not called by name, so not declared) ------------------ */

static double complex operand(lua_State *L, const char *fn, int idx) {
    double complex z = 0;
    const char *what = idx == 1 ? "left" : "right";
    if (!toc(L, idx, &z))
        pcl_error(L, "%s: argument #%d (%s) must be a complex number or a number, got %s", fn, idx, what, pcl_shown(L, idx));
    if (!isfinite(creal(z)) || !isfinite(cimag(z)))
        pcl_error(L, "%s: argument #%d (%s) must be a finite number, got %s", fn, idx, what, pcl_shown(L, idx));
    return z;
}

static int arith(lua_State *L, char op) {
    static const char *names[] = {"complex +", "complex -", "complex *", "complex /", "complex ^"};
    const char *fn = names[op == '+' ? 0 : op == '-' ? 1 : op == '*' ? 2 : op == '/' ? 3 : 4];
    double complex a = operand(L, fn, 1), b = operand(L, fn, 2);
    pc_cnum r;
    int st = pc_cnum_arith(op, (pc_cnum){creal(a), cimag(a)}, (pc_cnum){creal(b), cimag(b)}, &r);
    if (st == PC_EPOLE)
        return pcl_error(L, "%s: division by zero%s", fn,
                         op == '^' ? " (zero to a power whose real part is not positive)" : "");
    if (st != PC_OK) return pcl_error(L, "%s: the result overflows (not finite)", fn);
    pushc(L, r.re, r.im);
    return 1;
}
static int c_add(lua_State *L) { return arith(L, '+'); }
static int c_sub(lua_State *L) { return arith(L, '-'); }
static int c_mul(lua_State *L) { return arith(L, '*'); }
static int c_div(lua_State *L) { return arith(L, '/'); }
static int c_pow(lua_State *L) { return arith(L, '^'); }

static int c_unm(lua_State *L) {
    double complex z = operand(L, "complex -", 1);
    pushcc(L, -z);
    return 1;
}

static int c_eq(lua_State *L) {
    double complex a, b;
    lua_pushboolean(L, toc(L, 1, &a) && toc(L, 2, &b) && a == b);
    return 1;
}

static int c_tostring(lua_State *L) {
    cnum *z = tocnum(L, 1);
    if (!z) return pcl_error(L, "tostring: not a complex number");
    const char *re = pcl_pushnum(L, z->re), *im = pcl_pushnum(L, z->im);
    lua_pushfstring(L, "complex(%s, %s)", re, im);
    return 1;
}

/* ---- complex.f(z) and z:f(): one body, the value an argument or the receiver ------------- */

static double complex the_z(lua_State *L) {
    pcl_val a[1] = {0};
    cnum *z = PCL_READ(L, a);
    return z ? CMPLX(z->re, z->im) : CMPLX(a[0].v[0], a[0].v[1]);
}

static int c_conj(lua_State *L) {
    pushcc(L, conj(the_z(L)));
    return 1;
}
static int c_abs(lua_State *L) {
    lua_pushnumber(L, cabs(the_z(L)));
    return 1;
}
static int c_arg(lua_State *L) {
    lua_pushnumber(L, carg(the_z(L)));
    return 1;
}
static int c_exp(lua_State *L) {
    double complex z = the_z(L);
    pc_cnum r;
    if (pc_cnum_exp((pc_cnum){creal(z), cimag(z)}, &r) != PC_OK) return pcl_fail(L, "the result overflows (not finite)");
    pushc(L, r.re, r.im);
    return 1;
}
static int c_point(lua_State *L) {
    double complex z = the_z(L);
    double x[2] = {creal(z), cimag(z)};
    pcl_pushpoint(L, 2, x);
    return 1;
}

static int c_index(lua_State *L) {
    cnum *z = tocnum(L, 1);
    const char *k = lua_tostring(L, 2);
    if (!z || !k) return 0;
    if (!strcmp(k, "re")) lua_pushnumber(L, z->re);
    else if (!strcmp(k, "im")) lua_pushnumber(L, z->im);
    else lua_getfield(L, lua_upvalueindex(1), k);          /* the methods */
    return 1;
}

/* complex(re [, im]), complex(P) or complex(z): the __call of the table complex */
static void *self_table(lua_State *L, int idx) { return lua_istable(L, idx) ? (void *)1 : NULL; }
static const pcl_arg new_args[] = {{.name = "re", .kind = PCL_NUMBER, .expect = "a finite number or a 2-D point"},
                                   A_NUMOPT("im", 0, NULL), PCL_END};
static const pcl_arg point_arg = A_POINT("P", 2);

static int c_new(lua_State *L) {
    cnum *z = tocnum(L, 2);
    if (z) {
        pushc(L, z->re, z->im);
        return 1;
    }
    pcl_val a[2] = {0};
    if (pcl_tovalue(L, 2)) {
        pcl_readone(L, 2, 1, 0, &point_arg, 0, &a[0]);
        pushc(L, a[0].v[0], a[0].v[1]);
        return 1;
    }
    PCL_READ(L, a);
    pushc(L, a[0].x, a[1].x);
    return 1;
}

static const pcl_arg polar_args[] = {A_NUM("r"), A_NUM("u"), PCL_END};
static int c_polar(lua_State *L) {
    pcl_val a[2] = {0};
    PCL_READ(L, a);
    pushc(L, a[0].x * cos(a[1].x), a[0].x * sin(a[1].x));
    return 1;
}

/* ---- Moebius ------------------------------------------------------------------------------- */

static void apply(lua_State *L, const mobius *m, double re, double im, double *w) {
    int st = pc_mobius(m->z0re, m->z0im, m->phi, re, im, &w[0], &w[1]);
    if (st == PC_EPOLE) {
        const char *tre = pcl_pushnum(L, re), *tim = pcl_pushnum(L, im);
        pcl_fail(L, "z = complex(%s, %s) is the pole 1/conj(z0) of the map", tre, tim);
    }
    if (st != PC_OK) pcl_fail(L, "%s", pc_strerror(st));
}

/* M(z), M(x, y), M(P): the form follows the arguments */
static const pcl_arg m_args[] = {A_ANY("z", read_c, "a complex number, a 2-D point or x, y"), PCL_END};
static const pcl_arg coord_x = A_NUM("x"), coord_y = A_NUM("y");

static int m_call(lua_State *L) {
    mobius *m = tomobius(L, 1);           /* a __call: the map itself (PCL_READ checks it) */
    pcl_val a[2] = {0};
    double w[2];
    if (lua_type(L, 2) == LUA_TNUMBER && !lua_isnoneornil(L, 3)) {
        pcl_readone(L, 2, 1, 0, &coord_x, 0, &a[0]);
        pcl_readone(L, 3, 2, 0, &coord_y, 0, &a[1]);
        apply(L, m, a[0].x, a[1].x, w);
        lua_pushnumber(L, w[0]);
        lua_pushnumber(L, w[1]);
        return 2;
    }
    if (pcl_tovalue(L, 2)) {
        pcl_readone(L, 2, 1, 0, &point_arg, 0, &a[0]);
        apply(L, m, a[0].v[0], a[0].v[1], w);
        pcl_pushpoint(L, 2, w);
        return 1;
    }
    m = PCL_READ(L, a);
    apply(L, m, a[0].v[0], a[0].v[1], w);
    pushc(L, w[0], w[1]);
    return 1;
}

static void pushm(lua_State *L, double re, double im, double phi) {
    mobius *m = lua_newuserdatauv(L, sizeof *m, 0);
    m->self = PCL_SELF_TAG(m, &MOBIUS_TAG);
    m->z0re = re;
    m->z0im = im;
    m->phi = phi;
    luaL_setmetatable(L, MOBIUS_MT);
}

static int m_inverse(lua_State *L) {
    mobius *m = pcl_read(L, NULL, 0);
    double re, im, phi;
    pc_mobius_inverse(m->z0re, m->z0im, m->phi, &re, &im, &phi);
    pushm(L, re, im, phi);
    return 1;
}

static int m_index(lua_State *L) {
    mobius *m = tomobius(L, 1);
    const char *k = lua_tostring(L, 2);
    if (!m || !k) return 0;
    if (!strcmp(k, "z0")) pushc(L, m->z0re, m->z0im);
    else if (!strcmp(k, "phi")) lua_pushnumber(L, m->phi);
    else lua_getfield(L, lua_upvalueindex(1), k);          /* inverse */
    return 1;
}

static int m_tostring(lua_State *L) {
    mobius *m = tomobius(L, 1);
    if (!m) return pcl_error(L, "tostring: not a Moebius map");
    const char *re = pcl_pushnum(L, m->z0re), *im = pcl_pushnum(L, m->z0im), *phi = pcl_pushnum(L, m->phi);
    lua_pushfstring(L, "mobius(complex(%s, %s), %s)", re, im, phi);
    return 1;
}

static const pcl_arg mobius_args[] = {A_COMPLEX("z0"), A_NUMOPT("phi", 0, NULL), PCL_END};
static int l_mobius(lua_State *L) {
    pcl_val a[2] = {0};
    PCL_READ(L, a);
    if (hypot(a[0].v[0], a[0].v[1]) >= 1)
        return pcl_argfail(L, 1, "must be a point inside the unit disc (|z0| < 1), got %s", luaL_tolstring(L, 1, NULL));
    pushm(L, a[0].v[0], a[0].v[1], a[1].x);
    return 1;
}

static const pcl_arg z_arg[] = {A_COMPLEX("z"), PCL_END};
#define ZMETHOD(nm, f, res, text) {.name = nm, .fn = f, .result = res, .help = text, .self = self_cnum, .selftype = "complex number"}
static const pcl_fn zmethods[] = {
    ZMETHOD("z:conj", c_conj, "z", "The complex conjugate re - i im."), ZMETHOD("z:abs", c_abs, "number", "The modulus |z|."),
    ZMETHOD("z:arg", c_arg, "number", "The argument of z: atan2(im, re), in radians."), ZMETHOD("z:exp", c_exp, "z", "The complex exponential e^z."),
    ZMETHOD("z:point", c_point, "P", "The 2-D point (re, im) of the complex plane."), PCL_END};
static const pcl_fn cfns[] = {
    PCL_FN("complex.polar", c_polar, polar_args, "z", "The complex number r e^(iu)."),
    PCL_FN("complex.exp", c_exp, z_arg, "z", "The complex exponential."), PCL_FN("complex.abs", c_abs, z_arg, "number", "The modulus |z|."),
    PCL_FN("complex.arg", c_arg, z_arg, "number", "The argument of z: atan2(im, re), in radians."),
    PCL_FN("complex.conj", c_conj, z_arg, "z", "The complex conjugate."), PCL_END};
static const pcl_fn cnew[] = {{.name = "complex", .fn = c_new, .args = new_args, .self = self_table, .selftype = "table", .key = "__call",
                               .sig = "complex(re [, im]) | complex(P) -> z", .help = "A complex number (from a 2-D point, x + iy); + - * / ^ mix with numbers; z.re, z.im, z:conj(), z:abs(), z:arg(), z:exp(), z:point()."}, PCL_END};
static const pcl_fn mfns[] = {PCL_FN("mobius", l_mobius, mobius_args, "M", "The Moebius automorphism w = e^(i phi)(z - z0)/(1 - conj(z0) z) of the unit disc (examples 15, 16): M(z), M(x, y), M(P), M:inverse()."), PCL_END};
static const pcl_fn mcall[] = {{.name = "M", .fn = m_call, .args = m_args, .self = self_mobius, .selftype = "Moebius map", .key = "__call", .topic = "M(z)",
                                .callname = 1, .sig = "M(z) -> z\nM(x, y) -> x, y\nM(P) -> P", .help = "The Moebius map applied to a complex number, to coordinates or to a 2-D point."}, PCL_END};
static const pcl_fn mmethods[] = {{.name = "M:inverse", .fn = m_inverse, .result = "M", .self = self_mobius, .selftype = "Moebius map",
                                   .help = "The inverse Moebius map (another automorphism of the disc)."}, PCL_END};

void pcl_open_complex(lua_State *L) {
    int module = lua_gettop(L);
    static const luaL_Reg cmeta[] = {
        {"__add", c_add}, {"__sub", c_sub}, {"__mul", c_mul}, {"__div", c_div}, {"__pow", c_pow},
        {"__unm", c_unm}, {"__eq", c_eq}, {"__tostring", c_tostring}, {NULL, NULL}};
    static const luaL_Reg mmeta[] = {{"__tostring", m_tostring}, {NULL, NULL}};
    pcl_open_type(L, COMPLEX_MT, cmeta, NULL, zmethods, c_index);
    pcl_open_type(L, MOBIUS_MT, mmeta, mcall, mmethods, m_index);
    lua_settop(L, module);

    lua_newtable(L);   /* complex: a table of functions, callable as the constructor */
    pcl_register(L, -1, cfns, 0);
    pushc(L, 0, 1);
    lua_setfield(L, -2, "i");
    lua_newtable(L);
    pcl_register(L, -1, cnew, 0);
    lua_setmetatable(L, -2);
    lua_setfield(L, module, "complex");
    pcl_register(L, module, mfns, 0);
}
