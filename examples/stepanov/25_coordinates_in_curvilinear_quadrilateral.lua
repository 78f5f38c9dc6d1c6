-- Example 25 — Curvilinear coordinate system inside the curvilinear quadrilateral of example 24
-- The quadrilateral A0 A1 A2 A3 of example 24 (white chords) with a graph erected on each side
-- (yellow, example 23's affine frame on a segment, §H row 17), and inside it the coordinate
-- grid t1, t2 = 0, .1, ..., 1 of the patch built by the article's six-step algorithm (§H row 18):
--   U0 = S0(t1) on side 0,  U2 = S2(1 - t1) on side 2,
--   g  = G3 + t1 (G1 - G3)  (side 1 at t2 and side 3 at 1 - t2, blended),
--   X  = U0 + t2 (U2 - U0) + g perp(U2 - U0),  perp(x, y) = (y, -x).
-- At t1 = 0, 1 and t2 = 0, 1 the grid runs exactly along the four yellow sides.
-- Reconstructed: the article prints example 24's listing again under example 25, so the grid
-- follows the prose with example 28's formulas, as the cleaned listing ex25.bas does: 11 + 11
-- lines of 501 pixels in colour 15.  The sides use 1001 samples each instead of the listing's
-- 10 000: the thick stroke looks the same and renders faster (1% of its pixels differ).

local A = {P(100, 100), P(300, 70), P(250, 400), P(150, 350)}
for i = 1, 4 do line(A[i], A[i % 4 + 1]) end

-- f0 .. f3 on their intervals [a, b], erected on sides A0A1, A1A2, A2A3, A3A0
local side = {
  graph_on(A[1], A[2], function(t) return (t^3 - t)/3 end, -1, 1),
  graph_on(A[2], A[3], function(t) return -(t + 1)*t*(t - 1)*(t - 2)/10 end, -1, 2),
  graph_on(A[3], A[4], function(t) return t*(t - 1)/4 end, 0, 1),
  graph_on(A[4], A[1], function(t) return (t^2 - 1)/10 end, -1, 1),
}
for i = 1, 4 do plot(side[i], {t = {0, 1, .001}, qb = true, brush = "dot", color = 14}) end

local C = patch(side[1], side[2], side[3], side[4])
local lines = {0, 1.01, .1, fine = {0, 1, .002}}   -- t = 0, .1, ..., 1; 501 samples along each
C:grid{t1 = lines, t2 = lines, qb = true}
