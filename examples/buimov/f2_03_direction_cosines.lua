-- The direction cosines of an axis: n = [n1 n2 n3] = [cos alpha, cos beta, cos gamma]
-- Buimov §2.6, Fig. 2.3: the unit vector n of the axis makes the angles alpha, beta, gamma with
-- x, y, z; its components are their cosines and n1^2 + n2^2 + n3^2 = 1. Here n = (2, 1, 2)/3:
-- alpha = 48.19°, beta = 70.53°, gamma = 48.19°. The dashed lines drop n's end onto the axes.
-- Seen from the azimuth 35°, elevation 18° with z up.

local O = P(0, 0, 0)
-- the axes x, y, z through the view, lettered at their ends
local function axes3(view, len)
  camera(view)
  for _, v in ipairs{V(len, 0, 0), V(0, len, 0), V(0, 0, len)} do arrow(O, O + v, "end", 8) end
  camera(nil)
  for _, a in ipairs{{V(len, 0, 0), "$x$"}, {V(0, len, 0), "$y$"}, {V(0, 0, len), "$z$"}} do
    label(a[2], view(O + a[1]), nil, 8)
  end
end

local n = V(2, 1, 2) / 3
local view = map.translate(V(320, 330)) * map.scale({300, -300}) * map.view{azimuth = 35, elevation = 18}
axes3(view, 1.1)
camera(view)
vector(O, n, 12)
pen{dash = {4, 3}}
for _, foot in ipairs{P(n.x, 0, 0), P(0, n.y, 0), P(0, 0, n.z), P(n.x, n.y, 0)} do line(O + n, foot, 8) end
line(P(n.x, 0, 0), P(n.x, n.y, 0), 8); line(P(0, n.y, 0), P(n.x, n.y, 0), 8)
pen()
-- each angle as an arc in the plane of its axis and n, radius 0.2 (alpha), 0.26, 0.32
local arcs = {}
for i, a in ipairs{{V(1, 0, 0), "$\\alpha$"}, {V(0, 1, 0), "$\\beta$"}, {V(0, 0, 1), "$\\gamma$"}} do
  local e, r = a[1], 0.14 + 0.06 * i
  local w = unit(n - e * dot(n, e))
  local ang = math.acos(dot(n, e))
  local arc = curve(function(t) return O + e * (r * math.cos(t)) + w * (r * math.sin(t)) end, 0, ang)
  arc:draw{color = 14}
  arcs[i] = {arc(ang / 2), a[2]}
end
camera(nil)
label("$n$", view(O + n), nil, 12)
for _, a in ipairs(arcs) do label(a[2], view(a[1]), nil, 14) end
for _, c in ipairs{{P(n.x, 0, 0), "$n_1$"}, {P(0, n.y, 0), "$n_2$"}, {P(0, 0, n.z), "$n_3$"}} do
  mark(view(c[1]), "dot", 4, 15); label(c[2], view(c[1]), nil, 15)
end
caption(string.format("n = (2, 1, 2)/3:  $\\alpha$ = %.2f°, $\\beta$ = %.2f°, $\\gamma$ = %.2f°",
  math.deg(math.acos(n.x)), math.deg(math.acos(n.y)), math.deg(math.acos(n.z))), "bottom", 7)
