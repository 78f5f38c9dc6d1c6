-- Example 5 — Smooth curve through two points with prescribed directions (cubic smoothstep)
-- Through A = P0 leaving along a and B = P1 arriving along b (screen angles u0 = 7 pi/15,
-- u1 = 0.9 pi, y down, so they turn clockwise on screen), the article's five-step rule
-- (§H block 7, `spline2`):
--   P = A + a,  Q = B - b,  M = A + t (P - A),  N = Q + t (B - Q),  X = M + g(t) (N - M)
-- with the cubic smoothstep g(t) = -2t^3 + 3t^2. The two cyan segments (colour 3) are the
-- prescribed directions, before A and after B. The green curve (colour 2, thick dots) is drawn
-- for t in [-1, 3] to show the curve's "general behaviour" outside [0, 1]: beyond B it curls
-- into a loop and leaves to the right, before A it leaves through the bottom-right corner.
-- Loop counts as in QBasic (qb = true): 101 dots per segment, 4001 on the curve.

screen(12)
local r = 100
local function e(u) return V(math.cos(u), math.sin(u)) end   -- screen angle u (y down)
local A, a = P(300, 200), e(7*math.pi/15)*r
local B, b = P(350, 400), e(.9*math.pi)*r

plot(function(t) return A + a*t end, {t = {-1, 0, .01}, qb = true, brush = "dot", color = 3})
plot(function(t) return B + b*t end, {t = {0, 1, .01}, qb = true, brush = "dot", color = 3})

spline2(A, a, B, b, smooth.cubic):draw{t = {-1, 3, .001}, qb = true, brush = "dot", color = 2}
