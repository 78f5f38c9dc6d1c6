-- A uniform scale by 2: T = [[2, 0], [0, 2]]
-- Buimov §1.7.3, Fig. 1.11: A[3 1], B[3 2], C[1 2] give A*[6 2], B*[6 4], C*[2 4]: the shape is
-- kept, every length doubled, every point twice as far from the origin (the dashed rays).

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
local T = map.matrix({{2, 0, 0}, {0, 2, 0}, {0, 0, 1}}, "row")
local tri = {P(3, 1), P(3, 2), P(1, 2)}
local img = {}
for i, p in ipairs(tri) do img[i] = T(p) end
frame(-0.8, -0.8, 7, 5)
pen{dash = {4, 3}}; for _, p in ipairs(img) do line(P(0, 0), p, 8) end; pen()
path(tri, {closed = true, color = 15}); path(img, {closed = true, color = 14})
for i, n in ipairs{"A", "B", "C"} do dot(tri[i], "$" .. n .. "$", 15)
dot(img[i], "$" .. n .. "^*$", 14) end
caption("[[3, 1], [3, 2], [1, 2]] [[2, 0], [0, 2]] = [[6, 2], [6, 4], [2, 4]]", "bottom", 7)
