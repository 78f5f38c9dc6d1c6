-- The unit square turned by theta: T = [[cos theta, sin theta], [-sin theta, cos theta]]
-- Buimov §1.7.5, Fig. 1.13: A* = [0 0], B* = [cos, sin], C* = [cos - sin, cos + sin],
-- D* = [-sin, cos]; theta = 30° here (the book keeps it general): C* = (0.366025, 1.366025).

-- equal units on both axes: the box (x0, y0)-(x1, y1) centred above the caption line
local function frame(x0, y0, x1, y1)
  local s = math.max((x1 - x0) / 580, (y1 - y0) / 390)
  local cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
  window(cx - 320 * s, cy - 250 * s, cx + 320 * s, cy + 230 * s)
  arrow(P(x0, 0), P(x1, 0), "end", 8); arrow(P(0, y0), P(0, y1), "end", 8)
  label("$x$", P(x1, 0), "s", 8); label("$y$", P(0, y1), "w", 8)
end
local function dot(p, name, colour)
  mark(p, "dot", 4, colour); label(name, p, nil, colour)
end
local th = math.rad(30)
local T = map.matrix({{math.cos(th), math.sin(th), 0}, {-math.sin(th), math.cos(th), 0}, {0, 0,
  1}}, "row")
local sq = {P(0, 0), P(1, 0), P(1, 1), P(0, 1)}
local img = {}
for i, p in ipairs(sq) do img[i] = T(p) end
frame(-0.9, -0.4, 1.6, 1.7)
path(sq, {closed = true, color = 15}); path(img, {closed = true, color = 14})
angle_mark(sq[2], sq[1], img[2], "$\\theta$", 40, 12)
for i, n in ipairs{"A", "B", "C", "D"} do dot(sq[i], "$" .. n .. "$", 15) end
for i, n in ipairs{"B", "C", "D"} do dot(img[i + 1], "$" .. n .. "^*$", 14) end
caption("$\\theta$ = 30°:  C* = (cos - sin, cos + sin) = (0.366, 1.366)", "bottom", 7)
