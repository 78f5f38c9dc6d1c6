-- Example 16 — Gear wheel on the Lobachevsky plane
-- The 24 teeth of example 14 (outline only) built in the Möbius coordinates of example 15: the
-- white absolute and a gear between the images of the circles |z| = .9 and |z| = .7.  The teeth
-- are large in the upper right and shrink as they crowd against the absolute in the lower left.
-- A tooth flank joins the images of the two circles at the same angle u with the degree-5 power
-- half-spline k (example 7): X = W(.9, u) + k(t)(W(.7, u) - W(.9, u)), falling from .9 to .7,
-- then rising from .7 to .9 half a pitch later.  W(r, u) is the point with coordinates (r, u) of
-- example 15's system, taken straight to the screen: the screen map is affine, so the junction
-- can be formed there.  101 points per flank, as QBasic's loop runs.

screen(12)
local pi = math.pi
circle(320, 240, 200)                                -- the absolute

local M = mobius(complex.polar(1/2, pi/4))
local W = curvilinear(function(r, u) return M(r*math.cos(u), r*math.sin(u)) end)
  :post(screenmap(320, 240, 200))

local m, k = 24, smooth.power(5)
local t = {0, 1, .01, qb = true}
for i = 0, m do
  local ug = 2*pi*i/m
  plot(function(t) local u = ug + pi*t/m; return lerp(W(.9, u), W(.7, u), k(t)) end, {t = t})
  ug = ug + pi/m
  plot(function(t) local u = ug + pi*t/m; return lerp(W(.7, u), W(.9, u), k(t)) end, {t = t})
end
