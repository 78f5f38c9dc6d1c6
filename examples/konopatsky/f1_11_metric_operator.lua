-- Konopatsky §1.4 (Fig. 1.11): the metric operator of three points
-- Chosen A(0,0), B(6,0), C(2,3.5): H is the foot of the perpendicular from C to AB, alpha the
-- angle at A, and Sigma^A_BC = Sum (B - A)(C - A) = AH AB = AB AC cos alpha =
-- (AB^2 + AC^2 - BC^2)/2, each computed.
local A, B, C = P(0, 0), P(6, 0), P(2, 3.5)
local S = dot(B - A, C - A)                             -- Sigma^A_BC, coordinate by coordinate
local H = A + (B - A) * (S / dot(B - A, B - A))         -- H = A + (B - A) Sigma^A_BC/Sigma^A_BB
fit{around = {A, B, C}, pad = 0.8}
path({A, B, C, A}, {color = 15})
pen{dash = {4, 3}} line(C, H, 7) pen()
angle_mark(C, H, A, "", 14, 7)
angle_mark(B, A, C, "$\\alpha$", 30, 11)
for _, p in ipairs{A, B, C} do mark(p, "dot", 5, 15) end
mark(H, "dot", 4, 7)
label("$A$", A) label("$B$", B) label("$C$", C) label("$H$", H, nil, 7)
local a = math.acos(S / (dist(A, B) * dist(A, C)))
caption(string.format("Sigma = %.4g = AH AB = %.4g = AB AC cos(alpha) = %.4g = %.4g", S,
  dist(A, H) * dist(A, B), dist(A, B) * dist(A, C) * math.cos(a),
  (dist(A, B) ^ 2 + dist(A, C) ^ 2 - dist(B, C) ^ 2) / 2), "bottom", 7)
