-- Konopatsky §2.1.1 (Fig. 2.3): the ellipse in the simplex CAB with the right angle at C
-- Set E: C(0,0) the centre, A(4,0) the end of the major semi-axis, B(0,2) of the minor, angle
-- BCA = 90 degrees; the foci F1 = (A - C)e + C and F2 = -(A - C)e + C (F1 + F2 = 2C), e = c/a
-- (conic.foci); the simplex CAB hatched.
local C, A, B = P(0, 0), P(4, 0), P(0, 2)
local F1, F2, e, p = conic.foci(C, A, B)
fit{around = {P(-4, -2), P(4, 2)}, pad = 0.6}
hatch({C, A, B}, 8, 45, 8)
path({C, A, B, C}, {color = 9})
conic.ellipse{C = C, A = A, B = B}:draw{color = 15}
angle_mark(A, C, B, "", 14, 7)
for _, q in ipairs{C, A, B} do mark(q, "dot", 5, 15) end
for _, q in ipairs{F1, F2} do mark(q, "dot", 5, 11) end
label("$C$", C) label("$A$", A) label("$B$", B) label("$F_1$", F1, nil, 11) label("$F_2$", F2, nil, 11)
caption(string.format("e = %.6f,  |CF1| = c = %.6f,  p = b^2/a = %g", e, dist(C, F1), p), "bottom", 7)
