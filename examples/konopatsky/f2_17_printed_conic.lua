-- Konopatsky §2.1.5 (Fig. 2.17): the book's example of the five-point conic, x(t), y(t) as printed
-- The book prints x = 4t(9t + 0.8)/(70t^2 - 75t + 44.2), y = -8t(t - 1)/(14t^2 - 15t + 8.84),
-- t in [0, 1], without its inputs; the digest reconstructs A(0,0), B(1,0), C(0.5,1), p1 = p2 =
-- 0.7, q2 = q3 = 0.8, so A1(0.15, 0.3), A2(0.64, 0.384), A3(0.9, 0.2).  The printed curve
-- (yellow dots) on the corrected (2.93) of those inputs (green, conic.five_points2): they
-- coincide (p1 = p2 hides the misprint); the equation as the library prints it in the caption.
local A, B, C = P(0, 0), P(1, 0), P(0.5, 1)
local arc = conic.five_points2{C = C, A = A, B = B, p1 = 0.7, p2 = 0.7, q2 = 0.8, q3 = 0.8}
local A1, A2, A3 = P(0.15, 0.3), P(0.64, 0.384), P(0.9, 0.2)
fit{around = {A, B, C}, pad = 0.08}
path({A, C, B}, {color = 8}) line(A, B, 8)
arc:draw{color = 10}
for i = 0, 40 do                                    -- the printed x(t), y(t)
  local t = i / 40
  mark(P(4 * t * (9 * t + 0.8) / (70 * t * t - 75 * t + 44.2), -8 * t * (t - 1) / (14 * t * t - 15 * t + 8.84)), "dot", 3, 14)
end
for _, p in ipairs{A, B, C, A1, A2, A3} do mark(p, "dot", 5, 15) end
label("$A$", A) label("$B$", B) label("$C$", C)
label("$A_1$", A1) label("$A_2$", A2) label("$A_3$", A3)
caption(string.format("M(0.5) = (%.6f, %.6f)", arc(0.5).x, arc(0.5).y), "bottom", 7)
