-- Konopatsky §2.5 (Fig. 2.31): the sinusoid whose axis is a circle, of the 1st generation
-- The digest's C(0,0), A(1,0), B(0,1), m = 4 waves and phi = 0.5: the axis circle of radius
-- b = |CA| about C, Q the rotation of A by phi (2.138), the generating circle of radius
-- rho1 = b/m about Q, P its point on the ray CQ (where theta starts) and T at the angle
-- theta = b phi/rho1 = m phi from P (rolling without slip, (2.136)); M on the ray CQ with
-- |CM| = |CT| (2.137)-(2.140), on the sinusoid (2.142) (red).
local C, A, B = P(0, 0), P(1, 0), P(0, 1)
local m, phi = 4, 0.5
local axis = conic.circle{A = A, B = B, C = C, R = 1}
local M1 = conic.sinusoid{C = C, A = A, B = B, k = {m}}
local Q = konopatsky.rotate(C, A, B, phi)
local u = unit(Q - C)
local w = V(-u.y, u.x)
local theta = m * phi
local Pp = Q + u * (1 / m)
local T = Q + (u * math.cos(theta) + w * math.sin(theta)) * (1 / m)
local M = M1(phi)
fit{around = {P(-1.25, -1.25), P(1.25, 1.25)}, pad = 0.18}
axis:draw{color = 10}
M1:draw{color = 12}
circle(Q, 1 / m, 7)
line(C, A, 8) line(C, Pp, 8) line(Q, T, 11) line(C, T, 8)
angle_mark(A, C, Q, "$\\varphi$", 40, 10)
angle_mark(Pp, Q, T, "$\\theta$", 16, 11)
for _, p in ipairs{C, A} do mark(p, "dot", 5, 15) end
mark(Q, "dot", 5, 10) mark(Pp, "dot", 4, 11) mark(T, "dot", 5, 11) mark(M, "dot", 5, 14)
label("$C$", C) label("$A$", A) label("$Q$", Q, nil, 10) label("$P$", Pp, nil, 11)
label("$T$", T, nil, 11) label("$M$", M, nil, 14)
caption(string.format("m = %d, phi = %.2f, theta = m phi = %.2f;  |CM| = |CT| = %.4f", m, phi, theta,
  dist(C, T)), "bottom", 7)
