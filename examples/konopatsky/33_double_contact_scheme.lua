-- Konopatsky §3.4 (Fig. 3.5): the scheme of a curve of double contact
-- Simplex A(0,0), B(10,0), C(4,6) (chosen): the first-generation arcs P (k_p = 0.3) and
-- Q (k_q = 0.7) of (2.97) share the tangents CA, CB; at v = 0.45 the segment PQ carries
-- M = P(1 - f(v)) + Q f(v) with f(v) = v (the linear case), and M runs the second-generation
-- curve (green) with the same end tangents.
local function mark(p, name, _, c) circle(p, 0.1, c or 15) label(name, p, nil, c or 15) end
local A, B, C = P(0, 0), P(10, 0), P(4, 6)
window(-1, -1.5, 11, 7.5)
path({A, C, B}, {color = 8}) line(A, B, 8)
local Pc, Qc = conic.ed(A, B, C, 0.3), conic.ed(A, B, C, 0.7)
Pc:draw{color = 12} Qc:draw{color = 12}
local M = oneratio.double_contact(A, B, C, 0.3, 0.7)
M:draw{color = 10}
local v = 0.45
pen{dash = {4, 3}} line(Pc(v), Qc(v), 7) pen()
mark(A, "$A$", "sw") mark(B, "$B$", "se") mark(C, "$C$", "n")
mark(Pc(v), "$P$", "n", 12) mark(Qc(v), "$Q$", "s", 12) mark(M(v), "$M$", "e", 14)
label("kp = 0.3, kq = 0.7, f(v) = v, v = 0.45", P(-0.8, -1.1), "e", 7)
