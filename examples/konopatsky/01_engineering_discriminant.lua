-- Konopatsky §2.1.6 (Fig. 2.21): conic arcs by the engineering discriminant
-- Triangle ABC, A(0,0), B(4,0), C(2,3), with the median CT1; the arcs (2.97) for k = 0.3
-- (hyperbola, red), 0.5 (parabola, yellow) and 0.7 (ellipse, green), each through its shoulder
-- point K = (T1 - C)k + C on the median.  The scheme of the current point at u = 0.2 for
-- k = 0.7 (conic.ed_scheme): T on AB, N its harmonic conjugate with respect to A, B, P = AK x CT,
-- Q = BK x CT, and M = KN x BP = AQ x BP on the arc.
local A, B, C = P(0, 0), P(4, 0), P(2, 3)
local k, u = 0.7, 0.2
local s = conic.ed_scheme(A, B, C, k, u)
fit{around = {A, B, C, s.N}, pad = 0.4}
path({A, C, B, A}, {color = 8})
line(s.N, A, 8)                          -- AB extended to N
pen{dash = {4, 3}} line(C, s.T1, 8) pen()
local colors = {[0.3] = 12, [0.5] = 14, [0.7] = 10}
for _, kk in ipairs{0.3, 0.5, 0.7} do
  local arc = conic.ed(A, B, C, kk)
  arc:draw{color = colors[kk]}
  mark(arc(0.5), "dot", 4, colors[kk])
  label(string.format("$k = %.1f$", kk), arc(0.78), nil, colors[kk])
end
pen{dash = {2, 2}}
line(C, s.T, 7) line(A, s.Q, 7) line(B, s.P, 7) line(s.N, s.K, 7)
line(A, s.K, 11) line(B, s.K, 11)
pen()
for _, p in ipairs{A, B, C, s.T1, s.T, s.N} do mark(p, "dot", 5, 15) end
for _, p in ipairs{s.P, s.Q} do mark(p, "dot", 5, 11) end
mark(s.M, "dot", 6, 14)
label("$A$", A) label("$B$", B) label("$C$", C) label("$T_1$", s.T1) label("$T$", s.T)
label("$N$", s.N) label("$K$", s.K, nil, 10) label("$P$", s.P, nil, 11) label("$Q$", s.Q, nil, 11)
label("$M$", s.M, nil, 14)
caption(string.format("k = %.1f, u = %.1f:  M = (%.6f, %.6f)", k, u, s.M.x, s.M.y), "bottom", 7)
