/* Affine maps by point correspondences, frames, composition and inverse. */
#include "affine.h"
#include "linalg.h"
#include <math.h>
#include <string.h>

void pc_affine_identity(pc_affine *f, int n) {
    memset(f, 0, sizeof *f);
    f->nin = f->nout = n;
    for (int i = 0; i < n; i++) PC_AFFINE_AT(f, i, i) = 1.0;
}

int pc_affine_from_points(pc_affine *f, int nin, int nout, const double *src, const double *dst) {
    if (nin < 1 || nout < 1 || nin > PC_MAXDIM || nout > PC_MAXDIM) return PC_EDIM;
    /* edges E_i = S_i - S_0 (rows), F_i = D_i - D_0; M E_i = F_i for all i, i.e.
     * M = F^T E^-T.  With E^T = Q R (columns, pc_qr): M = F^T R^-1 Q, then t = D_0 - M S_0. */
    double e[PC_MAXDIM * PC_MAXDIM], q[PC_MAXDIM * PC_MAXDIM], r[PC_MAXDIM * PC_MAXDIM];
    for (int i = 0; i < nin; i++)
        for (int j = 0; j < nin; j++) e[i * nin + j] = src[(i + 1) * nin + j] - src[j];
    int st = pc_qr(nin, nin, e, q, r, PC_DEGEN_TOL);
    if (st != PC_OK) return st;
    memset(f, 0, sizeof *f);
    f->nin = nin;
    f->nout = nout;
    for (int o = 0; o < nout; o++) {
        /* row o of M: solve x^T R^-1 with x_i = F_i[o], i.e. R^T y = x, then row = y^T Q */
        double y[PC_MAXDIM];
        for (int i = 0; i < nin; i++) {
            double t = dst[(i + 1) * nout + o] - dst[o];
            for (int j = 0; j < i; j++) t -= r[j * nin + i] * y[j];
            y[i] = t / r[i * nin + i];
        }
        double tr = dst[o];
        for (int c = 0; c < nin; c++) {
            double s = 0;
            for (int i = 0; i < nin; i++) s += y[i] * q[i * nin + c];
            PC_AFFINE_AT(f, o, c) = s;
            tr -= s * src[c];
        }
        PC_AFFINE_AT(f, o, nin) = tr;
    }
    return PC_OK;
}

int pc_affine_frame(pc_affine *f, int nout, int naxes, const double *o, const double *axes) {
    if (naxes < 1 || nout < 1 || naxes > PC_MAXDIM || nout > PC_MAXDIM) return PC_EDIM;
    memset(f, 0, sizeof *f);
    f->nin = naxes;
    f->nout = nout;
    for (int i = 0; i < nout; i++) {
        for (int j = 0; j < naxes; j++) PC_AFFINE_AT(f, i, j) = axes[j * nout + i];
        PC_AFFINE_AT(f, i, naxes) = o[i];
    }
    return PC_OK;
}

void pc_affine_apply(const pc_affine *f, const double *in, double *out) {
    int nin = f->nin;
    double w = in[nin], tmp[PC_MAXDIM + 1];
    for (int i = 0; i < f->nout; i++) {
        const double *row = f->m + i * (nin + 1);
        double s = row[nin] * w;
        for (int j = 0; j < nin; j++) s += row[j] * in[j];
        tmp[i] = s;
    }
    tmp[f->nout] = w;
    memcpy(out, tmp, sizeof(double) * (size_t)(f->nout + 1));
}

int pc_affine_compose(const pc_affine *f, const pc_affine *g, pc_affine *h) {
    if (g->nout != f->nin) return PC_EDIM;
    pc_affine r;
    memset(&r, 0, sizeof r);
    r.nin = g->nin;
    r.nout = f->nout;
    int mid = f->nin;
    for (int i = 0; i < r.nout; i++) {
        for (int j = 0; j <= r.nin; j++) {
            double s = (j == r.nin) ? PC_AFFINE_AT(f, i, mid) : 0.0;
            for (int l = 0; l < mid; l++) s += PC_AFFINE_AT(f, i, l) * PC_AFFINE_AT(g, l, j);
            PC_AFFINE_AT(&r, i, j) = s;
        }
    }
    *h = r;
    return PC_OK;
}

int pc_affine_inverse(const pc_affine *f, pc_affine *inv) {
    int n = f->nin;
    if (f->nout != n) return PC_EDIM;
    pc_affine r;
    memset(&r, 0, sizeof r);
    r.nin = r.nout = n;
    /* solve M X = I column by column; then t' = -M^-1 t */
    for (int c = 0; c < n; c++) {
        double m[PC_MAXDIM * PC_MAXDIM], b[PC_MAXDIM];
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) m[i * n + j] = PC_AFFINE_AT(f, i, j);
            b[i] = (i == c);
        }
        int st = pc_lu_solve(n, m, b);
        if (st != PC_OK) return st;
        for (int i = 0; i < n; i++) PC_AFFINE_AT(&r, i, c) = b[i];
    }
    for (int i = 0; i < n; i++) {
        double s = 0;
        for (int j = 0; j < n; j++) s -= PC_AFFINE_AT(&r, i, j) * PC_AFFINE_AT(f, j, n);
        PC_AFFINE_AT(&r, i, n) = s;
    }
    *inv = r;
    return PC_OK;
}
