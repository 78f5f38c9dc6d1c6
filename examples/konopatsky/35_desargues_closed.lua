-- Konopatsky §3.7 (Fig. 3.14): the Desargues arc when C = B
-- Chosen points (the book prints none): the planar arc
-- M = (A t'^3 + B t t' + D t^3)/(2t^2 - 2t + 1) from A to D with tangents AB and BD.
local dot = mark
local function mark(p, name, _, c) dot(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end

fit{around = {P(-1, -1.5), P(11, 8)}}
local A, B, D = P(0, 0), P(5, 7), P(10, 0)
path({A, B, D}, {color = 12})
oneratio.desargues(A, B, B, D):draw{color = 10}
mark(A, "$A$", "sw") mark(B, "$B = C$", "n") mark(D, "$D$", "se")
label("$C = B$", P(-0.8, -1.1), "e", 7)
