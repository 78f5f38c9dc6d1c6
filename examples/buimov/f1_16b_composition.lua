-- Composition is not commutative: a quarter turn and a reflection in either order
-- Buimov §1.7.3 and §1.7.8: T1 = [[0, 1], [-1, 0]] (90°), T2 = [[-1, 0], [0, 1]] (about x = 0).
-- The point (5, 7) through T1 then T2 (T1 T2 = [[0, 1], [1, 0]]) goes to (7, 5), through T2
-- then T1 (T2 T1 = [[0, -1], [-1, 0]]) to (-7, -5): the book prints [-x -y] for [-y -x].
-- Dashed: the intermediate points A T1 and A T2.

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
local T1 = map.matrix({{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}, "row")
local T2 = map.matrix({{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, "row")
local A = P(5, 7)
frame(-8.5, -6.5, 8.5, 8.5)
local a1, a2 = T1(A), T2(A)
pen{dash = {4, 3}}
line(A, a1, 8); line(a1, T2(a1), 10); line(A, a2, 8); line(a2, T1(a2), 12)
pen()
dot(A, "$A$ = (5, 7)", 15)
dot(a1, "$AT_1$", 8); dot(a2, "$AT_2$", 8)
dot(T2(a1), "$(AT_1)T_2$ = (7, 5)", 10); dot(T1(a2), "$(AT_2)T_1$ = (-7, -5)", 12)
caption("T1 T2 = [[0, 1], [1, 0]],  T2 T1 = [[0, -1], [-1, 0]]", "bottom", 7)
