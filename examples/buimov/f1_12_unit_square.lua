-- The unit square onto a parallelogram: area times |det T|
-- Buimov §1.7.4, Fig. 1.12: [[0, 0], [1, 0], [1, 1], [0, 1]] [[a, b], [c, d]] =
-- [[0, 0], [a, b], [a + c, b + d], [c, d]]: B* is the first row of T, D* the second. With
-- T = [[1, 2], [3, 1]] (the book keeps T general) the area is |ad - bc| = |det T| = 5.

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
local rows = {{1, 2}, {3, 1}}
local T = map.matrix({{1, 2, 0}, {3, 1, 0}, {0, 0, 1}}, "row")
local sq = {P(0, 0), P(1, 0), P(1, 1), P(0, 1)}
local img = {}
for i, p in ipairs(sq) do img[i] = T(p) end
frame(-0.6, -0.6, 4.6, 3.6)
path(img, {closed = true, color = 14}); hatch(img, 12, 45, 14)
path(sq, {closed = true, color = 15})
for i, n in ipairs{"A", "B", "C", "D"} do dot(sq[i], "$" .. n .. "$", 15) end
dot(img[2], "$B^*$ = ($a$, $b$)", 14)
dot(img[3], "$C^*$", 14)
dot(img[4], "$D^*$ = ($c$, $d$)", 14)
caption(string.format("T = [[1, 2], [3, 1]]:  S* = |det T| S = %g",
  math.abs(buimov.det(rows))), "bottom", 7)
