/* Binding of the one map type (stdlib/geom/map.h): one userdata "map" for affine and
 * projective maps, the 3-D -> 2-D projections and the textbook's matrices, in the tables
 * affine and map; the projections of l_curvilinear.c are maps of this type too. */
#include "pcl_args.h"
#include "pcl_point.h"
#include "pcl_core.h"
#include "pcl_books.h"
#include "map_make.h"

static const char REGKEY[] = "pointcalc.map";      /* the metatable in the registry */

/* A genuine map's block is a pc_map with dimensions 1..PC_MAXDIM (pcl.h: forged userdata). */
pc_map *pcl_tomap(lua_State *L, int idx) {
    pc_map *f = luaL_testudata(L, idx, REGKEY);
    int ok = !f || (lua_rawlen(L, idx) == sizeof(pc_map) && f->nin >= 1 && f->nin <= PC_MAXDIM &&
                    f->nout >= 1 && f->nout <= PC_MAXDIM);
    return pcl_genuine(L, idx, f, ok, "map");
}
static void *self_map(lua_State *L, int idx) { return pcl_tomap(L, idx); }

pc_map *pcl_newmap(lua_State *L) {
    pc_map *f = lua_newuserdatauv(L, sizeof(pc_map), 0);
    luaL_setmetatable(L, REGKEY);
    return f;
}

/* the new map on the stack top (1: pcl_check returns PC_OK), or its status explained by the why-table */
static int made(lua_State *L, int st) { return pcl_check(L, st, pc_map_why) == PC_OK; }

/* A map of pc_map_make, of the kind the function is named by (map.isometric): the declared
 * numbers in order (an enum: the index of its choice). */
PCL_BODY(l_make, a) {
    double x[3] = {0};
    for (int i = 0; i < pcl_nvalues(L) && i < 3; i++) x[i] = a[i].s ? a[i].n : a[i].x;
    return made(L, pc_map_make(pcl_newmap(L), pc_map_kind_named(strrchr(pcl_name(L), '.') + 1), x));
}

static const char *const CONVENTIONS[] = {"row", "column", NULL};   /* index 0: the textbook's rows */
#define CONVENTION {.name = "convention", .kind = PCL_ENUM, .flags = PCL_OPT, .choices = CONVENTIONS, .dflt = 1}

/* ---- affine(src, dst), affine.frame, affine.identity ----------------------------------------- */

/* The points of argument #k (a table, or a simplex) into out; their count, *dim their dimension. */
static int read_points(lua_State *L, int k, int idx, double *out, int *dim) {
    int t = lua_type(L, idx);
    if (t == LUA_TUSERDATA && luaL_getmetafield(L, idx, "__len") != LUA_TNIL) lua_pop(L, 1);
    else if (t != LUA_TTABLE)
        return pcl_argfail(L, k, "must be a table of points or a simplex, got %s", pcl_shown(L, idx));
    int m = (int)luaL_len(L, idx);
    if (m > PC_MAXDIM + 1) return pcl_argfail(L, k, "holds %d points; the largest dimension is %d", m, PC_MAXDIM);
    static const pcl_arg pt = {.kind = PCL_POINT, .flags = PCL_SAMEDIM};
    for (int i = 1; i <= m; i++) {
        pcl_val v;
        lua_geti(L, idx, i);
        pcl_readone(L, lua_gettop(L), k, i, &pt, i > 1 ? *dim : 0, &v);
        if (i == 1) *dim = v.n;
        memcpy(out + (i - 1) * v.n, v.v, sizeof(double) * (size_t)v.n);
        lua_pop(L, 1);
    }
    return m;
}

#define POINTSET "a table of points or a simplex"
static const pcl_arg affine_args[] = {{.name = "source points", .kind = PCL_ANY, .expect = POINTSET},
                                      {.name = "image points", .kind = PCL_ANY, .expect = POINTSET}, PCL_END};
PCL_BODY(l_affine, a) {
    double src[(PC_MAXDIM + 1) * PC_MAXDIM], dst[(PC_MAXDIM + 1) * PC_MAXDIM];
    int nin = 0, nout = 0, m = read_points(L, 1, 2, src, &nin), m2 = read_points(L, 2, 3, dst, &nout);
    pc_why_call why;
    pcl_check(L, pc_map_affine_checked(pcl_newmap(L), m, nin, m2, nout, src, dst, &why), why.row);
    return 1;
}

static const pcl_arg frame_args[] = {A_SAMEPOINT("O"), A_SAMELOC("X", 0), A_SAMELOC("Y", PCL_OPT),
                                     A_SAMELOC("Z", PCL_OPT), PCL_END};
static int l_frame(lua_State *L) {
    int m = lua_gettop(L), k = 0;
    if (m - 1 > PC_MAXDIM) return pcl_fail(L, "%d axes; the largest dimension is %d", m - 1, PC_MAXDIM);
    pcl_val a[PC_MAXDIM + 1] = {0};   /* O, X, Y, Z declared, the axes after them read one by one */
    PCL_READ(L, a);
    int n = a[0].n;
    double axes[PC_MAXDIM * PC_MAXDIM];
    static const pcl_arg more = A_SAMELOC(NULL, 0);
    for (int j = 2; j <= m && (j > 4 || a[j - 1].present); j++, k++) {   /* the axes up to the first absent */
        if (j > 4) pcl_readone(L, j, j, 0, &more, n, &a[j - 1]);
        for (int i = 0; i < n; i++)   /* a unit point: X - O */
            axes[k * n + i] = a[j - 1].v[i] - (a[j - 1].v[n] == 1 ? a[0].v[i] : 0);
    }
    return made(L, pc_map_frame(pcl_newmap(L), n, k, a[0].v, axes));
}

static const pcl_arg dim_arg[] = {A_INT("n", 1, PC_MAXDIM), PCL_END};

/* ---- the constructors of the map table ------------------------------------------------------ */

#define ROWS "a table of rows (tables of numbers)"
static const pcl_arg matrix_args[] = {{.name = "rows", .kind = PCL_TABLE, .expect = ROWS}, CONVENTION, PCL_END};
PCL_BODY(l_matrix_ctor, a) {
    int rowvec = a[1].n == 0, nr = (int)luaL_len(L, 1), nc = 0;
    if (nr < 2 || nr > PC_MAXDIM + 1)
        return pcl_argfail(L, 1, "holds %d rows; a map of n-D to m-D takes (m + 1) rows of n + 1 numbers "
                           "(\"row\": n + 1 rows of m + 1), n and m 1..%d", nr, PC_MAXDIM);
    double m[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)];
    pcl_read_rows(L, 1, 0, m, &nr, &nc);
    int nin = rowvec ? nr - 1 : nc - 1, nout = rowvec ? nc - 1 : nr - 1;
    return made(L, pc_map_from_matrix(pcl_newmap(L), nin, nout, m, rowvec));
}

static const pcl_arg translate_args[] = {A_VECTOR("V", 0), PCL_END};
PCL_BODY(l_translate, a) {
    return made(L, pc_map_translate_finite(pcl_newmap(L), a[0].n, a[0].v));
}

#define FACTORS "a number or a list of numbers {kx, ky, ...}"
static const pcl_arg scale_args[] = {{.name = "k", .kind = PCL_ANY, .expect = FACTORS},
                                     {.name = "centre", .kind = PCL_ANY, .flags = PCL_OPT}, PCL_END};
PCL_BODY(l_scale, a) {
    static const pcl_arg k0 = A_NUM("k"), dim = A_INT("n", 1, PC_MAXDIM);
    static const pcl_arg factors = A_NUMBERS("k", 1, PC_MAXDIM), centre = A_SAMEPOINT("centre");
    double k[PC_MAXDIM];
    pcl_val v = {.list = k, .cap = PC_MAXDIM}, c = {0};
    int single = lua_type(L, 1) == LUA_TNUMBER, ndim = single && lua_type(L, 2) == LUA_TNUMBER;
    if (!single && !lua_istable(L, 1)) return pcl_argfail(L, 1, "must be " FACTORS ", got %s", pcl_shown(L, 1));
    pcl_readone(L, 1, 1, 0, single ? &k0 : &factors, 0, &v);
    if (single && !ndim && !pcl_tovalue(L, 2))
        return pcl_argfail(L, 2, "must be a point or a dimension (a single factor k needs one), got %s",
                           pcl_shown(L, 2));
    if (a[1].present) pcl_readone(L, 2, 2, 0, ndim ? &dim : &centre, single ? 0 : v.n, &c);
    int n = ndim ? (int)c.x : single ? c.n : v.n;
    for (int i = 0; single && i < n; i++) k[i] = v.x;       /* one factor for every axis */
    pc_map_scale(pcl_newmap(L), n, k, c.present && !ndim ? c.v : NULL);
    return 1;
}

#define A_ANYOPT(nm) {.name = nm, .kind = PCL_ANY, .flags = PCL_OPT}
static const pcl_arg rotate_args[] = {A_ANYOPT("angle | A"), A_ANYOPT("centre | B"), A_ANYOPT("angle"), PCL_END};
PCL_BODY(l_rotate, a) {
    pcl_val A = {0}, B = {0}, t = {0};
    static const pcl_arg angle = A_NUM("angle");
    if (lua_type(L, 1) != LUA_TNUMBER && pcl_tovalue(L, 1)) {       /* about an axis in space */
        static const pcl_arg pA = A_POINT("A", 3), pB = A_SAMELOC("B", 0), dir = A_SAMELOC("direction", 0);
        if (pcl_tovalue(L, 1)->n != 3)
            return pcl_argfail(L, 1, "must be 3-D, got %d-D (a rotation in the plane is map.rotate(angle [, centre]))",
                               pcl_tovalue(L, 1)->n);
        pcl_readone(L, 1, 1, 0, &pA, 0, &A);
        pcl_value *q = pcl_tovalue(L, 2);
        int is_dir = q && pc_kind_of(q->h[q->n]) == PC_KIND_VECTOR;
        if (!q) return pcl_argfail(L, 2, "must be a point of the axis or its direction, got %s", pcl_shown(L, 2));
        pcl_readone(L, 2, 2, 0, is_dir ? &dir : &pB, 3, &B);
        pcl_readone(L, 3, 3, 0, &angle, 0, &t);
        return made(L, pc_map_rotate_axis(pcl_newmap(L), A.v, B.v, is_dir, t.x));
    }
    pcl_readone(L, 1, 1, 0, &angle, 0, &t);
    if (a[1].present) {
        static const pcl_arg centre = A_POINT("centre", 2);
        pcl_value *p = pcl_tovalue(L, 2);
        if (p && p->n != 2)
            return pcl_argfail(L, 2, "must be 2-D, got %d-D (a rotation in space is map.rotate(A, B or direction, "
                               "angle))", p->n);
        pcl_readone(L, 2, 2, 0, &centre, 0, &B);
    }
    pc_map_rotate2(pcl_newmap(L), t.x, B.present ? B.v : NULL);
    return 1;
}

static const pcl_arg reflect_args[] = {A_SAMEPOINT("A"), A_SAMEVECTOR("normal"), PCL_END};
PCL_BODY(l_reflect, a) {
    return made(L, pc_map_reflect(pcl_newmap(L), a[0].n, a[0].v, a[1].v));
}

/* Argument #k, an axis: 1..n or "x", "y", "z", "w"; returns it 0-based. */
static int axis_of(lua_State *L, int k, int n) {
    const char *s = lua_type(L, k) == LUA_TSTRING ? lua_tostring(L, k) : NULL;
    const char *at = s && s[0] && !s[1] ? strchr("xyzw", s[0]) : NULL;
    if (at && at - "xyzw" < n) return (int)(at - "xyzw");
    double i = lua_tonumber(L, k);
    if (!s && lua_type(L, k) == LUA_TNUMBER && i == floor(i) && i >= 1 && i <= n) return (int)i - 1;
    return pcl_argfail(L, k, "must be an axis 1..%d (or \"x\", \"y\", ...), got %s", n, pcl_shown(L, k));
}
static const pcl_arg shear_args[] = {A_INT("n", 2, PC_MAXDIM), {.name = "i", .kind = PCL_ANY},
                                     {.name = "j", .kind = PCL_ANY}, A_NUM("k"), PCL_END};
PCL_BODY(l_shear, a) {
    int n = (int)a[0].x, i = axis_of(L, 2, n), j = axis_of(L, 3, n);
    return made(L, pc_map_shear(pcl_newmap(L), n, i, j, a[3].x));   /* the axes in range: i == j fails */
}

static const char *const AXES[] = {"x", "y", "z", NULL};
static const pcl_arg ortho_args[] = {{.name = "axis", .kind = PCL_ENUM, .flags = PCL_OPT, .choices = AXES, .dflt = 2},
                                     PCL_END};
static const pcl_arg axono_args[] = {A_NUM("phi"), A_NUM("theta"), PCL_END};
#define FZ "a number between 0 and 1 (the foreshortening of the z axis)"
static const pcl_arg dimetric_args[] = {{.name = "fz", .kind = PCL_NUMBER, .expect = FZ}, PCL_END};
#define ALPHA {.name = "alpha", .kind = PCL_NUMBER, .flags = PCL_OPT, .dflt = 0.78539816339744831}
static const pcl_arg oblique_args[] = {A_NUM("k"), ALPHA, PCL_END};
static const pcl_arg alpha_arg[] = {ALPHA, PCL_END};
static const pcl_arg pqr_args[] = {A_NUM("p"), A_NUM("q"), A_NUM("r"), PCL_END};

static const pcl_arg persp_args[] = {A_POINT("eye", 3), A_POINT("p0", 3),
                                     {.name = "up", .kind = PCL_VECTOR, .flags = PCL_OPT, .dim = 3}, PCL_END};
PCL_BODY(l_perspective, a) {
    int st = pc_map_perspective(pcl_newmap(L), a[0].v, a[1].v, a[2].present ? a[2].v : NULL);
    return st == PC_OK ? 1 : pcl_fail(L, "%s", pc_map_perspective_why(st, a[2].present));
}

/* the foreshortening of an axonometry (§2.8.3), the plane's axial affinity (geom/map_more.c) */
static const pcl_arg map_args[] = {A_MAP("f"), PCL_END};
PCL_BODY(l_foreshortening, a) {
    const pc_map *f = a[0].obj;
    double k[PC_MAXDIM];
    pcl_check(L, pc_map_foreshortening(f, k), pc_map_why);
    return pcl_push_packed(L, f->nin, "x", k);
}

static const pcl_arg affinity_args[] = {A_POINT("A", 2), A_VECTOR("d", 2), A_VECTOR("s", 2), A_NUM("k"), PCL_END};
PCL_BODY(l_axial_affinity, a) {
    return made(L, pc_map_axial_affinity(pcl_newmap(L), a[0].v, a[1].v, a[2].v, a[3].x));
}

/* ---- applying a map ------------------------------------------------------------------------- */

/* f(p) or f(x, y, ...): the image, its weight snapped by the one rule (a weight of 1e-17 from
 * a projective matrix is a direction, not a point at 1e17); f:xy(...), the same body: the
 * coordinates of the image of a point as numbers.  The value is argument #1, or nin numbers. */
static int l_apply(lua_State *L) {
    pc_map *f = pcl_read(L, NULL, 0);
    int xy = !strcmp(pcl_running(L)->d->name, "f:xy"), m = lua_gettop(L) - 1, nin = f->nin, n = f->nout;
    if (!xy && (pcl_tocurve(L, 2) || pcl_tosurface(L, 2))) {   /* f(c) is c:map(f) */
        lua_getfield(L, 2, "map");
        lua_pushvalue(L, 2);
        lua_pushvalue(L, 1);
        lua_call(L, 2, 1);
        return 1;
    }
    double in[PC_MAXDIM + 1], out[PC_MAXDIM + 1];
    pcl_value *p = pcl_tovalue(L, 2);
    if (p) {
        if (m != 1) return pcl_fail(L, "takes one point or vector, got %d arguments", m);
        if (p->n != nin)
            return pcl_fail(L, "argument #1 is %d-D, but the map takes %d-D: dimensions cannot be mixed", p->n, nin);
        memcpy(in, p->h, sizeof(double) * (size_t)(nin + 1));
        pc_snap_weight(nin, in);
        if (xy && in[nin] != 1)
            return pcl_fail(L, "argument #1 (X) must be a point (weight 1), got weight %s", pcl_pushnum(L, in[nin]));
    } else {
        const char *got = !m ? "nothing" : lua_istable(L, 2) ? "a table (map a list with a loop, or a curve with f(c))"
                                                             : luaL_typename(L, 2);
        if (m != nin || lua_type(L, 2) != LUA_TNUMBER)
            return pcl_fail(L, "takes a %d-D point or vector, or %d coordinates; got %s", nin, nin, got);
        static const pcl_arg x = {.kind = PCL_NUMBER};
        for (int i = 0; i < nin; i++) {
            pcl_val v;
            pcl_readone(L, i + 2, i + 1, 0, &x, 0, &v);
            in[i] = v.x;
        }
        in[nin] = 1.0;
    }
    int st = pc_map_image_rule(f, in, out);
    if (st == PC_EPOLE) return pcl_fail(L, "argument #1 is the centre of the projection, which has no image");
    if (st == PC_ENONFINITE) return pcl_fail(L, "the image of argument #1 is out of range (not finite: a coordinate overflowed)");
    if (!xy) return pcl_push_packed(L, n, "w", out);
    if (st == PC_IMPROPER || out[n] == 0)
        return pcl_fail(L, "the image of argument #1 is at infinity (a direction); f(X) gives it as a vector");
    for (int i = 0; i < n; i++) out[i] /= out[n];
    return pcl_push_packed(L, n, "x", out);
}

static int compose(lua_State *L, pc_map *f, pc_map *g) {
    if (pc_map_compose(f, g, pcl_newmap(L)) != PC_OK)
        return pcl_error(L, "cannot compose: the first map applied gives %d-D, the second takes %d-D", g->nout, f->nin);
    return 1;
}

static int l_mul(lua_State *L) {
    pc_map *f = pcl_tomap(L, 1), *g = pcl_tomap(L, 2);
    const char *kind = pc_map_is_affine(f ? f : g) ? "an affine map" : "a projective map";
    if (!f || !g)
        return pcl_error(L, "cannot multiply %s by a %s: f * g composes two maps, and f(p) applies one", kind,
                         luaL_typename(L, f ? 2 : 1));
    return compose(L, f, g);
}

static const pcl_arg g_arg[] = {A_MAP("g"), PCL_END};
PCL_METHOD(l_compose, pc_map *f, a) {
    return compose(L, f, a[0].obj);
}

static int l_inverse(lua_State *L) {
    pc_map *f = pcl_read(L, NULL, 0);
    int st = pc_map_inverse(f, pcl_newmap(L));
    if (st == PC_EDIM)
        return pcl_fail(L, "a map from %d-D to %d-D (a projection or an embedding) has no inverse", f->nin, f->nout);
    return made(L, st);
}

static const pcl_arg conv_arg[] = {CONVENTION, PCL_END};
PCL_METHOD(l_matrix, pc_map *f, a) {
    int rowvec = a[0].n == 0;
    double m[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)];
    pc_map_to_matrix(f, rowvec, m);
    pcl_push_rows(L, rowvec ? f->nin + 1 : f->nout + 1, rowvec ? f->nout + 1 : f->nin + 1, m);
    return 1;
}

static int l_is_affine(lua_State *L) { return pcl_push_results(L, 0, "b", pc_map_is_affine(pcl_read(L, NULL, 0))); }

static int l_vanishing(lua_State *L) {
    pc_map *f = pcl_read(L, NULL, 0);
    double out[3][PC_MAXDIM + 1];
    int finite[3];
    if (pc_map_vanishing_points(f, out, finite) != PC_OK)
        return pcl_fail(L, "the map goes from %d-D to %d-D; vanishing points are the images of the axis "
                        "directions of a map from 3-D to 2-D or 3-D", f->nin, f->nout);
    for (int i = 0; i < 3; i++)
        if (finite[i]) pcl_push_packed(L, f->nout, "w", out[i]);
        else lua_pushnil(L);                   /* the direction stays at infinity */
    return 3;
}

PCL_METHOD(l_show, pc_map *f, v) {
    char text[(PC_MAXDIM + 1) * (PC_MAXDIM + 1) * 20 + 128];
    pc_map_show(f, v[0].n == 0, text, sizeof text);
    if (lua_getglobal(L, "print") == LUA_TFUNCTION) {
        lua_pushstring(L, text);
        lua_call(L, 1, 0);
    } else {
        printf("%s\n", text);
        fflush(stdout);
    }
    return 0;
}

static int l_tostring(lua_State *L) {
    pc_map *f = pcl_meta_self(L, pcl_tomap(L, 1), "tostring: not a map");
    char text[(PC_MAXDIM + 1) * (PC_MAXDIM + 1) * 24 + 64];
    pc_map_text(f, text, sizeof text);
    return pcl_push_results(L, 0, "s", text);
}

/* __index: the methods, then f.nin, f.nout and f.C0, f.C1, ... (the images of the origin and
 * of the unit points of the axes: a projection's screen points C0..C3). */
static int l_index(lua_State *L) {
    if (lua_type(L, 2) != LUA_TSTRING) return 0;
    const char *k = lua_tostring(L, 2);
    if (lua_getfield(L, lua_upvalueindex(1), k) != LUA_TNIL) return 1;   /* a plain table */
    pc_map *f = pcl_tomap(L, 1);
    if (!f) return 0;
    if (!strcmp(k, "nin") || !strcmp(k, "nout")) return pcl_push_results(L, 0, "i", k[1] == 'i' ? f->nin : f->nout);
    int i = pc_map_unit_name(k);
    if (i < 0) return 0;
    int st = pc_map_unit_image(f, i, pcl_newvalue(L, f->nout)->h);
    return st != PC_EPOLE && st != PC_EDOMAIN;   /* a point at infinity is its direction */
}

#define METHOD(nm, f, a, res, text) {.name = nm, .fn = f, .args = a, .result = res, .help = text, .self = self_map, .selftype = "map"}
#define METHODSIG(nm, f, forms, text) {.name = nm, .fn = f, .sig = forms, .help = text, .self = self_map, .selftype = "map"}
static const pcl_fn methods[] = {
    {.name = "f:compose", .fn = l_compose, .args = g_arg, .sig = "f:compose(g) | f * g -> map", .self = self_map, .selftype = "map", .help = "The map applying g first, then f."},
    METHOD("f:inverse", l_inverse, NULL, "map", "The inverse map; a singular or non-square map is an error."),
    METHODSIG("f:xy", l_apply, "f:xy(p) | f:xy(x, y, ...) -> x', y', ...", "The coordinates of the image of a point as numbers (two for a map into the plane)."),
    METHOD("f:matrix", l_matrix, conv_arg, "rows", "The homogeneous matrix as a table of rows: column vectors (the default) or the textbook's rows, p' = p T."),
    METHOD("f:is_affine", l_is_affine, NULL, "boolean", "Whether the map is affine (its weight row is 0 ... 0 1): it keeps points points and vectors vectors."), METHOD("f:vanishing_points", l_vanishing, NULL, "Vx, Vy, Vz", "The images of the x, y and z directions of a map from 3-D: points, or nil for a direction that stays at infinity."),
    METHOD("f:show", l_show, conv_arg, NULL, "Print the matrix with its convention named and the columns aligned."), PCL_END};
static const pcl_fn apply[] = {
    {.name = "f", .fn = l_apply, .self = self_map, .selftype = "map", .key = "__call", .topic = "f(p)", .callname = 1, .sig = "f(p) | f(x, y, ...) -> value", .help = "Apply a map: vectors ignore a translation; a point a projective map sends to infinity comes back as its direction, a vector."},
    PCL_END};
static const pcl_fn affine_call[] = {
    {.name = "affine", .fn = l_affine, .args = affine_args, .result = "f", .self = pcl_self_table, .selftype = "table", .key = "__call", .sig = "affine({A, B, C}, {A2, B2, C2}) -> f", .help = "The affine map sending A to A2, B to B2, C to C2 (3 pairs in the plane, 4 in space; images may have another dimension)."},
    PCL_END};
static const pcl_fn affine_fns[] = {
    {.name = "affine.frame", .fn = l_frame, .args = frame_args, .sig = "affine.frame(O, X, Y [, Z]) -> f", .help = "The map (x, y, z) -> O + x(X - O) + y(Y - O) + z(Z - O); the axes may also be vectors."},
    PCL_FN("affine.identity", l_make, dim_arg, "f", "The identity map of n-space."), PCL_END};
static const pcl_fn ctors[] = {
    PCL_FN("map.matrix", l_matrix_ctor, matrix_args, "f", "The map of a homogeneous matrix (a table of rows): by default (m+1) rows of n+1 acting on column vectors; \"row\": the textbook's p' = p T, n+1 rows of m+1."),
    PCL_FN("map.translate", l_translate, translate_args, "f", "The translation x -> x + V, in the dimension of V."),
    {.name = "map.scale", .fn = l_scale, .args = scale_args, .sig = "map.scale(k, centre | n) | map.scale({kx, ky, ...} [, centre]) -> f", .help = "Scaling by k (or by kx, ky, ... per axis) about centre (default: the origin); a single k needs a centre or the dimension n."},
    {.name = "map.rotate", .fn = l_rotate, .args = rotate_args, .sig = "map.rotate(angle [, centre]) -> f\nmap.rotate(A, B | direction, angle) -> f", .help = "The plane turned counter-clockwise about centre (default: the origin), or space turned about the axis through A and B (or through A along direction) by the right-hand rule."},
    PCL_FN("map.reflect", l_reflect, reflect_args, "f", "The reflection in the line (plane, hyperplane) through A perpendicular to the vector normal."),
    PCL_FN("map.shear", l_shear, shear_args, "f", "The shear of n-space adding k times coordinate j to coordinate i (axes 1..n or \"x\", \"y\", \"z\")."),
    PCL_FN("map.orthographic", l_make, ortho_args, "f", "Space onto a coordinate plane, dropping that axis: \"z\" (the default) keeps (x, y), \"y\" keeps (x, z), \"x\" keeps (y, z)."),
    PCL_FN("map.axonometric", l_make, axono_args, "f", "Space turned about y by phi, then about x by theta, then projected along z (the textbook's T = Ry Rx Pz)."),
    PCL_FN("map.isometric", l_make, NULL, "f", "The isometric projection: phi = 45 degrees, theta = 35.26 degrees, all axes foreshortened by sqrt(2/3)."),
    PCL_FN("map.dimetric", l_make, dimetric_args, "f", "The dimetric projection with the z axis foreshortened by fz (0 < fz < 1) and x, y equally: sin^2 theta = fz^2/2."),
    PCL_FN("map.oblique", l_make, oblique_args, "f", "The oblique projection x' = x + k z cos(alpha), y' = y + k z sin(alpha)."),
    PCL_FN("map.cavalier", l_make, alpha_arg, "f", "The oblique projection with k = 1 (receding axis at full length); alpha defaults to 45 degrees."),
    PCL_FN("map.cabinet", l_make, alpha_arg, "f", "The oblique projection with k = 1/2; alpha defaults to 45 degrees."),
    PCL_FN("map.perspective", l_perspective, persp_args, "f", "The central projection from eye onto the plane through p0 facing it: picture origin at p0, x to the right, y along up (default: the z axis); a direction goes to its vanishing point."),
    PCL_FN("map.perspective_pqr", l_make, pqr_args, "f", "The textbook's perspective transform (Buimov §2.8.5): the 3-D map of row-vector matrix [[1,0,0,p],[0,1,0,q],[0,0,1,r],[0,0,0,1]], h = px + qy + rz + 1, vanishing points (1/p, 0, 0), (0, 1/q, 0), (0, 0, 1/r); one, two or three nonzero give the one-, two- and three-point perspectives. Follow it with a parallel projection."),
    {.name = "map.foreshortening", .fn = l_foreshortening, .args = map_args, .result = "fx, fy, fz", .help = "The foreshortening factors of an affine map (any axonometry, trimetric included): the lengths of the images of the unit axis vectors (§2.8.3)."},
    PCL_FN("map.axial_affinity", l_axial_affinity, affinity_args, "f", "The axial affinity of the plane: the axis through A along d fixed, each point moved along s with its distance (measured along s) from the axis multiplied by k (k = -1 an oblique reflection)."),
    PCL_END};

void pcl_open_map(lua_State *L) {
    int module = lua_gettop(L);
    static const luaL_Reg meta[] = {{"__mul", l_mul}, {"__tostring", l_tostring}, {NULL, NULL}};
    pcl_open_type(L, REGKEY, meta, apply, methods, l_index);
    lua_pushliteral(L, "map");
    lua_setfield(L, -2, "__name");

    pcl_new_table(L, module, "affine", affine_fns, affine_call);   /* affine(src, dst) its __call */
    pcl_new_table(L, module, "map", ctors, NULL);
    lua_settop(L, module);
}
