-- Konopatsky §2.1.3.2 (Fig. 2.14): the parabolic arc through three points with an improper point, (2.59)-(2.62)
-- The parabola through A(0,0), C(1,3), B(4,0) with tC = 0.25: TC on AB, K on BC with AK parallel
-- to TC C, T on AB at t = 0.35, N with TN parallel to TC K, and M on NB; the axis direction
-- C_inf is that of CTC (red).
local dot = mark
local function mark(p, name, _, c) dot(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end

fit{around = {P(-1.4, -1.4), P(5.4, 6.3)}}
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
mark(A, "$A$", "sw") mark(B, "$B$", "se") mark(C, "$C$", "ne") mark(TC, "$T_C$", "s", 11) mark(K, "$K$", "n", 11)
mark(T, "$T$", "s", 11) mark(N, "$N$", "e", 11) mark(Mt, "$M$", "ne", 14)
label("(2.62) tC = 0.25, t = 0.35", P(-1, -1.2), "e", 7)
