-- The physical spline: a thin strip held at points by weights
-- Buimov §4.2, Fig. 4.1: the draughtsman's spline, an elastic lath laid through given points
-- and held there by weights ("ducks"), takes the shape of least bending energy, a curve with
-- continuous curvature; the cubic spline is its linearised model. Here the strip through five
-- points is the natural cubic spline (free ends, no bending moment at them: P'' = 0), the weights
-- drawn as blocks on it.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
-- a control polygon (grey) with its vertices lettered P_0, P_1, ... (or from first)
local function polygon(pts, first, colour)
  for i = 1, #pts - 1 do line(pts[i], pts[i + 1], colour or 8) end
  for i, p in ipairs(pts) do dot(p, "$P_{" .. (i - 1 + (first or 0)) .. "}$", 15) end
end
local pts = {P(0, 0.5), P(1.5, 1.6), P(3.2, 1.1), P(4.6, 2.0), P(6.2, 1.2)}
fit{around = {P(-0.4, -0.4), P(6.6, 2.8)}, pad = 0.36, band = 20}
local s, tangents = buimov.spline(pts, {ends = "natural", param = "chord"})
s:draw{color = 14}
for i, p in ipairs(pts) do
  local d = unit(tangents[i])
  local nrm = V(-d.y, d.x)
  -- a weight sitting on the strip: a small block above the point
  path({p + nrm * 0.05 - d * 0.18, p + nrm * 0.05 + d * 0.18, p + nrm * 0.35 + d * 0.14, p + nrm
      * 0.35 - d * 0.14}, {closed = true, color = 7})
  dot(p, "$P_{" .. i .. "}$", 15)
end
caption("the strip: natural cubic spline through P1..P5 (chord lengths)", "bottom", 7)
