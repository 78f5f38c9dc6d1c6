-- Konopatsky §3.7 (Figs. 3.11, 3.12): the Desargues configuration and the scheme of the Desargues arc
-- Left (Fig. 3.11, chosen points): triangles A1B1C1 and A2B2C2 in perspective from O; the meets
-- of corresponding sides X, Y, Z lie on the axis of perspectivity (red).  Right (Fig. 3.12), a
-- planar simplex A(0,0), C(1,5), B(9,5), D(10,0) (the book prints no numbers) at t = 0.3, from
-- oneratio.desargues_scheme: P, Q, K on AC, CB, BD with the one ratio t; T = AB x PQ and
-- S = CD x QK (Menelaus), R on TS, N on PQ and J on QK (the quadratic Beziers ACB and CBD),
-- M = SN x TJ on the arc (3.6) from A (tangent AC) to D (tangent BD), green.
local function mark(p, name, _, c, r) circle(p, r or 0.1, c or 15) label(name, p, nil, c or 15) end

view(5, 60, 260, 420)
window(-0.8, -1.6, 9.2, 12.5)
local O = P(0, 4)
local A1, B1, C1 = P(2, 6), P(2.5, 2.5), P(3.5, 4.5)
local f1, f2, f3 = 2.2, 1.3, 1.7
local A2, B2, C2 = lerp(O, A1, f1), lerp(O, B1, f2), lerp(O, C1, f3)
for _, p in ipairs{A2, B2, C2} do line(O, p, 8) end
path({A1, B1, C1, A1}, {color = 11}) path({A2, B2, C2, A2}, {color = 14})
local X, Y, Z = meet(A1, B1, A2, B2), meet(B1, C1, B2, C2), meet(C1, A1, C2, A2)
pen{dash = {4, 3}}
line(B1, X, 7) line(B2, X, 7) line(C1, Y, 7) line(C2, Y, 7) line(A1, Z, 7) line(A2, Z, 7)
pen()
line(X, Z, 12) line(Y, Z, 12) line(X, Y, 12)
mark(O, "$O$", "w") mark(A1, "$A_1$", "w", 11) mark(B1, "$B_1$", "e", 11) mark(C1, "$C_1$", "e", 11)
mark(A2, "$A_2$", "w", 14) mark(B2, "$B_2$", "e", 14) mark(C2, "$C_2$", "e", 14)
mark(X, "$X$", "s", 12) mark(Y, "$Y$", "s", 12) mark(Z, "$Z$", "s", 12)

view(270, 60, 635, 420)
window(-3.5, -2.5, 11, 8.5)
local A, B, C, D = P(0, 0), P(9, 5), P(1, 5), P(10, 0)
local t = 0.3
local s = oneratio.desargues_scheme(A, B, C, D, t)
local Pp, K = lerp(A, C, t), lerp(B, D, t)
path({A, C, B, D}, {color = 8})
oneratio.desargues(A, B, C, D):draw{color = 10}
pen{dash = {4, 3}}
line(s.T, B, 7) line(s.S, C, 7) line(s.T, s.Q, 11) line(K, s.S, 11) line(s.T, s.S, 13)
line(s.S, s.N, 7) line(s.T, s.J, 7)
pen()
mark(A, "$A$", "sw") mark(B, "$B$", "ne") mark(C, "$C$", "n") mark(D, "$D$", "se")
mark(Pp, "$P$", "w", 11) mark(s.Q, "$Q$", "n", 11) mark(K, "$K$", "e", 11)
mark(s.T, "$T$", "w", 13) mark(s.S, "$S$", "s", 13) mark(s.R, "$R$", "s", 13)
mark(s.N, "$N$", "nw", 12) mark(s.J, "$J$", "ne", 12) mark(s.M, "$M$", "s", 14)
label("t = AP/AC = CQ/CB = BK/BD = 0.3", P(-3.3, -2.1), "e", 7)
