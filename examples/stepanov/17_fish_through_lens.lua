-- Example 17 — A fish seen through a curvilinear "lens", with homothety
-- d'Arcy Thompson's transformation of a form: a primitive fish of three splines (example 10's
-- one-stroke curve) is looked at through the curvilinear system u = x(y^2 + 1), v = y(x^2 + 1),
-- on the screen (320 + 100u, 240 + 100v).  White: the system's coordinate lines, the image of the
-- square [-1, 1]^2 with lines at -1, -.6, ..., 1, a pillow with pinched sides.  Then the fish
-- after the homothety (x, y) -> (kf x, kf y) for kf = 1 (blue), 2 (green), 3 (cyan): scaling the
-- Cartesian picture changes its shape in the curvilinear one, from a small fish near the centre
-- to a large, strongly bent one.  Nose on the left, an ichthys tail on the right where the body
-- lines cross.
-- The nodes are the listing's screen points normalised by (X - 200)/200, (Y - 240)/200 (y down);
-- angles in turns, counter-clockwise on the screen; sides /200; n = m = 2, t0 = .5.
-- The listing draws its grid with x and y swapped and v negated; the grid is symmetric under that
-- exchange, so the same lens serves both here.  It does not draw the plain Cartesian fish that
-- the article also shows.

screen(12)
local lens = curvilinear(function(x, y) return x*(y^2 + 1), y*(x^2 + 1) end)
  :post(function(u, v) return 320 + 100*u, 240 + 100*v end)

local lines = {-1, 1.01, .4, fine = {-1, 1, .01}}
lens:grid{t1 = lines, t2 = lines, qb = true}

local fish = stroke{
  nodes = {P(-.5, 0), P(.5, .2), P(.5, -.2), P(-.5, 0)},   -- nose, belly end, back end, nose
  uin   = {.125, -.125, .125, .325},
  kink  = {0, .5, .5, .5},
  rin   = {1, 1, .25, .75},
  rout  = {1, .25, .125, .5},
}

for kf = 1, 3 do
  lens:pre(function(x, y) return kf*x, kf*y end)     -- the homothety, then the lens
      :draw(fish, {t = {0, 1, .001}, qb = true, brush = "dot", color = kf})
end
