/* Simplex: evaluation by natural and barycentric parameters, recovery of the parameters of a
 * point in any ambient dimension, measure, and the S/V-theorem ratio. */
#include "simplex.h"
#include "linalg.h"
#include <math.h>
#include <string.h>

size_t pc_simplex_size(int n, int k) {
    return sizeof(pc_simplex) + sizeof(double) * (size_t)((k + 1) * n + k * n + k * k);
}

int pc_simplex_init(pc_simplex *s, int n, int k, const double *vertices) {
    if (n < 1 || k < 1 || n > PC_MAXDIM || k > n) return PC_EDIM;
    s->n = n;
    s->k = k;
    double *v = PC_SIMPLEX_V(s);
    memcpy(v, vertices, sizeof(double) * (size_t)((k + 1) * n));
    double e[PC_MAXDIM * PC_MAXDIM];
    for (int i = 0; i < k; i++)
        for (int j = 0; j < n; j++) e[i * n + j] = v[(i + 1) * n + j] - v[j];
    /* independence (§4.3): the edges from the initial point must span a k-flat */
    return pc_qr(n, k, e, PC_SIMPLEX_Q(s), PC_SIMPLEX_R(s), PC_DEGEN_TOL);
}

void pc_simplex_eval(const pc_simplex *s, const double *p, double *out) {
    int n = s->n, k = s->k;
    const double *v = PC_SIMPLEX_V(s);
    for (int j = 0; j < n; j++) {
        double c = v[j], x = c;
        for (int i = 0; i < k; i++) x += (v[(i + 1) * n + j] - c) * p[i];
        out[j] = x;
    }
}

void pc_simplex_bary(const pc_simplex *s, const double *c, double *out) {
    int n = s->n, k = s->k;
    const double *v = PC_SIMPLEX_V(s);
    double w = c[k];
    for (int j = 0; j < n; j++) out[j] = v[j] * c[k];
    for (int i = 0; i < k; i++) {
        w += c[i];
        for (int j = 0; j < n; j++) out[j] += v[(i + 1) * n + j] * c[i];
    }
    out[n] = w;
}

void pc_simplex_params(const pc_simplex *s, const double *m, double *p, double *residual) {
    int n = s->n, k = s->k;
    const double *v = PC_SIMPLEX_V(s), *q = PC_SIMPLEX_Q(s), *r = PC_SIMPLEX_R(s);
    double w[PC_MAXDIM], y[PC_MAXDIM];
    for (int j = 0; j < n; j++) w[j] = m[j] - v[j];
    /* least squares: the edges as columns are E = Q R (pc_qr), so E p = w gives R p = Q^T w */
    for (int i = 0; i < k; i++) y[i] = pc_dot(n, q + i * n, w);
    for (int i = 0; i < k; i++) {                       /* w - Q^T y: out of the flat */
        const double *qi = q + i * n;
        for (int j = 0; j < n; j++) w[j] -= y[i] * qi[j];
    }
    /* back substitution in the upper triangular R (r[i*k+j] = <q_i, e_j>, j >= i) */
    for (int i = k - 1; i >= 0; i--) {
        double t = y[i];
        for (int j = i + 1; j < k; j++) t -= r[i * k + j] * p[j];
        p[i] = t / r[i * k + i];
    }
    if (residual) *residual = pc_norm(n, w);
}

double pc_simplex_measure(const pc_simplex *s) {
    int n = s->n, k = s->k;
    const double *v = PC_SIMPLEX_V(s), *r = PC_SIMPLEX_R(s);
    double fact = 1;
    for (int i = 2; i <= k; i++) fact *= i;
    if (k == n) {
        double e[PC_MAXDIM * PC_MAXDIM];
        for (int i = 0; i < k; i++)
            for (int j = 0; j < n; j++) e[i * n + j] = v[(i + 1) * n + j] - v[j];
        return pc_det(k, e) / fact;
    }
    double m = 1;
    for (int i = 0; i < k; i++) m *= r[i * k + i];
    return m / fact;
}

double pc_simplex_ratio(const pc_simplex *s, const double *pts, double *residual) {
    int n = s->n, k = s->k, k1 = k + 1;
    double m[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)], res, worst = 0;
    /* rows (1, p_i, q_i, ...): the book's determinant of the parameters bordered by a
     * column of 1s.  The 1s go first so that the simplex's own vertices, in its order,
     * give +1 in every dimension; in 2-D this equals the book's det[p_i q_i 1]. */
    for (int i = 0; i < k1; i++) {
        m[i * k1] = 1.0;
        pc_simplex_params(s, pts + i * n, m + i * k1 + 1, &res);
        worst = fmax(worst, res);
    }
    if (residual) *residual = worst;
    return pc_det(k1, m);
}
