-- Konopatsky §3.6 (Fig. 3.10): the evolution of the contour arcs of smoothness order n = 1..5
-- A(0,0), B(10,0) and the tangents' meet C(4,6) (chosen): M1 (the quadratic Bezier) to M5 in
-- five colours; the higher the order, the flatter the arc at its ends (zero curvature for
-- n >= 2).  Each M_n is the general law M_n = (A - C)t'^(n+1)/D_n + (B - C)t^(n+1)/D_n + C,
-- D_n = t'^n + t'^(n-1) t + ... + t^n (the digest's, which gives the book's M2..M5), written
-- as a point equation over a param and compiled.
local A, B, C = P(0, 0), P(10, 0), P(4, 6)
fit{around = {A, B, C}, pad = 0.6}
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
