-- Konopatsky §1.3.1 (Fig. 1.6): corollary 3 of the theorem on areas, B1 = A1 and B3 = A3
-- Chosen triangle A1(0,0), A2(6,0), A3(2,4) and B2 on A2A3 with lambda2 = 2: the triangles
-- A1B2A3 and A1A2A3 share the height from A1 (dashed), so S_A1B2A3/S_A1A2A3 = -b with
-- b = (B2A2A3) = -1/(1 + lambda2) (konopatsky.area_theorem).
local A1, A2, A3 = P(0, 0), P(6, 0), P(2, 4)
local B2 = (A2 + A3 * 2) / 3
local r = konopatsky.area_theorem(A1, A2, A3, A1, B2, A3)
local H = A2 + (A3 - A2) * (dot(A1 - A2, A3 - A2) / dot(A3 - A2, A3 - A2))   -- foot of the height
fit{around = {A1, A2, A3, B2, H}, pad = 0.8}
hatch({A1, A2, A3}, 8, 45, 9)
hatch({A1, B2, A3}, 6, -45, 6)
path({A1, A2, A3, A1}, {color = 9})
path({A1, B2}, {color = 14})
pen{dash = {4, 3}} line(A1, H, 7) pen()
for _, p in ipairs{A1, A2, A3} do mark(p, "dot", 5, 15) end
mark(B2, "dot", 5, 14)
label("$A_1 \\equiv B_1$", A1) label("$A_2$", A2) label("$A_3 \\equiv B_3$", A3)
label("$B_2$", B2, nil, 14) label("$H$", H, nil, 7)
caption(string.format("-b = %.6f,  k = %.6f = S(A1B2A3)/S(A1A2A3) = %.6f",
  -r.b, r.k, area(A1, B2, A3) / area(A1, A2, A3)), "bottom", 7)
