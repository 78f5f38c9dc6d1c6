-- Konopatsky §4.9 (Figs. 4.3-4.5): interpolation contour arcs with end tangents
-- The digest's nodes M = (0,0), (3,2), (6,2), (9,0) with the tangent handles C2 = (0,2) and
-- C5 = (9,2) (convex, Fig. 4.4a) or C5 = (9,-2) (with an inflection, Fig. 4.4b): the quintic
-- through the four nodes at u = 0, 1/3, 2/3, 1 with M'(0) = 5(C2 - M1), M'(1) = 5(M4 - C5)
-- (Fig. 4.3's scheme).  Bottom right (Fig. 4.5): the cubic through three nodes with the start
-- tangent M1C2 only.
local function mark(p, name, _, c) circle(p, 0.1, c or 15) label(name, p, nil, c or 15) end
local M = {P(0, 0), P(3, 2), P(6, 2), P(9, 0)}
local C2 = P(0, 2)
for i, C5 in ipairs{P(9, 2), P(9, -2)} do
  view(5 + (i - 1) * 315, 10, 310 + (i - 1) * 315, 235)
  window(-1.5, -3, 10.5, 4)
  local arc = interp.arc(M, C2, C5)
  pen{dash = {4, 3}} line(M[1], C2, 12) line(M[4], C5, 12) pen()
  arc:draw{color = 10}
  for j, p in ipairs(M) do mark(p, "$M_" .. j .. "$", "s") end
  mark(C2, "$C_2$", "n", 12) mark(C5, "$C_5$", "n", 12)
  label(i == 1 and "Fig. 4.4a convex" or "Fig. 4.4b inflection", P(-1.3, -2.6), "e", 7)
end
view(5, 245, 310, 470)
window(-1.5, -3, 10.5, 4)
local cps = interp.controls(M)
path(cps, {color = 8})
interp.lagrange(M):draw{color = 14}
for j, p in ipairs(M) do mark(p, "$M_" .. j .. "$", "s") end
label("order 3 through the same nodes", P(-1.3, -2.6), "e", 7)
view(320, 245, 625, 470)
window(-1.5, -3, 10.5, 4)
local M3 = {P(0, 0), P(4.5, 2), P(9, 0)}
local C2b = P(1, 3)
local arc3 = interp.arc(M3, C2b)
pen{dash = {4, 3}} line(M3[1], C2b, 12) pen()
arc3:draw{color = 10}
for j, p in ipairs(M3) do mark(p, "$M_" .. j .. "$", "s") end
mark(C2b, "$C_2$", "n", 12)
label("Fig. 4.5 one tangent M1C2", P(-1.3, -2.6), "e", 7)
