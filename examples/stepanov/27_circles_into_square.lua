-- Example 27 — Growing concentric circles mapped into the square; the "almost square"
-- A circle growing in the plane, carried into the square by the map of example 26
-- (x = p/sqrt(p^2 + 1), y = q/sqrt(q^2 + 1), §H row 19), presses ever more tightly against the
-- square's border.  White dots: the images of the circles r = .1, .2, ..., 5 (100 points each);
-- small ones stay round, large ones become rounded squares whose dots crowd into the corners.
-- The image of the circle r = 100 is the "almost square" (120, 40)-(520, 440): a smooth
-- parametrisation of the square that spends most of its points in the corners, so the middles
-- of the sides come out dashed.  Example 27b traces it with the loop the article recommends.
-- The circles are drawn through example 26's system, the plane seen in the square as a lens.
-- Loops as QBasic runs them (qb = true): 50 circles of 100 points, and 99 884 points.

local pi, cos, sin = math.pi, math.cos, math.sin
local C = curvilinear(squash):post(screenmap(320, 240, 200))   -- plane -> square -> screen
local function circle_of(r) return function(u) return r*cos(u), r*sin(u) end end

for r in qb.range(.1, 5, .1) do
  C:draw(circle_of(r), {t = {0, 2*pi, pi/50}, qb = true})
end
C:draw(circle_of(100), {t = {0, 2*pi, pi/50000}, qb = true})   -- the almost square
