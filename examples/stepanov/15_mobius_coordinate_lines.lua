-- Example 15 — Coordinate lines of a Möbius (Poincaré-disc) coordinate system
-- The polar grid of the unit disc carried by the Möbius map w = e^(i phi)(z - z0)/(1 - conj(z0) z),
-- z0 = r0 e^(i u0) with r0 = 1/2, u0 = pi/4, phi = 0: a motion of the Lobachevsky plane in the
-- Poincaré model.  The white absolute (radius 200 at (320, 240)), the images of the concentric
-- circles |z| = 0, .05, ..., .90 (Euclidean circles crowding towards w = -z0, lower left) and,
-- dotted, of the 20 radii arg z = k pi/10: arcs through -z0 orthogonal to the absolute.  In the
-- Lobachevsky plane these are a "hyperbolic polar grid" centred at -z0.
-- The coordinate system is (r, u) -> M(r cos u, r sin u), seen on the screen with y up and
-- scale 200.  Loop counts as in QBasic: the circle loop never reaches r = .95 (19 circles), each
-- circle has 400 points and each radius 100 (r = 0 .. .99).

screen(12)
local pi, cos, sin = math.pi, math.cos, math.sin
circle(320, 240, 200)                                -- the absolute

local M = mobius(complex.polar(1/2, pi/4))           -- phi = 0
local C = curvilinear(function(r, u) return M(r*cos(u), r*sin(u)) end)
  :post(screenmap(320, 240, 200))

C:grid{t1 = {0, .95, .05, fine = {0, .99, .01}},     -- circles r = const; radii traced to .99
       t2 = {0, 2*pi, pi/10, pi/200},                -- radii u = const; circles traced by pi/200
       qb = true}
