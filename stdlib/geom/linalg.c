/* Small dense linear algebra: Gram-Schmidt, LU solve, determinant. */
#include "linalg.h"
#include "point.h"
#include <math.h>
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
