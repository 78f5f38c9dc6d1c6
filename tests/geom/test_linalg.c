/* Small linear algebra (linalg.h): the tridiagonal solver, plain and cyclic, against the dense
 * LU solver on random diagonally dominant systems (1e-12), with several right-hand sides, and
 * its error statuses; the dense solver and determinant on a textbook matrix. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "linalg.h"
#include "point.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

static double rnd(unsigned *s) {
    *s = *s * 1103515245u + 12345u;
    return ((*s >> 8) & 0xffff) / 32768.0 - 1;
}

/* tridiagonal (cyclic or not) of size n against pc_lu_solve of the same dense matrix */
static void check(int n, int cyclic, unsigned seed) {
    enum { N = 12, R = 3 };
    double a[N], b[N], c[N], d[N * R], m[N * N], x[N];
    unsigned s = seed;
    for (int i = 0; i < n; i++) {
        a[i] = rnd(&s);
        c[i] = rnd(&s);
        b[i] = 3 + rnd(&s);          /* |b| > |a| + |c| */
        if (i % 2) b[i] = -b[i];
        for (int r = 0; r < R; r++) d[i * R + r] = 10 * rnd(&s);
    }
    memset(m, 0, sizeof m);
    for (int i = 0; i < n; i++) {
        m[i * n + i] += b[i];
        if (i > 0) m[i * n + i - 1] += a[i];
        else if (cyclic) m[i * n + n - 1] += a[i];
        if (i + 1 < n) m[i * n + i + 1] += c[i];
        else if (cyclic) m[i * n] += c[i];
    }
    double sol[N * R];
    memcpy(sol, d, sizeof d);
    assert_int_equal(pc_tridiag_solve(n, R, a, b, c, sol, cyclic), PC_OK);
    for (int r = 0; r < R; r++) {
        double mm[N * N];
        memcpy(mm, m, sizeof(double) * n * n);
        for (int i = 0; i < n; i++) x[i] = d[i * R + r];
        assert_int_equal(pc_lu_solve(n, mm, x), PC_OK);
        for (int i = 0; i < n; i++) NEAR(sol[i * R + r], x[i], 1e-12 * (1 + fabs(x[i])));
        for (int i = 0; i < n; i++) {     /* and the residual itself */
            double sum = 0;
            for (int j = 0; j < n; j++) sum += m[i * n + j] * sol[j * R + r];
            NEAR(sum, d[i * R + r], 1e-12 * (1 + fabs(d[i * R + r])));
        }
    }
}

static void test_tridiag(void **state) {
    (void)state;
    for (int n = 1; n <= 12; n++) {
        check(n, 0, 100 + n);
        check(n, 1, 200 + n);
    }
}

/* known small systems, exactly:
 * [2 1 0; 1 2 1; 0 1 2] x = (4, 8, 8) has x = (1, 2, 3) */
static void test_known(void **state) {
    (void)state;
    const double a[3] = {0, 1, 1}, b[3] = {2, 2, 2}, c[3] = {1, 1, 0};
    double d[3] = {4, 8, 8};
    assert_int_equal(pc_tridiag_solve(3, 1, a, b, c, d, 0), PC_OK);
    NEAR(d[0], 1, 1e-15);
    NEAR(d[1], 2, 1e-15);
    NEAR(d[2], 3, 1e-15);
    /* cyclic [4 1 1; 1 4 1; 1 1 4] x = (6, 6, 6): x = 1 */
    const double ca[3] = {1, 1, 1}, cb[3] = {4, 4, 4}, cc[3] = {1, 1, 1};
    double cd[3] = {6, 6, 6};
    assert_int_equal(pc_tridiag_solve(3, 1, ca, cb, cc, cd, 1), PC_OK);
    for (int i = 0; i < 3; i++) NEAR(cd[i], 1, 1e-15);
    /* Buimov §1.2.4: the inverse of [[1,2,3],[1,3,3],[1,2,4]] has first column (6, -1, -1) */
    double m[9] = {1, 2, 3, 1, 3, 3, 1, 2, 4}, e[3] = {1, 0, 0};
    NEAR(pc_det(3, m), 1, 1e-14);
    assert_int_equal(pc_lu_solve(3, m, e), PC_OK);
    NEAR(e[0], 6, 1e-14);
    NEAR(e[1], -1, 1e-14);
    NEAR(e[2], -1, 1e-14);
}

static void test_errors(void **state) {
    (void)state;
    const double a[3] = {0, 1, 1}, b[3] = {2, 2, 2}, c[3] = {1, 1, 0}, z[3] = {0, 0, 0};
    double d[3] = {1, 2, 3};
    assert_int_equal(pc_tridiag_solve(0, 1, a, b, c, d, 0), PC_EDIM);
    assert_int_equal(pc_tridiag_solve(3, 0, a, b, c, d, 0), PC_EDIM);
    assert_int_equal(pc_tridiag_solve(3, 1, z, z, z, d, 0), PC_ESINGULAR);
    const double b0[3] = {0, 2, 2};       /* a zero first pivot (no pivoting) */
    assert_int_equal(pc_tridiag_solve(3, 1, a, b0, c, d, 0), PC_ESINGULAR);
    const double sa[2] = {0, 1}, sb[2] = {1, 1}, sc[2] = {1, 0};   /* [[1 1] [1 1]] */
    assert_int_equal(pc_tridiag_solve(2, 1, sa, sb, sc, d, 0), PC_ESINGULAR);
    const double ca[3] = {1, 1, 1}, cb[3] = {-2, -2, -2}, cc[3] = {1, 1, 1};   /* rows sum to 0 */
    assert_int_equal(pc_tridiag_solve(3, 1, ca, cb, cc, d, 1), PC_ESINGULAR);
    const double bn[3] = {2, NAN, 2};
    assert_int_equal(pc_tridiag_solve(3, 1, a, bn, c, d, 0), PC_ENONFINITE);
    double dn[3] = {1, INFINITY, 3};
    assert_int_equal(pc_tridiag_solve(3, 1, a, b, c, dn, 0), PC_ENONFINITE);
    /* a[0] and c[n-1] are not read unless cyclic */
    const double an[3] = {NAN, 1, 1}, cn[3] = {1, 1, NAN};
    double d2[3] = {4, 8, 8};
    assert_int_equal(pc_tridiag_solve(3, 1, an, b, cn, d2, 0), PC_OK);
    NEAR(d2[2], 3, 1e-15);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tridiag), cmocka_unit_test(test_known), cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
