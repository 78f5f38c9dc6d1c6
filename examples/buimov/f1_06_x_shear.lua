-- A shear along x: T = [[1, 0], [c, 1]], c = 3
-- Buimov §1.3, Fig. 1.6: [x y] T = [x + c y, y]: y is kept, x grows with y (c is not given in the
-- book; 3 here; the text calls it Fig. 2.6). The triangle ABC (black) and its image A*B*C* (colour)
-- under the book's row-vector map p* = p T, drawn at true shape.
local T = map.matrix({{1, 0, 0}, {3, 1, 0}, {0, 0, 1}}, "row")
local tri = {P(0.5, 0.5), P(1.5, 0.5), P(1, 1.5)}
local img = {}
for i, p in ipairs(tri) do img[i] = T(p) end
local xs, ys = {0}, {0}
for _, p in ipairs(tri) do xs[#xs + 1] = p.x; ys[#ys + 1] = p.y end
for _, p in ipairs(img) do xs[#xs + 1] = p.x; ys[#ys + 1] = p.y end
local x0, x1 = math.min(table.unpack(xs)) - 0.6, math.max(table.unpack(xs)) + 0.8
local y0, y1 = math.min(table.unpack(ys)) - 0.6, math.max(table.unpack(ys)) + 0.8
-- equal units on both axes, the box centred above the caption line
local s = math.max((x1 - x0) / 580, (y1 - y0) / 390)
local cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
window(cx - 320 * s, cy - 250 * s, cx + 320 * s, cy + 230 * s)
arrow(P(x0, 0), P(x1, 0), "end", 8); arrow(P(0, y0), P(0, y1), "end", 8)
label("$x$", P(x1, 0), "s", 8); label("$y$", P(0, y1), "w", 8)
path(tri, {closed = true, color = 15}); path(img, {closed = true, color = 14})
for i, n in ipairs{"A", "B", "C"} do
  mark(tri[i], "dot", 4, 15); label("$" .. n .. "$", tri[i])
  mark(img[i], "dot", 4, 14); label("$" .. n .. "^*$", img[i], nil, 14)
end
caption("T = [[1, 0], [3, 1]]: x* = x + 3y", "bottom", 7)
