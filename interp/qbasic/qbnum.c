/* QBasic number semantics: SINGLE rounding, float32 FOR loops, CINT, RND.  See qbnum.h. */
#include "qbnum.h"
#include <math.h>
#include <string.h>

double qb_f32(double x) {
    return (double)(float)x;
}

static double round_half_even(double x) {
    /* rint rounds to nearest with ties to even in the default rounding mode */
    return nearbyint(x);
}

double qb_cint(double x, int *ok) {
    double r = round_half_even(x);
    *ok = r >= -32768.0 && r <= 32767.0;
    return r;
}

double qb_clng(double x, int *ok) {
    double r = round_half_even(x);
    *ok = r >= -2147483648.0 && r <= 2147483647.0;
    return r;
}

/* ---- RND ---------------------------------------------------------------------------------- */

#define LCG_A 16598013u
#define LCG_C 12820163u
#define MASK24 0xFFFFFFu

void qb_rnd_init(qb_rnd_state *s) {
    s->seed = QB_RND_SEED0;
}

double qb_rnd(qb_rnd_state *s, double n) {
    float f = (float)n;
    if (f != 0.0f) {
        if (f < 0.0f) {
            /* reseed from the bit pattern of the SINGLE argument: low 24 bits plus the top byte */
            uint32_t bits;
            memcpy(&bits, &f, sizeof bits);
            s->seed = ((bits & MASK24) + (bits >> 24)) & MASK24;
        }
        s->seed = (s->seed * LCG_A + LCG_C) & MASK24;
    }
    return (double)s->seed / 16777216.0;
}

void qb_randomize(qb_rnd_state *s, double n) {
    /* the high 32 bits of the DOUBLE, folded to 16 bits, become the seed's middle bytes */
    uint64_t bits;
    memcpy(&bits, &n, sizeof bits);
    uint32_t hi = (uint32_t)(bits >> 32);
    hi ^= hi >> 16;
    s->seed = ((hi & 0xFFFFu) << 8) | (s->seed & 0xFFu);
}

/* ---- FOR loops ----------------------------------------------------------------------------- */

void qb_range_init(qb_range *r, double a, double b, double step) {
    r->value = qb_f32(a);
    r->limit = qb_f32(b);
    r->step = qb_f32(step);
    r->started = 0;
}

int qb_range_next(qb_range *r, double *v) {
    if (r->started) r->value = qb_f32(r->value + r->step);
    r->started = 1;
    int go = r->step >= 0 ? r->value <= r->limit : r->value >= r->limit;
    if (go) *v = r->value;
    return go;
}

long qb_range_count(double a, double b, double step, long max) {
    qb_range r;
    double v;
    long n = 0;
    qb_range_init(&r, a, b, step);
    while (n < max && qb_range_next(&r, &v)) n++;
    return n;
}
