-- Konopatsky §2.2 (Fig. 2.28): curves by systems of triples, (a) with and (b) without a Pascal line
-- (a) The (self-crossing) hexagon A1 A2 A3 A4 A5 M in the conic through A1..A5 (chosen points on an
-- ellipse): A = A1A2 x A4A5, B = A2A3 x A5M, C = A3A4 x MA1 lie on the Pascal line (red).
-- (b) The digest's example p2 = q2 = 0.2, p3 = q3 = 0.4, q4 = 0.5 in the simplex A1(1,0),
-- A5(0,1), A(0,0): the current C on A1A5 (t = 0.4), B = AA1 x A2C, M = BA3 x CA4.  The locus
-- (green, corrected: B uses A, not A5) is a conic through A1, A3 and A4, not through A2 and A5
-- (a hyperbola: it breaks at its points at infinity).  Each triple of the system is drawn as the
-- line of its three points: A A1 B, A2 B C, B A3 M, M A4 C and A1 A5 C.
local function pt(p, name, c) mark(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end
-- the segment spanning three collinear points (the triple's line)
local function triple(p, q, r, c)
  local best, a, b = -1, p, q
  for _, e in ipairs{{p, q}, {q, r}, {p, r}} do
    local d = dist(e[1], e[2])
    if d > best then best, a, b = d, e[1], e[2] end
  end
  line(a, b, c)
end

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
for i, p in ipairs{A1, A2, A3, A4, A5} do pt(p, "$A_" .. i .. "$") end
pt(M, "$M$", 14)
pt(Ap, "$A$", 12) pt(Bp, "$B$", 12) pt(Cp, "$C$", 12)
label("(a) Pascal line ACB", P(-2.4, -2.3), "e", 7)

view(325, 40, 635, 440)
window(-0.42, -0.36, 1.33, 1.9)
local B1, B5, B0 = P(1, 0), P(0, 1), P(0, 0)        -- A1, A5, A of system (b)
local Q2, Q3, Q4 = P(0.2, 0.2), P(0.4, 0.4), P(0, 0.5)
path({B1, B5, B0, B1}, {color = 8})
local loc = conic.triples(B1, Q2, Q3, Q4, B5, -3, 4)
loc:draw{color = 10}
local t = 0.4
local Cc = lerp(B1, B5, t)
local Bc = meet(B0, B1, Q2, Cc)
local Mc = meet(Bc, Q3, Cc, Q4)
pen{dash = {4, 3}}
triple(B0, B1, Bc, 8) triple(Q2, Bc, Cc, 7) triple(Bc, Q3, Mc, 7) triple(Mc, Q4, Cc, 7)
pen()
pt(B1, "$A_1$") pt(B5, "$A_5$") pt(B0, "$A$")
pt(Q2, "$A_2$") pt(Q3, "$A_3$") pt(Q4, "$A_4$")
pt(Cc, "$C$", 11) pt(Bc, "$B$", 11) pt(Mc, "$M$", 14)
label("(b) conic through A1, A3, A4", P(-0.4, -0.28), "e", 7)
