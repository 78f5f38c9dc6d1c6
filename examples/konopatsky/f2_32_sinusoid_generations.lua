-- Konopatsky §2.5 (Fig. 2.32): sinusoids about a circle of the 1st and the 2nd generation
-- The digest's C(0,0), A(1,0), B(0,1) (the book does not print its m, n): the axis circle
-- (green), the 1st generation m = 6 (red, (2.142)) and the 2nd, n = 24 waves on it (blue,
-- (2.144)), conic.sinusoid{k = {m, n}}.
local C, A, B = P(0, 0), P(1, 0), P(0, 1)
fit{around = {P(-1.25, -1.25), P(1.25, 1.25)}, pad = 0.18}
conic.circle{A = A, B = B, C = C, R = 1}:draw{color = 10}
conic.sinusoid{C = C, A = A, B = B, k = {6}}:draw{color = 12}
conic.sinusoid{C = C, A = A, B = B, k = {6, 24}}:draw{color = 9}
for _, p in ipairs{C, A, B} do mark(p, "dot", 5, 15) end
label("$C$", C) label("$A$", A) label("$B$", B)
caption("m = 6 (red), n = 24 (blue)", "bottom", 7)
