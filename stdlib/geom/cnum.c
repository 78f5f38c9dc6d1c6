/* Complex arithmetic with status codes (cnum.h); C99's complex type does the work. */
#include "cnum.h"
#include <complex.h>
#include <math.h>
#include <stdlib.h>

static int is_finite(pc_cnum z) { return isfinite(z.re) && isfinite(z.im); }

static int put(double complex r, pc_cnum *out) {
    pc_cnum z = {creal(r), cimag(r)};
    if (!is_finite(z)) return PC_ENONFINITE;
    *out = z;
    return PC_OK;
}

static int power(double complex a, double complex b, pc_cnum *out) {
    if (a == 0) {
        if (b == 0) return put(1, out);                     /* 0^0 = 1, as Lua's 0^0 */
        return creal(b) > 0 ? put(0, out) : PC_EPOLE;     /* 0^b: |a^b| = 0 or a pole */
    }
    if (cimag(b) == 0 && creal(b) == floor(creal(b)) && fabs(creal(b)) <= 64) {
        int k = (int)creal(b);
        double complex base = k < 0 ? 1 / a : a, r = 1;
        for (int i = 0; i < abs(k); i++) r *= base;
        return put(r, out);
    }
    return put(cpow(a, b), out);
}

int pc_cnum_arith(char op, pc_cnum a, pc_cnum b, pc_cnum *out) {
    if (!is_finite(a) || !is_finite(b)) return PC_ENONFINITE;
    double complex x = CMPLX(a.re, a.im), y = CMPLX(b.re, b.im);
    switch (op) {
    case '+': return put(x + y, out);
    case '-': return put(x - y, out);
    case '*': return put(x * y, out);
    case '/': return y == 0 ? PC_EPOLE : put(x / y, out);
    case '^': return power(x, y, out);
    case 'u': return put(-x, out);
    default: return PC_EDOMAIN;
    }
}

int pc_cnum_exp(pc_cnum z, pc_cnum *out) {
    if (!is_finite(z)) return PC_ENONFINITE;
    return put(cexp(CMPLX(z.re, z.im)), out);
}

int pc_cnum_fn(char op, pc_cnum z, pc_cnum *out) {
    double complex x = CMPLX(z.re, z.im);
    switch (op) {
    case 'c': return put(conj(x), out);
    case 'a': return put(cabs(x), out);
    case 'g': return put(carg(x), out);
    case 'e': return pc_cnum_exp(z, out);
    default: return PC_EDOMAIN;
    }
}
