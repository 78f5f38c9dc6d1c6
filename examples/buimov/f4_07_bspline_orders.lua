-- B-splines of order k = 2, 3, 4 on one polygon of four vertices
-- Buimov §4.4, Fig. 4.7: on P0..P3 the order k = 2 gives the polygon itself (knots [0 0 1 2 3 3]),
-- k = 3 a curve nearer the polygon (knots [0 0 0 1 2 2 2]) and k = 4, the number of vertices, the
-- Bezier curve (knots [0 0 0 0 1 1 1 1]); the lower the order, the closer the curve. The
-- vertices (1, 1), (2, 3), (4, 3), (3, 1) of the Bezier example; k = 3 gives P(1) = (3, 3).

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
-- a control polygon (grey) with its vertices lettered P_0, P_1, ... (or from first)
local function polygon(pts, first, colour)
  for i = 1, #pts - 1 do line(pts[i], pts[i + 1], colour or 8) end
  for i, p in ipairs(pts) do dot(p, "$P_{" .. (i - 1 + (first or 0)) .. "}$", 15) end
end
local pts = {P(1, 1), P(2, 3), P(4, 3), P(3, 1)}
fit{around = {P(0.4, 0.4), P(4.6, 3.6)}, pad = 0.29, band = 20}
local colours = {[2] = 12, [3] = 10, [4] = 14}
for k = 2, 4 do
  local c = buimov.bspline(pts, k)
  c:draw{color = colours[k]}
  local q = buimov.knots(pts, k)
  label("$k = " .. k .. "$", c(0.62 * q[#q]), nil, colours[k])
end
for i, p in ipairs(pts) do dot(p, "$P_" .. (i - 1) .. "$", 15) end
caption("k = 2: the polygon;  k = 3;  k = 4 = the number of vertices: the Bezier curve", "bottom",
  7)
