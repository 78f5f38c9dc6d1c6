-- Konopatsky §2.1 (Fig. 2.1): the notation of a triangle used through chapter 2
-- Chosen A(0,0), B(6,0), C(2,4): the sides a = |BC|, b = |CA|, c = |AB| opposite the vertices,
-- the angles alpha, beta, gamma at A, B, C.  In any dimension a = sqrt(Sigma^B_CC) and
-- cos gamma = Sigma^C_AB/(ab) (the metric operator of §1.4); the caption prints them.
local A, B, C = P(0, 0), P(6, 0), P(2, 4)
fit{around = {A, B, C}, pad = 0.7}
path({A, B, C, A}, {color = 15})
angle_mark(B, A, C, "$\\alpha$", 34, 11)
angle_mark(C, B, A, "$\\beta$", 34, 11)
angle_mark(A, C, B, "$\\gamma$", 30, 11)
for _, p in ipairs{A, B, C} do mark(p, "dot", 5, 15) end
label("$A$", A) label("$B$", B) label("$C$", C)
label("$a$", mid(B, C), "ne", 14) label("$b$", mid(C, A), "nw", 14) label("$c$", mid(A, B), "s", 14)
local a, b, c = dist(B, C), dist(C, A), dist(A, B)
local g = math.acos(dot(A - C, B - C) / (a * b))
caption(string.format("a = %.4f, b = %.4f, c = %.4f;  alpha + beta + gamma = %.4f", a, b, c,
  math.acos(dot(B - A, C - A) / (b * c)) + math.acos(dot(A - B, C - B) / (a * c)) + g), "bottom", 7)
