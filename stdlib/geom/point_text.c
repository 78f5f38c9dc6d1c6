/* A value as text (point.h): P(1, 2) for a point, V(0, 1) for a vector, k*P(x, y) for a weight
 * k other than 0 and 1: valid Lua that rebuilds it, coordinates with 14 significant digits
 * and no "-0". */
#include <stdio.h>
#include <string.h>
#include "point.h"

static size_t add(char *buf, size_t size, size_t len, const char *s) {
    if (len < size) snprintf(buf + len, size - len, "%s", s);
    return len + strlen(s);
}

static size_t add_num(char *buf, size_t size, size_t len, double x) {
    char s[32];
    snprintf(s, sizeof s, "%.14g", x == 0 ? 0.0 : x);
    return add(buf, size, len, s);
}

size_t pc_value_text(int n, const double *h, char *buf, size_t size) {
    double w = h[n], div = 1;
    pc_kind kind = pc_kind_of(w);
    size_t len = 0;
    if (size) buf[0] = 0;
    if (kind == PC_KIND_WEIGHTED) {
        len = add(buf, size, add_num(buf, size, len, w), "*");
        div = w;
    } else if (kind == PC_KIND_POINT) {
        div = w;                          /* within 1e-9 of 1: shown as the point it counts as */
    }
    len = add(buf, size, len, kind == PC_KIND_VECTOR ? "V(" : "P(");
    for (int i = 0; i < n; i++) {
        if (i) len = add(buf, size, len, ", ");
        len = add_num(buf, size, len, div == 1 ? h[i] : h[i] / div);
    }
    return add(buf, size, len, ")");
}
