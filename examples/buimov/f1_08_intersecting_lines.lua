-- Two intersecting lines under T = [[1, 2], [1, -2]]: the meet goes to the meet
-- Buimov §1.6, Fig. 1.8: A[0 4], B[4 0] (x + y = 4) and C[-1 -1], D[3 3] (y = x) meet at
-- [2 2]; their images A*[4 -8], B*[4 8] (x = 4) and C*[-2 0], D*[6 0] (y = 0) meet at
-- [2 2] T = [4 0].

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); label(name, p, nil, colour)
end
local T = map.matrix({{1, 2, 0}, {1, -2, 0}, {0, 0, 1}}, "row")
local pts = {A = P(0, 4), B = P(4, 0), C = P(-1, -1), D = P(3, 3)}
fit{around = {P(-3, -9), P(7.5, 9)}, pad = 1.6, band = 20}
axes{x = {-3, 7.5}, y = {-9, 9}, ticks = 0, labels = false, color = 8}
label("$x$", P(7.5, 0), "s", 8); label("$y$", P(0, 9), "w", 8)
line(pts.A, pts.B, 15); line(pts.C, pts.D, 15)
line(T(pts.A), T(pts.B), 14); line(T(pts.C), T(pts.D), 14)
for _, n in ipairs{"A", "B", "C", "D"} do
  dot(pts[n], "$" .. n .. "$", 15); dot(T(pts[n]), "$" .. n .. "^*$", 14)
end
local X = meet(pts.A, pts.B, pts.C, pts.D)
dot(X, "(2, 2)", 15); dot(T(X), "(4, 0)", 14)
caption("[[0, 4], [4, 0], [-1, -1], [3, 3]] T = [[4, -8], [4, 8], [-2, 0], [6, 0]]", "bottom", 7)
