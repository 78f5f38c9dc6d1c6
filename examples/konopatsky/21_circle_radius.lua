-- Konopatsky §2.1.8.3 (Fig. 2.27): the circle about C by an angle and the radius R, (2.118)
-- The book's points A(0;0), B(0,5;1), C(1;0) and R = 0.5: M at the angle phi = MCA (here
-- 0.8) from CA toward CB, its parameters p = S_MCB/S_ACB and q = S_ACM/S_ACB, and the aid T on
-- AC with TM parallel to CB (dashed): M = (A - C)p + (B - C)q + C, T = (A - C)p + C.
local function mark(p, name, _, c) circle(p, 0.012, c or 15) label(name, p, nil, c or 15) end
local A, B, C, R = P(0, 0), P(0.5, 1), P(1, 0), 0.5
window(-0.4, -0.6, 1.933, 1.15)
path({A, B, C, A}, {color = 8})
local circ = conic.circle{A = A, B = B, C = C, R = R}
circ:draw{color = 10}
local phi = 0.8
local M = circ(phi)
local S = simplex(C, A, B)
local p, q = S:params(M)
local T = (A - C) * p + C
line(C, M, 11)
pen{dash = {4, 3}} line(T, M, 7) pen()
mark(A, "$A$", "sw") mark(B, "$B$", "n") mark(C, "$C$", "se") mark(T, "$T$", "s", 11) mark(M, "$M$", "nw", 14)
label(string.format("R = %.1f  phi = %.1f  p = %.4f  q = %.4f", R, phi, p, q), P(-0.35, -0.53), "e", 7)
