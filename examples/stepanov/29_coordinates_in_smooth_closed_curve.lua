-- Example 29 — Curvilinear coordinate system in a region bounded by a smooth closed curve (a proposal)
-- NOT FROM THE ARTICLE.  Example 29 has no listing and no figure, only the prose plan: "set
-- direction vectors at the vertices of a quadrilateral and build splines that join into a smooth
-- closed curve; build the coordinate system from the four spline functions; introduce an
-- analogue of polar coordinates".  The listing this script is compared with, ex29.bas, is itself
-- a reconstructed proposal (every line marked RECONSTRUCTED); this script draws the same figure.
-- Choices of that proposal:
--   - the quadrilateral of examples 24-28; the one-stroke spline of example 10 through its
--     vertices, closed, with the tangent at a vertex parallel to the chord of its neighbours,
--     sides = chord/3, n = m = 2, t0 = .5 (§H row 8: `stroke{nodes = A, closed = true}`);
--     drawn as the thick yellow boundary (1001 dots per piece);
--   - the four spline pieces as the sides of the patch of examples 25/28 (§H row 18), sides 1 and
--     3 entering through their coordinates (xi, eta) in the frame of their own chord (example 23):
--     U0 = S0(t1), U2 = S2(1 - t1), (xi, eta) = (xi, eta)_3 + t1 ((xi, eta)_1 - (xi, eta)_3),
--     X = U0 + xi (U2 - U0) + eta perp(U2 - U0);
--   - the polar analogue: the polar grid of the plane carried through plane -> square -> region
--     (`squash01`, example 28): the circles r = .2, .4, ..., 2 in white, 16 rays in light grey.

local pi, cos, sin = math.pi, math.cos, math.sin
local A = {P(100, 100), P(300, 70), P(250, 400), P(150, 350)}
for i = 1, 4 do circle(A[i], 5, 14) end

local S = stroke{nodes = A, closed = true}                  -- the smooth closed boundary
S:draw{t = {0, 1, .001}, qb = true, brush = "dot", color = 14}

local function side(i) return function(t) return S:piece_xy(i, t) end end
local C = patch(side(1), side(2), side(3), side(4)):pre(squash01)   -- plane -> square -> region
local polar = C:pre(function(r, u) return r*cos(u), r*sin(u) end)

local r, u = {.2, 2.01, .2, fine = {0, 10, .005}}, {0, 2*pi - .01, pi/8, fine = {0, 2*pi, pi/1000}}
polar:grid{t1 = r, t2 = u, family = "t1", qb = true}             -- circles r = .2 .. 2
polar:grid{t1 = r, t2 = u, family = "t2", qb = true, color = 7}  -- rays u = 0, pi/8, ..., 15 pi/8
