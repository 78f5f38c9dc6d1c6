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

/* z of a method z:f() (also called as z.f(5): the message names it) */
static cnum *checkz(lua_State *L, const char *fn) {
    cnum *z = tocnum(L, 1);
    if (!z) pcl_argerror_full(L, fn, 1, 0, NULL, "a complex number (call it as z:f())");
    return z;
}

/* a complex operand: a complex or a real number */
static int toc(lua_State *L, int idx, double complex *z) {
    cnum *c = tocnum(L, idx);
    if (c) {
        *z = CMPLX(c->re, c->im);
        return 1;
    }
    if (lua_type(L, idx) == LUA_TNUMBER) {
        *z = CMPLX(lua_tonumber(L, idx), 0.0);
        return 1;
    }
    return 0;
}

static double complex checkc(lua_State *L, const char *fn, int idx, const char *what) {
    double complex z = 0;
    if (!toc(L, idx, &z)) pcl_argerror_full(L, fn, idx, idx, what, "a complex number or a number");
    if (!isfinite(creal(z)) || !isfinite(cimag(z))) pcl_argerror_full(L, fn, idx, idx, what, "a finite number");
    return z;
}

static int arith(lua_State *L, char op) {
    static const char *names[] = {"complex +", "complex -", "complex *", "complex /", "complex ^"};
    const char *fn = names[op == '+' ? 0 : op == '-' ? 1 : op == '*' ? 2 : op == '/' ? 3 : 4];
    double complex a = checkc(L, fn, 1, "left"), b = checkc(L, fn, 2, "right");
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
    cnum *z = checkz(L, "complex -");
    pushc(L, -z->re, -z->im);
    return 1;
}

static int c_eq(lua_State *L) {
    double complex a, b;
    lua_pushboolean(L, toc(L, 1, &a) && toc(L, 2, &b) && a == b);
    return 1;
}

static int c_tostring(lua_State *L) {
    cnum *z = checkz(L, "tostring");
    pcl_pushnum(L, z->re);
    pcl_pushnum(L, z->im);
    lua_pushfstring(L, "complex(%s, %s)", lua_tostring(L, -2), lua_tostring(L, -1));
    return 1;
}

static int c_conj(lua_State *L) {
    double complex z = checkc(L, "z:conj", 1, "z");
    pushcc(L, conj(z));
    return 1;
}
static int c_abs(lua_State *L) {
    lua_pushnumber(L, cabs(checkc(L, "z:abs", 1, "z")));
    return 1;
}
static int c_arg(lua_State *L) {
    lua_pushnumber(L, carg(checkc(L, "z:arg", 1, "z")));
    return 1;
}
static int c_exp(lua_State *L) {
    double complex z = checkc(L, "complex.exp", 1, "z");
    pc_cnum r;
    if (pc_cnum_exp((pc_cnum){creal(z), cimag(z)}, &r) != PC_OK)
        return pcl_error(L, "complex.exp: the result overflows (not finite)");
    pushc(L, r.re, r.im);
    return 1;
}
static int c_point(lua_State *L) {
    cnum *z = checkz(L, "z:point");
    double x[2] = {z->re, z->im};
    pcl_pushpoint(L, 2, x);
    return 1;
}

static int c_index(lua_State *L) {
    cnum *z = checkz(L, "z.field");
    const char *k = lua_tostring(L, 2);
    if (!k) return 0;
    if (!strcmp(k, "re")) lua_pushnumber(L, z->re);
    else if (!strcmp(k, "im")) lua_pushnumber(L, z->im);
    else if (!strcmp(k, "conj")) lua_pushcfunction(L, c_conj);
    else if (!strcmp(k, "abs")) lua_pushcfunction(L, c_abs);
    else if (!strcmp(k, "arg")) lua_pushcfunction(L, c_arg);
    else if (!strcmp(k, "exp")) lua_pushcfunction(L, c_exp);
    else if (!strcmp(k, "point")) lua_pushcfunction(L, c_point);
    else return 0;
    return 1;
}

/* complex(re [, im]) or complex(P); called through the table complex (argument 1 is it) */
static int c_new(lua_State *L) {
    const char *fn = "complex";
    double x[2];
    lua_remove(L, 1);   /* the table complex: arguments are now in their places */
    lua_settop(L, 2);
    if (pcl_tovalue(L, 1)) {
        pcl_checkloc(L, 1, "P", 2, 0, x);
        pushc(L, x[0], x[1]);
        return 1;
    }
    cnum *z = tocnum(L, 1);
    if (z) {
        pushc(L, z->re, z->im);
        return 1;
    }
    if (lua_type(L, 1) != LUA_TNUMBER) pcl_argerror_full(L, fn, 1, 1, "re", "a number or a 2-D point");
    double re = pcl_checknum(L, fn, 1, "re"), im = pcl_optnum(L, fn, 2, "im", 0.0);
    pushc(L, re, im);
    return 1;
}

static int c_polar(lua_State *L) {
    double r = pcl_checknum(L, "complex.polar", 1, "r"), u = pcl_checknum(L, "complex.polar", 2, "u");
    pushc(L, r * cos(u), r * sin(u));
    return 1;
}

/* ---- Moebius ------------------------------------------------------------------------------- */

static mobius *checkm(lua_State *L, int idx, const char *fn) {
    mobius *m = luaL_testudata(L, idx, MOBIUS_MT);
    int ok = !m || (lua_rawlen(L, idx) == sizeof *m && m->self == PCL_SELF_TAG(m, &MOBIUS_TAG));
    pcl_genuine(L, idx, m, ok, "Moebius map");
    if (!m) pcl_argerror_full(L, fn, idx, idx, "self", "a Moebius map");
    return m;
}

static void apply(lua_State *L, const mobius *m, double re, double im, double *wre, double *wim) {
    int st = pc_mobius(m->z0re, m->z0im, m->phi, re, im, wre, wim);
    if (st == PC_EPOLE)
    {
        const char *tre = pcl_pushnum(L, re), *tim = pcl_pushnum(L, im);
        pcl_error(L, "mobius: z = complex(%s, %s) is the pole 1/conj(z0) of the map", tre, tim);
    }
    if (st != PC_OK) pcl_error(L, "mobius: %s", pc_strerror(st));
}

static int m_call(lua_State *L) {
    const char *fn = "mobius map";
    mobius *m = checkm(L, 1, fn);
    double w[2];
    if (lua_type(L, 2) == LUA_TNUMBER && !lua_isnoneornil(L, 3)) {
        double re = pcl_checknum_m(L, fn, 2, "x"), im = pcl_checknum_m(L, fn, 3, "y");
        apply(L, m, re, im, &w[0], &w[1]);
        lua_pushnumber(L, w[0]);
        lua_pushnumber(L, w[1]);
        return 2;
    }
    if (pcl_tovalue(L, 2)) {
        double x[2];
        pcl_checkloc(L, 2, "P", 2, 0, x);
        apply(L, m, x[0], x[1], &w[0], &w[1]);
        pcl_pushpoint(L, 2, w);
        return 1;
    }
    double complex z;
    if (!toc(L, 2, &z)) pcl_argerror_full(L, fn, 2, 1, "z", "a complex number, a 2-D point or x, y");
    apply(L, m, creal(z), cimag(z), &w[0], &w[1]);
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
    mobius *m = checkm(L, 1, "M:inverse");
    double re, im, phi;
    pc_mobius_inverse(m->z0re, m->z0im, m->phi, &re, &im, &phi);
    pushm(L, re, im, phi);
    return 1;
}

static int m_index(lua_State *L) {
    mobius *m = checkm(L, 1, "mobius map");
    const char *k = lua_tostring(L, 2);
    if (!k) return 0;
    if (!strcmp(k, "z0")) pushc(L, m->z0re, m->z0im);
    else if (!strcmp(k, "phi")) lua_pushnumber(L, m->phi);
    else if (!strcmp(k, "inverse")) lua_pushcfunction(L, m_inverse);
    else return 0;
    return 1;
}

static int m_tostring(lua_State *L) {
    mobius *m = checkm(L, 1, "mobius map");
    pcl_pushnum(L, m->z0re);
    pcl_pushnum(L, m->z0im);
    pcl_pushnum(L, m->phi);
    lua_pushfstring(L, "mobius(complex(%s, %s), %s)", lua_tostring(L, -3), lua_tostring(L, -2),
                    lua_tostring(L, -1));
    return 1;
}

static int l_mobius(lua_State *L) {
    const char *fn = "mobius";
    double complex z0 = checkc(L, fn, 1, "z0");
    double phi = pcl_optnum(L, fn, 2, "phi", 0.0);
    if (!isfinite(creal(z0)) || !isfinite(cimag(z0)))
        pcl_argerror_full(L, fn, 1, 1, "z0", "a finite complex number");
    if (cabs(z0) >= 1) pcl_argerror_full(L, fn, 1, 1, "z0", "a point inside the unit disc (|z0| < 1)");
    pushm(L, creal(z0), cimag(z0), phi);
    return 1;
}

void pcl_open_complex(lua_State *L) {
    int module = lua_gettop(L);
    luaL_newmetatable(L, COMPLEX_MT);
    static const luaL_Reg cmeta[] = {
        {"__add", c_add}, {"__sub", c_sub}, {"__mul", c_mul}, {"__div", c_div},
        {"__pow", c_pow}, {"__unm", c_unm}, {"__eq", c_eq},   {"__tostring", c_tostring},
        {"__index", c_index}, {NULL, NULL}};
    luaL_setfuncs(L, cmeta, 0);
    luaL_newmetatable(L, MOBIUS_MT);
    static const luaL_Reg mmeta[] = {
        {"__call", m_call}, {"__index", m_index}, {"__tostring", m_tostring}, {NULL, NULL}};
    luaL_setfuncs(L, mmeta, 0);
    lua_settop(L, module);

    lua_newtable(L);   /* complex: a table of functions, callable as the constructor */
    static const luaL_Reg cfns[] = {{"polar", c_polar}, {"exp", c_exp}, {"conj", c_conj},
                                    {"abs", c_abs},     {"arg", c_arg}, {NULL, NULL}};
    luaL_setfuncs(L, cfns, 0);
    pushc(L, 0, 1);
    lua_setfield(L, -2, "i");
    lua_newtable(L);
    lua_pushcfunction(L, c_new);
    lua_setfield(L, -2, "__call");
    lua_setmetatable(L, -2);
    lua_setfield(L, module, "complex");
    lua_pushcfunction(L, l_mobius);
    lua_setfield(L, module, "mobius");
}
