-- A triangle turned by 90° about the origin: T = [[0, 1], [-1, 0]]
-- Buimov §1.7.1, Fig. 1.9: A[3 -1], B[4 1], C[2 1] give A*[1 3], B*[-1 4], C*[-1 2]; the
-- arc shows the quarter turn of A (counter-clockwise, the book's positive sense).

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
local T = map.matrix({{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}, "row")
local tri = {P(3, -1), P(4, 1), P(2, 1)}
local img = {}
for i, p in ipairs(tri) do img[i] = T(p) end
frame(-2.5, -2, 5, 5)
path(tri, {closed = true, color = 15}); path(img, {closed = true, color = 14})
plane.ellipse(P(0, 0), math.sqrt(10), math.sqrt(10), math.atan(-1, 3), math.atan(3,
  1)):draw{color = 8}
for i, n in ipairs{"A", "B", "C"} do dot(tri[i], "$" .. n .. "$", 15)
dot(img[i], "$" .. n .. "^*$", 14) end
caption("[[3, -1], [4, 1], [2, 1]] [[0, 1], [-1, 0]] = [[1, 3], [-1, 4], [-1, 2]]", "bottom", 7)
