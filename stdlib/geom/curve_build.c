/* Curves built from nodes: the C2 cubic spline (Buimov §4.2: derivatives from a tridiagonal
 * system, then Hermite segments) and the polynomial interpolation curve (Konopatsky ch. 4:
 * the Bezier control points of the curve through the nodes, by Bernstein collocation). */
#include "curve_impl.h"
#include "linalg.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static pc_curve *fail_null(int *status, int st) {
    if (status) *status = st;
    return NULL;
}

/* The derivative equations at the nodes, for C2 joints (Buimov §4.2, with the printed
 * subscripts corrected as the digest says):
 *   h_i m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_{i-1} m_{i+1}
 *       = 3 [h_i (p_i - p_{i-1}) / h_{i-1} + h_{i-1} (p_{i+1} - p_i) / h_i],
 * h_i = u_{i+1} - u_i; natural ends 2 m_0 + m_1 = 3 (p_1 - p_0)/h_0 (and mirrored), clamped
 * ends m = the given derivative, periodic: the rows wrap around and m_{n-1} = m_0. */
pc_curve *pc_curve_cubic_spline(int dim, int n, const double *p, const double *u,
                                pc_end_kind ends, const double *d0, const double *d1,
                                int *status) {
    if (dim < 1 || dim > PC_MAXDIM || n < 2 || (ends == PC_END_PERIODIC && n < 3) || n > (1 << 26))
        return fail_null(status, PC_EDIM);
    if (ends != PC_END_NATURAL && ends != PC_END_CLAMPED && ends != PC_END_PERIODIC)
        return fail_null(status, PC_EARG);
    if (!p || (ends == PC_END_CLAMPED && (!d0 || !d1))) return fail_null(status, PC_EARG);
    if (!pcc_finite((size_t)n * dim, p) || (u && !pcc_finite((size_t)n, u)) ||
        (ends == PC_END_CLAMPED && (!pcc_finite((size_t)dim, d0) || !pcc_finite((size_t)dim, d1))))
        return fail_null(status, PC_ENONFINITE);
    if (ends == PC_END_PERIODIC) {
        double scale = 0, gap = 0;
        for (int x = 0; x < n * dim; x++) scale = fmax(scale, fabs(p[x]));
        for (int x = 0; x < dim; x++) gap = fmax(gap, fabs(p[(n - 1) * dim + x] - p[x]));
        if (gap > 1e-12 * scale) return fail_null(status, PC_EDOMAIN);
    }
    int N = ends == PC_END_PERIODIC ? n - 1 : n, st = PC_OK;
    double *U = malloc(sizeof(double) * (size_t)n), *h = malloc(sizeof(double) * (size_t)n);
    double *a = malloc(sizeof(double) * (size_t)N * 3), *m = malloc(sizeof(double) * (size_t)n * dim);
    pc_curve *c = NULL;
    if (!U || !h || !a || !m) {
        st = PC_ENOMEM;
        goto done;
    }
    double *b = a + N, *cc = b + N;
    U[0] = u ? u[0] : 0;
    for (int i = 0; i + 1 < n; i++) {
        U[i + 1] = u ? u[i + 1] : U[i] + pc_dist(dim, p + i * dim, p + (i + 1) * dim);
        h[i] = U[i + 1] - U[i];
        if (!(h[i] > 0)) {
            st = u ? PC_EDOMAIN : PC_ECOINCIDENT;
            goto done;
        }
    }
    if (!isfinite(U[n - 1])) {
        st = PC_ENONFINITE;
        goto done;
    }
    for (int i = 0; i < N; i++) {
        double *r = m + i * dim;
        if (ends != PC_END_PERIODIC && (i == 0 || i == n - 1)) {
            int first = i == 0;
            if (ends == PC_END_CLAMPED) {
                a[i] = cc[i] = 0;
                b[i] = 1;
                memcpy(r, first ? d0 : d1, sizeof(double) * dim);
            } else {
                double hh = first ? h[0] : h[n - 2];
                const double *q0 = p + (first ? 0 : n - 2) * dim, *q1 = q0 + dim;
                a[i] = first ? 0 : 1;
                cc[i] = first ? 1 : 0;
                b[i] = 2;
                for (int x = 0; x < dim; x++) r[x] = 3 * (q1[x] - q0[x]) / hh;
            }
            continue;
        }
        int ip = (i - 1 + N) % N;      /* for periodic rows, node -1 is node n-2 */
        double hp = h[ip], hn = h[i];
        const double *pp = p + ip * dim, *pi = p + i * dim, *pn = p + (i + 1) * dim;
        a[i] = hn;
        b[i] = 2 * (hp + hn);
        cc[i] = hp;
        for (int x = 0; x < dim; x++)
            r[x] = 3 * (hn * (pi[x] - pp[x]) / hp + hp * (pn[x] - pi[x]) / hn);
    }
    if ((st = pc_tridiag_solve(N, dim, a, b, cc, m, ends == PC_END_PERIODIC))) goto done;
    if (ends == PC_END_PERIODIC) memcpy(m + (n - 1) * dim, m, sizeof(double) * dim);
    c = pc_curve_hermite(dim, n, p, m, NULL, U, 0, &st);
    if (c) c->closed = ends == PC_END_PERIODIC;
done:
    free(U);
    free(h);
    free(a);
    free(m);
    if (status) *status = st;
    return c;
}

/* Bernstein basis of degree deg at s into B (deg + 1 values) */
static void bernstein(int deg, double s, double *B) {
    B[0] = 1;
    for (int k = 1; k <= deg; k++) {
        double saved = 0;
        for (int i = 0; i < k; i++) {
            double t = B[i];
            B[i] = saved + (1 - s) * t;
            saved = s * t;
        }
        B[k] = saved;
    }
}

pc_curve *pc_curve_interpolate(int dim, int n, const double *p, const double *u, int *status) {
    if (dim < 1 || dim > PC_MAXDIM || n < 2 || n > PC_CURVE_MAXDEG + 1)
        return fail_null(status, PC_EDIM);
    if (!p) return fail_null(status, PC_EARG);
    if (!pcc_finite((size_t)n * dim, p) || (u && !pcc_finite((size_t)n, u)))
        return fail_null(status, PC_ENONFINITE);
    double lo = u ? u[0] : 0, hi = u ? u[0] : 1;
    for (int i = 0; u && i < n; i++) {
        lo = fmin(lo, u[i]);
        hi = fmax(hi, u[i]);
        for (int j = 0; j < i; j++)
            if (u[j] == u[i]) return fail_null(status, PC_ECOINCIDENT);
    }
    int deg = n - 1, w = dim + 1, st = PC_OK;
    double *M = malloc(sizeof(double) * (size_t)n * n * 2), *cp = malloc(sizeof(double) * (size_t)n * w);
    double rhs[PCC_ROWS];
    pc_curve *c = NULL;
    if (!M || !cp) {
        st = PC_ENOMEM;
        goto done;
    }
    double *work = M + n * n;
    for (int j = 0; j < n; j++) {
        double s = u ? (u[j] - lo) / (hi - lo) : (double)j / deg;
        bernstein(deg, s, M + j * n);
    }
    for (int x = 0; x < dim; x++) {
        memcpy(work, M, sizeof(double) * (size_t)n * n);
        for (int j = 0; j < n; j++) rhs[j] = p[j * dim + x];
        if ((st = pc_lu_solve(n, work, rhs))) goto done;
        for (int i = 0; i < n; i++) cp[i * w + x] = rhs[i];
    }
    for (int i = 0; i < n; i++) cp[i * w + dim] = 1;
    if (!pcc_finite((size_t)n * w, cp)) {
        st = PC_ENONFINITE;
        goto done;
    }
    double brk[2] = {lo, hi};
    c = pc_curve_bezier_pieces(dim, deg, 1, cp, brk, &st);
done:
    free(M);
    free(cp);
    if (status) *status = st;
    return c;
}
