-- Konopatsky §3.3 (Fig. 3.4): the cubic Bezier curve by the de Casteljau scheme of one ratio
-- A(0,0), B(10,0) and the tangent points C1(2,5), C2(8,5) (the digest's defaults): at t = 0.4
-- the levels of (3.4) from oneratio.levels, P1 on AC1, P2 on C1C2, P3 on C2B (the print's
-- P3 = (C2 - B)t + C2 has the wrong sign), Q1 on P1P2, Q2 on P2P3 and M on Q1Q2; the curve
-- M = A t'^3 + 3 C1 t'^2 t + 3 C2 t' t^2 + B t^3 (corrected powers) in green.
local function mark(p, name, _, c) circle(p, 0.08, c or 15) label(name, p, nil, c or 15) end
local A, C1, C2, B = P(0, 0), P(2, 5), P(8, 5), P(10, 0)
window(-1, -1.5, 11, 6.5)
path({A, C1, C2, B}, {color = 8})
oneratio.bezier3(A, C1, C2, B):draw{color = 10}
local lv = oneratio.levels({A, C1, C2, B}, 0.4)
local P1, P2, P3 = lv[1][1], lv[1][2], lv[1][3]
local Q1, Q2, M = lv[2][1], lv[2][2], lv[3][1]
pen{dash = {4, 3}} path({P1, P2, P3}, {color = 11}) line(Q1, Q2, 13) pen()
mark(A, "$A$", "sw") mark(B, "$B$", "se") mark(C1, "$C_1$", "n") mark(C2, "$C_2$", "n")
mark(P1, "$P_1$", "w", 11) mark(P2, "$P_2$", "n", 11) mark(P3, "$P_3$", "e", 11)
mark(Q1, "$Q_1$", "nw", 13) mark(Q2, "$Q_2$", "ne", 13) mark(M, "$M$", "s", 14)
label("AP1/AC1 = C1P2/C1C2 = C2P3/C2B = P1Q1/P1P2 = P2Q2/P2P3 = Q1M/Q1Q2 = 0.4", P(-0.9, -1.1), "e", 7)
