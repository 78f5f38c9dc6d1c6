-- Konopatsky §3.1 (Figs. 3.1, 3.2): the curve of one ratio by a moving simplex
-- Simplex A(0,0), B(10,0), C(4,6) (the digest's defaults; the book prints no numbers).  Left,
-- the scheme at t = 0.4: N on AC with AN/AC = t, M on the moving segment NB with NM/NB = t
-- (oneratio.simplex_scheme); the curve (3.1) M = A t'^2 + B t + C t t' (corrected).  Right, the
-- curve in the simplex CAB with the tangent BC at B and the tangent at A along the median
-- from A (dashed), not along AC.
local function mark(p, name, _, c) circle(p, 0.1, c or 15) label(name, p, nil, c or 15) end
local A, B, C = P(0, 0), P(10, 0), P(4, 6)

view(5, 60, 315, 420)
window(-1, -1.5, 11, 7.5)
path({A, C, B}, {color = 8})
local curve31 = oneratio(A, B, C)
for _, t in ipairs{0.2, 0.4, 0.6, 0.8} do
  local s = oneratio.simplex_scheme(A, B, C, t)
  line(s.N, B, t == 0.4 and 11 or 8)
end
curve31:draw{color = 10}
local s = oneratio.simplex_scheme(A, B, C, 0.4)
mark(A, "$A$", "sw") mark(B, "$B$", "se") mark(C, "$C$", "n") mark(s.N, "$N$", "nw", 11) mark(s.M, "$M$", "n", 14)
label("AN/AC = NM/NB = t = 0.4", P(-0.8, -1.1), "e", 7)

view(325, 60, 635, 420)
window(-1, -1.5, 11, 7.5)
path({A, C, B}, {color = 8})
curve31:draw{color = 10}
local tA = curve31:deriv(0)
pen{dash = {4, 3}} line(A, A + tA * 0.6, 12) line(A, mid(B, C), 8) pen()
line(B, C, 12)
mark(A, "$A$", "sw") mark(B, "$B$", "se") mark(C, "$C$", "n") mark(mid(B, C), "", "n", 8)
label("tangent BC at B; at A the median", P(-0.8, -1.1), "e", 7)
