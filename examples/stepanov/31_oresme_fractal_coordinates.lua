-- Example 31 — Fractal coordinate system from Oresme lambda-functions
-- The two pencils of straight lines reparametrised as x = f1(t1), y = f2(t2) with increasing
-- functions; with Oresme's lambda-functions (nowhere differentiable) the images of smooth curves
-- come out fractally broken.  Each function is tabulated on 2^12 cells (§H row 22):
--   y(0) = 1, y(2^12) = 2, y(j + s/2) = lambda y(j) + (1 - lambda) y(j + s), level by level,
-- with lambda = .3 for x and .2 for y, and looked up at INT(t 2^12) as the listing does.
-- Screen (120 + 400 (f1 - 1), 40 + 400 (f2 - 1)), with no y flip: the system fills the square
-- (120, 40)-(520, 440).  White pixels: the images of the circles r = .1, .2, ..., .5 about
-- (t1, t2) = (.5, .5): jagged staircase curves crowded toward the lower right (lambda < 1/2
-- pulls each midpoint toward the right-hand value), with a long spike toward the top.
-- 19 998 points per circle, as QBasic runs `for u = 0 to 2*pi step pi/10000` (qb = true).

local pi, cos, sin = math.pi, math.cos, math.sin
local f1, f2 = oresme(.3, 12, 1, 2), oresme(.2, 12, 1, 2)
local C = curvilinear(function(t1, t2) return 120 + 400*(f1(t1) - 1), 40 + 400*(f2(t2) - 1) end)

for r in qb.range(.1, .51, .1) do
  C:draw(function(u) return .5 + r*cos(u), .5 + r*sin(u) end, {t = {0, 2*pi, pi/10000}, qb = true})
end
