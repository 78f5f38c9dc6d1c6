-- Konopatsky §2.1.1 (Fig. 2.2): the ellipse, its foci and the focal radii of a point
-- Set E of the digest (a = 4, b = 2): the centre C, the vertices A1, A2 on the major axis and B1,
-- B2 on the minor, the foci F1, F2 at c = sqrt(a^2 - b^2) from C (conic.foci), a current point M
-- (phi = 2.2 by (2.24)) and its focal radii with |F1M| + |F2M| = 2a (2.1).
local C, A, B = P(0, 0), P(4, 0), P(0, 2)
local F1, F2, e = conic.foci(C, A, B)
local el = conic.ellipse{C = C, A = A, B = B, by = "compression"}
local M = el(2.2)
local A1, A2, B1, B2 = A, 2 * C - A, B, 2 * C - B
fit{around = {A1, A2, B1, B2}, pad = 0.6}
line(A2 - V(0.5, 0), A1 + V(0.5, 0), 8) line(B2 - V(0, 0.5), B1 + V(0, 0.5), 8)
el:draw{color = 15}
line(F1, M, 11) line(F2, M, 11)
for _, p in ipairs{C, A1, A2, B1, B2, M} do mark(p, "dot", 5, 15) end
for _, p in ipairs{F1, F2} do mark(p, "dot", 5, 11) end
label("$C$", C) label("$A_1$", A1) label("$A_2$", A2) label("$B_1$", B1) label("$B_2$", B2)
label("$M$", M) label("$F_1$", F1, nil, 11) label("$F_2$", F2, nil, 11)
caption(string.format("|F1M| + |F2M| = %.6f = 2a,  e = c/a = %.6f", dist(F1, M) + dist(F2, M), e), "bottom", 7)
