-- Cubic Bezier curves of four different polygons
-- Buimov §4.3, Fig. 4.5: the shape follows the polygon: an arch, an S, a loop when the inner
-- vertices cross over far, a cusp when they cross just so (x'(1/2) = 0; the book gives no points;
-- four polygons of the
-- same end points P0 = (0, 0), P3 = (3, 0), side by side, 4.2 units apart).

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
local sets = {
  {P(0, 0), P(0.5, 2), P(2.5, 2), P(3, 0)},
  {P(0, 0), P(0.5, 2), P(2.5, -2), P(3, 0)},
  {P(0, 0), P(3.5, 2), P(-0.5, 2), P(3, 0)},
  {P(0, 0), P(3, 2), P(0, 2), P(3, 0)},
}
frame(-0.4, -1.8, 16.6, 2.4, true)
for k, s in ipairs(sets) do
  local sh = {}
  for i, p in ipairs(s) do sh[i] = p + V(4.3 * (k - 1), 0) end
  for i = 1, 3 do line(sh[i], sh[i + 1], 8) end
  for i, p in ipairs(sh) do dot(p, "$P_" .. (i - 1) .. "$", 15) end
  bezier(sh):draw{color = 14}
end
caption("four polygons with the same ends:  arch, S, loop, cusp", "bottom", 7)
