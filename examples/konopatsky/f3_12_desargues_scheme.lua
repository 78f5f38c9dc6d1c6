-- Konopatsky §3.7 (Fig. 3.12): the scheme of the Desargues arc (3.6)
-- A planar simplex A(0,0), C(1,5), B(9,5), D(10,0) (the book prints no numbers) at t = 0.3,
-- from oneratio.desargues_scheme: P, Q, K on AC, CB, BD with the one ratio t; T = AB x PQ and
-- S = CD x QK (Menelaus), R on TS, N on PQ and J on QK (the quadratic Beziers ACB and CBD),
-- M = SN x TJ on the arc (3.6) from A (tangent AC) to D (tangent BD), green.
local dot = mark
local function mark(p, name, _, c) dot(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end

fit{around = {P(-3.5, -2.5), P(11, 8.5)}}
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
