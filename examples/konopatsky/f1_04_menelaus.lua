-- Konopatsky §1.3.1 (Fig. 1.4): corollary 1 of the theorem on areas, B1, B2, B3 collinear
-- Chosen triangle A1(0,0), A2(6,0), A3(2,4) and the transversal d through (1.2, 2.4) and (5, 1):
-- B1, B2, B3 are its meets with the side lines A1A2, A2A3, A3A1, so S_B1B2B3 = 0 and (1.3)
-- lambda1 lambda2 lambda3 = -1 (Menelaus with oriented segments; konopatsky.area_theorem).
local A1, A2, A3 = P(0, 0), P(6, 0), P(2, 4)
local D1, D2 = P(1.2, 2.4), P(5, 1)
local B1, B2, B3 = meet(A1, A2, D1, D2), meet(A2, A3, D1, D2), meet(A3, A1, D1, D2)
local r = konopatsky.area_theorem(A1, A2, A3, B1, B2, B3)
fit{around = {A1, A2, A3, B1, B2, B3, lerp(D1, D2, -0.4), lerp(D1, D2, 1.9)}, pad = 0.8}
path({A1, A2, A3, A1}, {color = 9})
pen{dash = {4, 3}} line(A2, B1, 7) pen()     -- side lines extended
line(lerp(D1, D2, -0.4), lerp(D1, D2, 1.9), 12)
for _, p in ipairs{A1, A2, A3} do mark(p, "dot", 5, 15) end
for _, p in ipairs{B1, B2, B3} do mark(p, "dot", 5, 14) end
label("$A_1$", A1) label("$A_2$", A2) label("$A_3$", A3)
label("$B_1$", B1, nil, 14) label("$B_2$", B2, nil, 14) label("$B_3$", B3, nil, 14)
label("$d$", lerp(D1, D2, -0.4), nil, 12)
caption(string.format("l1 l2 l3 = %.6f,  k = %.2g,  collinear: %s",
  r.lambda[1] * r.lambda[2] * r.lambda[3], r.k, tostring(r.collinear)), "bottom", 7)
