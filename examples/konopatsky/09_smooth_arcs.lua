-- Konopatsky §3.6 (Fig. 3.9): the scheme of the contour arc of smoothness order 2
-- A(0,0), B(10,0) and the tangents' meet C(4,6) (chosen; the book prints none).  At t = 0.4
-- (oneratio.smooth_scheme): P1, P2 on AC and Q1, Q2 on CB with
-- AP1/AP2 = P1P2/P1C = CQ1/CQ2 = Q1Q2/Q1B = P2M/P2Q1 = t, and M on P2Q1 (yellow) on the arc
-- M2 = (A - C)t'^3/(1 - t't) + (B - C)t^3/(1 - t't) + C (green), flat at both ends, beside the
-- quadratic Bezier arc M1 (grey) of the same A, B, C.
local A, B, C, t = P(0, 0), P(10, 0), P(4, 6), 0.4
local s = oneratio.smooth_scheme(A, B, C, 2, t)
local P1, P2, Q1, Q2, M = s.P[1], s.P[2], s.Q[1], s.Q[2], s.M
fit{around = {A, B, C}, pad = 0.6}
path({A, C, B}, {color = 8})
oneratio.smooth(A, B, C, 1):draw{color = 7}
oneratio.smooth(A, B, C, 2):draw{color = 10}
pen{dash = {3, 2}} line(A, P2, 11) line(P1, C, 11) line(C, Q2, 11) line(Q1, B, 11) pen()
line(P2, Q1, 14)
for _, p in ipairs{A, B, C} do mark(p, "dot", 5, 15) end
for _, p in ipairs{P1, P2, Q1, Q2} do mark(p, "dot", 5, 11) end
mark(M, "dot", 6, 14)
label("$A$", A) label("$B$", B) label("$C$", C)
label("$P_1$", P1, nil, 11) label("$P_2$", P2, nil, 11)
label("$Q_1$", Q1, nil, 11) label("$Q_2$", Q2, nil, 11) label("$M$", M, nil, 14)
label("$M_2$", oneratio.smooth(A, B, C, 2)(0.75), nil, 10)
label("$M_1$", oneratio.smooth(A, B, C, 1)(0.75), nil, 7)
caption(string.format("t = %.1f:  P2M/P2Q1 = %.4f", t, dist(P2, M) / dist(P2, Q1)), "bottom", 7)
