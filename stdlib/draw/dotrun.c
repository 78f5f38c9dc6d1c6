/* Dense runs of dots (dotrun.h). */
#include <math.h>
#include "dotrun.h"

size_t pc_dot_runs(const pc_xy *d, size_t n, size_t *runs) {
    size_t m = 0;
    for (size_t i = 0; i < n;) {
        size_t j = i + 1;
        double far = 0;
        while (j < n && hypot(d[j].x - d[j - 1].x, d[j].y - d[j - 1].y) <= PC_DOTRUN_DENSE) {
            double r = hypot(d[j].x - d[i].x, d[j].y - d[i].y);
            if (r > far) far = r;
            j++;
        }
        if (j - i >= PC_DOTRUN_MIN && far >= PC_DOTRUN_EXTENT) {
            runs[2 * m] = i;
            runs[2 * m + 1] = j;
            m++;
        }
        i = j;
    }
    return m;
}

size_t pc_dot_run_thin(const pc_xy *d, size_t n, double step, pc_xy *out) {
    if (n == 0) return 0;
    size_t m = 0;
    out[m++] = d[0];
    for (size_t i = 1; i + 1 < n; i++)
        if (hypot(d[i].x - out[m - 1].x, d[i].y - out[m - 1].y) >= step) out[m++] = d[i];
    if (n > 1) out[m++] = d[n - 1];
    return m;
}
