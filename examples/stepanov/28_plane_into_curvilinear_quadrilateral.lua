-- Example 28 — Plane mapped into the curvilinear quadrilateral; its boundary as a pressed circle
-- The whole plane goes into the curvilinear quadrilateral of examples 24-25 in two steps: the
-- plane onto the open unit square, t = .5 p/sqrt(p^2 + 1) + .5 (example 26 rescaled, §H row 19,
-- `squash01`), then the square into the region by the patch of example 25 (§H row 18):
--   U0 = S0(t1), U2 = S2(1 - t1), g = G3 + t1 (G1 - G3), X = U0 + t2 (U2 - U0) + g perp(U2 - U0).
-- The image of a circle of radius 10 is pressed against the border (t in [.0025, .9975]), so the
-- white closed curve parametrises the boundary of the region, with slightly rounded corners.
-- Yellow rings of radius 5 mark the vertices A0..A3 (the listing draws A0 twice, from its 5th
-- DATA point; once gives the same picture).
-- 19 998 points, as QBasic runs `for ug = 0 to 2*pi step pi/10000` (qb = true).

local pi, cos, sin = math.pi, math.cos, math.sin
local A = {P(100, 100), P(300, 70), P(250, 400), P(150, 350)}
for i = 1, 4 do circle(A[i], 5, 14) end

local side = {                     -- the graphs of f0 .. f3 erected on the sides (example 24)
  graph_on(A[1], A[2], function(t) return (t^3 - t)/3 end, -1, 1),
  graph_on(A[2], A[3], function(t) return -(t + 1)*t*(t - 1)*(t - 2)/10 end, -1, 2),
  graph_on(A[3], A[4], function(t) return t*(t - 1)/4 end, 0, 1),
  graph_on(A[4], A[1], function(t) return (t^2 - 1)/10 end, -1, 1),
}
local C = patch(side[1], side[2], side[3], side[4]):pre(squash01)   -- plane -> square -> region

local rad = 10
C:draw(function(u) return rad*cos(u), rad*sin(u) end, {t = {0, 2*pi, pi/10000}, qb = true})
