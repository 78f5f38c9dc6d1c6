-- Composition is not commutative: a quarter turn and a reflection in either order
-- Buimov §1.7.3 and §1.7.8: T1 = [[0, 1], [-1, 0]] (90°), T2 = [[-1, 0], [0, 1]] (about x = 0).
-- The point (5, 7) through T1 then T2 (T1 T2 = [[0, 1], [1, 0]]) goes to (7, 5), through T2
-- then T1 (T2 T1 = [[0, -1], [-1, 0]]) to (-7, -5): the book prints [-x -y] for [-y -x].
-- Dashed: the intermediate points A T1 and A T2.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); label(name, p, nil, colour)
end
local T1 = map.matrix({{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}, "row")
local T2 = map.matrix({{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, "row")
local A = P(5, 7)
fit{around = {P(-8.5, -6.5), P(8.5, 8.5)}, pad = 1.3, band = 20}
axes{x = {-8.5, 8.5}, y = {-6.5, 8.5}, ticks = 0, labels = false, color = 8}
label("$x$", P(8.5, 0), "s", 8); label("$y$", P(0, 8.5), "w", 8)
local a1, a2 = T1(A), T2(A)
pen{dash = {4, 3}}
line(A, a1, 8); line(a1, T2(a1), 10); line(A, a2, 8); line(a2, T1(a2), 12)
pen()
dot(A, "$A$ = (5, 7)", 15)
dot(a1, "$AT_1$", 8); dot(a2, "$AT_2$", 8)
dot(T2(a1), "$(AT_1)T_2$ = (7, 5)", 10); dot(T1(a2), "$(AT_2)T_1$ = (-7, -5)", 12)
caption("T1 T2 = [[0, 1], [1, 0]],  T2 T1 = [[0, -1], [-1, 0]]", "bottom", 7)
