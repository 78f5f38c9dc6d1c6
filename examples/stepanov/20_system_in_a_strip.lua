-- Example 20 — Curvilinear system concentrated in a strip between two graphs
-- Example 19's system y = f(x) + t (g(x) - f(x)) blows up for large |t|.  Replacing t by a
-- "characteristic function" s(t), 0 for t <= 0 and 1 for t >= 1, keeps the whole system inside
-- the strip between f(x) = (x - e^(x - 1))/3 - 1 and g(x) = sin(5x)/2 + 3.  The listing's s is
-- the clamped smoothstep 0 / 2t^2 / 1 - 2(1 - t)^2 / 1 (smooth.clamp; the prose says s = t).
-- Circles x = r cos u, t = r sin u + .5, r = .1, .4, ..., 1.3, drawn in the system: the smallest
-- is an ellipse, the larger ones are pressed flat against the strip and take on its shape, the
-- sine ripple of g on top and f below.  Scale 50, origin (320, 300), y up.
-- Colour 0: the listing draws the boundary graphs and the grid (41 lines t = const, 32
-- verticals) in colour 0, the background, so only the five blue curves show.  This script keeps
-- that; 20v_colour8_grid.lua draws them in dark grey to show the strip.
-- The listing's IF chain uses strict inequalities, so at t exactly 0, .5 or 1 s keeps its last
-- value (C:clamp{qb = true}, one memory for the whole program): every circle starts at u = 0,
-- t = .5, and the first one inherits s = 1 from the grid, a stray dot on the upper boundary
-- (it lands where the largest circle is pressed against g, so it does not show).

screen(12)
local pi, cos, sin, exp = math.pi, math.cos, math.sin, math.exp
local f = function(x) return (x - exp(x - 1))/3 - 1 end
local g = function(x) return sin(5*x)/2 + 3 end
local strip = graphs(f, g):post(screenmap(320, 300, 50))
local C = strip:clamp{t2 = true, qb = true}          -- t -> s(t), the listing's IF chain
local hidden = tonumber((...)) or 0                  -- the listing's colour: the background (20v passes 8)

for _, t in ipairs{0, 1} do                          -- the boundary graphs f and g
  strip:draw(function(x) return x, t end, {t = {-3.2, 3.2, .01}, qb = true, brush = "dot", color = hidden})
end
C:grid{t1 = {-3.2, 3.2, .2, .01},                    -- verticals x = const
       t2 = {-.5, 1.501, .05, fine = {-.5, 1.5, .01}}, -- lines t = const, all inside the strip
       qb = true, color = hidden}

for r in qb.range(.1, 1.301, .3) do
  C:draw(function(u) return r*cos(u), r*sin(u) + .5 end,
         {t = {0, 2*pi, pi/1000}, qb = true, brush = "dot", color = 1})
end
