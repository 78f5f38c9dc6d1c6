-- The help registry: every public name of pointcalc with its area, signature and a one-line
-- description.  It is the single source of the REPL's :help and of docs/api.md
-- (docs/gen_api.lua); tests/lua/test_help.lua checks that every function of the pointcalc
-- module has an entry here and that every entry names something that exists.
--
-- Entries: name (as written in a script: "lerp", "qb.rnd", "A.x", ":show"), area, sig (one
-- form, or a list of forms), desc (one line), kind ("function", "method", "field", "value",
-- "operator", or "library": a function of Lua's own library that pointcalc extends, math.sin).
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

def("P")
def("V")
def("lerp")
def("bar")
def("mid")
def("dist")
def("dot")
def("cross")
def("unit")
def("perp")
def("angle")
def("foot")
def("Sigma")
def("sr")
def("divide")
def("harmonic")
def("cross_ratio")
def("meet")
def("area")
def("volume")
def("normalize")
def("weight")
def("coords")
def("near")

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

def("smooth.sine")
def("smooth.cubic")
def("smooth.power")
def("smooth.half")
def("smooth.locus")
def("smooth.clamp")
def("smooth.clamp_qb")
def("g(t)", nil, nil, "method")
def("g:deriv", nil, nil, "method")

-- ---------------------------------------------------------------------------------------
area("curves", "Curves",
  "One curve type for every construction: Bezier (rational through weighted points), B-spline " ..
  "and NURBS, Hermite pieces, splines and interpolation through nodes, Stepanov's strokes and " ..
  "Fourier curves, a Lua function. A curve c gives points c(t), derivatives, length, curvature, " ..
  "and draws itself as one path with c:draw().",
  "curves.md")

def("bezier")
def("bspline")
def("hermite")
def("cubic_spline")
def("interpolate")
def("curve")
def("spline2")
def("stroke", "stroke{nodes = {P, ...}, uin = ..., kink = ... | ein = {V, ...}, rin =, rout =, n =, m =, t0 =, g =, closed = false} -> curve",
  "The one-stroke curve through the nodes, one quadrilateral-spline piece per pair (examples 10, 11, 13); its t runs over 0..pieces.")
def("fourier")
def("sphdir")
def("plot", {"plot(f, {t = {a, b [, step]}, color = c, map = m, tol = px})",
             "plot(f, {t = {a, b, step}, brush = \"pset\"|\"dot\"|fn | dots = true | qb = true, ...})"},
  "Draw t -> f(t) as one connected path (3-D through map or the camera); with a brush, dots = true or qb = true, dots at those steps as the listings do.")
def("c(t)", nil, nil, "method")
def("c:xy", nil, nil, "method")
def("c:eval", nil, nil, "method")
def("c:deriv", nil, nil, "method")
def("c:tangent", nil, nil, "method")
def("c:normal", nil, nil, "method")
def("c:curvature", nil, nil, "method")
def("c:split", nil, nil, "method")
def("c:sub", nil, nil, "method")
def("c:insert_knot", nil, nil, "method")
def("c:length", nil, nil, "method")
def("c:bbox", nil, nil, "method")
def("c:controls", nil, nil, "method")
def("c:knots", nil, nil, "method")
def("c:map", nil, nil, "method")
def("c:flatten", nil, nil, "method")
def("c:each", "c:each{t = {a, b, step}, qb = false} -> iterator of point, piece, t",
  "Walk a curve: for M, i, t in c:each{t = {0, 1, .01}} do ... end.", "method")
def("c:draw", nil, nil, "method")
def("c:piece", nil, nil, "method")
def("c:piece_xy", nil, nil, "method")
def("c:coef", nil, nil, "method")
def("c:monomial", nil, nil, "method")
def("c:conic", nil, nil, "method")

-- ---------------------------------------------------------------------------------------
area("equations", "Point equations",
  "The book's point equations as compiled objects: arithmetic on a parameter builds an " ..
  "equation (common parts shared), which curve() and surface() compile to C with exact " ..
  "derivatives; the membership condition is checked when one is made.",
  "equations.md")

def("param")
def("M(t)", nil, nil, "method")
def("M:with", nil, nil, "method")
def("M:show", nil, nil, "method")
def("M:expanded", nil, nil, "method")
def("M:sample", nil, nil, "method")
def("s:sum", nil, nil, "method")
def("math.sin", nil, nil, "library")
def("math.cos", nil, nil, "library")
def("math.tan", nil, nil, "library")
def("math.exp", nil, nil, "library")
def("math.log", nil, nil, "library")
def("math.sqrt", nil, nil, "library")
def("math.abs", nil, nil, "library")
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

def("squash")
def("squash01")
def("oblique")
def("projection")
def("complex")
def("complex.i", "complex.i", "The imaginary unit.", "value")
def("complex.polar")
def("complex.exp")
def("complex.abs")
def("complex.arg")
def("complex.conj")
def("z:conj", nil, nil, "method")
def("z:abs", nil, nil, "method")
def("z:arg", nil, nil, "method")
def("z:exp", nil, nil, "method")
def("z:point", nil, nil, "method")
def("mobius")
def("M(z)", nil, nil, "method")
def("M:inverse", nil, nil, "method")
def("oresme")
def("o(t)", nil, nil, "method")
def("bisect")

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
def("slider")
def("camera")
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

def("qb.f32")
def("qb.csng")
def("qb.cint")
def("qb.clng")
def("qb.rnd")
def("qb.randomize")
def("qb.seed")
def("qb.range")

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

def("conic.ed")
def("conic.ed_k")
def("conic.circle_k")
def("conic.ceva")
def("conic.ceva_k")
def("konopatsky.area_k")
def("konopatsky.area_theorem")
def("konopatsky.o_theorem")
def("konopatsky.simplex_ratio")
def("konopatsky.meet_line_plane")
def("konopatsky.polar")
def("konopatsky.rotate")
def("konopatsky.moving_simplex")
def("konopatsky.equation")
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
def("conic.parabola")
def("conic.ellipse")
def("conic.hyperbola")
def("conic.circle")
def("conic.tilted")
def("conic.five_points")
def("conic.five_points2")
def("conic.triples")
def("conic.redundant")
def("conic.reparam")
def("conic.sinusoid")
def("conic.cycloid")
def("conic.cones")
def("conic.contour")

def("oneratio")
def("oneratio.simplex")
def("oneratio.tetra")
def("oneratio.bezier3")
def("oneratio.smooth")
def("oneratio.smooth_scheme")
def("oneratio.desargues")
def("oneratio.double_contact")
def("oneratio.closed")
def("oneratio.simplex_scheme")
def("oneratio.levels")
def("oneratio.desargues_scheme")

def("interp.lagrange")
def("interp.weights")
def("interp.controls")
def("interp.conic")
def("interp.arc")
def("interp.adaptive")
def("interp.prototype")
def("interp.basis")
def("interp.rational22")

def("approx.curve")
def("approx.mse")
def("approx.optimal_nodes")
def("approx.chebyshev")
def("approx.lagrange_mse")
def("approx.nelder_mead")

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
