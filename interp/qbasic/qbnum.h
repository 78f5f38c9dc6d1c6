/* QBasic number semantics that plain C doubles do not give: SINGLE rounding, the FOR loop that
 * accumulates in single precision, CINT/CLNG rounding, and QBasic's RND generator.
 *
 * Pure C, no Lua.  Used by the QBasic front end (through the binding stdlib/lua/l_qb.c) and by
 * Lua scripts that want QBasic-faithful loops (qb.range).
 *
 * Facts honoured (see ../shared/reference/stepanov_examples.md §E, §F):
 *  - SINGLE is IEEE binary32; a value stored in a SINGLE variable is rounded to nearest.
 *  - FOR var = a TO b STEP s: a, b, s are evaluated once and rounded to the variable's type; the
 *    test var <= b (var >= b for a negative step) comes before every pass; NEXT adds the step
 *    in single precision.  `FOR t = 0 TO 1 STEP .001` runs 1001 times.
 *  - RND: 24-bit LCG seed = (seed * 16598013 + 12820163) mod 2^24, value = seed / 2^24,
 *    initial seed 327680.  RND(0) repeats the last value; a negative argument reseeds from the
 *    bits of its SINGLE value first.  RANDOMIZE n mixes the high 32 bits of the DOUBLE n into
 *    the middle 16 bits of the seed.
 */
#ifndef PC_QBNUM_H
#define PC_QBNUM_H

#include <stdint.h>

/* Round to SINGLE (binary32), returned as a double holding that exact value.  Values beyond
 * the SINGLE range become +-inf (the caller reports QBasic's "Overflow"). */
double qb_f32(double x);

/* QBasic's CINT / CLNG rounding: to nearest, ties to even.  *ok is set to 0 when the result is
 * outside -32768..32767 (cint) or -2147483648..2147483647 (clng) ("Overflow"), else 1. */
double qb_cint(double x, int *ok);
double qb_clng(double x, int *ok);

/* ---- RND ---------------------------------------------------------------------------------- */

#define QB_RND_SEED0 327680u

typedef struct {
    uint32_t seed;   /* 24 bits */
} qb_rnd_state;

void qb_rnd_init(qb_rnd_state *s);
/* RND(n): n > 0 the next value; n == 0 the last value again; n < 0 reseed from n, then the
 * next value.  The result is a SINGLE in [0, 1). */
double qb_rnd(qb_rnd_state *s, double n);
/* RANDOMIZE n */
void qb_randomize(qb_rnd_state *s, double n);

/* ---- FOR loops ----------------------------------------------------------------------------- */

typedef struct {
    double value;    /* the loop variable (a SINGLE value) */
    double limit, step;
    int started;
} qb_range;

/* Prepare FOR v = a TO b STEP step with a SINGLE loop variable. */
void qb_range_init(qb_range *r, double a, double b, double step);
/* The next value of the loop variable: returns 1 and stores it in *v, or 0 when the loop ends
 * (r->value then holds the value QBasic leaves in the variable: the last one plus the step). */
int qb_range_next(qb_range *r, double *v);
/* How many times such a loop runs (counting stops at max). */
long qb_range_count(double a, double b, double step, long max);

#endif
