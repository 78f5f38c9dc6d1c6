-- A triangle turned by 90° about the origin: T = [[0, 1], [-1, 0]]
-- Buimov §1.7.1, Fig. 1.9: A[3 -1], B[4 1], C[2 1] give A*[1 3], B*[-1 4], C*[-1 2]; the
-- arc shows the quarter turn of A (counter-clockwise, the book's positive sense).

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); label(name, p, nil, colour)
end
local T = map.matrix({{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}, "row")
local tri = {P(3, -1), P(4, 1), P(2, 1)}
local img = {}
for i, p in ipairs(tri) do img[i] = T(p) end
fit{around = {P(-2.5, -2), P(5, 5)}, pad = 0.63, band = 20}
axes{x = {-2.5, 5}, y = {-2, 5}, ticks = 0, labels = false, color = 8}
label("$x$", P(5, 0), "s", 8); label("$y$", P(0, 5), "w", 8)
path(tri, {closed = true, color = 15}); path(img, {closed = true, color = 14})
plane.ellipse(P(0, 0), math.sqrt(10), math.sqrt(10), math.atan(-1, 3), math.atan(3,
  1)):draw{color = 8}
for i, n in ipairs{"A", "B", "C"} do dot(tri[i], "$" .. n .. "$", 15)
dot(img[i], "$" .. n .. "^*$", 14) end
caption("[[3, -1], [4, 1], [2, 1]] [[0, 1], [-1, 0]] = [[1, 3], [-1, 4], [-1, 2]]", "bottom", 7)
