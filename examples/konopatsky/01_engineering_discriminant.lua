-- Konopatsky §2.1.6 (Fig. 2.21): conic arcs by the engineering discriminant
-- Triangle ABC with the median CT1; the arcs (2.97) for k = 0.3 (hyperbola, red),
-- 0.5 (parabola, yellow) and 0.7 (ellipse, green), each through its shoulder point K on the
-- median; the construction of the current point at u = 0.4 for k = 0.7: T on AB, P = AK x CT,
-- Q = BK x CT, M = AQ x BP.
local A, B, C = P(0, 0), P(4, 0), P(2, 3)
local T1 = mid(A, B)
window(-0.6, -0.8, 4.6, 3.6)
path({A, C, B, A}, {color = 8})
pen{dash = {4, 3}}
line(C, T1, 8)
pen()
local colors = {[0.3] = 12, [0.5] = 14, [0.7] = 10}
for _, k in ipairs{0.3, 0.5, 0.7} do
  local arc = conic.ed(A, B, C, k)
  arc:draw{color = colors[k]}
  local K = arc(0.5)
  circle(K, 0.03, colors[k])
  label(string.format("k = %.1f", k), K, "e", colors[k])
end
-- the construction at u = 0.4 for k = 0.7
local k, u = 0.7, 0.4
local K = lerp(C, T1, k)
local T = lerp(A, B, u)
local Pp, Q = meet(A, K, C, T), meet(B, K, C, T)
local M = meet(A, Q, B, Pp)
pen{dash = {2, 2}}
line(C, T, 7) line(A, Q, 7) line(B, Pp, 7)
pen()
for name, p in pairs{A = A, B = B, C = C, T1 = T1, T = T, P = Pp, Q = Q, M = M} do
  circle(p, 0.03, 15)
end
label("A", A, nil, 15) label("B", B, nil, 15) label("C", C, nil, 15)
label("T1", T1, nil, 15) label("T", T, nil, 15) label("P", Pp, nil, 7)
label("Q", Q, nil, 7) label("M", M, nil, 15)
