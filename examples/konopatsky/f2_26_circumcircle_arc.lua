-- Konopatsky §2.1.8.2 (Fig. 2.26): the circumcircle arc A -> B -> C, (2.116)
-- The book's A(0;0), B(0,5;1), C(1;0): (2.115) with delta = beta, the angle at B, for phi in
-- [0, pi - beta] (green) runs through A (phi = 0), B (phi = gamma) and C (phi = pi - beta; the
-- print's gamma at C corrected); the rest of the circle dashed.
local A, B, C = P(0, 0), P(0.5, 1), P(1, 0)
local beta = angle(B, A, C)
fit{around = {P(-0.1, -0.45), P(1.1, 1.05)}, pad = 0.05}
path({A, B, C, A}, {color = 8})
local arc = conic.circle{A = A, B = B, C = C, delta = beta, range = {0, math.pi - beta}}
pen{dash = {4, 3}} conic.circle{A = A, B = B, C = C, delta = beta}:draw{color = 7} pen()
arc:draw{color = 10}
angle_mark(A, B, C, "$\\beta$", 22, 11)
for _, p in ipairs{A, B, C} do mark(p, "dot", 5, 15) end
label("$A$", A) label("$B$", B) label("$C$", C)
caption(string.format("delta = beta = %.6f;  M(pi - beta) = (%.6f, %.6f) = C", beta,
  arc(math.pi - beta).x, arc(math.pi - beta).y), "bottom", 7)
