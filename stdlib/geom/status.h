/* One set of status codes for the whole core (stdlib/geom and stdlib/draw), with one message
 * each.  Functions that can meet degenerate geometry or bad input return PC_OK or one of these
 * and never produce NaN silently; the bindings turn a code into a Lua error with
 * pc_strerror(). */
#ifndef PC_STATUS_H
#define PC_STATUS_H

enum {
    PC_OK = 0,
    PC_IMPROPER,      /* not an error: the result is a point at infinity (weight 0) */
    PC_EZERO,         /* a zero vector where a direction is needed */
    PC_ECOINCIDENT,   /* points that must be distinct coincide */
    PC_ENOTCOLLINEAR, /* points that must lie on one line do not */
    PC_ECOLLINEAR,    /* points that must span a plane (or more) are dependent */
    PC_ESAME_LINE,    /* two lines coincide: no single meet */
    PC_ESKEW,         /* two lines in 3-D or more do not meet */
    PC_ESINGULAR,     /* a singular linear map or system */
    PC_EWEIGHT,       /* a weight neither 1 nor 0 where a location is needed */
    PC_EDIM,          /* dimensions do not fit */
    PC_ENONFINITE,    /* a NaN or an infinity */
    PC_EDOMAIN,       /* a parameter outside its domain (t0 not in (0,1), n <= 0, ...) */
    PC_ENOBRACKET,    /* f(a) and f(b) have the same sign: no root is bracketed */
    PC_EPOLE,         /* a map evaluated at its pole (division by zero) */
    PC_EARG,          /* an argument out of range (the canvas's message says which) */
    PC_ENOMEM,        /* out of memory, or a size beyond the core's limits */
    PC_EIO,           /* a writer could not write its file */
    PC_ENOCONVERGE,   /* an iteration (Newton, optimiser) did not converge */
    PC_EDOMAIN2,      /* a second parameter outside its domain (a why-table, why.h, says which) */
    PC_EDOMAIN3       /* a third parameter outside its domain */
};

/* A short English description of a status code: it names the condition; the caller adds
 * which argument or object it concerns. */
const char *pc_strerror(int status);

#endif
