/* More of the map type in Lua (geom/map_more.c), declared on the argument layer, in the table
 * map: the textbook's perspective by (p, q, r) (§2.8.5), the foreshortening of an axonometry
 * (§2.8.3), the plane's axial affinity. */
#include "pcl_args.h"

static int l_perspective_pqr(lua_State *L) {
    pcl_val a[3] = {0};
    PCL_READ(L, a);
    pc_map *f = pcl_newmap(L);
    int st = pc_map_perspective_pqr(f, a[0].x, a[1].x, a[2].x);
    return st == PC_OK ? 1 : pcl_fail(L, "%s", pc_strerror(st));
}

static int l_foreshortening(lua_State *L) {
    pcl_val a[1] = {0};
    PCL_READ(L, a);
    const pc_map *f = a[0].obj;
    double k[PC_MAXDIM];
    if (pc_map_foreshortening(f, k) != PC_OK)
        return pcl_fail(L, "a perspective (projective) map has no constant foreshortening; give an affine map (an axonometry)");
    for (int i = 0; i < f->nin; i++) lua_pushnumber(L, k[i]);
    return f->nin;
}

static int l_axial_affinity(lua_State *L) {
    pcl_val a[4] = {0};
    PCL_READ(L, a);
    pc_map *f = pcl_newmap(L);
    int st = pc_map_axial_affinity(f, a[0].v, a[1].v, a[2].v, a[3].x);
    if (st == PC_EZERO) return pcl_fail(L, "the directions d and s must not be zero");
    if (st == PC_ECOLLINEAR) return pcl_fail(L, "the direction s lies along the axis d: no affinity");
    return st == PC_OK ? 1 : pcl_fail(L, "%s", pc_strerror(st));
}

static const pcl_arg pqr_args[] = {A_NUM("p"), A_NUM("q"), A_NUM("r"), PCL_END};
static const pcl_arg map_args[] = {A_MAP("f"), PCL_END};
static const pcl_arg affinity_args[] = {A_POINT("A", 2), A_VECTOR("d", 2), A_VECTOR("s", 2), A_NUM("k"), PCL_END};

static const pcl_fn fns[] = {
    PCL_FN("map.perspective_pqr", l_perspective_pqr, pqr_args, "f",
           "The textbook's perspective transform (Buimov §2.8.5): the 3-D map of row-vector matrix [[1,0,0,p],[0,1,0,q],[0,0,1,r],[0,0,0,1]], h = px + qy + rz + 1, vanishing points (1/p, 0, 0), (0, 1/q, 0), (0, 0, 1/r); one, two or three nonzero give the one-, two- and three-point perspectives. Follow it with a parallel projection."),
    {.name = "map.foreshortening", .fn = l_foreshortening, .args = map_args, .result = "fx, fy, fz",
     .help = "The foreshortening factors of an affine map (any axonometry, trimetric included): the lengths of the images of the unit axis vectors (§2.8.3)."},
    PCL_FN("map.axial_affinity", l_axial_affinity, affinity_args, "f",
           "The axial affinity of the plane: the axis through A along d fixed, each point moved along s with its distance (measured along s) from the axis multiplied by k (k = -1 an oblique reflection)."),
    PCL_END};

/* After pcl_open_map, with the module table on top. */
void pcl_open_map_more(lua_State *L) {
    lua_getfield(L, -1, "map");
    pcl_register(L, lua_gettop(L), fns, 0);
    lua_pop(L, 1);
}
