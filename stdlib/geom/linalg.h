/* Small dense linear algebra for the point calculus core (internal to stdlib/geom).
 * Matrices are row-major arrays of doubles; sizes are at most PC_MAXDIM (+1). */
#ifndef PC_LINALG_H
#define PC_LINALG_H

/* Orthonormalise the k edge vectors e (k rows of n) by modified Gram-Schmidt with one
 * re-orthogonalisation pass: e = R^T Q, i.e. row i of e is sum_j r[j*k+i] q_j.
 * q: k rows of n (orthonormal); r: k x k upper triangular with positive diagonal.
 * Returns PC_OK, PC_ECOINCIDENT if an edge is zero, PC_ECOLLINEAR if an edge lies (within
 * tol relative to its length) in the span of the previous ones, PC_EDIM if k > n.
 * tol = PC_DEGEN_TOL detects degenerate simplices; tol = 0 fails only on exact dependence. */
int pc_qr(int n, int k, const double *e, double *q, double *r, double tol);

/* Solve m x = b in place (m: k x k, destroyed; b: k, overwritten by x) with partial
 * pivoting.  PC_ESINGULAR if a pivot is below PC_DEGEN_TOL times the largest entry. */
int pc_lu_solve(int k, double *m, double *b);

/* Determinant of a k x k matrix (m is not modified). */
double pc_det(int k, const double *m);

/* Solve the tridiagonal system a[i] x[i-1] + b[i] x[i] + c[i] x[i+1] = d[i] (i = 0..n-1) for
 * nrhs right-hand sides at once: d holds n rows of nrhs, overwritten by the solution.  Not
 * cyclic: a[0] and c[n-1] are ignored.  Cyclic (periodic splines): a[0] multiplies x[n-1] and
 * c[n-1] multiplies x[0] (Sherman-Morrison on the Thomas algorithm).  No pivoting: meant for
 * diagonally dominant systems.  PC_ESINGULAR if a pivot falls below PC_DEGEN_TOL times the
 * largest coefficient, PC_EDIM for n < 1 or nrhs < 1, PC_ENONFINITE for NaN/inf,
 * PC_ENOMEM.  (Allocates O(n) scratch.) */
int pc_tridiag_solve(int n, int nrhs, const double *a, const double *b, const double *c,
                     double *d, int cyclic);

/* Least squares: the x (n values) minimising |a x - b| for an m x n matrix a (m >= n, row-major,
 * destroyed) and b (m values, overwritten: x in b[0..n-1], and the norm of b[n..m-1] is the
 * residual |a x - b|).  Householder QR, so the condition number is not squared as by the normal
 * equations (Buimov §2.8.6 reconstructs a point from two views and a camera from six points
 * this way).  PC_EDIM unless 1 <= n <= m, PC_ENONFINITE for NaN/inf, PC_ESINGULAR if the
 * columns are dependent (a diagonal entry of R below PC_DEGEN_TOL times the largest column). */
int pc_lsq_solve(int m, int n, double *a, double *b);

#endif
