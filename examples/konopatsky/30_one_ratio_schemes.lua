-- Konopatsky §3.1 (Fig. 3.1): the scheme of the curve of one ratio by a moving simplex
-- Simplex A(0,0), B(10,0), C(4,6) (the digest's defaults; the book prints no numbers): at
-- t = 0.4, N on AC with AN/AC = t and M on the moving segment NB with NM/NB = t
-- (oneratio.simplex_scheme), the segments NB at t = 0.2 ... 0.8; the curve (3.1)
-- M = A t'^2 + B t + C t t' (corrected).
local dot = mark
local function mark(p, name, _, c) dot(p, "dot", 5, c or 15) label(name, p, nil, c or 15) end
local A, B, C = P(0, 0), P(10, 0), P(4, 6)

fit{around = {P(-1, -1.5), P(11, 7.5)}}
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
