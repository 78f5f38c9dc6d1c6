-- The overall scale s of the homogeneous matrix: x* = x/s, y* = y/s
-- Buimov §1.7.6, Fig. 1.14: [x y 1] [[1, 0, 0], [0, 1, 0], [0, 0, s]] = [x y s], the point
-- [x/s y/s]; s = 2 here (s > 1 shrinks), the same as [[1/s, 0], [0, 1/s]].

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); label(name, p, nil, colour)
end
local T = map.matrix({{1, 0, 0}, {0, 1, 0}, {0, 0, 2}}, "row")
local tri = {P(2, 1), P(6, 2), P(3, 5)}
local img = {}
for i, p in ipairs(tri) do img[i] = T(p) end
fit{around = {P(-0.8, -0.8), P(7, 6)}, pad = 0.61, band = 20}
axes{x = {-0.8, 7}, y = {-0.8, 6}, ticks = 0, labels = false, color = 8}
label("$x$", P(7, 0), "s", 8); label("$y$", P(0, 6), "w", 8)
pen{dash = {4, 3}}; for _, p in ipairs(tri) do line(P(0, 0), p, 8) end; pen()
path(tri, {closed = true, color = 15}); path(img, {closed = true, color = 14})
for i, n in ipairs{"A", "B", "C"} do dot(tri[i], "$" .. n .. "$", 15)
dot(img[i], "$" .. n .. "^*$", 14) end
caption("s = 2:  [6 2 1] T = [6 2 2] = [3 1 1]", "bottom", 7)
