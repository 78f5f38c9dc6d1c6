-- A segment under T = [[1, 2], [3, 1]]: its midpoint stays its midpoint
-- Buimov §1.4, Fig. 1.7: A = [0 1], B = [2 3] times T (lost in the conversion, recovered from
-- the printed result) give A* = [3 1], B* = [11 7]; the midpoint M = [1 2] goes to M* = [7 4],
-- the midpoint of A*B* (the same for every division ratio).

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); label(name, p, nil, colour)
end
local T = map.matrix({{1, 2, 0}, {3, 1, 0}, {0, 0, 1}}, "row")
local A, B = P(0, 1), P(2, 3)
local M = mid(A, B)
fit{around = {P(-1, -1), P(12.5, 8)}, pad = 0.7, band = 20}
axes{x = {-1, 12.5}, y = {-1, 8}, ticks = 0, labels = false, color = 8}
label("$x$", P(12.5, 0), "s", 8); label("$y$", P(0, 8), "w", 8)
line(A, B, 15); line(T(A), T(B), 14)
dot(A, "$A$", 15); dot(B, "$B$", 15); dot(M, "$M$", 15)
dot(T(A), "$A^*$", 14); dot(T(B), "$B^*$", 14); dot(T(M), "$M^*$", 14)
caption("[[0, 1], [2, 3]] T = [[3, 1], [11, 7]],  M* = (7, 4) = (A* + B*)/2", "bottom", 7)
