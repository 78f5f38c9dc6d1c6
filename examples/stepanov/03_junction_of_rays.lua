-- Example 3 — Smooth junction of two rays parallel to the x axis
-- The rays y = a, x <= c and y = b, x >= d (white) leave the opposite corners of the rectangle
-- c <= x <= d, b <= y <= a (filled cyan, colour 3). A curve drawn with the listings' thick dot
-- joins them, horizontal at both ends: x = c + t (d - c), y = a + g(t) (b - a) with the sine
-- smoothstep g(t) = (1 + sin(pi t - pi/2))/2 = (1 - cos pi t)/2, g(0) = 0, g(1) = 1,
-- g'(0) = g'(1) = 0 (§H block 4, `smooth.sine`).
-- The second ray is drawn to x = 640 as printed (clipped at the edge); 1001 samples, as QBasic.

screen(12)
local a, b, c, d = 400, 100, 200, 300
local A, B = P(c, a), P(d, b)                -- where the curve leaves ray 1 and meets ray 2
line(A, B, 3, "bf")
line(A, P(0, a))                             -- first ray
line(B, P(640, b))                           -- second ray

local t = param "t"                          -- the junction as a compiled point equation
plot(curve(P(lerp(c, d, t), lerp(a, b, smooth.sine(t))), 0, 1),
     {t = {0, 1, .001}, qb = true, brush = "dot"})
