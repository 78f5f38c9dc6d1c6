-- Konopatsky §2.6 (Fig. 2.33): the cubic as the meet of two quadric cones
-- The Cartesian simplex of the book's algorithm: A = E1(1,0,0), B = E2(0,1,0), C = E3(0,0,1),
-- D = O; the base arcs APB (fP = 0.3) and AQB (fQ = 0.8) of (2.97) in the plane ABC, the cone
-- vertices D and N = (D - A)n + A with n = -0.5 (the book gives no n), the generators DP and NQ at
-- u = 0.85 and the space cubic M = DP x NQ (corrected z_Q, a line meet instead of (2.159)).
local function mark(p, name, _, c) circle(p, 0.015, c or 15) label(name, p, nil, c or 15) end
local A, B, C, D = P(1, 0, 0), P(0, 1, 0), P(0, 0, 1), P(0, 0, 0)
local fP, fQ, n = 0.3, 0.8, -0.5
local N = (D - A) * n + A
camera(map.axonometric(math.rad(35), math.rad(25)))
window(-0.5, -0.55, 1.8, 1.2)
for _, e in ipairs{{A, B}, {B, C}, {C, A}, {D, A}, {D, B}, {D, C}} do line(e[1], e[2], 8) end
pen{dash = {4, 3}} line(D, N, 8) line(N, B, 8) line(N, C, 8) pen()
local arcP, arcQ = conic.ed(A, B, C, fP), conic.ed(A, B, C, fQ)
arcP:draw{color = 12} arcQ:draw{color = 9}
local M = conic.cones(A, B, C, D, fP, fQ, n)
M:draw{color = 10}
local u = 0.85
local Pu = arcP(u)
local Mu = M(u)
local Qu = meet(N, Mu, A, Pu)                         -- A, P, Q are collinear (2.147)
pen{dash = {3, 2}} line(D, Pu, 7) line(N, Qu, 7) line(A, Qu, 7) pen()
mark(A, "$A$", "s") mark(B, "$B$", "e") mark(C, "$C$", "n") mark(D, "$D$", "sw") mark(N, "$N$", "w")
mark(Pu, "$P$", "ne", 12) mark(Qu, "$Q$", "e", 9) mark(Mu, "$M$", "nw", 14)
camera()
label(string.format("fP = %.1f  fQ = %.1f  n = %.1f", fP, fQ, n), P(-0.45, -0.5), "e", 7)
