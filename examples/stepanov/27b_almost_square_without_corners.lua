-- Example 27 (variant) — The "almost square" traced by the replacement loop the article recommends
-- Example 27 with the last loop replaced as the article recommends.  The images of the circles
-- r = .1, ..., 5 under the plane -> square map x = p/sqrt(p^2 + 1), y = q/sqrt(q^2 + 1)
-- (§H row 19) are as before; the circle r = 100, whose image is the almost square, is now traced
-- only over the four arcs between the corner directions u0 = -pi/4 + i pi/2, from u0 + .35 to
-- u0 + pi/2 - .7 with step pi/10000.  All but four radii of that circle run into the corners,
-- so skipping the corner directions loses nothing: about 6 600 points instead of 99 884 draw
-- the same square, solid toward the corners and dotted in the middles of the sides, where the
-- parametrisation runs fastest.
-- The limits +.35 / -.7 are asymmetric as printed (probably a slip for -.35; the only effect is
-- a small gap near one end of each side); kept.  Loops as QBasic runs them (qb = true).

local pi, cos, sin = math.pi, math.cos, math.sin
local C = curvilinear(squash):post(screenmap(320, 240, 200))   -- plane -> square -> screen
local function circle_of(r) return function(u) return r*cos(u), r*sin(u) end end

for r in qb.range(.1, 5, .1) do
  C:draw(circle_of(r), {t = {0, 2*pi, pi/50}, qb = true})
end
for i = 0, 3 do
  local u0 = -pi/4 + i*pi/2                                      -- a corner direction
  C:draw(circle_of(100), {t = {u0 + .35, u0 + pi/2 - .7, pi/10000}, qb = true})
end
