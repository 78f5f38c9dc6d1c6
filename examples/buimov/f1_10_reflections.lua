-- A triangle reflected about the line y = x and about the x axis
-- Buimov §1.7.2, Fig. 1.10: A[8 1], B[6 2], C[7 3]; T = [[0, 1], [1, 0]] (about y = x) gives
-- A*[1 8], B*[2 6], C*[3 7]; T = [[1, 0], [0, -1]] (about y = 0) gives A**[8 -1], B**[6 -2],
-- C**[7 -3]. The mirror y = x is dashed.

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
local Txy = map.matrix({{0, 1, 0}, {1, 0, 0}, {0, 0, 1}}, "row")
local Tx = map.matrix({{1, 0, 0}, {0, -1, 0}, {0, 0, 1}}, "row")
local tri = {P(8, 1), P(6, 2), P(7, 3)}
local a, b = {}, {}
for i, p in ipairs(tri) do a[i] = Txy(p); b[i] = Tx(p) end
frame(-1, -4, 10, 9)
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
