-- The parabola y^2 = 4px and the points of its recurrence
-- Buimov §3.4, Fig. 3.5: x = p th^2, y = 2p th (the book writes y^2 = 2px, but both its
-- parametrisations give y^2 = 4px); the recurrence x' = x + y dth + p dth^2, y' = y + 2p dth
-- (the book prints "- y dth") from the vertex, p = 1/2, dth = 0.2, ten steps to (0.5 th^2, th)
-- with th = 2: (2, 2); the fourth quadrant by reflection. The focus F = (p, 0).

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
local p = 0.5
fit{around = {P(-0.5, -2.6), P(3.2, 2.6)}, pad = 0.47, band = 20}
axes{x = {-0.5, 3.2}, y = {-2.6, 2.6}, ticks = 0, labels = false, color = 8}
label("$x$", P(3.2, 0), "s", 8); label("$y$", P(0, 2.6), "w", 8)
plane.parabola(p, -2.3, 2.3):draw{color = 14}
for _, q in ipairs(plane.points("parabola", {A = p, step = 0.2, n = 10, method = "recurrence"})) do
  dot(q, nil, 15); dot(P(q.x, -q.y), nil, 7)
end
dot(P(p, 0), "$F$", 12); dot(P(2, 2), "(2, 2)", 15)
pen{dash = {4, 3}}; line(P(-p, -2.4), P(-p, 2.4), 8); pen()
label("$x = -p$", P(-p, 2.4), nil, 8)
caption("p = 1/2, d$\\theta$ = 0.2:  x' = x + y d$\\theta$ + p d$\\theta$^2,  y' = y + 2p d$\\theta$", "bottom", 7)
