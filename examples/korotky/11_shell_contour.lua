-- Korotky (2015) Fig. 2a, 2b: the closed contour of a conic shell and its determinant
-- 2a (left): the contour ABCD, rectangular in plan; the frontal links AB (plane y = 4) and DC
-- (y = 0) are conic arcs through L and L', tangent at 60 and 45 degrees to the ground, the
-- lateral links AD and BC waves z = 0.3 sin(pi y / 4).  2b (right): the determinant of the
-- shell: the guide l = LL', the conoid (AD, p) and the cylindroid (BC, q), both with the plane
-- of parallelism xz (their rulings lie in the planes y = const).  The compatibility condition:
-- the points 1, 2 where p meets the planes of AB and DC lie on the end tangents at A and D,
-- the points 3, 4 of q on those at B and C.  Drawn in perspective, world units equal.
local r3 = math.sqrt(3)
local A, B, C, D = P(0, 4, 0), P(6, 4, 0), P(6, 0, 0), P(0, 0, 0)
local L, L1 = P(3, 4, 3), P(3, 0, 2)
local AB = korotky.conic_arc(A, V(1, 0, r3), B, V(1, 0, -r3), L)
local DC = korotky.conic_arc(D, V(1, 0, 1), C, V(1, 0, -1), L1)
local function wave(x)   -- a lateral link: x fixed, z = 0.3 sin(pi y / 4), as a curve in y
  return curve(function(y) return P(x, y, .3 * math.sin(math.pi * y / 4)) end, 0, 4)
end
local AD, BC = wave(0), wave(6)
-- the directrices: p straight through 2 and 1, q a curve through 4 and 3 (so (BC, q) is a
-- cylindroid); both run with y, as the sweep's parameter
local p1, p2 = A + V(1, 0, r3), D + V(1, 0, 1)          -- 1 on A's tangent, 2 on D's
local q3, q4 = B + V(-1, 0, r3), C + V(-1, 0, 1)         -- 3 on B's tangent, 4 on C's
local p = bezier{p2, p1}
local q = bezier{q4, P(5.6, 2, 1.55), q3}
local l = bezier{L1, L}

local function view(x0)
  camera(map.translate(V(x0, 230)) * map.scale({38, -38}) *
         map.perspective(P(-6, -9, 9), P(3, 2, 1)), {hidden = "show"})
end

-- 2a: the contour alone
view(150)
AB:draw{color = 14}; DC:draw{color = 14}
AD:draw{color = 15}; BC:draw{color = 15}
label("A", A); label("B", B); label("C", C); label("D", D)
label("L", L); label("$L'$", L1)
camera(nil)

-- 2b: the determinant: the end tangents with the points 1-4, p and q, the rulings of the
-- conoid and the cylindroid in the planes y = const, and the guide l
view(470)
AB:draw{color = 14}; DC:draw{color = 14}
AD:draw{color = 15}; BC:draw{color = 15}
for _, t in ipairs{{A, p1}, {D, p2}, {B, q3}, {C, q4}} do line(t[1], t[2], 7) end
for k = 1, 5 do
  local y = (k - 1) / 4
  line(AD(4 * y), p(y), 8)
  line(BC(4 * y), q(y), 8)
end
p:draw{color = 13}; q:draw{color = 13}
l:draw{color = 12}
label("A", A); label("B", B); label("C", C); label("D", D)
label("1", p1); label("2", p2); label("3", q3); label("4", q4)
label("p", p(.5)); label("q", q(.5)); label("l", l(.5))
camera(nil)
label("2a  the contour ABCD", P(60, 455), "e", 11)
label("2b  l, (AD, p) conoid, (BC, q) cylindroid", P(300, 455), "e", 11)
