-- Konopatsky §2.1.5 (Figs. 2.18-2.20): the five-point conic with tangents at its ends
-- The scheme of Fig. 2.16 (A(0,0), B(1,0), C(0.5,1), p2 = 0.7, q2 = 0.8) when A1 moves to A
-- (p1 = 1: tangent CA at A, Fig. 2.18), when A3 moves to B (q3 = 1: tangent CB at B, Fig. 2.19)
-- and both (Fig. 2.20: a contour arc through A2 with tangents CA and CB, the corrected (2.96)).
-- The tangent lines are drawn in red; the free p1, q3 are 0.7 and 0.8 as in Fig. 2.16.
local A, B, C = P(0, 0), P(1, 0), P(0.5, 1)
local cases = {{1, 0.8, "Fig. 2.18  p1 = 1"}, {0.7, 1, "Fig. 2.19  q3 = 1"}, {1, 1, "Fig. 2.20  p1 = q3 = 1"}}
for i, cs in ipairs(cases) do
  local p1, q3, p2, q2 = cs[1], cs[2], 0.7, 0.8
  view(5 + (i - 1) * 211, 80, 210 + (i - 1) * 211, 400)
  window(-0.1, -0.45, 1.1, 1.4)
  path({A, C, B}, {color = 8}) line(A, B, 8)
  local A1, A3 = (A - C) * p1 + C, (B - C) * q3 + C
  local A2 = ((((A3 - A1) * p2 + A1) - C) * q2) + C
  local arc = conic.five_points2{C = C, A = A, B = B, p1 = p1, p2 = p2, q2 = q2, q3 = q3}
  arc:draw{color = 10}
  local d0, d1 = arc:deriv(0), arc:deriv(1)
  if p1 == 1 then line(A - d0 * 0.25, A + d0 * 0.6, 12) end
  if q3 == 1 then line(B - d1 * 0.6, B + d1 * 0.25, 12) end
  for _, pt in ipairs{{A, "A", "sw"}, {B, "B", "se"}, {C, "C", "n"}, {A1, p1 == 1 and "" or "A1", "w"},
                      {A2, "A2", "n"}, {A3, q3 == 1 and "" or "A3", "e"}} do
    circle(pt[1], 0.012, 15) label(pt[2], pt[1], pt[3], 15)
  end
  label(cs[3], P(-0.05, -0.3), "e", 7)
end
