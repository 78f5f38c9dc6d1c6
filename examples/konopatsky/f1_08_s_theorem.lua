-- Konopatsky §1.3.3 (Fig. 1.8): the S-theorem, the area ratio is the determinant of the parameters
-- Chosen simplex A(6,0), B(2,5), C(0,0) and A_i = Ap_i + Bq_i + Cr_i with the rows
-- (0.6, 0.2, 0.2), (0.2, 0.6, 0.2), (0.1, 0.2, 0.7): S_A1A2A3/S_ABC = det of the rows
-- (konopatsky.simplex_ratio), against the areas measured from the coordinates.
local A, B, C = P(6, 0), P(2, 5), P(0, 0)
local rows = {{0.6, 0.2, 0.2}, {0.2, 0.6, 0.2}, {0.1, 0.2, 0.7}}
local T = {}
for i, r in ipairs(rows) do T[i] = A * r[1] + B * r[2] + C * r[3] end
fit{around = {A, B, C}, pad = 0.6}
hatch({T[1], T[2], T[3]}, 6, -45, 6)
path({A, B, C, A}, {color = 9})
path({T[1], T[2], T[3], T[1]}, {color = 14})
for _, p in ipairs{A, B, C} do mark(p, "dot", 5, 15) end
for _, p in ipairs(T) do mark(p, "dot", 5, 14) end
label("$A$", A) label("$B$", B) label("$C$", C)
for i = 1, 3 do label("$A_" .. i .. "$", T[i], nil, 14) end
caption(string.format("det = %.6f,  S(A1A2A3)/S(ABC) = %.6f", konopatsky.simplex_ratio(rows),
  area(T[1], T[2], T[3]) / area(A, B, C)), "bottom", 7)
