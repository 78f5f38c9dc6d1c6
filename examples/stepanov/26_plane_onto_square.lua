-- Example 26 — Map of the whole plane onto the open square
-- The plane (p, q) goes onto the open square -1 < x, y < 1 by x = p/sqrt(p^2 + 1),
-- y = q/sqrt(q^2 + 1) (§H row 19, `squash`): a model of the whole Euclidean plane in a square.
-- The picture is the image of the Cartesian grid p, q = -5, -4.5, ..., 5 (white pixels): the
-- lines stay straight but crowd toward the border of the square (yellow), which is the image of
-- the points at infinity.  Scale 200 about the centre (320, 240), y up.
-- The fine steps run as QBasic's FOR does (qb = true: 1000 samples from -5 to 5 step .01).

local O, a = P(320, 240), 200
line(O - V(a, a), O + V(a, a), 14, "b")             -- the square |x|, |y| < 1

local C = curvilinear(squash):post(screenmap(O.x, O.y, a))
local lines = {-5, 5, .5, .01}                       -- p = -5, -4.5, ..., 5; traced with step .01
C:grid{t1 = lines, t2 = lines, qb = true}
