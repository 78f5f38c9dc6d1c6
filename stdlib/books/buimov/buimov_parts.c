/* The parts of the textbook's constructions the bindings need (buimov_parts.h). */
#include "buimov_parts.h"

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
