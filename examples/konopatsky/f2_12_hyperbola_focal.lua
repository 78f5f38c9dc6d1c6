-- Konopatsky §2.1.2.3 (Fig. 2.12): the hyperbola by the focal angle at F1, (2.56)
-- Set H: C(0,0), A(3,0), B(0,2).  The angle phi is measured at F1 = (A - C)e + C from the
-- direction C -> A; the focal radius rho = |F1M| = p/(1 - e cos phi), p = b^2/a.  The branch
-- through A (green) is phi in (arcsin(b/c), 2 pi - arcsin(b/c)), phi = pi giving A; the book's
-- printed range (yellow) gives rho < 0, the other branch through 2C - A (digest §5.2).  The
-- current point M at phi = 1.2 and its focal radius.
local C, A, B = P(0, 0), P(3, 0), P(0, 2)
local F1, F2, e, p = conic.foci(C, A, B, "hyperbola")
local near = conic.hyperbola{C = C, A = A, B = B, by = "focal"}
local far = conic.hyperbola{C = C, A = A, B = B, by = "focal", branch = 2}
local phi = 1.2
local M = near(phi)
fit{around = {P(-5, -3), P(5, 3)}, pad = 0.2}
line(P(-7, 0), P(7, 0), 8)
pen{dash = {4, 3}} line(P(-7, -14 / 3), P(7, 14 / 3), 8) line(P(-7, 14 / 3), P(7, -14 / 3), 8) pen()
near:draw{color = 10}
far:draw{color = 14}
line(F1, M, 15)
angle_mark(F1 + (A - C), F1, M, "$\\varphi$", 26, 11)
for _, q in ipairs{A, C, F2} do mark(q, "dot", 5, 15) end
mark(F1, "dot", 5, 11) mark(M, "dot", 5, 15)
label("$C$", C) label("$A$", A) label("$F_2$", F2) label("$F_1$", F1, nil, 11)
label("$M$", M) label("$\\rho$", lerp(F1, M, 0.5))
caption(string.format("phi = 1.2:  rho = %.6f = p/(1 - e cos phi) = %.6f", dist(F1, M),
  p / (1 - e * math.cos(phi))), "bottom", 7)
