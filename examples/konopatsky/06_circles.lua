-- Konopatsky §2.1.8.2 (Figs. 2.25, 2.26): circles by an angular parameter
-- A(0;0), B(0,5;1), C(1;0) and delta = pi/3, as the book gives them: (2.115) for phi in
-- [0, 2pi/3] (green, where angle AMC = delta) and [2pi/3, pi] (yellow, where it is pi - delta);
-- the circumcircle arc (2.116) A -> B -> C (cyan, delta = beta) and (2.118), the circle of radius
-- 0.5 about C (magenta).
local A, B, C = P(0, 0), P(0.5, 1), P(1, 0)
window(-0.7, -0.8, 1.9, 1.15)
path({A, B, C, A}, {color = 8})
local F = {A = A, B = B, C = C, delta = math.pi / 3}
F.range = {0, 2 * math.pi / 3}
conic.circle(F):draw{color = 10}
F.range = {2 * math.pi / 3, math.pi}
conic.circle(F):draw{color = 14}
local beta = angle(B, A, C)
pen{dash = {3, 2}}
conic.circle{A = A, B = B, C = C, delta = beta, range = {0, math.pi - beta}}:draw{color = 11}
pen()
conic.circle{A = A, B = B, C = C, R = 0.5}:draw{color = 13}
local M = conic.circle{A = A, B = B, C = C, delta = math.pi / 3}(1.0)
line(A, M, 7) line(C, M, 7)
for _, p in ipairs{A, B, C, M} do circle(p, 0.015, 15) end
label("$A$", A, nil, 15) label("$B$", B, nil, 15) label("$C$", C, nil, 15) label("$M$", M, nil, 15)
