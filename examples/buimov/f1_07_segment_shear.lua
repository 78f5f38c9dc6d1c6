-- A segment under T = [[1, 2], [3, 1]]: its midpoint stays its midpoint
-- Buimov §1.4, Fig. 1.7: A = [0 1], B = [2 3] times T (lost in the conversion, recovered from
-- the printed result) give A* = [3 1], B* = [11 7]; the midpoint M = [1 2] goes to M* = [7 4],
-- the midpoint of A*B* (the same for every division ratio).

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
local T = map.matrix({{1, 2, 0}, {3, 1, 0}, {0, 0, 1}}, "row")
local A, B = P(0, 1), P(2, 3)
local M = mid(A, B)
frame(-1, -1, 12.5, 8)
line(A, B, 15); line(T(A), T(B), 14)
dot(A, "$A$", 15); dot(B, "$B$", 15); dot(M, "$M$", 15)
dot(T(A), "$A^*$", 14); dot(T(B), "$B^*$", 14); dot(T(M), "$M^*$", 14)
caption("[[0, 1], [2, 3]] T = [[3, 1], [11, 7]],  M* = (7, 4) = (A* + B*)/2", "bottom", 7)
