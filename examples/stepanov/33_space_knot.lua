-- Example 33 — Space curve: a knot
-- Example 10's one-stroke spline generalised to space (§H row 8): the direction at a node is
-- given by longitude u1 and latitude u2, e = (cos u1 cos u2, sin u1 cos u2, sin u2) (§H row 25),
-- each piece is the quadrilateral spline P = N_i + rout e_out, Q = N_i+1 - rin e_in,
-- X = M + g(t)(N - M).  Knottedness is a property of space, so the 18 nodes lie on a cylinder
-- and a torus (§H row 26), with the tangents mostly along their circular sections.
-- Oblique projection (§H row 23): C0 = (320, 240), unit 150, ellipse ratio .3, turned by -pi/3.
-- Cyan rings: the nodes.  Thick white curve (101 dots per piece): down a vertical strand from
-- the top node, once round the unit circle z = 0 (the large flat ellipse), twice round the
-- tube of the torus (tight loops at the right), then down to the bottom node.
-- Defects fixed in the cleaned listing and followed here: node angles pi/10 (printed pi/40 in
-- one coordinate), the extra 19th rin value dropped, the node projection's x/y terms.

local pi, cos, sin = math.pi, math.cos, math.sin
local function cylinder(u, z) return P(cos(u), sin(u), z) end
local function torus(u1, u2) return P(cos(u1)*(1 + .2*cos(u2)), sin(u1)*(1 + .2*cos(u2)), .2*sin(u2)) end

local N = {cylinder(0, 1), cylinder(0, .1)}
for k = 0, 3 do N[#N + 1] = cylinder(pi/10 + k*pi/2, 0) end
N[#N + 1] = cylinder(0, 0)
N[#N + 1] = cylinder(pi/20, -.1)
N[#N + 1] = torus(pi/10, -pi/2)
for k = 1, 8 do N[#N + 1] = torus(pi/5 + k*pi/35, -pi/2 + (k - 1)*pi/2) end
N[#N + 1] = cylinder(0, -1)

local pr = oblique(P(320, 240), 150, .3, -pi/3)
for _, X in ipairs(N) do circle(pr(X), 3, 3) end

local knot = stroke{nodes = N,                       -- angles in turns; no kinks; n = m = 2, t0 = .5
  uin  = {0, 0, .3, .55, .8, 1.05, 0, .3, .35, .4, 0, .45, 0, .5, 0, .55, 0, 0},
  uin2 = {-.25, -.25, 0, 0, 0, 0, -.25, 0, 0, 0, .25, 0, -.25, 0, .25, 0, -.25, -.25},
  rin  = {.25, .25, .25, 1, 1, 1, .1, .25, .25, .25, .25, .25, .25, .25, .25, .25, .25, 1},
  rout = {.25, .25, 1, 1, 1, .1, .25, .25, .25, .25, .25, .25, .25, .25, .25, .25, 1, .25}}
knot:draw{t = {0, 1, .01}, qb = true, map = pr, brush = "dot"}
