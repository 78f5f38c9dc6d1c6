-- The textbook's plane curves: circles by three points, two points and a radius, a point and slopes; conics and their point generators
-- Buimov ch. 3: Fig 3.1, the circle from (1, 1) with slope 1 to slope 0 at x = 3 (centre
-- (3, -1), r = sqrt 8) and the circle through (1, 1), (2, 2), (3, 2); example 2, the two circles
-- of radius 5 through (1, 1) and (3, 2) (the book finds one, rounded); Fig 3.2, points of a
-- circle by uniform x (explicit), uniform angle (parametric) and uniform t (rational); the
-- ellipse, parabola (y^2 = 4px) and hyperbola with its asymptotes, each drawn as an exact
-- rational curve with the points of the book's recurrence (corrected) as dots.
local function panel(ox, oy, s, caption, cx, cy)
  label(caption, P(cx, cy), "c", 7)
  return affine.frame(P(ox, oy), V(s, 0), V(0, -s))
end
local function dots(F, pts, colour)
  for _, p in ipairs(pts) do circle(F(p), 2, colour) end
end

-- Fig 3.1 and example 1
local F = panel(23, 115, 26, "Fig 3.1: point and slopes", 107, 20)
line(F(P(-0.5, 0)), F(P(5.5, 0)), 8); line(F(P(0, -1)), F(P(0, 3)), 8)
local s1, s2 = plane.circle_slopes(P(1, 1), 1, 3, 0)
pen{dash = {3, 3}}; s1.curve:draw{color = 8, map = F}; pen()
s1.arc:draw{color = 14, map = F}
line(F(P(0.2, 0.2)), F(P(1.8, 1.8)), 12)                   -- the slope 1 at the start
line(F(s1.finish - V(0.8, 0)), F(s1.finish + V(0.8, 0)), 12)  -- slope 0 at x = 3
label("(1, 1)", F(P(1, 1)), nil, 15); label("(3, 1.83)", F(s1.finish), nil, 15)
circle(F(s1.centre), 2, 14); label("C(3, -1)", F(s1.centre), nil, 14)
local c3 = plane.circle3(P(1, 1), P(2, 2), P(3, 2))
c3.arc:draw{color = 11, map = F}
for _, p in ipairs{P(2, 2), P(3, 2)} do circle(F(p), 2, 11) end
label("x^2+y^2-5x-y+4=0", F(P(2.5, 2.4)), nil, 11)

-- example 2: radius 5 through (1, 1) and (3, 2): both circles
F = panel(301, 143, 9.5, "r = 5 through two points", 320, 20)
local k1, k2 = plane.circle2r(P(1, 1), P(3, 2), 5)
k1.curve:draw{color = 14, map = F}; k2.curve:draw{color = 10, map = F}
for _, k in ipairs{{k1, 14}, {k2, 10}} do   -- the centres labelled inside their circles
  circle(F(k[1].centre), 2, k[2])
  label(string.format("(%.3f, %.3f)", k[1].centre.x, k[1].centre.y), F(k[1].centre), "e", k[2])
end
circle(F(P(1, 1)), 2, 15); circle(F(P(3, 2)), 2, 15)

-- Fig 3.2: a quarter circle in 10 steps by three methods, on radii 1, 0.8 and 0.6
F = panel(460, 200, 150, "Fig 3.2: 10 steps", 533, 20)
-- (uniform x: step r/10; uniform angle: pi/20; rational: t = tan(th/2) in steps of 0.1)
for _, m in ipairs{{1, "explicit", 0.1, 12}, {0.8, "param", math.pi / 20, 10}, {0.6, "rational", 0.1, 11}} do
  local r = m[1]
  plane.ellipse(P(0, 0), r, r, 0, math.pi / 2):draw{color = 8, map = F}
  dots(F, plane.points("circle", {A = r, step = m[2] == "explicit" and r / 10 or m[3], n = 10, method = m[2]}), m[4])
end
label("uniform x", P(458, 228), "c", 12); label("angle", P(522, 228), "c", 10); label("rational", P(595, 228), "c", 11)

-- the ellipse (alpha 3, beta 2), the parabola p = 0.5 and the hyperbola (2, 1.5) with the
-- points of the recurrences: dth = 0.1 (ellipse), 0.2 (parabola), 0.1 (hyperbola ch/sh)
F = panel(107, 370, 30, "ellipse 3, 2", 107, 262)
plane.ellipse(P(0, 0), 3, 2):draw{color = 14, map = F}
dots(F, plane.points("ellipse", {A = 3, B = 2, step = 0.1, n = 62, method = "recurrence"}), 15)
F = panel(270, 370, 28, "parabola p = 1/2", 320, 262)
line(F(P(-0.3, 0)), F(P(2.8, 0)), 8)
plane.parabola(0.5, -2.2, 2.2):draw{color = 14, map = F}
local pp = plane.points("parabola", {A = 0.5, step = 0.2, n = 11, method = "recurrence"})
dots(F, pp, 15)
for _, p in ipairs(pp) do circle(F(P(p.x, -p.y)), 2, 7) end   -- the fourth quadrant by reflection
F = panel(520, 370, 22, "hyperbola 2, 1.5", 533, 262)
pen{dash = {3, 3}}
line(F(P(-3.5, -3.5 * 0.75)), F(P(3.5, 3.5 * 0.75)), 8); line(F(P(-3.5, 3.5 * 0.75)), F(P(3.5, -3.5 * 0.75)), 8)
pen()
local h = plane.hyperbola(2, 1.5, -1.3, 1.3)
h:draw{color = 14, map = F}
h:draw{color = 14, map = F * map.reflect(P(0, 0), V(1, 0))}
dots(F, plane.points("hyperbola_ch", {A = 2, B = 1.5, step = 0.1, n = 13, method = "recurrence"}), 15)
dots(F, plane.points("hyperbola", {A = 2, B = 1.5, step = 0.1, n = 8, method = "recurrence"}), 12)
label("ch/sh", P(600, 450), "c", 15); label("sec/tan", P(600, 465), "c", 12)
