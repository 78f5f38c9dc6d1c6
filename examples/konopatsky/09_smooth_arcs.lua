-- Konopatsky §3.6 (Figs. 3.9, 3.10): contour arcs of smoothness order n = 1..5
-- A(0,0), B(10,0) and the tangents' meet C(4,6): M1 (the quadratic Bezier) to M5 in five
-- colours; the higher the order, the flatter the arc at its ends (zero curvature for n >= 2).
-- The scheme of M2 at t = 0.4: P2 on AC, Q1 on CB and M on P2Q1.  Each M_n is the general law
-- M_n = (A - C) t̄^(n+1)/D_n + (B - C) t^(n+1)/D_n + C, D_n = t̄^n + t̄^(n-1) t + ... + t^n
-- (the digest's, which gives the book's M2..M5), written as a point equation and compiled.
local A, B, C = P(0, 0), P(10, 0), P(4, 6)
window(-1, -1.5, 11, 7.5)
path({A, C, B}, {color = 8})
local colors = {15, 14, 10, 11, 13}
local tp = param "t"
for n = 1, 5 do
  local D = 0
  for k = 0, n do D = D + bar(tp)^k * tp^(n - k) end
  local M = curve((A - C)*(bar(tp)^(n + 1)/D) + (B - C)*(tp^(n + 1)/D) + C, 0, 1)
  M:draw{color = colors[n]}
  label("M" .. n, M(0.5), "e", colors[n])
end
local t, tb = 0.4, 0.6
local d = 1 - tb * t
local P2 = (A * tb * tb + C * t) / d
local Q1 = (B * t * t + C * tb) / d
pen{dash = {3, 2}}
line(P2, Q1, 7)
pen()
circle(P2, 0.08, 7) circle(Q1, 0.08, 7) circle(lerp(P2, Q1, t), 0.08, 14)
label("P2", P2, nil, 7) label("Q1", Q1, nil, 7)
label("A", A, nil, 15) label("B", B, nil, 15) label("C", C, nil, 15)
