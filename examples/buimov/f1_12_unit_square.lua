-- The unit square onto a parallelogram: area times |det T|
-- Buimov §1.7.4, Fig. 1.12: [[0, 0], [1, 0], [1, 1], [0, 1]] [[a, b], [c, d]] =
-- [[0, 0], [a, b], [a + c, b + d], [c, d]]: B* is the first row of T, D* the second. With
-- T = [[1, 2], [3, 1]] (the book keeps T general) the area is |ad - bc| = |det T| = 5.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); label(name, p, nil, colour)
end
local rows = {{1, 2}, {3, 1}}
local T = map.matrix({{1, 2, 0}, {3, 1, 0}, {0, 0, 1}}, "row")
local sq = {P(0, 0), P(1, 0), P(1, 1), P(0, 1)}
local img = {}
for i, p in ipairs(sq) do img[i] = T(p) end
fit{around = {P(-0.6, -0.6), P(4.6, 3.6)}, pad = 0.38, band = 20}
axes{x = {-0.6, 4.6}, y = {-0.6, 3.6}, ticks = 0, labels = false, color = 8}
label("$x$", P(4.6, 0), "s", 8); label("$y$", P(0, 3.6), "w", 8)
path(img, {closed = true, color = 14}); hatch(img, 12, 45, 14)
path(sq, {closed = true, color = 15})
for i, n in ipairs{"A", "B", "C", "D"} do dot(sq[i], "$" .. n .. "$", 15) end
dot(img[2], "$B^*$ = ($a$, $b$)", 14)
dot(img[3], "$C^*$", 14)
dot(img[4], "$D^*$ = ($c$, $d$)", 14)
caption(string.format("T = [[1, 2], [3, 1]]:  S* = |det T| S = %g",
  math.abs(buimov.det(rows))), "bottom", 7)
