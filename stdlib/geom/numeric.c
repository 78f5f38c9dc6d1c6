/* Oresme lambda-functions and bisection (stepanov_examples.md examples 30, 31). */
#include "numeric.h"
#include <math.h>
#include <stdio.h>
#include "names.h"

int pc_oresme_fill(double lambda, int m, double y0, double y1, double *y) {
    if (m < 0 || m > PC_ORESME_MAXLEVEL) return PC_EDOMAIN;
    if (!isfinite(lambda) || !isfinite(y0) || !isfinite(y1)) return PC_ENONFINITE;
    long n = 1L << m;
    y[0] = y0;
    y[n] = y1;
    for (int i = 0; i < m; i++) {
        long s = n >> i;
        for (long j = 0; j <= n - s; j += s) y[j + s / 2] = lambda * y[j] + (1 - lambda) * y[j + s];
    }
    return PC_OK;
}

double pc_oresme_at(const double *y, int m, double t) {
    long n = 1L << m;
    double i = floor(t * (double)n);
    if (!(i > 0)) return y[0];   /* also NaN */
    if (i > (double)n) return y[n];
    return y[(long)i];
}

int pc_bisect(pc_scalar_fn f, void *ud, double a, double b, double tol, double *x, int *iters) {
    int count = 0;
    if (iters) *iters = 0;
    /* a NaN end never compares equal to the midpoint, so the loop below would not end */
    if (!isfinite(a) || !isfinite(b)) return PC_ENONFINITE;
    double fa = f(a, ud);
    if (!isfinite(fa)) return PC_ENONFINITE;
    if (fa == 0) {
        *x = a;
        return PC_OK;
    }
    double fb = f(b, ud);
    if (!isfinite(fb)) return PC_ENONFINITE;
    if (fb == 0) {
        *x = b;
        return PC_OK;
    }
    if ((fa < 0) == (fb < 0)) return PC_ENOBRACKET;
    double x0 = a, x1 = b, f0 = fa, mid;
    for (;;) {
        mid = (x0 + x1) / 2;
        if (count > 0 && (mid == x0 || mid == x1)) break;   /* the interval stopped shrinking */
        double fm = f(mid, ud);
        count++;
        if (!isfinite(fm)) {
            if (iters) *iters = count;
            return PC_ENONFINITE;
        }
        if (fm == 0) break;                                   /* an exact root */
        if ((fm < 0) != (f0 < 0)) {
            x1 = mid;
        } else {
            x0 = mid;
            f0 = fm;
        }
        if (fabs(x1 - x0) <= tol) break;
    }
    *x = mid;
    if (iters) *iters = count;
    return PC_OK;
}

/* ---- Newton's method for small systems (Korotky & Vitovtov solve (23) this way) ---------- */
#include <string.h>

static double maxabs(int n, const double *v) {
    double m = 0;
    for (int i = 0; i < n; i++) m = fmax(m, fabs(v[i]));
    return m;
}

/* Residuals at x; PC_ENONFINITE (and *bad) on the first NaN or infinity. */
static int residuals(pc_system_fn f, void *ud, int n, const double *x, double *r, int *bad) {
    int st = f(ud, x, r);
    if (st != PC_OK) return st;
    for (int i = 0; i < n; i++)
        if (!isfinite(r[i])) {
            if (bad) *bad = i;
            return PC_ENONFINITE;
        }
    return PC_OK;
}

/* Gaussian elimination with partial pivoting that says which unknown has no pivot. */
static int solve_pivot(int n, double *m, double *b, int *col) {
    double scale = 0;
    for (int i = 0; i < n * n; i++) scale = fmax(scale, fabs(m[i]));
    for (int c = 0; c < n; c++) {
        int p = c;
        for (int i = c + 1; i < n; i++)
            if (fabs(m[i * n + c]) > fabs(m[p * n + c])) p = i;
        if (!(fabs(m[p * n + c]) > 1e-13 * scale)) {
            *col = c;
            return PC_ESINGULAR;
        }
        if (p != c) {
            for (int j = 0; j < n; j++) {
                double t = m[c * n + j]; m[c * n + j] = m[p * n + j]; m[p * n + j] = t;
            }
            double t = b[c]; b[c] = b[p]; b[p] = t;
        }
        for (int i = c + 1; i < n; i++) {
            double q = m[i * n + c] / m[c * n + c];
            for (int j = c; j < n; j++) m[i * n + j] -= q * m[c * n + j];
            b[i] -= q * b[c];
        }
    }
    for (int i = n - 1; i >= 0; i--) {
        double s = b[i];
        for (int j = i + 1; j < n; j++) s -= m[i * n + j] * b[j];
        b[i] = s / m[i * n + i];
    }
    return PC_OK;
}

int pc_newton(int n, pc_system_fn f, void *ud, double *x, double tol, int maxit, int *iters,
              int *worst) {
    if (iters) *iters = 0;
    if (worst) *worst = -1;
    if (n < 1 || n > PC_NEWTON_MAXN) return PC_EDIM;
    for (int i = 0; i < n; i++)
        if (!isfinite(x[i])) {
            if (worst) *worst = i;
            return PC_ENONFINITE;
        }
    if (!(tol > 0)) tol = 1e-12;
    double r[PC_NEWTON_MAXN], rt[PC_NEWTON_MAXN], xt[PC_NEWTON_MAXN], dx[PC_NEWTON_MAXN];
    double J[PC_NEWTON_MAXN * PC_NEWTON_MAXN];
    int st = residuals(f, ud, n, x, r, worst);
    if (st != PC_OK) return st;
    double norm = maxabs(n, r);
    for (int it = 1; it <= maxit; it++) {
        if (iters) *iters = it;
        if (norm == 0) return PC_OK;
        for (int j = 0; j < n; j++) {   /* forward differences, one column per unknown */
            double e = 1e-7 * fmax(1, fabs(x[j]));
            memcpy(xt, x, sizeof(double) * (size_t)n);
            xt[j] += e;
            st = residuals(f, ud, n, xt, rt, worst);
            if (st != PC_OK) return st;
            for (int i = 0; i < n; i++) J[i * n + j] = (rt[i] - r[i]) / e;
        }
        for (int i = 0; i < n; i++) dx[i] = -r[i];
        int col = 0;
        if (solve_pivot(n, J, dx, &col) != PC_OK) {
            if (worst) *worst = col;
            return PC_ESINGULAR;
        }
        /* step halving: the full step first; accept the first step that does not raise max|f| */
        double a = 1, tnorm = norm;
        for (int k = 0; k < 30; k++, a *= .5) {
            for (int i = 0; i < n; i++) xt[i] = x[i] + a * dx[i];
            st = residuals(f, ud, n, xt, rt, NULL);
            if (st != PC_OK && st != PC_ENONFINITE) return st;
            tnorm = st == PC_OK ? maxabs(n, rt) : INFINITY;
            if (tnorm <= norm) break;
        }
        if (!(tnorm <= norm)) break;    /* no step lowers the residual: give up */
        int small = 1;
        for (int i = 0; i < n; i++) {
            if (fabs(a * dx[i]) > tol * (1 + fabs(x[i]))) small = 0;
            x[i] = xt[i];
            r[i] = rt[i];
        }
        norm = tnorm;
        if (small) return PC_OK;
    }
    if (worst) {
        int w = 0;
        for (int i = 1; i < n; i++)
            if (fabs(r[i]) > fabs(r[w])) w = i;
        *worst = w;
    }
    return PC_ENOCONVERGE;
}

/* f with its calls watched: the last x and f(x), and f(a), f(b) (the first two calls) */
typedef struct {
    pc_scalar_fn f;
    void *ud;
    int calls;
    double x, y, ends[2];
} watched_fn;

static double watch(double x, void *ud) {
    watched_fn *w = ud;
    w->x = x;
    w->y = w->f(x, w->ud);
    if (w->calls < 2) w->ends[w->calls] = w->y;
    w->calls++;
    return w->y;
}

int pc_bisect_why(pc_scalar_fn f, void *ud, double a, double b, double tol, double *x, int *iters,
                  char *why, size_t n) {
    watched_fn w = {.f = f, .ud = ud};
    int st = pc_bisect(watch, &w, a, b, tol, x, iters);
    char t[4][40];
    why[0] = 0;
    if (st == PC_ENOBRACKET)
        snprintf(why, n, "f(a) and f(b) have the same sign (f(%s) = %s, f(%s) = %s): the interval "
                 "brackets no root",
                 pc_num_text(a, t[0], 40), pc_num_text(w.ends[0], t[1], 40), pc_num_text(b, t[2], 40),
                 pc_num_text(w.ends[1], t[3], 40));
    else if (st == PC_ENONFINITE && !w.calls)
        snprintf(why, n, "the ends a and b must be finite numbers");
    else if (st == PC_ENONFINITE)
        snprintf(why, n, "f(%s) must return a finite number, got %s", pc_num_text(w.x, t[0], 40),
                 pc_num_text(w.y, t[1], 40));
    return st;
}
