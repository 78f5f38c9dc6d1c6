-- Konopatsky §2.1.1.3 (Fig. 2.6): the ellipse by the focal angle at F2, (2.16)-(2.18)
-- Set E: C(0,0), A(4,0), B(0,2), F2 = -(A - C)e + C.  The current point M at the angle
-- phi = pi/3 measured at F2 from the direction F2 -> A, rho = |F2M| = p/(1 - e cos phi); the
-- simplex A B F2 (dashed) in which (2.16) writes M = (A - F2) p_A + (B - F2) p_B + F2
-- (conic.focal_point, the first term's missing factor p restored).
local C, A, B = P(0, 0), P(4, 0), P(0, 2)
local F1, F2, e, p = conic.foci(C, A, B)
local phi = math.pi / 3
local M, F, pa, pb = conic.focal_point(C, A, B, phi)
fit{around = {P(-4, -2), P(4, 2)}, pad = 0.6}
line(P(-4.6, 0), P(4.6, 0), 8)
conic.ellipse{C = C, A = A, B = B, by = "focal"}:draw{color = 15}
pen{dash = {4, 3}} path({A, B, F2, A}, {color = 9}) pen()
line(F2, M, 10)
angle_mark(A, F2, M, "$\\varphi$", 36, 11)
for _, q in ipairs{C, A, B, F1, F2} do mark(q, "dot", 5, 15) end
mark(M, "dot", 5, 14)
label("$C$", C) label("$A$", A) label("$B$", B) label("$F_1$", F1) label("$F_2$", F2)
label("$M$", M, nil, 14) label("$\\rho$", lerp(F2, M, 0.55), nil, 10)
caption(string.format("rho = %.6f = p/(1 - e cos phi) = %.6f,  p_A = %.4f, p_B = %.4f", dist(F2, M),
  p / (1 - e * math.cos(phi)), pa, pb), "bottom", 7)
