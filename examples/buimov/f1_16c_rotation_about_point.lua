-- A rotation about an arbitrary point: translate it to the origin, turn, translate back
-- Buimov §1.7.8: T = Tr(-m, -n) R(theta) Tr(m, n); about (m, n) = (2, 3) by 90° its third row
-- is [m + n, -m + n, 1] = [5 1 1] (the origin goes to (5, 1)). The triangle ABC (black), its
-- translate and turned translate (dashed) and the result A*B*C* (colour).

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
fit{around = {P(-2.5, -1.5), P(5.8, 5.8)}, pad = 0.66, band = 20}
axes{x = {-2.5, 5.8}, y = {-1.5, 5.8}, ticks = 0, labels = false, color = 8}
label("$x$", P(5.8, 0), "s", 8); label("$y$", P(0, 5.8), "w", 8)
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
