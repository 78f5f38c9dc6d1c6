-- Konopatsky §2.1.3 (Figs. 2.13, 2.14): the parabola of one ratio and the parabola through three points
-- Left (2.57)-(2.58): the two-link Bernstein polyline A1 A3 A2 (A3 the middle vertex, where the
-- end tangents meet), B1 on A1A3 and B2 on A3A2 with one ratio t = 0.3, M on B1B2; the digest's
-- A1(0,0), A2(4,0), A3(2,4).  Right (2.59)-(2.62): the parabola through A(0,0), C(1,3), B(4,0)
-- with tC = 0.25: TC on AB, K on BC with AK parallel to TC C, T on AB at t = 0.35, N with TN
-- parallel to TC K, and M on NB; the axis direction C_inf is that of CTC (dashed arrow).
local function mark(p, name, _, c) circle(p, 0.05, c or 15) label(name, p, nil, c or 15) end

view(5, 40, 315, 440)
window(-0.6, -0.8, 4.6, 4.6)
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

view(325, 40, 635, 440)
window(-1.4, -1.4, 5.4, 6.3)
local A, C, B, tC = P(0, 0), P(1, 3), P(4, 0), 0.25
local arc = conic.parabola(A, C, B, tC)
arc:draw{color = 10}
local TC = lerp(A, B, tC)
local K = B * (-tC / (1 - tC)) + C * (1 / (1 - tC))      -- on BC with AK parallel to TC C
local tt = 0.35
local T = lerp(A, B, tt)
local N = (K - TC) * (tt / tC) + T                        -- (2.60): TN parallel to TC K
local Mt = N * (1 - tt) + B * tt                          -- (2.61)
path({A, B}, {color = 8}) path({B, K}, {color = 8})
pen{dash = {4, 3}}
line(TC, C, 7) line(A, K, 7) line(TC, K, 7) line(T, N, 7) line(N, B, 7)
pen()
local axis = C - TC
line(C, C - axis * 0.3, 12) label("$C_\\infty$", C - axis * 0.3, "e", 12)
mark(A, "$A$", "sw") mark(B, "$B$", "se") mark(C, "$C$", "ne") mark(TC, "TC", "s", 11) mark(K, "$K$", "n", 11)
mark(T, "$T$", "s", 11) mark(N, "$N$", "e", 11) mark(Mt, "$M$", "ne", 14)
label("(2.62) tC = 0.25, t = 0.35", P(-1, -1.2), "e", 7)
