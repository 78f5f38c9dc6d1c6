/* A simplex as text, and the wording of a simplex that cannot be built (simplex.h). */
#include <stdio.h>
#include <string.h>
#include "simplex.h"

size_t pc_simplex_init_text(int st, int n, int k, const double *v, char *buf, size_t size) {
    static const char *const shapes[] = {"simplex", "segment", "triangle", "tetrahedron"};
    const char *shape = shapes[k <= 3 ? k : 0], *how = k == 2 ? "collinear" : k == 3 ? "coplanar" : "dependent";
    if (st == PC_EDIM && k > n)
        return (size_t)snprintf(buf, size, "%d points in %d-D are always dependent: a simplex has at most "
                                "dimension + 1 = %d vertices", k + 1, n, n + 1);
    for (int i = 1; st == PC_ECOINCIDENT && i <= k; i++)
        if (pc_dist(n, v, v + i * n) == 0)
            return (size_t)snprintf(buf, size, "argument #%d coincides with argument #1 (the initial point): "
                                    "a degenerate simplex", i + 1);
    if (st == PC_ECOLLINEAR)
        return (size_t)snprintf(buf, size, "the %d points are %s: a flat (degenerate) %s", k + 1, how, shape);
    return (size_t)snprintf(buf, size, "%s", pc_strerror(st));
}

size_t pc_simplex_text(const pc_simplex *s, char *buf, size_t size) {
    size_t len = (size_t)snprintf(buf, size, "simplex(");
    double h[PC_MAXDIM + 1];
    for (int i = 0; i <= s->k; i++) {
        memcpy(h, PC_SIMPLEX_V(s) + i * s->n, sizeof(double) * (size_t)s->n);
        h[s->n] = 1;
        len += (size_t)snprintf(len < size ? buf + len : NULL, len < size ? size - len : 0, "%s", i ? ", " : "");
        len += pc_value_text(s->n, h, len < size ? buf + len : NULL, len < size ? size - len : 0);
    }
    len += (size_t)snprintf(len < size ? buf + len : NULL, len < size ? size - len : 0, ")");
    return len;
}
