-- Example 18 — Smooth junction of two parametric curves (a cubic graph and an ellipse arc)
-- Two curves A(t1), B(t1) span the ruled curvilinear system C(t1, t2) = A(t1) + t2 (B(t1) - A(t1)),
-- in which they are the coordinate lines t2 = 0 and t2 = 1; the graph t2 = g(t1) of a smoothstep
-- then joins them smoothly.  A is the arc x in [-1.2, 1.3] of the cubic y = x^3 - x - 1, B the
-- lower half of the ellipse x = cos u, y = 1 + .5 sin u, u from pi to 2 pi.
-- Green (thick): the whole cubic (x from -2 to 2, leaving the screen) and the whole ellipse.
-- Blue: the 11 x 11 coordinate lines of the system between them.  Cyan (thick): the junction
-- t2 = g(t1), g the n = 2 half-spline 2t^2 / 1 - 2(1 - t)^2 (example 7), tangent to the cubic
-- at (-1.2, -1.528) and to the ellipse at (1, 1).  Scale 100, origin (320, 240), y up.
-- The article's prose misprints the system as y_c = g1 + t2 (g2 - g1) with "t^2 = g(t1)"; the
-- listing (and this script) use t2 = g(t1).  Its junction loop runs t1 to 1.01, slightly past
-- the ellipse, as printed.

screen(12)
local pi, cos, sin = math.pi, math.cos, math.sin
local screen_ = screenmap(320, 240, 100)

local function cubic(x) return P(x, x^3 - x - 1) end
local function ellipse(u) return P(cos(u), 1 + .5*sin(u)) end

plot(cubic,   {t = {-2, 2, .001},       qb = true, brush = "dot", color = 2, map = screen_})
plot(ellipse, {t = {0, 2*pi, pi/500},   qb = true, brush = "dot", color = 2, map = screen_})

local A = function(t1) return cubic(-1.2 + 2.5*t1) end
local B = function(t1) return ellipse(pi + pi*t1) end
local C = ruled(A, B):post(screen_)

local lines = {0, 1.01, .1, fine = {0, 1, .01}}
C:grid{t1 = lines, t2 = lines, qb = true, color = 1}

local g = smooth.power(2)
C:draw(function(t1) return t1, g(t1) end, {t = {0, 1.01, .001}, qb = true, brush = "dot", color = 3})
