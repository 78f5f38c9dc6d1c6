-- Cubic segments with the same end points and directions but different tangent lengths
-- Buimov §4.2, Fig. 4.3: the segment P1 = (0, 0) to P2 = (4, 0) with the end tangents along
-- (1, 1) and (1, -1) scaled by k = 1, 2, 4, 8: the longer the tangents, the fuller the curve
-- (the book draws such a family without numbers).

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
-- a control polygon (grey) with its vertices lettered P_0, P_1, ... (or from first)
local function polygon(pts, first, colour)
  for i = 1, #pts - 1 do line(pts[i], pts[i + 1], colour or 8) end
  for i, p in ipairs(pts) do dot(p, "$P_{" .. (i - 1 + (first or 0)) .. "}$", 15) end
end
local P1, P2 = P(0, 0), P(4, 0)
fit{around = {P(-0.6, -0.6), P(4.8, 3.3)}, pad = 0.35, band = 20}
axes{x = {-0.6, 4.8}, y = {-0.6, 3.3}, ticks = 0, labels = false, color = 8}
label("$x$", P(4.8, 0), "s", 8); label("$y$", P(0, 3.3), "w", 8)
local colours = {11, 10, 14, 12}
for i, k in ipairs{1, 2, 4, 8} do
  local seg = buimov.hermite(P1, P2, V(k, k), V(k, -k))
  seg:draw{color = colours[i]}
  label("$k = " .. k .. "$", seg(0.5), nil, colours[i])
end
vector(P1, V(0.7, 0.7), 7); vector(P2, V(0.7, -0.7), 7)
dot(P1, "$P_1$", 15); dot(P2, "$P_2$", 15)
caption("P'1 = k (1, 1), P'2 = k (1, -1):  k = 1, 2, 4, 8", "bottom", 7)
