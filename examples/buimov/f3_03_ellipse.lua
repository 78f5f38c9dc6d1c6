-- The ellipse: centre (m, n), semi-axes alpha > beta, the parameter theta
-- Buimov §3.3, Fig. 3.3: (x - m)^2/alpha^2 + (y - n)^2/beta^2 = 1, the point (m + alpha cos theta,
-- n + beta sin theta) drawn from the circles of radii alpha and beta (dashed); m = 1, n = 2,
-- alpha = 3, beta = 2 and theta = 1: the point (2.620907, 3.682942), plane.ellipse's parameter
-- being the book's theta exactly.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
local C, a, b, th = P(1, 2), 3, 2, 1
local e = plane.ellipse(C, a, b)
fit{around = {P(-2.6, -0.6), P(4.6, 5.4)}, pad = 0.54, band = 20}
axes{x = {-2.6, 4.6}, y = {-0.6, 5.4}, ticks = 0, labels = false, color = 8}
label("$x$", P(4.6, 0), "s", 8); label("$y$", P(0, 5.4), "w", 8)
pen{dash = {4, 3}}
plane.ellipse(C, a, a):draw{color = 8}; plane.ellipse(C, b, b):draw{color = 8}
local Pa, Pb, X = C + V(a * math.cos(th), a * math.sin(th)), C + V(b * math.cos(th), b
    * math.sin(th)), e(th)
line(C, Pa, 8); line(Pa, X, 8); line(Pb, X, 8)
pen()
e:draw{color = 14}
line(C - V(a, 0), C + V(a, 0), 7); line(C - V(0, b), C + V(0, b), 7)
angle_mark(C + V(1, 0), C, Pa, "$\\theta$", 30, 12)
dot(C, "($m$, $n$)", 15); dot(X, string.format("(%.6f, %.6f)", X.x, X.y), 14)
label("$\\alpha$", mid(C, C + V(a, 0)), "s", 7); label("$\\beta$", mid(C, C + V(0, b)), "w", 7)
caption("m, n = 1, 2;  $\\alpha$, $\\beta$ = 3, 2;  $\\theta$ = 1", "bottom", 7)
