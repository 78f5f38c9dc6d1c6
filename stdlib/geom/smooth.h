/* Smoothsteps: functions g on [0, 1] with g(0) = 0, g(1) = 1, g'(0) = g'(1) = 0, used to join
 * two curves smoothly (stepanov_examples.md §H rows 4-6).  Outside [0, 1] the formulas
 * extrapolate, as example 5 shows, except the clamps, which are constant there; a power piece
 * of fractional degree has no real value past its end (pc_hspline_check). */
#ifndef PC_SMOOTH_H
#define PC_SMOOTH_H

#include <stddef.h>
#include "status.h"

/* (1 - cos(pi t)) / 2, examples 3 and 4. */
double pc_smooth_sine(double t);
/* 3t^2 - 2t^3 (the article's -2t^3 + 3t^2), examples 5, 6, 9. */
double pc_smooth_cubic(double t);
/* Symmetric power half-spline of degree n (example 7): 2^(n-1) t^n for t < 1/2,
 * 1 - 2^(n-1) (1 - t)^n for t >= 1/2.  It is the asymmetric half-spline (n, n, 1/2). */
double pc_smooth_power(double n, double t);

/* Asymmetric half-spline (example 8): c1 t^n for t < t0, 1 - c2 (1 - t)^m for t >= t0, with
 *   c1 = m / ((n - n t0 + m t0) t0^(n-1)),   c2 = (1 - c1 t0^n) / (1 - t0)^m,
 * which makes g and g' continuous at t0.  The junction ordinate is g(t0) = v(t0). */
typedef struct {
    double n, m, t0;   /* degrees of the two pieces and the junction abscissa */
    double c1, c2;     /* the coefficients above */
} pc_hspline;

/* PC_ENONFINITE for a NaN or infinite parameter; PC_EDOMAIN unless n > 0, m > 0,
 * 0 < t0 < 1, or when c1 or c2 overflows a double (degrees in the hundreds: t0^(n-1)
 * underflows).  h is untouched on error. */
int pc_hspline_init(pc_hspline *h, double n, double m, double t0);
double pc_hspline_eval(const pc_hspline *h, double t);
/* g'(t): n c1 t^(n-1) for t < t0, m c2 (1 - t)^(m-1) for t >= t0. */
double pc_hspline_deriv(const pc_hspline *h, double t);
/* Where the formulas extrapolate: t^n for t < 0 and (1 - t)^m for t > 1 are real only for a
 * whole degree.  PC_EDOMAIN when t < 0 and n is fractional, or t > 1 and m is (eval and
 * deriv would give NaN there); PC_OK otherwise. */
int pc_hspline_check(const pc_hspline *h, double t);
/* Why pc_hspline_check refuses t, as the message of the argument t: "must be at least 0 (the
 * degree n = 2.5 is fractional, so the formula does not extrapolate past 0)" into buf; 0 (buf
 * untouched) when it accepts t, else the length. */
size_t pc_hspline_check_text(const pc_hspline *h, double t, char *buf, size_t size);
/* Why pc_hspline_init refused degrees n, m > 0 and 0 < t0 < 1: c1 or c2 overflows a double. */
size_t pc_hspline_init_text(double n, double m, double t0, char *buf, size_t size);
/* The locus of the junction points (example 8): v(t0) = m t0 / (n - n t0 + m t0). */
double pc_hspline_locus(double n, double m, double t0);
/* The parameter name of h ("n", "m", "t0", "c1", "c2", or "v" the junction ordinate g(t0)) into
 * *x: 1, or 0 for another name. */
int pc_hspline_field(const pc_hspline *h, const char *name, double *x);

/* Clamped smoothstep of examples 20-22 ("characteristic function"): 0 for t <= 0, 2t^2 on
 * [0, 1/2], 1 - 2(1 - t)^2 on [1/2, 1], 1 for t >= 1. */
double pc_smooth_clamp(double t);
/* The same as the listings write it, with strict inequalities only:
 *   if t < 0 then s = 0;  if t > 0 and t < .5 then s = 2t^2;
 *   if t > .5 and t < 1 then s = 1 - 2(1 - t)^2;  if t > 1 then s = 1
 * so at t exactly 0, 1/2 or 1 (and for NaN) s keeps its previous value: returns prev. */
double pc_smooth_clamp_qb(double t, double prev);

/* A smoothstep chosen at run time (what a spline piece blends with). */
typedef enum { PC_G_HALF, PC_G_CUBIC, PC_G_SINE, PC_G_LINEAR } pc_gkind;
typedef struct {
    pc_gkind kind;
    pc_hspline h;      /* used when kind == PC_G_HALF */
} pc_gfun;

double pc_gfun_eval(const pc_gfun *g, double t);
/* pc_hspline_check for a half-spline, PC_OK for the others (defined for every t). */
int pc_gfun_check(const pc_gfun *g, double t);

#endif
