-- Example 4 — Smooth junction of two lines in general position
-- Example 3 moved into an arbitrary quadrilateral P0 P1 P2 P3 (white): the sine smoothstep
-- (t, g(t)) of the unit square, g(t) = (1 - cos pi t)/2, is carried by the bilinear map
--   xa = P0 + t (P1 - P0),  xb = P3 + t (P2 - P3),  X = xa + g(t) (xb - xa)
-- (§H blocks 3 and 4). The result (cyan thick dots) leaves P0 along P0P1 and arrives at P2
-- along P3P2, so it joins the line P1P0 (ray beyond P0) to the line P3P2 (ray beyond P2),
-- both drawn in cyan for t in [-1, 0] on their sides.
-- Loop counts as in QBasic: 101 dots per ray, 1001 on the junction (qb = true).

screen(12)
local P0, P1, P2, P3 = P(200, 100), P(400, 150), P(380, 300), P(250, 400)
line(P0, P1); line(P1, P2); line(P2, P3); line(P3, P0)

-- Rays and junction are point equations in t, compiled (docs/equations.md).
local t = param "t"
plot(curve(lerp(P0, P1, t), -1, 0), {t = {-1, 0, .01}, qb = true, brush = "dot", color = 3})
plot(curve(lerp(P2, P3, t), -1, 0), {t = {-1, 0, .01}, qb = true, brush = "dot", color = 3})

local X = lerp(lerp(P0, P1, t), lerp(P3, P2, t), smooth.sine(t))   -- xa + g(t) (xb - xa)
plot(curve(X, 0, 1), {t = {0, 1, .001}, qb = true, brush = "dot", color = 3})
