-- Konopatsky §2.1.7 (Fig. 2.22): the conic in Ceva's parametrisation (2.104)
-- The digest's A1(0,0), A2(4,0), A3(2,3): the pencils at A1 and A2, the tangents A1A3, A2A3.
-- The fifth point K (on the k = 1 arc at t = 1/2) fixes k = v31/v23 (2.100) through
-- K1 = A1K x A2A3 and K2 = A2K x A3A1.  The current point M (t = 0.7) and its cevians: M1 on
-- A2A3, M2 on A3A1, M3 on A1A2.  Arcs for k = 1/4 (the parabola, yellow) and k = 1 (green);
-- the k = 1/4 arc's point at t = 2/3 halves the median A3M3 (the book's t3 = 1/2).
local function mark(p, name, _, c) circle(p, 0.04, c or 15) label(name, p, nil, c or 15) end
local A1, A2, A3 = P(0, 0), P(4, 0), P(2, 3)
window(-0.8, -1.0, 4.8, 3.4)
path({A1, A3, A2, A1}, {color = 8})
local par, ell = conic.ceva(A1, A2, A3, 0.25), conic.ceva(A1, A2, A3, 1)
par:draw{color = 14} ell:draw{color = 10}
local K = ell(0.5)
local K1, K2 = meet(A1, K, A2, A3), meet(A2, K, A3, A1)
local k = conic.ceva_k(A1, A2, A3, K)
local M = ell(0.7)
local M1, M2, M3 = meet(A1, M, A2, A3), meet(A2, M, A3, A1), meet(A3, M, A1, A2)
pen{dash = {4, 3}}
line(A1, K1, 8) line(A2, K2, 8)
line(A1, M1, 7) line(A2, M2, 7) line(A3, M3, 7)
pen()
local H = par(2 / 3)
mark(A1, "$A_1$", "sw") mark(A2, "$A_2$", "se") mark(A3, "$A_3$", "n")
mark(K, "$K$", "s", 11) mark(K1, "$K_1$", "e", 11) mark(K2, "$K_2$", "w", 11)
mark(M1, "$M_1$", "e", 13) mark(M2, "$M_2$", "w", 13) mark(M3, "$M_3$", "s", 13) mark(M, "$M$", "nw", 14)
mark(H, "", "n", 14)
label(string.format("k = v31/v23 = %.4f from K;  k = 1/4: parabola", k), P(-0.7, -0.7), "e", 7)
