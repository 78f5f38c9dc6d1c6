-- The physical spline: a thin strip held at points by weights
-- Buimov §4.2, Fig. 4.1: the draughtsman's spline, an elastic lath laid through given points
-- and held there by weights ("ducks"), takes the shape of least bending energy, a curve with
-- continuous curvature; the cubic spline is its linearised model. Here the strip through five
-- points is the natural cubic spline (free ends, no bending moment at them: P'' = 0), the weights
-- drawn as blocks on it.

-- equal units on both axes: the box (x0, y0)-(x1, y1) centred above the caption line
local function frame(x0, y0, x1, y1, bare)
  local s = math.max((x1 - x0) / 580, (y1 - y0) / 390)
  local cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
  window(cx - 320 * s, cy - 250 * s, cx + 320 * s, cy + 230 * s)
  if bare then return end
  arrow(P(x0, 0), P(x1, 0), "end", 8); arrow(P(0, y0), P(0, y1), "end", 8)
  label("$x$", P(x1, 0), "s", 8); label("$y$", P(0, y1), "w", 8)
end
local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
-- a control polygon (grey) with its vertices lettered P_0, P_1, ... (or from first)
local function polygon(pts, first, colour)
  for i = 1, #pts - 1 do line(pts[i], pts[i + 1], colour or 8) end
  for i, p in ipairs(pts) do dot(p, "$P_{" .. (i - 1 + (first or 0)) .. "}$", 15) end
end
local pts = {P(0, 0.5), P(1.5, 1.6), P(3.2, 1.1), P(4.6, 2.0), P(6.2, 1.2)}
frame(-0.4, -0.4, 6.6, 2.8, true)
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
