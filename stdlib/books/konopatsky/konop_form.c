/* The forms of the spec tables (konop_form.h). */
#include <math.h>
#include <stddef.h>
#include "konop_form.h"
#include "conic.h"
#include "konop_why.h"
#include "names.h"
#include <string.h>

static pc_curve *fail(pc_why_call *w, const char *op, int st, const char *key, const char *text, double x,
                      int *status) {
    char num[40];
    *status = st;
    pc_why_call_set(w, op, st, 0, key, text, isnan(x) ? "nil" : pc_num_text(x, num, sizeof num));
    return NULL;
}

int pc_konop_form_base(const char *op) {
    static const struct { const char *op; int form; } base[] = {
        {"conic.ellipse", PC_KC_ELLIPSE_ANGLE}, {"conic.hyperbola", PC_KC_HYPERBOLA_ANGLE},
        {"conic.circle", PC_KC_CIRCLE_ANGLE}, {"conic.reparam", PC_KC_PARABOLA_ANGLE},
        {"conic.sinusoid", PC_KC_SINUSOID}, {"conic.cycloid", PC_KC_CYCLOID}};
    for (size_t i = 0; i < sizeof base / sizeof base[0]; i++)
        if (strcmp(base[i].op, op) == 0) return base[i].form;
    return -1;
}

pc_curve *pc_konop_form(const char *op, int form, int dim, const double *c, const double *a,
                        const double *b, const double *k, const double *par, int npar, double t0,
                        double t1, int *status, pc_why_call *w) {
    pc_curve *curve;
    if (form == PC_KF_DIAMETER && !k) return fail(w, op, PC_EARG, "K", "must be a point, got nil", NAN, status);
    if (form == PC_KF_DIAMETER && !(par[0] > 0 && par[0] < 1))
        return fail(w, op, PC_EDOMAIN, "lambda", "must be a number in (0, 1), got %s", par[0], status);
    if (form != PC_KF_DIAMETER && !c) return fail(w, op, PC_EARG, "C", "must be a point, got nil", NAN, status);
    if (form == PC_KC_CIRCLE_ANGLE && !(par[0] > 0 && par[0] < M_PI))
        return fail(w, op, PC_EDOMAIN, "delta", "must be an angle in (0, pi), got %s", par[0], status);
    if (form == PC_KF_DIAMETER) {
        curve = pc_conic_conjugate2(dim, k, a, b, par[0], status);
    } else if (form == PC_KF_CONJUGATE) {
        curve = pc_conic_conjugate(dim, c, a, b, status);
    } else if (form == PC_KF_CIRCLE_ARC) {
        curve = pc_conic_circle_arc(dim, a, b, c, status);
    } else {
        curve = pc_kcurve((pc_kcurve_kind)form, dim, c, a, b, par, npar, t0, t1, status);
        double r[2];
        if (!curve && *status == PC_EDOMAIN3
            && pc_kcurve_range((pc_kcurve_kind)form, dim, c, a, b, par, npar, r, r + 1) == PC_OK) {
            char lo[40], hi[40];
            pc_why_call_set(w, op, *status, 0, "range", "must lie within the form's real range [%s, %s]",
                            pc_num_text(r[0], lo, sizeof lo), pc_num_text(r[1], hi, sizeof hi));
            return NULL;
        }
    }
    const pc_why *row = curve ? NULL : pc_why_find(pc_konop_why, op, *status);
    if (row) pc_why_call_set(w, op, *status, row->arg, row->key, "%s", row->text);
    else pc_why_call_set(w, NULL, *status, 0, NULL, "");
    return curve;
}
