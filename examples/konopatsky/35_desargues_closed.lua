-- Konopatsky §3.7 (Figs. 3.14, 3.15): the Desargues arc when two vertices coincide
-- Chosen points (the book prints none).  Left, C = B (Fig. 3.14): the planar arc
-- M = (A t'^3 + B t t' + D t^3)/(2t^2 - 2t + 1) from A to D with tangents AB and BD.  Right,
-- A = D (Fig. 3.15): the closed arc M = (A(1 - 3t t') + B t^2 t' + C t'^2 t)/(2t^2 - 2t + 1)
-- from A back to A, leaving along AC and returning along BA; M(1/2) the centroid of A, A, B, C.
local function mark(p, name, _, c) circle(p, 0.08, c or 15) label(name, p, nil, c or 15) end

view(5, 60, 315, 420)
window(-1, -1.5, 11, 8)
local A, B, D = P(0, 0), P(5, 7), P(10, 0)
path({A, B, D}, {color = 12})
oneratio.desargues(A, B, B, D):draw{color = 10}
mark(A, "$A$", "sw") mark(B, "$B = C$", "n") mark(D, "$D$", "se")
label("$C = B$", P(-0.8, -1.1), "e", 7)

view(325, 60, 635, 420)
window(-2, -2, 8, 6)
local A2, B2, C2 = P(0, 0), P(6, 4), P(1, 5)
path({A2, C2, B2, A2}, {color = 12})
local arc = oneratio.desargues(A2, B2, C2, A2)
arc:draw{color = 10}
mark(A2, "$A = D$", "sw") mark(B2, "$B$", "e") mark(C2, "$C$", "n") mark(arc(0.5), "$G$", "s", 14)
label("A = D: closed", P(-1.8, -1.6), "e", 7)
