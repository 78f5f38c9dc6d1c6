-- Konopatsky §3.7 (Fig. 3.15): the closed Desargues arc when A = D
-- Chosen points (the book prints none): M = (A(1 - 3t t') + B t^2 t' + C t'^2 t)/(2t^2 - 2t + 1)
-- from A back to A, leaving along AC and returning along BA; M(1/2) = G, the centroid of A, A, B,
-- C.
local dot = mark
local function mark(p, name, _, c) dot(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end

fit{around = {P(-2, -2), P(8, 6)}}
local A2, B2, C2 = P(0, 0), P(6, 4), P(1, 5)
path({A2, C2, B2, A2}, {color = 12})
local arc = oneratio.desargues(A2, B2, C2, A2)
arc:draw{color = 10}
mark(A2, "$A = D$", "sw") mark(B2, "$B$", "e") mark(C2, "$C$", "n") mark(arc(0.5), "$G$", "s", 14)
label("A = D: closed", P(-1.8, -1.6), "e", 7)
