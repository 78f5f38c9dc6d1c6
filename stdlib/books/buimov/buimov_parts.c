/* The parts of the textbook's constructions the bindings need (buimov_parts.h). */
#include "buimov_parts.h"
#include "names.h"

int pc_bezier_points(const pc_curve *c, double *out) {
    int ok = c->kind == PC_CURVE_BEZIER && c->nknots == 2;
    for (int i = 0; ok && i < c->ncp; i++) ok = c->cp[i * (c->dim + 1) + c->dim] == 1;
    if (!ok) return -1;
    for (int i = 0; i < c->ncp; i++)
        for (int j = 0; j < c->dim; j++) out[i * c->dim + j] = c->cp[i * (c->dim + 1) + j];
    return c->degree;
}

const char *pc_bezier_joint_name(int kind) {
    static const char *names[4] = {"none", "C0", "G1", "C1"};
    return kind >= 0 && kind < 4 ? names[kind] : "none";
}

int pc_book_spline_check(int n, pc_book_ends *ends, int ends_given, int nd, int param_given, int nlen,
                         const double *len, pc_why_call *w) {
    const char *op = "buimov.spline";
    char num[40];
    if (!ends_given && nd == 2) *ends = PC_BOOK_CLAMPED;
    if (*ends == PC_BOOK_CLAMPED && nd < 2)
        return pc_why_call_set(w, op, PC_EDOMAIN, 0, NULL, "clamped ends need both end tangents d0 and d1");
    if ((*ends == PC_BOOK_CYCLIC || *ends == PC_BOOK_ANTICYCLIC) && n < 4)
        return pc_why_call_set(w, op, PC_EDOMAIN, 0, NULL, "cyclic and anticyclic ends need at least 4 points, got %d", n);
    if (nlen >= 0 && param_given)
        return pc_why_call_set(w, op, PC_EDOMAIN, 0, NULL, "give the parameter as param or as lengths, not both");
    if (nlen >= 0 && nlen != n - 1)
        return pc_why_call_set(w, op, PC_EDOMAIN, 0, "lengths", "must hold %d segment lengths (one per segment), got %d",
                               n - 1, nlen);
    for (int i = 0; i < nlen; i++)
        if (!(len[i] > 0))
            return pc_why_call_set(w, op, PC_EDOMAIN, 0, "lengths", "[%d] must be a positive length, got %s", i + 1,
                                   pc_num_text(len[i], num, sizeof num));
    return pc_why_call_set(w, op, PC_OK, 0, NULL, "");
}

int pc_book_basis_checked(const double *q, int nq, int i, int k, double t, double *out, pc_why_call *w) {
    const char *op = "buimov.basis";
    for (int j = 1; j < nq; j++)
        if (q[j] < q[j - 1]) return pc_why_call_set(w, op, PC_EDOMAIN, 4, NULL, "must not decrease ([%d])", j + 1);
    int st = pc_book_basis(q, nq, i, k, t, out);
    return pc_why_call_set(w, op, st, 0, NULL, "N(i = %d, k = %d) needs the knots q[i] .. q[i + k]: %d knots given",
                           i, k, nq);
}
