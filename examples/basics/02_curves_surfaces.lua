-- Curves, surfaces and maps: one type of each, drawn as paths with their letters
-- Left: a cubic Bezier with its control polygon, a quarter circle as a rational quadratic
-- (weights 1, cos 45°, 1), a natural cubic spline through five nodes.  Right: a surface of
-- revolution in isometric projection, its profile a B-spline,, drawn as a wireframe of iso-lines.
local A, B, C, D = P(40, 200), P(90, 40), P(250, 40), P(300, 200)
pen{dash = {4, 3}}
path({A, B, C, D}, {color = 8})
pen()
bezier{A, B, C, D}:draw{color = 14}
local points = {A = A, B = B, C = C, D = D}
for _, name in ipairs{"A", "B", "C", "D"} do   -- a list, not pairs: the same file every run
  local p = points[name]
  circle(p, 2, 15)
  label(name, p, (name == "A" or name == "D") and "sw" or "n", 15)
end

-- the quarter circle of radius 120 about O, exactly, from weighted control points
local O, r, w = P(40, 440), 120, math.cos(math.pi / 4)
bezier{O + V(r, 0), (O + V(r, -r)) * w, O + V(0, -r)}:draw{color = 11}
label("O", O, "sw", 11)
label("r = 120", O + V(r / 2, 0), "s", 11)

-- a natural cubic spline through five nodes
local nodes = {P(180, 430), P(220, 300), P(260, 380), P(300, 270), P(330, 330)}
cubic_spline(nodes):draw{color = 10}
for i, p in ipairs(nodes) do circle(p, 2, 15); label("P" .. i, p, "e", 10) end

-- a vase: a B-spline profile turned about the y axis (the textbook's vertical), seen in
-- isometric projection, scaled and put on the screen (y down)
local profile = bspline({P(0, 0, 0), P(.9, 0, 0), P(.4, .6, 0), P(.8, 1.2, 0), P(.5, 1.6, 0),
  P(.6, 2, 0)}, 3)
local vase = surface.revolution(profile, P(0, 0, 0), V(0, 1, 0))
camera(map.translate(V(480, 420)) * map.scale({100, -100}) * map.isometric())
vase:wireframe{nu = 12, nv = 16, color = 3}
profile:draw{color = 14}
label("surface.revolution", P(0, 2.2, 0), "n", 15)
camera(nil)
label("bezier, rational arc, cubic_spline", P(20, 470), "e", 7)
