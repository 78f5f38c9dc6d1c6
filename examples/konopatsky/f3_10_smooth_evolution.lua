-- Konopatsky §3.6 (Fig. 3.10): the evolution of the contour arcs of smoothness order n = 1..5
-- A(0,0), B(10,0) and the tangents' meet C(4,6) (chosen): M1 (the quadratic Bezier) to M5 in
-- five colours; the higher the order, the flatter the arc at its ends (zero curvature for
-- n >= 2).  Each M_n is the general law M_n = (A - C)t'^(n+1)/D_n + (B - C)t^(n+1)/D_n + C,
-- D_n = t'^n + t'^(n-1) t + ... + t^n (the digest's, which gives the book's M2..M5), written
-- as a point equation over a param and compiled.
-- equal units on the 4:3 canvas around the figure's points, pad world units on every side
local function frame(pts, pad)
  local x0, y0, x1, y1 = math.huge, math.huge, -math.huge, -math.huge
  for _, p in ipairs(pts) do
    x0, x1, y0, y1 = math.min(x0, p.x), math.max(x1, p.x), math.min(y0, p.y), math.max(y1, p.y)
  end
  local cx, cy, h = (x0 + x1) / 2, (y0 + y1) / 2, math.max((x1 - x0) * 3 / 4, y1 - y0) / 2 + pad
  window(cx - h * 4 / 3, cy - h, cx + h * 4 / 3, cy + h)
end
local A, B, C = P(0, 0), P(10, 0), P(4, 6)
frame({A, B, C}, 0.6)
path({A, C, B}, {color = 8})
local colors = {15, 14, 10, 11, 13}
local tp = param "t"
for n = 1, 5 do
  local D = 0
  for k = 0, n do D = D + bar(tp)^k * tp^(n - k) end
  local M = curve((A - C)*(bar(tp)^(n + 1)/D) + (B - C)*(tp^(n + 1)/D) + C, 0, 1)
  M:draw{color = colors[n]}
  label("$M_" .. n .. "$", M(0.62 + 0.06 * n), nil, colors[n])
end
for _, p in ipairs{A, B, C} do mark(p, "dot", 5, 15) end
label("$A$", A) label("$B$", B) label("$C$", C)
