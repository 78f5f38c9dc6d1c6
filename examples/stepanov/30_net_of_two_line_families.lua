-- Example 30 — Coordinate system from two families of lines (intersection by bisection)
-- A net of two curve families defines coordinates implicitly: the point (t1, t2) is where the
-- cubic y = x^3 + t1 meets the line y = -x - t2.  Its x solves u(x) = x^3 + x + c = 0,
-- c = t1 + t2; u increases, so the one root lies between -c and 0 and bisection finds it
-- (to .001, as the listing; §H row 21).  Scale 100 about (320, 240), y up.
-- White pixels: the 17 cubics t1 = -2, -1.75, ..., 2 and the 17 lines t2 = const, each over
-- the other parameter's range [-2, 2]: a twisted, sheared mesh.  Thick dots: the images of the
-- circles r = .1, .4, ..., 2.5 of the (t1, t2) plane, nested ovals tilted along the mesh.
-- Loops as QBasic runs them (qb = true: 401 samples per grid line, 200 per circle).

local pi, cos, sin = math.pi, math.cos, math.sin
local C = curvilinear(function(t1, t2)
  local c = t1 + t2
  local x = bisect(function(x) return x^3 + x + c end, -c, 0, .001)
  return x, x^3 + t1
end):post(screenmap(320, 240, 100))

local lines = {-2, 2.01, .25, fine = {-2, 2, .01}}
C:grid{t1 = lines, t2 = lines, qb = true}
for r in qb.range(.1, 2.51, .3) do
  C:draw(function(u) return r*cos(u), r*sin(u) end, {t = {0, 2*pi, pi/100}, qb = true, brush = "dot"})
end
