-- The one curve type through Lua: bezier, bspline, hermite, cubic_spline, interpolate,
-- curve(f, ...), their methods (evaluation, derivatives, split, length, bbox, flatten, map),
-- drawing as paths, plot's paths and dots, and every argument error.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy
local pi, cos, sin, sqrt = math.pi, math.cos, math.sin, math.sqrt
local same = check.same_within(1e-9)

-- Bezier: the explicit Bernstein sum ---------------------------------------------------------
local A, B, C, D = P(0, 0), P(1, 2), P(3, 3), P(4, 0)
local b = bezier{A, B, C, D}
eq(b.kind, "bezier", "kind"); eq(b.degree, 3, "degree"); eq(b.dim, 2, "dim")
eq(b.t0, 0, "t0"); eq(b.t1, 1, "t1")
for t = 0, 1, .125 do
  local s = 1 - t
  same(b(t), A*s^3 + B*3*s^2*t + C*3*s*t^2 + D*t^3, "Bernstein sum at " .. t)
end
same(b:deriv(0), (B - A)*3, "C'(0) = 3(B - A)")
same(b:deriv(1), (D - C)*3, "C'(1) = 3(D - C)")
same(b:deriv(0, 2), (C - B*2 + A)*6, "C''(0) = 6(C - 2B + A)")
same(b:tangent(0), unit(B - A), "unit tangent")
local x, y = b:xy(.5)
near(x, 2, 1e-12, "xy x"); near(y, 1.875, 1e-12, "xy y")

-- split: the halves meet and reproduce the curve
local l, r = b:split(.3)
eq(l.t1, .3, "the left part keeps its parameters: [0, .3]"); eq(r.t0, .3, "the right [.3, 1]")
same(l(.3), b(.3), "left ends at the split"); same(r(.3), b(.3), "right starts there")
same(l(.15), b(.15), "left half"); same(r(.65), b(.65), "right half")
local sb = b:sub(.2, .6)
same(sb(sb.t0), b(.2), "sub starts at a"); same(sb(sb.t1), b(.6), "sub ends at b")

-- a rational quadratic with weights (1, cos(theta/2), 1) is a circular arc
local th = pi / 2
local w = cos(th / 2)
local arc = bezier{P(1, 0), P(1, 1) * w, P(0, 1)}
for t = 0, 1, .1 do near(dist(arc(t), P(0, 0)), 1, 1e-12, "arc radius at " .. t) end
near(arc:curvature(.37), 1, 1e-9, "curvature of the unit circle")
near(arc:length(), pi / 2, 1e-9, "quarter circle length")
local lo, hi = arc:bbox()
same(lo, P(0, 0), "bbox lo", 1e-6); same(hi, P(1, 1), "bbox hi", 1e-6)
local ctl = arc:controls()
eq(#ctl, 3, "three control values"); near(weight(ctl[2]), w, 1e-15, "the middle weight kept")

-- B-spline: order k on k points is the Bezier curve; knots; insertion keeps the curve
local bs = bspline({A, B, C, D}, 3)
for t = 0, 1, .1 do same(bs(t), b(t), "B-spline = Bezier at " .. t) end
local k = bspline({A, B, C, D, P(5, 2), P(6, 0)}, 3)
eq(#k:knots(), 10, "open knots: points + degree + 1")
same(k(k.t0), A, "open: starts at the first point"); same(k(k.t1), P(6, 0), "ends at the last")
local k2 = k:insert_knot((k.t0 + k.t1) / 3)
eq(#k2:controls(), 7, "one more control point")
for i = 0, 20 do
  local t = k.t0 + (k.t1 - k.t0) * i / 20
  same(k2(t), k(t), "knot insertion keeps the curve at " .. t)
end
local per = bspline({P(0, 0), P(1, 0), P(1, 1), P(0, 1)}, 3, "periodic")
truthy(per.closed, "periodic is closed"); same(per(per.t0), per(per.t1), "periodic closes")
local given = bspline({A, B, C, D}, 2, {0, 0, 0, .5, 1, 1, 1})
same(given(0), A, "given knots"); same(given(1), D, "given knots, end")

-- Hermite and the cubic spline through nodes
local h = hermite({P(0, 0), P(1, 1), P(2, 0)}, {V(1, 1), V(1, 0), V(1, -1)})
same(h(0), P(0, 0), "node 1"); same(h(1), P(1, 1), "node 2"); same(h(2), P(2, 0), "node 3")
same(h:deriv(1), V(1, 0), "derivative at node 2")
local pts = {P(0, 0), P(1, 2), P(2, 1), P(3, 3), P(4, 0)}
local ns = cubic_spline(pts, {u = {0, 1, 2, 3, 4}})
for i, p in ipairs(pts) do same(ns(i - 1), p, "natural spline through node " .. i) end
near(ns:deriv(0, 2).x, 0, 1e-9, "natural: C''(0) = 0"); near(ns:deriv(4, 2).y, 0, 1e-9, "natural: C''(end) = 0")
same(ns:deriv(2 - 1e-9, 2), ns:deriv(2 + 1e-9, 2), "C2 at a joint", 1e-5)
local cl = cubic_spline(pts, {u = {0, 1, 2, 3, 4}, ends = "clamped", d0 = V(1, 0), d1 = V(1, 0)})
same(cl:deriv(0), V(1, 0), "clamped start"); same(cl:deriv(4), V(1, 0), "clamped end")

-- interpolation through nodes at given parameters
local ip = interpolate({P(0, 0), P(1, 1), P(2, 0), P(3, 2)}, {0, .2, .7, 1})
same(ip(.2), P(1, 1), "interpolates node 2"); same(ip(.7), P(2, 0), "interpolates node 3")
eq(ip.degree, 3, "degree n - 1")

-- a Lua function as a curve: numbers or points, any dimension
local f = curve(function(t) return cos(t), sin(t) end, 0, pi)
same(f(pi / 2), P(0, 1), "function curve"); near(f:length(), pi, 1e-6, "half circle length")
same(f:tangent(pi / 2), V(-1, 0), "differenced tangent", 1e-6)
local f3 = curve(function(t) return P(cos(t), sin(t), t) end, 0, 2 * pi)
eq(f3.dim, 3, "3-D function curve")

-- 3-D and rational curves keep their dimension and weights; maps apply exactly
local b3 = bezier{P(0, 0, 0), P(1, 0, 1), P(1, 1, 2)}
same(b3(1), P(1, 1, 2), "3-D Bezier")
local m = map.translate(V(1, 2))
local moved = m(b)
same(moved(.4), b(.4) + V(1, 2), "f(curve) = curve of images")
same(b:map(m)(.9), b(.9) + V(1, 2), "c:map(f)")

-- flatten: the polyline lies within tol of the curve; a hyperbola breaks at infinity
local polys = b:flatten(.001)
eq(#polys, 1, "one piece")
for _, p in ipairs(polys[1]) do
  -- every vertex is on the curve: the nearest sample is within the tolerance
  local best = math.huge
  for t = 0, 1, .0001 do best = math.min(best, dist(p, b(t))) end
  truthy(best < .001, "vertex on the curve")
end
local hyp = bezier{P(1, 0), P(0, 0) * -1 + V(0, 0), P(0, 1)}   -- weight -1 in the middle
local branches = hyp:flatten(.01)
eq(#branches, 2, "the rational quadratic with a negative weight has two branches")

-- drawing: a path of connected pixels, never a trail of dots
screen(12)
cls()
bezier{P(100, 400), P(200, 100), P(400, 100), P(500, 400)}:draw{color = 14}
eq(point(100, 400), 14, "the path starts at the first control point")
eq(point(500, 400), 14, "and ends at the last")
-- connected: every ink pixel of the path has an ink neighbour (8-connectivity)
local lonely = 0
for yy = 150, 400 do
  for xx = 100, 500 do
    if point(xx, yy) == 14 then
      local n = 0
      for dy = -1, 1 do for dx = -1, 1 do
        if (dx ~= 0 or dy ~= 0) and point(xx + dx, yy + dy) == 14 then n = n + 1 end
      end end
      if n == 0 then lonely = lonely + 1 end
    end
  end
end
eq(lonely, 0, "no isolated pixels: the curve is one connected path")
cls()
plot(function(t) return 320 + 200 * cos(t), 240 + 200 * sin(t) end, {t = {0, 2 * pi}, color = 12})
eq(point(520, 240), 12, "plot draws a path through (520, 240)")
eq(point(320, 40), 12, "and (320, 40)")
cls()
plot(function(t) return 320 + 100 * t, 240 end, {t = {0, 1, .25}, dots = true, color = 9})
eq(point(345, 240), 9, "dots on request: a dot at t = .25"); eq(point(330, 240), 0, "nothing between")

-- the camera: 3-D curves and points drawn through a projection
camera(map.orthographic("z"))
cls()
bezier{P(100, 100, 5), P(300, 100, -5)}:draw{color = 10}
eq(point(200, 100), 10, "a 3-D segment through the camera")
pset(P(50, 60, 7), 11)
eq(point(50, 60), 11, "pset of a 3-D point")
line(P(10, 10, 0), P(20, 10, 100), 13)
eq(point(15, 10), 13, "line of 3-D points")
camera(nil)
err(function() pset(P(1, 2, 3)) end, "2-D", "no camera: a 3-D point is an error")
err(function() bezier{P(0, 0, 0), P(1, 1, 1)}:draw() end, "needs a projection", "3-D curve without a camera")

-- 3-D values handed to 2-D-only functions are errors, not silently flattened
err(function() plot(function(t) return P(t, t, t) end, {t = {0, 1, .5}, dots = true}) end,
    "3-D", "plot of a 3-D function without a projection")

-- errors ---------------------------------------------------------------------------------------
err(function() bezier{P(0, 0)} end, "bezier: argument #1 (points) must hold 2 to 65 points, got 1", "one control point")
err(function() bezier(3) end, "bezier: argument #1 (points)", "not a table")
err(function() bezier{P(0, 0), 5} end, "bezier: argument #1 (points) [2] must be a point, got 5", "not a point")
err(function() bezier{P(0, 0), P(1, 1, 1)} end, "bezier: argument #1 (points) [2] is 3-D, but [1] is 2-D (mixed dimensions)", "mixed dimensions")
err(function() bspline({A, B, C}, 3) end, "degree", "degree too high")
err(function() bspline({A, B, C}, 1.5) end, "an integer", "fractional degree")
err(function() bspline({A, B, C}, 2, {0, 1, 0, 1, 2, 3}) end, "non-decreasing", "decreasing knots")
err(function() bspline({A, B, C}, 2, {0, 0, 1}) end, "knots", "wrong knot count")
err(function() bspline({A, B, C}, 2, "sideways") end, "argument #3 (knots)", "bad knot kind")
err(function() hermite({A, B}, {V(1, 0)}) end, "hermite: argument #2 (tangents) must hold 2 vectors, got 1", "tangent count")
err(function() hermite({A, B}, {V(1, 0), P(1, 0)}) end, "hermite: argument #2 (tangents) [2] must be a 2-D vector, got P(1, 0); a vector has weight 0: a difference of points is a vector, e.g. B - A", "a point as a tangent")
err(function() cubic_spline({A, B}, {ends = "loose"}) end, "cubic_spline: option 'ends' must be \"natural\", \"clamped\" or \"periodic\", got \"loose\"", "bad ends")
err(function() cubic_spline({A, B}, {ends = "clamped"}) end, "cubic_spline: clamped ends need the end derivatives d0 and d1 (vectors)", "clamped without d0")
err(function() interpolate({A, B, C}, {0, .5, .5}) end, "interpolate", "repeated parameter")
err(function() hermite({A, B}, {V(1, 0), V(1, 0)}, {u = {0, 0}}) end,
    "hermite: option 'u' must increase, but [2] = 0 follows [1] = 0", "hermite's parameters increase")
err(function() cubic_spline({A, B, C}, {u = {0, 2, 1}}) end,
    "cubic_spline: option 'u' must increase, but [3] = 1 follows [2] = 2", "cubic_spline's parameters increase")
err(function() cubic_spline({A, B, C}, {u = {0, 1}}) end,
    "cubic_spline: option 'u' must hold 3 numbers (one per point), got 2", "one parameter per point")
eq(interpolate({A, B, C}, {0, 2, 1}).t1, 2, "interpolation takes distinct parameters in any order")
err(function() curve(5, 0, 1) end, "argument #1 (f)", "not a function")
err(function() curve(function(t) return t, t end, 1, 0) end, "t1", "empty domain")
err(function() b(0 / 0) end, "finite", "NaN parameter")
err(function() b:split(1) end, "inside the domain", "split at the end")
err(function() b:insert_knot(.5) end, "not a B-spline", "insert into a Bezier")
err(function() f3:flatten() end, "needs a map", "flatten 3-D without a map")
err(function() curve(function(t) error("boom") end, 0, 1) end, "boom", "an error in f")
local bad = curve(function(t) if t > .5 then error("late boom") end return t, t end, 0, 1)
err(function() bad:length() end, "late boom", "an error inside the core's loop reaches the script")

check.done()
