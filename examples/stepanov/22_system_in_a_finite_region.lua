-- Example 22 — Curvilinear system in a finite region (part of a strip closed by two segments)
-- The region between the lower graph f(x) = -1 - x^2/10 over [-2.5, 2.5] and the upper graph
-- g(x) = 1 - x^6/(1 + x^6) - x^2/20 over [-2, 2], closed left and right by the segments joining
-- their ends.  Its system is the ruled system between the two graphs, both run by t1:
-- A(t1) = (x1, f(x1)), x1 = -2.5 + 5 t1;  B(t1) = (x2, g(x2)), x2 = -2 + 4 t1;
-- C(t1, t2) = A(t1) + t2 (B(t1) - A(t1)).
-- White: its 11 x 11 coordinate lines, filling a "bell" with a cabin-like bump on top.  White,
-- thick: circles of radius .1, ..., .7 about (t1, t2) = (.5, .5), drawn through the system
-- with both parameters clamped by the smoothstep s (0 / 2t^2 / 1 - 2(1 - t)^2 / 1), which keeps
-- them inside the region: the larger ones are pressed into its boundary.
-- Scale 100, origin (320, 240), y up.  The listing's strict IF chains keep s1, s2 at t exactly
-- 0, .5 or 1 (C:clamp{qb = true}): the first point takes s1 = 0, a stray dot on the left side,
-- hidden under the largest circle pressed against it.

screen(12)
local pi, cos, sin = math.pi, math.cos, math.sin
local f = function(x) return -1 - x^2/10 end
local g = function(x) return 1 - x^6/(x^6 + 1) - x^2/20 end
-- the points (x1, f(x1)) and (x2, g(x2)) of the two graphs, as coordinates (an inner loop)
local A = function(t1) local x1 = -2.5 + 5*t1; return x1, f(x1) end
local B = function(t1) local x2 = -2 + 4*t1; return x2, g(x2) end
local C = ruled(A, B):post(screenmap(320, 240, 100))

local lines = {0, 1.01, .1, fine = {0, 1, .001}}
C:grid{t1 = lines, t2 = lines, qb = true}

local S = C:clamp{qb = true}                         -- s1 = s(t1), s2 = s(t2)
for r in qb.range(.1, .71, .1) do
  S:draw(function(u) return r*sin(u) + 1/2, r*cos(u) + 1/2 end,
         {t = {0, 2*pi, pi/1000}, qb = true, brush = "dot"})
end
