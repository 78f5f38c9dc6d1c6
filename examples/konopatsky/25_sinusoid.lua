-- Konopatsky §2.5 (Figs. 2.31, 2.32): sinusoids whose axis is a circle, of the 1st and 2nd generation
-- Left (Fig. 2.31, m = 4, phi = 0.5): the axis circle of radius b = |CA| about C, Q the rotation of A by phi,
-- the generating circle of radius rho1 = b/m about Q and its point T at the angle
-- theta = b phi/rho1 = m phi (rolling without slip); M on the ray CQ with |CM| = |CT| (2.137)-(2.140).
-- Right (Fig. 2.32): the digest's C(0,0), A(1,0), B(0,1) (the book does not print its m, n):
-- the axis circle (green), the 1st generation m = 6 (red, (2.142)) and the 2nd, n = 24 (blue, (2.144)).
local function mark(p, name, _, c) circle(p, 0.015, c or 15) label(name, p, nil, c or 15) end
local C, A, B = P(0, 0), P(1, 0), P(0, 1)

view(5, 60, 315, 420)
window(-1.26, -1.45, 1.26, 1.45)
local m, phi = 4, 0.5
local axis = conic.circle{A = A, B = B, C = C, R = 1}
axis:draw{color = 10}
local M1 = conic.sinusoid{C = C, A = A, B = B, k = {m}}
M1:draw{color = 12}
local Q = axis(phi)
local u = unit(Q - C)
local w = V(-u.y, u.x)
local theta = m * phi
local T = Q + (u * math.cos(theta) + w * math.sin(theta)) * (1 / m)
local roll = {}
for i = 0, 48 do local a = 2 * math.pi * i / 48 roll[#roll + 1] = Q + (u * math.cos(a) + w * math.sin(a)) * (1 / m) end
path(roll, {color = 7})
local M = M1(phi)
line(C, M, 8) line(Q, T, 11) line(C, T, 8)
pen{dash = {3, 3}} line(Q, Q + u * (1 / m), 8) pen()
mark(C, "C", "sw") mark(A, "A", "se") mark(Q, "Q", "sw", 10) mark(T, "T", "e", 11) mark(M, "M", "ne", 14)
label(string.format("m = %d  phi = %.2f  theta = m phi", m, phi), P(-1.24, -1.25), "e", 7)
label(string.format("|CM| = |CT| = %.4f", dist(C, T)), P(-1.24, -1.4), "e", 7)

view(325, 60, 635, 420)
window(-1.26, -1.45, 1.26, 1.45)
axis:draw{color = 10}
conic.sinusoid{C = C, A = A, B = B, k = {6}}:draw{color = 12}
conic.sinusoid{C = C, A = A, B = B, k = {6, 24}}:draw{color = 9}
mark(C, "C", "s") mark(A, "A", "e") mark(B, "B", "n")
