-- Konopatsky §2.1.1.1-2.1.1.2 (Fig. 2.4): the construction of the ellipse by the central angle (2.11) and radius (2.15)
-- Set E of the digest: C(0,0), A(4,0), B(0,2), so a = 4, b = 2, c = 2 sqrt 3; the foci
-- F1 = (A - C)e + C and F2 (conic.foci).  The current point M at the central angle phi = pi/6
-- from CA, its radius rho = |CM| = ab/sqrt(a^2 sin^2 phi + b^2 cos^2 phi), and the focal radii
-- F1M, F2M with |F1M| + |F2M| = 2a, the law of cosines of (2.6)-(2.10).
local C, A, B = P(0, 0), P(4, 0), P(0, 2)
local F1, F2, e = conic.foci(C, A, B)
local el = conic.ellipse{C = C, A = A, B = B, by = "angle"}
local phi = math.pi / 6
local M = el(phi)
fit{around = {P(-4, -2), P(4, 2)}, pad = 0.6}
line(P(-4.6, 0), P(4.6, 0), 8) line(P(0, -2.5), P(0, 2.5), 8)
el:draw{color = 15}
line(C, M, 10)
pen{dash = {4, 3}} line(F1, M, 7) line(F2, M, 7) pen()
angle_mark(A, C, M, "$\\varphi$", 40, 11)
for _, p in ipairs{C, A, B, F1, F2} do mark(p, "dot", 5, 15) end
mark(M, "dot", 5, 14)
label("$C$", C) label("$A$", A) label("$B$", B) label("$F_1$", F1) label("$F_2$", F2)
label("$M$", M, nil, 14) label("$\\rho$", lerp(C, M, 0.6), nil, 10)
caption(string.format("rho = %.6f,  |F1M| + |F2M| = %.6f = 2a,  e = %.6f", dist(C, M),
  dist(F1, M) + dist(F2, M), e), "bottom", 7)
