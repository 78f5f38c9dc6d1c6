-- Konopatsky §4.9 (Fig. 4.4 a, b): the four-node contour arc, convex and with an inflection
-- The digest's nodes M = (0,0), (3,2), (6,2), (9,0), C2 = (0,2) and C5 = (9,2) (a, convex, top)
-- or C5 = (9,-2) (b, with an inflection, bottom): the quintic of interp.arc through the nodes
-- with the end tangents M1C2 and C5M4 (red, dashed).
local M = {P(0, 0), P(3, 2), P(6, 2), P(9, 0)}
local C2 = P(0, 2)
for i, C5 in ipairs{P(9, 2), P(9, -2)} do
  view(100, 5 + (i - 1) * 237, 540, 237 + (i - 1) * 237)
  window(-1.5, -2.9, 10.5, 3.43)   -- 440 x 232 px: equal units
  pen{dash = {4, 3}} line(M[1], C2, 12) line(M[4], C5, 12) pen()
  interp.arc(M, C2, C5):draw{color = 10}
  for j, p in ipairs(M) do mark(p, "dot", 5, 15) label("$M_" .. j .. "$", p) end
  mark(C2, "dot", 5, 12) mark(C5, "dot", 5, 12)
  label("$C_2$", C2, nil, 12) label("$C_5$", C5, nil, 12)
  label(i == 1 and "(a) convex" or "(b) inflection", P(-1.3, -2.6), "e", 7)
end
