/* The optimal-node search of Konopatsky's chapter 5 (approx.h). */
#include <math.h>
#include <string.h>
#include "approx.h"
#include "status.h"

/* ---- the book's approximation measure -------------------------------------------------------- */

pc_curve *pc_approx_curve(pc_scalar_fn f, void *ud, int N, const double *x, int *bad, int *status) {
    double p[128];
    if (N < 2 || N > 64) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    for (int j = 0; j < N; j++) {
        p[2 * j] = x[j], p[2 * j + 1] = f(x[j], ud);
        if (!isfinite(p[2 * j + 1])) {
            *bad = j;
            *status = PC_ENONFINITE;
            return NULL;
        }
    }
    return pc_curve_interpolate(2, N, p, NULL, status);
}

int pc_approx_mse(pc_scalar_fn f, void *ud, int N, const double *x, int m, double *mse) {
    if (N < 2 || N > 64 || m < 1) return PC_EDOMAIN;
    double y[64], sse = 0;
    for (int j = 0; j < N; j++) {
        y[j] = f(x[j], ud);
        if (!isfinite(y[j]) || !isfinite(x[j])) return PC_ENONFINITE;
    }
    for (int i = 0; i <= m; i++) {
        double t = (double)i / m, xt = 0, yt = 0;
        for (int j = 0; j < N; j++) {          /* Lagrange weights on t_j = j/(N-1) */
            double w = 1, tj = (double)j / (N - 1);
            for (int q = 0; q < N; q++)
                if (q != j) w *= (t - (double)q / (N - 1)) / (tj - (double)q / (N - 1));
            xt += w * x[j], yt += w * y[j];
        }
        double r = f(xt, ud) - yt;
        if (!isfinite(r)) return PC_ENONFINITE;
        sse += r * r;
    }
    *mse = sse / (m + 1);
    return PC_OK;
}

int pc_approx_rescale(double mse, int m, pc_mse_divisor d, double *out) {
    double div = d == PC_MSE_DIV_M ? m : d == PC_MSE_DIV_MMINUS1 ? m - 1 : m + 1;
    if (!(div > 0)) return PC_EDOMAIN;
    *out = mse * (m + 1) / div;
    return PC_OK;
}

typedef struct {
    pc_scalar_fn f;
    void *ud;
    double a, b;
    int N, m, evals, failed;
} nodes_problem;

/* inner nodes from z (N-2 values): gaps softmax(0, z_1, ..., z_(N-2)) of the N-1 spans */
static void z_to_nodes(const nodes_problem *q, const double *z, double *x) {
    double e[64], s = 1, mx = 0;
    for (int i = 0; i < q->N - 2; i++) mx = fmax(mx, z[i]);
    e[0] = exp(-mx), s = e[0];
    for (int i = 0; i < q->N - 2; i++) e[i + 1] = exp(z[i] - mx), s += e[i + 1];
    x[0] = q->a;
    double c = 0;
    for (int i = 0; i < q->N - 1; i++) {
        c += e[i] / s;
        x[i + 1] = q->a + (q->b - q->a) * c;
    }
    x[q->N - 1] = q->b;
}

static void nodes_to_z(const nodes_problem *q, const double *x, double *z) {
    double g0 = x[1] - x[0];
    for (int i = 0; i < q->N - 2; i++) z[i] = log((x[i + 2] - x[i + 1]) / g0);
}

static double nodes_objective(void *ud, const double *z) {
    nodes_problem *q = ud;
    double x[64], mse;
    q->evals++;
    z_to_nodes(q, z, x);
    int st = pc_approx_mse(q->f, q->ud, q->N, x, q->m, &mse);
    if (st) {
        q->failed = st;
        return INFINITY;
    }
    return mse;
}

int pc_approx_optimal_nodes(pc_scalar_fn f, void *ud, double a, double b, int N, int m,
                            double *nodes, double *mse, int *evals) {
    if (N < 3 || N > 16 || m < N) return PC_EDOMAIN;
    if (!isfinite(a) || !isfinite(b)) return PC_ENONFINITE;
    if (!(b > a)) return PC_EDOMAIN;
    nodes_problem q = {f, ud, a, b, N, m, 0, 0};
    int nz = N - 2;
    double best_z[64], best = INFINITY;
    for (int start = 0; start < 3; start++) {
        double x[64], z[64], fz;
        for (int j = 0; j < N; j++) {
            double s = (double)j / (N - 1);
            if (start == 1) s = 0.5 - 0.5 * cos(M_PI * s);                 /* Chebyshev-like */
            else if (start == 2) s = 0.5 + 0.5 * (2 * s - 1) * fabs(2 * s - 1); /* to the middle */
            x[j] = a + (b - a) * s;
        }
        nodes_to_z(&q, x, z);
        fz = nodes_objective(&q, z);
        if (q.failed) return q.failed;
        double step = 0.5, prev = fz;
        int budget = q.evals + 40000;     /* objective calls per start */
        for (int round = 0; round < 40 && q.evals < budget; round++) {
            pc_nelder_mead(nz, nodes_objective, &q, z, step, 1e-13, 1e-10, 4000, &fz, NULL);
            if (q.failed) return q.failed;
            if (round > 0 && !(fz < prev * (1 - 1e-9))) break;    /* no improvement: stop */
            prev = fz;
            step = fmax(step * 0.5, 1e-4);
        }
        if (fz < best) {
            best = fz;
            memcpy(best_z, z, sizeof(double) * (size_t)nz);
        }
    }
    z_to_nodes(&q, best_z, nodes);
    *mse = best;
    if (evals) *evals = q.evals;
    return PC_OK;
}

int pc_chebyshev_nodes(int N, double a, double b, double *x) {
    if (!(b > a) || N < 1) return PC_EDOMAIN;
    for (int k = 0; k < N; k++) {
        double c = cos((2.0 * (N - 1 - k) + 1) * M_PI / (2.0 * N));   /* increasing */
        x[k] = 0.5 * (a + b) + 0.5 * (b - a) * c;
    }
    return PC_OK;
}

int pc_lagrange_mse_x(pc_scalar_fn f, void *ud, int N, const double *x, double a, double b,
                      int M, double *mse) {
    if (N < 1 || N > 64 || M < 2) return PC_EDOMAIN;
    double y[64], s = 0;
    for (int j = 0; j < N; j++) {
        y[j] = f(x[j], ud);
        if (!isfinite(y[j])) return PC_ENONFINITE;
        for (int q = 0; q < j; q++)
            if (x[q] == x[j]) return PC_ECOINCIDENT;
    }
    for (int i = 0; i < M; i++) {
        double xi = a + (b - a) * i / (M - 1), p = 0;
        for (int j = 0; j < N; j++) {
            double w = 1;
            for (int q = 0; q < N; q++)
                if (q != j) w *= (xi - x[q]) / (x[j] - x[q]);
            p += w * y[j];
        }
        double r = p - f(xi, ud);
        if (!isfinite(r)) return PC_ENONFINITE;
        s += r * r;
    }
    *mse = s / M;
    return PC_OK;
}
