-- The ellipse: centre (m, n), semi-axes alpha > beta, the parameter theta
-- Buimov §3.3, Fig. 3.3: (x - m)^2/alpha^2 + (y - n)^2/beta^2 = 1, the point (m + alpha cos theta,
-- n + beta sin theta) drawn from the circles of radii alpha and beta (dashed); m = 1, n = 2,
-- alpha = 3, beta = 2 and theta = 1: the point (2.620907, 3.682942), plane.ellipse's parameter
-- being the book's theta exactly.

-- equal units on both axes: the box (x0, y0)-(x1, y1) centred above the caption line
local function frame(x0, y0, x1, y1)
  local s = math.max((x1 - x0) / 580, (y1 - y0) / 390)
  local cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
  window(cx - 320 * s, cy - 250 * s, cx + 320 * s, cy + 230 * s)
  arrow(P(x0, 0), P(x1, 0), "end", 8); arrow(P(0, y0), P(0, y1), "end", 8)
  label("$x$", P(x1, 0), "s", 8); label("$y$", P(0, y1), "w", 8)
end
local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
local C, a, b, th = P(1, 2), 3, 2, 1
local e = plane.ellipse(C, a, b)
frame(-2.6, -0.6, 4.6, 5.4)
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
