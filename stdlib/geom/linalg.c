/* Small dense linear algebra: Gram-Schmidt, LU solve, determinant; tridiagonal systems. */
#include "linalg.h"
#include "point.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

int pc_qr(int n, int k, const double *e, double *q, double *r, double tol) {
    if (k > n) return PC_EDIM;
    memset(r, 0, sizeof(double) * (size_t)k * (size_t)k);
    for (int i = 0; i < k; i++) {
        double *qi = q + (size_t)i * n;
        memcpy(qi, e + (size_t)i * n, sizeof(double) * (size_t)n);
        double len0 = pc_norm(n, qi);
        if (len0 == 0.0) return PC_ECOINCIDENT;
        for (int pass = 0; pass < 2; pass++) {          /* "twice is enough" */
            for (int j = 0; j < i; j++) {
                const double *qj = q + (size_t)j * n;
                double c = pc_dot(n, qj, qi);
                r[j * k + i] += c;
                for (int d = 0; d < n; d++) qi[d] -= c * qj[d];
            }
        }
        double len = pc_norm(n, qi);
        if (!(len > tol * len0)) return PC_ECOLLINEAR;
        r[i * k + i] = len;
        for (int d = 0; d < n; d++) qi[d] /= len;
    }
    return PC_OK;
}

int pc_lu_solve(int k, double *m, double *b) {
    double scale = 0;
    for (int i = 0; i < k * k; i++) scale = fmax(scale, fabs(m[i]));
    if (!(scale > 0)) return PC_ESINGULAR;
    for (int c = 0; c < k; c++) {
        int p = c;
        for (int i = c + 1; i < k; i++)
            if (fabs(m[i * k + c]) > fabs(m[p * k + c])) p = i;
        if (!(fabs(m[p * k + c]) > PC_DEGEN_TOL * scale)) return PC_ESINGULAR;
        if (p != c) {
            for (int j = 0; j < k; j++) {
                double t = m[c * k + j]; m[c * k + j] = m[p * k + j]; m[p * k + j] = t;
            }
            double t = b[c]; b[c] = b[p]; b[p] = t;
        }
        for (int i = c + 1; i < k; i++) {
            double f = m[i * k + c] / m[c * k + c];
            if (f == 0) continue;
            for (int j = c; j < k; j++) m[i * k + j] -= f * m[c * k + j];
            b[i] -= f * b[c];
        }
    }
    for (int i = k - 1; i >= 0; i--) {
        double s = b[i];
        for (int j = i + 1; j < k; j++) s -= m[i * k + j] * b[j];
        b[i] = s / m[i * k + i];
    }
    return PC_OK;
}

double pc_det(int k, const double *m0) {
    double m[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)];
    memcpy(m, m0, sizeof(double) * (size_t)k * (size_t)k);
    double det = 1;
    for (int c = 0; c < k; c++) {
        int p = c;
        for (int i = c + 1; i < k; i++)
            if (fabs(m[i * k + c]) > fabs(m[p * k + c])) p = i;
        if (m[p * k + c] == 0) return 0;
        if (p != c) {
            for (int j = 0; j < k; j++) {
                double t = m[c * k + j]; m[c * k + j] = m[p * k + j]; m[p * k + j] = t;
            }
            det = -det;
        }
        det *= m[c * k + c];
        for (int i = c + 1; i < k; i++) {
            double f = m[i * k + c] / m[c * k + c];
            for (int j = c; j < k; j++) m[i * k + j] -= f * m[c * k + j];
        }
    }
    return det;
}

/* Thomas algorithm on rows 0..n-1 (a[0], c[n-1] unused); cp: n scratch values */
static int thomas(int n, int nrhs, const double *a, const double *b, const double *c, double *d,
                  double *cp, double small) {
    for (int i = 0; i < n; i++) {
        double piv = b[i] - (i > 0 ? a[i] * cp[i - 1] : 0);
        if (!(fabs(piv) > small)) return PC_ESINGULAR;
        cp[i] = i + 1 < n ? c[i] / piv : 0;
        for (int r = 0; r < nrhs; r++)
            d[i * nrhs + r] = (d[i * nrhs + r] - (i > 0 ? a[i] * d[(i - 1) * nrhs + r] : 0)) / piv;
    }
    for (int i = n - 2; i >= 0; i--)
        for (int r = 0; r < nrhs; r++) d[i * nrhs + r] -= cp[i] * d[(i + 1) * nrhs + r];
    return PC_OK;
}

int pc_tridiag_solve(int n, int nrhs, const double *a, const double *b, const double *c,
                     double *d, int cyclic) {
    if (n < 1 || nrhs < 1) return PC_EDIM;
    double scale = 0;
    for (int i = 0; i < n; i++) {
        double ai = (i > 0 || cyclic) ? a[i] : 0, ci = (i + 1 < n || cyclic) ? c[i] : 0;
        if (!isfinite(ai) || !isfinite(b[i]) || !isfinite(ci)) return PC_ENONFINITE;
        scale = fmax(scale, fmax(fabs(ai), fmax(fabs(b[i]), fabs(ci))));
    }
    for (int i = 0; i < n * nrhs; i++)
        if (!isfinite(d[i])) return PC_ENONFINITE;
    double small = PC_DEGEN_TOL * scale;
    if (!(scale > 0)) return PC_ESINGULAR;
    if (cyclic && n <= 2) {           /* the corner entries fold onto the others */
        if (n == 1) {
            double s = a[0] + b[0] + c[0];
            if (!(fabs(s) > small)) return PC_ESINGULAR;
            for (int r = 0; r < nrhs; r++) d[r] /= s;
            return PC_OK;
        }
        double m00 = b[0], m01 = a[0] + c[0], m10 = a[1] + c[1], m11 = b[1];
        double det = m00 * m11 - m01 * m10;
        if (!(fabs(det) > small * scale)) return PC_ESINGULAR;
        for (int r = 0; r < nrhs; r++) {
            double y0 = d[r], y1 = d[nrhs + r];
            d[r] = (m11 * y0 - m01 * y1) / det;
            d[nrhs + r] = (m00 * y1 - m10 * y0) / det;
        }
        return PC_OK;
    }
    double *work = malloc(sizeof(double) * (size_t)n * (cyclic ? 3 : 1));
    if (!work) return PC_ENOMEM;
    int st;
    if (!cyclic) {
        st = thomas(n, nrhs, a, b, c, d, work, small);
    } else {
        /* A = T + u v^T with u = (g, 0, ..., 0, alpha), v = (1, 0, ..., 0, beta/g) */
        double *bb = work + n, *z = bb + n;
        double beta = a[0], alpha = c[n - 1], g = b[0] != 0 ? -b[0] : -scale;
        memcpy(bb, b, sizeof(double) * (size_t)n);
        bb[0] = b[0] - g;
        bb[n - 1] = b[n - 1] - alpha * beta / g;
        st = thomas(n, nrhs, a, bb, c, d, work, small);
        if (!st) {
            memset(z, 0, sizeof(double) * (size_t)n);
            z[0] = g;
            z[n - 1] = alpha;
            st = thomas(n, 1, a, bb, c, z, work, small);
        }
        if (!st) {
            double den = 1 + z[0] + beta * z[n - 1] / g;
            if (!(fabs(den) > PC_DEGEN_TOL)) st = PC_ESINGULAR;
            for (int r = 0; !st && r < nrhs; r++) {
                double f = (d[r] + beta * d[(n - 1) * nrhs + r] / g) / den;
                for (int i = 0; i < n; i++) d[i * nrhs + r] -= f * z[i];
            }
        }
    }
    free(work);
    return st;
}

int pc_lsq_solve(int m, int n, double *a, double *b) {
    if (n < 1 || m < n) return PC_EDIM;
    double scale = 0;
    for (int i = 0; i < m; i++) {
        if (!isfinite(b[i])) return PC_ENONFINITE;
        for (int j = 0; j < n; j++) {
            if (!isfinite(a[(size_t)i * n + j])) return PC_ENONFINITE;
        }
    }
    for (int j = 0; j < n; j++) {                      /* the largest column norm */
        double s = 0;
        for (int i = 0; i < m; i++) s = hypot(s, a[(size_t)i * n + j]);
        scale = fmax(scale, s);
    }
    if (!(scale > 0)) return PC_ESINGULAR;
    for (int k = 0; k < n; k++) {
        /* the reflection H = I - 2 v v^T / (v^T v) sending column k below the diagonal to 0 */
        double norm = 0;
        for (int i = k; i < m; i++) norm = hypot(norm, a[(size_t)i * n + k]);
        if (!(norm > PC_DEGEN_TOL * scale)) return PC_ESINGULAR;
        double akk = a[(size_t)k * n + k];
        double alpha = akk > 0 ? -norm : norm;         /* no cancellation in v_k = akk - alpha */
        double vk = akk - alpha, vtv = vk * vk;
        for (int i = k + 1; i < m; i++) vtv += a[(size_t)i * n + k] * a[(size_t)i * n + k];
        a[(size_t)k * n + k] = vk;                      /* v is column k from row k on */
        for (int j = k + 1; j <= n; j++) {             /* j == n: the right-hand side */
            double s = 0;
            for (int i = k; i < m; i++) s += a[(size_t)i * n + k] * (j < n ? a[(size_t)i * n + j] : b[i]);
            s = 2 * s / vtv;
            for (int i = k; i < m; i++) {
                if (j < n) a[(size_t)i * n + j] -= s * a[(size_t)i * n + k];
                else b[i] -= s * a[(size_t)i * n + k];
            }
        }
        a[(size_t)k * n + k] = alpha;                  /* R's diagonal */
    }
    for (int i = n - 1; i >= 0; i--) {                 /* R x = Q^T b */
        double s = b[i];
        for (int j = i + 1; j < n; j++) s -= a[(size_t)i * n + j] * b[j];
        b[i] = s / a[(size_t)i * n + i];
    }
    return PC_OK;
}
