-- Konopatsky §3.5 (Fig. 3.8): the closed curve of scheme 2, two arcs run in opposite directions
-- Simplex A(0,0), B(10,0), C(4,6) (the digest's defaults; the book prints none) and row 1 of Table
-- 3.2: P the arc (2.97) of k_P = 0.8 run from B to A (red), Q the arc of k_Q = 0.5 from C to B
-- with its tangents meeting at A (the printed Q's u^2 and u'^2 exchanged) (blue); M = P u' + Q u
-- (green, oneratio.closed) runs from B back to B, with a corner at B.  The segment PQ and its
-- point M at u = 0.3.
local A, B, C, kP, kQ, u = P(0, 0), P(10, 0), P(4, 6), 0.8, 0.5, 0.3
local arcP, arcQ = conic.ed(A, B, C, kP), conic.ed(C, B, A, kQ)
local M = oneratio.closed(A, B, C, kP, kQ, 2)
local Pu, Qu = arcP(1 - u), arcQ(u)
fit{around = {A, B, C}, pad = 0.6}
path({A, C, B, A}, {color = 8})
arcP:draw{color = 12} arcQ:draw{color = 9}
M:draw{color = 10}
line(Pu, Qu, 7)
for _, p in ipairs{A, B, C} do mark(p, "dot", 5, 15) end
mark(Pu, "dot", 5, 12) mark(Qu, "dot", 5, 9) mark(M(u), "dot", 5, 10)
label("$A$", A) label("$B$", B) label("$C$", C)
label("$P$", Pu, nil, 12) label("$Q$", Qu, nil, 9) label("$M$", M(u), nil, 10)
caption(string.format("scheme 2: k_P = %g, k_Q = %g;  M(0.3) = (%.6f, %.6f),  PM/PQ = %.2f", kP, kQ,
  M(u).x, M(u).y, dist(Pu, M(u)) / dist(Pu, Qu)), "bottom", 7)
