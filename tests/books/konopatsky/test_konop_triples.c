/* The symbolic method of §2.2 (konop_triples.h): Baluba's two 7-line systems of Fig. 2.28 as
 * tables; (b) against the corrected construction of conic.h (pc_triples_conic), (a) Pascal's
 * on the conic through A1..A5; an indeterminate table refused. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include "konop_triples.h"
#include "conic.h"
#include "quadratic.h"

#define NEAR(a, b, tol) assert_true(fabs((a) - (b)) <= (tol))

enum { A1, A2, A3, A4, A5, PA, PB, PC, PM, NPTS };

static const double PTS[NPTS * 2] = {0, 0, 1.2, 2.1, 3, 2.9, 4.6, 1.8, 5, 0};

static void test_system_b(void **state) {
    (void)state;
    const int tri[7][3] = {{A1, PA, PB}, {A2, PB, PC}, {A3, A2, PA}, {A4, A5, PA},
                           {A5, A1, PC}, {PM, A3, PB}, {PM, A4, PC}};
    unsigned char known[NPTS] = {1, 1, 1, 1, 1, 0, 0, 0, 0};
    pc_triples_plan plan;
    assert_int_equal(pc_triples_plan_make(NPTS, 7, tri, known, PC, A1, A5, PM, &plan), PC_OK);
    assert_int_equal(plan.nsteps, 3);              /* A, B, M */
    assert_int_equal(plan.step[0].x, PA);
    int st;
    pc_curve *c = pc_triples_curve(&plan, 2, PTS, 0.05, 0.95, &st);
    pc_curve *ref = pc_triples_conic(2, PTS, PTS + 2, PTS + 4, PTS + 6, PTS + 8, 0.05, 0.95, &st);
    assert_non_null(c);
    assert_non_null(ref);
    for (double t = 0.1; t < 0.9; t += 0.1) {
        double x[2], y[2];
        assert_int_equal(pc_curve_eval(c, t, x), PC_OK);
        assert_int_equal(pc_curve_eval(ref, t, y), PC_OK);
        NEAR(x[0], y[0], 1e-10);
        NEAR(x[1], y[1], 1e-10);
    }
    pc_curve_release(c);
    pc_curve_release(ref);
}

static void test_system_a(void **state) {
    (void)state;
    /* Pascal: the hexagon A1 A2 A3 A4 A5 M cut by the line A C B; C runs on A3A4 */
    const int tri[7][3] = {{A1, A2, PA}, {A2, A3, PB}, {A3, A4, PC}, {A4, A5, PA},
                           {A5, PM, PB}, {PM, A1, PC}, {PA, PC, PB}};
    unsigned char known[NPTS] = {1, 1, 1, 1, 1, 0, 0, 0, 0};
    pc_triples_plan plan;
    assert_int_equal(pc_triples_plan_make(NPTS, 7, tri, known, PC, A3, A4, PM, &plan), PC_OK);
    double q[6];
    assert_int_equal(pc_conic_coef_five(PTS, q), PC_OK);
    double all[NPTS * 3];
    int checked = 0;
    for (double t = -0.8; t < 2; t += 0.35) {
        if (pc_triples_eval(&plan, 2, PTS, t, all) != PC_OK) continue;
        const double *m = all + PM * 3;
        if (m[2] == 0) continue;
        NEAR(pc_conic_eq(q, m[0] / m[2], m[1] / m[2]), 0, 1e-10);
        checked++;
    }
    assert_true(checked >= 6);
    /* an indeterminate table: M only on one line */
    const int bad[2][3] = {{A1, A2, PA}, {PM, A1, PC}};
    assert_int_equal(pc_triples_plan_make(NPTS, 2, bad, known, PC, A3, A4, PM, &plan), PC_EDOMAIN);
    /* the current point's line must join two given points */
    assert_int_equal(pc_triples_plan_make(NPTS, 7, tri, known, PC, A3, PM, PM, &plan), PC_EDOMAIN2);
    assert_int_equal(pc_triples_plan_make(NPTS, 7, tri, known, PC, A3, A4, PM, &plan), PC_OK);
    int st;
    assert_null(pc_triples_curve(&plan, 2, PTS, 0.5, 0.5, &st));
    assert_int_equal(st, PC_EDOMAIN3);   /* an empty range */
}

/* the table by names: indices in order of appearance, the steps as the book writes them */
static void test_names(void **state) {
    (void)state;
    pc_triples_names nm = {0};
    const char *pts[] = {"A1", "A2", "A3", "A4", "A5"};
    for (int i = 0; i < 5; i++) assert_int_equal(pc_triples_name(&nm, pts[i]), i);
    assert_int_equal(pc_triples_name(&nm, "A3"), A3);       /* known already */
    const char *more[] = {"A", "B", "C", "M"};
    for (int i = 0; i < 4; i++) assert_int_equal(pc_triples_name(&nm, more[i]), PA + i);
    assert_int_equal(nm.n, NPTS);
    const int tri[7][3] = {{A1, PA, PB}, {A2, PB, PC}, {A3, A2, PA}, {A4, A5, PA},
                           {A5, A1, PC}, {PM, A3, PB}, {PM, A4, PC}};
    unsigned char known[NPTS] = {1, 1, 1, 1, 1, 0, 0, 0, 0};
    pc_triples_plan plan;
    assert_int_equal(pc_triples_plan_make(NPTS, 7, tri, known, PC, A1, A5, PM, &plan), PC_OK);
    char buf[64];
    pc_triples_step_text(&plan, 0, &nm, buf, sizeof buf);
    assert_string_equal(buf, "A = A3A2 x A4A5");
    pc_triples_step_text(&plan, 2, &nm, buf, sizeof buf);
    assert_int_equal(buf[0], 'M');
    char name[PC_TRIPLES_MAXPTS][16];
    for (int i = nm.n; i < PC_TRIPLES_MAXPTS; i++) {
        snprintf(name[i], sizeof name[i], "X%d", i);
        assert_int_equal(pc_triples_name(&nm, name[i]), i);
    }
    assert_int_equal(pc_triples_name(&nm, "Y"), -1);         /* full */
}

/* a table given by names, as conic.scheme reads it: system (b) with its points as values */
static void test_table(void **state) {
    (void)state;
    pc_triples_table t = {0};
    const char *given[] = {"A1", "A2", "A3", "A4", "A5"};
    for (int i = 0; i < 5; i++) {
        const double h[3] = {PTS[2 * i], PTS[2 * i + 1], 1 + 1e-12};   /* snapped to a point */
        assert_int_equal(pc_triples_give(&t, given[i], 2, h), PC_OK);
    }
    assert_int_equal(t.dim, 2);
    NEAR(t.pts[2 * A3 + 1], PTS[2 * A3 + 1], 1e-11);   /* divided by the weight */
    assert_int_equal(pc_triples_give(&t, "V", 2, (const double[]){1, 0, 0}), PC_EDIM);       /* a vector */
    assert_int_equal(pc_triples_give(&t, "H", 2, (const double[]){2, 2, 2}), PC_EDIM);       /* weight 2 */
    assert_int_equal(pc_triples_give(&t, "W", 3, (const double[]){1, 0, 0, 1}), PC_EDIM);    /* 3-D */
    assert_int_equal(pc_triples_give(&t, "N", 2, NULL), PC_EDIM);
    const char *tri[7][3] = {{"A1", "A", "B"}, {"A2", "B", "C"}, {"A3", "A2", "A"}, {"A4", "A5", "A"},
                             {"A5", "A1", "C"}, {"M", "A3", "B"}, {"M", "A4", "C"}};
    for (int j = 0; j < 7; j++)
        for (int k = 0; k < 3; k++) assert_int_equal(pc_triples_index(&t, tri[j][k], &t.tri[j][k]), PC_OK);
    const char *cur[3] = {"C", "A1", "A5"};
    for (int k = 0; k < 3; k++) assert_int_equal(pc_triples_index(&t, cur[k], &t.cur[k]), PC_OK);
    pc_triples_plan plan;
    assert_int_equal(pc_triples_table_plan(&t, 7, "M", &plan), PC_OK);
    assert_int_equal(plan.nsteps, 3);
    assert_int_equal(plan.result, PM);
    assert_int_equal(pc_triples_table_plan(&t, 7, "Z", &plan), PC_EDOMAIN);   /* on no line */
    char name[PC_TRIPLES_MAXPTS][16];
    int idx;
    for (int i = t.nm.n; i < PC_TRIPLES_MAXPTS; i++) {
        snprintf(name[i], sizeof name[i], "X%d", i);
        assert_int_equal(pc_triples_index(&t, name[i], &idx), PC_OK);
    }
    assert_int_equal(pc_triples_index(&t, "Y", &idx), PC_EARG);
    assert_int_equal(pc_triples_give(&t, "Y", 2, (const double[]){1, 1, 1}), PC_EARG);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_system_b), cmocka_unit_test(test_system_a),
                                       cmocka_unit_test(test_names), cmocka_unit_test(test_table)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
