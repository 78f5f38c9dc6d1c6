-- A circle from a point and two slopes, and the circle through three points
-- Buimov §3.2, Fig. 3.1: from (1, 1) with the slope 1 there to the slope 0 at x = 3: with
-- dy/dx = -(2x + d)/(2y + e) the conditions give d = -6, e = 2, f = 2, the circle
-- x^2 + y^2 - 6x + 2y + 2 = 0, centre (3, -1), r = sqrt 8, ending at (3, 1.828427) (the book
-- rounds to 1.8). The slopes are read back from the implicit curve (plane.conic_slope). Beside
-- it (example 1) the circle through (1, 1), (2, 2), (3, 2): x^2 + y^2 - 5x - y + 4 = 0 (the book
-- prints "+ y"), centre (2.5, 0.5), r = 1.581139.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
local c = plane.circle_slopes(P(1, 1), 1, 3, 0)
local coef = {1, 0, 1, c.d, c.e, c.f}
local c3 = plane.circle3(P(1, 1), P(2, 2), P(3, 2))
fit{around = {P(-0.6, -4.2), P(6.4, 2.9)}, pad = 0.64, band = 20}
axes{x = {-0.6, 6.4}, y = {-4.2, 2.9}, ticks = 0, labels = false, color = 8}
label("$x$", P(6.4, 0), "s", 8); label("$y$", P(0, 2.9), "w", 8)
pen{dash = {4, 3}}; c.curve:draw{color = 8}; c3.curve:draw{color = 8}; pen()
c.arc:draw{color = 14}; c3.arc:draw{color = 11}
-- the two tangents, with the slopes of the implicit curve at the ends
local m1, m2 = plane.conic_slope(coef, P(1, 1)), plane.conic_slope(coef, c.finish)
line(P(0.3, 1 - 0.7 * m1), P(1.8, 1 + 0.8 * m1), 12)
line(c.finish - V(0.9, 0.9 * m2), c.finish + V(0.9, 0.9 * m2), 12)
dot(P(1, 1), "(1, 1)", 15); dot(c.finish, "(3, 1.83)", 14); dot(c.centre, "$C$ (3, -1)", 14)
dot(P(2, 2), nil, 11); dot(P(3, 2), nil, 11); dot(c3.centre, "(2.5, 0.5)", 11)
caption(string.format("d, e, f = %g, %g, %g;  slopes %g at (1, 1) and %g at x = 3",
  c.d, c.e, c.f, m1, m2 + 0.0 == 0 and 0 or m2), "bottom", 7)
