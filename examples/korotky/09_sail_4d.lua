-- Korotky (2015) Fig. 1b: the sail by the "key" construction in four dimensions
-- The contour ABC is lifted into 4-D by a fourth coordinate t: the foot AB (a parabola
-- cambered in x) gets t = z, so it lies in the plane tau (y = 0, t = z); the luff AC and
-- the leech BC are straight in xyt (x and t grow linearly with the height y) and bowed in z.
-- The surface is the set of meets of two pencils of 2-planes: omega(u) through C, the point
-- AB(u) and Z (the point at infinity of the z axis), delta(v) through X (that of the x axis)
-- and the points of AC and BC at the level v.  The hyper-epure shows it twice, through two
-- 4-D -> 2-D maps (3 x 5 matrices): left its xyz projection, the sail; right its xyt
-- projection, the cone with vertex C over AB.
local A, B, C = P(0, 0, 0, 0), P(0, 0, 4, 4), P(0, 6, .3, 2)
local foot = bezier{A, P(1.6, 0, 2, 2), B}         -- y = 0, t = z: in the plane tau
local luff = bezier{A, P(0, 3, -.2, 1), C}         -- parameters run with the height y
local leech = bezier{B, P(0, 3, 2.9, 3), C}
local Z, X = V(0, 0, 1, 0), V(1, 0, 0, 0)
local sail = korotky.two_pencils{omega = {C, foot, Z}, delta = {X, luff, leech}}

-- the views: the receding axis x drawn at 36 degrees, 0.8 of its length; the others as they are
local c, s = .8 * math.cos(math.pi / 5), .8 * math.sin(math.pi / 5)
local views = {
  {name = "xyz", f = map.matrix({{c, 0, 1, 0, 0}, {s, 1, 0, 0, 0}, {0, 0, 0, 0, 1}}), ax = 3},
  {name = "xyt", f = map.matrix({{c, 0, 0, 1, 6}, {s, 1, 0, 0, 0}, {0, 0, 0, 0, 1}}), ax = 4},
}
window(-1.2, -1.6, 11.2, 7.7)
for _, view in ipairs(views) do
  camera(view.f)
  -- axes from the origin: x (receding), y (up), and z or t to the right
  local o = P(0, 0, 0, 0)
  local e = {V(1.6, 0, 0, 0), V(0, 7, 0, 0), view.ax == 3 and V(0, 0, 4.8, 0) or V(0, 0, 0, 4.8)}
  for i, d in ipairs(e) do
    line(o, o + d, 8)
    label(({"x", "y", view.ax == 3 and "z" or "t"})[i], o + d, i == 2 and "n" or "e", 8)
  end
  sail:wireframe{nu = 8, nv = 8, color = 11}
  foot:draw{color = 14}
  luff:draw{color = 14}
  leech:draw{color = 14}
  label("A", A, nil, 15); label("B", B, nil, 15); label("C", C, nil, 15)
  camera(nil)
end
-- the linking lines of the hyper-epure: the same point in both views at the same height y
for _, p in ipairs{sail(.5, .5), sail(1, .25), C} do
  local a, b = views[1].f(p), views[2].f(p)
  pen{dash = {3, 3}}
  line(a, b, 7)
  pen{}
end
label("G(xyz): the sail", P(-.6, -1.2), "e", 11)
label("G(xyt): the cone over AB", P(5.6, -1.2), "e", 11)
