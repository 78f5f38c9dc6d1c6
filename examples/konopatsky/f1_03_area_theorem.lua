-- Konopatsky §1.3.1 (Fig. 1.3): the theorem on triangle areas (1.2)
-- Chosen triangle A1(0,0), A2(6,0), A3(2,4) and the digest's ratios lambda1 = 0.5,
-- lambda2 = 2, lambda3 = -3: B_i divides the side line A_iA_(i+1) in the ratio
-- lambda_i = A_iB_i/B_iA_(i+1), so B3 lies outside A3A1.  The signed areas give
-- S_B1B2B3/S_A1A2A3 = k = (1 + l1 l2 l3)/((1 + l1)(1 + l2)(1 + l3)) (konopatsky.area_theorem).
local A1, A2, A3 = P(0, 0), P(6, 0), P(2, 4)
local l = {0.5, 2, -3}
local function on(X, Y, lam) return (X + Y * lam) / (1 + lam) end
local B1, B2, B3 = on(A1, A2, l[1]), on(A2, A3, l[2]), on(A3, A1, l[3])
local r = konopatsky.area_theorem(A1, A2, A3, B1, B2, B3)
fit{around = {A1, A2, A3, B1, B2, B3}, pad = 0.8}
hatch({A1, A2, A3}, 8, 45, 9)
hatch({B1, B2, B3}, 6, -45, 6)
path({A1, A2, A3, A1}, {color = 9})
path({B1, B2, B3, B1}, {color = 14})
pen{dash = {4, 3}} line(A3, B3, 7) pen()        -- the side line A3A1 extended to B3
for _, p in ipairs{A1, A2, A3} do mark(p, "dot", 5, 15) end
for _, p in ipairs{B1, B2, B3} do mark(p, "dot", 5, 14) end
label("$A_1$", A1) label("$A_2$", A2) label("$A_3$", A3)
label("$B_1$", B1, nil, 14) label("$B_2$", B2, nil, 14) label("$B_3$", B3, nil, 14)
caption(string.format("l1 = %g, l2 = %g, l3 = %g:  k = %.6f = S(B1B2B3)/S(A1A2A3) = %.6f",
  r.lambda[1], r.lambda[2], r.lambda[3], konopatsky.area_k(l[1], l[2], l[3]),
  area(B1, B2, B3) / area(A1, A2, A3)), "bottom", 7)
