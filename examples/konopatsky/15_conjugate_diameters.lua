-- Konopatsky §2.1.1.5 (Fig. 2.8): the ellipse on conjugate diameters, variant 1 (2.32)
-- The centre C(0,0) and the ends A(3,0), B(1,2) of two conjugate semi-diameters (a skew pair,
-- chosen); P on CB and Q on NB with one ratio t, N = A + B - C, K = 2C - A; the rays KP and QA
-- meet at M on the quarter A -> B (green), drawn at t = 0.6; the whole ellipse (2.24) in grey.
local dot = mark
local function mark(p, name, _, c) dot(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end

fit{around = {P(-3.4, -2.9), P(4.6, 4.2)}}
local C, A, B = P(0, 0), P(3, 0), P(1, 2)
local N, K = A + B - C, C * 2 - A
path({K, A}, {color = 8}) path({C, B}, {color = 8})
path({A, N, B}, {color = 8})
conic.ellipse{C = C, A = A, B = B, by = "compression"}:draw{color = 7}
local quarter = conic.ellipse{C = C, A = A, B = B, by = "conjugate"}
quarter:draw{color = 10}
local t = 0.6
local Pp, Q = lerp(C, B, t), lerp(N, B, t)
local M = meet(K, Pp, Q, A)
pen{dash = {4, 3}}
line(K, M, 7) line(Q, A, 7)
pen()
mark(C, "$C$", "s") mark(A, "$A$", "se") mark(B, "$B$", "nw") mark(N, "$N$", "ne") mark(K, "$K$", "sw")
mark(Pp, "$P$", "w", 11) mark(Q, "$Q$", "n", 11) mark(M, "$M$", "ne", 14)
label(string.format("(2.32), t = CP/CB = NQ/NB = %.1f", t), P(-3.2, -2.6), "e", 7)
