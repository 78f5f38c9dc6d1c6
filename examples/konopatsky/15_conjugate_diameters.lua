-- Konopatsky §2.1.1.5-2.1.1.6 (Figs. 2.8, 2.9): the ellipse on conjugate diameters
-- Left, variant 1 (2.32): the centre C and the ends A, B of two conjugate semi-diameters (a
-- skew pair, chosen); P on CB and Q on NB with one ratio t, N = A + B - C, K = 2C - A; the rays
-- KP and QA meet at M on the quarter A -> B (green), drawn at t = 0.6.  Right, variant 2: the
-- digest's K(-4,0), A(4,0), B(2, sqrt 3), lambda = 0.75 fixing C = (A - K)lambda + K; N on KA
-- (t = 0.85), L = B + N - C, the line NL parallel to BC meets BA at P and KB at Q, and
-- M = KP x QA runs the half ellipse K -> B -> A.
local function mark(p, name, _, c) circle(p, 0.06, c or 15) label(name, p, nil, c or 15) end

view(5, 30, 315, 470)
window(-3.4, -2.9, 4.6, 4.2)
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

view(325, 30, 635, 470)
window(-4.8, -2.4, 4.8, 4.2)
local K2, A2, B2, lam = P(-4, 0), P(4, 0), P(2, math.sqrt(3)), 0.75
local C2 = lerp(K2, A2, lam)
path({K2, A2}, {color = 8}) path({K2, B2, A2}, {color = 8}) line(C2, B2, 8)
local half = conic.ellipse{by = "diameter", K = K2, A = A2, B = B2, lambda = lam}
half:draw{color = 10}
local t2 = 0.85
local N2 = lerp(K2, A2, t2)
local L2 = B2 + N2 - C2
local P2, Q2 = meet(N2, L2, B2, A2), meet(N2, L2, K2, B2)
local M2 = meet(K2, P2, Q2, A2)
pen{dash = {4, 3}}
line(N2, P2, 7) line(K2, P2, 7) line(Q2, A2, 7) line(C2, L2, 8) line(B2, L2, 8)
pen()
mark(K2, "$K$", "sw") mark(A2, "$A$", "se") mark(B2, "$B$", "ne") mark(C2, "$C$", "s")
mark(N2, "$N$", "s", 11) mark(L2, "$L$", "e", 11) mark(P2, "$P$", "ne", 11) mark(Q2, "$Q$", "nw", 11)
mark(M2, "$M$", "n", 14)
label(string.format("KC/KA = %.2f, KN/KA = %.2f", lam, t2), P(-4.7, -1.6), "e", 7)
