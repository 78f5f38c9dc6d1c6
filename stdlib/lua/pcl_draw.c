/* Facilities the drawing bindings share (pcl_draw.h): fields of a result table, and lists of
 * n-D points as places on the screen. */
#include "pcl_draw.h"
#include "pcl_curve.h"

void pcl_set_fields(lua_State *L, int n, const char *const *names, const double *x, int integers) {
    for (int i = 0; i < n; i++) {
        if (integers) lua_pushinteger(L, (lua_Integer)x[i]);
        else lua_pushnumber(L, x[i]);
        lua_setfield(L, -2, names[i]);
    }
}

int pcl_rows_to_xy(lua_State *L, int n, int dim, const double *rows, double *xy) {
    for (int i = 0; i < n; i++) {
        double h[PC_MAXDIM + 1];
        memcpy(h, rows + (size_t)i * dim, sizeof(double) * (size_t)dim);
        h[dim] = 1;
        if (dim == 2) xy[2 * i] = h[0], xy[2 * i + 1] = h[1];
        else if (pcl_project(L, dim, h, &xy[2 * i], &xy[2 * i + 1]) != PC_OK) return i;
    }
    return -1;
}
