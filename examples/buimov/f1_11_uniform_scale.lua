-- A uniform scale by 2: T = [[2, 0], [0, 2]]
-- Buimov §1.7.3, Fig. 1.11: A[3 1], B[3 2], C[1 2] give A*[6 2], B*[6 4], C*[2 4]: the shape is
-- kept, every length doubled, every point twice as far from the origin (the dashed rays).

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); label(name, p, nil, colour)
end
local T = map.matrix({{2, 0, 0}, {0, 2, 0}, {0, 0, 1}}, "row")
local tri = {P(3, 1), P(3, 2), P(1, 2)}
local img = {}
for i, p in ipairs(tri) do img[i] = T(p) end
fit{around = {P(-0.8, -0.8), P(7, 5)}, pad = 0.52, band = 20}
axes{x = {-0.8, 7}, y = {-0.8, 5}, ticks = 0, labels = false, color = 8}
label("$x$", P(7, 0), "s", 8); label("$y$", P(0, 5), "w", 8)
pen{dash = {4, 3}}; for _, p in ipairs(img) do line(P(0, 0), p, 8) end; pen()
path(tri, {closed = true, color = 15}); path(img, {closed = true, color = 14})
for i, n in ipairs{"A", "B", "C"} do dot(tri[i], "$" .. n .. "$", 15)
dot(img[i], "$" .. n .. "^*$", 14) end
caption("[[3, 1], [3, 2], [1, 2]] [[2, 0], [0, 2]] = [[6, 2], [6, 4], [2, 4]]", "bottom", 7)
