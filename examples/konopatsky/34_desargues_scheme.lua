-- Konopatsky §3.7 (Fig. 3.11): the Desargues configuration
-- Chosen points: triangles A1B1C1 and A2B2C2 in perspective from O; the meets of corresponding
-- sides X, Y, Z lie on the axis of perspectivity (red).
local dot = mark
local function mark(p, name, _, c) dot(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end

fit{around = {P(-0.6, -0.8), P(8.6, 9)}}
local O = P(0, 4)
local A1, B1, C1 = P(2, 6), P(2.5, 2.5), P(3.5, 4.5)
local f1, f2, f3 = 2.2, 1.3, 1.7
local A2, B2, C2 = lerp(O, A1, f1), lerp(O, B1, f2), lerp(O, C1, f3)
for _, p in ipairs{A2, B2, C2} do line(O, p, 8) end
path({A1, B1, C1, A1}, {color = 11}) path({A2, B2, C2, A2}, {color = 14})
local X, Y, Z = meet(A1, B1, A2, B2), meet(B1, C1, B2, C2), meet(C1, A1, C2, A2)
pen{dash = {4, 3}}
line(B1, X, 7) line(B2, X, 7) line(C1, Y, 7) line(C2, Y, 7) line(A1, Z, 7) line(A2, Z, 7)
pen()
line(X, Z, 12) line(Y, Z, 12) line(X, Y, 12)
mark(O, "$O$", "w") mark(A1, "$A_1$", "w", 11) mark(B1, "$B_1$", "e", 11) mark(C1, "$C_1$", "e", 11)
mark(A2, "$A_2$", "w", 14) mark(B2, "$B_2$", "e", 14) mark(C2, "$C_2$", "e", 14)
mark(X, "$X$", "s", 12) mark(Y, "$Y$", "s", 12) mark(Z, "$Z$", "s", 12)
