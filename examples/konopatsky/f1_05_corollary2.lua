-- Konopatsky §1.3.1 (Fig. 1.5): corollary 2 of the theorem on areas, B3 = A3
-- Chosen triangle A1(0,0), A2(6,0), A3(2,4), lambda1 = 0.5, lambda2 = 2 and B3 at A3
-- (lambda3 = 0): S_B1B2A3/S_A1A2A3 = ab with a = (B1A1A2) = -1/(1 + lambda1) and
-- b = (B2A2A3) = -1/(1 + lambda2) (konopatsky.area_theorem's a, b).
local A1, A2, A3 = P(0, 0), P(6, 0), P(2, 4)
local function on(X, Y, lam) return (X + Y * lam) / (1 + lam) end
local B1, B2 = on(A1, A2, 0.5), on(A2, A3, 2)
local r = konopatsky.area_theorem(A1, A2, A3, B1, B2, A3)
fit{around = {A1, A2, A3, B1, B2}, pad = 0.8}
hatch({A1, A2, A3}, 8, 45, 9)
hatch({B1, B2, A3}, 6, -45, 6)
path({A1, A2, A3, A1}, {color = 9})
path({B1, B2, A3, B1}, {color = 14})
for _, p in ipairs{A1, A2, A3} do mark(p, "dot", 5, 15) end
for _, p in ipairs{B1, B2} do mark(p, "dot", 5, 14) end
label("$A_1$", A1) label("$A_2$", A2) label("$A_3 \\equiv B_3$", A3)
label("$B_1$", B1, nil, 14) label("$B_2$", B2, nil, 14)
caption(string.format("ab = %.6f,  k = %.6f = S(B1B2A3)/S(A1A2A3) = %.6f",
  r.a * r.b, r.k, area(B1, B2, A3) / area(A1, A2, A3)), "bottom", 7)
