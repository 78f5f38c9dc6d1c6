-- A point turned about an arbitrary axis by the Rodrigues formula
-- Buimov §2.7, Fig. 2.4: P* = (P . n) n (1 - cos theta) + P cos theta + (n x P) sin theta for the
-- axis through the origin with the unit direction n. With n = (1, 1, 1)/sqrt 3 and theta = 120°
-- the matrix is the cyclic permutation [[0,1,0,0],[0,0,1,0],[1,0,0,0],[0,0,0,1]]: P = (1, 0, 0)
-- goes to P* = (0, 1, 0). Q = (P . n) n is the centre of P's circle about the axis, S = n x P
-- the direction of the turn at P; the whole circle grey, the turn by theta in colour.

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

local n = unit(V(1, 1, 1))
local th = 2 * math.pi / 3
local R = map.rotate(O, n, th)
local Pt = P(1, 0, 0)
local Ps = R(Pt)
local Q = O + n * dot(Pt - O, n)
local S = cross(n, Pt - O)
local view = map.translate(V(330, 300)) * map.scale({190, -190})
    * map.view{azimuth = 35, elevation = 25}
axes3(view, 1.2)
camera(view)
line(O - n * 0.3, O + n * 1.5, 12)                       -- the axis
local u, w = unit(Pt - Q), unit(cross(n, Pt - Q))
local r = dist(Pt, Q)
curve(function(t) return Q + u * (r * math.cos(t)) + w * (r * math.sin(t)) end, 0, 2
    * math.pi):draw{color = 8}
curve(function(t) return Q + u * (r * math.cos(t)) + w * (r
    * math.sin(t)) end, 0, th):draw{color = 14}
line(Q, Pt, 7); line(Q, Ps, 7)
vector(Pt, S * 0.5, 10)
camera(nil)
for _, m in ipairs{{Pt, "$P$", 15}, {Ps, "$P^*$", 14}, {Q, "$Q$", 7}, {Pt + S
    * 0.5, "$S = n \\times P$", 10},
                   {O + n * 1.5, "$n$", 12}} do
  mark(view(m[1]), "dot", 4, m[3]); label(m[2], view(m[1]), nil, m[3])
end
angle_mark(view(Pt), view(Q), view(Ps), "$\\theta$", 26, 14)
local function z(x) return math.abs(x) < 1e-12 and 0 or x end      -- no "-0" in the caption
caption(string.format("n = (1, 1, 1)/sqrt 3, $\\theta$ = 120°:  P* = (%g, %g, %g)",
  z(Ps.x), z(Ps.y), z(Ps.z)), "bottom", 7)
