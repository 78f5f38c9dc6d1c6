-- The help registry: every public name of pointcalc with its area, signature and a one-line
-- description.  It is the single source of the REPL's :help and of docs/api.md
-- (docs/gen_api.lua); tests/lua/test_help.lua checks that every function of the pointcalc
-- module has an entry here and that every entry names something that exists.
--
-- Entries: name (as written in a script: "lerp", "qb.rnd", "A.x", ":show"), area, sig (one
-- form, or a list of forms), desc (one line).
--
-- A function declared in C on the argument layer (stdlib/lua/pcl_args.h, docs/bindings.md)
-- carries its own signature and description: its entry here is def(NAME) alone, placing it in
-- its area, and both texts come from the declaration (pointcalc._decl).  An entry that repeats
-- a declared signature is listed in H.conflicts (tests/lua/test_help.lua fails on it).

local H = {areas = {}, entries = {}, by_name = {}, conflicts = {}}
local pc = package.loaded.pointcalc or rawget(_G, "pointcalc")
H.decls = pc and rawget(pc, "_decl") or {}

local current
local function area(id, title, intro, guide)
  current = {id = id, title = title, intro = intro, guide = guide, entries = {}}
  H.areas[#H.areas + 1] = current
  H.areas[id] = current
end

local function def(name, sig, desc, kind)
  assert(not H.by_name[name], "duplicate help entry " .. name)
  local d = H.decls[name]
  if d and (sig or desc) then
    H.conflicts[#H.conflicts + 1] = name .. ": declared in C, so help.lua must not repeat its signature or description"
  elseif not d and not sig then
    H.conflicts[#H.conflicts + 1] = name .. ": def(NAME) alone, but there is no declaration of it"
  end
  if d then sig, desc = d.sig, d.desc end
  local e = {name = name, area = current.id, sig = sig, desc = desc, kind = kind or "function",
             declared = d ~= nil}
  H.entries[#H.entries + 1] = e
  current.entries[#current.entries + 1] = e
  H.by_name[name] = e
end

-- ---------------------------------------------------------------------------------------
area("points", "Point calculus",
  "Points, vectors and weighted points of any dimension, and the operations of the books. " ..
  "A point has weight 1, a vector weight 0, `k*A` weight k; sums add weights.",
  "points.md")

def("P", "P(x, y [, z, ...]) -> point",
  "A point (weight 1) of any dimension from 1 up: P(1, 2), P(0, 0, 1).")
def("V", "V(x, y [, z, ...]) -> vector",
  "A vector (weight 0), as the difference of two points is: V(0, 1).")
def("lerp", "lerp(A, B, t) -> value",
  "(B - A)t + A, the point of line AB with parameter t (t = 0 gives A, t = 1 gives B); also for vectors and numbers.")
def("bar", "bar(t) -> number",
  "The complement 1 - t (the book's t with a bar), as in A*bar(t) + B*t.")
def("mid", "mid(A, B, ...) -> value",
  "The midpoint of two values, or the centroid of several.")
def("dist", "dist(A, B) | dist(v) -> number",
  "The distance between two points, or the length of a vector.")
def("dot", "dot(u, v) -> number",
  "The scalar product of two vectors.")
def("cross", "cross(u, v) -> vector | number",
  "The cross product: a vector in 3-D, the number u.x v.y - u.y v.x in 2-D.")
def("unit", "unit(v) -> vector",
  "The vector v scaled to length 1; the zero vector is an error.")
def("perp", "perp(v) -> vector",
  "The 2-D vector v turned by +90 degrees: V(-v.y, v.x).")
def("angle", "angle(A, B, C) | angle(u, v) -> number",
  "The angle at A of triangle ABC, or between two vectors: unsigned, in radians, 0..pi.")
def("foot", "foot(C, A, B) -> point",
  "The foot of the perpendicular from C to line AB.")
def("Sigma", "Sigma(A, B [, C]) -> number",
  "The metric operator (B - A).(C - A) of three points; Sigma(A, B) is the squared distance AB^2.")
def("sr", "sr(X, Y, Z) -> number",
  "The simple ratio (XYZ) = (X - Z)/(Z - Y) in which Z divides XY; math.huge when Z = Y, -1 for the point at infinity.")
def("divide", "divide(X, Y, lambda) -> point",
  "The point Z with (XYZ) = lambda: (X + lambda Y)/(1 + lambda); lambda = -1 gives the point at infinity of XY.")
def("harmonic", "harmonic(A, B, T) -> point",
  "The harmonic conjugate N of T with respect to A, B: (ABN) = -(ABT); the midpoint gives the point at infinity.")
def("cross_ratio", "cross_ratio(A, B, C, D) -> number",
  "The cross ratio (ABCD) = (ABC)/(ABD) of four collinear points (C, D may be points at infinity).")
def("meet", "meet(A1, A2, B1, B2) -> K, lambda, mu",
  "The intersection K = A1 + (A2 - A1)lambda = B1 + (B2 - B1)mu of two lines, any dimension; an end may be a point at infinity (a vector: the line's direction); parallel lines give their direction (weight 0), skew ones nil and their distance. With point equations among the ends (param \"u\") K, lambda and mu are equations with exact derivatives, so a scheme of meets compiles with curve().")
def("area", "area(A, B, C) | area(A, B, C, D, ...) -> number",
  "The area of a triangle (signed in 2-D, counter-clockwise positive) or of a 2-D polygon.")
def("volume", "volume(A, B, C, D) -> number",
  "The volume of a tetrahedron: signed in 3-D (positive when right-handed), unsigned in 4-D and up.")
def("normalize", "normalize(p) -> point",
  "Divide a weighted value by its weight (projective normalisation); weight 0 is an error.")
def("weight", "weight(p) -> number",
  "The weight of a value: 1 for a point, 0 for a vector, k for k*A.")
def("coords", "coords(p) -> x, y, ...",
  "The coordinates of a point or the components of a vector, as numbers.")
def("near", "near(a, b [, eps]) -> boolean",
  "Numbers, or values of one dimension, equal within eps (default 1e-9) relative to their size.")

-- ---------------------------------------------------------------------------------------
area("values", "Point values",
  "What a point, vector or weighted value offers: fields, indexing, operators, methods.",
  "points.md")

def("p.x", "p.x, p.y, p.z -> number",
  "The coordinates of a point (components of a vector); a weight other than 0 and 1 is an error.", "field")
def("p.w", "p.w -> number",
  "The weight: 1 for a point, 0 for a vector.", "field")
def("p[i]", "p[i] -> number",
  "Coordinate i (1-based) of a value of any dimension.", "field")
def("#p", "#p -> integer",
  "The dimension of the value.", "operator")
def("p+q", "p + q, p - q, k*p, p*k, p/k, -p",
  "Arithmetic on values: weights add and scale, so A - B is a vector and A*t + B*(1 - t) a point.", "operator")
def("p==q", "p == q",
  "Equal values: same dimension, weight and coordinates.", "operator")
def("p:method", {"p:lerp(B, t)  p:mid(B)  p:dist(B)  p:dot(v)  p:cross(v)  p:unit()",
                 "p:perp()  p:angle(...)  p:normalize()  p:weight()  p:coords()  p:near(q)"},
  "The one-receiver functions as methods: p:dist(B) is dist(p, B).", "method")

-- Fields and methods that a value's __index computes (so Tab cannot find them in a table), by
-- the metatable's __name.
H.fields_of = {
  point = {"x", "y", "z", "w"},
  complex = {"re", "im", "conj", "abs", "arg", "exp", "point"},
  mobius = {"z0", "phi", "inverse"},
  map = {"nin", "nout", "C0", "C1", "C2", "C3"},
  curve = {"kind", "dim", "degree", "t0", "t1", "lo", "hi", "closed", "pieces", "n"},
  surface = {"kind", "dim", "u0", "u1", "v0", "v1"},
  oresme = {"lambda", "m", "n"},
  halfspline = {"n", "m", "t0", "c1", "c2", "v", "deriv"},
  equation = {"dim", "params"},
}

-- ---------------------------------------------------------------------------------------
area("frames", "Simplices and affine maps",
  "Frames of reference: a simplex gives natural parameters, an affine map changes the frame.",
  "points.md")

def("simplex")
def("S(p, q)", nil, nil, "method")
def("S:bary", nil, nil, "method")
def("S:params", nil, nil, "method")
def("S:measure", nil, nil, "method")
def("S:ratio", nil, nil, "method")
def("affine")
def("affine.frame")
def("affine.identity")

-- ---------------------------------------------------------------------------------------
area("transforms", "Maps: transformations and projections (map.*)",
  "One map type for affine and projective maps of any dimension: the textbook's " ..
  "transformations, the 3-D -> 2-D projections, affine(...) and the toolkit's projection(...) " ..
  "all make it, and any two of fitting dimensions compose. Angles are in radians.",
  "maps.md")

def("map.matrix")
def("map.translate")
def("map.scale")
def("map.rotate")
def("map.reflect")
def("map.shear")
def("map.orthographic")
def("map.axonometric")
def("map.isometric")
def("map.dimetric")
def("map.oblique")
def("map.cavalier")
def("map.cabinet")
def("map.perspective")
def("map.view")
def("map.perspective_pqr")
def("map.foreshortening")
def("map.axial_affinity")
def("f(p)", nil, nil, "method")
def("f:xy", nil, nil, "method")
def("f:compose", nil, nil, "method")
def("f:inverse", nil, nil, "method")
def("f:matrix", nil, nil, "method")
def("f:is_affine", nil, nil, "method")
def("f:vanishing_points", nil, nil, "method")
def("f:show", nil, nil, "method")
def("f.nin", "f.nin, f.nout -> integer",
  "The dimensions of the points the map takes and gives.", "field")
def("f.C0", "f.C0, f.C1, ... -> point",
  "The images of the origin and of the unit points of the axes (a projection's screen points).", "field")

-- ---------------------------------------------------------------------------------------
area("smooth", "Smoothsteps (smooth.*)",
  "Functions g on [0, 1] with g(0) = 0, g(1) = 1 and zero slope at both ends, which join two " ..
  "curves smoothly; the curve builders take them as their g.",
  "toolkit.md")

def("smooth.sine", "smooth.sine(t) -> number",
  "(1 - cos(pi t))/2, the smoothstep of examples 3 and 4.")
def("smooth.cubic", "smooth.cubic(t) -> number",
  "3t^2 - 2t^3, the smoothstep of examples 5, 6 and 9.")
def("smooth.power", "smooth.power(n [, t]) -> number | g",
  "The symmetric power half-spline of degree n (example 7): 2^(n-1) t^n below 1/2, mirrored above; without t the half-spline g.")
def("smooth.half", "smooth.half(n, m, t0 [, t]) -> number | g",
  "The asymmetric half-spline of example 8: c1 t^n before t0, 1 - c2 (1 - t)^m after, slope continuous; without t the object g (g(t), g:deriv(t), g.c1, g.c2, g.v).")
def("smooth.locus", "smooth.locus(n, m, t0) -> number",
  "The junction ordinate v(t0) = m t0/(n - n t0 + m t0) of the half-spline (n, m, t0): the locus of example 8.")
def("smooth.clamp", "smooth.clamp(t) -> number",
  "The clamped smoothstep of examples 20-22: 0 before 0, 2t^2 to 1/2, 1 - 2(1 - t)^2 to 1, then 1.")
def("smooth.clamp_qb", "smooth.clamp_qb(t [, prev]) -> number",
  "smooth.clamp as the listings' strict IF chain computes it: at t exactly 0, 1/2 or 1 it keeps prev.")

-- ---------------------------------------------------------------------------------------
area("curves", "Curves",
  "One curve type for every construction: Bezier (rational through weighted points), B-spline " ..
  "and NURBS, Hermite pieces, splines and interpolation through nodes, Stepanov's strokes and " ..
  "Fourier curves, a Lua function. A curve c gives points c(t), derivatives, length, curvature, " ..
  "and draws itself as one path with c:draw().",
  "curves.md")

def("bezier", "bezier{P0, P1, ..., Pn} -> curve",
  "The Bezier curve of degree n over [0, 1]; weighted points w*P make it rational (a conic), vectors are control points at infinity.")
def("bspline", "bspline(points, degree [, \"open\"|\"uniform\"|\"periodic\"|knots]) -> curve",
  "The B-spline (NURBS with weighted points) of that degree; open knots by default, or a non-decreasing list of points + degree + 1 knots.")
def("hermite", "hermite(points, tangents [, {tin = {...}, u = {...}, closed = false}]) -> curve",
  "Piecewise cubic Hermite through the points with these derivatives (tin: the arriving ones, for corners); u: the parameters of the nodes.")
def("cubic_spline", "cubic_spline(points [, {ends = \"natural\"|\"clamped\"|\"periodic\", d0 = V, d1 = V, u = {...}}]) -> curve",
  "The C2 cubic spline through the points (parameters: accumulated chord lengths unless u is given).")
def("interpolate", "interpolate(points [, params]) -> curve",
  "The polynomial curve of degree n - 1 through n points at the given parameters (default evenly spaced in [0, 1]).")
def("curve", "curve(f, t0, t1) -> curve",
  "A Lua function t -> point (or numbers) over [t0, t1] as a curve: it flattens, measures and draws like any other.")
def("spline2", "spline2(A, a, B, b [, g]) -> curve",
  "The curve from A with direction a to B with direction b, blended by the smoothstep g (default smooth.cubic): Stepanov's example 5.")
def("stroke", "stroke{nodes = {P, ...}, uin = ..., kink = ... | ein = {V, ...}, rin =, rout =, n =, m =, t0 =, g =, closed = false} -> curve",
  "The one-stroke curve through the nodes, one quadrilateral-spline piece per pair (examples 10, 11, 13); its t runs over 0..pieces.")
def("fourier", "fourier({P1, P2, ..., P2n}) -> curve",
  "The closed curve through 2n points by a finite Fourier series (example 12), t in [0, 2 pi].")
def("sphdir", "sphdir(u1, u2) -> vector",
  "The unit vector of longitude u1 and latitude u2 (example 33).")
def("plot", {"plot(f, {t = {a, b [, step]}, color = c, map = m, tol = px})",
             "plot(f, {t = {a, b, step}, brush = \"pset\"|\"dot\"|fn | dots = true | qb = true, ...})"},
  "Draw t -> f(t) as one connected path (3-D through map or the camera); with a brush, dots = true or qb = true, dots at those steps as the listings do.")
def("c(t)", "c(t) -> point | c:xy(t) -> x, y",
  "The point of a curve at parameter t (a vector where a rational curve is at infinity). With t a scalar equation (param \"t\", t^2, ...) a single-piece Bezier curve gives the composed point equation: conic.ed(A, B, C, k)(t) is (2.97).", "method")
def("c:deriv", "c:deriv(t [, order] [, \"left\"|\"right\"]) -> vector",
  "The derivative of any order (default 1) at t, exact for Bezier and B-spline curves (rational ones by Leibniz's rule; up to order 2 for function curves). At a joint the default is the piece that starts there (the right-hand side, the left at the end of the domain); \"left\" takes the piece that ends there.", "method")
def("c:tangent", "c:tangent(t) -> vector | c:normal(t) -> vector",
  "The unit tangent; the unit principal normal (in the plane: the tangent turned by +90 degrees).", "method")
def("c:curvature", "c:curvature(t) -> number",
  "The curvature: signed in the plane (positive turning counter-clockwise), unsigned in space.", "method")
def("c:split", "c:split(t) -> left, right | c:sub(a, b) -> curve",
  "The two parts at t (de Casteljau, knot insertion), or the part over [a, b], of the same kind.", "method")
def("c:insert_knot", "c:insert_knot(u) -> curve",
  "The same B-spline with the knot u inserted (one more control point).", "method")
def("c:length", "c:length([a, b]) -> number",
  "The arc length over the domain or [a, b] (adaptive Gauss-Legendre).", "method")
def("c:bbox", "c:bbox() -> lo, hi",
  "The corners of the axis-aligned bounding box.", "method")
def("c:controls", {"c:controls() -> {values}", "c:controls(i) -> A, P, Q, B"},
  "The control values (weighted as given); for a stroke, the quadrilateral of piece i.", "method")
def("c:knots", "c:knots() -> {numbers}",
  "The knot vector of a B-spline, or the breakpoints of pieces.", "method")
def("c:map", "c:map(f) -> curve | f(c)",
  "The image under a map: control points mapped exactly, so a projective map keeps a rational curve rational.", "method")
def("c:flatten", "c:flatten([tol [, map]]) -> {polylines}",
  "Adaptive polylines within tol of the curve (projected by map to the plane), broken where the curve passes through infinity.", "method")
def("c:each", "c:each{t = {a, b, step}, qb = false} -> iterator of point, piece, t",
  "Walk a curve: for M, i, t in c:each{t = {0, 1, .01}} do ... end.", "method")
def("c:draw", {"c:draw{color = c, tol = px, map = m}", "c:draw{t = {a, b, step}, brush = \"pset\"|\"dot\"|fn, qb = false, ...}"},
  "Draw the curve as one path, flattened to within tol pixels (default 1/4) through map or the camera; with t or a brush, dots as the listings draw them.", "method")
def("c:piece", "c:piece(i, t) -> point | c:piece_xy(i, t) -> x, y",
  "A stroke's piece i at its own parameter t.", "method")
def("c:coef", "c:coef(k) -> a, b",
  "The Fourier coefficient lists of coordinate k of a fourier curve.", "method")
def("c:monomial", "c:monomial([piece]) -> {{a0, a1, ...}, {b0, b1, ...}, ... [, w = {...}]}",
  "The power-basis coefficients of a Bezier or B-spline piece (default 1) in the curve's own parameter: x(t) = a0 + a1 t + ..., one list per coordinate (ch. 4-5 print their results so); w the weight polynomial of a rational curve (the coordinates' lists are then its numerators).", "method")
def("c:conic", nil, nil, "method")

-- ---------------------------------------------------------------------------------------
area("equations", "Point equations",
  "The book's point equations as compiled objects: arithmetic on a parameter builds an " ..
  "equation (common parts shared), which curve() and surface() compile to C with exact " ..
  "derivatives; the membership condition is checked when one is made.",
  "equations.md")

def("param", "param(name) -> equation",
  "A symbolic parameter: local t = param \"t\"; then A*bar(t)^2 + 2*B*t*bar(t) + C*t^2 (with + - * / ^, lerp bar dot cross unit P V, math.sin ... and the smoothsteps) is an equation, not a value.")
def("M(t)", {"M(t [, s ...]) -> value", "M{t = ..., s = ...} -> value"},
  "The equation's value at parameter values given in the order of M.params, or by name.", "method")
def("M:with", "M:with{s = value | equation, ...} -> equation",
  "The one-parameter family M(t; s) at a value of s (or with s replaced by another equation).", "method")
def("M:show", "M:show{A = A, B = B, ...} -> string",
  "The equation in the book's notation with the points named (tostring(M) prints them as P(x, y)).", "method")
def("M:sample", "M:sample(a, b [, n = 1001 [, s]]) -> samples",
  "n values at evenly spaced t in [a, b], computed in C (into s when given): #s, s[i] (a point), s:sum().", "method")
def("curve(M)", {"curve(M, t0, t1) -> curve", "surface(M, u0, u1, v0, v1) -> surface"},
  "A one-parameter equation as a curve, a two-parameter one (u the first made) as a surface: exact tangents, normals, curvature.", "method")

-- ---------------------------------------------------------------------------------------
area("surfaces", "Surfaces (surface.*)",
  "One surface type in (u, v): tensor-product Bezier and B-spline patches, bilinear, bicubic " ..
  "Hermite, ruled, Coons, surfaces of revolution and Lua functions; s(u, v) is a point, " ..
  "s:iso gives curves, s:wireframe draws the iso-lines through the camera.",
  "curves.md")

def("surface")
def("surface.bilinear")
def("surface.bezier")
def("surface.bspline")
def("surface.hermite")
def("surface.ruled")
def("surface.coons")
def("surface.revolution")
def("s(u, v)", nil, nil, "method")
def("s:eval", nil, nil, "method")
def("s:partials", nil, nil, "method")
def("s:normal", nil, nil, "method")
def("s:iso", nil, nil, "method")
def("s:map", nil, nil, "method")
def("s:wireframe", nil, nil, "method")
def("s:shade", nil, nil, "method")

-- ---------------------------------------------------------------------------------------
area("curvilinear", "Curvilinear coordinates",
  "A system C maps (t1, t2) to points, draws its own grid, and carries any curve given in " ..
  "(t1, t2) through it \"as a lens\" (Stepanov's method).",
  "toolkit.md")

def("curvilinear", "curvilinear(f) -> C",
  "The system of a function f(t1, t2) returning a point or x, y.")
def("bilinear", "bilinear(P0, P1, P2, P3) -> C",
  "The bilinear system of a quadrilateral: P0 + t1(P1 - P0) + t2(P3 - P0) + t1 t2(P2 - P3 - P1 + P0) (example 2).")
def("ruled", "ruled(A, B) -> C",
  "The ruled system between two curves: C(t1, t2) = A(t1) + t2(B(t1) - A(t1)).")
def("graphs", "graphs(f, g) -> C",
  "The system between the graphs y = f(x) and y = g(x): C(x, t) = (x, f(x) + t(g(x) - f(x))) (example 19).")
def("patch", "patch(S0, S1, S2, S3) -> C",
  "The system inside a curvilinear quadrilateral with sides S0..S3 (curves over [0, 1], end to end): example 25.")
def("graph_on", "graph_on(A, B, f [, a, b]) -> function",
  "The graph of f over [a, b] erected on the segment AB, as a curve t -> point for t in [0, 1] (example 23).")
def("screenmap", "screenmap(x0, y0, a [, b]) -> function",
  "(x, y) -> (x0 + a x, y0 - b y): mathematical coordinates (y up) onto the screen, as the listings' xe, ye.")
def("C(t1, t2)", "C(t1, t2) -> point | C:xy(t1, t2) -> x, y",
  "The point of a system with coordinates t1, t2.", "method")
def("C:grid", "C:grid{t1 = {a, b, step [, fine]}, t2 = {...}, family = \"t1\"|\"t2\", brush =, color =, map =}",
  "Draw the coordinate lines t1 = const and t2 = const of a system.", "method")
def("C:draw", "C:draw(curve, opts)",
  "Draw a curve given in (t1, t2) through the system, as through a lens.", "method")
def("C:pre", "C:pre(g) -> C",
  "The system (t1, t2) -> C(g(t1, t2)): a reparametrisation, such as squash01.", "method")
def("C:post", "C:post(h) -> C",
  "The system (t1, t2) -> h(C(t1, t2)), such as screenmap(320, 240, 100).", "method")
def("C:clamp", "C:clamp{t1 = true, t2 = true, qb = false} -> C",
  "The system with smooth.clamp applied to the chosen parameters (examples 20-22).", "method")

-- ---------------------------------------------------------------------------------------
area("maps", "Maps, projections and numerics",
  "The plane onto a square, oblique projections, complex numbers and the Moebius map, " ..
  "Oresme's function and bisection.",
  "toolkit.md")

def("squash", "squash(p [, q]) -> numbers",
  "The plane onto the open square: p/sqrt(p^2 + 1) in (-1, 1), for each argument (examples 26-28).")
def("squash01", "squash01(p [, q]) -> numbers",
  "The plane onto the open unit square: .5 p/sqrt(p^2 + 1) + .5 in (0, 1), for each argument.")
def("oblique", "oblique(C0, r, k, u) -> map",
  "The oblique projection of examples 32-34 (a 3-D -> 2-D map): the x and y axes of length r at angles u and u + 90 degrees on an ellipse squeezed by k, the z axis straight up.")
def("projection", "projection(C0, C1, C2, C3) -> map",
  "The projection (x, y, z) -> C0 + x(C1 - C0) + y(C2 - C0) + z(C3 - C0) by four screen points, a 3-D -> 2-D map; pr(P), pr:xy(x, y, z), pr.C0.")
def("complex", "complex(re [, im]) | complex(P) -> z",
  "A complex number (from a 2-D point, x + iy); + - * / ^ mix with numbers; z.re, z.im, z:conj(), z:abs(), z:arg(), z:exp(), z:point().")
def("complex.i", "complex.i", "The imaginary unit.", "value")
def("complex.polar", "complex.polar(r, u) -> z",
  "The complex number r e^(iu).")
def("complex.exp", "complex.exp(z) -> z", "The complex exponential.")
def("complex.abs", "complex.abs(z) -> number", "The modulus |z|.")
def("complex.arg", "complex.arg(z) -> number", "The argument of z: atan2(im, re), in radians.")
def("complex.conj", "complex.conj(z) -> z", "The complex conjugate.")
def("mobius", "mobius(z0 [, phi]) -> M",
  "The Moebius automorphism w = e^(i phi)(z - z0)/(1 - conj(z0) z) of the unit disc (examples 15, 16): M(z), M(x, y), M(P), M:inverse().")
def("oresme", "oresme(lambda [, m [, y0, y1]]) -> o",
  "Oresme's lambda-function on 2^m cells (m = 12 by default) from y0 to y1 (example 31): o(t), o[j], #o.")
def("bisect", "bisect(f, a, b [, tol]) -> x, iterations",
  "A root of f in [a, b] by bisection, as example 30 does it (tol 1e-10 by default).")

-- ---------------------------------------------------------------------------------------
area("draw", "Drawing (QBasic SCREEN 12)",
  "A 640x480 16-colour canvas, y down, as QBasic's SCREEN 12. Every pair of coordinates " ..
  "may be given as one 2-D point: pset(M), line(A, B).",
  "drawing.md")

def("screen")
def("cls")
def("color")
def("palette")
def("pset")
def("preset")
def("line")
def("line_to")
def("circle")
def("paint")
def("point")
def("window")
def("view")
def("last_point")
def("size")
def("pen")
def("path")
def("fill")
def("label")
def("figure")
def("text")
def("slider", "slider(name, min, max, default [, step | {step =, animate = true}]) -> value",
  "A parameter of the script: its default, or the value given by --set name=value, a live page's slider (pointcalc serve) or an animation frame (--frames).")
def("camera", {"camera(f [, {hidden = \"dashed\"|\"hide\"|\"show\"}])", "camera(nil)", "camera() -> f"},
  "The current projection (a map to 2-D): with one set, drawing calls take its points (3-D) and draw their images; with hidden, 3-D lines, curves, marks and wireframes form a scene whose hidden parts are resolved when the picture is written, whatever the drawing order.")
def("save")

-- ---------------------------------------------------------------------------------------
area("figures", "Figures: label placement, markers, arrows, dimensions",
  "Furniture of engineering drawings, drawn through the ordinary display list (every writer " ..
  "shows it): sizes in screen pixels, numbers measured in world units. Labels without a " ..
  "direction are placed when the picture is written.",
  "figures.md")

def("fit")
def("caption")
def("axes")
def("graph")
def("legend")
def("placed_labels")
def("mark")
def("arrow")
def("vector")
def("dimension")
def("angle_mark")
def("ticks")
def("hatch")
def("centre_line")

-- ---------------------------------------------------------------------------------------
area("qbscreen", "QBasic's screen: modes, text cells, blocks, DRAW, pages",
  "What QBasic programs do on a graphics screen besides drawing: the other screen modes " ..
  "(screen(1), (2), (7), (9) with their sizes, palettes and pages), PRINT's character cells, " ..
  "GET/PUT, DRAW, PCOPY and PMAP. Translated QBasic programs use them; scripts may too.",
  "qbasic.md")

def("mode_info")
def("print_at")
def("scroll_text")
def("get_block")
def("put_block")
def("draw")
def("pages")
def("pcopy")
def("pmap")
def("paint_tile")

-- ---------------------------------------------------------------------------------------
area("qb", "QBasic numbers (qb.*)",
  "QBasic's number semantics, used by translated QBasic programs and available to scripts.",
  nil)

def("qb.f32", "qb.f32(x) -> number",
  "x rounded to QBasic's SINGLE (IEEE float32); beyond the SINGLE range (about 3.4E+38) it is +-inf, as a float32 is (translated QBasic reports Overflow).")
def("qb.cint", "qb.cint(x) -> integer, ok",
  "CINT: round to the nearest integer, ties to even; ok is false on INTEGER overflow.")
def("qb.clng", "qb.clng(x) -> integer, ok",
  "CLNG: round to the nearest integer, ties to even; ok is false on LONG overflow.")
def("qb.rnd", "qb.rnd([n]) -> number",
  "QBasic's RND(n): the next number of QBasic's own generator (n = 0 repeats, n < 0 reseeds).")
def("qb.randomize", "qb.randomize(n)",
  "QBasic's RANDOMIZE n: reseed the generator.")
def("qb.seed", "qb.seed([s]) -> seed",
  "The generator's 24-bit seed; sets it when s is given.")
def("qb.range", "qb.range(a, b [, step]) -> iterator",
  "A QBasic FOR loop accumulating in SINGLE: for t in qb.range(0, 1, .001) runs 1001 times, as QBasic does.")

-- ---------------------------------------------------------------------------------------
area("buimov", "The textbook: plane curves (plane.*) and the book's constructions (buimov.*)",
  "Buimov's textbook (after Rogers & Adams) where it builds things its own way: circles and " ..
  "conics of ch. 3 with the book's point generators, B-splines with its knot algorithm, Hermite " ..
  "segments and splines of ch. 4, the sphere of ch. 5, a point from two views and a camera from " ..
  "six points (§2.8.6). Curves and surfaces are the one curve and surface types; misprints " ..
  "are corrected (docs/buimov.md lists them).",
  "buimov.md")

def("plane.circle3")
def("plane.circle2r")
def("plane.circle_slopes")
def("plane.arc3")
def("plane.classify")
def("plane.rotate_conic")
def("plane.conic_value")
def("plane.conic_coef")
def("plane.ellipse")
def("plane.parabola")
def("plane.hyperbola")
def("plane.points")

def("buimov.knots")
def("buimov.basis")
def("buimov.bspline")
def("buimov.bernstein")
def("buimov.blend")
def("buimov.hermite")
def("buimov.hermite_coeffs")
def("buimov.spline")
def("buimov.helix")
def("buimov.sphere")
def("buimov.sphere_frame")
def("buimov.det")
def("buimov.reconstruct")
def("buimov.calibrate")
def("plane.conic_slope")
def("buimov.g1_next")
def("buimov.joint")

-- ---------------------------------------------------------------------------------------
area("konopatsky", "The monograph's curves (conic.*, oneratio.*, interp.*, approx.*)",
  "Konopatsky's point-calculus curves: the conics of chapter 2 in all the book's " ..
  "parametrisations, curves of one ratio (ch. 3), interpolation (ch. 4) and approximation with " ..
  "optimal nodes (ch. 5). Every curve is the one curve type; conic arcs are rational quadratics " ..
  "and pass through their points at infinity. Misprints of the book are implemented corrected.",
  "konopatsky.md")

def("conic.ed", "conic.ed(A, B, C, k) -> curve",
  "(2.97) The engineering-discriminant arc A -> B with tangents CA, CB through K = kT1 + (1 - k)C on the median: k < 1/2 hyperbola, 1/2 parabola, > 1/2 ellipse.")
def("conic.ed_k", "conic.ed_k(A, B, C, K) -> k",
  "The discriminant k = CK/CT1 of the arc (2.97) through K on the median from C.")
def("conic.circle_k", "conic.circle_k(A, B, C) -> k",
  "(2.107) k of the circular arc AB whose tangents meet at C (|CA| = |CB|): 1/2 + 2h^2/c^2.")
def("conic.ceva", "conic.ceva(A1, A2, A3, k) -> curve",
  "(2.104) Ceva's parametrisation: A2 (t = 0) to A1 (t = 1), tangents through A3; k = 1/4 parabola, < 1/4 hyperbola.")
def("conic.ceva_k", "conic.ceva_k(A1, A2, A3, K) -> k",
  "(2.100) k = v31/v23 of the conic of the pencil through the point K.")
def("konopatsky.area_k")
def("konopatsky.area_theorem")
def("konopatsky.o_theorem")
def("konopatsky.simplex_ratio")
def("konopatsky.meet_line_plane")
def("konopatsky.polar")
def("konopatsky.rotate")
def("konopatsky.moving_simplex")
def("conic.ed_scheme")
def("conic.five_scheme")
def("conic.ceva_to_ed")
def("conic.ed_to_ceva")
def("conic.cones_excluded")
def("conic.foci")
def("conic.ceva_scheme")
def("conic.focal_point")
def("conic.scheme")
def("conic.elements")
def("conic.parabola", {"conic.parabola(A1, A3, A2) -> curve", "conic.parabola(A, C, B, tC) -> curve"},
  "(2.58) The parabola of one ratio with tangents meeting at A3; or (2.62) the parabola through A, C (at t = tC), B.")
def("conic.ellipse", "conic.ellipse{C =, A =, B = [, by = \"angle\"|\"radius\"|\"focal\"|\"compression\"|\"algebraic\"|\"conjugate\", quadrant =, range = {t0, t1}]} -> curve",
  "The ellipse of centre C with semi-axes CA, CB in the book's forms (2.11), (2.15), (2.18), (2.24), sqrt, (2.32); by = \"diameter\" with K, A, B, lambda: §2.1.1.6.")
def("conic.hyperbola", "conic.hyperbola{C =, A =, B = [, by = \"angle\"|\"radius\"|\"focal\", branch = 1|2, range =]} -> curve",
  "The hyperbola of centre C, vertex A, imaginary semi-axis CB: (2.49), (2.53) with rho >= a, (2.56) with the branch through A by default (corrected ranges).")
def("conic.circle", "conic.circle{A =, B =, C = [, delta = | R =]} -> curve",
  "Circles: the arc AB with tangents through C (§2.1.8.1); delta: the locus angle AMC = delta (2.115); R: centre C, radius R (2.118).")
def("conic.tilted", "conic.tilted(A, B, C, theta, m, n) -> curve, P, Q",
  "§2.1.1.1 The ellipse of centre C, semi-axes m, n, its major axis at angle theta to AB; P, Q end the semi-axes.")
def("conic.five_points", "conic.five_points(A, B, C, D, E [, {u0 =, u1 =, whole = true}]) -> curve, u",
  "§2.1.4 The conic through five points by Pascal's hexagon with the corrected S = BE x AD; u.A ... u.E are the parameters of the points.")
def("conic.five_points2", "conic.five_points2{C =, A =, B =, p1 =, p2 =, q2 =, q3 =} -> curve",
  "§2.1.5 The conic A -> B through A1, A2, A3 given by their ratios in simplex CAB (corrected 2.93); p1 = q3 = 1 gives tangents CA, CB.")
def("conic.triples", "conic.triples(A1, A2, A3, A4, A5 [, t0, t1]) -> curve",
  "§2.2 (b) The system of triples without a Pascal line; corrected, its locus is the conic through A1, A3, A4.")
def("conic.redundant", {"conic.redundant(C, A, B, u, v) -> point", "conic.redundant(C, A, B) -> curve"},
  "(2.120) The redundant parametrisation of the plane K = AQ x BP; without u, v the curve (2.121) u = v = t.")
def("conic.reparam", "conic.reparam{C =, A =, B = [, by = \"angle\"|\"sigma\", branch = 1|2]} -> curve",
  "§2.4 The one-ratio parabola by the angle MCA, or by sigma = CK + KM (the print's radius |CM| is not what its formula measures).")
def("conic.sinusoid", "conic.sinusoid{C =, A =, B =, k = {m, n, ...}} -> curve",
  "(2.145) The sinusoid whose axis is the circle of centre C through A, one wave number per generation.")
def("conic.cycloid", "conic.cycloid{C =, A =, B = [, concave = true, range =]} -> curve",
  "§2.8 The convex (or concave) cycloid arc from B to A in the simplex CAB; range {0, 2pi} gives the whole arch.")
def("conic.cones", "conic.cones(A, B, C, D, fP, fQ, n) -> curve",
  "§2.6 The space cubic DP x NQ of two quadric cones over the arcs (2.97) fP, fQ in ABC, N = (D - A)n + A.")
def("conic.contour", "conic.contour(A1, A2, A3, u, v [, du, dv]) -> curve",
  "(2.161) The general contour arc A1 -> A2 with tangents through A3, driven by the functions u(t), v(t).")

def("oneratio", "oneratio(A, B, C) -> curve",
  "The same as oneratio.simplex.")
def("oneratio.simplex", "oneratio.simplex(A, B, C) -> curve",
  "(3.1) The moving-simplex curve A t'^2 + B t + C t t' (corrected): tangent BC at B.")
def("oneratio.tetra", "oneratio.tetra(A, B, C, D) -> curve",
  "(3.2) The arc of one ratio in the simplex DABC; planar, through the centroid at t = 1/2.")
def("oneratio.bezier3", "oneratio.bezier3(A, C1, C2, B) -> curve",
  "(3.4) The cubic Bezier curve of the de Casteljau scheme (corrected powers).")
def("oneratio.smooth", "oneratio.smooth(A, B, C [, n]) -> curve",
  "§3.6 The contour arc of smoothness order n (2 by default): zero curvature at the ends for n >= 2.")
def("oneratio.smooth_scheme")
def("oneratio.desargues", "oneratio.desargues(A, B, C, D) -> curve",
  "(3.6) The Desargues arc A -> D with tangents AC and BD, through the centroid.")
def("oneratio.double_contact", "oneratio.double_contact(A, B, C, kp, kq [, f]) -> curve",
  "§3.4 M = P(1 - f(v)) + Q f(v) of the arcs (2.97) kp and kq; f a function of v or a number (default v).")
def("oneratio.closed", "oneratio.closed(A, B, C, kP, kQ [, scheme]) -> curve",
  "§3.5 The closed curve P u' + Q u through B, scheme 1 or 2 (corrected Q): wing profiles.")
def("oneratio.simplex_scheme", "oneratio.simplex_scheme(A, B, C, t) -> {N =, M =}",
  "Fig. 3.1 The moving simplex at t: N = A t' + C t on AC and M = N t' + B t on NB (the point of (3.1)).")
def("oneratio.levels", "oneratio.levels(points, t) -> {{P1, ...}, {Q1, ...}, ..., {M}}",
  "Fig. 3.4 The de Casteljau levels at the one ratio t (for A, C1, C2, B: P1 P2 P3, Q1 Q2, M of (3.4)).")
def("oneratio.desargues_scheme", "oneratio.desargues_scheme(A, B, C, D, t) -> {T =, S =, R =, N =, J =, Q =, M =, pJ =, qJ =}",
  "Fig. 3.12 The points of the Desargues arc's scheme at t; T, S, R are directions (vectors) at t = 1/2.")

def("interp.lagrange", "interp.lagrange(points [, params]) -> curve",
  "§4.2 The book's interpolation curve through the points (uniform t = j/n by default): Lagrange in t, a Bezier curve.")
def("interp.weights", {"interp.weights(n, t) -> {w1, ..., w(n+1)}", "interp.weights(params, t) -> {w1, ...}"},
  "The weights of the interpolation curve of the book's order n (n + 1 nodes at j/n: (4.10)-(4.28) for n = 2..6), or at the node parameters params; they sum to 1. With t a param the weights are equations, the polynomials the Maple program of §4.8 prints.")
def("interp.controls", "interp.controls(points [, params]) -> {C1, ...}",
  "The Bezier control points of the interpolation curve ((4.9), C1... of §4.4-4.7).")
def("interp.conic", "interp.conic(A, K, B, k) -> curve",
  "§4.1 The conic arc through A, K (u = 1/2), B with discriminant k (corrected apex C = K/k' - (A + B)k/(2k')).")
def("interp.arc", "interp.arc(points, C2 [, Cn] [, params]) -> curve",
  "§4.9 The curve through the points with the end tangent handles C2 (and Cn): M'(0) = N(C2 - M1); at uniform u, or at the increasing node parameters params (the curve then runs over [params[1], params[#params]]).")
def("interp.adaptive", "interp.adaptive(points [, axis]) -> params",
  "§4.10 The adaptive parameters v_j = (x_1 - x_j)/(x_1 - x_n) along an axis (1 by default).")
def("interp.prototype", "interp.prototype(\"desargues\"|\"rational\"|\"exp\"|\"exp1\"|\"trig\", points [, k] [, t0, t1]) -> curve",
  "§4.11 Interpolation on the book's prototypes: (4.35), (4.37), (4.39) with exponents k, its affine variant, (4.40).")
def("interp.basis", "interp.basis({g1, g2, ...}, points, params [, t0, t1]) -> curve, affine, deviation",
  "§4.11 The simplex-replacement engine on any basis of Lua functions g_i(t), nodes at params; affine: the weights sum to 1 (membership condition) over [t0, t1], deviation the largest |sum - 1|.")
def("interp.rational22", "interp.rational22({M1, ..., M5}) -> curve, coef",
  "(4.38) Per coordinate (a1 t^2 + a2 t + a3)/(a4 t^2 + a5 t + 1) through 5 points at t = j/4.")

def("approx.curve", "approx.curve(f, nodes) -> curve",
  "§5.1 The approximation curve through (x_j, f(x_j)) at uniform t.")
def("approx.mse", "approx.mse(f, nodes [, m] [, {m =, divisor = \"m+1\"|\"m\"|\"m-1\"}]) -> mse",
  "§5.1 The book's mean-square error: samples t = i/m (m = 100), residual f(x(t)) - y(t), the SSE divided by m + 1 (the book's; divisor = \"m\" or \"m-1\" for comparison: SSE/m gives 0.0000287 for Runge).")
def("approx.optimal_nodes", "approx.optimal_nodes(f, a, b, N [, m] [, {m =, divisor =}]) -> nodes, mse, evals",
  "§5.1 The optimal nodes of the N-node curve on [a, b]: deterministic multi-start Nelder-Mead over ordered nodes.")
def("approx.chebyshev", "approx.chebyshev(N [, a, b]) -> nodes",
  "The N Chebyshev nodes (roots) on [a, b], increasing.")
def("approx.lagrange_mse", "approx.lagrange_mse(f, nodes, a, b [, M]) -> mse",
  "§5.2 The MSE of Lagrange's polynomial on the nodes against f over M = 101 uniform x.")
def("approx.nelder_mead", "approx.nelder_mead(f, x0 [, step]) -> x, fx, iterations",
  "Deterministic Nelder-Mead minimisation of f(x1, ..., xn) from the list x0.")

-- ---------------------------------------------------------------------------------------
area("module", "The module", "What else the pointcalc table holds.", nil)

def("_VERSION", "_VERSION -> string", "The version of pointcalc, e.g. \"pointcalc 0.1.0\".", "value")

-- ---------------------------------------------------------------------------------------
area("repl", "REPL commands",
  "Lines starting with ':' are commands of the REPL; everything else is Lua. " ..
  "Expressions print their values.",
  "repl.md")

def(":help", ":help [NAME | AREA]",
  "List the commands and the API by area; with a name, its signature and description.", "command")
def(":show", ":show [COLUMNS]",
  "Draw the canvas in the terminal with braille dots, in colour, fitted to the window (or COLUMNS wide).", "command")
def(":save", ":save FILE [paper|screen]",
  "Write the canvas to FILE: PNG, SVG or PPM by the extension.", "command")
def(":load", ":load SCRIPT",
  "Run a Lua script, or a QBasic program (.bas), in this session.", "command")
def(":clear", ":clear",
  "Erase the drawing, keeping the screen's settings (colours, window, view).", "command")
def(":watch", ":watch [FILE | off]",
  "Rewrite FILE (.png, .svg, .ppm) after every statement that changes the canvas; as --watch FILE.", "command")
def(":quit", ":quit",
  "Leave the REPL (so does Ctrl-D).", "command")

-- ---------------------------------------------------------------------------------------
area("korotky", "Nature-like curves and conic surfaces (korotky.*)",
  "Korotky's articles: the polynomial and Ferguson splines through support points, the elastic " ..
  "reference curve (least bending energy) with the measures that compare a model with it, conic " ..
  "arcs from three points and two tangents with their centre, axes and asymptotes, conic sweeps, " ..
  "the rotational and ridge shells, the 4-D key construction and elliptic domes. A tangent is a slope " ..
  "tg(delta) or a 2-D vector.",
  "korotky.md")

def("korotky.poly_spline")
def("korotky.ferguson")
def("korotky.ferguson_lambda")
def("korotky.ferguson_tangents")
def("korotky.ferguson_substitution")
def("korotky.elastic")
def("korotky.graphical_slope")
def("korotky.deviation")
def("korotky.joint_jumps")
def("korotky.energy")
def("korotky.conic_arc")
def("korotky.conic_sweep")
def("korotky.dome_rect")
def("korotky.dome_tri")
def("korotky.conic_elements")
def("korotky.two_pencils")
def("korotky.conic_revolve")
def("korotky.ridge_shell")
def("korotky.plane_meet")

-- ---------------------------------------------------------------------------------------

-- The entry for a name, accepting "show" for ":show" when no API name is "show".
function H.find(name)
  return H.by_name[name] or H.by_name[":" .. name]
end

-- The signature forms of an entry as a list.
function H.forms(e)
  if type(e.sig) == "table" then return e.sig end
  return {e.sig}
end

return H
