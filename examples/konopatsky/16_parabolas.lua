-- Konopatsky §2.1.3.1 (Fig. 2.13): the parabola of one ratio, (2.57)-(2.58)
-- The two-link Bernstein polyline A1 A3 A2 (A3 the middle vertex, where the end tangents meet),
-- B1 on A1A3 and B2 on A3A2 with one ratio t = 0.3, M on B1B2; the digest's A1(0,0), A2(4,0),
-- A3(2,4).
local dot = mark
local function mark(p, name, _, c) dot(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end

fit{around = {P(-0.6, -0.8), P(4.6, 4.6)}}
local A1, A2, A3 = P(0, 0), P(4, 0), P(2, 4)
path({A1, A3, A2}, {color = 8})
conic.parabola(A1, A3, A2):draw{color = 10}
local t = 0.3
local B1, B2 = lerp(A1, A3, t), lerp(A3, A2, t)
local M = lerp(B1, B2, t)
pen{dash = {4, 3}} line(B1, B2, 7) pen()
mark(A1, "$A_1$", "sw") mark(A2, "$A_2$", "se") mark(A3, "$A_3$", "n")
mark(B1, "$B_1$", "w", 11) mark(B2, "$B_2$", "e", 11) mark(M, "$M$", "s", 14)
label("(2.58) t = 0.3", P(-0.4, -0.5), "e", 7)
