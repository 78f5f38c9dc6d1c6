-- The help registry: every public name of pointcalc with its area, signature and a one-line
-- description.  It is the single source of the REPL's :help and of docs/api.md
-- (tools/gen_api.lua); tests/lua/test_help.lua checks that every function of the pointcalc
-- module has an entry here and that every entry names something that exists.
--
-- Entries: name (as written in a script: "lerp", "qb.rnd", "A.x", ":show"), area, sig (one
-- form, or a list of forms), desc (one line).

local H = {areas = {}, entries = {}, by_name = {}}

local current
local function area(id, title, intro, guide)
  current = {id = id, title = title, intro = intro, guide = guide, entries = {}}
  H.areas[#H.areas + 1] = current
  H.areas[id] = current
end

local function def(name, sig, desc, kind)
  assert(not H.by_name[name], "duplicate help entry " .. name)
  local e = {name = name, area = current.id, sig = sig, desc = desc, kind = kind or "function"}
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
  "The intersection K = A1 + (A2 - A1)lambda = B1 + (B2 - B1)mu of two lines, any dimension; parallel lines give their direction (weight 0), skew ones nil and their distance.")
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

-- Fields that a value's __index computes (so Tab cannot find them in a table), by __name.
H.fields_of = {point = {"x", "y", "z", "w"}}

-- ---------------------------------------------------------------------------------------
area("frames", "Simplices and affine maps",
  "Frames of reference: a simplex gives natural parameters, an affine map changes the frame.",
  "points.md")

def("simplex", "simplex(C, A, B, ...) -> S",
  "A simplex with initial point C (the book's simplex CAB): S(p, q) = (A - C)p + (B - C)q + C.")
def("S(p, q)", "S(p, q, ...) -> point",
  "The point of simplex S with natural parameters p, q, ...", "method")
def("S:bary", "S:bary(p, q, ..., r) -> value",
  "Ap + Bq + ... + Cr: barycentric coefficients, the initial point's last (weighted when they do not sum to 1).", "method")
def("S:params", "S:params(M) -> p, q, ..., residual",
  "The natural parameters of M (least squares off the simplex's flat) and M's distance from that flat.", "method")
def("S:measure", "S:measure() -> number",
  "Length, area, volume...: signed when the simplex is full-dimensional.", "method")
def("S:ratio", "S:ratio(P1, P2, ...) -> ratio, residual",
  "The S-/V-theorem: the signed ratio of the measure of P1P2... to the simplex's own.", "method")
def("affine", "affine({A, B, C}, {A2, B2, C2}) -> f",
  "The affine map sending A to A2, B to B2, C to C2 (3 pairs in the plane, 4 in space; images may have another dimension).")
def("affine.frame", "affine.frame(O, X, Y [, Z]) -> f",
  "The map (x, y, z) -> O + x(X - O) + y(Y - O) + z(Z - O); the axes may also be vectors.")
def("affine.identity", "affine.identity(n) -> f",
  "The identity map of n-space.")
def("f(p)", "f(p) | f(x, y, ...) -> value",
  "Apply an affine map (vectors ignore the translation).", "method")
def("f:compose", "f:compose(g) | f * g -> map",
  "The map applying g first, then f.", "method")
def("f:inverse", "f:inverse() -> map",
  "The inverse map; a singular or non-square map is an error.", "method")

-- ---------------------------------------------------------------------------------------
area("draw", "Drawing (QBasic SCREEN 12)",
  "A 640x480 16-colour canvas, y down, as QBasic's SCREEN 12. Every pair of coordinates " ..
  "may be given as one 2-D point: pset(M), line(A, B).",
  "drawing.md")

def("screen", {"screen(12) | screen(13)", "screen{width=W, height=H [, colors=16|256]}"},
  "A new blank canvas: 640x480x16 (12), 320x200x256 (13) or any size.")
def("cls", "cls()",
  "Clear the view to the background colour.")
def("color", {"color(fg [, bg])", "color() -> fg, bg"},
  "Set the drawing colour (and the background used by cls), or read both.")
def("palette", {"palette(attr, colour)", "palette()"},
  "Change what a colour number looks like (65536*b + 256*g + r in 0..63, \"#rrggbb\" or {r, g, b}); no argument restores the default.")
def("pset", "pset(x, y [, c]) | pset(A [, c])",
  "Plot one pixel in colour c (default: the drawing colour).")
def("preset", "preset(x, y [, c]) | preset(A [, c])",
  "Plot one pixel in colour c (default: the background: erases).")
def("line", "line(x1, y1, x2, y2 [, c [, \"b\"|\"bf\"]]) | line(A, B [, c [, style]])",
  "A segment, or with \"b\" the outline of a box, with \"bf\" a filled box.")
def("line_to", "line_to(x, y [, c [, \"b\"|\"bf\"]]) | line_to(B [, c [, style]])",
  "A segment from the last point referenced to (x, y): QBasic's LINE -(x, y).")
def("circle", "circle(x, y, r [, c [, start, end [, aspect]]]) | circle(A, r, ...)",
  "A circle, an ellipse (aspect) or an arc (angles in radians; a negative angle also draws that radius).")
def("paint", "paint(x, y [, c [, border]]) | paint(A [, c [, border]])",
  "Flood-fill from (x, y) up to pixels of the border colour (default: the paint colour).")
def("point", "point(x, y) -> colour | point(A) -> colour",
  "The colour number at (x, y), or -1 outside the view.")
def("window", {"window(x1, y1, x2, y2 [, \"screen\"])", "window()"},
  "World coordinates: (x1, y1)-(x2, y2) fill the view, y up (y down with \"screen\"); no argument: pixels again.")
def("view", {"view(x1, y1, x2, y2 [, fill [, border [, \"screen\"]]])", "view()"},
  "A viewport in pixels: drawing is clipped to it and, without \"screen\", relative to it.")
def("last_point", "last_point() -> x, y",
  "The graphics cursor: the last point referenced, in world coordinates.")
def("size", "size() -> width, height, colours",
  "The size of the canvas and its number of colours.")
def("save", "save(path [, \"paper\"|\"screen\"])",
  "Write the canvas: PNG, SVG or PPM by the extension, atomically; \"paper\" prints dark ink on white.")

-- ---------------------------------------------------------------------------------------
area("qb", "QBasic numbers (qb.*)",
  "QBasic's number semantics, used by translated QBasic programs and available to scripts.",
  nil)

def("qb.f32", "qb.f32(x) -> number",
  "x rounded to QBasic's SINGLE (IEEE float32).")
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
