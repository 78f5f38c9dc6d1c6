-- Konopatsky §2.1.2 (Fig. 2.10): the hyperbola in the simplex CAB
-- Set H: C(0,0), A(3,0), B(0,2), angle BCA = 90 degrees: A the vertex, B the end of the
-- imaginary semi-axis.  The fundamental rectangle on CA and CB, the asymptotes (dashed) along
-- its diagonals, the foci F1 = (A - C)e + C and F2 = -(A - C)e + C (2.43), e = sqrt 13/3; both
-- branches by the central angle (2.49), each breaking at its points at infinity.
local C, A, B = P(0, 0), P(3, 0), P(0, 2)
local F1, F2, e = conic.foci(C, A, B, "hyperbola")
fit{around = {P(-6, -3.4), P(6, 3.4)}, pad = 0.2}
line(P(-7, 0), P(7, 0), 8) line(P(0, -4), P(0, 4), 8)
path({A + (B - C), 2 * C - A + (B - C), 2 * C - A - (B - C), A - (B - C), A + (B - C)}, {color = 8})
pen{dash = {4, 3}} line(P(-7, -14 / 3), P(7, 14 / 3), 7) line(P(-7, 14 / 3), P(7, -14 / 3), 7) pen()
local H = {C = C, A = A, B = B, by = "angle"}
conic.hyperbola(H):draw{color = 10}
H.branch = 2
conic.hyperbola(H):draw{color = 10}
line(C, A, 15) line(C, B, 15)
for _, p in ipairs{A, B, C} do mark(p, "dot", 5, 15) end
for _, p in ipairs{F1, F2} do mark(p, "dot", 5, 11) end
label("$C$", C) label("$A$", A) label("$B$", B)
label("$F_1$", F1, nil, 11) label("$F_2$", F2, nil, 11)
caption(string.format("a = 3, b = 2, c = |CF1| = %.6f, e = %.6f", dist(C, F1), e), "bottom", 7)
