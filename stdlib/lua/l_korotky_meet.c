/* korotky.plane_meet(P1, P2, P3, Q1, Q2, Q3) -> K, declared on the argument layer: the
 * standalone meet of two 2-planes of 4-space (books/korotky/pencils4.h pc_meet_planes4, the
 * step of the 4-D key construction of Korotky 2015, B.4). */
#include "pcl_args.h"
#include "pcl_point.h"
#include "pencils4.h"

static int l_plane_meet(lua_State *L) {
    pcl_val a[6] = {0};
    PCL_READ(L, a);
    double p[3][5], q[3][5], out[5];
    for (int i = 0; i < 6; i++)
        for (int k = 0; k < 5; k++) (i < 3 ? p[i] : q[i - 3])[k] = a[i].v[k];
    int st = pc_meet_planes4(p, q, out);
    if (st == PC_ESAME_LINE) return pcl_fail(L, "the planes share a line (more than one common point)");
    if (st == PC_ESKEW) return pcl_fail(L, "the planes do not meet (a spanning triple is collinear, or they are parallel)");
    if (st != PC_OK) return pcl_fail(L, "%s", pc_strerror(st));
    pcl_snap_weight(4, out);
    pcl_value *r = pcl_newvalue(L, 4);
    for (int k = 0; k < 5; k++) r->h[k] = out[k];
    return 1;
}

#define A_LOC4(nm) {.name = nm, .kind = PCL_LOC, .dim = 4}
static const pcl_arg meet_args[] = {A_LOC4("P1"), A_LOC4("P2"), A_LOC4("P3"),
                                    A_LOC4("Q1"), A_LOC4("Q2"), A_LOC4("Q3"), PCL_END};
static const pcl_fn fns[] = {
    PCL_FN("korotky.plane_meet", l_plane_meet, meet_args, "K",
           "The meet of the 2-plane through P1, P2, P3 and the one through Q1, Q2, Q3 in 4-space (B.4, the step of the key construction): one point in general, a vector when it is at infinity; a vector among the six is a point at infinity."),
    PCL_END};

/* After pcl_open_korotky, with the module table on top. */
void pcl_open_korotky_meet(lua_State *L) {
    lua_getfield(L, -1, "korotky");
    pcl_register(L, lua_gettop(L), fns, 0);
    lua_pop(L, 1);
}
