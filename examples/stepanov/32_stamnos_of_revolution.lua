-- Example 32 — 3-D stamnos as a surface of revolution
-- The vase profile of example 11 (the one-stroke spline of example 10, §H row 8) rotated about
-- its axis: each meridian is the profile at the angle a, point (r cos a, r sin a, h) in space,
-- with radius r = x/200 and height h = 2 - y/200 of the profile point (x, y) in pixels.  Drawn in
-- the oblique projection of the listing (§H rows 23-24): axis foot C0 = (320, 400), unit 150,
-- ellipse ratio .3, turned by pi/6; the listing writes it as a radial axis C1(a) turning on an
-- ellipse, screen = C0 + r (C1(a) - C0) + h (C2 - C0), which is the same map.
-- White pixels: 50 meridians of 101 points per piece.  The base, a disc of radii from the axis
-- to the foot ring; the belly widest about y = 250, the neck about y = 175 and the out-turned
-- lip above it; the meridians crowd at the silhouette.  The last node sits at the neck radius
-- a3 (not on the axis, as in example 11), so the mouth stays open.
-- The printed kink DATA has 7 values for 8 nodes; the cleaned listing adds the 8th (0).
-- Loops as QBasic runs them (qb = true: 50 angles a = 0, pi/25, ..., 101 points per piece).

local pi, cos, sin = math.pi, math.cos, math.sin
local a1, a2, a3, a4 = 90, 205, 105, 135            -- radii (px): foot, belly, neck, lip
local h1, h2, h3, h4, h5 = 10, 210, 300, 320, 330   -- heights (px) above the base y = 410
local profile = stroke{
  x = {0, a1, a1, a2, a3, a4, a4, a3},
  y = {410, 410, 410 - h1, 410 - h2, 410 - h3, 410 - h4, 410 - h5, 410 - h5},
  uin  = {0, 0, .5, .25, .25, 0, .5, .5},           -- turns, counter-clockwise on screen
  kink = {0, 0, -.25, 0, 0, 0, 0, 0},               -- the corner at the top of the foot
  rin  = {20, 20, 20, 150, 150, 20, 20, 20},
  rout = {20, 20, 150, 150, 20, 20, 20, 20},
  n = {2, 4, 2, 2, 2, 2, 2, 2}, m = {2, 4, 2, 2, 2, 2, 2, 2}, t0 = .5}

local pr = oblique(P(320, 400), 150, .3, pi/6)
for a in qb.range(0, 2*pi, pi/25) do
  local c, s = cos(a), sin(a)
  profile:draw{t = {0, 1, .01}, qb = true, map = function(M)
    local r, h = M.x/200, 2 - M.y/200
    return pr:xy(r*c, r*s, h)                      -- the meridian point (r cos a, r sin a, h)
  end}
end
