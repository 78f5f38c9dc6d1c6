-- A triangle reflected about the line y = x and about the x axis
-- Buimov §1.7.2, Fig. 1.10: A[8 1], B[6 2], C[7 3]; T = [[0, 1], [1, 0]] (about y = x) gives
-- A*[1 8], B*[2 6], C*[3 7]; T = [[1, 0], [0, -1]] (about y = 0) gives A**[8 -1], B**[6 -2],
-- C**[7 -3]. The mirror y = x is dashed.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); label(name, p, nil, colour)
end
local Txy = map.matrix({{0, 1, 0}, {1, 0, 0}, {0, 0, 1}}, "row")
local Tx = map.matrix({{1, 0, 0}, {0, -1, 0}, {0, 0, 1}}, "row")
local tri = {P(8, 1), P(6, 2), P(7, 3)}
local a, b = {}, {}
for i, p in ipairs(tri) do a[i] = Txy(p); b[i] = Tx(p) end
fit{around = {P(-1, -4), P(10, 9)}, pad = 1.2, band = 20}
axes{x = {-1, 10}, y = {-4, 9}, ticks = 0, labels = false, color = 8}
label("$x$", P(10, 0), "s", 8); label("$y$", P(0, 9), "w", 8)
pen{dash = {4, 3}}; line(P(0, 0), P(8.5, 8.5), 8); pen()
path(tri, {closed = true, color = 15})
path(a, {closed = true, color = 14})
path(b, {closed = true, color = 11})
for i, n in ipairs{"A", "B", "C"} do
  dot(tri[i], "$" .. n .. "$", 15)
  dot(a[i], "$" .. n .. "^*$", 14)
  dot(b[i], "$" .. n .. "^{**}$", 11)
end
label("$y = x$", P(8.5, 8.5), nil, 8)
caption("about y = x: [[0, 1], [1, 0]];  about y = 0: [[1, 0], [0, -1]]", "bottom", 7)
