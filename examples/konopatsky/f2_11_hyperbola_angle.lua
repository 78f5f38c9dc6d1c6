-- Konopatsky §2.1.2.1 (Fig. 2.11): the hyperbola by the central angle, (2.49)
-- Set H of the digest: C(0,0), A(3,0), B(0,2), c = sqrt 13.  M at the central angle phi = 0.5
-- from CA, rho = |CM| = ab/sqrt(b^2 cos^2 phi - a^2 sin^2 phi); the focal radii with
-- |F2M| - |F1M| = 2a; the asymptotes (dashed) at arcsin(b/c), where rho is infinite and the
-- curve passes through its points at infinity: phi in (-arcsin(b/c), arcsin(b/c)) is the branch
-- through A, around pi the other (branch = 2).
local C, A, B = P(0, 0), P(3, 0), P(0, 2)
local F1, F2 = conic.foci(C, A, B, "hyperbola")
local h = conic.hyperbola{C = C, A = A, B = B, by = "angle"}
local phi = 0.5
local M = h(phi)
fit{around = {P(-6, -3.2), P(6, 3.2)}, pad = 0.2}
line(P(-7, 0), P(7, 0), 8) line(P(0, -4), P(0, 4), 8)
pen{dash = {4, 3}} line(P(-7, -14 / 3), P(7, 14 / 3), 7) line(P(-7, 14 / 3), P(7, -14 / 3), 7) pen()
path({P(3, 2), P(-3, 2), P(-3, -2), P(3, -2), P(3, 2)}, {color = 8})
h:draw{color = 15}
conic.hyperbola{C = C, A = A, B = B, by = "angle", branch = 2}:draw{color = 15}
line(C, M, 10)
pen{dash = {2, 3}} line(F1, M, 7) line(F2, M, 7) pen()
angle_mark(A, C, M, "$\\varphi$", 44, 11)
for _, p in ipairs{C, A, B, F1, F2} do mark(p, "dot", 5, 15) end
mark(M, "dot", 5, 14)
label("$C$", C) label("$A$", A) label("$B$", B) label("$F_1$", F1) label("$F_2$", F2)
label("$M$", M, nil, 14) label("$\\rho$", lerp(C, M, 0.7), nil, 10)
caption(string.format("rho = %.6f,  |F2M| - |F1M| = %.6f = 2a", dist(C, M), dist(F2, M) - dist(F1, M)), "bottom", 7)
