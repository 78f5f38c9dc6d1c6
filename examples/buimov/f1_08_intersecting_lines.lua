-- Two intersecting lines under T = [[1, 2], [1, -2]]: the meet goes to the meet
-- Buimov §1.6, Fig. 1.8: A[0 4], B[4 0] (x + y = 4) and C[-1 -1], D[3 3] (y = x) meet at
-- [2 2]; their images A*[4 -8], B*[4 8] (x = 4) and C*[-2 0], D*[6 0] (y = 0) meet at
-- [2 2] T = [4 0].

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
local T = map.matrix({{1, 2, 0}, {1, -2, 0}, {0, 0, 1}}, "row")
local pts = {A = P(0, 4), B = P(4, 0), C = P(-1, -1), D = P(3, 3)}
frame(-3, -9, 7.5, 9)
line(pts.A, pts.B, 15); line(pts.C, pts.D, 15)
line(T(pts.A), T(pts.B), 14); line(T(pts.C), T(pts.D), 14)
for _, n in ipairs{"A", "B", "C", "D"} do
  dot(pts[n], "$" .. n .. "$", 15); dot(T(pts[n]), "$" .. n .. "^*$", 14)
end
local X = meet(pts.A, pts.B, pts.C, pts.D)
dot(X, "(2, 2)", 15); dot(T(X), "(4, 0)", 14)
caption("[[0, 4], [4, 0], [-1, -1], [3, 3]] T = [[4, -8], [4, 8], [-2, 0], [6, 0]]", "bottom", 7)
