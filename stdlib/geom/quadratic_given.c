/* The conic of given points and tangents (quadratic_given.h). */
#include "quadratic_given.h"
#include "status.h"

int pc_conic_info_five(const double pts[10], pc_conic_info *out) {
    int st = pc_conic_coef_five(pts, out->coef);
    if (st == PC_ECOLLINEAR) return PC_ECOINCIDENT;
    return st ? st : pc_conic_info_coef(out->coef, out);
}

int pc_conic_info_given(int np, const double *pts, int nt, const double *tangents, pc_conic_info *out) {
    if (np < 0 || nt < 0 || np + nt != 5) return PC_EDIM;
    double rows[30];
    for (int i = 0; i < np; i++) pc_conic_row_point(pts[2 * i], pts[2 * i + 1], rows + 6 * i);
    for (int i = 0; i < nt; i++) {
        const double *t = tangents + 4 * i;
        pc_conic_row_tangent(t[0], t[1], t[2], t[3], rows + 6 * (np + i));
    }
    int st = pc_conic_coef_conditions(rows, out->coef);
    if (st == PC_ECOLLINEAR) return PC_ESINGULAR;
    return st ? st : pc_conic_info_coef(out->coef, out);
}
