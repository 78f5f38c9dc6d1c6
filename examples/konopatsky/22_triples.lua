-- Konopatsky §2.2 (Fig. 2.28): curves by systems of triples, (a) with and (b) without a Pascal line
-- (a) The (self-crossing) hexagon A1 A2 A3 A4 A5 M in the conic through A1..A5 (chosen points on an
-- ellipse): A = A1A2 x A4A5, B = A2A3 x A5M, C = A3A4 x MA1 lie on the Pascal line (red).
-- (b) The digest's example p2 = q2 = 0.2, p3 = q3 = 0.4, q4 = 0.5 in the simplex A1(1,0),
-- A5(0,1), A(0,0): the current C on A1A5 (t = 0.6), B = AA1 x A2C, M = BA3 x CA4.  The locus
-- (green, corrected: B uses A, not A5) is a conic through A1, A3 and A4, not through A2 and A5
-- (a hyperbola: it breaks at its points at infinity).
local function mark(p, name, _, c, r) circle(p, r or 0.03, c or 15) label(name, p, nil, c or 15) end

view(5, 40, 315, 440)
window(-2.5, -2.6, 2.5, 3.8)
local function ell(a) return P(2 * math.cos(a), 1.2 * math.sin(a)) end
local A1, A2, A3, A4, A5, M = ell(0.5), ell(3.0), ell(5.0), ell(1.5), ell(4.0), ell(2.5)
local c5 = conic.five_points(A1, A2, A3, A4, A5, {whole = true})
c5:draw{color = 10}
path({A1, A2, A3, A4, A5, M, A1}, {color = 7})
local Ap, Bp, Cp = meet(A1, A2, A4, A5), meet(A2, A3, A5, M), meet(A3, A4, M, A1)
pen{dash = {4, 3}}
line(A2, Ap, 8) line(A4, Ap, 8) line(A3, Bp, 8) line(M, Bp, 8) line(A4, Cp, 8) line(A1, Cp, 8)
line(Ap, Bp, 12) line(Ap, Cp, 12)
pen()
for i, p in ipairs{A1, A2, A3, A4, A5} do mark(p, "A" .. i, ({"ne", "w", "se", "n", "sw"})[i]) end
mark(M, "M", "nw", 14)
mark(Ap, "A", "e", 12) mark(Bp, "B", "e", 12) mark(Cp, "C", "e", 12)
label("(a) Pascal line ACB", P(-2.4, -2.3), "e", 7)

view(325, 40, 635, 440)
window(-0.8, -0.6, 1.5, 2.4)
local B1, B5, B0 = P(1, 0), P(0, 1), P(0, 0)        -- A1, A5, A of system (b)
local Q2, Q3, Q4 = P(0.2, 0.2), P(0.4, 0.4), P(0, 0.5)
path({B1, B5, B0, B1}, {color = 8})
local loc = conic.triples(B1, Q2, Q3, Q4, B5, -3, 4)
loc:draw{color = 10}
local t = 0.6
local Cc = lerp(B1, B5, t)
local Bc = meet(B0, B1, Q2, Cc)
local Mc = meet(Bc, Q3, Cc, Q4)
pen{dash = {4, 3}}
line(Q2, Bc, 7) line(Bc, Mc, 7) line(Cc, Mc, 7) line(B0, Q3, 8) line(B0, Bc, 8)
pen()
mark(B1, "A1", "s", 15, 0.015) mark(B5, "A5", "w", 15, 0.015) mark(B0, "A", "sw", 15, 0.015)
mark(Q2, "A2", "e", 15, 0.015) mark(Q3, "A3", "e", 15, 0.015) mark(Q4, "A4", "w", 15, 0.015)
mark(Cc, "C", "ne", 11, 0.015) mark(Bc, "B", "s", 11, 0.015) mark(Mc, "M", "e", 14, 0.015)
label("(b) conic through A1, A3, A4", P(-0.75, -0.5), "e", 7)
