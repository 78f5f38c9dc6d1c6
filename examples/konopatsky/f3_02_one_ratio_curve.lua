-- Konopatsky §3.1 (Fig. 3.2): the curve of one ratio (3.1) in the simplex CAB
-- Simplex A(0,0), B(10,0), C(4,6) (chosen): the curve (3.1) with the tangent BC at B and the
-- tangent at A along the median from A to the midpoint of BC (dashed), not along AC.
local dot = mark
local function mark(p, name, _, c) dot(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end
local A, B, C = P(0, 0), P(10, 0), P(4, 6)

fit{around = {P(-1, -1.5), P(11, 7.5)}}
path({A, C, B}, {color = 8})
local curve31 = oneratio(A, B, C)
curve31:draw{color = 10}
local tA = curve31:deriv(0)
pen{dash = {4, 3}} line(A, A + tA * 0.6, 12) line(A, mid(B, C), 8) pen()
line(B, C, 12)
mark(A, "$A$", "sw") mark(B, "$B$", "se") mark(C, "$C$", "n") mark(mid(B, C), "", "n", 8)
label("tangent BC at B; at A the median", P(-0.8, -1.1), "e", 7)
