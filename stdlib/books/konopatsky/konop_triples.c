/* The symbolic method of §2.2: a table of triples as a construction (konop_triples.h). */
#include "konop_triples.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "point.h"

int pc_triples_plan_make(int npts, int ntri, const int (*tri)[3], const unsigned char *known,
                         int cur, int cur_a, int cur_b, int result, pc_triples_plan *plan) {
    if (npts < 1 || npts > PC_TRIPLES_MAXPTS || ntri < 1 || ntri > PC_TRIPLES_MAXTRI) return PC_EDIM;
    int ids[4] = {cur, cur_a, cur_b, result};
    for (int i = 0; i < 4; i++)
        if (ids[i] < 0 || ids[i] >= npts) return PC_EDOMAIN;
    for (int j = 0; j < ntri; j++)
        for (int k = 0; k < 3; k++)
            if (tri[j][k] < 0 || tri[j][k] >= npts) return PC_EDOMAIN;
    if (!known[cur_a] || !known[cur_b] || cur_a == cur_b) return PC_EDOMAIN2;
    if (known[cur]) return PC_EDOMAIN;
    unsigned char have[PC_TRIPLES_MAXPTS];
    memcpy(have, known, (size_t)npts);
    have[cur] = 1;
    memset(plan, 0, sizeof *plan);
    plan->npts = npts;
    plan->cur = cur, plan->cur_a = cur_a, plan->cur_b = cur_b, plan->result = result;
    for (int progress = 1; progress && !have[result];) {
        progress = 0;
        for (int x = 0; x < npts && !progress; x++) {
            if (have[x]) continue;
            /* the lines through x whose other two points are known */
            int line[PC_TRIPLES_MAXTRI][2], nl = 0;
            for (int j = 0; j < ntri; j++) {
                int o[2], n = 0, hit = 0;
                for (int k = 0; k < 3; k++) {
                    if (tri[j][k] == x) hit = 1;
                    else if (n < 2) o[n++] = tri[j][k];
                }
                if (hit && n == 2 && have[o[0]] && have[o[1]] && o[0] != o[1]) {
                    line[nl][0] = o[0], line[nl][1] = o[1];
                    nl++;
                }
            }
            /* two lines that are not the same pair of points */
            for (int i = 0; i < nl && !progress; i++)
                for (int j = i + 1; j < nl && !progress; j++) {
                    int same = (line[i][0] == line[j][0] && line[i][1] == line[j][1]) ||
                               (line[i][0] == line[j][1] && line[i][1] == line[j][0]);
                    if (same) continue;
                    pc_triple_step s = {x, line[i][0], line[i][1], line[j][0], line[j][1]};
                    plan->step[plan->nsteps++] = s;
                    have[x] = 1;
                    progress = 1;
                }
        }
    }
    return have[result] ? PC_OK : PC_EDOMAIN;
}

int pc_triples_eval(const pc_triples_plan *plan, int dim, const double *pts, double t, double *all) {
    int w = dim + 1;
    for (int i = 0; i < plan->npts; i++) {
        for (int k = 0; k < dim; k++) all[i * w + k] = pts[i * dim + k];
        all[i * w + dim] = 1;
    }
    double *c = all + plan->cur * w;
    const double *a = pts + plan->cur_a * dim, *b = pts + plan->cur_b * dim;
    for (int k = 0; k < dim; k++) c[k] = a[k] * (1 - t) + b[k] * t;   /* cur = a t' + b t */
    c[dim] = 1;
    for (int s = 0; s < plan->nsteps; s++) {
        const pc_triple_step *p = &plan->step[s];
        int st = pc_meet_h(dim, all + p->a * w, all + p->b * w, all + p->c * w, all + p->d * w,
                           all + p->x * w, NULL, NULL, NULL);
        if (st != PC_OK && st != PC_IMPROPER) return st == PC_ENONFINITE ? st : PC_EDOMAIN;
    }
    return PC_OK;
}

typedef struct {
    pc_triples_plan plan;
    int dim;
    double pts[PC_TRIPLES_MAXPTS * PC_MAXDIM];
} triples_ud;

static int triples_fn(void *ud, double t, int order, double *out) {
    if (order > 0) return PC_EDOMAIN;       /* the core differences the values */
    const triples_ud *u = ud;
    double all[PC_TRIPLES_MAXPTS * (PC_MAXDIM + 1)];
    int st = pc_triples_eval(&u->plan, u->dim, u->pts, t, all);
    if (st != PC_OK) return st;
    memcpy(out, all + u->plan.result * (u->dim + 1), sizeof(double) * (size_t)(u->dim + 1));
    return PC_OK;
}

pc_curve *pc_triples_curve(const pc_triples_plan *plan, int dim, const double *pts, double t0,
                           double t1, int *status) {
    if (dim < 2 || dim > PC_MAXDIM || !(t1 > t0)) {
        *status = dim < 2 || dim > PC_MAXDIM ? PC_EDIM : PC_EDOMAIN3;
        return NULL;
    }
    triples_ud *u = malloc(sizeof *u);
    if (!u) {
        *status = PC_ENOMEM;
        return NULL;
    }
    u->plan = *plan;
    u->dim = dim;
    memcpy(u->pts, pts, sizeof(double) * (size_t)(plan->npts * dim));
    pc_curve *c = pc_curve_func(dim, t0, t1, 0, triples_fn, free, u, status);
    if (!c) free(u);
    return c;
}

int pc_triples_name(pc_triples_names *nm, const char *s) {
    for (int i = 0; i < nm->n; i++)
        if (!strcmp(nm->name[i], s)) return i;
    if (nm->n == PC_TRIPLES_MAXPTS) return -1;
    nm->name[nm->n] = s;
    return nm->n++;
}

int pc_triples_index(pc_triples_table *t, const char *name, int *idx) {
    *idx = pc_triples_name(&t->nm, name);
    return *idx < 0 ? PC_EARG : PC_OK;
}

int pc_triples_give(pc_triples_table *t, const char *name, int n, const double *h) {
    double x[PC_MAXDIM + 1];
    if (!h || n < 2 || n > PC_MAXDIM || (t->dim && n != t->dim)) return PC_EDIM;
    memcpy(x, h, sizeof(double) * (size_t)(n + 1));
    if (pc_snap_weight(n, x) != PC_KIND_POINT) return PC_EDIM;
    int i;
    if (pc_triples_index(t, name, &i) != PC_OK) return PC_EARG;
    t->dim = n, t->known[i] = 1;
    memcpy(t->pts + i * n, x, sizeof(double) * (size_t)n);
    return PC_OK;
}

int pc_triples_table_plan(pc_triples_table *t, int ntri, const char *result, pc_triples_plan *plan) {
    int res = pc_triples_name(&t->nm, result);   /* -1 beyond the names: not determined */
    return pc_triples_plan_make(t->nm.n, ntri, (const int (*)[3])t->tri, t->known, t->cur[0], t->cur[1],
                                t->cur[2], res, plan);
}

void pc_triples_step_text(const pc_triples_plan *plan, int s, const pc_triples_names *nm, char *buf, size_t size) {
    const pc_triple_step *p = &plan->step[s];
    snprintf(buf, size, "%s = %s%s x %s%s", nm->name[p->x], nm->name[p->a], nm->name[p->b], nm->name[p->c],
             nm->name[p->d]);
}
