-- Example 2 — Oval inscribed in an arbitrary quadrilateral
-- A white quadrilateral P0 P1 P2 P3 and a white oval touching each of its sides once.
-- Two points oscillate in step on the opposite sides P0P1 and P3P2,
--   A = P0 + s1 (P1 - P0),  B = P3 + s1 (P2 - P3),  s1 = (1 + cos u)/2,
-- and a third oscillates on the moving segment AB a quarter period later,
--   X = A + s2 (B - A),     s2 = (1 + sin u)/2.
-- That is the bilinear map of the quadrilateral (§H block 3, derived in §4 of the article)
-- applied to the circle inscribed in the unit square, written here as one point equation in t
-- and compiled (docs/equations.md).
-- QBasic's `for t = 0 to 1 step .001` (1001 samples) is kept with qb = true.

screen(12)
local P0, P1, P2, P3 = P(100, 100), P(300, 150), P(280, 200), P(150, 300)
line(P0, P1); line(P1, P2); line(P2, P3); line(P3, P0)

local t = param "t"
local u = 2*math.pi*t
local s1, s2 = (1 + math.cos(u))/2, (1 + math.sin(u))/2   -- the circle in the unit square
local X = lerp(lerp(P0, P1, s1), lerp(P3, P2, s1), s2)   -- A + s2 (B - A)
plot(curve(X, 0, 1), {t = {0, 1, .001}, qb = true})
