/* Facilities the drawing bindings share (pcl_draw.h): the attribute reader, genuine tagged
 * userdata, the reader of strings, lists of n-D points as places on the screen. */
#include "pcl_draw.h"

int pcl_read_attr(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    int n = pcl_active_canvas(L)->ncolors, isint;
    lua_Integer v = lua_tointegerx(L, idx, &isint);
    if (lua_type(L, idx) == LUA_TNUMBER && isint && v >= 0 && v < n) return (out->x = (double)v), 1;
    return pcl_readfail(L, idx, lua_pushfstring(L, "%s 0..%d", a->dim ? "an attribute" : "a colour number", n - 1));
}

int pcl_read_bytes(lua_State *L, int idx, const pcl_arg *a, pcl_val *out) {
    size_t n;
    int t = lua_type(L, idx);
    if (t != LUA_TSTRING && (t != LUA_TNUMBER || !a->dim)) return 0;
    out->s = lua_tolstring(L, idx, &n);
    out->n = (int)n;
    if (a->hi == 0) return strlen(out->s) == n || pcl_readfail(L, idx, a->dim ? "a string without NUL bytes"
                                                                             : "a string without zero bytes");
    return (n >= a->lo && n <= a->hi) || pcl_readfail(L, idx, a->expect);
}

double *pcl_places(lua_State *L, const pcl_val *list, const char *what) {
    double *xy = lua_newuserdatauv(L, sizeof(double) * 2 * (size_t)list->n + 1, 0);
    long bad = pc_place_rows(pcl_camera(L), (size_t)list->n, list->dim, list->list, xy);
    if (bad >= 0)
        pcl_fail(L, "%s [%d] must be " PCL_PLACE_TEXT ", got a %d-D point", what, (int)bad + 1, list->dim);
    return xy;
}
