-- Konopatsky §2.1.5 (Fig. 2.19): the five-point conic tangent to CB at B (q3 = 1)
-- The scheme of Fig. 2.16 (A(0,0), B(1,0), C(0.5,1), p2 = 0.7, q2 = 0.8, the free p1, q3 as there
-- 0.7 and 0.8) with A3 moved to B (q3 = 1: the tangent CB at B, (2.95)); conic.five_points2 gives
-- the corrected (2.93)-(2.96).  The tangent lines in red.
local A, B, C = P(0, 0), P(1, 0), P(0.5, 1)
local p1, q3, p2, q2 = 0.7, 1, 0.7, 0.8
fit{around = {P(-0.1, -0.15), P(1.1, 1.08)}}
path({A, C, B}, {color = 8}) line(A, B, 8)
local A1, A3 = (A - C) * p1 + C, (B - C) * q3 + C
local A2 = ((((A3 - A1) * p2 + A1) - C) * q2) + C
local arc = conic.five_points2{C = C, A = A, B = B, p1 = p1, p2 = p2, q2 = q2, q3 = q3}
arc:draw{color = 10}
local d0, d1 = arc:deriv(0), arc:deriv(1)
if p1 == 1 then line(A - d0 * 0.25, A + d0 * 0.6, 12) end
if q3 == 1 then line(B - d1 * 0.6, B + d1 * 0.25, 12) end
for _, p in ipairs{A, B, C, A1, A2, A3} do mark(p, "dot", 5, 15) end
label(p1 == 1 and "$A \\equiv A_1$" or "$A$", A) label(q3 == 1 and "$B \\equiv A_3$" or "$B$", B)
label("$C$", C) label("$A_2$", A2)
if p1 ~= 1 then label("$A_1$", A1) end
if q3 ~= 1 then label("$A_3$", A3) end
caption("q3 = 1", "bottom", 7)
