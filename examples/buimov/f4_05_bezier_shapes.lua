-- Cubic Bezier curves of four different polygons
-- Buimov §4.3, Fig. 4.5: the shape follows the polygon: an arch, an S, a loop when the inner
-- vertices cross over far, a cusp when they cross just so (x'(1/2) = 0; the book gives no points;
-- four polygons of the
-- same end points P0 = (0, 0), P3 = (3, 0), side by side, 4.2 units apart).

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
-- a control polygon (grey) with its vertices lettered P_0, P_1, ... (or from first)
local function polygon(pts, first, colour)
  for i = 1, #pts - 1 do line(pts[i], pts[i + 1], colour or 8) end
  for i, p in ipairs(pts) do dot(p, "$P_{" .. (i - 1 + (first or 0)) .. "}$", 15) end
end
local sets = {
  {P(0, 0), P(0.5, 2), P(2.5, 2), P(3, 0)},
  {P(0, 0), P(0.5, 2), P(2.5, -2), P(3, 0)},
  {P(0, 0), P(3.5, 2), P(-0.5, 2), P(3, 0)},
  {P(0, 0), P(3, 2), P(0, 2), P(3, 0)},
}
fit{around = {P(-0.4, -1.8), P(16.6, 2.4)}, pad = 0.88, band = 20}
for k, s in ipairs(sets) do
  local sh = {}
  for i, p in ipairs(s) do sh[i] = p + V(4.3 * (k - 1), 0) end
  for i = 1, 3 do line(sh[i], sh[i + 1], 8) end
  for i, p in ipairs(sh) do dot(p, "$P_" .. (i - 1) .. "$", 15) end
  bezier(sh):draw{color = 14}
end
caption("four polygons with the same ends:  arch, S, loop, cusp", "bottom", 7)
