-- Example 2 (animated) — The oval drawn by the bilinear map of a quadrilateral, moving
-- Two points A and B run in step along the opposite sides P0P1 and P3P2 (s1 = (1 + cos u)/2)
-- and a third, X, runs along the moving segment AB a quarter period later (s2 = (1 + sin u)/2),
-- u = 2 pi t: the kinematic reading of example 2.  t is a slider {animate = true}; see
-- docs/live.md for the live page and the frames.

local t = slider("t", 0, 1, .35, {animate = true})
local P0, P1, P2, P3 = P(100, 100), P(300, 150), P(280, 200), P(150, 300)
path({P0, P1, P2, P3}, {closed = true, color = 7})
local function parts(s)
  local u = 2 * math.pi * s
  local s1, s2 = (1 + math.cos(u)) / 2, (1 + math.sin(u)) / 2
  local A, B = lerp(P0, P1, s1), lerp(P3, P2, s1)
  return A, B, lerp(A, B, s2)
end
if t > 0 then plot(function(s) local _, _, X = parts(s); return X end, {t = {0, t, .001}, color = 14}) end
local A, B, X = parts(t)
line(A, B, 10)
circle(A, 3, 10); label("A", A, "ne", 10)
circle(B, 3, 10); label("B", B, "sw", 10)
circle(X, 4, 12)
label("X", X, "e", 12)
for i, q in ipairs{P0, P1, P2, P3} do label("P" .. (i - 1), q, ({"nw", "ne", "se", "sw"})[i], 7) end
label(string.format("t = %.3f", t), P(200, 440), "c", 15)
