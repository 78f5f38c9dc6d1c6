-- Konopatsky §2.1.5 (Fig. 2.16): the conic through five points by the hexagon A A1 A2 M A3 B
-- The inputs reconstructed in the digest from the book's Fig. 2.17 equations: A(0,0), B(1,0),
-- C(0.5,1), A1 = (A - C)p1 + C, A3 = (B - C)q3 + C, T2 = (A3 - A1)p2 + A1, A2 = (T2 - C)q2 + C
-- with p1 = p2 = 0.7, q2 = q3 = 0.8.  At t = 0.7: P = (A - C)t' + C, Q = A1A2 x BC,
-- R = AB x PQ (the Pascal line P Q R, red), M = RA2 x PA3; the conic (green, the corrected
-- (2.93), conic.five_points2).
local dot = mark
local function mark(p, name, _, c) dot(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end
local A, B, C = P(0, 0), P(1, 0), P(0.5, 1)
local p1, p2, q2, q3 = 0.7, 0.7, 0.8, 0.8
window(-0.2, -0.25, 1.6, 1.1)
path({A, C, B}, {color = 8}) line(A, B, 8)
local A1, A3 = (A - C) * p1 + C, (B - C) * q3 + C
local T2 = (A3 - A1) * p2 + A1
local A2 = (T2 - C) * q2 + C
local arc = conic.five_points2{C = C, A = A, B = B, p1 = p1, p2 = p2, q2 = q2, q3 = q3}
arc:draw{color = 10}
local t = 0.7
local Pp = (A - C) * (1 - t) + C
local Q = meet(A1, A2, B, C)
local R = meet(A, B, Pp, Q)
local M = meet(R, A2, Pp, A3)
path({A, A1, A2, M, A3, B, A}, {color = 7})          -- the hexagon
line(T2, C, 8) line(A1, A3, 8)
pen{dash = {4, 3}}
line(Pp, R, 12) line(B, R, 8) line(A1, Q, 7) line(R, A2, 7) line(Pp, A3, 7)
pen()
mark(A, "$A$", "sw") mark(B, "$B$", "s") mark(C, "$C$", "n") mark(A1, "$A_1$", "w") mark(A2, "$A_2$", "s")
mark(A3, "$A_3$", "e") mark(T2, "$T_2$", "ne", 7) mark(Pp, "$P$", "w", 12) mark(Q, "$Q$", "e", 12)
mark(R, "$R$", "s", 12) mark(M, "$M$", "n", 14)
