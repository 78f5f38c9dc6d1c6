-- Konopatsky §4.9 (Fig. 4.5): the interpolation arc through three points with one tangent
-- Chosen nodes M1(0,0), M2(4.5,2), M3(9,0) and the start handle C2(1,3): the cubic through the
-- nodes with the start tangent M1C2 (red, dashed) only (interp.arc(M, C2)).
local M = {P(0, 0), P(4.5, 2), P(9, 0)}
local C2 = P(1, 3)
fit{around = {P(-1, -1), P(10, 3.5)}}
pen{dash = {4, 3}} line(M[1], C2, 12) pen()
interp.arc(M, C2):draw{color = 10}
for j, p in ipairs(M) do mark(p, "dot", 5, 15) label("$M_" .. j .. "$", p) end
mark(C2, "dot", 5, 12) label("$C_2$", C2, nil, 12)
