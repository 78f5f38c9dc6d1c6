-- The argument layer's kinds for lists of weighted values and of vectors, callables, tables and
-- numbers that may be infinite (docs/bindings.md), its private declarations (_tk), the one knot
-- reader, and the guard of declarations against debug.setupvalue: values read and every
-- message as the user sees it.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, err, truthy = check.eq, check.err, check.truthy

-- ---- lists of values (bezier, bspline): weights kept, one dimension, finite ---------------
local c = bezier{P(0, 0), 2 * P(1, 1), P(2, 0)}        -- a rational quadratic (a conic arc)
eq(tostring(c(0.5)), "P(1, 0.66666666666667)", "a weighted control point makes it rational")
eq(tostring(bezier{P(0, 0), V(1, 0), P(2, 0)}(0.5)), "P(2, 0)", "a vector is a control point at infinity: (0.5 V + 0.25 (P0 + P2)) / 0.5")
local ctl = c:controls()
eq(#ctl, 3, "three control values back")
eq(tostring(ctl[2]), "2*P(1, 1)", "the weighted one as given")
err(function() return bezier{P(0, 0), P(1, 1, 1)} end,
  "bezier: argument #1 (points) [2] is 3-D, but [1] is 2-D (mixed dimensions)", "mixed dimensions")
err(function() return bezier{P(0, 0), P(1, 1) * 1e308 * 10} end, "out of range", "an overflowing value is refused where it is made")
err(function() return bezier{P(0, 0)} end, "bezier: argument #1 (points) must hold 2 to 65 points, got 1", "the count")
err(function() return bspline({P(0, 0), 5, P(2, 0)}, 2) end, "bspline: argument #1 (points) [2] must be a point, got 5", "a number in the list")

-- ---- lists of vectors (hermite's tangents and tin): the points' dimension ------------------
local h = hermite({P(0, 0), P(1, 1)}, {V(1, 0), V(1, 0)}, {tin = {V(1, 0), V(0, 1)}})
eq(tostring(h(0.5)), "P(0.625, 0.375)", "hermite with arriving tangents")
err(function() return hermite({P(0, 0), P(1, 1)}, {V(1, 0), V(1, 0, 0)}) end,
  "hermite: argument #2 (tangents) [2] must be a 2-D vector, got V(1, 0, 0)", "a tangent of another dimension")
err(function() return hermite({P(0, 0), P(1, 1)}, {V(1, 0), V(1, 0)}, {tin = {V(1, 0)}}) end,
  "hermite: option 'tin' must hold 2 vectors, got 1", "tin's count")
err(function() return hermite({P(0, 0), P(1, 1)}, {V(1, 0), V(1, 0)}, {tin = {V(1, 0), P(1, 1)}}) end,
  "hermite: option 'tin' [2] must be a 2-D vector, got P(1, 1); a vector has weight 0", "a point in tin")

-- ---- the one knot reader: bspline and surface.bspline -----------------------------------------
local pts = {P(0, 0), P(1, 1), P(2, 0)}
eq(#bspline(pts, 2, {0, 0, 0, 1, 1, 1}):knots(), 6, "a list of knots")
err(function() return bspline(pts, 2, {0, 0, 0, 1, 1}) end,
  "bspline: argument #3 (knots) must hold points + degree + 1 = 6 knots, got 5", "the knot count")
err(function() return bspline(pts, 2, {0, 0, 0, 1, "x", 1}) end,
  "bspline: argument #3 (knots) [5] must be a finite number, got \"x\"", "a knot that is no number")
err(function() return bspline(pts, 2, {0, 0, 1, 0, 1, 1}) end,
  "bspline: argument #3 (knots) must be non-decreasing, but knot [4] = 0 is less than knot [3] = 1", "decreasing knots")
err(function() return bspline(pts, 2, "opn") end,
  "bspline: argument #3 (knots) must be \"open\", \"uniform\", \"periodic\" or a list of numbers, got \"opn\"", "a misspelt kind")
local grid = {{P(0, 0, 0), P(1, 0, 0)}, {P(0, 1, 0), P(1, 1, 1)}}
err(function() return surface.bspline(grid, 1, 1, {0, 0, 1}) end,
  "surface.bspline: argument #4 (knots) must hold points + degree + 1 = 4 knots, got 3", "a surface's knots")

-- ---- callables, tables, numbers that may be infinite --------------------------------------------
local f = setmetatable({}, {__call = function(_, x) return x - 2 end})
check.near(select(1, bisect(f, 0, 5)), 2, 1e-9, "bisect takes a callable table")
err(function() return bisect(5, 0, 1) end, "bisect: argument #1 (f) must be a function, got 5", "a number for f")
local t = param "t"
err(function() return (t * 2):with(5) end, "M:with: argument #1 (values) must be a table {name = value}, got 5", "M:with's table")
eq(squash(math.huge), 1, "squash(inf) is the square's side")
err(function() return squash(0 / 0) end, "squash: argument #1 (p) must be a number other than NaN", "NaN")
eq(tostring(divide(P(0, 0), P(2, 0), math.huge)), "P(2, 0)", "divide with lambda = inf gives Y")

-- ---- private declarations (_tk): read and worded by the layer ------------------------------------
local Q = bilinear(P(0, 0), P(2, 0), P(2, 2), P(0, 2))
eq(tostring(Q(0.5, 0.5)), "P(1, 1)", "bilinear's centre")
err(function() return bilinear(P(0, 0), P(2, 0), P(2, 2, 0), P(0, 2)) end,
  "bilinear: argument #3 (P2) is 3-D, but argument #1 (P0) is 2-D (mixed dimensions)", "bilinear's corners")
err(function() return pointcalc._tk.param_set("1x", 2) end,
  "_tk.param_set: argument #1 (name) must be a parameter name, got \"1x\"", "param_set's name")

-- ---- the guard: a declaration cannot be swapped, the other upvalues can ---------------------------
local other = select(2, debug.getupvalue(dist, 1))
err(function() debug.setupvalue(lerp, 1, other) end, "upvalue 1 of a declared function is its declaration", "swapping declarations")
eq(dist(P(0, 0), P(3, 4)), 5, "dist still reads its own arguments")
eq(debug.getupvalue(debug.setupvalue, 1), nil, "the guard keeps Lua's function out of reach")
debug.setmetatable(select(2, debug.getupvalue(lerp, 1)), nil)   -- the guard does not go by it
err(function() debug.setupvalue(lerp, 1, other) end, "cannot be replaced", "a declaration without its metatable")
eq(tostring(lerp(P(0, 0), P(2, 2), 0.5)), "P(1, 1)", "lerp still reads its own arguments")
eq(debug.setupvalue(function() return other end, 1, 5), "other", "a Lua function's upvalues are set as before")

check.done()
