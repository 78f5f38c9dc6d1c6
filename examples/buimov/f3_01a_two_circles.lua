-- The two circles of radius 5 through two points
-- Buimov §3.2, example 2: through (1, 1) and (3, 2) with r = 5 the book iterates to the rounded
-- d = -8.4, e = 5.7, f = 0.7, centre (4.2, -2.85); exactly the centres are (4.179449, -2.858899)
-- (d = -8.358899, e = 5.717798, f = 0.641101; the book's circle) and (-0.179449, 5.858899),
-- which the book does not mention.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
local k1, k2 = plane.circle2r(P(1, 1), P(3, 2), 5)
fit{around = {P(-5.8, -8.2), P(9.6, 11.2)}, pad = 1.7, band = 20}
axes{x = {-5.8, 9.6}, y = {-8.2, 11.2}, ticks = 0, labels = false, color = 8}
label("$x$", P(9.6, 0), "s", 8); label("$y$", P(0, 11.2), "w", 8)
k1.curve:draw{color = 14}; k2.curve:draw{color = 10}
for _, k in ipairs{{k1, 14}, {k2, 10}} do
  dot(k[1].centre, string.format("(%.6f, %.6f)", k[1].centre.x, k[1].centre.y), k[2])
end
dot(P(1, 1), "(1, 1)", 15); dot(P(3, 2), "(3, 2)", 15)
caption(string.format("the book's circle: d = %.6f, e = %.6f, f = %.6f",
  k1.d, k1.e, k1.f), "bottom", 7)
