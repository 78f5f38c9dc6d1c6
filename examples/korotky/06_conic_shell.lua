-- Korotky (2015) Fig. 2: a shell on a closed contour swept by conics
-- The contour ABCD is rectangular in plan: the frontal links AB (y = 4) and DC (y = 0) are
-- conic arcs, the lateral links AD and BC waves z = 0.3 sin(pi y / 4).  In each plane y = const
-- the generator is the conic through U0 on AD, V0 on BC and T on the guide l = LL', tangent to
-- the rulings U0 P and V0 Q of the conoid (AD, p) and the cylindroid (BC, q).  Left: the guide l
-- straight; right: l bowed down by 0.8 (the concave case: its middle generators flatten).
local function seg(a, b) return bezier{a, b} end
local function wave(x)   -- a lateral link: x fixed, z = 0.3 sin(pi y / 4), as a curve in y
  return curve(function(y) return P(x, y, .3 * math.sin(math.pi * y / 4)) end, 0, 4)
end
-- the directrices p and q of the contact surfaces, through the points 1, 2 and 3, 4 on the
-- end tangents of DC (45 degrees) and AB (60 degrees)
local p = seg(P(1, 0, 1), P(1, 4, math.sqrt(3)))
local q = seg(P(5, 0, 1), P(5, 4, math.sqrt(3)))
local function shell(l)
  return korotky.conic_sweep{U = wave(0), V = wave(6), T = l, P = p, Q = q}
end
local straight = seg(P(3, 0, 2), P(3, 4, 3))
local bowed = bezier{P(3, 0, 2), P(3, 2, 1.7), P(3, 4, 3)}

for k, l in ipairs{straight, bowed} do
  camera(map.translate(V(k == 1 and 165 or 480, 270)) * map.scale({34, -34}) *
         map.perspective(P(-6, -9, 9), P(3, 2, 1)))
  local s = shell(l)
  s:wireframe{nu = 8, nv = 10, color = k == 1 and 11 or 10, hidden = "hide"}
  l:draw{color = 14}
  p:draw{color = 8}
  q:draw{color = 8}
  label("A", P(0, 4, 0), nil, 15); label("B", P(6, 4, 0), nil, 15)
  label("C", P(6, 0, 0), nil, 15); label("D", P(0, 0, 0), nil, 15)
  label("L", l(1), nil, 14); label("L'", l(0), nil, 14)
  label("p", p(.5), nil, 8); label("q", q(.5), nil, 8)
  camera(nil)
end
label("l straight", P(110, 460), "e", 11)
label("l bowed (concave)", P(420, 460), "e", 10)
