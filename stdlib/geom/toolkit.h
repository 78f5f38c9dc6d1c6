/* Status codes shared by the curvilinear-coordinates toolkit (smooth.h, spline.h, fourier.h,
 * cmap.h, numeric.h): the building blocks of Stepanov's "method of curvilinear coordinates"
 * (../shared/reference/stepanov_examples.md §H).  Pure C, no Lua.  Functions that can fail
 * return PC_TK_OK (0) or one of these codes and never produce NaN silently. */
#ifndef PC_TOOLKIT_H
#define PC_TOOLKIT_H

enum {
    PC_TK_OK = 0,
    PC_TK_EDOMAIN,     /* a parameter outside its domain (t0 not in (0,1), n <= 0, ...) */
    PC_TK_EZERO,       /* a zero vector where a direction is needed */
    PC_TK_ENOBRACKET,  /* f(a) and f(b) have the same sign: no root is bracketed */
    PC_TK_EPOLE,       /* a map evaluated at its pole (division by zero) */
    PC_TK_EDIM,        /* dimensions do not fit */
    PC_TK_ENONFINITE   /* a NaN or an infinity */
};

/* A short English description of a status code ("t0 must lie in (0, 1)" style messages are
 * the binding's business; this names the condition). */
const char *pc_tk_strerror(int status);

#endif
