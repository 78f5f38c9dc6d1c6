-- Konopatsky §3.2 (Fig. 3.3): the arc of one ratio in the simplex DABC
-- The digest's A(0,0,0), B(4,0,0), C(1,3,0), D(4,3,2) (the book prints no numbers), drawn in
-- isometric projection: P on AC and Q on DB with AP/AC = DQ/DB = t, M on PQ with PM/PQ = t;
-- the rulings PQ at t = 0.1 ... 0.9 (grey) sweep a ruled surface, but the arc (3.2) (green) is
-- planar, the parabola with tangents AS and BS, S the midpoint of CD (3.3), through the
-- centroid K of the tetrahedron at t = 1/2.
local function mark(p, name, _, c) circle(p, 0.05, c or 15) label(name, p, nil, c or 15) end
local A, B, C, D = P(0, 0, 0), P(4, 0, 0), P(1, 3, 0), P(4, 3, 2)
camera(map.isometric())
window(-0.8, -1.2, 6.2, 4.05)
for _, e in ipairs{{A, B}, {A, C}, {A, D}, {B, C}, {B, D}, {C, D}} do line(e[1], e[2], 12) end
for i = 1, 9 do
  local t = i / 10
  line(lerp(A, C, t), lerp(D, B, t), 8)
end
local arc = oneratio.tetra(A, B, C, D)
arc:draw{color = 10}
local S = mid(C, D)
pen{dash = {4, 3}} line(A, S, 7) line(B, S, 7) pen()
local t = 0.3
local Pp, Q = lerp(A, C, t), lerp(D, B, t)
line(Pp, Q, 11)
local K = (A + B + C + D) / 4
mark(A, "$A$", "w") mark(B, "$B$", "e") mark(C, "$C$", "n") mark(D, "$D$", "n") mark(S, "$S$", "n", 7)
mark(Pp, "$P$", "w", 11) mark(Q, "$Q$", "e", 11) mark(lerp(Pp, Q, t), "$M$", "s", 14) mark(K, "$K$", "se", 14)
camera()
label("AP/AC = DQ/DB = PM/PQ = t", P(-0.7, -1.0), "e", 7)
