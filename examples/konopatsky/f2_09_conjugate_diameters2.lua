-- Konopatsky §2.1.1.6 (Fig. 2.9): the ellipse on conjugate diameters, variant 2
-- The digest's K(-4,0), A(4,0), B(2, sqrt 3), lambda = 0.75 fixing C = (A - K)lambda + K; N on
-- KA (t = 0.85), L = B + N - C, the line NL parallel to BC meets BA at P and KB at Q, and
-- M = KP x QA runs the half ellipse K -> B -> A (green).
local dot = mark
local function mark(p, name, _, c) dot(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end

fit{around = {P(-4.8, -2.4), P(4.8, 4.2)}}
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
