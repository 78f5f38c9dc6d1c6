-- The ellipse's points by the book's recurrence: equal steps of theta
-- Buimov §3.3, Fig. 3.4: x0 = alpha, y0 = 0, x' = x cos dth - (alpha/beta) y sin dth,
-- y' = (beta/alpha) x sin dth + y cos dth, alpha = 3, beta = 2, dth = 2 pi/32: equal steps of
-- the angle give points closer together where the ellipse is flatter (near (0, +-2)) than
-- where it turns fast. After ten steps of dth = 0.1 the recurrence is at (3 cos 1, 2 sin 1) =
-- (1.620907, 1.682942), marked.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
fit{around = {P(-3.6, -2.6), P(3.9, 2.7)}, pad = 0.48, band = 20}
axes{x = {-3.6, 3.9}, y = {-2.6, 2.7}, ticks = 0, labels = false, color = 8}
label("$x$", P(3.9, 0), "s", 8); label("$y$", P(0, 2.7), "w", 8)
plane.ellipse(P(0, 0), 3, 2):draw{color = 14}
for _, p in ipairs(plane.points("ellipse", {A = 3, B = 2, step = 2
    * math.pi / 32, n = 32, method = "recurrence"})) do
  line(P(0, 0), p, 8); dot(p, nil, 15)
end
local ten = plane.points("ellipse", {A = 3, B = 2, step = 0.1, n = 10, method = "recurrence"})[11]
mark(ten, "open", 10, 12); label(string.format("(%.6f, %.6f)", ten.x, ten.y), ten, nil, 12)
caption("32 steps of d$\\theta$ = 2 $\\pi$/32;  10 steps of 0.1 end at (3 cos 1, 2 sin 1)",
  "bottom", 7)
