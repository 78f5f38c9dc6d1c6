-- A rotation about an arbitrary point: translate it to the origin, turn, translate back
-- Buimov §1.7.8: T = Tr(-m, -n) R(theta) Tr(m, n); about (m, n) = (2, 3) by 90° its third row
-- is [m + n, -m + n, 1] = [5 1 1] (the origin goes to (5, 1)). The triangle ABC (black), its
-- translate and turned translate (dashed) and the result A*B*C* (colour).

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
local C = P(2, 3)
local Tr = map.matrix({{1, 0, 0}, {0, 1, 0}, {-2, -3, 1}}, "row")
local R = map.matrix({{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}, "row")
local Tb = map.matrix({{1, 0, 0}, {0, 1, 0}, {2, 3, 1}}, "row")
local T = Tb * R * Tr                                 -- the book's Tr R Tr', applied left to right
local tri = {P(4, 3), P(5, 4), P(4, 5)}
local steps = {{}, {}, {}}
for i, p in ipairs(tri) do steps[1][i] = Tr(p); steps[2][i] = R(Tr(p)); steps[3][i] = T(p) end
frame(-2.5, -1.5, 5.8, 5.8)
pen{dash = {4, 3}}
path(steps[1], {closed = true, color = 8})
path(steps[2], {closed = true, color = 8})
pen()
path(tri, {closed = true, color = 15}); path(steps[3], {closed = true, color = 14})
plane.ellipse(C, 2, 2, 0, math.pi / 2):draw{color = 12}
dot(C, "($m$, $n$) = (2, 3)", 12); dot(T(P(0, 0)), "$O^*$ = (5, 1)", 14)
for i, n in ipairs{"A", "B", "C"} do dot(tri[i], "$" .. n .. "$", 15)
dot(steps[3][i], "$" .. n .. "^*$", 14) end
caption("$\\theta$ = 90°:  T = [[0, 1, 0], [-1, 0, 0], [5, 1, 1]]", "bottom", 7)
