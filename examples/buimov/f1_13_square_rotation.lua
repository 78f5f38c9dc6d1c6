-- The unit square turned by theta: T = [[cos theta, sin theta], [-sin theta, cos theta]]
-- Buimov §1.7.5, Fig. 1.13: A* = [0 0], B* = [cos, sin], C* = [cos - sin, cos + sin],
-- D* = [-sin, cos]; theta = 30° here (the book keeps it general): C* = (0.366025, 1.366025).

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); label(name, p, nil, colour)
end
local th = math.rad(30)
local T = map.matrix({{math.cos(th), math.sin(th), 0}, {-math.sin(th), math.cos(th), 0}, {0, 0,
  1}}, "row")
local sq = {P(0, 0), P(1, 0), P(1, 1), P(0, 1)}
local img = {}
for i, p in ipairs(sq) do img[i] = T(p) end
fit{around = {P(-0.9, -0.4), P(1.6, 1.7)}, pad = 0.19, band = 20}
axes{x = {-0.9, 1.6}, y = {-0.4, 1.7}, ticks = 0, labels = false, color = 8}
label("$x$", P(1.6, 0), "s", 8); label("$y$", P(0, 1.7), "w", 8)
path(sq, {closed = true, color = 15}); path(img, {closed = true, color = 14})
angle_mark(sq[2], sq[1], img[2], "$\\theta$", 40, 12)
for i, n in ipairs{"A", "B", "C", "D"} do dot(sq[i], "$" .. n .. "$", 15) end
for i, n in ipairs{"B", "C", "D"} do dot(img[i + 1], "$" .. n .. "^*$", 14) end
caption("$\\theta$ = 30°:  C* = (cos - sin, cos + sin) = (0.366, 1.366)", "bottom", 7)
