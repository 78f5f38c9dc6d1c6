/* More of the map type in Lua (geom/map_more.c), in the table map:
 *   map.perspective_pqr(p, q, r) -> f      the textbook's perspective transform (§2.8.5)
 *   map.foreshortening(f) -> fx, fy, fz    of an axonometry (§2.8.3)
 *   map.axial_affinity(A, d, s, k) -> f    the plane's affinity with the axis A + t d */
#include <math.h>
#include "pcl.h"
#include "pcl_point.h"
#include "pcl_books.h"

static int l_perspective_pqr(lua_State *L) {
    const char *fn = "map.perspective_pqr";
    double p = pcl_checknum(L, fn, 1, "p"), q = pcl_checknum(L, fn, 2, "q"), r = pcl_checknum(L, fn, 3, "r");
    pc_map *f = pcl_newmap(L);
    int st = pc_map_perspective_pqr(f, p, q, r);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    return 1;
}

static int l_foreshortening(lua_State *L) {
    const char *fn = "map.foreshortening";
    pc_map *f = pcl_tomap(L, 1);
    if (!f) return pcl_argerror_full(L, fn, 1, 1, "f", "a map");
    double k[PC_MAXDIM];
    if (pc_map_foreshortening(f, k) != PC_OK)
        return pcl_error(L, "%s: a perspective (projective) map has no constant foreshortening; give an affine map (an axonometry)", fn);
    for (int i = 0; i < f->nin; i++) lua_pushnumber(L, k[i]);
    return f->nin;
}

static int l_axial_affinity(lua_State *L) {
    const char *fn = "map.axial_affinity";
    double a[2], d[2], s[2];
    pclb_point(L, fn, 1, "A", 2, 0, NULL, a);
    static const char *vn[2] = {"d", "s"};
    double *v[2] = {d, s};
    for (int i = 0; i < 2; i++) {
        pcl_value *x = pcl_tovalue(L, i + 2);
        if (!x || x->n != 2 || fabs(x->h[2]) > PC_WEIGHT_TOL)
            return pcl_argerror_full(L, fn, i + 2, i + 2, vn[i], "a 2-D vector");
        v[i][0] = x->h[0], v[i][1] = x->h[1];
    }
    double k = pcl_checknum(L, fn, 4, "k");
    pc_map *f = pcl_newmap(L);
    int st = pc_map_axial_affinity(f, a, d, s, k);
    if (st == PC_EZERO) return pcl_error(L, "%s: the directions d and s must not be zero", fn);
    if (st == PC_ECOLLINEAR) return pcl_error(L, "%s: the direction s lies along the axis d: no affinity", fn);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    return 1;
}

/* After pcl_open_map, with the module table on top. */
void pcl_open_map_more(lua_State *L) {
    lua_getfield(L, -1, "map");
    static const luaL_Reg fns[] = {
        {"perspective_pqr", l_perspective_pqr}, {"foreshortening", l_foreshortening},
        {"axial_affinity", l_axial_affinity}, {NULL, NULL}};
    luaL_setfuncs(L, fns, 0);
    lua_pop(L, 1);
}
