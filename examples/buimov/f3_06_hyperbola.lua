-- The hyperbola with its asymptotes and the points of both recurrences
-- Buimov §3.5, Fig. 3.6: x^2/alpha^2 - y^2/beta^2 = 1, alpha = 2, beta = 1.5, the vertex (alpha, 0)
-- and the asymptotes y = +-(beta/alpha) x (dashed). Points of the sec/tan recurrence
-- x' = beta x/(beta cos dth - y sin dth), y' = beta (y + beta tan dth)/(beta - y tan dth) (the book
-- prints "+" in the last denominator; red) and of the ch/sh recurrence (green), dth = 0.1; the
-- branch (alpha ch t, beta sh t) is drawn at the book's t (plane.hyperbola), both branches.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
local a, b = 2, 1.5
fit{around = {P(-4.4, -3.2), P(4.4, 3.2)}, pad = 0.57, band = 20}
axes{x = {-4.4, 4.4}, y = {-3.2, 3.2}, ticks = 0, labels = false, color = 8}
label("$x$", P(4.4, 0), "s", 8); label("$y$", P(0, 3.2), "w", 8)
pen{dash = {4, 3}}
line(P(-4, -4 * b / a), P(4, 4 * b / a), 8); line(P(-4, 4 * b / a), P(4, -4 * b / a), 8)
pen()
local h = plane.hyperbola(a, b, -1.4, 1.4)
h:draw{color = 14}; h:draw{color = 14, map = map.reflect(P(0, 0), V(1, 0))}
for _, q in ipairs(plane.points("hyperbola_ch", {A = a, B = b, step = 0.1, n = 14,
  method = "recurrence"})) do dot(q, nil, 10) end
for _, q in ipairs(plane.points("hyperbola", {A = a, B = b, step = 0.1, n = 9,
  method = "recurrence"})) do dot(q, nil, 12) end
dot(P(a, 0), "($\\alpha$, 0)", 15); dot(P(-a, 0), "($-\\alpha$, 0)", 15)
label("$y = \\beta x/\\alpha$", P(4, 4 * b / a), nil, 8)
caption("$\\alpha$, $\\beta$ = 2, 1.5;  d$\\theta$ = 0.1:  sec/tan (red), ch/sh (green)",
  "bottom", 7)
