-- Konopatsky §2.1.8.2 (Fig. 2.25): the circle by an angular parameter, (2.115)
-- A(0;0), B(0,5;1), C(1;0) and delta = pi/3, as the book gives them: (2.115) for phi in
-- [0, 2pi/3] (green, where angle AMC = delta) and [2pi/3, pi] (yellow, where it is pi - delta);
-- the current point M at phi = 1 with the chords MA, MC.
local A, B, C = P(0, 0), P(0.5, 1), P(1, 0)
local F = {A = A, B = B, C = C, delta = math.pi / 3}
local M = conic.circle(F)(1.0)
fit{around = {P(-0.1, -0.6), P(1.1, 1.05)}, pad = 0.05}
path({A, B, C, A}, {color = 8})
F.range = {0, 2 * math.pi / 3}
conic.circle(F):draw{color = 10}
F.range = {2 * math.pi / 3, math.pi}
conic.circle(F):draw{color = 14}
line(A, M, 7) line(C, M, 7)
angle_mark(A, M, C, "$\\delta$", 22, 11)
for _, p in ipairs{A, B, C, M} do mark(p, "dot", 5, 15) end
label("$A$", A) label("$B$", B) label("$C$", C) label("$M$", M)
caption(string.format("angle AMC = %.6f = pi/3", angle(M, A, C)), "bottom", 7)
