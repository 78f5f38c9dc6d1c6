-- Konopatsky §1.2 (Fig. 1.1): the segment AB and its current point M = (B - A)t + A in space
-- The digest's A(1, 2, 0.5), B(4, 1, 3) and t = 0.4 (the book prints no numbers), in an
-- axonometric view with z up: the point equation holds per axis, x_M = (x_B - x_A)t + x_A and
-- so on, so the projections of A, M, B on each axis (dashed) divide it in the same ratio
-- t = AM/AB.
local A, B, t = P(1, 2, 0.5), P(4, 1, 3), 0.4
local M = (B - A) * t + A
local view = map.view{azimuth = -35, elevation = 20}
local O = P(0, 0, 0)
local X, Y, Z = P(5, 0, 0), P(0, 3, 0), P(0, 0, 3.6)
camera(view)
fit{around = {O, X, Y, Z, A, B}, pad = 0.5}
for _, ax in ipairs{X, Y, Z} do arrow(O, ax, "end", 7) end
local feet = {}
for i, p in ipairs{A, M, B} do feet[i] = {P(p.x, 0, 0), P(0, p.y, 0), P(0, 0, p.z)} end
pen{dash = {4, 3}}
for i, p in ipairs{A, M, B} do for _, q in ipairs(feet[i]) do line(p, q, 8) end end
pen()
line(A, B, 15)
for i, p in ipairs{A, M, B} do
  mark(p, "dot", 5, i == 2 and 14 or 15)
  for _, q in ipairs(feet[i]) do mark(q, "dot", 4, 11) end
end
label("$A$", A) label("$B$", B) label("$M$", M, nil, 14)
for i, s in ipairs{"A", "M", "B"} do
  label("$x_" .. s .. "$", feet[i][1], nil, 11)
  label("$y_" .. s .. "$", feet[i][2], nil, 11)
  label("$z_" .. s .. "$", feet[i][3], nil, 11)
end
label("$x$", X, nil, 7) label("$y$", Y, nil, 7) label("$z$", Z, nil, 7)
camera()
caption(string.format("M = (B - A)t + A,   t = AM/AB = %.2f", dist(A, M) / dist(A, B)), "bottom", 7)
