/* The sphere of the textbook (Buimov §5.1): its point, tangent, twist and normal vectors, and
 * the sphere patch as a FUNC surface with a C callback: see buimov.h. */
#include "buimov.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void pc_sphere_frame(double th, double ph, double out[15]) {
    double ct = cos(th), st = sin(th), cp = cos(ph), sp = sin(ph);
    const double v[15] = {
        ct * sp, st * sp, cp,                  /* S (y = sin th sin ph; printed sin th cos ph) */
        -st * sp, ct * sp, 0,                  /* S_th (e2: cos th sin ph; printed cos th cos ph) */
        ct * cp, st * cp, -sp,                 /* S_ph (e1: +cos th cos ph; printed with -) */
        -st * cp, ct * cp, 0,                  /* the twist S_th,ph */
        -ct * sp * sp, -st * sp * sp, -sp * cp /* N = S_th x S_ph, inwards */
    };
    memcpy(out, v, sizeof v);
}

int pc_sphere_frame_at(const double c[3], double r, double th, double ph, double out[15]) {
    if (!isfinite(c[0]) || !isfinite(c[1]) || !isfinite(c[2]) || !isfinite(r) || !isfinite(th) ||
        !isfinite(ph))
        return PC_ENONFINITE;
    if (!(r > 0)) return PC_EDOMAIN;
    pc_sphere_frame(th, ph, out);
    /* S = c + r S1: the derivatives and the twist scale by r, N = S_th x S_ph by r^2 */
    for (int j = 0; j < 3; j++) {
        out[j] = c[j] + r * out[j];
        for (int row = 1; row <= 3; row++) out[3 * row + j] *= r;
        out[12 + j] *= r * r;
    }
    return PC_OK;
}

static int sphere_eval(void *ud, double u, double v, int order, double *out) {
    const double *s = ud;                       /* centre, radius */
    double f[15];
    pc_sphere_frame(u, v, f);
    for (int j = 0; j < 3; j++) out[j] = s[j] + s[3] * f[j];
    out[3] = 1;
    if (order > 0) {
        for (int j = 0; j < 3; j++) {
            out[4 + j] = s[3] * f[3 + j];
            out[8 + j] = s[3] * f[6 + j];
        }
        out[7] = out[11] = 0;
    }
    return PC_OK;
}

pc_surface *pc_surface_sphere(const double c[3], double r, double th0, double th1, double ph0,
                              double ph1, int *status) {
    if (!isfinite(c[0]) || !isfinite(c[1]) || !isfinite(c[2]) || !isfinite(r) ||
        !isfinite(th0) || !isfinite(th1) || !isfinite(ph0) || !isfinite(ph1)) {
        *status = PC_ENONFINITE;
        return NULL;
    }
    if (!(r > 0) || !(th1 > th0) || !(ph1 > ph0)) {
        *status = PC_EDOMAIN;
        return NULL;
    }
    double *s = malloc(4 * sizeof(double));
    if (!s) {
        *status = PC_ENOMEM;
        return NULL;
    }
    memcpy(s, c, 3 * sizeof(double));
    s[3] = r;
    pc_surface *sf = pc_surface_func(3, th0, th1, ph0, ph1, sphere_eval, free, s, status);
    if (!sf) free(s);
    return sf;
}
