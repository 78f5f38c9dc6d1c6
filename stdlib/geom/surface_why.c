/* What a surface's constructors and drawing calls need, by status (surface.h, why.h). */
#include "surface.h"
#include "names.h"

const pc_why pc_surface_why[] = {
    {"surface.coons", PC_EDOMAIN, 0, NULL, "the boundary curves do not meet at the corners (cu0 and c0v must start "
                                           "together, cu0 must end where c1v starts, ...)"},
    {"surface.revolution", PC_EZERO, 3, NULL, "must be a nonzero vector (the axis)"},
    {"s:shade", PC_EZERO, 0, "light", "must be a nonzero vector (the direction towards the light), got V(0, 0, 0)"},
    {"s:shade", PC_ESINGULAR, 0, NULL, "the projection is singular (it flattens space onto a line)"},
    {NULL, 0, 0, NULL, NULL}};

/* st of an evaluation at (u, v): a point at infinity explained, another status not */
static int at_infinity(const char *op, int st, double u, double v, pc_why_call *why) {
    char a[40], b[40];
    if (st != PC_IMPROPER) return pc_why_call_set(why, NULL, st, 0, NULL, "");
    return pc_why_call_set(why, op, st, 0, NULL, "the point at (%s, %s) is at infinity", pc_num_text(u, a, sizeof a),
                           pc_num_text(v, b, sizeof b));
}

int pc_surface_eval_checked(const char *op, const pc_surface *s, double u, double v, double *out, pc_why_call *why) {
    return at_infinity(op, pc_surface_eval(s, u, v, out), u, v, why);
}

int pc_surface_partials_checked(const char *op, const pc_surface *s, double u, double v,
                                double *out, pc_why_call *why) {
    return at_infinity(op, pc_surface_partials(s, u, v, out), u, v, why);
}

int pc_surface_normal_checked(const char *op, const pc_surface *s, double u, double v, double *n, pc_why_call *why) {
    char a[40], b[40];
    if (s->dim != 3)
        return pc_why_call_set(why, op, PC_EDIM, 0, NULL, "a normal needs a 3-D surface, this one is %d-D", s->dim);
    int st = pc_surface_normal(s, u, v, n);
    if (st != PC_EZERO) return pc_why_call_set(why, NULL, st, 0, NULL, "");
    return pc_why_call_set(why, op, st, 0, NULL, "the surface is singular at (%s, %s): its partial derivatives are parallel",
                           pc_num_text(u, a, sizeof a), pc_num_text(v, b, sizeof b));
}
