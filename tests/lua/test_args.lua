-- The declared argument layer (stdlib/lua/pcl_args.h, docs/bindings.md): the one weight rule,
-- the one dimension rule and wording of messages, checked option keys, and the registry of
-- declarations that :help and docs/api.md read.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, err, truthy = check.eq, check.err, check.truthy
local help = require "help"
local root = arg[0]:match("^(.-)tests/lua/[^/]*$") or "./"

-- ---- one weight rule: |w - 1| <= 1e-9 is a point, |w| <= 1e-9 a direction ----------------
local M = (P(1.2, .9) * 49) * (1 / 49)          -- weight 0.99999999999999989, prints P(1.2, 0.9)
truthy(weight(M) ~= 1 and math.abs(weight(M) - 1) < 1e-9, "M's weight is near 1, not 1")
local pts = {P(0, 0), M, P(2.5, 0.3)}
truthy(korotky.poly_spline(pts), "korotky.poly_spline takes a near-1 weight as a point")
truthy(korotky.ferguson(pts, {0, 0, 0}, {1, 1, 1, 1}), "korotky.ferguson takes it")
truthy(korotky.ferguson_tangents(pts, {0, 0, 0}), "korotky.ferguson_tangents takes it")
truthy(korotky.elastic(pts), "korotky.elastic takes it")
truthy(buimov.spline(pts), "buimov.spline takes it")
truthy(plane.circle3(P(0, 0), M, P(2, 0)), "plane.circle3 takes it")
truthy(conic.parabola(P(0, 0), M, P(2.5, 0.3)), "conic.parabola takes it")
truthy(interp.lagrange(pts), "interp.lagrange takes it in a list")
truthy(conic.ellipse{C = P(0, 0), A = M, B = P(-0.9, 1.2)}, "conic.ellipse takes it as a key")
truthy(simplex(P(0, 0), M, P(0, 1)), "simplex takes it")
truthy(map.reflect(M, V(0, 1)), "map.reflect takes it")
eq(tostring(affine.frame(M, V(1, 0), V(0, 1))(P(0, 0))), "P(1.2, 0.9)", "affine.frame's origin")
eq(dist(M, P(1.2, 0)), 0.9, "dist takes a near-1 weight as a point")
eq(tostring(foot(M, P(0, 0), P(1, 0))), "P(1.2, 0)", "foot takes it")
eq(select(2, coords(M)), 0.9, "coords reads it as the point it prints")
truthy(sr(P(0, 0), P(2.4, 1.8), M) and meet(P(0, 0), M, P(0, 1), P(1, 0)), "sr and meet take it")
local D = V(1, 0) + P(0, 0) * 1e-12                 -- weight 1e-12: a direction
eq(tostring(map.translate(D)(P(1, 1))), "P(2, 1)", "a 1e-12 weight is a vector")
err(function() korotky.poly_spline({P(0, 0), P(1, 1) * 2}) end,
    "korotky.poly_spline: argument #1 (points) [2] must be a 2-D point, got 2*P(1, 1); its weight is 2, and a point equation's coefficients sum to 1 for a point, 0 for a vector (the membership condition)",
    "a weighted point is refused with its weight")

-- maps apply it to their images: the 1e-17 weight of a projective matrix is a direction
local tilt = map.matrix({{1, 0, 0}, {0, 1, 0}, {0, 1e-17, 1}})
local img = tilt(V(0, 1))
eq(tostring(img), "V(0, 1)", "map.matrix(...)(V(0, 1)) with weight 1e-17 is V(0, 1), not P(0, 1e+17)")
eq(weight(img), 0, "its weight is exactly 0")
eq(tostring(tilt(P(0, 1))), "P(0, 1)", "the point keeps weight 1")
err(function() return tilt:xy(V(0, 1)) end, "f:xy: argument #1 (X) must be a point (weight 1), got weight 0", "f:xy of a direction")

-- ---- lists of points leave nothing among the arguments -----------------------------------
local c, tangents = buimov.spline({P(0, 0), P(1, 1), P(2, 0)})
eq(c.dim, 2, "buimov.spline(points) without options")
eq(#tangents, 3, "one tangent per point")
eq(tostring(tangents[2]), "V(1, 0)", "the natural spline's middle tangent")
eq(#select(2, buimov.spline({P(0, 0), P(1, 1), P(2, 0)}, nil)), 3, "and with nil options")
eq(select(2, korotky.elastic({P(0, 0), P(1, 1), P(2, 0)})) > 0, true, "korotky.elastic(points) short form")

-- ---- option tables are checked ----------------------------------------------------------------
err(function() buimov.spline(pts, {edns = "cyclic"}) end,
    "buimov.spline: unknown option 'edns' (did you mean 'ends'?)", "a misspelt key is suggested")
err(function() korotky.elastic(pts, {peices = 2}) end,
    "korotky.elastic: unknown option 'peices' (did you mean 'pieces'?)", "a swap of letters")
err(function() korotky.poly_spline(pts, {zzz = 1}) end,
    "korotky.poly_spline: unknown option 'zzz' (the options are ends, s0, s1)", "no near key: the known ones")
err(function() buimov.spline(pts, {colr = 1}) end,
    "buimov.spline: unknown option 'colr' (the options are ends, d0, d1, param, lengths)", "colr where there is no colour")
err(function() korotky.poly_spline(pts, {1}) end,
    "korotky.poly_spline: argument #2 (opts) holds [1]; its options are named (key = value)", "a positional entry")
err(function() korotky.elastic(pts, {pieces = 9}) end,
    "korotky.elastic: option 'pieces' must be an integer from 1 to 4, got 9", "a key's own kind")
err(function() korotky.conic_sweep{U = 1} end,
    "korotky.conic_sweep: option 'U' must be a 3-D curve, got 1", "a call table's field")
err(function() korotky.conic_revolve{} end,
    "korotky.conic_revolve: option 'A' must be a 3-D point, got nil", "a required key")
err(function() figure{widht = 8} end, "figure: unknown option 'widht' (did you mean 'width'?)", "figure's keys")
err(function() conic.ellipse{C = P(0, 0), A = P(4, 0), B = P(0, 2), qudrant = 2} end,
    "conic.ellipse: unknown option 'qudrant' (did you mean 'quadrant'?)", "a call table's keys")
err(function() conic.five_points(P(1, 0), P(0, 1), P(-1, 0), P(0, -1), P(.6, .8), {whoel = true}) end,
    "conic.five_points: unknown option 'whoel' (did you mean 'whole'?)", "an options table's keys")

-- c:draw checks its options on the layer (stdlib/lua/l_camera.c)
local cd = curve(function(t) return P(t, t) end, 0, 1)
err(function() cd:draw{colr = 4} end, "c:draw: unknown option 'colr' (did you mean 'color'?)", "c:draw{colr}")
err(function() cd:draw{colour = {}} end, "c:draw: option 'colour' must be a colour number 0..15 or \"#rrggbb\", got table", "c:draw{colour} is the colour option")
err(function() cd:draw{closd = true} end, "c:draw: unknown option 'closd' (did you mean 'closed'?)", "c:draw{closd}")
err(function() cd:draw{color = 4, colour = 4} end, "c:draw: options 'color' and 'colour' are one option: give one", "both spellings")
-- the Lua-written calls of curves.lua check their keys the same way (_tk.check_options)
local diag = function(t) return P(t, t) end
err(function() plot(diag, {t = {0, 1}, colr = 3}) end, "plot: unknown option 'colr' (did you mean 'color'?)", "plot{colr}")
err(function() plot(diag, {t = {0, 1}, widht = 3}) end, "plot: unknown option 'widht' (see :help plot)", "plot with no near key")
err(function() stroke{nodes = {P(0, 0), P(1, 1)}, closd = true} end, "stroke: unknown option 'closd' (did you mean 'closed'?)", "stroke{closd}")
err(function() cd:each{tt = {0, 1, .5}} end, "c:each: unknown option 'tt' (did you mean 't'?)", "c:each{tt}")
err(function() plot(diag, {t = {0, 1}, color = {}}) end,
    "plot: option 'color' must be a colour number 0..15 or \"#rrggbb\", got table", "plot's colour names plot, not its helper")
screen(12)
plot(diag, {t = {0, 100}, colour = 4})
eq(point(50, 50), 4, "plot{colour = 4} draws in colour 4")
cd:draw{colour = 2}
eq(point(0, 0), 2, "c:draw{colour = 2} draws in colour 2")
cd:draw{colour = 5, t = {0, 1, .25}}
eq(point(1, 1), 5, "c:draw{colour = 5, t = ...} draws its dots in colour 5")
cd:draw{colour = 6, map = function(X) return X + V(10, 0) end}
eq(point(10, 0), 6, "c:draw{colour = 6, map = function} draws in colour 6")
local many66 = {}
for i = 1, 66 do many66[i] = P(i, 0) end
err(function() bezier(many66) end, "bezier: argument #1 (points) must hold 2 to 65 points, got 66", "bezier of 66 points names the cap")
err(function() bspline({P(0, 0), P(1, 1), P(2, 0), P(3, 1), P(4, 0)}, 3, {0, 0, 0, 0, 0, 0, 0, 0, 0}) end,
    "bspline: argument #3 (knots) leaves no domain: knot [4] = 0 (the start) must be less than knot [6] = 0 (the end)", "bspline names its knots")
truthy(hermite({P(0, 0), M}, {V(1, 0), V(1, 0)}) and cubic_spline({P(0, 0), M, P(2, 0)}) and interpolate(pts) and fourier({P(0, 0), M}),
       "hermite, cubic_spline, interpolate and fourier take the near-1 weight as a point")
err(function() cubic_spline(pts, {ends = "clamped", d0 = V(1, 0), d1 = V(1, 0, 0)}) end,
    "cubic_spline: option 'd1' is 3-D, but argument #1 (points) is 2-D (mixed dimensions)", "an end derivative of another dimension")
err(function() cubic_spline(pts, {endz = "natural"}) end, "cubic_spline: unknown option 'endz' (did you mean 'ends'?)", "cubic_spline's keys")
err(function() hermite(pts, {V(1, 0), V(1, 0), V(1, 0)}, {closd = true}) end, "hermite: unknown option 'closd' (did you mean 'closed'?)", "hermite's keys")
local strk = stroke{nodes = {P(0, 0), P(1, 1), P(2, 0)}}
err(function() strk:deriv(.5, P(1, 2)) end, "c:deriv: argument #2 (order) must be a whole number from 1 to 64, or \"left\" / \"right\", got P(1, 2)",
    "s:deriv(.5, P(1, 2)) names c:deriv and its order (it said Lua's bad argument #2 to 'deriv')")
err(function() strk.each() end, "c:each: call it as c:each(...), with a colon", "s.each()")
err(function() cd.xy(0.5) end, "c:xy: must be called on a curve, as c:xy(...)", "a C method of a curve called with a dot")
err(function() plot(function(t) return t end, {t = {0, 1, 0.1}}) end,
    "plot: a 1-D object needs a projection", "plot of a function of one number names plot")
err(function() screen{widht = 300} end, "screen: unknown option 'widht' (did you mean 'width'?)", "screen's keys")
err(function() path({P(0, 0), P(1, 1)}, {colr = 4}) end, "path: unknown option 'colr' (did you mean 'color'?)", "path's keys")
err(function() path({P(0, 0), P(1, 1)}, {closd = true}) end, "path: unknown option 'closd' (did you mean 'closed'?)", "closd")
err(function() path({P(0, 0), P(1, 1)}, {colour = 99}) end, "path: option 'colour' must be a colour number 0..15 or \"#rrggbb\", got 99", "colour is color")
err(function() path({P(0, 0), P(1, 1)}, {color = 1, colour = 2}) end, "path: options 'color' and 'colour' are one option: give one", "not both")
err(function() pen{widht = 2} end, "pen: unknown option 'widht' (did you mean 'width'?)", "pen's keys")
err(function() label("A", 0, 0, {sise = 9}) end, "label: unknown option 'sise' (did you mean 'size'?)", "label's keys")
err(function() put_block(0, 0, {}) end, "put_block: argument #3 (block) must be a block from get_block, got table", "put_block's block")
err(function() put_block(P(0, 0), get_block(0, 0, 1, 1), "xxor") end,
    "put_block: argument #3 (action) must be \"pset\", \"preset\", \"and\", \"or\" or \"xor\", got \"xxor\"", "shown by its slot after a point")
err(function() pages(3) end, "pages: argument #1 (active page) must be an integer from 0 to 0, got 3", "a range the screen sets")
path({P(0, 0), P(1, 1)}, {colour = 4})
eq(point(0, 0), 4, "path{colour = 4} draws in colour 4")

-- The misspelt keys of the issue on the calls where they apply.  Those calls live in files not
-- yet on the layer: each is listed here with the message it must give, and checked to FAIL to
-- give it; a converter who moves the call onto the layer moves its entry to the live checks
-- above (this test fails until then, saying which).
local PENDING = {
}
local still = {}
for _, p in ipairs(PENDING) do
  local ok, msg = pcall(p[2])
  if not ok and tostring(msg):find(p[3], 1, true) then
    error("pending check '" .. p[1] .. "' passes now: move it to the live checks of test_args.lua", 0)
  end
  still[#still + 1] = p[1]
end
eq(#still, #PENDING, "pending checks of unconverted files: " .. table.concat(still, "; "))

-- ---- one wording: names the user's call, the argument by position and name -------------------
local many = {}
for i = 1, 33 do many[i] = P(i, 0) end
err(function() korotky.poly_spline(many) end,
    "korotky.poly_spline: argument #1 (points) must hold 2 to 32 points, got 33", "a count with its cap")
err(function() korotky.poly_spline({P(0, 0), P(1, 1), V(1, 2)}) end,
    "korotky.poly_spline: argument #1 (points) [3] must be a 2-D point, got V(1, 2); a point has weight 1: to place a vector, add it to a point, e.g. P(0, 0) + v", "a list element")
err(function() buimov.knots({P(0, 0), P(1, 1, 1)}, 2) end,
    "buimov.knots: argument #1 (points) [2] is 3-D, but [1] is 2-D (mixed dimensions)", "mixed dimensions in a list")
err(function() korotky.conic_arc(P(0, 0), V(1, 0), P(1, 0, 0), V(0, 1), P(1, 1)) end,
    "korotky.conic_arc: argument #3 (V) is 3-D, but argument #1 (U) is 2-D (mixed dimensions)", "mixed dimensions")
err(function() korotky.ferguson_substitution(pts, {0, 0, 0}, 1, 2, "mid") end,
    "korotky.ferguson_substitution: argument #5 (root) must be \"min\" or \"max\", got \"mid\"", "an enum shows the string")
err(function() dist(P(0, 0), P(1, 1, 1)) end, "dist: argument #2 (B) is 3-D, but argument #1 (A) is 2-D (mixed dimensions)", "the point functions' mixed dimensions")
err(function() return P(0, 0):dist(P(1, 1, 1)) end, "dist: argument #1 (B) is 3-D, but self (A) is 2-D (mixed dimensions)", "a value's method counts after self")
err(function() assert(pcall(dot, P(1, 2), V(1, 0))) end, "dot: argument #1 (u) must be a vector, got P(1, 2)", "pcall(dot, ...) names dot")
err(function() return smooth.half(2, 3, .5).deriv(.5) end, "g:deriv: must be called on a half-spline, as g:deriv(...)", "a half-spline method with a dot")
err(function() return complex(1, 2).abs(5) end, "z:abs: must be called on a complex number, as z:abs(...)", "a complex method with a dot")
err(function() local t = param "t" return (P(0, 0) + V(1, 0) * t).with(3) end, "M:with: must be called on an equation, as M:with(...)", "an equation method with a dot")
err(function() local t = param "t" return math.log(t, 1) end, "math.log: argument #2 (base) must be a positive number other than 1, got 1", "math.log of an equation names its base")
local e = korotky.energy
err(function() e(3) end, "korotky.energy: argument #1 (curve) must be a curve, got 3", "an alias keeps the declared name")
err(function() assert(pcall(korotky.energy, 3)) end, "korotky.energy: argument #1", "pcall names the function, not pcall")
err(function() assert(pcall(label, 5)) end, "label:", "pcall(label, 5) names label")
err(function() interp.prototype("desargues") end,
    "interp.prototype: argument #2 (points) must hold 4 points (the \"desargues\" prototype), got nil", "the count the kind takes")
err(function() interp.prototype("exp", {P(0, 0), P(1, 1)}, {1, 2, 3}) end,
    "interp.prototype: argument #2 (points) must hold 3 points, got 2", "a count without \"3 to 3\"")
err(function() conic.ed(P(0, 0), P(2, 0), P(1, 1, 0), .6) end,
    "conic.ed: argument #3 (C) is 3-D, but argument #1 (A) is 2-D (mixed dimensions)", "conic.ed's dimensions")
local ed = conic.ed
err(function() assert(pcall(ed, P(0, 0), P(2, 0), P(1, 1), 0)) end,
    "conic.ed: argument #4 (k) must be a non-zero number", "an alias of conic.ed keeps its name")
local odd = setmetatable({}, {__len = function() return "x" end})   -- a length that is no integer
err(function() interp.lagrange(odd) end, "interp.lagrange: argument #1 (points) must be a list of points, got table", "a list with a bad __len")
err(function() approx.mse(math.sin, odd) end, "approx.mse: argument #2 (nodes) must be a list of numbers, got table", "numbers with a bad __len")
err(function() approx.mse(3, {0, 1}) end, "approx.mse: argument #1 (f) must be a function of x, got 3", "approx names its function")
local T = map.rotate(1)
err(function() return T({P(1, 2)}) end, "T: takes a 2-D point or vector, or 2 coordinates; got a table", "a map applied to a list names the map")
err(function() return T.inverse(3) end, "f:inverse: must be called on a map, as f:inverse(...)", "a method called with a dot")
err(function() return simplex(P(0, 0), P(1, 0), P(0, 1)).params(5) end,
    "S:params: must be called on a simplex, as S:params(...)", "a simplex method with a dot")
local cv = curvilinear(function(a, b) return P(a, b) end)
err(function() cv.clamp() end, "C:clamp: call it as C:clamp(...), with a colon", "a Lua-written method called with a dot")
err(function() cv.xy(1, 2) end, "C:xy: call it as C:xy(...), with a colon", "C.xy")
local cu = curve(function(t) return P(t, t) end, 0, 1)
err(function() cu.each() end, "c:each: call it as c:each(...), with a colon", "c.each()")
err(function() cu.draw{} end, "c:draw: must be called on a curve, as c:draw(...)", "c.draw{}")
err(function() buimov.basis(0, 2, 0.5, {0, 1, 0}) end, "buimov.basis: argument #4 (knots) must not decrease ([3])", "a body's own check on a declared argument")

-- ---- the registry: every declared function documented from its declaration ----------------
local decls = rawget(pointcalc, "_decl")
truthy(type(decls) == "table" and next(decls), "pointcalc._decl holds the declarations")
eq(#help.conflicts, 0, "help.lua and the declarations agree:\n  " .. table.concat(help.conflicts, "\n  "))
local api = assert(io.open(root .. "docs/api.md")):read("a")
local function cell(s) return (s:gsub("|", "\\|")) end
local n = 0
for name, d in pairs(decls) do
  n = n + 1
  local entry = help.by_name[name]
  truthy(entry, name .. " is declared, so help.lua must place it: def(\"" .. name .. "\")")
  truthy(entry.declared, name .. ": its help entry comes from the declaration")
  eq(table.concat(help.forms(entry), "\n"), type(d.sig) == "table" and table.concat(d.sig, "\n") or d.sig,
     name .. ": :help shows the declared signature")
  eq(entry.desc, d.desc, name .. ": :help shows the declared description")
  truthy(d.desc ~= "", name .. " has a help line")
  local forms = {}
  for i, f in ipairs(help.forms(entry)) do forms[i] = "`" .. cell(f) .. "`" end
  truthy(api:find("| `" .. cell(name) .. "` | " .. table.concat(forms, "<br>") .. " |", 1, true),
         name .. ": docs/api.md's row is the declaration's (regenerate: pointcalc docs/gen_api.lua > docs/api.md)")
end
truthy(n >= 60, "the converted files declare their functions (" .. n .. ")")

-- every function of a converted table is declared (converters add their tables here)
local CONVERTED = {"korotky", "plane", "buimov", "map", "affine", "konopatsky", "smooth", "complex", "conic", "oneratio", "interp", "approx", "qb", "surface"}
-- global functions of converted files, and the curve methods written in C
for _, k in ipairs{"bezier", "bspline", "hermite", "cubic_spline", "interpolate", "curve", "spline2", "fourier",
                   "sphdir", "camera", "squash", "squash01", "oblique", "projection", "oresme", "bisect"} do
  truthy(decls[k], k .. " has a declaration")
end
for k, v in pairs(pointcalc._tk.curve_methods) do
  truthy(decls["c:" .. k] or k == "each", "c:" .. k .. " has a declaration")
end
for _, t in ipairs(CONVERTED) do
  for k, v in pairs(pointcalc[t]) do
    if type(v) == "function" then truthy(decls[t .. "." .. k], t .. "." .. k .. " has a declaration") end
  end
end
-- the global functions of converted files
for _, k in ipairs{"P", "V", "lerp", "bar", "mid", "dist", "dot", "cross", "unit", "perp", "angle", "foot", "Sigma", "sr",
                   "divide", "harmonic", "cross_ratio", "meet", "area", "volume", "normalize", "weight", "coords", "near",
                   "mobius", "param"} do
  truthy(decls[k], k .. " has a declaration")
end
truthy(decls["simplex"] and decls["S(p, q)"] and decls["f(p)"] and decls["f:xy"], "constructors, calls and methods")
truthy(decls["figure"], "figure has a declaration")
truthy(decls["oneratio"], "oneratio(A, B, C), the table's __call, has a declaration")
eq(tostring(oneratio(P(0, 0), M, P(1, 1))):match("^[%w.]+"), "oneratio.simplex", "oneratio(...) is oneratio.simplex")
for _, name in ipairs{"screen", "cls", "color", "palette", "pset", "preset", "line", "line_to", "circle",
                      "paint", "point", "window", "view", "save", "size", "last_point", "pen", "path",
                      "fill", "label", "text", "print_at", "scroll_text", "get_block", "put_block", "draw",
                      "pages", "pcopy", "pmap", "mode_info", "paint_tile"} do
  truthy(decls[name], name .. " has a declaration")
end
local sig = help.forms(help.by_name["korotky.poly_spline"])[1]
eq(sig, 'korotky.poly_spline(points [, {ends = "natural"|"clamped", s0 =, s1 =}]) -> curve, coef', "a generated signature")
eq(help.forms(help.by_name["korotky.conic_sweep"])[1], "korotky.conic_sweep{U =, V =, T =, P =, Q =} -> s", "a call table's signature")

check.done()
