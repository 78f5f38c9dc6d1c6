-- Example 34 (variant) — Schematic 3-D church with its spline net drawn in colour 8
-- NOT THE LISTING AS PRINTED: example 34 draws the net of meridians with `pset (x, y), 0`, the
-- background colour, so the faithful figure (34_church.lua) shows only the guide curves, the
-- knob and the cross.  This variant draws the same net in colour 8 (dark grey), as the digest
-- recommends: the church appears - a bulbous onion dome on a drum, and two walls with three
-- zakomary arches each, all as dense vertical meridians.  ("0" may be an OCR misreading of
-- "8"; that is unverified.)  Everything else is example 34 unchanged:
-- the 7 nodes of each meridian slide along five circles of the dome and the drum, the wall top
-- z = |cos b|/(4 + b^2) + 2 (zakomary) and the ground line z = (1 - |cos b|)^10 (pilasters),
-- b = 3 pi t1/2 (§H row 27); every node tangent is (0, 0, -1) (§H row 8, explicit vectors),
-- sides .5, n = m = 2, t0 = .5; 19 meridians t1 = -1, -8/9, ..., 1 per wall; oblique projection
-- C0 = (320, 400), unit 60, ellipse ratio .3, turned by pi/5 (§H row 23).  The guide curves
-- (white) are drawn before each wall's net, which paints over some of their pixels.

local pi, cos, sin, abs = math.pi, math.cos, math.sin, math.abs
local NET_COLOUR = 8                                -- the listing has 0 (the background)

local pr = oblique(P(320, 400), 60, .3, pi/5)
local r = {.05, .05, .6, .3, .3}                    -- the circles of the dome and the drum:
local h = {3.9, 3.8, 3.1, 2.8, 2.5}                 -- radius and height

-- the 7 nodes of the meridian at t1 in [-1, 1] on wall j
local function nodes(j, t1)
  local a = j == 1 and pi*t1/4 - pi/2 or -pi*t1/4 - pi   -- angle on the circles
  local N = {}
  for i = 1, 5 do N[i] = P(r[i]*cos(a), r[i]*sin(a), h[i]) end
  local x, y = t1, -1                               -- wall 1: the face y = -1
  if j == 2 then x, y = -1, t1 end                  -- wall 2: the face x = -1
  local b = 3*pi*t1/2
  N[6] = P(x, y, abs(cos(b))/(4 + b^2) + 2)         -- the top with three zakomary
  N[7] = P(x, y, (1 - abs(cos(b)))^10)              -- the ground line and the pilasters
  return N
end

local knob = pr(P(0, 0, h[1]))
circle(knob, 4, nil, nil, nil, 5); paint(knob)

local down = V(0, 0, -1)
for j = 1, 2 do
  for t1 in qb.range(-1, 1, .001) do                -- the guide curves
    for _, X in ipairs(nodes(j, t1)) do pset(pr(X)) end
  end
  for t1 in qb.range(-1, 1.01, 1/9) do              -- the net of meridians
    local meridian = stroke{nodes = nodes(j, t1), ein = {down, down, down, down, down, down, down},
                            rin = .5, rout = .5}
    meridian:draw{t = {0, 1, .01}, qb = true, map = pr, color = NET_COLOUR}
  end
end

for x in qb.range(-r[1], r[1] + .01, r[1]/3) do     -- the cross, in the plane y = 0
  for z in qb.range(h[1] - .1, h[1] + 1, .01) do pset(pr(P(x, 0, z))) end
end
for x in qb.range(-.4, .4, .01) do
  for z in qb.range(h[1] + .5, h[1] + .61, .01) do pset(pr(P(x, 0, z))) end
end
