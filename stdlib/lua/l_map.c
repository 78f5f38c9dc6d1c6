/* Binding of the one map type (stdlib/geom/map.h): one userdata "map" for affine and
 * projective maps, the 3-D -> 2-D projections and the textbook's matrices.
 *
 *   f = affine({A, B, C}, {A2, B2, C2})   the map sending A to A2, B to B2, C to C2 (2-D by 3 pairs,
 *                                          3-D by 4; the images may have another dimension)
 *   f = affine.frame(O, X, Y [, Z])        (x, y, z) -> O + x(X - O) + y(Y - O) + z(Z - O); axes
 *                                          may also be given as vectors
 *   affine.identity(n)
 *   map.matrix(rows [, "row"|"column"])    the homogeneous matrix; "row": the textbook's p' = p T
 *   map.translate(V)  map.scale(k | {kx, ky, ...} [, centre | n])  map.rotate(angle [, centre])
 *   map.rotate(A, B | direction, angle)    map.reflect(A, normal)  map.shear(n, i, j, k)
 *   map.orthographic("z"|"y"|"x")  map.axonometric(phi, theta)  map.isometric()  map.dimetric(fz)
 *   map.oblique(k, alpha)  map.cavalier([alpha])  map.cabinet([alpha])  map.perspective(eye, p0 [, up])
 *   f(p), f(x, y, ...)                     apply (vectors ignore a translation; a point sent to
 *                                          infinity gives its direction, a vector)
 *   f:xy(p), f:xy(x, y, ...)               the image's coordinates as numbers
 *   f * g, f:compose(g)                    g first, then f
 *   f:inverse()                            singular or non-square maps are an error
 *   f:matrix([convention])  f:is_affine()  f:vanishing_points()  f:show([convention])
 *   f.nin, f.nout, f.C0, f.C1, ...         dimensions; the images of the origin and unit points
 * The projections of l_curvilinear.c (projection, oblique) are maps of this type too. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pcl_point.h"
#include "pcl_curve.h"
#include "map.h"

#define AMT lua_upvalueindex(1)
static const char REGKEY[] = "pointcalc.map";      /* the metatable in the registry */

/* A genuine map's block is a pc_map with dimensions 1..PC_MAXDIM (pcl.h: forged userdata). */
static pc_map *genuine_map(lua_State *L, int idx, pc_map *f) {
    int ok = !f || (lua_rawlen(L, idx) == sizeof(pc_map) && f->nin >= 1 &&
                    f->nin <= PC_MAXDIM && f->nout >= 1 && f->nout <= PC_MAXDIM);
    return pcl_genuine(L, idx, f, ok, "map");
}

static pc_map *tomap(lua_State *L, int idx) { return genuine_map(L, idx, pcl_testudata(L, idx, AMT)); }

pc_map *pcl_tomap(lua_State *L, int idx) { return genuine_map(L, idx, luaL_testudata(L, idx, REGKEY)); }

pc_map *pcl_newmap(lua_State *L) {
    pc_map *f = lua_newuserdatauv(L, sizeof(pc_map), 0);
    luaL_setmetatable(L, REGKEY);
    return f;
}

static pc_map *newmap(lua_State *L) {
    pc_map *f = lua_newuserdatauv(L, sizeof(pc_map), 0);
    lua_pushvalue(L, AMT);
    lua_setmetatable(L, -2);
    return f;
}

static const char *kind_of(const pc_map *f) {
    return pc_map_is_affine(f) ? "an affine map" : "a projective map";
}

/* ---- argument checks with an explicit function name (map.rotate, ...) ----------------------- */

/* Push x as points print their coordinates (%.14g, no -0) and return it. */
static const char *numtext(lua_State *L, double x) {
    char s[32];
    snprintf(s, sizeof s, "%.14g", x == 0 ? 0.0 : x);
    return lua_pushstring(L, s);
}

static double checknum(lua_State *L, const char *fn, int arg, const char *what) {
    int isnum;
    double v = lua_tonumberx(L, arg, &isnum);
    if (!isnum || lua_type(L, arg) != LUA_TNUMBER || !isfinite(v))
        pcl_argerror_full(L, fn, arg, arg, what, "a finite number");
    return v;
}

static double optnum(lua_State *L, const char *fn, int arg, const char *what, double dflt) {
    return lua_isnoneornil(L, arg) ? dflt : checknum(L, fn, arg, what);
}

/* A point (weight 1) of dimension dim (0: any) into out; returns its dimension. */
static int checkpoint(lua_State *L, const char *fn, int arg, const char *what, int dim,
                      int dim_arg, double *out) {
    pcl_value *p = pcl_tovalue(L, arg);
    if (!p) pcl_argerror_full(L, fn, arg, arg, what, "a point");
    if (dim > 0 && p->n != dim) {
        if (dim_arg > 0)
            pcl_error(L, "%s: argument #%d (%s) is %d-D, but argument #%d is %d-D: dimensions "
                      "cannot be mixed", fn, arg, what, p->n, dim_arg, dim);
        pcl_error(L, "%s: argument #%d (%s) must be %d-D, got %d-D", fn, arg, what, dim, p->n);
    }
    if (pc_loc(p->n, p->h, out) != PC_OK)
        pcl_error(L, "%s: argument #%d (%s) must be a point (weight 1), got %s of weight %s", fn,
                  arg, what, pc_kind_of(p->h[p->n]) == PC_KIND_VECTOR ? "a vector" : "a value",
                  numtext(L, p->h[p->n]));
    return p->n;
}

/* A vector (weight 0) of dimension dim (0: any) into out; returns its dimension. */
static int checkvector(lua_State *L, const char *fn, int arg, const char *what, int dim,
                       int dim_arg, double *out) {
    pcl_value *p = pcl_tovalue(L, arg);
    if (!p) pcl_argerror_full(L, fn, arg, arg, what, "a vector");
    if (dim > 0 && p->n != dim) {
        if (dim_arg > 0)
            pcl_error(L, "%s: argument #%d (%s) is %d-D, but argument #%d is %d-D: dimensions "
                      "cannot be mixed", fn, arg, what, p->n, dim_arg, dim);
        pcl_error(L, "%s: argument #%d (%s) must be %d-D, got %d-D", fn, arg, what, dim, p->n);
    }
    if (pc_kind_of(p->h[p->n]) != PC_KIND_VECTOR)
        pcl_error(L, "%s: argument #%d (%s) must be a vector (weight 0), got %s; a difference of "
                  "points is a vector, e.g. B - A", fn, arg, what, luaL_tolstring(L, arg, NULL));
    memcpy(out, p->h, sizeof(double) * (size_t)p->n);
    return p->n;
}

/* The convention argument: 1 for "row", 0 for "column" (the default). */
static int checkconv(lua_State *L, const char *fn, int idx, int shown) {
    if (lua_isnoneornil(L, idx)) return 0;
    const char *s = lua_type(L, idx) == LUA_TSTRING ? lua_tostring(L, idx) : NULL;
    if (s && !strcmp(s, "row")) return 1;
    if (s && !strcmp(s, "column")) return 0;
    return pcl_argerror_full(L, fn, idx, shown, "convention", "\"row\" or \"column\"");
}

/* ---- affine(src, dst), affine.frame, affine.identity ----------------------------------------- */

/* Points of a table (or a simplex) at arg into out; returns their count, *dim their dimension. */
static int read_points(lua_State *L, int arg, const char *what, double *out, int *dim) {
    int t = lua_type(L, arg);                        /* a table, or a simplex */
    if (t != LUA_TTABLE && t != LUA_TUSERDATA) return pcl_argerror(L, arg, what, "a table of points");
    if (t == LUA_TUSERDATA) {    /* one that has a length and items: a simplex, not complex(1, 2) */
        if (luaL_getmetafield(L, arg, "__len") == LUA_TNIL)
            return pcl_argerror(L, arg, what, "a table of points or a simplex");
        lua_pop(L, 1);
    }
    int m = (int)luaL_len(L, arg);
    if (m > PC_MAXDIM + 1)
        return pcl_error(L, "%s: argument #%d (%s) holds %d points; the largest dimension is %d",
                          pcl_fname(L), arg, what, m, PC_MAXDIM);
    int n = 0;
    for (int i = 1; i <= m; i++) {
        lua_geti(L, arg, i);
        pcl_value *p = pcl_tovalue(L, -1);
        if (!p)
            return pcl_error(L, "%s: argument #%d (%s) item [%d] must be a point, got %s",
                              pcl_fname(L), arg, what, i, luaL_typename(L, -1));
        if (i == 1) n = p->n;
        if (p->n != n)
            return pcl_error(L, "%s: argument #%d (%s) mixes dimensions: item [%d] is %d-D, item "
                              "[1] is %d-D", pcl_fname(L), arg, what, i, p->n, n);
        if (pc_loc(n, p->h, out + (i - 1) * n) != PC_OK)
            return pcl_error(L, "%s: argument #%d (%s) item [%d] must be a point (weight 1), got "
                              "one of weight %f", pcl_fname(L), arg, what, i, p->h[n]);
        lua_pop(L, 1);
    }
    *dim = n;
    return m;
}

/* affine(src, dst), the __call of the affine table: the table itself is dropped, so that
 * src and dst are arguments #1 and #2 and a missing dst reads as nil. */
static int l_affine(lua_State *L) {
    lua_remove(L, 1);
    double src[(PC_MAXDIM + 1) * PC_MAXDIM], dst[(PC_MAXDIM + 1) * PC_MAXDIM];
    int nin, nout;
    int m = read_points(L, 1, "source points", src, &nin);
    int m2 = read_points(L, 2, "image points", dst, &nout);
    if (m < 2)
        return pcl_error(L, "affine: argument #1 (source points) holds %d points; a map of n-D "
                          "needs n + 1 (3 in the plane, 4 in space)", m);
    if (m != nin + 1)
        return pcl_error(L, "affine: argument #1 (source points) holds %d %d-D points; a map of "
                          "%d-D needs %d (dimension + 1)", m, nin, nin, nin + 1);
    if (m2 != m)
        return pcl_error(L, "affine: argument #2 (image points) holds %d points, argument #1 %d: "
                          "they must pair up", m2, m);
    pc_map *f = newmap(L);
    int st = pc_map_affine_points(f, nin, nout, src, dst);
    if (st == PC_ECOINCIDENT || st == PC_ECOLLINEAR) {
        const char *how = nin == 1 ? "coincide" : nin == 2 ? "are collinear" :
                          nin == 3 ? "are coplanar" : "are dependent";
        return pcl_error(L, "affine: the source points %s, so they do not fix an affine map",
                          how);
    }
    if (st != PC_OK) return pcl_error(L, "affine: %s", pc_strerror(st));
    return 1;
}

static int l_frame(lua_State *L) {
    int m = lua_gettop(L);
    double o[PC_MAXDIM], axes[PC_MAXDIM * PC_MAXDIM];
    int n = pcl_checkloc(L, 1, "O", 0, 0, o);
    if (m < 2) pcl_argerror(L, 2, "X", "a point or vector");
    if (m - 1 > PC_MAXDIM)
        return pcl_error(L, "%s: %d axes; the largest dimension is %d", pcl_fname(L), m - 1,
                          PC_MAXDIM);
    static const char *names[] = {"X", "Y", "Z"};
    for (int j = 2; j <= m; j++) {
        const char *what = j - 2 < 3 ? names[j - 2] : NULL;
        pcl_value *p = pcl_checkvalue(L, j, what);
        if (p->n != n) pcl_dimerror(L, j, what, p->n, n, 1);
        double *a = axes + (j - 2) * n;
        if (pc_kind_of(p->h[n]) == PC_KIND_VECTOR) {
            memcpy(a, p->h, sizeof(double) * (size_t)n);          /* an axis vector */
        } else {
            pcl_checkloc(L, j, what, n, 1, a);                     /* a unit point: X - O */
            for (int i = 0; i < n; i++) a[i] -= o[i];
        }
    }
    pc_map *f = newmap(L);
    pc_map_frame(f, n, m - 1, o, axes);
    return 1;
}

static int l_identity(lua_State *L) {
    int isint;
    lua_Integer n = lua_tointegerx(L, 1, &isint);
    if (!isint || n < 1 || n > PC_MAXDIM) {
        char expected[48];
        snprintf(expected, sizeof expected, "a dimension 1..%d", PC_MAXDIM);
        return pcl_argerror(L, 1, "n", expected);
    }
    pc_map_identity(newmap(L), (int)n);
    return 1;
}

/* ---- the constructors of the map table ------------------------------------------------------ */

static int l_matrix_ctor(lua_State *L) {
    const char *fn = "map.matrix";
    if (!lua_istable(L, 1))
        return pcl_argerror_full(L, fn, 1, 1, "rows", "a table of rows (tables of numbers)");
    int rowvec = checkconv(L, fn, 2, 2);
    int nr = (int)luaL_len(L, 1), nc = 0;
    if (nr < 2 || nr > PC_MAXDIM + 1)
        return pcl_error(L, "%s: argument #1 (rows) holds %d rows; a map of n-D to m-D takes "
                          "(m + 1) rows of n + 1 numbers (\"row\": n + 1 rows of m + 1), n and m "
                          "1..%d", fn, nr, PC_MAXDIM);
    double a[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)];
    for (int i = 1; i <= nr; i++) {
        if (lua_geti(L, 1, i) != LUA_TTABLE)
            return pcl_error(L, "%s: argument #1 (rows) row [%d] must be a table of numbers, got "
                              "%s", fn, i, luaL_typename(L, -1));
        int len = (int)luaL_len(L, -1);
        if (i == 1) {
            nc = len;
            if (nc < 2 || nc > PC_MAXDIM + 1)
                return pcl_error(L, "%s: argument #1 (rows) row [1] holds %d numbers; a "
                                  "homogeneous matrix has 2..%d columns", fn, nc, PC_MAXDIM + 1);
        } else if (len != nc) {
            return pcl_error(L, "%s: argument #1 (rows) row [%d] holds %d numbers, row [1] %d: "
                              "the rows must be of one length", fn, i, len, nc);
        }
        for (int j = 1; j <= nc; j++) {
            lua_geti(L, -1, j);
            int isnum;
            double v = lua_tonumberx(L, -1, &isnum);
            if (!isnum || lua_type(L, -1) != LUA_TNUMBER || !isfinite(v))
                return pcl_error(L, "%s: argument #1 (rows) entry [%d][%d] must be a finite "
                                  "number, got %s", fn, i, j, luaL_tolstring(L, -1, NULL));
            a[(i - 1) * nc + (j - 1)] = v;
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    int nin = rowvec ? nr - 1 : nc - 1, nout = rowvec ? nc - 1 : nr - 1;
    pc_map f;
    int st = pc_map_from_matrix(&f, nin, nout, a, rowvec);
    if (st == PC_ESINGULAR)
        return pcl_error(L, "%s: the zero matrix is no map (it sends every point nowhere)", fn);
    if (st != PC_OK) return pcl_error(L, "%s: %s", fn, pc_strerror(st));
    *newmap(L) = f;
    return 1;
}

static int l_translate(lua_State *L) {
    double v[PC_MAXDIM];
    int n = checkvector(L, "map.translate", 1, "V", 0, 0, v);
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i])) return pcl_argerror_full(L, "map.translate", 1, 1, "V", "a finite vector");
    pc_map_translate(newmap(L), n, v);
    return 1;
}

static int l_scale(lua_State *L) {
    const char *fn = "map.scale";
    double k[PC_MAXDIM], c[PC_MAXDIM];
    int n = 0, has_c = 0;
    if (lua_type(L, 1) == LUA_TNUMBER) {
        double k0 = checknum(L, fn, 1, "k");
        if (lua_type(L, 2) == LUA_TNUMBER) {
            int isint;
            lua_Integer d = lua_tointegerx(L, 2, &isint);
            if (!isint || d < 1 || d > PC_MAXDIM)
                return pcl_argerror_full(L, fn, 2, 2, "n", "a dimension 1..16");
            n = (int)d;
        } else if (pcl_tovalue(L, 2)) {
            n = checkpoint(L, fn, 2, "centre", 0, 0, c);
            has_c = 1;
        } else {
            return pcl_argerror_full(L, fn, 2, 2, "centre",
                                     "a point or a dimension (a single factor k needs one)");
        }
        for (int i = 0; i < n; i++) k[i] = k0;
    } else if (lua_istable(L, 1)) {
        n = (int)luaL_len(L, 1);
        if (n < 1 || n > PC_MAXDIM)
            return pcl_error(L, "%s: argument #1 (k) holds %d factors; one per axis, 1..%d", fn, n,
                              PC_MAXDIM);
        for (int i = 1; i <= n; i++) {
            lua_geti(L, 1, i);
            int isnum;
            double v = lua_tonumberx(L, -1, &isnum);
            if (!isnum || lua_type(L, -1) != LUA_TNUMBER || !isfinite(v))
                return pcl_error(L, "%s: argument #1 (k) item [%d] must be a finite number, got "
                                  "%s", fn, i, luaL_tolstring(L, -1, NULL));
            k[i - 1] = v;
            lua_pop(L, 1);
        }
        if (!lua_isnoneornil(L, 2)) {
            checkpoint(L, fn, 2, "centre", n, 1, c);
            has_c = 1;
        }
    } else {
        return pcl_argerror_full(L, fn, 1, 1, "k", "a number or a list of numbers {kx, ky, ...}");
    }
    pc_map_scale(newmap(L), n, k, has_c ? c : NULL);
    return 1;
}

static int l_rotate(lua_State *L) {
    const char *fn = "map.rotate";
    if (lua_type(L, 1) != LUA_TNUMBER && pcl_tovalue(L, 1)) {       /* about an axis in space */
        double a[3], d[3];
        pcl_value *p = pcl_tovalue(L, 1);
        if (p->n != 3)
            return pcl_error(L, "%s: argument #1 (A) must be 3-D, got %d-D (a rotation in the "
                              "plane is map.rotate(angle [, centre]))", fn, p->n);
        checkpoint(L, fn, 1, "A", 3, 0, a);
        pcl_value *q = pcl_tovalue(L, 2);
        if (!q) return pcl_argerror_full(L, fn, 2, 2, "B", "a point of the axis or its direction");
        const char *what;
        if (pc_kind_of(q->h[q->n]) == PC_KIND_VECTOR) {
            what = "direction";
            checkvector(L, fn, 2, what, 3, 1, d);
        } else {
            what = "B";
            double b[3];
            checkpoint(L, fn, 2, what, 3, 1, b);
            for (int i = 0; i < 3; i++) d[i] = b[i] - a[i];
        }
        double angle = checknum(L, fn, 3, "angle");
        pc_map f;
        int st = pc_map_rotate3(&f, a, d, angle);
        if (st == PC_EZERO)
            return pcl_error(L, "%s: %s", fn, what[0] == 'B' ? "the axis points A and B coincide, "
                              "so they give no axis" : "argument #2 (direction) is the zero "
                              "vector, which gives no axis");
        if (st != PC_OK) return pcl_error(L, "%s: %s", fn, pc_strerror(st));
        *newmap(L) = f;
        return 1;
    }
    double angle = checknum(L, fn, 1, "angle");
    double c[2];
    int has_c = 0;
    if (!lua_isnoneornil(L, 2)) {
        pcl_value *p = pcl_tovalue(L, 2);
        if (p && p->n != 2)
            return pcl_error(L, "%s: argument #2 (centre) must be 2-D, got %d-D (a rotation in "
                              "space is map.rotate(A, B or direction, angle))", fn, p->n);
        checkpoint(L, fn, 2, "centre", 2, 0, c);
        has_c = 1;
    }
    pc_map_rotate2(newmap(L), angle, has_c ? c : NULL);
    return 1;
}

static int l_reflect(lua_State *L) {
    const char *fn = "map.reflect";
    double a[PC_MAXDIM], nrm[PC_MAXDIM];
    int n = checkpoint(L, fn, 1, "A", 0, 0, a);
    checkvector(L, fn, 2, "normal", n, 1, nrm);
    pc_map f;
    int st = pc_map_reflect(&f, n, a, nrm);
    if (st == PC_EZERO)
        return pcl_error(L, "%s: argument #2 (normal) is the zero vector, which gives no mirror",
                          fn);
    if (st != PC_OK) return pcl_error(L, "%s: %s", fn, pc_strerror(st));
    *newmap(L) = f;
    return 1;
}

/* An axis: 1..n or "x", "y", "z", "w"; returns it 0-based. */
static int checkaxis(lua_State *L, const char *fn, int arg, const char *what, int n) {
    if (lua_type(L, arg) == LUA_TSTRING) {
        const char *s = lua_tostring(L, arg);
        const char *at = s[0] && !s[1] ? strchr("xyzw", s[0]) : NULL;
        if (at && at - "xyzw" < n) return (int)(at - "xyzw");
    } else {
        int isint;
        lua_Integer i = lua_tointegerx(L, arg, &isint);
        if (isint && lua_type(L, arg) == LUA_TNUMBER && i >= 1 && i <= n) return (int)i - 1;
    }
    char expected[64];
    snprintf(expected, sizeof expected, "an axis 1..%d (or \"x\", \"y\", ...)", n);
    return pcl_argerror_full(L, fn, arg, arg, what, expected);
}

static int l_shear(lua_State *L) {
    const char *fn = "map.shear";
    int isint;
    lua_Integer n = lua_tointegerx(L, 1, &isint);
    if (!isint || lua_type(L, 1) != LUA_TNUMBER || n < 2 || n > PC_MAXDIM)
        return pcl_argerror_full(L, fn, 1, 1, "n", "a dimension 2..16");
    int i = checkaxis(L, fn, 2, "i", (int)n), j = checkaxis(L, fn, 3, "j", (int)n);
    double k = checknum(L, fn, 4, "k");
    if (i == j)
        return pcl_error(L, "%s: arguments #2 and #3 (i, j) name the same axis; a shear adds "
                          "k times axis j to axis i", fn);
    pc_map_shear(newmap(L), (int)n, i, j, k);
    return 1;
}

static int l_orthographic(lua_State *L) {
    const char *fn = "map.orthographic";
    char axis = 'z';
    if (!lua_isnoneornil(L, 1)) {
        const char *s = lua_type(L, 1) == LUA_TSTRING ? lua_tostring(L, 1) : "";
        axis = (s[0] && !s[1]) ? s[0] : '?';
    }
    if (pc_map_orthographic(newmap(L), axis) != PC_OK)
        return pcl_argerror_full(L, fn, 1, 1, "axis", "\"x\", \"y\" or \"z\" (the axis dropped)");
    return 1;
}

static int l_axonometric(lua_State *L) {
    const char *fn = "map.axonometric";
    double phi = checknum(L, fn, 1, "phi"), theta = checknum(L, fn, 2, "theta");
    pc_map_axonometric(newmap(L), phi, theta);
    return 1;
}

static int l_isometric(lua_State *L) {
    pc_map_isometric(newmap(L));
    return 1;
}

static int l_dimetric(lua_State *L) {
    const char *fn = "map.dimetric";
    double fz = checknum(L, fn, 1, "fz");
    if (pc_map_dimetric(newmap(L), fz) != PC_OK)
        return pcl_argerror_full(L, fn, 1, 1, "fz",
                                 "a number between 0 and 1 (the foreshortening of the z axis)");
    return 1;
}

static int oblique_with(lua_State *L, const char *fn, double k, int alpha_arg) {
    double alpha = optnum(L, fn, alpha_arg, "alpha", atan(1.0));
    pc_map_oblique(newmap(L), k, alpha);
    return 1;
}
static int l_oblique(lua_State *L) {
    return oblique_with(L, "map.oblique", checknum(L, "map.oblique", 1, "k"), 2);
}
static int l_cavalier(lua_State *L) { return oblique_with(L, "map.cavalier", 1.0, 1); }
static int l_cabinet(lua_State *L) { return oblique_with(L, "map.cabinet", 0.5, 1); }

static int l_perspective(lua_State *L) {
    const char *fn = "map.perspective";
    double e[3], p0[3], up[3];
    checkpoint(L, fn, 1, "eye", 3, 0, e);
    checkpoint(L, fn, 2, "p0", 3, 1, p0);
    int has_up = !lua_isnoneornil(L, 3);
    if (has_up) checkvector(L, fn, 3, "up", 3, 1, up);
    pc_map f;
    int st = pc_map_perspective(&f, e, p0, has_up ? up : NULL);
    switch (st) {
    case PC_OK: break;
    case PC_ECOINCIDENT:
        return pcl_error(L, "%s: the eye and p0 coincide, so there is no direction of view", fn);
    case PC_EZERO:
        return pcl_error(L, "%s: argument #3 (up) is the zero vector", fn);
    case PC_ECOLLINEAR:
        return pcl_error(L, "%s: %s is along the line of sight, so it gives no upward direction "
                          "in the picture; give another up", fn,
                          has_up ? "argument #3 (up)" : "the default up, the z axis,");
    default: return pcl_error(L, "%s: %s", fn, pc_strerror(st));
    }
    *newmap(L) = f;
    return 1;
}

/* ---- applying a map ------------------------------------------------------------------------- */

static pc_map *checkself(lua_State *L) {
    pc_map *f = tomap(L, 1);
    if (!f) {
        const char *name = pcl_fname(L);
        pcl_error(L, "%s: must be called on a map, as f:%s(...)", name, name);
    }
    return f;
}

/* The value to map from the arguments first..last (a point or vector, or nin numbers) into
 * in; the first is shown as argument #1.  Returns 1 if they were numbers. */
static int read_input(lua_State *L, const pc_map *f, int first, int last, double *in) {
    int m = last - first + 1, nin = f->nin;
    const char *fn = pcl_fname(L);
    pcl_value *p = m >= 1 ? pcl_tovalue(L, first) : NULL;
    if (p) {
        if (m != 1)
            return pcl_error(L, "%s: takes one point or vector, got %d arguments", fn, m);
        if (p->n != nin)
            return pcl_error(L, "%s: argument #1 is %d-D, but the map takes %d-D: dimensions "
                              "cannot be mixed", fn, p->n, nin);
        memcpy(in, p->h, sizeof(double) * (size_t)(nin + 1));
        return 0;
    }
    if (m != nin || lua_type(L, first) != LUA_TNUMBER)
        return pcl_error(L, "%s: takes a %d-D point or vector, or %d coordinates; got %s", fn,
                          nin, nin, m ? luaL_typename(L, first) : "nothing");
    for (int i = 0; i < nin; i++) {
        int isnum;
        double v = lua_tonumberx(L, first + i, &isnum);
        if (!isnum || lua_type(L, first + i) != LUA_TNUMBER)
            pcl_argerror_full(L, fn, first + i, i + 1, NULL, "a number");
        if (!isfinite(v)) pcl_argerror_full(L, fn, first + i, i + 1, NULL, "a finite number");
        in[i] = v;
    }
    in[nin] = 1.0;
    return 1;
}

static int pole_error(lua_State *L, int shown) {
    return pcl_error(L, "%s: argument #%d is the centre of the projection, which has no image",
                      pcl_fname(L), shown);
}

/* f(p) or f(x, y, ...); the map moves to the top so the arguments count from #1. */
static int l_apply(lua_State *L) {
    pc_map *f = checkself(L);
    if (pcl_tocurve(L, 2) || pcl_tosurface(L, 2)) {   /* f(c) is c:map(f) */
        lua_settop(L, 2);
        lua_getfield(L, 2, "map");
        lua_pushvalue(L, 2);
        lua_pushvalue(L, 1);
        lua_call(L, 2, 1);
        return 1;
    }
    lua_rotate(L, 1, -1);                /* the map stays on the stack (it may be a temporary) */
    double in[PC_MAXDIM + 1];
    read_input(L, f, 1, lua_gettop(L) - 1, in);
    pcl_value *r = pcl_newvalue(L, f->nout);
    if (pc_map_image(f, in, r->h) == PC_EPOLE) return pole_error(L, 1);
    return 1;
}

/* f:xy(p) or f:xy(x, y, ...): the coordinates of the image point as numbers. */
static int l_xy(lua_State *L) {
    pc_map *f = checkself(L);
    double in[PC_MAXDIM + 1], out[PC_MAXDIM + 1];
    if (!read_input(L, f, 2, lua_gettop(L), in) && pc_kind_of(in[f->nin]) != PC_KIND_POINT)
        return pcl_error(L, "%s: argument #1 (X) must be a point (weight 1), got weight %s",
                          pcl_fname(L), numtext(L, in[f->nin]));
    int st = pc_map_image(f, in, out);
    if (st == PC_EPOLE) return pole_error(L, 1);
    if (st == PC_IMPROPER)
        return pcl_error(L, "%s: the image of argument #1 is at infinity (a direction); f(X) "
                          "gives it as a vector", pcl_fname(L));
    int n = f->nout;
    luaL_checkstack(L, n, NULL);
    for (int i = 0; i < n; i++) lua_pushnumber(L, out[i] / out[n]);
    return n;
}

static int compose(lua_State *L, pc_map *f, pc_map *g) {
    pc_map h;
    if (pc_map_compose(f, g, &h) != PC_OK)
        return pcl_error(L, "cannot compose: the first map applied gives %d-D, the second takes "
                          "%d-D", g->nout, f->nin);
    *newmap(L) = h;
    return 1;
}

static int l_mul(lua_State *L) {
    pc_map *f = tomap(L, 1), *g = tomap(L, 2);
    if (!f || !g)
        return pcl_error(L, "cannot multiply %s by a %s: f * g composes two maps, and f(p) "
                          "applies one", kind_of(f ? f : g), luaL_typename(L, f ? 2 : 1));
    return compose(L, f, g);
}

static int l_compose(lua_State *L) {
    pc_map *f = checkself(L);
    pc_map *g = tomap(L, 2);
    if (!g) return pcl_argerror(L, 2, "g", "a map");
    return compose(L, f, g);
}

static int l_inverse(lua_State *L) {
    pc_map *f = checkself(L);
    pc_map inv;
    int st = pc_map_inverse(f, &inv);
    if (st == PC_EDIM)
        return pcl_error(L, "%s: a map from %d-D to %d-D (a projection or an embedding) has no "
                          "inverse", pcl_fname(L), f->nin, f->nout);
    if (st != PC_OK)
        return pcl_error(L, "%s: the map is singular (it flattens space), so it has no inverse",
                          pcl_fname(L));
    *newmap(L) = inv;
    return 1;
}

static int l_matrix(lua_State *L) {
    pc_map *f = checkself(L);
    int rowvec = checkconv(L, pcl_fname(L), 2, 1);
    double a[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)];
    pc_map_to_matrix(f, rowvec, a);
    int nr = rowvec ? f->nin + 1 : f->nout + 1, nc = rowvec ? f->nout + 1 : f->nin + 1;
    lua_createtable(L, nr, 0);
    for (int i = 0; i < nr; i++) {
        lua_createtable(L, nc, 0);
        for (int j = 0; j < nc; j++) {
            lua_pushnumber(L, a[i * nc + j] == 0 ? 0.0 : a[i * nc + j]);   /* no -0 */
            lua_rawseti(L, -2, j + 1);
        }
        lua_rawseti(L, -2, i + 1);
    }
    return 1;
}

static int l_is_affine(lua_State *L) {
    lua_pushboolean(L, pc_map_is_affine(checkself(L)));
    return 1;
}

static int l_vanishing(lua_State *L) {
    pc_map *f = checkself(L);
    if (f->nin != 3 || f->nout < 2 || f->nout > 3)
        return pcl_error(L, "%s: the map goes from %d-D to %d-D; vanishing points are the images "
                          "of the axis directions of a map from 3-D to 2-D or 3-D", pcl_fname(L),
                          f->nin, f->nout);
    for (int i = 0; i < 3; i++) {
        double in[4] = {0, 0, 0, 0}, out[4];
        in[i] = 1;
        if (pc_map_image(f, in, out) != PC_OK || out[f->nout] == 0) {
            lua_pushnil(L);                    /* the direction stays at infinity */
        } else {
            pcl_value *v = pcl_newvalue(L, f->nout);
            memcpy(v->h, out, sizeof(double) * (size_t)(f->nout + 1));
        }
    }
    return 3;
}

static void fmt_num(char *s, size_t size, double x, const char *fmt) {
    if (x == 0) x = 0;                            /* no -0 */
    snprintf(s, size, fmt, x);
}

/* f:show([convention]): print the matrix with its convention, columns aligned. */
static int l_show(lua_State *L) {
    pc_map *f = checkself(L);
    int rowvec = checkconv(L, pcl_fname(L), 2, 1);
    double a[(PC_MAXDIM + 1) * (PC_MAXDIM + 1)];
    pc_map_to_matrix(f, rowvec, a);
    int nr = rowvec ? f->nin + 1 : f->nout + 1, nc = rowvec ? f->nout + 1 : f->nin + 1;
    double big = 0;                               /* rounding noise (cos 90°) prints as 0 */
    for (int i = 0; i < nr * nc; i++) big = fmax(big, fabs(a[i]));
    for (int i = 0; i < nr * nc; i++)
        if (fabs(a[i]) < 1e-14 * big) a[i] = 0;
    int width[PC_MAXDIM + 1] = {0};
    char cell[32];
    for (int i = 0; i < nr; i++)
        for (int j = 0; j < nc; j++) {
            fmt_num(cell, sizeof cell, a[i * nc + j], "%.6g");
            int w = (int)strlen(cell);
            if (w > width[j]) width[j] = w;
        }
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    lua_pushfstring(L, "%s %d-D -> %d-D, %s:", pc_map_is_affine(f) ? "affine map" : "projective map",
                    f->nin, f->nout, rowvec ? "row vectors p' = p T" : "column vectors p' = M p");
    luaL_addvalue(&b);
    for (int i = 0; i < nr; i++) {
        luaL_addstring(&b, "\n ");
        for (int j = 0; j < nc; j++) {
            char padded[64];
            fmt_num(cell, sizeof cell, a[i * nc + j], "%.6g");
            snprintf(padded, sizeof padded, "%s%*s", (j == nc - 1) ? "  | " : "  ", width[j], cell);
            luaL_addstring(&b, padded);
        }
    }
    luaL_pushresult(&b);
    lua_getglobal(L, "print");
    if (lua_isfunction(L, -1)) {
        lua_pushvalue(L, -2);
        lua_call(L, 1, 0);
    } else {
        printf("%s\n", lua_tostring(L, -2));
        fflush(stdout);
    }
    return 0;
}

static int l_tostring(lua_State *L) {
    pc_map *f = tomap(L, 1);
    if (!f) return pcl_error(L, "tostring: not a map");
    int affine = pc_map_is_affine(f), rows = affine ? f->nout : f->nout + 1;
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    lua_pushfstring(L, "%s map %d-D -> %d-D [", affine ? "affine" : "projective", f->nin, f->nout);
    luaL_addvalue(&b);
    for (int i = 0; i < rows; i++) {
        if (i) luaL_addstring(&b, "; ");
        for (int j = 0; j <= f->nin; j++) {
            char s[32];
            if (j) luaL_addstring(&b, j == f->nin ? " | " : " ");
            fmt_num(s, sizeof s, PC_MAP_AT(f, i, j), "%.14g");
            luaL_addstring(&b, s);
        }
    }
    luaL_addchar(&b, ']');
    luaL_pushresult(&b);
    return 1;
}

/* __index: the methods, then f.nin, f.nout and f.C0, f.C1, ... (the images of the origin and
 * of the unit points of the axes: a projection's screen points C0..C3). */
static int l_index(lua_State *L) {
    if (lua_type(L, 2) != LUA_TSTRING) return 0;
    lua_pushvalue(L, 2);
    if (lua_rawget(L, lua_upvalueindex(1)) != LUA_TNIL) return 1;
    pc_map *f = pcl_tomap(L, 1);
    if (!f) return 0;
    const char *k = lua_tostring(L, 2);
    if (!strcmp(k, "nin")) { lua_pushinteger(L, f->nin); return 1; }
    if (!strcmp(k, "nout")) { lua_pushinteger(L, f->nout); return 1; }
    if (k[0] == 'C' && k[1] >= '0' && k[1] <= '9') {
        char *end;
        long i = strtol(k + 1, &end, 10);
        if (*end || i > f->nin || (k[1] == '0' && k[2])) return 0;
        double in[PC_MAXDIM + 1] = {0};
        in[f->nin] = 1;
        if (i > 0) in[i - 1] = 1;
        pcl_value *v = pcl_newvalue(L, f->nout);
        if (pc_map_image(f, in, v->h) == PC_EPOLE) return 0;
        return 1;
    }
    return 0;
}

void pcl_open_map(lua_State *L) {
    int module = lua_gettop(L);
    lua_newtable(L);                                     /* the metatable of maps */
    int mt = lua_gettop(L);
    lua_pushliteral(L, "map");
    lua_setfield(L, mt, "__name");
    lua_pushvalue(L, mt);
    lua_setfield(L, LUA_REGISTRYINDEX, REGKEY);
    static const luaL_Reg meta[] = {
        {"__call", l_apply}, {"__mul", l_mul}, {"__tostring", l_tostring}, {NULL, NULL}
    };
    lua_pushvalue(L, mt);
    luaL_setfuncs(L, meta, 1);
    lua_newtable(L);                                     /* the methods */
    static const luaL_Reg methods[] = {
        {"compose", l_compose}, {"inverse", l_inverse}, {"xy", l_xy}, {"matrix", l_matrix},
        {"is_affine", l_is_affine}, {"vanishing_points", l_vanishing}, {"show", l_show},
        {NULL, NULL}
    };
    lua_pushvalue(L, mt);
    luaL_setfuncs(L, methods, 1);
    lua_pushcclosure(L, l_index, 1);
    lua_setfield(L, mt, "__index");

    lua_newtable(L);                                     /* the affine table */
    static const luaL_Reg actors[] = {{"frame", l_frame}, {"identity", l_identity}, {NULL, NULL}};
    lua_pushvalue(L, mt);
    luaL_setfuncs(L, actors, 1);
    lua_newtable(L);                                     /* its metatable: affine(src, dst) */
    lua_pushvalue(L, mt);
    lua_pushcclosure(L, l_affine, 1);
    lua_setfield(L, -2, "__call");
    lua_setmetatable(L, -2);
    lua_setfield(L, module, "affine");

    lua_newtable(L);                                     /* the map table */
    static const luaL_Reg ctors[] = {
        {"matrix", l_matrix_ctor}, {"translate", l_translate}, {"scale", l_scale},
        {"rotate", l_rotate}, {"reflect", l_reflect}, {"shear", l_shear},
        {"orthographic", l_orthographic}, {"axonometric", l_axonometric},
        {"isometric", l_isometric}, {"dimetric", l_dimetric}, {"oblique", l_oblique},
        {"cavalier", l_cavalier}, {"cabinet", l_cabinet}, {"perspective", l_perspective},
        {NULL, NULL}
    };
    lua_pushvalue(L, mt);
    luaL_setfuncs(L, ctors, 1);
    lua_setfield(L, module, "map");
    lua_settop(L, module);
}
