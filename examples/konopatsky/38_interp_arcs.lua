-- Konopatsky §4.9 (Fig. 4.3): the interpolation contour arc through four nodes with two end tangents
-- The digest's nodes M = (0,0), (3,2), (6,2), (9,0) and the tangent handles C2 = (0,2),
-- C5 = (9,2): the quintic through the nodes at u = 0, 1/3, 2/3, 1 with M'(0) = 5(C2 - M1),
-- M'(1) = 5(M4 - C5) (interp.arc, green), beside the cubic through the same nodes without the
-- tangents (interp.lagrange, yellow, its control polygon grey).
local M = {P(0, 0), P(3, 2), P(6, 2), P(9, 0)}
local C2, C5 = P(0, 2), P(9, 2)
fit{around = {P(-1, -1.5), P(10, 3.5)}}
path(interp.controls(M), {color = 8})
interp.lagrange(M):draw{color = 14}
pen{dash = {4, 3}} line(M[1], C2, 12) line(M[4], C5, 12) pen()
interp.arc(M, C2, C5):draw{color = 10}
for j, p in ipairs(M) do mark(p, "dot", 5, 15) label("$M_" .. j .. "$", p) end
mark(C2, "dot", 5, 12) mark(C5, "dot", 5, 12)
label("$C_2$", C2, nil, 12) label("$C_5$", C5, nil, 12)
