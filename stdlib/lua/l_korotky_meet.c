/* korotky.plane_meet(P1, P2, P3, Q1, Q2, Q3) -> K: the standalone meet of two 2-planes of
 * 4-space (books/korotky/pencils4.h pc_meet_planes4, the step of the 4-D key construction of
 * Korotky 2015, B.4), each plane through three 4-D points (a vector is a point at infinity). */
#include "pcl.h"
#include "pcl_point.h"
#include "pencils4.h"

static int l_plane_meet(lua_State *L) {
    const char *fn = "korotky.plane_meet";
    static const char *nm[6] = {"P1", "P2", "P3", "Q1", "Q2", "Q3"};
    double p[3][5], q[3][5], out[5];
    for (int i = 0; i < 6; i++) {
        pcl_value *v = pcl_tovalue(L, i + 1);
        if (!v) return pcl_argerror_full(L, fn, i + 1, i + 1, nm[i], "a 4-D point or vector");
        if (v->n != 4) return pcl_error(L, "%s: argument #%d (%s) must be 4-D, got %d-D", fn, i + 1, nm[i], v->n);
        for (int k = 0; k < 5; k++) (i < 3 ? p[i] : q[i - 3])[k] = v->h[k];
    }
    int st = pc_meet_planes4(p, q, out);
    if (st == PC_ESAME_LINE) return pcl_error(L, "%s: the planes share a line (more than one common point)", fn);
    if (st == PC_ESKEW) return pcl_error(L, "%s: the planes do not meet (a spanning triple is collinear, or they are parallel)", fn);
    if (st != PC_OK) return pcl_statuserror(L, fn, st, NULL);
    pcl_value *r = pcl_newvalue(L, 4);
    for (int k = 0; k < 5; k++) r->h[k] = out[k];
    return 1;
}

/* After pcl_open_korotky, with the module table on top. */
void pcl_open_korotky_meet(lua_State *L) {
    lua_getfield(L, -1, "korotky");
    lua_pushcfunction(L, l_plane_meet);
    lua_setfield(L, -2, "plane_meet");
    lua_pop(L, 1);
}
