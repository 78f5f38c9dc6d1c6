-- Points of a circle by three methods: uniform x, uniform angle, uniform rational parameter
-- Buimov §3.2, Fig. 3.2: a quarter of the unit circle in 10 steps: the explicit y = sqrt(1 - x^2)
-- with a uniform step in x crowds its points near the x axis (red), the parametric (cos th,
-- sin th) with a uniform step in th spaces them evenly (green), the rational ((1 - t^2)/(1 + t^2),
-- 2t/(1 + t^2)) with a uniform step in t = tan(th/2) lies between (blue). Three radii 1, 0.8,
-- 0.6 keep the three sets apart.

local function dot(p, name, colour)
  mark(p, "dot", 4, colour); if name then label(name, p, nil, colour) end
end
fit{around = {P(-0.15, -0.15), P(1.25, 1.15)}, pad = 0.12, band = 20}
axes{x = {-0.15, 1.25}, y = {-0.15, 1.15}, ticks = 0, labels = false, color = 8}
label("$x$", P(1.25, 0), "s", 8); label("$y$", P(0, 1.15), "w", 8)
local sets = {{1, "explicit", 0.1, 12, "uniform $x$"}, {0.8, "param", math.pi / 20, 10,
  "uniform $\\theta$"},
              {0.6, "rational", 0.1, 11, "uniform $t$"}}
for _, m in ipairs(sets) do
  local r = m[1]
  plane.ellipse(P(0, 0), r, r, 0, math.pi / 2):draw{color = 8}
  local pts = plane.points("circle", {A = r, step = m[2] == "explicit" and r / 10 or m[3], n = 10,
    method = m[2]})
  for _, p in ipairs(pts) do dot(p, nil, m[4]) end
  label(m[5], P(r * 0.68, r * 0.68 + 0.04), nil, m[4])
end
caption("10 steps:  x = 0.1 r,  $\\theta$ = $\\pi$/20,  t = 0.1", "bottom", 7)
