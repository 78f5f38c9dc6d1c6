/* The one map type: projective maps of homogeneous coordinates (map.h).  Affine maps keep the
 * last row (0 ... 0 | 1) exactly through composition and inversion, so an affine map stays
 * affine and keeps weights; projective results are scaled so that their corner entry is 1
 * when it is not 0 (a scale of the whole matrix does not change the map). */
#include "map.h"
#include "linalg.h"
#include <math.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

static void blank(pc_map *f, int nin, int nout) {
    memset(f, 0, sizeof *f);
    f->nin = nin;
    f->nout = nout;
}

static int dim_ok(int n) { return n >= 1 && n <= PC_MAXDIM; }

void pc_map_identity(pc_map *f, int n) {
    blank(f, n, n);
    for (int i = 0; i <= n; i++) PC_MAP_AT(f, i, i) = 1.0;
}

/* Divide the whole matrix by its corner when that is neither 0 nor 1. */
static void normalise(pc_map *f) {
    double s = PC_MAP_AT(f, f->nout, f->nin);
    if (s == 0.0 || s == 1.0) return;
    for (int i = 0; i <= f->nout; i++)
        for (int j = 0; j <= f->nin; j++) PC_MAP_AT(f, i, j) /= s;
    PC_MAP_AT(f, f->nout, f->nin) = 1.0;
}

int pc_map_from_matrix(pc_map *f, int nin, int nout, const double *a, int rowvec) {
    if (!dim_ok(nin) || !dim_ok(nout)) return PC_EDIM;
    pc_map r;
    blank(&r, nin, nout);
    int any = 0;
    for (int i = 0; i <= nout; i++)
        for (int j = 0; j <= nin; j++) {
            double v = rowvec ? a[j * (nout + 1) + i] : a[i * (nin + 1) + j];
            if (!isfinite(v)) return PC_ENONFINITE;
            if (v != 0.0) any = 1;
            PC_MAP_AT(&r, i, j) = v;
        }
    if (!any) return PC_ESINGULAR;
    /* the textbook's overall scale s, a last row (0 ... 0 | s): the affine map divided by s */
    int affine_scaled = 1;
    for (int j = 0; j < nin; j++)
        if (PC_MAP_AT(&r, nout, j) != 0.0) affine_scaled = 0;
    if (affine_scaled && PC_MAP_AT(&r, nout, nin) != 0.0) normalise(&r);
    *f = r;
    return PC_OK;
}

void pc_map_to_matrix(const pc_map *f, int rowvec, double *a) {
    int nin = f->nin, nout = f->nout;
    for (int i = 0; i <= nout; i++)
        for (int j = 0; j <= nin; j++) {
            if (rowvec) a[j * (nout + 1) + i] = PC_MAP_AT(f, i, j) + 0.0;   /* no -0 */
            else a[i * (nin + 1) + j] = PC_MAP_AT(f, i, j) + 0.0;
        }
}

int pc_map_is_affine(const pc_map *f) {
    for (int j = 0; j < f->nin; j++)
        if (PC_MAP_AT(f, f->nout, j) != 0.0) return 0;
    return PC_MAP_AT(f, f->nout, f->nin) == 1.0;
}

void pc_map_apply(const pc_map *f, const double *in, double *out) {
    int nin = f->nin;
    double w = in[nin], tmp[PC_MAXDIM + 1];
    for (int i = 0; i <= f->nout; i++) {
        const double *row = f->m + i * (nin + 1);
        double s = row[nin] * w;                 /* the translation first: O + x a1 + y a2 ... */
        for (int j = 0; j < nin; j++) s += row[j] * in[j];
        tmp[i] = s;
    }
    memcpy(out, tmp, sizeof(double) * (size_t)(f->nout + 1));
}

int pc_map_image(const pc_map *f, const double *in, double *out) {
    int nin = f->nin, nout = f->nout;
    if (pc_map_is_affine(f)) {
        pc_map_apply(f, in, out);
        return PC_OK;
    }
    double h[PC_MAXDIM + 1], size = 0, insize = 0;
    pc_map_apply(f, in, h);
    const double *last = f->m + nout * (nin + 1);
    for (int j = 0; j <= nin; j++) {
        size += fabs(last[j] * in[j]);
        insize += fabs(in[j]);
    }
    double w = h[nout], win = in[nin];
    if (fabs(w) <= 1e-13 * size) w = 0.0;        /* cancelled to rounding: at infinity */
    if (w == 0.0) {
        double big = 0;
        for (int i = 0; i < nout; i++) big = fmax(big, fabs(h[i]));
        memcpy(out, h, sizeof(double) * (size_t)nout);
        out[nout] = 0.0;
        if (!(big > 0) && insize > 0) return PC_EPOLE;  /* the centre of a projection */
        return win == 0.0 ? PC_OK : PC_IMPROPER;
    }
    double k = (win == 0.0 ? 1.0 : win) / w;       /* keep the weight (a direction: 1) */
    for (int i = 0; i < nout; i++) out[i] = h[i] * k;
    out[nout] = win == 0.0 ? 1.0 : win;
    return PC_OK;
}

int pc_map_compose(const pc_map *f, const pc_map *g, pc_map *h) {
    if (g->nout != f->nin) return PC_EDIM;
    pc_map r;
    blank(&r, g->nin, f->nout);
    int mid = f->nin;
    for (int i = 0; i <= r.nout; i++)
        for (int j = 0; j <= r.nin; j++) {
            /* the weight column of g last, so an affine translation adds as t + M t' */
            double s = PC_MAP_AT(f, i, mid) * PC_MAP_AT(g, mid, j);
            for (int l = 0; l < mid; l++) s += PC_MAP_AT(f, i, l) * PC_MAP_AT(g, l, j);
            PC_MAP_AT(&r, i, j) = s;
        }
    normalise(&r);
    *h = r;
    return PC_OK;
}

int pc_map_inverse(const pc_map *f, pc_map *inv) {
    int n = f->nin;
    if (f->nout != n) return PC_EDIM;
    pc_map r;
    blank(&r, n, n);
    if (pc_map_is_affine(f)) {
        /* solve M X = I column by column; then t' = -M^-1 t; the last row stays (0 | 1) */
        for (int c = 0; c < n; c++) {
            double m[PC_MAXDIM * PC_MAXDIM], b[PC_MAXDIM];
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n; j++) m[i * n + j] = PC_MAP_AT(f, i, j);
                b[i] = (i == c);
            }
            int st = pc_lu_solve(n, m, b);
            if (st != PC_OK) return st;
            for (int i = 0; i < n; i++) PC_MAP_AT(&r, i, c) = b[i];
        }
        for (int i = 0; i < n; i++) {
            double s = 0;
            for (int j = 0; j < n; j++) s -= PC_MAP_AT(&r, i, j) * PC_MAP_AT(f, j, n);
            PC_MAP_AT(&r, i, n) = s;
        }
        PC_MAP_AT(&r, n, n) = 1.0;
    } else {
        int k = n + 1;
        for (int c = 0; c < k; c++) {
            double m[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)], b[PC_MAXDIM + 1];
            memcpy(m, f->m, sizeof(double) * (size_t)(k * k));
            for (int i = 0; i < k; i++) b[i] = (i == c);
            int st = pc_lu_solve(k, m, b);
            if (st != PC_OK) return st;
            for (int i = 0; i < k; i++) PC_MAP_AT(&r, i, c) = b[i];
        }
        normalise(&r);
    }
    *inv = r;
    return PC_OK;
}

/* --- affine maps ---------------------------------------------------------------------------- */

int pc_map_affine_points(pc_map *f, int nin, int nout, const double *src, const double *dst) {
    if (!dim_ok(nin) || !dim_ok(nout)) return PC_EDIM;
    /* edges E_i = S_i - S_0 (rows), F_i = D_i - D_0; M E_i = F_i for all i, i.e.
     * M = F^T E^-T.  With E^T = Q R (columns, pc_qr): M = F^T R^-1 Q, then t = D_0 - M S_0. */
    double e[PC_MAXDIM * PC_MAXDIM], q[PC_MAXDIM * PC_MAXDIM], r[PC_MAXDIM * PC_MAXDIM];
    for (int i = 0; i < nin; i++)
        for (int j = 0; j < nin; j++) e[i * nin + j] = src[(i + 1) * nin + j] - src[j];
    int st = pc_qr(nin, nin, e, q, r, PC_DEGEN_TOL);
    if (st != PC_OK) return st;
    blank(f, nin, nout);
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
            PC_MAP_AT(f, o, c) = s;
            tr -= s * src[c];
        }
        PC_MAP_AT(f, o, nin) = tr;
    }
    PC_MAP_AT(f, nout, nin) = 1.0;
    return PC_OK;
}

int pc_map_frame(pc_map *f, int nout, int naxes, const double *o, const double *axes) {
    if (!dim_ok(naxes) || !dim_ok(nout)) return PC_EDIM;
    blank(f, naxes, nout);
    for (int i = 0; i < nout; i++) {
        for (int j = 0; j < naxes; j++) PC_MAP_AT(f, i, j) = axes[j * nout + i];
        PC_MAP_AT(f, i, naxes) = o[i];
    }
    PC_MAP_AT(f, nout, naxes) = 1.0;
    return PC_OK;
}

void pc_map_translate(pc_map *f, int n, const double *v) {
    pc_map_identity(f, n);
    for (int i = 0; i < n; i++) PC_MAP_AT(f, i, n) = v[i];
}

void pc_map_scale(pc_map *f, int n, const double *k, const double *c) {
    pc_map_identity(f, n);
    for (int i = 0; i < n; i++) {
        PC_MAP_AT(f, i, i) = k[i];
        PC_MAP_AT(f, i, n) = c ? c[i] - k[i] * c[i] : 0.0;
    }
}

/* x -> c + L (x - c) for the linear part L already in f: t = c - L c. */
static void about(pc_map *f, const double *c) {
    int n = f->nin;
    if (!c) return;
    for (int i = 0; i < n; i++) {
        double s = c[i];
        for (int j = 0; j < n; j++) s -= PC_MAP_AT(f, i, j) * c[j];
        PC_MAP_AT(f, i, n) = s;
    }
}

void pc_map_rotate2(pc_map *f, double angle, const double *c) {
    pc_map_identity(f, 2);
    double co = cos(angle), si = sin(angle);
    PC_MAP_AT(f, 0, 0) = co; PC_MAP_AT(f, 0, 1) = -si;
    PC_MAP_AT(f, 1, 0) = si; PC_MAP_AT(f, 1, 1) = co;
    about(f, c);
}

int pc_map_rotate3(pc_map *f, const double *a, const double *d, double angle) {
    if (!isfinite(angle)) return PC_ENONFINITE;
    for (int i = 0; i < 3; i++)
        if (!isfinite(a[i]) || !isfinite(d[i])) return PC_ENONFINITE;
    double n[3];
    if (pc_unit(3, d, n) != PC_OK) return PC_EZERO;
    /* Rodrigues (Buimov §2.7): R = cos I + (1 - cos) n n^T + sin [n]x, [n]x v = n x v */
    double co = cos(angle), si = sin(angle), c1 = 1 - co;
    pc_map_identity(f, 3);
    double cr[3][3] = {{0, -n[2], n[1]}, {n[2], 0, -n[0]}, {-n[1], n[0], 0}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            PC_MAP_AT(f, i, j) = (i == j ? co : 0.0) + c1 * n[i] * n[j] + si * cr[i][j];
    about(f, a);
    return PC_OK;
}

int pc_map_reflect(pc_map *f, int n, const double *a, const double *nrm) {
    if (!dim_ok(n)) return PC_EDIM;
    for (int i = 0; i < n; i++)
        if (!isfinite(a[i]) || !isfinite(nrm[i])) return PC_ENONFINITE;
    double u[PC_MAXDIM];
    if (pc_unit(n, nrm, u) != PC_OK) return PC_EZERO;
    pc_map_identity(f, n);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) PC_MAP_AT(f, i, j) -= 2 * u[i] * u[j];
    about(f, a);
    return PC_OK;
}

int pc_map_shear(pc_map *f, int n, int i, int j, double k) {
    if (!dim_ok(n)) return PC_EDIM;
    if (i < 0 || j < 0 || i >= n || j >= n || i == j) return PC_EDOMAIN;
    if (!isfinite(k)) return PC_ENONFINITE;
    pc_map_identity(f, n);
    PC_MAP_AT(f, i, j) = k;
    return PC_OK;
}

/* --- 3-D -> 2-D projections ------------------------------------------------------------------ */

/* A 3-D -> 2-D affine map from its two rows of linear part (no translation). */
static void linear32(pc_map *f, const double rx[3], const double ry[3]) {
    blank(f, 3, 2);
    for (int j = 0; j < 3; j++) {
        PC_MAP_AT(f, 0, j) = rx[j];
        PC_MAP_AT(f, 1, j) = ry[j];
    }
    PC_MAP_AT(f, 2, 3) = 1.0;
}

int pc_map_orthographic(pc_map *f, char axis) {
    static const double ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0}, ez[3] = {0, 0, 1};
    switch (axis) {
    case 'z': case 'Z': linear32(f, ex, ey); return PC_OK;
    case 'y': case 'Y': linear32(f, ex, ez); return PC_OK;
    case 'x': case 'X': linear32(f, ey, ez); return PC_OK;
    default: return PC_EDOMAIN;
    }
}

void pc_map_axonometric(pc_map *f, double phi, double theta) {
    /* the textbook's T = Ry(phi) Rx(theta) Pz (§2.8.3), transposed: its first two columns */
    double cp = cos(phi), sp = sin(phi), ct = cos(theta), st = sin(theta);
    double rx[3] = {cp, 0, sp}, ry[3] = {sp * st, ct, -cp * st};
    linear32(f, rx, ry);
}

void pc_map_isometric(pc_map *f) {
    pc_map_axonometric(f, PI / 4, asin(tan(PI / 6)));
}

int pc_map_dimetric(pc_map *f, double fz) {
    if (!(fz > 0 && fz < 1)) return PC_EDOMAIN;
    /* Buimov §2.8.3: sin^2 theta = fz^2/2, sin^2 phi = fz^2/(2 - fz^2) */
    pc_map_axonometric(f, asin(sqrt(fz * fz / (2 - fz * fz))), asin(fz / sqrt(2.0)));
    return PC_OK;
}

void pc_map_oblique(pc_map *f, double k, double alpha) {
    double rx[3] = {1, 0, k * cos(alpha)}, ry[3] = {0, 1, k * sin(alpha)};
    linear32(f, rx, ry);
}

int pc_map_perspective(pc_map *f, const double *e, const double *p0, const double *up) {
    static const double zup[3] = {0, 0, 1};
    if (!up) up = zup;
    for (int i = 0; i < 3; i++)
        if (!isfinite(e[i]) || !isfinite(p0[i]) || !isfinite(up[i])) return PC_ENONFINITE;
    double d[3] = {p0[0] - e[0], p0[1] - e[1], p0[2] - e[2]};
    double dist = pc_norm(3, d);
    if (!(dist > 0)) return PC_ECOINCIDENT;
    double n[3] = {d[0] / dist, d[1] / dist, d[2] / dist};
    double ulen = pc_norm(3, up);
    if (!(ulen > 0)) return PC_EZERO;
    double un = pc_dot(3, up, n), v[3];
    for (int i = 0; i < 3; i++) v[i] = up[i] - un * n[i];
    double vlen = pc_norm(3, v);
    if (!(vlen > PC_DEGEN_TOL * ulen)) return PC_ECOLLINEAR;
    for (int i = 0; i < 3; i++) v[i] /= vlen;
    double r[3];
    pc_cross3(n, v, r);                          /* looking along n with v up: r is right */
    /* X - e = q: picture (D q.r / q.n, D q.v / q.n), i.e. the rows (r | -r.e), (v | -v.e),
     * (n/D | -n.e/D): a point of the picture plane has weight 1, the eye weight 0. */
    blank(f, 3, 2);
    for (int j = 0; j < 3; j++) {
        PC_MAP_AT(f, 0, j) = r[j];
        PC_MAP_AT(f, 1, j) = v[j];
        PC_MAP_AT(f, 2, j) = n[j] / dist;
    }
    PC_MAP_AT(f, 0, 3) = -pc_dot(3, r, e);
    PC_MAP_AT(f, 1, 3) = -pc_dot(3, v, e);
    PC_MAP_AT(f, 2, 3) = -pc_dot(3, n, e) / dist;
    return PC_OK;
}
