-- Curvilinear coordinate systems through Lua (docs/toolkit.md): curvilinear, bilinear (example
-- 2), ruled and graphs with the clamps (examples 18-22), graph_on and patch (examples 23-25, 28,
-- compared with example 28's own arithmetic), pre/post, grids and lenses as exact pixels.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near, err, truthy = check.eq, check.near, check.err, check.truthy
local pi, cos, sin = math.pi, math.cos, math.sin

local same = check.same_within(1e-9)             -- points/vectors equal within tol

-- curvilinear(f): points or numbers ------------------------------------------------------------------
local C = curvilinear(function(t1, t2) return P(t1 + t2, t1 - t2) end)
same(C(1, 2), P(3, -1), "C(t1, t2) is a point")
local x, y = C:xy(1, 2)
eq(x, 3, "C:xy x"); eq(y, -1, "C:xy y")
local Cn = curvilinear(function(t1, t2) return 10 * t1, 20 * t2 end)
same(Cn(.5, .5), P(5, 10), "a map returning numbers")
eq(curvilinear(C), C, "a system is its own system")
eq(tostring(C), "curvilinear system", "tostring")

-- bilinear: example 2 -----------------------------------------------------------------------------------
local P0, P1, P2, P3 = P(100, 100), P(300, 150), P(280, 200), P(150, 300)
local Q = bilinear(P0, P1, P2, P3)
same(Q(0, 0), P0, "corner (0, 0)"); same(Q(1, 0), P1, "corner (1, 0)")
same(Q(1, 1), P2, "corner (1, 1)"); same(Q(0, 1), P3, "corner (0, 1)")
same(Q(.5, .5), (P0 + P1 + P2 + P3) / 4, "the centre is the mean of the corners")
local s1, s2 = .3, .8
local Aq, Bq = P0 + (P1 - P0) * s1, P3 + (P2 - P3) * s1
same(Q(s1, s2), Aq + (Bq - Aq) * s2, "A on P0P1, B on P3P2, X on AB (example 2)")
same(bilinear(P(0, 0, 0), P(1, 0, 0), P(1, 1, 1), P(0, 1, 0))(.5, .5), P(.5, .5, .25), "3-D corners")

-- grid and lens: exact pixels ---------------------------------------------------------------------------
cls()
local R = curvilinear(function(t1, t2) return 100 + 100 * t1, 100 + 50 * t2 end)
R:grid{t1 = {0, 1, .5}, t2 = {0, 1, .5}, color = 8}
for _, p in ipairs({{100, 100}, {150, 100}, {200, 100}, {100, 125}, {100, 150}, {150, 137}, {173, 125}, {200, 150}}) do
  eq(point(p[1], p[2]), 8, "grid line pixel " .. p[1] .. "," .. p[2])
end
eq(point(125, 112), 0, "inside a grid cell: empty")
cls()
R:grid{t1 = {0, 1, .5}, t2 = {0, 1, .5}, color = 9, family = "t1"}
eq(point(150, 137), 9, "family t1: the line t1 = 1/2"); eq(point(173, 125), 0, "family t1: no line t2 = 1/2")
-- the other family over its own range, and QBasic-faithful counts
local hits = 0
R:grid{t1 = {0, 1, .5, fine = {0, .5, .25}}, t2 = {0, 1, .5, .5}, brush = function() hits = hits + 1 end}
eq(hits, 3 * 3 + 3 * 3, "fine = {0, .5, .25}: the lines t2 = const traced over t1 in [0, .5]")
hits = 0
R:grid{t1 = {0, 1, .5, .001}, t2 = {0, 1, .5, .001}, qb = true, brush = function() hits = hits + 1 end}
eq(hits, 2 * 3 * 1001, "qb = true: 1001 samples per line, as QBasic's FOR")
cls()
R:grid{t1 = {0, 1, 1, fine = {0, .5, .01}}, t2 = {0, 1, 1}, color = 13, family = "t2"}
eq(point(140, 100), 13, "fine range: the line t2 = 0 up to t1 = .5"); eq(point(155, 100), 0, "and no further")
cls()
-- lines are paths: a system that runs fast (x = 100 + 400 t1^6) still gives unbroken lines,
-- where dots at the same fine step fall apart
local fast = curvilinear(function(t1, t2) return 100 + 400 * t1 ^ 6, 300 + 100 * t2 end)
fast:grid{t1 = {0, 1, 1, .01}, t2 = {0, 1, 1, .01}, color = 12, family = "t2"}
local gaps = 0
for x = 100, 500 do if point(x, 300) ~= 12 then gaps = gaps + 1 end end
eq(gaps, 0, "the line t2 = 0 is unbroken from x = 100 to 500")
cls()
fast:grid{t1 = {0, 1, 1, .01}, t2 = {0, 1, 1, .01}, color = 12, family = "t2", dots = true}
gaps = 0
for x = 100, 500 do if point(x, 300) ~= 12 then gaps = gaps + 1 end end
truthy(gaps > 300, "dots = true: 101 dots, most of the line empty (" .. gaps .. " gaps)")
cls()
err(function() R:draw(function(t) return P(t, t, t) end, {t = {0, 1}}) end,
    "the curve must give the system's two parameters", "a 3-D curve through a 2-parameter system")
err(function() ruled(function(t) return P(t, 0, 1) end, function(t) return P(t, 1, 0) end)(.5, .5) end,
    "got the 3-D P(0.5, 0, 1)", "ruled between 3-D curves: not silently flattened")
-- a unit circle in (t1, t2) seen through R: an ellipse of radii 50, 25 around (150, 125)
R:draw(function(u) return .5 + .5 * cos(u), .5 + .5 * sin(u) end, {t = {0, 2 * pi, .001}, color = 10})
eq(point(200, 125), 10, "lens: right"); eq(point(150, 150), 10, "lens: bottom"); eq(point(100, 125), 10, "lens: left")
eq(point(150, 125), 0, "lens: centre empty")
R:draw(function(t) return P(t, 0) end, {t = {0, 1, .01}, color = 11})
eq(point(150, 100), 11, "lens: a curve returning points (t1, t2)")
-- a stroke drawn through a system (example 17's fish): the stroke's coordinates are (t1, t2)
local fishlike = stroke{nodes = {P(0, 0), P(1, 1)}, ein = {V(1, 0), V(0, 1)}}
cls()
R:draw(fishlike, {t = {0, 1, .01}, color = 12})
eq(point(100, 100), 12, "curve object through the lens: start"); eq(point(200, 150), 12, "end")

-- pre / post ---------------------------------------------------------------------------------------------
local Rk = R:pre(function(t1, t2) return 2 * t1, 2 * t2 end)   -- a homothety (example 17)
same(Rk(.25, .25), R(.5, .5), "pre: C(g(t1, t2))")
local Rs = R:post(function(x, y) return x + 1, y end)
same(Rs(0, 0), P(101, 100), "post: h(C(t1, t2))")
local S01 = R:pre(squash01)
same(S01(0, 0), R(.5, .5), "pre(squash01): the plane into the unit square")
local scr = screenmap(320, 240, 100)
local sx, sy = scr(1, 1)
eq(sx, 420, "screenmap x"); eq(sy, 140, "screenmap y (y up)")
local sx2, sy2 = screenmap(320, 300, 50, 25)(P(2, 2))
eq(sx2, 420, "screenmap of a point, x"); eq(sy2, 250, "screenmap b")
-- as a draw map it is called with numbers (no point per sample): the same pixels either way
screen(12)
plot(function(t) return t, t * t end, {t = {0, 1, .25}, map = scr, color = 5})
plot(function(t) return P(t, -t) end, {t = {0, 1, .25}, map = scr, color = 6})
for _, t in ipairs{.25, .5, .75, 1} do      -- (t = 0 is the origin of both)
  eq(point(320 + 100 * t, 240 - 100 * t * t), 5, "plot through screenmap, t = " .. t)
  eq(point(320 + 100 * t, 240 + 100 * t), 6, "plot of points through screenmap, t = " .. t)
end

-- ruled, graphs and the clamps: examples 18-22 ------------------------------------------------------------
-- example 18: A(t1) = (v1, v1^3 - v1 - 1), B(t1) = (cos u, 1 + .5 sin u)
local E18 = ruled(function(t1) local v = -1.2 + 2.5 * t1 return v, v ^ 3 - v - 1 end,
                  function(t1) local u = pi + pi * t1 return P(cos(u), 1 + .5 * sin(u)) end)
same(E18(0, 0), P(-1.2, -1.2 ^ 3 + 1.2 - 1), "t2 = 0: the cubic")
same(E18(1, 1), P(1, 1), "t2 = 1: the ellipse at (1, 1)")
local v1, u = -1.2 + 2.5 * .3, pi + pi * .3
local w1, v2, w2 = v1 ^ 3 - v1 - 1, cos(u), 1 + .5 * sin(u)
same(E18(.3, .6), P(v1 + .6 * (v2 - v1), w1 + .6 * (w2 - w1)), "C = A + t2 (B - A), the listing's p, q")
-- example 19: the system between the graphs of f and g
local f = function(x) return (x - math.exp(x - 1)) / 3 end
local g = function(x) return sin(5 * x) / 2 + 2 end
local E19 = graphs(f, g)
same(E19(.7, 0), P(.7, f(.7)), "graphs: t = 0 on f"); same(E19(.7, 1), P(.7, g(.7)), "t = 1 on g")
same(E19(.7, -1.5), P(.7, f(.7) - 1.5 * (g(.7) - f(.7))), "t outside [0, 1] extrapolates")
-- example 20: the clamped system stays in the strip
local E20 = graphs(f, g):clamp{t2 = true}
same(E20(.7, -1.5), P(.7, f(.7)), "clamped: below the strip -> on f")
same(E20(.7, 2), P(.7, g(.7)), "clamped: above -> on g")
same(E20(.7, .25), P(.7, f(.7) + .125 * (g(.7) - f(.7))), "clamped: s(.25) = .125")
local q20 = graphs(f, g):clamp{t2 = true, qb = true}
same(q20(.7, .5), P(.7, f(.7)), "qb: the first t = 1/2 keeps s = 0 (example 20's stray dot)")
same(q20(.7, .25), P(.7, f(.7) + .125 * (g(.7) - f(.7))), "qb: elsewhere the clamp")
same(q20(.7, .5), P(.7, f(.7) + .125 * (g(.7) - f(.7))), "qb: then t = 1/2 keeps the previous s")
-- example 22: two clamps
local E22 = ruled(function(t) local x = -2.5 + 5 * t return x, -1 - x ^ 2 / 10 end,
                  function(t) local x = -2 + 4 * t return x, 1 - x ^ 6 / (x ^ 6 + 1) - x ^ 2 / 20 end)
local B22 = E22:clamp()
same(B22(-3, 7), E22(0, 1), "both clamped: (0, 1) corner"); same(B22(.75, .25), E22(.875, .125), "s1, s2")

-- graph_on and patch: examples 23-25, 28 ---------------------------------------------------------------------
local G23 = graph_on(P(320, 240), P(480, 200), function(t) return t ^ 3 - t end, -1, 1)
same(G23(0), P(320, 240), "graph on a segment: starts at A"); same(G23(1), P(480, 200), "ends at B")
-- the listing's frame: x = x0 + t1 (x1 - x0) + t2 (x3 - x0), x3 = x0 + (y1 - y0), y3 = y0 - (x1 - x0)
local t1, t = .3, -1 + 2 * .3
local t2 = t ^ 3 - t
same(G23(.3), P(320 + t1 * 160 + t2 * (320 + (200 - 240) - 320), 240 + t1 * -40 + t2 * (240 - 160 - 240)), "example 23 frame")
local QX, QY = {100, 300, 250, 150, 100}, {100, 70, 400, 350, 100}
local A = {}
for i = 1, 5 do A[i] = P(QX[i], QY[i]) end
local Sd = {
  graph_on(A[1], A[2], function(t) return (t - 1) * t * (t + 1) / 3 end, -1, 1),
  graph_on(A[2], A[3], function(t) return -(t + 1) * t * (t - 1) * (t - 2) / 10 end, -1, 2),
  graph_on(A[3], A[4], function(t) return t * (t - 1) / 4 end),
  graph_on(A[4], A[5], function(t) return (t ^ 2 - 1) / 10 end, -1, 1),
}
local Pt = patch(Sd[1], Sd[2], Sd[3], Sd[4])
local function listing28(t1, t2)
  local x, y = QX, QY
  local x3, y3 = x[1] + (y[2] - y[1]), y[1] - (x[2] - x[1])
  local t = -1 + 2 * t1
  local g = (t - 1) * t * (t + 1) / 3
  local u0, v0 = x[1] + t1 * (x[2] - x[1]) + g * (x3 - x[1]), y[1] + t1 * (y[2] - y[1]) + g * (y3 - y[1])
  x3, y3 = x[3] + (y[4] - y[3]), y[3] - (x[4] - x[3])
  t = 1 - t1
  g = t * (t - 1) / 4
  local u2, v2 = x[3] + (1 - t1) * (x[4] - x[3]) + g * (x3 - x[3]), y[3] + (1 - t1) * (y[4] - y[3]) + g * (y3 - y[3])
  local uu, vv = u0 + (v2 - v0), v0 - (u2 - u0)
  t = -1 + 2 * (1 - t2)
  local g1 = -(t ^ 2 - 1) / 10
  t = -1 + 3 * t2
  local g3 = -(t + 1) * t * (t - 1) * (t - 2) / 10
  g = g1 + t1 * (g3 - g1)
  return P(u0 + t2 * (u2 - u0) + g * (uu - u0), v0 + t2 * (v2 - v0) + g * (vv - v0))
end
for a = 0, 1, .25 do
  for b = 0, 1, .2 do same(Pt(a, b), listing28(a, b), string.format("patch = example 28 at (%g, %g)", a, b), 1e-9) end
end
for s = 0, 1, .1 do
  same(Pt(s, 0), Sd[1](s), "side 0"); same(Pt(1, s), Sd[2](s), "side 1")
  same(Pt(s, 1), Sd[3](1 - s), "side 2 reversed"); same(Pt(0, s), Sd[4](1 - s), "side 3 reversed")
end
-- sides that are any functions (points or x, y) give the same patch as graph_on's curves, which
-- patch evaluates through their numeric form
local Sx = {}
for i = 1, 4 do Sx[i] = function(t) local p = Sd[i](t) return p.x, p.y end end
local Px = patch(function(t) return Sd[1](t) end, Sx[2], function(t) return Sd[3](t) end, Sx[4])
for a = 0, 1, .25 do
  for b = 0, 1, .2 do same(Px(a, b), Pt(a, b), string.format("patch of plain functions at (%g, %g)", a, b)) end
end
-- example 28: the plane into the patch; a circle of radius 10 presses against the boundary
local Ppl = Pt:pre(squash01)
same(Ppl(0, 0), Pt(.5, .5), "the origin to the centre")
same(Ppl(1e9, 0), Pt(1, .5), "far right to side 1", 1e-6)

-- errors ---------------------------------------------------------------------------------------------------
err(function() curvilinear(5) end, "curvilinear: argument #1 (f) must be a function (t1, t2) -> point or x, y, got 5", "not a map")
err(function() R:grid{t1 = {0, 1, .1}} end, "C:grid: t2 must be a range {a, b, step [, fine step]}, got nil", "grid t2")
err(function() R:grid{t1 = {0, 1, .1}, t2 = {0, 1, .1}, family = "x"} end, 'C:grid: family must be "t1", "t2" or nil (both), got string', "family")
err(function() R:grid{t1 = {0, 1, .1, fine = 3}, t2 = {0, 1, .1}} end, "C:grid: t1.fine must be a range {a, b, step}, got 3", "fine")
err(function() R:grid(3) end, "C:grid: argument #1 (opts) must be a table", "grid opts")
err(function() R:draw(function(t) return t, t end) end, "C:draw: give the parameter range t = {a, b, step}", "draw without t")
err(function() R:pre(1) end, "C:pre: argument #1 (g) must be a function", "pre")
err(function() ruled(1, 2) end, "ruled: argument #1 (A) must be a curve (a function of t1), got 1", "ruled")
err(function() graph_on(P(0, 0), P(1, 0), 3) end, "graph_on: argument #3 (f) must be a function, got 3", "graph_on f")
err(function() graph_on(P(1, 2), P(1, 2), math.sin) end, "graph_on: argument #2 (B) must be a point other than A (AB is the graph's axis), got P(1, 2)", "graph_on A = B")
err(function() graph_on(P(0, 0, 0), P(1, 0), math.sin) end, "graph_on: argument #1 (A) must be a 2-D point", "graph_on 3-D")
err(function() patch(Sd[1], Sd[2], Sd[3]) end, "patch: argument #4 (S3) must be a curve (a function of t in [0, 1]), got nil", "patch sides")
err(function() patch(Sd[1], function() return P(0, 0) end, Sd[3], Sd[4]) end, "patch: side S1 starts and ends at the same point", "patch degenerate")
err(function() curvilinear(function() return "x" end)(0, 0) end, "a map or curve must return a 2-D point or two numbers, got string", "bad map result")
err(function() screenmap("a", 1, 1) end, "screenmap: argument #1 (x0) must be a number, got string", "screenmap")
check.done()
