/* Complex arithmetic for the complex numbers of examples 15 and 16 (the Moebius map of the
 * disc, stepanov_examples.md §H row 14), as status-returning functions so that a division by
 * zero or an overflow is reported instead of producing inf or NaN. */
#ifndef PC_CNUM_H
#define PC_CNUM_H

#include "status.h"

typedef struct {
    double re, im;
} pc_cnum;

/* out = a op b for op one of + - * / ^, or -a for op 'u' (b unused, but finite).  PC_EPOLE for a division by zero and for zero
 * raised to a power whose real part is not positive; PC_ENONFINITE when an operand or the
 * result is not finite (an overflow); PC_EDOMAIN for an unknown op.  Integer powers
 * |k| <= 64 are repeated multiplications, exact where the operands are (i^2 = -1, not
 * -1 + 1.2e-16 i); other powers are the principal value exp(b log a). */
int pc_cnum_arith(char op, pc_cnum a, pc_cnum b, pc_cnum *out);
/* e^z; PC_ENONFINITE when it overflows. */
int pc_cnum_exp(pc_cnum z, pc_cnum *out);
/* A function of z: op 'c' its conjugate, 'a' its modulus |z| and 'g' its argument atan2(im, re)
 * (both into out->re, out->im 0), 'e' e^z.  PC_ENONFINITE when z or the result is not finite,
 * PC_EDOMAIN for an unknown op. */
int pc_cnum_fn(char op, pc_cnum z, pc_cnum *out);

#endif
